/*
 * sdram_init.c — the SDRAM's power-up sequence through LiteDRAM's DFI software interface
 * (sdram_init.h). The waits are the chip's (ISSI IS42S16160G data sheet, power-up and
 * initialisation; the timing table of its slowest speed grade), each longer than the chip needs
 * at any clock: the register writes between commands take longer still.
 */
#include <generated/csr.h>
#include <generated/sdram_phy.h>

#include "sdram_init.h"

enum {
    SDRAM_POWER_UP_WAIT_NS = 200000u,  /* clock and CKE stable, NOPs only, before the first command */
    SDRAM_T_RP_NS          = 20u,      /* PRECHARGE to the next command */
    SDRAM_T_RC_NS          = 70u,      /* AUTO REFRESH to the next command (tRC = tRFC) */
    SDRAM_T_MRD_NS         = 60u,      /* LOAD MODE REGISTER to the next command (2 clocks at 33 MHz) */
};

/* Address bit 10 of PRECHARGE: all banks. */
#define SDRAM_A10_ALL_BANKS 0x400u

uint32_t sdram_mode_register(uint32_t cas_latency, uint32_t phases)
{
    uint32_t burst_code = 0u;
    while ((1u << burst_code) < phases && burst_code < 3u) {
        burst_code++;
    }
    return ((cas_latency & 0x7u) << 4) | burst_code;
}

/* One command on the DFI's phase 0 with the chip selected; RAS/CAS/WE as the command's truth table. */
static void sdram_command(uint32_t command, uint32_t address, uint32_t wait_ns)
{
    sdram_dfii_pi0_address_write(address);
    sdram_dfii_pi0_baddress_write(0u);
    sdram_dfii_pi0_command_write(command | DFII_COMMAND_CS);
    sdram_dfii_pi0_command_issue_write(1u);
    sdram_delay_ns(wait_ns);
}

void sdram_take_pins(void)
{
    /* Software control of the pins (SEL clear), CKE high: NOPs until the next command. */
    sdram_dfii_control_write(DFII_CONTROL_CKE | DFII_CONTROL_ODT | DFII_CONTROL_RESET_N);
}

uint32_t sdram_init(void)
{
    const uint32_t mode = sdram_mode_register(SDRAM_PHY_CL, SDRAM_PHY_PHASES);

    sdram_take_pins();
    sdram_delay_ns(SDRAM_POWER_UP_WAIT_NS);

    sdram_command(DFII_COMMAND_RAS | DFII_COMMAND_WE, SDRAM_A10_ALL_BANKS, SDRAM_T_RP_NS);
    sdram_command(DFII_COMMAND_RAS | DFII_COMMAND_CAS, 0u, SDRAM_T_RC_NS);
    sdram_command(DFII_COMMAND_RAS | DFII_COMMAND_CAS, 0u, SDRAM_T_RC_NS);
    sdram_command(DFII_COMMAND_RAS | DFII_COMMAND_CAS | DFII_COMMAND_WE, mode, SDRAM_T_MRD_NS);

    /* The controller takes the pins (and refreshes from now on). */
    sdram_dfii_control_write(DFII_CONTROL_SEL | DFII_CONTROL_CKE | DFII_CONTROL_ODT | DFII_CONTROL_RESET_N);
    ddrctrl_init_done_write(1u);
    return mode;
}
