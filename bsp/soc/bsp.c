/*
 * bsp.c — start-up and exit on the FPGA SoC.
 *
 * Exit writes the status to SYS EXIT: in simulation (socsim) the run ends with that status, as
 * QEMU's does through sifive_test; on a board the SYS block latches it (LEDs) and the core waits
 * here. picolibc's exit() lands in _exit() below, so exit(n) and a return from main() (crt0.c
 * calls exit(main())) both end the run with status n.
 */
#include <stdint.h>

#include "bsp.h"
#include "bsp_internal.h"

/* VexRiscv's CfuPlugin refuses custom instructions (illegal instruction) until bit 31 of CSR 0xBC0,
 * which it shares with the external-interrupt mask (line 31: none in soc_top), is set. */
_Static_assert(SOC_CSR_IRQ_MASK == 0xBC0u && SOC_CSR_CFU_ENABLE == 0x80000000u,
               "bsp_init enables the custom-function port as bit 31 of CSR 0xBC0");

void bsp_init(void)
{
    bsp_trap_install();
    bsp_uart_init();
    /* the projection unit (firmware/render/proj_unit.h) */
    __asm__ volatile("csrs 0xBC0, %0" ::"r"(SOC_CSR_CFU_ENABLE));
}

void bsp_exit(int code)
{
    uint32_t status = (uint32_t)code & 0xFFu;

    if (code != 0 && status == 0u) {
        status = 1u;  /* only 8 bits reach the host: never turn a failure into success */
    }
    /* Let the UART finish what was printed: the harness ends the run at the EXIT write. */
    while ((BSP_MMIO32(SOC_UART_BASE, SOC_UART_REG_STATUS) & SOC_UART_STATUS_TX_IDLE_MASK) == 0u) {
    }
    BSP_MMIO32(SOC_SYS_BASE, SOC_SYS_REG_EXIT) = status;
    for (;;) {
        __asm__ volatile("wfi");
    }
}

/* picolibc's exit() calls this after running atexit handlers. */
void _exit(int status) __attribute__((noreturn));
void _exit(int status)
{
    bsp_exit(status);
}
