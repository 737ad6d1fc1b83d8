// ulx3s_pll: the board's clocks from its 25 MHz oscillator, with one ECP5 EHXPLLL.
//
// Contract: clk_tmds = 125 MHz (the DVI bit clock, 10 bits a pixel sent on both edges), clk_pix =
// 25 MHz (640x480@60), clk_sys = SYS_MHZ; all from one VCO at 750 MHz, so they are related (the DVI
// serialiser relies on clk_tmds = 5 x clk_pix). With SDRAM_CLK = 1 (the SDRAM build), clk_sdram =
// SYS_MHZ too, lagging clk_sys by SDRAM_PHASE_DEG (below); with 0 the fourth output stays off, as it
// is in the build without SDRAM, and clk_sdram is 0. locked rises once the loop has settled; until
// then the clocks are not to be trusted (ulx3s_system holds every domain in reset).
// Dividers: VCO = 25 MHz x CLKFB_DIV 5 x CLKOP_DIV 6 (feedback from CLKOP, 125 MHz); CLKOS = VCO / 30;
// CLKOS2 and CLKOS3 = VCO / (750 / SYS_MHZ), so SYS_MHZ must divide 750: 25, 30, 50, 75 or 125. The
// VCO range of the ECP5 PLL is 400..800 MHz (Lattice TN1263).
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
// without SDRAM stays as it was). CLKOS3's lag is therefore counted from CLKOS2's setting: CPHASE =
// SYS_DIV + lag_eighths / 8, FPHASE = lag_eighths % 8, larger meaning later (Diamond, LiteX, ecppll
// agree on that direction).
//
// The SDRAM clock's phase, SDRAM_PHASE_DEG = 126: 7.0 ns at 50 MHz, 5 VCO periods and 2 eighths.
// LiteDRAM's GENSDRPHY registers commands and write data in the I/O cells (OFS1P3BX) and read data in
// IFS1P3BX, all on clk_sys; sdram_clk leaves through an ODDRX1F on clk_sdram, the same kind of I/O
// path, so the two global clock trees' insertion cancels. Delays are the Trellis database's, speed 6,
// min/typ/max (prjtrellis-db ECP5/timing/speed_6/cells.json: LVCMOS33 PADDO->PAD 1.99/2.33/2.67,
// PADDT->PAD 2.20/2.61/3.02, PAD->PADDI 0.99/1.07/1.14; I/O register clock to out 1.20, ODDRX1F 0.98,
// input register setup 0.44), compared corner with corner. With d the lag and T = 20 ns the chip's
// clock edge is at C = d + 2.97..3.65 ns after the controller's. The chip's figures (those of the
// related AS4C32M16SB / IS42S16800A, /work/notes/board_research.md; to check against the IS42S16160G
// data sheet): input setup 1.5, hold 0.8; CAS latency 2 puts read data out tAC <= 6 ns after the edge
// one clock after READ, held tOH >= 2.5 ns past the next; the PHY samples it 2T after the command's
// edge. B, the board traces out and back, is taken as 0.8 ns (an estimate: the chip sits beside the
// FPGA).
//   command setup (I/O register out at 1.20 + 2.67):   C - 1.5 >= 3.87                     d >= 1.7
//   write hold (next edge's data no sooner than 3.19):  23.19 - C >= 0.8                     d <= 18.7
//   read setup:                           C + T + tAC + B + 1.14 <= 2T - 0.44                d <= 8.0
//   read hold:                            C + 2T + tOH + 0.99 >= 2T + 0.31                   d >= -6.2
//   write data with the output enable:    C - 1.5 >= OE
// The last moved the choice from LiteX's 90 degrees (its ULX3S target, the same PHY; the research
// note's window, 45..155 degrees, is the first four with the corners mixed): LiteDRAM registers
// DQ's output enable in the fabric, not the I/O cells, and yosys merges its 16 flops into one,
// whose inverted output (one LUT4) reaches the 16 DQ pads, 18 columns of I/O apart, across the
// chip. In six SDRAM builds of these files (85F and 45F, three placements each; nextpnr's routed
// delays, --sdf): flop 0.48 + 0.71 + LUT 0.22 + 2.6..4.1 of routing to the farthest pad + PADDT
// 2.61 = OE 6.6..8.1 ns typical, 7.5..9.2 at the slow corner. A write that follows a read or an
// idle clock then needs d >= 4.8..6.3 ns typical, 5.4..7.1 slow: 90 degrees (5.0 ns) fails it in
// four of the six even at typical delays. So d is placed between that bound and the read bound: 7.0
// ns leaves 0.7..2.2 ns to the write bound at typical delays (-0.1..1.6 at the slow corner; 1.6 and
// 2.2 typical in the builds of 323a186), and 1.4 ns to the read bound (1.0 at the slow
// corner). The output-enable path changes with placement; with the enables registered in the I/O
// cells (one flop per pad, marked syn_useioff for nextpnr to pack) the window would be 1.7..8.0 ns
// and about 90 degrees its centre again. nextpnr does not time these pin paths (the constraints
// give no I/O timing): this argument is their check.
`default_nettype none

module ulx3s_pll #(
    parameter integer SYS_MHZ = 50,          // system clock: a divisor of 750
    parameter integer SDRAM_CLK = 0,         // 1: clk_sdram on CLKOS3 (the SDRAM build); 0: CLKOS3 off
    parameter integer SDRAM_PHASE_DEG = 126, // clk_sdram's lag behind clk_sys (the argument above)
    localparam integer VCO_MHZ = 750,
    localparam integer SYS_DIV = VCO_MHZ / SYS_MHZ,
    // the lag in eighths of a VCO period, rounded to the nearest (LiteX's round(deg x DIV / 45))
    localparam integer SDRAM_LAG_8THS = (SDRAM_PHASE_DEG * SYS_DIV * 8 + 180) / 360
) (
    input  wire clk_25mhz,    // the board's oscillator (G2)
    output wire clk_tmds,     // 125 MHz
    output wire clk_pix,      // 25 MHz
    output wire clk_sys,      // SYS_MHZ
    output wire clk_sdram,    // SYS_MHZ, SDRAM_PHASE_DEG after clk_sys (SDRAM_CLK = 1)
    output wire locked
);
    generate if (SYS_DIV * SYS_MHZ != VCO_MHZ || SYS_DIV < 1 || SYS_DIV > 128) begin : g_bad_sys
        $error("ulx3s_pll: SYS_MHZ must divide 750 (25, 30, 50, 75, 125)");
    end endgenerate
    generate if (SDRAM_PHASE_DEG < 0 || SDRAM_PHASE_DEG >= 360) begin : g_bad_phase
        $error("ulx3s_pll: SDRAM_PHASE_DEG must be 0..359");
    end endgenerate

    wire pll_clkintfb, pll_intlock, pll_refclk;  // outputs this design does not use
    wire unused_pll = pll_clkintfb | pll_intlock | pll_refclk;

    // Without SDRAM_CLK, CLKOS3's parameters are the primitive's defaults (disabled, DIV 8, phase 0).
    localparam OS3_ENABLE = SDRAM_CLK != 0 ? "ENABLED" : "DISABLED";
    localparam integer OS3_DIV = SDRAM_CLK != 0 ? SYS_DIV : 8;
    localparam integer OS3_CPHASE = SDRAM_CLK != 0 ? SYS_DIV + SDRAM_LAG_8THS / 8 : 0;
    localparam integer OS3_FPHASE = SDRAM_CLK != 0 ? SDRAM_LAG_8THS % 8 : 0;

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
        .CLKOS2_FPHASE    (0),
        .CLKOS3_ENABLE    (OS3_ENABLE),
        .CLKOS3_DIV       (OS3_DIV),
        .CLKOS3_CPHASE    (OS3_CPHASE),
        .CLKOS3_FPHASE    (OS3_FPHASE)
    ) u_pll (
        .RST          (1'b0),
        .STDBY        (1'b0),
        .CLKI         (clk_25mhz),
        .CLKOP        (clk_tmds),
        .CLKOS        (clk_pix),
        .CLKOS2       (clk_sys),
        .CLKOS3       (clk_sdram),
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
