// ulx3s_pll: the board's clocks from its 25 MHz oscillator, with one ECP5 EHXPLLL.
//
// Contract: clk_tmds = 125 MHz (the DVI bit clock, 10 bits a pixel sent on both edges), clk_pix =
// 25 MHz (640x480@60), clk_sys = SYS_MHZ; all three from one VCO at 750 MHz, so they are related
// (the DVI serialiser relies on clk_tmds = 5 x clk_pix). locked rises once the loop has settled;
// until then the clocks are not to be trusted (ulx3s_system holds every domain in reset).
// Dividers: VCO = 25 MHz x CLKFB_DIV 5 x CLKOP_DIV 6 (feedback from CLKOP, 125 MHz); CLKOS = VCO / 30;
// CLKOS2 = VCO / (750 / SYS_MHZ), so SYS_MHZ must divide 750: 25, 30, 50, 75 or 125. The VCO range
// of the ECP5 PLL is 400..800 MHz (Lattice TN1263). Phases: each output's coarse phase CPHASE equal
// to its divider, fine phase 0, as LiteX's ECP5 PLL sets them for 0 degrees.
`default_nettype none

module ulx3s_pll #(
    parameter integer SYS_MHZ = 50,          // system clock: a divisor of 750
    localparam integer VCO_MHZ = 750,
    localparam integer SYS_DIV = VCO_MHZ / SYS_MHZ
) (
    input  wire clk_25mhz,    // the board's oscillator (G2)
    output wire clk_tmds,     // 125 MHz
    output wire clk_pix,      // 25 MHz
    output wire clk_sys,      // SYS_MHZ
    output wire locked
);
    generate if (SYS_DIV * SYS_MHZ != VCO_MHZ || SYS_DIV < 1 || SYS_DIV > 128) begin : g_bad_sys
        $error("ulx3s_pll: SYS_MHZ must divide 750 (25, 30, 50, 75, 125)");
    end endgenerate

    wire pll_clkos3, pll_clkintfb, pll_intlock, pll_refclk;  // outputs this design does not use
    wire unused_pll = pll_clkos3 | pll_clkintfb | pll_intlock | pll_refclk;

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
        .CLKOS2_ENABLE    ("ENABLED"),
        .CLKOS2_DIV       (SYS_DIV),
        .CLKOS2_CPHASE    (SYS_DIV),
        .CLKOS2_FPHASE    (0)
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
