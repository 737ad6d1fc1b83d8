// MMCME2_BASE: a lint-only stand-in for the Xilinx 7 Series MMCM (UG953) — the parameters and ports
// digilent_clocks uses, with the primitive's names and types; CLKOUT0/CLKOUT1 follow CLKIN1 and
// LOCKED is 1, which is no model of the MMCM, only enough for Verilator --lint-only
// (boards/digilent/lint.sh). Never synthesised: yosys and Vivado have the real one.
`default_nettype none

module MMCME2_BASE #(
    parameter BANDWIDTH = "OPTIMIZED",
    parameter real CLKIN1_PERIOD = 0.0,
    parameter integer DIVCLK_DIVIDE = 1,
    parameter real CLKFBOUT_MULT_F = 5.0,
    parameter real CLKFBOUT_PHASE = 0.0,
    parameter real CLKOUT0_DIVIDE_F = 1.0,
    parameter real CLKOUT0_DUTY_CYCLE = 0.5,
    parameter real CLKOUT0_PHASE = 0.0,
    parameter integer CLKOUT1_DIVIDE = 1,
    parameter real CLKOUT1_DUTY_CYCLE = 0.5,
    parameter real CLKOUT1_PHASE = 0.0,
    parameter real REF_JITTER1 = 0.010,
    parameter STARTUP_WAIT = "FALSE"
) (
    input  wire CLKIN1,
    input  wire CLKFBIN,
    input  wire PWRDWN,
    input  wire RST,
    output wire CLKFBOUT,
    output wire CLKFBOUTB,
    output wire CLKOUT0,
    output wire CLKOUT0B,
    output wire CLKOUT1,
    output wire CLKOUT1B,
    output wire CLKOUT2,
    output wire CLKOUT2B,
    output wire CLKOUT3,
    output wire CLKOUT3B,
    output wire CLKOUT4,
    output wire CLKOUT5,
    output wire CLKOUT6,
    output wire LOCKED
);
    assign CLKFBOUT = CLKIN1;
    assign CLKFBOUTB = !CLKIN1;
    assign CLKOUT0 = CLKIN1;
    assign CLKOUT0B = !CLKIN1;
    assign CLKOUT1 = CLKIN1;
    assign CLKOUT1B = !CLKIN1;
    assign CLKOUT2 = 1'b0;
    assign CLKOUT2B = 1'b0;
    assign CLKOUT3 = 1'b0;
    assign CLKOUT3B = 1'b0;
    assign CLKOUT4 = 1'b0;
    assign CLKOUT5 = 1'b0;
    assign CLKOUT6 = 1'b0;
    assign LOCKED = 1'b1;
    wire unused = CLKFBIN | PWRDWN | RST;
endmodule

`default_nettype wire
