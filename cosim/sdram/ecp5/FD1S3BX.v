// FD1S3BX: an ECP5 fabric flip-flop with asynchronous preset (Lattice FPGA Libraries Reference
// Guide), as LiteDRAM's generated core (soc_rtl/litedram) builds its reset synchroniser from two;
// for the RTL simulations.
// Contract: PD high sets Q to 1 at once; otherwise Q takes D at each rising CK edge. Power-up 1.
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDPARAM
module FD1S3BX (
    input  wire D,      // data
    input  wire CK,     // clock
    input  wire PD,     // asynchronous preset, active high
    output reg  Q = 1'b1
);
    parameter GSR = "ENABLED";  // global set/reset: not modelled (the simulations have none)

    always @(posedge CK or posedge PD)
        if (PD)
            Q <= 1'b1;
        else
            Q <= D;
endmodule

`default_nettype wire
