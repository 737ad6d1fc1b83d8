// ulx3s_pll: the board's clocks from its 25 MHz oscillator, with one ECP5 EHXPLLL.
//
// Contract: clk_tmds = 125 MHz (the DVI bit clock, 10 bits a pixel sent on both edges), clk_pix =
// 25 MHz (640x480@60), clk_sys = SYS_MHZ; all from one VCO at 750 MHz, so they are related (the DVI
// serialiser relies on clk_tmds = 5 x clk_pix). With SYS_CLK = 0 (the SDRAM build, whose system
// clock comes from ulx3s_sdram_pll) the third output is off and clk_sys is 0; the fourth is always
// off. locked rises once the loop has settled; until then the clocks are not to be trusted
// (ulx3s_system holds every domain in reset).
// Dividers: VCO = 25 MHz x CLKFB_DIV 5 x CLKOP_DIV 6 (feedback from CLKOP, 125 MHz); CLKOS = VCO / 30;
// CLKOS2 = VCO / (750 / SYS_MHZ), so SYS_MHZ must divide 750: 25, 30, 50, 75 or 125. The VCO range of
// the ECP5 PLL is 400..800 MHz (Lattice TN1263).
//
// Phases. Each output X has CLKOX_CPHASE (whole VCO periods, 1.33 ns) and CLKOX_FPHASE (eighths of
// one, 0.167 ns). Lattice's own tools put 0 degrees at CPHASE = DIV - 1, FPHASE = 0: Diamond's
// generated ECP5 PLLs show it (CLKOP_DIV 6 / CPHASE 5 with CLKOS_DIV 3 / CPHASE 2 in
// johonkanen/tube_amplifier_power_supply lfe5u/ip_cores/main_pll/main_pll_prim.v, Diamond 3.11;
// CLKOP_DIV 3 / CPHASE 2 with CLKOS_DIV 6 / CPHASE 5 in piotrmatera/lkd-5-15-up-fpga-software
// FPGA/Clarity/PLL_DSP/PLL_DSP_prim.v, Diamond 3.12), and LiteX's ECP5PLL computes the same
// (litex/soc/cores/clock/lattice_ecp5.py, 2024.12 in the venv: CPHASE = lag_eighths / 8 + DIV - 1,
// FPHASE = lag_eighths % 8, lag_eighths = round(degrees x DIV / 45); its commit 6636560c "Fix phase
// calculation to match Diamond output"). prjtrellis' ecppll counts from CLKOP's half period
// instead, and says its own output may be refused by Diamond 3.10 for "wrong CPHASE/FPHASE". This
// file has set every output to CPHASE = DIV since before the SDRAM: one VCO period after Lattice's
// 0 degrees on each of them alike, the feedback output CLKOP included, so the loop moves them all
// back together and their relations to one another are those of 0 degrees (kept, so that the build
// without SDRAM stays as it was). ulx3s_sdram_pll, which shifts one output, counts its lag the same
// way.
`default_nettype none

module ulx3s_pll #(
    parameter integer SYS_MHZ = 50,          // system clock: a divisor of 750
    parameter integer SYS_CLK = 1,           // 0: CLKOS2 off (the system clock is made elsewhere)
    localparam integer VCO_MHZ = 750,
    localparam integer SYS_DIV = VCO_MHZ / SYS_MHZ
) (
    input  wire clk_25mhz,    // the board's oscillator (G2)
    output wire clk_tmds,     // 125 MHz
    output wire clk_pix,      // 25 MHz
    output wire clk_sys,      // SYS_MHZ (SYS_CLK = 1)
    output wire locked
);
    generate if (SYS_DIV * SYS_MHZ != VCO_MHZ || SYS_DIV < 1 || SYS_DIV > 128) begin : g_bad_sys
        $error("ulx3s_pll: SYS_MHZ must divide 750 (25, 30, 50, 75, 125)");
    end endgenerate

    wire pll_clkos3, pll_clkintfb, pll_intlock, pll_refclk;  // outputs this design does not use
    wire unused_pll = pll_clkos3 | pll_clkintfb | pll_intlock | pll_refclk;

    // An output switched off keeps the primitive's defaults (DIV 8, phase 0).
    localparam OS2_ENABLE = SYS_CLK != 0 ? "ENABLED" : "DISABLED";
    localparam integer OS2_DIV = SYS_CLK != 0 ? SYS_DIV : 8;
    localparam integer OS2_CPHASE = SYS_CLK != 0 ? SYS_DIV : 0;

    (* FREQUENCY_PIN_CLKI = "25" *)
    (* FREQUENCY_PIN_CLKOP = "125" *)
    (* FREQUENCY_PIN_CLKOS = "25" *)
    (* ICP_CURRENT = "12" *) (* LPF_RESISTOR = "8" *) (* MFG_ENABLE_FILTEROPAMP = "1" *)
    (* MFG_GMCREF_SEL = "2" *)
    EHXPLLL #(
        .PLLRST_ENA       ("DISABLED"),
        .INTFB_WAKE       ("DISABLED"),
        .STDBY_ENABLE     ("DISABLED"),
        .DPHASE_SOURCE    ("DISABLED"),
        .OUTDIVIDER_MUXA  ("DIVA"),
        .OUTDIVIDER_MUXB  ("DIVB"),
        .OUTDIVIDER_MUXC  ("DIVC"),
        .OUTDIVIDER_MUXD  ("DIVD"),
        .CLKI_DIV         (1),
        .FEEDBK_PATH      ("CLKOP"),
        .CLKFB_DIV        (5),
        .CLKOP_ENABLE     ("ENABLED"),
        .CLKOP_DIV        (6),
        .CLKOP_CPHASE     (6),
        .CLKOP_FPHASE     (0),
        .CLKOS_ENABLE     ("ENABLED"),
        .CLKOS_DIV        (30),
        .CLKOS_CPHASE     (30),
        .CLKOS_FPHASE     (0),
        .CLKOS2_ENABLE    (OS2_ENABLE),
        .CLKOS2_DIV       (OS2_DIV),
        .CLKOS2_CPHASE    (OS2_CPHASE),
        .CLKOS2_FPHASE    (0),
        .CLKOS3_ENABLE    ("DISABLED"),
        .CLKOS3_DIV       (8),
        .CLKOS3_CPHASE    (0),
        .CLKOS3_FPHASE    (0)
    ) u_pll (
        .RST          (1'b0),
        .STDBY        (1'b0),
        .CLKI         (clk_25mhz),
        .CLKOP        (clk_tmds),
        .CLKOS        (clk_pix),
        .CLKOS2       (clk_sys),
        .CLKOS3       (pll_clkos3),
        .CLKFB        (clk_tmds),
        .CLKINTFB     (pll_clkintfb),
        .PHASESEL0    (1'b0),
        .PHASESEL1    (1'b0),
        .PHASEDIR     (1'b1),
        .PHASESTEP    (1'b1),
        .PHASELOADREG (1'b1),
        .PLLWAKESYNC  (1'b0),
        .ENCLKOP      (1'b0),
        .ENCLKOS      (1'b0),
        .ENCLKOS2     (1'b0),
        .ENCLKOS3     (1'b0),
        .LOCK         (locked),
        .INTLOCK      (pll_intlock),
        .REFCLK       (pll_refclk)
    );
endmodule

`default_nettype wire
