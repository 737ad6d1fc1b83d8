// digilent_clocks: the clocks of the Digilent Artix-7 builds (Basys3, Nexys A7-100T) — from the
// boards' 100 MHz oscillator, one MMCME2_BASE makes the system clock (SYS_MHZ) and the 25 MHz VGA
// pixel clock, each on a BUFG.
//
// Contract: locked (asynchronous) rises once both outputs run at their frequencies; the user holds
// every domain in reset until then (digilent_top drives soc_top's ext_rst with !locked).
// The MMCM (7 Series clocking guide UG472; ranges from the Artix-7 data sheet DS181, -1 speed grade):
//   VCO = 100 MHz x CLKFBOUT_MULT_F 10.0 / DIVCLK_DIVIDE 1 = 1000 MHz, inside the -1 grade's
//         600..1200 MHz (the PFD sees 100 MHz, inside 10..450 MHz);
//   clk_sys = VCO / CLKOUT0_DIVIDE_F (1000 / SYS_MHZ: 20.0 -> 50 MHz; a fractional divider in steps
//         of 1/8 from 2.0 to 128.0, so SYS_MHZ must divide 8000 and lie in 8..200 MHz here);
//   clk_pix = VCO / CLKOUT1_DIVIDE 40 = 25 MHz.
// The feedback loops CLKFBOUT straight to CLKFBIN (no BUFG): the outputs need no phase relation to
// the oscillator, and the two outputs keep theirs (they share the VCO), though the design treats
// them as asynchronous anyway (see the boards' XDC).
`default_nettype none

module digilent_clocks #(
    parameter integer SYS_MHZ = 50,                  // the system clock (a divisor of 8000, 8..200)
    localparam integer VCO_MHZ = 1000,               // 100 MHz x 10
    localparam integer PIX_DIV = VCO_MHZ / 25        // 40: 25 MHz
) (
    input  wire clk_100mhz,     // the board's oscillator (10 ns)
    output wire clk_sys,        // SYS_MHZ, on a BUFG
    output wire clk_pix,        // 25 MHz, on a BUFG
    output wire locked          // asynchronous
);
    generate if (8 * VCO_MHZ % SYS_MHZ != 0 || SYS_MHZ < 8 || SYS_MHZ > 200) begin : g_bad_sys_mhz
        $error("digilent_clocks: SYS_MHZ must divide 8000 and lie in 8..200 (CLKOUT0_DIVIDE_F = 1000 / SYS_MHZ)");
    end endgenerate

    wire clkfb, clk_sys_mmcm, clk_pix_mmcm;
    wire [9:0] unused_out;                           // the MMCM outputs not used

    MMCME2_BASE #(
        .BANDWIDTH          ("OPTIMIZED"),
        .CLKIN1_PERIOD      (10.0),                  // 100 MHz
        .DIVCLK_DIVIDE      (1),
        .CLKFBOUT_MULT_F    (10.0),                  // VCO 1000 MHz
        .CLKFBOUT_PHASE     (0.0),
        .CLKOUT0_DIVIDE_F   (1.0 * VCO_MHZ / SYS_MHZ),
        .CLKOUT0_DUTY_CYCLE (0.5),
        .CLKOUT0_PHASE      (0.0),
        .CLKOUT1_DIVIDE     (PIX_DIV),
        .CLKOUT1_DUTY_CYCLE (0.5),
        .CLKOUT1_PHASE      (0.0),
        .REF_JITTER1        (0.010),
        .STARTUP_WAIT       ("FALSE")
    ) u_mmcm (
        .CLKIN1    (clk_100mhz),
        .CLKFBIN   (clkfb),
        .CLKFBOUT  (clkfb),
        .CLKFBOUTB (unused_out[0]),
        .CLKOUT0   (clk_sys_mmcm),
        .CLKOUT0B  (unused_out[1]),
        .CLKOUT1   (clk_pix_mmcm),
        .CLKOUT1B  (unused_out[2]),
        .CLKOUT2   (unused_out[3]),
        .CLKOUT2B  (unused_out[4]),
        .CLKOUT3   (unused_out[5]),
        .CLKOUT3B  (unused_out[6]),
        .CLKOUT4   (unused_out[7]),
        .CLKOUT5   (unused_out[8]),
        .CLKOUT6   (unused_out[9]),
        .LOCKED    (locked),
        .PWRDWN    (1'b0),
        .RST       (1'b0)
    );

    BUFG u_bufg_sys (
        .I (clk_sys_mmcm),
        .O (clk_sys)
    );

    BUFG u_bufg_pix (
        .I (clk_pix_mmcm),
        .O (clk_pix)
    );
endmodule

`default_nettype wire
