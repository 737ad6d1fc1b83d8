// soc_stream_slice: a register slice on a valid/ready stream (a skid buffer of two entries), so that
// neither side's handshake reaches the other's logic in the same clock: out_valid and out_data
// come from flops, and so does in_ready. In the SoC it stands between sdram_wb_burst and LiteDRAM's
// command port, whose cmd_ready is combinational through the controller's crossbar (issue #27: the
// board's system path ran from the CPU's refill request through sdram_wb_burst into LiteDRAM's
// cmd_ready and back, 17.0 ns).
//
// Contract (both sides: an item moves in a clock where valid && ready; the sender holds valid and
// data until then):
//   order    items leave in the order they came, each once, unchanged; none is lost.
//   latency  an item taken in one clock is offered on out_* from the next: one clock more.
//   rate     one item a clock both ways while out_ready stays high: in_ready is high whenever the
//            second entry is empty, which it is unless the output stalled with both entries full.
//   out      out_valid, once high, stays high with out_data unchanged until out_ready (the stream
//            rule LiteDRAM's port needs); out_ready may depend on out_valid in the same clock.
`default_nettype none

module soc_stream_slice #(
    parameter integer W = 8                 // the item's bits
) (
    input  wire         clk,
    input  wire         rst,                // synchronous, active high: both entries emptied
    // ---- in: from the sender
    input  wire         in_valid,
    output wire         in_ready,           // from a flop: the skid entry is empty
    input  wire [W-1:0] in_data,
    // ---- out: to the receiver
    output reg          out_valid,
    input  wire         out_ready,
    output reg  [W-1:0] out_data
);
    reg         skid_valid;                 // an item taken while the output stalled
    reg [W-1:0] skid_data;

    assign in_ready = !skid_valid;
    wire in_take  = in_valid && in_ready;
    wire out_free = !out_valid || out_ready;    // the output entry is empty by the clock's end

    always @(posedge clk) begin
        if (rst) begin
            out_valid <= 1'b0;
            skid_valid <= 1'b0;
        end else if (out_free) begin
            // the output entry takes the oldest item: the skid's, else the one arriving now
            out_valid <= skid_valid || in_take;
            skid_valid <= 1'b0;                 // its item (if any) has moved out
        end else if (in_take) begin
            skid_valid <= 1'b1;                 // the output stalls: park the new item
        end
        if (out_free) out_data <= skid_valid ? skid_data : in_data;
        if (!out_free && in_take) skid_data <= in_data;
    end

`ifdef FORMAL
    // ---- formal properties (tests/formal/soc_stream_slice.sby, proved by induction; the sender's
    // rules and the port properties are in soc_stream_slice_check.sv). A shadow queue of what came
    // in and has not gone out, kept apart from the slice's own entries: the slice holds exactly its
    // items, oldest on the output, so items leave in order, each once, unchanged.
    reg [1:0]   f_count = 2'd0;            // items in the slice
    reg [W-1:0] f_q0, f_q1;                // the oldest and the next
    wire        f_pop = out_valid && out_ready;
    wire [1:0]  f_left = f_count - {1'b0, f_pop};   // after this clock's item left
    always @(posedge clk) begin
        if (rst) f_count <= 2'd0;
        else     f_count <= f_left + {1'b0, in_take};
        if (f_pop) f_q0 <= f_q1;
        if (in_take) begin
            if (f_left == 2'd0) f_q0 <= in_data;
            else                f_q1 <= in_data;
        end
    end
    always @(*) begin
        if (!rst) begin
            assert(f_count == {1'b0, out_valid} + {1'b0, skid_valid});
            if (skid_valid) assert(out_valid);
            if (out_valid) assert(out_data == f_q0);
            if (skid_valid) assert(skid_data == f_q1);
        end
    end
`endif
endmodule

`default_nettype wire
