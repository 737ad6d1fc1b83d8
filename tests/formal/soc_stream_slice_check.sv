// soc_stream_slice_check: formal properties of soc_stream_slice (soc_rtl/soc_stream_slice.v) at its
// ports (tests/formal/soc_stream_slice.sby; make formal); the module's `ifdef FORMAL block keeps a
// shadow queue of the items in flight and asserts that they leave in order, each once, unchanged.
//
// Environment (assumed): rst in the first clock; the sender holds in_valid and in_data until
// in_ready (the stream rule); out_ready anything at any clock (LiteDRAM's may follow out_valid).
// Properties (asserted):
//   out      out_valid, once high, stays high with out_data unchanged until out_ready.
//   latency  an item taken while the output entry is free is offered in the next clock.
//   rate     in_ready is high in every clock after one where the output was free (empty or
//            taken): the slice holds back its sender only while its receiver stalls.
// Covers: an item through; the skid entry used (in_ready low); three items through on three
// consecutive clocks.
`default_nettype none

module soc_stream_slice_check #(
    parameter integer W = 4
) (
    input wire         clk,
    input wire         rst,
    input wire         in_valid,
    input wire [W-1:0] in_data,
    input wire         out_ready
);
    wire         in_ready, out_valid;
    wire [W-1:0] out_data;
    soc_stream_slice #(.W(W)) dut (
        .clk(clk), .rst(rst),
        .in_valid(in_valid), .in_ready(in_ready), .in_data(in_data),
        .out_valid(out_valid), .out_ready(out_ready), .out_data(out_data)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;
    always @(*) if (!f_past_valid) assume(rst);

    reg         f_was_rst = 1'b1;
    reg         f_in_wait_q = 1'b0;     // last clock: an item offered and not taken
    reg         f_out_wait_q = 1'b0;    // last clock: an item offered out and not taken
    reg         f_in_fast_q = 1'b0;     // last clock: an item taken while the output was free
    reg         f_out_free_q = 1'b0;    // last clock: the output entry was empty or taken
    reg [W-1:0] f_in_data_q, f_out_data_q;
    reg [1:0]   f_run = 2'd0;           // consecutive clocks with an item out
    always @(posedge clk) begin
        f_was_rst <= rst;
        f_in_wait_q <= in_valid && !in_ready;
        f_out_wait_q <= out_valid && !out_ready;
        f_in_fast_q <= in_valid && in_ready && (!out_valid || out_ready);
        f_out_free_q <= !out_valid || out_ready;
        f_in_data_q <= in_data;
        f_out_data_q <= out_data;
        f_run <= (rst || !(out_valid && out_ready)) ? 2'd0 : f_run + (f_run != 2'd3);
    end
    wire f_held = f_past_valid && !f_was_rst && !rst;

    always @(*) begin
        if (f_held && f_in_wait_q) assume(in_valid && in_data == f_in_data_q);
    end

    always @(*) begin
        if (f_held) begin
            if (f_out_wait_q) assert(out_valid && out_data == f_out_data_q);
            if (f_in_fast_q) assert(out_valid && out_data == f_in_data_q);
            if (f_out_free_q) assert(in_ready);
        end
        cover(f_held && out_valid && out_ready);
        cover(f_held && in_valid && !in_ready);
        cover(f_held && f_run == 2'd2 && out_valid && out_ready);
    end
endmodule

`default_nettype wire
