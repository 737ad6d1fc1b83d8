// dvi_tx_check: the harness of dvi_tx's formal proof (boards/common/dvi_tx.v, whose `ifdef FORMAL
// block holds the properties of its pixel -> TMDS crossing; tests/formal/dvi_tx.sby).
//
// The clocks, as ulx3s_pll makes them (one VCO: clk_tmds exactly 5 x clk_pix, a fixed phase): the
// formal global clock is half a clk_tmds period; clk_tmds toggles at every step, and clk_pix is
// a divide-by-10 of the steps, phase-locked, at a phase chosen once (anyconst, any of the 10 steps:
// a clk_pix edge on a rising clk_tmds edge, whose flops then see the old values, or on a falling
// one, half a period before the next). Resets (assumed), as ulx3s_system gives them: both high from
// the start, each released once, at a rising edge of its own clock (which still resets), rst_tmds
// only once a clk_pix edge has reset the pixel domain, and no later than rst_pix. The video inputs
// are free, changing at clk_pix edges (dvi_tx.sby cuts the encoders free anyway).
// The properties are dvi_tx's own (its `ifdef FORMAL block: they need its toggle, synchroniser and
// shift registers, which a checker cannot name). Covers: clock words begun on ddr_d0[3]/ddr_d1[3],
// two at a phase where the clk_pix edge falls on a rising clk_tmds edge, one at a phase where it
// falls on a falling edge (the resets' release makes that one start ten steps later).
`default_nettype none

module dvi_tx_check (
    input wire       rst_pix,
    input wire       rst_tmds,
    input wire       de,
    input wire       hsync,
    input wire       vsync,
    input wire [7:0] r,
    input wire [7:0] g,
    input wire [7:0] b
);
    (* gclk *) reg step;

    // ---- the clocks: 10 steps a clk_pix period, 2 a clk_tmds period ----
    (* anyconst *) reg [3:0] pix_phase;   // where in the 10 steps clk_pix rises
    reg [3:0] t = 4'd0;                   // step within the clk_pix period
    always @(posedge step) t <= (t == 4'd9) ? 4'd0 : t + 4'd1;
    always @(*) assume(pix_phase <= 4'd9 && t <= 4'd9);
    wire [4:0] tp = {1'b0, t} + {1'b0, pix_phase};
    wire [3:0] pt = (tp >= 5'd10) ? tp[3:0] - 4'd10 : tp[3:0];   // (t + pix_phase) mod 10
    wire clk_tmds = t[0];
    wire clk_pix = pt >= 4'd5;

    reg past_valid = 1'b0;
    reg clk_pix_q = 1'b0, clk_tmds_q = 1'b0;
    reg pix_edge_seen = 1'b0;     // a clk_pix edge so far (with rst_pix: the pixel domain reset)
    always @(posedge step) begin
        past_valid <= 1'b1;
        clk_pix_q <= clk_pix;
        clk_tmds_q <= clk_tmds;
        if (pix_rise) pix_edge_seen <= 1'b1;
    end
    wire pix_rise = past_valid && clk_pix && !clk_pix_q;
    wire tmds_rise = past_valid && clk_tmds && !clk_tmds_q;

    // ---- resets and inputs ----
    always @(*) if (!past_valid) assume(rst_pix && rst_tmds);
    always @(posedge step) begin
        if (past_valid) begin
            if (rst_tmds != $past(rst_tmds)) assume(tmds_rise && !rst_tmds && (pix_rise || pix_edge_seen));
            if (rst_pix != $past(rst_pix)) assume(pix_rise && !rst_pix);
            if (!pix_rise) assume({de, hsync, vsync, r, g, b} == $past({de, hsync, vsync, r, g, b}));
        end
    end
    always @(*) if (!rst_pix) assume(!rst_tmds);

    wire [3:0] ddr_d0, ddr_d1;
    dvi_tx dut (
        .clk_pix(clk_pix), .rst_pix(rst_pix), .clk_tmds(clk_tmds), .rst_tmds(rst_tmds),
        .de(de), .hsync(hsync), .vsync(vsync), .r(r), .g(g), .b(b),
        .ddr_d0(ddr_d0), .ddr_d1(ddr_d1)
    );

    // ---- covers: two loads and their words on the lines, at each kind of phase ----
    reg [1:0] loads = 2'd0;       // clock words begun on ddr_d0[3] since rst_tmds, up to 3
    reg       d0_q = 1'b0;
    always @(posedge clk_tmds) begin
        d0_q <= ddr_d0[3];
        if (rst_tmds) loads <= 2'd0;
        else if (ddr_d0[3] && ddr_d1[3] && !d0_q && loads != 2'd3) loads <= loads + 2'd1;
    end
    always @(*) begin
        cover(loads == 2'd2 && !pix_phase[0]);   // clk_pix rises with clk_tmds
        cover(loads == 2'd1 && pix_phase[0]);    // clk_pix rises with clk_tmds falling
    end
endmodule

`default_nettype wire
