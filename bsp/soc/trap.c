/*
 * trap.c — machine-mode trap handler for the FPGA SoC.
 *
 * The firmware uses no interrupts, so any trap is a bug: print mcause, mepc, mtval and the cause's
 * name on the UART and exit with BSP_EXIT_TRAP. The line starts as qemu_virt's does.
 *
 * Bus errors: an access to an address no device decodes is answered with Wishbone ERR, which the
 * packaged VexRiscv ignores, so soc_top completes it (a load reads 0, a store is dropped), records
 * it in SYS BUS_ERR / BUS_ERR_ADDR and raises the core's external interrupt line
 * SOC_IRQ_BUS_ERROR (contract/soc-memory-map.md). bsp_trap_install() enables that one interrupt,
 * so the handler names the access and its address; being an interrupt it is imprecise: mepc is
 * the instruction the core was at when it took it, a few after the access:
 *
 *   TRAP: mcause=0x8000000b mepc=0x00000130 mtval=0x00000000 (bus error: load at 0x90000000)
 *
 * mtvec is in direct mode (MODE = 0), which needs the handler address 4-byte aligned. The handler uses only bsp_uart_putc, not stdio, so it still
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

/* csrs takes the CSR number as text, which a C constant with a 'u' suffix is not. */
_Static_assert(SOC_CSR_IRQ_MASK == 0xBC0u, "trap.c writes VexRiscv's mask CSR as 0xBC0");
#define TRAP_MCAUSE_EXTERNAL 0x8000000Bu  /* machine external interrupt */
#define TRAP_MIE_MEIE        0x800u       /* mie: machine external interrupts enabled */
#define TRAP_MSTATUS_MIE     0x8u         /* mstatus: interrupts enabled in machine mode */

/* "bus error: load at 0x...": what SYS BUS_ERR recorded of the first failed access. */
static void trap_put_bus_error(void)
{
    const uint32_t err = BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR);
    const uint32_t addr = BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR_ADDR);
    const char *kind = "load";

    if ((err & SOC_SYS_BUS_ERR_FETCH_MASK) != 0u) {
        kind = "fetch";
    } else if ((err & SOC_SYS_BUS_ERR_WRITE_MASK) != 0u) {
        kind = "store";
    }
    trap_puts("bus error: ");
    trap_puts(kind);
    trap_puts(" at ");
    trap_puthex(addr);
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
    if (mcause == TRAP_MCAUSE_EXTERNAL &&
        (BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR) & SOC_SYS_BUS_ERR_VALID_MASK) != 0u) {
        trap_put_bus_error();
    } else {
        trap_puts(trap_cause_name(mcause));
    }
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
    /* The bus-error interrupt and nothing else: its bit in VexRiscv's external-interrupt mask
     * CSR, then mie.MEIE, then mstatus.MIE. A bus error left over from before is cleared first. */
    BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR) = 0u;
    __asm__ volatile("csrs 0xBC0, %0" ::"r"(1u << SOC_IRQ_BUS_ERROR));
    __asm__ volatile("csrs mie, %0" ::"r"(TRAP_MIE_MEIE));
    __asm__ volatile("csrs mstatus, %0" ::"r"(TRAP_MSTATUS_MIE));
}
