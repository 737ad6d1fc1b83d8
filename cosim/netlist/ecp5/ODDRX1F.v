// ODDRX1F: the ECP5's generic x1 DDR output register (Lattice FPGA-TN-02035, "ECP5 and ECP5-5G
// High-Speed I/O Interface": ODDRX1F sends D0 on the rising and D1 on the falling edge of SCLK), for
// netlist simulation (make netlist-sim, cosim/netlist) — yosys ships only a black box.
//
// Contract: at each rising edge of SCLK both inputs are registered; Q carries that D0 while SCLK is
// high and that D1 while it is low — two bits a clock, D0 first, each for half a period. RST (active
// high) clears both registers, as the primitive's reset does. The fixed latency of the real IOLOGIC
// is left out: it delays the whole stream alike, which changes nothing a receiver decodes.
// Unit test: tests/boards/netlist_cells.sh (the serial stream against the pairs driven).
`default_nettype none

// verilator lint_off DECLFILENAME
module ODDRX1F (
    input  wire SCLK,   // the bit-pair clock
    input  wire RST,    // clears the registers (high)
    input  wire D0,     // sent first, while SCLK is high
    input  wire D1,     // sent second, while SCLK is low
    output wire Q       // the pin
);
    /* verilator lint_off UNUSEDPARAM */
    parameter GSR = "ENABLED";  // the global set/reset's enable: the netlist simulation has no GSR
    /* verilator lint_on UNUSEDPARAM */

    reg d0_q = 1'b0, d1_q = 1'b0;
    always @(posedge SCLK or posedge RST) begin
        if (RST) begin
            d0_q <= 1'b0;
            d1_q <= 1'b0;
        end else begin
            d0_q <= D0;
            d1_q <= D1;
        end
    end
    assign Q = SCLK ? d0_q : d1_q;
endmodule

`default_nettype wire
