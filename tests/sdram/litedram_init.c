/*
 * litedram_init.c — LiteDRAM's own power-up sequence for tests/sdram's bench (litedram_tb
 * --init litedram): the generated init_sequence() of <generated/sdram_phy.h>, then the pins to the
 * controller and init_done, as LiteX's BIOS does for an SDR chip (liblitedram's sdram_init: no
 * leveling). Run against the chip model to show what the chip's data sheet says of it
 * (docs/sdram.md); the SoC's firmware uses bsp/soc/sdram/sdram_init.c instead.
 */
#include <generated/csr.h>
#include <generated/sdram_phy.h>

void litedram_init_sequence(void);

void litedram_init_sequence(void)
{
    init_sequence();
    sdram_dfii_control_write(DFII_CONTROL_SEL | DFII_CONTROL_CKE | DFII_CONTROL_ODT | DFII_CONTROL_RESET_N);
    ddrctrl_init_done_write(1u);
}
