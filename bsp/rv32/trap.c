/*
 * rv32/trap.c — machine-mode trap handler of the RV32 platforms (see rv32/trap.h).
 *
 * The firmware uses no interrupts but those a platform enables to report faults, so any trap is a
 * bug: print one line
 *
 *   TRAP: mcause=0x00000005 mepc=0x00000130 mtval=0x90000000 (load access fault)
 *
 * on the UART (the part in brackets from the platform's describe hook, or the spec's name of the
 * cause) and exit with BSP_EXIT_TRAP. mtvec is in direct mode (MODE = 0), which needs the handler
 * address 4-byte aligned.
 */
#include <stdint.h>

#include "bsp.h"
#include "rv32/trap.h"

void rv32_trap_puts(const char *s)
{
    while (*s != '\0') {
        bsp_uart_putc(*s);
        s++;
    }
}

void rv32_trap_puthex(uint32_t v)
{
    static const char digits[] = "0123456789abcdef";

    rv32_trap_puts("0x");
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
    rv32_trap_puts("\nTRAP: mcause=");
    rv32_trap_puthex(mcause);
    rv32_trap_puts(" mepc=");
    rv32_trap_puthex(mepc);
    rv32_trap_puts(" mtval=");
    rv32_trap_puthex(mtval);
    rv32_trap_puts(" (");
    if (!rv32_trap_platform_describe(mcause)) {
        rv32_trap_puts(trap_cause_name(mcause));
    }
    rv32_trap_puts(")\n");
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
    rv32_trap_platform_enable();
}
