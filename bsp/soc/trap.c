/*
 * trap.c — what the SoC adds to the RV32 trap handler (rv32/trap.c): the bus-error interrupt.
 *
 * An access to an address no device decodes is answered with Wishbone ERR, which the packaged
 * VexRiscv ignores, so soc_top completes it (a load reads 0, a store is dropped), records it in
 * SYS BUS_ERR / BUS_ERR_ADDR and raises the core's external interrupt line SOC_IRQ_BUS_ERROR
 * (contract/soc-memory-map.md). The enable hook turns on that one interrupt, so the handler names
 * the access and its address; being an interrupt it is imprecise: mepc is the instruction the core
 * was at when it took it, a few after the access:
 *
 *   TRAP: mcause=0x8000000b mepc=0x00000130 mtval=0x00000000 (bus error: load at 0x90000000)
 */
#include <stdint.h>

#include "bsp.h"
#include "bsp_internal.h"

/* csrs takes the CSR number as text, which a C constant with a 'u' suffix is not. */
_Static_assert(SOC_CSR_IRQ_MASK == 0xBC0u, "trap.c writes VexRiscv's mask CSR as 0xBC0");
#define TRAP_MCAUSE_EXTERNAL 0x8000000Bu  /* machine external interrupt */
#define TRAP_MIE_MEIE        0x800u       /* mie: machine external interrupts enabled */
#define TRAP_MSTATUS_MIE     0x8u         /* mstatus: interrupts enabled in machine mode */

void rv32_trap_platform_enable(void)
{
    /* The bus-error interrupt and nothing else: its bit in VexRiscv's external-interrupt mask
     * CSR, then mie.MEIE, then mstatus.MIE. A bus error left over from before is cleared first. */
    BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR) = 0u;
    __asm__ volatile("csrs 0xBC0, %0" ::"r"(1u << SOC_IRQ_BUS_ERROR));
    __asm__ volatile("csrs mie, %0" ::"r"(TRAP_MIE_MEIE));
    __asm__ volatile("csrs mstatus, %0" ::"r"(TRAP_MSTATUS_MIE));
}

/* "bus error: load at 0x...": what SYS BUS_ERR recorded of the first failed access. */
int rv32_trap_platform_describe(uint32_t mcause)
{
    const uint32_t err = BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR);
    const uint32_t addr = BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_BUS_ERR_ADDR);
    const char *kind = "load";

    if (mcause != TRAP_MCAUSE_EXTERNAL || (err & SOC_SYS_BUS_ERR_VALID_MASK) == 0u) {
        return 0;
    }
    if ((err & SOC_SYS_BUS_ERR_FETCH_MASK) != 0u) {
        kind = "fetch";
    } else if ((err & SOC_SYS_BUS_ERR_WRITE_MASK) != 0u) {
        kind = "store";
    }
    rv32_trap_puts("bus error: ");
    rv32_trap_puts(kind);
    rv32_trap_puts(" at ");
    rv32_trap_puthex(addr);
    return 1;
}
