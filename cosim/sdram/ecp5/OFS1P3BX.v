// OFS1P3BX: an ECP5 output register in the I/O cell (Lattice FPGA Libraries Reference Guide: positive
// edge, clock enable SP, asynchronous preset PD, GSR ignored), as LiteDRAM's generated SDR PHY
// (soc_rtl/litedram) registers the SDRAM's outputs with it; for the RTL simulations.
// Contract: PD high sets Q to 1 at once; otherwise at each rising SCLK edge Q takes D if SP is high.
// Power-up value 1 (the preset type, as GSR would leave it).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDPARAM
module OFS1P3BX (
    input  wire D,      // data
    input  wire SP,     // clock enable
    input  wire SCLK,   // clock
    input  wire PD,     // asynchronous preset, active high
    output reg  Q = 1'b1
);
    parameter GSR = "ENABLED";  // global set/reset: not modelled (the simulations have none)

    always @(posedge SCLK or posedge PD)
        if (PD)
            Q <= 1'b1;
        else if (SP)
            Q <= D;
endmodule

`default_nettype wire
