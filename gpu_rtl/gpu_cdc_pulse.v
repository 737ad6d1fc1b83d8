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
`ifdef FORMAL
    wire [1:0] f_sync;  // u_sync's two flops, [0] first (formal only)
`endif
    gpu_cdc_sync u_sync (.clk(clk_dst), .in(toggle_src_q), .out(toggle_dst)
`ifdef FORMAL
        , .f_sync(f_sync)
`endif
    );

    reg toggle_seen_q = 1'b0;
    always @(posedge clk_dst) toggle_seen_q <= toggle_dst;
    assign dst_pulse = toggle_dst != toggle_seen_q;

`ifdef FORMAL
    // ---- formal properties (tests/formal/gpu_cdc_pulse.sby: proved by induction, multiclock) ----
    // ZipCPU's convention: the inputs' contract is assumed when this module is the proof's subject
    // (GPU_CDC_PULSE defined), asserted when a larger proof includes it.
`ifdef GPU_CDC_PULSE
`define GPU_CDC_PULSE_ASSUME assume
`else
`define GPU_CDC_PULSE_ASSUME assert
`endif
    // The contract's model, in flops of the two clocks themselves (each samples at its own edges,
    // as the design does, so either clock may stall or race the other): an event is src_pulse at a
    // clk_src edge; a pulse is dst_pulse at a clk_dst edge.
    reg       f_ev_src = 1'b0;      // clk_src: flips with every event
    reg [1:0] f_events = 2'd0;      // clk_src: events so far, mod 4
    reg       f_ev_dst = 1'b0;      // clk_dst: f_ev_src as the last clk_dst edge saw it
    reg [1:0] f_edges = 2'd3;       // clk_dst: clk_dst edges since f_ev_dst changed, up to 3
    reg [1:0] f_pulses = 2'd0;      // clk_dst: pulses so far, mod 4
    reg       f_pulse_prev = 1'b0;  // clk_dst: dst_pulse as the last clk_dst edge saw it
    always @(posedge clk_src) begin
        if (src_pulse) begin
            f_ev_src <= ~f_ev_src;
            f_events <= f_events + 2'd1;
        end
    end
    always @(posedge clk_dst) begin
        f_ev_dst <= f_ev_src;
        if (f_ev_src != f_ev_dst) f_edges <= 2'd1;
        else if (f_edges != 2'd3) f_edges <= f_edges + 2'd1;
        f_pulses <= f_pulses + {1'b0, dst_pulse};
        f_pulse_prev <= dst_pulse;
    end
    // clk_dst edges since the last event: 0 until the first edge after it, 3 for "3 or more"
    wire [1:0] f_since = (f_ev_src != f_ev_dst) ? 2'd0 : f_edges;
    wire [1:0] f_in_flight = f_events - f_pulses;

    // Inputs: no reset (the properties are those of a running crossing: a reset while the toggle is
    // 1 is itself a change the destination sees); events at least three clk_dst edges apart.
    always @(*) begin
        `GPU_CDC_PULSE_ASSUME(!rst_src);
        if (src_pulse) `GPU_CDC_PULSE_ASSUME(f_since == 2'd3);
    end

    // The contract: no pulse without an event and none lost (at most one event in flight, and the
    // event is in flight until exactly the third clk_dst edge after it sees its pulse: 2 to 3
    // clk_dst cycles), and a pulse one clk_dst cycle long.
    always @(*) begin
        assert(f_in_flight == 2'd0 || f_in_flight == 2'd1);
        assert((f_in_flight == 2'd1) == (f_since != 2'd3));
        assert(!(f_pulse_prev && dst_pulse));
    end

    // Invariants (the induction's): the toggle is the events' parity, the first sync flop is what
    // the last clk_dst edge saw, and the toggle's change is at one place of the chain toggle_src_q
    // -> f_sync[0] -> f_sync[1] (toggle_dst) -> toggle_seen_q, the place f_since says.
    always @(*) begin
        assert(toggle_src_q == f_ev_src);
        assert(f_sync[0] == f_ev_dst);
        case (f_since)
            2'd0: assert(toggle_src_q != f_sync[0] && f_sync[0] == toggle_dst
                         && toggle_dst == toggle_seen_q);
            2'd1: assert(toggle_src_q == f_sync[0] && f_sync[0] != toggle_dst
                         && toggle_dst == toggle_seen_q && !f_pulse_prev);
            2'd2: assert(toggle_src_q == f_sync[0] && f_sync[0] == toggle_dst
                         && toggle_dst != toggle_seen_q && !f_pulse_prev);
            default: assert(toggle_src_q == f_sync[0] && f_sync[0] == toggle_dst
                            && toggle_dst == toggle_seen_q);
        endcase
    end
`undef GPU_CDC_PULSE_ASSUME
`endif
endmodule

`default_nettype wire
