/*
 * bus_error.c — a load from an address no device of the SoC decodes, linked with the soc BSP
 * (tests/soc/bus_error.sh runs it on socsim).
 *
 * The bus answers ERR; soc_top completes the load with 0, records it in SYS BUS_ERR/BUS_ERR_ADDR
 * and raises the bus-error interrupt, which bsp_init() enabled: the BSP's trap handler must report
 * "bus error: load at 0x90000000" and end the run with BSP_EXIT_TRAP. Reaching the end of main
 * instead is a failure (status 1).
 */
#include <stdint.h>
#include <stdio.h>

#include "bsp.h"

#define BUS_ERROR_ADDR 0x90000000u  /* uncached, between the SYS window and nothing */

int main(void)
{
    volatile uint32_t *unmapped = (volatile uint32_t *)(uintptr_t)BUS_ERROR_ADDR;
    uint32_t value;

    bsp_init();
    printf("bus_error: loading from 0x%08lx\n", (unsigned long)BUS_ERROR_ADDR);
    value = *unmapped;
    /* The interrupt is taken a few instructions after the load (it is not precise): give it
     * time before declaring that nothing happened. */
    for (int i = 0; i < 64; i++) {
        __asm__ volatile("nop");
    }
    printf("bus_error: no trap after the load (it read 0x%08lx)\n", (unsigned long)value);
    return 1;
}
