/* hw/common.h — LiteX's CSR accessors as LiteDRAM's generated csr.h and sdram_phy.h call them,
 * for tests/sdram's host-side bench: each access is a Wishbone cycle on the Verilated core's
 * control bus (tests/sdram/litedram_tb.cpp implements them). */
#ifndef TESTS_SDRAM_STUB_HW_COMMON_H
#define TESTS_SDRAM_STUB_HW_COMMON_H
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif
uint32_t csr_read_simple(unsigned long addr);
void csr_write_simple(uint32_t value, unsigned long addr);
#ifdef __cplusplus
}
#endif
#endif
