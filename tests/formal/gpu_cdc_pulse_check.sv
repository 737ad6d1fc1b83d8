// gpu_cdc_pulse_check: the harness of gpu_cdc_pulse's formal proof (gpu_rtl/gpu_cdc_pulse.v, whose
// `ifdef FORMAL block holds the properties; tests/formal/gpu_cdc_pulse.sby; make formal).
//
// The properties live with the module (ZipCPU's way): they need its toggle, its synchroniser's
// flops and its toggle_seen_q, which a checker cannot name (yosys reads no hierarchical names),
// and counters the module's invariants must name. The module's block assumes its input contract
// (GPU_CDC_PULSE is defined by the .sby): no rst_src, and events at least three clk_dst edges
// apart. Here: clk_src and clk_dst are free inputs (multiclock on), each toggling at any step of
// the formal global clock, together or not, or not at all; src_pulse is free (the module counts it
// where it samples it, at clk_src edges).
// Covers: one pulse, two pulses, and two pulses three clk_dst edges apart (events at the closest
// spacing the contract allows, so the assumption leaves that case in).
`default_nettype none

module gpu_cdc_pulse_check (
    input wire clk_src,
    input wire clk_dst,
    input wire src_pulse
);
    wire dst_pulse;
    gpu_cdc_pulse dut (
        .clk_src(clk_src), .rst_src(1'b0), .src_pulse(src_pulse),
        .clk_dst(clk_dst), .dst_pulse(dst_pulse)
    );

    reg [1:0] seen = 2'd0;         // pulses seen at clk_dst edges, up to 3
    reg [2:0] edges_since = 3'd0;  // clk_dst edges since the last pulse seen, up to 7
    reg       close = 1'b0;        // a pulse seen three clk_dst edges after the previous one
    always @(posedge clk_dst) begin
        if (dst_pulse) begin
            if (seen != 2'd3) seen <= seen + 2'd1;
            edges_since <= 3'd1;
            close <= seen != 2'd0 && edges_since == 3'd3;
        end else if (edges_since != 3'd7) begin
            edges_since <= edges_since + 3'd1;
        end
    end

    always @(*) begin
        cover(seen == 2'd1);
        cover(seen == 2'd2);
        cover(close);
    end
endmodule

`default_nettype wire
