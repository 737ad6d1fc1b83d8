/* hw/common.h — LiteX's CSR accessors as LiteDRAM's generated csr.h and sdram_phy.h call them, for
 * the SoC's firmware: one uncached 32-bit access each (the SDRAM_CTRL region, bit 31 set). */
#ifndef BSP_SOC_SDRAM_HW_COMMON_H
#define BSP_SOC_SDRAM_HW_COMMON_H
#include <stdint.h>
static inline uint32_t csr_read_simple(unsigned long addr)
{
    return *(volatile uint32_t *)addr;
}
static inline void csr_write_simple(uint32_t value, unsigned long addr)
{
    *(volatile uint32_t *)addr = value;
}
#endif
