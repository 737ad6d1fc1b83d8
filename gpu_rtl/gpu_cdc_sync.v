// gpu_cdc_sync: a level crossing into the clock domain of clk — the one synchroniser of the GPU.
//
// Contract: out follows in (a signal of another clock domain, or asynchronous) STAGES clocks of clk
// later. For a single bit, or a multi-bit value only when it is constant while it crosses (the
// caller's argument, stated where it is used): each bit resolves on its own, so a changing word
// may be seen half old, half new for one clock. The first flop may go metastable; it has a whole
// clock to settle before the second samples it. RESET_VALUE is the output at configuration, so a
// reset that crosses here is held from power-on (the flops need no reset of their own).
`default_nettype none

module gpu_cdc_sync #(
    parameter integer WIDTH = 1,
    parameter integer STAGES = 2,           // >= 2; more for a faster clock than the GPU's
    parameter [WIDTH-1:0] RESET_VALUE = {WIDTH{1'b0}}
) (
    input  wire             clk,            // destination clock
    input  wire [WIDTH-1:0] in,             // source domain (or asynchronous)
    output wire [WIDTH-1:0] out             // clk domain
`ifdef FORMAL
    ,
    // Formal only: the flops, stage k in bits k*WIDTH +: WIDTH, for a caller's invariants (yosys
    // reads no hierarchical names such as u_sync.sync_q; gpu_cdc_pulse's proof names its flops).
    output wire [STAGES*WIDTH-1:0] f_sync
`endif
);
    (* ASYNC_REG = "TRUE" *) reg [WIDTH-1:0] sync_q [0:STAGES-1];
    integer i;
    initial begin
        for (i = 0; i < STAGES; i = i + 1) sync_q[i] = RESET_VALUE;
    end
    always @(posedge clk) begin
        sync_q[0] <= in;
        for (i = 1; i < STAGES; i = i + 1) sync_q[i] <= sync_q[i - 1];
    end
    assign out = sync_q[STAGES - 1];

`ifdef FORMAL
    genvar f_k;
    generate for (f_k = 0; f_k < STAGES; f_k = f_k + 1) begin : g_f_sync
        assign f_sync[f_k*WIDTH +: WIDTH] = sync_q[f_k];
    end endgenerate
`endif
endmodule

`default_nettype wire
