// gpu_cdc_pulse_check: formal properties of gpu_cdc_pulse (gpu_rtl/gpu_cdc_pulse.v) across two
// unrelated clocks, from its ports only (tests/formal/gpu_cdc_pulse.sby; make formal).
//
// Environment (assumed): clk_src and clk_dst toggle at arbitrary steps of the formal global clock,
// each edge a step of its own; src_pulse changes only at a clk_src rising edge (a clk_src signal);
// no reset after the start; events as the contract requires them, at least three clk_dst cycles
// plus one clk_src cycle apart (counted here as 4 clk_dst rising edges between them).
// Properties (asserted):
//   - no dst_pulse without an event: pulses seen never outnumber events sent;
//   - no event lost: at most one event is in flight, and the 3rd clk_dst edge after it sees it;
//   - a dst_pulse lasts one clk_dst cycle (two successive clk_dst edges never both see it).
// Covers: an event arrives, and two events arrive one after the other.
`default_nettype none

module gpu_cdc_pulse_check (
    input wire clk_src,
    input wire clk_dst,
    input wire src_pulse
);
    (* gclk *) reg step;

    wire dst_pulse;
    gpu_cdc_pulse dut (
        .clk_src(clk_src), .rst_src(1'b0), .src_pulse(src_pulse),
        .clk_dst(clk_dst), .dst_pulse(dst_pulse)
    );

    reg past_valid = 1'b0;
    reg clk_src_q = 1'b0;
    reg clk_dst_q = 1'b0;
    always @(posedge step) begin
        past_valid <= 1'b1;
        clk_src_q <= clk_src;
        clk_dst_q <= clk_dst;
    end
    wire src_rise = clk_src && !clk_src_q;
    wire dst_rise = clk_dst && !clk_dst_q;

    // The clocks: one edge at a time; each clock's rising edge a separate step from the other's.
    always @(*) if (past_valid) assume(!(clk_src != clk_src_q && clk_dst != clk_dst_q));
    // src_pulse is a clk_src signal: it changes only with a rising clk_src edge.
    always @(posedge step) if (past_valid && !src_rise) assume(src_pulse == $past(src_pulse));

    // What a flop of each domain samples at its rising edge: the value before the edge (the
    // previous step's; yosys's multiclock model updates a flop in the step of its clock's edge).
    reg src_pulse_q = 1'b0;
    reg dst_pulse_q = 1'b0;
    always @(posedge step) begin
        src_pulse_q <= src_pulse;
        dst_pulse_q <= dst_pulse;
    end
    wire event_sent = src_rise && src_pulse_q;
    wire pulse_seen = dst_rise && dst_pulse_q;

    reg [3:0] sent = 4'd0;
    reg [3:0] seen = 4'd0;
    reg [2:0] dst_edges_since = 3'd7;  // clk_dst rising edges since the last event, saturating
    reg       pulse_prev = 1'b0;       // dst_pulse as the previous clk_dst edge sampled it
    always @(posedge step) begin
        if (event_sent) begin
            sent <= sent + 4'd1;
            dst_edges_since <= 3'd0;
        end else if (dst_rise && dst_edges_since != 3'd7) begin
            dst_edges_since <= dst_edges_since + 3'd1;
        end
        if (dst_rise) begin
            seen <= seen + {3'd0, dst_pulse_q};
            pulse_prev <= dst_pulse_q;
        end
    end
    // The contract's spacing: a new event only after 4 clk_dst edges since the last.
    always @(*) if (event_sent) assume(dst_edges_since >= 3'd4);
    always @(*) assume(sent != 4'd15);  // the counters do not wrap within the proof

    always @(*) begin
        assert(seen <= sent);                                  // no pulse without an event
        assert(sent - seen <= 4'd1);                           // at most one in flight
        if (sent != seen) assert(dst_edges_since <= 3'd2);     // ... seen by the 3rd clk_dst edge
        if (pulse_seen) assert(!pulse_prev);                   // one clk_dst cycle long
    end

    always @(*) begin
        cover(seen == 4'd1);
        cover(seen == 4'd2);
    end
endmodule

`default_nettype wire
