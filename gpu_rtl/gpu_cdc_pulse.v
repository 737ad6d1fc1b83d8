// gpu_cdc_pulse: a one-clock event of clk_src as a one-clock pulse of clk_dst.
//
// Contract: each src_pulse (high for one clk_src cycle) flips a toggle in the source domain; the
// toggle crosses through gpu_cdc_sync (two flops) and each change seen in the destination domain is
// one dst_pulse, 2 to 3 clk_dst cycles after the event. Events must be at least three clk_dst cycles
// plus one clk_src cycle apart, or two of them merge into one — the GPU sends one a frame.
`default_nettype none

module gpu_cdc_pulse (
    input  wire clk_src,
    input  wire rst_src,     // synchronous to clk_src
    input  wire src_pulse,   // clk_src domain
    input  wire clk_dst,
    output wire dst_pulse    // clk_dst domain
);
    reg toggle_src_q = 1'b0;
    always @(posedge clk_src) begin
        if (rst_src) toggle_src_q <= 1'b0;
        else if (src_pulse) toggle_src_q <= ~toggle_src_q;
    end

    wire toggle_dst;
    gpu_cdc_sync u_sync (.clk(clk_dst), .in(toggle_src_q), .out(toggle_dst));

    reg toggle_seen_q = 1'b0;
    always @(posedge clk_dst) toggle_seen_q <= toggle_dst;
    assign dst_pulse = toggle_dst != toggle_seen_q;
endmodule

`default_nettype wire
