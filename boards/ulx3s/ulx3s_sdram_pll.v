// ulx3s_sdram_pll: the SDRAM build's system clocks from the board's 25 MHz oscillator, with a second
// ECP5 EHXPLLL beside ulx3s_pll (which keeps the DVI's clk_tmds and clk_pix; every ECP5 of the ULX3S
// has at least two PLLs).
//
// Contract: clk_sys = SYS_MHZ, clk_sys2x = 2 x SYS_MHZ with its rising edges on clk_sys's (LiteDRAM's
// HalfRateGENSDRPHY finds which clk_sys2x edge starts a clk_sys period and needs them aligned), and
// clk_sdram = 2 x SYS_MHZ lagging clk_sys2x by SDRAM_PHASE_DEG (of its own period; the argument
// below). All from one VCO at 500 MHz, so SYS_MHZ must be 25 or 50: 2 x SYS_MHZ divides 500 and is at
// most 100 MHz, the chip's fastest clock at CAS latency 2 (the -6 grade's tCK, 10 ns). locked rises
// once the loop has settled (ulx3s_system holds every domain in reset until both PLLs lock). clk_sys
// and ulx3s_pll's clk_pix come from different loops: every crossing between them is synchronised
// (boards/ulx3s/crossings.toml), none relies on their phase.
// Dividers: VCO = 25 MHz x CLKFB_DIV x CLKOP_DIV (feedback from CLKOP, clk_sys2x); phases counted as
// in ulx3s_pll (every output at CPHASE = DIV, one VCO period after Lattice's 0 degrees, alike; the
// lag added in eighths of a VCO period, 0.25 ns).
//
// The SDRAM clock's phase, SDRAM_PHASE_DEG = 261: 7.25 ns at 100 MHz, 3 VCO periods and 5 eighths.
// HalfRateGENSDRPHY runs LiteDRAM's GENSDRPHY on clk_sys2x: commands and write data registered in the
// I/O cells (OFS1P3BX), read data in IFS1P3BX; sdram_clk leaves through an ODDRX1F on clk_sdram, the
// same kind of I/O path, so the two global clock trees' insertion cancels. Delays are the Trellis
// database's, speed 6, min/typ/max (prjtrellis-db ECP5/timing/speed_6/cells.json: LVCMOS33
// PADDO->PAD 1.99/2.33/2.67, PADDT->PAD 2.20/2.61/3.02, PAD->PADDI 0.99/1.07/1.14; I/O register clock
// to out 1.20, ODDRX1F 0.98, input register setup 0.44), compared corner with corner. With d the lag
// and T = 10 ns the chip's clock edge is at C = d + 2.97..3.65 ns after the PHY's. The chip's figures
// (IS42S16160G, -6 and -7 alike): input setup 1.5, hold 0.8; at CAS latency 2 read data out tAC <= 6
// ns after the edge one clock after READ, held tOH >= 2.5 ns past the next. The half-rate PHY's read
// latency takes the data at the PHY's edge 3T after the command's (tests/sdram/litedram.sh: with the
// chip a whole clk2x period behind, every word right; half a period, every word a beat early). B,
// the board traces out and back, 0.8 ns (an estimate: the chip sits beside the FPGA).
//   command setup (I/O register out at 1.20 + 2.67):   C - 1.5 >= 3.87                     d >= 2.4
//   command and write hold (next from T + 3.19):        T + 3.19 - C >= 0.8                 d <= 8.7
//   read setup:                           C + T + tAC + B + 1.14 <= 3T - 0.44                d <= 8.0
//   read hold:                            C + 2T + tOH + 0.99 >= 3T + 0.31                   d >= 3.9
//   write data with the output enable:    C - 1.5 >= OE                         d >= OE - 1.47
// LiteDRAM registers DQ's output enable in the fabric (one flop, its inverted output to 16 pads):
// OE = 6.6..8.1 ns typical, 7.5..9.2 slow, in six SDRAM builds' routed delays (the 1:1 PHY's
// measurement, the same path now on clk_sys2x), so a write after a read or an idle clock needs d >=
// 5.1..6.6 typical, 6.0..7.7 slow. d = 7.25 ns sits between that bound and the read setup: 0.6..2.1
// ns to the write bound at typical delays (-0.5..1.2 at the slow corner) and 0.7 ns to the read bound.
// LiteX's ULX3S target drives the same PHY's clock at 180 degrees (5.0 ns), under the write bound
// here. nextpnr does not time these pin paths (the constraints give no I/O timing): this argument
// is their check, not yet confirmed on a board.
`default_nettype none

module ulx3s_sdram_pll #(
    parameter integer SYS_MHZ = 50,           // 25 or 50: clk_sys2x is twice it
    parameter integer SDRAM_PHASE_DEG = 261,  // clk_sdram's lag behind clk_sys2x (the argument above)
    localparam integer VCO_MHZ = 500,
    localparam integer DIV_2X = VCO_MHZ / (2 * SYS_MHZ),       // clk_sys2x and clk_sdram
    localparam integer FB_DIV = 2 * SYS_MHZ / 25,              // CLKOP (clk_sys2x) / the 25 MHz input
    // the lag in eighths of a VCO period, rounded to the nearest (LiteX's round(deg x DIV / 45))
    localparam integer SDRAM_LAG_8THS = (SDRAM_PHASE_DEG * DIV_2X * 8 + 180) / 360
) (
    input  wire clk_25mhz,    // the board's oscillator (G2)
    output wire clk_sys,      // SYS_MHZ
    output wire clk_sys2x,    // 2 x SYS_MHZ, rising edges on clk_sys's
    output wire clk_sdram,    // 2 x SYS_MHZ, SDRAM_PHASE_DEG after clk_sys2x
    output wire locked
);
    generate if (SYS_MHZ != 25 && SYS_MHZ != 50) begin : g_bad_sys
        $error("ulx3s_sdram_pll: SYS_MHZ must be 25 or 50 (the SDRAM at twice it, at most 100 MHz)");
    end endgenerate
    generate if (SDRAM_PHASE_DEG < 0 || SDRAM_PHASE_DEG >= 360) begin : g_bad_phase
        $error("ulx3s_sdram_pll: SDRAM_PHASE_DEG must be 0..359");
    end endgenerate

    wire pll_clkos3, pll_clkintfb, pll_intlock, pll_refclk;  // outputs this design does not use
    wire unused_pll = pll_clkos3 | pll_clkintfb | pll_intlock | pll_refclk;

    (* FREQUENCY_PIN_CLKI = "25" *)
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
        .CLKFB_DIV        (FB_DIV),
        .CLKOP_ENABLE     ("ENABLED"),
        .CLKOP_DIV        (DIV_2X),
        .CLKOP_CPHASE     (DIV_2X),
        .CLKOP_FPHASE     (0),
        .CLKOS_ENABLE     ("ENABLED"),
        .CLKOS_DIV        (2 * DIV_2X),
        .CLKOS_CPHASE     (2 * DIV_2X),
        .CLKOS_FPHASE     (0),
        .CLKOS2_ENABLE    ("ENABLED"),
        .CLKOS2_DIV       (DIV_2X),
        .CLKOS2_CPHASE    (DIV_2X + SDRAM_LAG_8THS / 8),
        .CLKOS2_FPHASE    (SDRAM_LAG_8THS % 8),
        .CLKOS3_ENABLE    ("DISABLED"),
        .CLKOS3_DIV       (8),
        .CLKOS3_CPHASE    (0),
        .CLKOS3_FPHASE    (0)
    ) u_pll (
        .RST          (1'b0),
        .STDBY        (1'b0),
        .CLKI         (clk_25mhz),
        .CLKOP        (clk_sys2x),
        .CLKOS        (clk_sys),
        .CLKOS2       (clk_sdram),
        .CLKOS3       (pll_clkos3),
        .CLKFB        (clk_sys2x),
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
