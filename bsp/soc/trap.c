/*
 * trap.c — machine-mode trap handler for the FPGA SoC.
 *
 * The firmware uses no interrupts, so any trap is a bug: print mcause, mepc, mtval and the cause's
 * name on the UART and exit with BSP_EXIT_TRAP. The line starts as qemu_virt's does:
 *
 *   TRAP: mcause=0x00000005 mepc=0x00000124 mtval=0x90000000 (load access fault)
 *
 * An access to an address no device decodes ends in a Wishbone ERR, which the core takes as an
 * access fault with mtval = the address. mtvec is in direct mode (MODE = 0), which needs the
 * handler address 4-byte aligned. The handler uses only bsp_uart_putc, not stdio, so it still
 * works when the fault came from inside printf.
 */
#include <stdint.h>

#include "bsp.h"
#include "bsp_internal.h"

static void trap_puts(const char *s)
{
    while (*s != '\0') {
        bsp_uart_putc(*s);
        s++;
    }
}

static void trap_puthex(uint32_t v)
{
    static const char digits[] = "0123456789abcdef";

    trap_puts("0x");
    for (int shift = 28; shift >= 0; shift -= 4) {
        bsp_uart_putc(digits[(v >> shift) & 0xFu]);
    }
}

/* The privileged spec's exception codes (mcause with the interrupt bit clear). */
static const char *trap_cause_name(uint32_t mcause)
{
    static const char *const names[] = {
        "instruction address misaligned", "instruction access fault", "illegal instruction",
        "breakpoint", "load address misaligned", "load access fault",
        "store address misaligned", "store access fault", "ecall from U-mode",
        "ecall from S-mode", "reserved", "ecall from M-mode",
    };

    if ((mcause & 0x80000000u) != 0u) {
        return "interrupt";
    }
    if (mcause < sizeof names / sizeof names[0]) {
        return names[mcause];
    }
    return "unknown cause";
}

static void trap_report(void) __attribute__((noreturn, noinline));
static void trap_report(void)
{
    uint32_t mcause;
    uint32_t mepc;
    uint32_t mtval;

    __asm__ volatile("csrr %0, mcause" : "=r"(mcause));
    __asm__ volatile("csrr %0, mepc" : "=r"(mepc));
    __asm__ volatile("csrr %0, mtval" : "=r"(mtval));
    trap_puts("\nTRAP: mcause=");
    trap_puthex(mcause);
    trap_puts(" mepc=");
    trap_puthex(mepc);
    trap_puts(" mtval=");
    trap_puthex(mtval);
    trap_puts(" (");
    trap_puts(trap_cause_name(mcause));
    trap_puts(")\n");
    bsp_exit(BSP_EXIT_TRAP);
}

/* The "interrupt" attribute makes GCC save what it uses and end with mret; the handler never
 * returns, but keeping the attribute keeps the entry sequence correct for a trap context. */
static void __attribute__((interrupt("machine"), aligned(4))) trap_entry(void)
{
    trap_report();
}

void bsp_trap_install(void)
{
    uintptr_t base = (uintptr_t)&trap_entry;  /* aligned(4): MODE bits [1:0] = 0 = direct */

    __asm__ volatile("csrw mtvec, %0" ::"r"(base));
}
