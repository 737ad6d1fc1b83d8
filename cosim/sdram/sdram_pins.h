// sdram_pins.h — the SDRAM chip model (sdram_chip.h) on a Verilated model's pins. Both harnesses
// that play the chip (socsim's system with SDRAM, cosim/soc/soc_sdram_sim.sv, and the controller's
// bench, tests/sdram/litedram_tb_top.sv) name the pins alike: sdram_a, sdram_ba, sdram_cs_n,
// sdram_ras_n, sdram_cas_n, sdram_we_n, sdram_cke, sdram_dqm, sdram_dq_pins (DQ as resolved),
// ctrl_dq_oe (the controller drives DQ) out; chip_dq, chip_dq_oe (the chip's drive) in.
#pragma once

#include "sdram_chip.h"

// The pins as they are now.
template <typename Top>
SdramPins sdram_pins_of(const Top &top) {
    SdramPins p{};
    p.cke = top.sdram_cke;
    p.cs_n = top.sdram_cs_n;
    p.ras_n = top.sdram_ras_n;
    p.cas_n = top.sdram_cas_n;
    p.we_n = top.sdram_we_n;
    p.ba = top.sdram_ba;
    p.a = top.sdram_a;
    p.dqm = top.sdram_dqm;
    p.dq_in = top.sdram_dq_pins;
    p.dq_driven = top.ctrl_dq_oe;
    return p;
}

// The chip's drive onto the model's DQ inputs (the caller evaluates it).
template <typename Top>
void sdram_drive(Top &top, const SdramDrive &d) {
    top.chip_dq = d.dq;
    top.chip_dq_oe = d.oe;
}
