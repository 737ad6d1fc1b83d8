// BUFG: a lint-only stand-in for the Xilinx global clock buffer (UG953), so that Verilator lints the
// Digilent tops (boards/digilent/lint.sh). Never synthesised: yosys and Vivado have the real one.
`default_nettype none

module BUFG (
    input  wire I,
    output wire O
);
    assign O = I;
endmodule

`default_nettype wire
