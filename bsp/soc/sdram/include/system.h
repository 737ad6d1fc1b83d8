/* system.h — what LiteDRAM's generated csr.h includes from LiteX's BSP, for the SoC's firmware:
 * only where its control registers are (csr.h adds its offsets to CSR_BASE), from the memory map. */
#ifndef BSP_SOC_SDRAM_SYSTEM_H
#define BSP_SOC_SDRAM_SYSTEM_H
#include "soc_map.h"
#define CSR_BASE SOC_SDRAM_CTRL_BASE
#endif
