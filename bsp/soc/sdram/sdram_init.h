/*
 * sdram_init.h — the SDRAM's power-up sequence, through LiteDRAM's DFI software interface.
 *
 * LiteDRAM's controller (soc_rtl/litedram) starts with the SDRAM's pins under software control:
 * the CPU issues the chip's power-up sequence one command at a time through the controller's
 * control registers (its generated <generated/csr.h>), then hands the pins to the controller and
 * sets init_done. The sequence is the chip's data sheet's, not LiteDRAM's generated
 * init_sequence() (docs/sdram.md says why).
 *
 * The core is pure but for the register accessors and sdram_delay_ns(), so the same file runs in
 * the SoC's firmware and in the host-side test bench of the controller (tests/sdram), which
 * provides both.
 */
#ifndef SDRAM_INIT_H
#define SDRAM_INIT_H

#include <stdint.h>

/* The mode register this sequence programs (the chip data sheet's Mode Register Definition):
 * burst length `phases` (A2..A0 = log2 of it: LiteDRAM's SDR PHY moves one word per command and
 * phase, 1 at full rate, 2 at half rate), sequential (A3 = 0), CAS latency cas_latency (A6..A4),
 * standard operation (A8..A7 = 0), programmed burst length for writes (A9 = 0), A12..A10
 * reserved 0. phases must be 1, 2, 4 or 8. */
uint32_t sdram_mode_register(uint32_t cas_latency, uint32_t phases);

/* The pins to software control at once (NOPs, CKE high): LiteDRAM leaves reset under hardware
 * control, its refresher sending PRECHARGE ALL and AUTO REFRESH every tREFI (7.8 us) to a chip
 * that has not finished its power-up wait. The boot code calls this within tREFI of reset (socsim's
 * chip model stops the run otherwise); sdram_init() calls it again. */
void sdram_take_pins(void);

/* Power-up: CKE high with NOPs for the power-up wait, PRECHARGE ALL, two AUTO REFRESH, LOAD MODE
 * REGISTER, then the controller takes the pins and init_done is set. Returns the mode register
 * value it programmed. */
uint32_t sdram_init(void);

/* Provided by the platform: wait at least ns nanoseconds. */
void sdram_delay_ns(uint32_t ns);

#endif /* SDRAM_INIT_H */
