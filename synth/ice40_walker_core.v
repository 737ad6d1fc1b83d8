// ice40_walker_core: the span walker (gpu_span_walker, SPAN_W = 4) behind a narrow load port, for
// place-and-route on an iCE40 HX8K. The whole rasterizer does not fit that part: its triangle set-up
// needs eight 18x18 multipliers, which the HX8K, having no DSP blocks, would build from ~10k LUTs
// (7-series maps them to DSP48s). The walker is the part that runs every clock, so its fmax is the
// one that bounds the fill rate. Synthesis and timing only; the GPU is gpu_rtl/gpu_top.v.
//
// Load port: each ld_valid shifts ld_data into a descriptor register (DESC_W bits, see the
// concatenation below); ld_go hands the descriptor to the walker. Span writes leave on fb_wr_*.
`default_nettype none

module ice40_walker_core #(
    parameter integer SPAN_W = 4,
    localparam integer COL_W = $clog2(320 / SPAN_W),
    localparam integer WAW = $clog2(320 * 240 / SPAN_W),
    localparam integer CNT_W = $clog2(SPAN_W + 1),
    localparam integer DESC_W = 1 + 8 + 9 * 36 + 3 + 2 * COL_W + 16 + 2 * 12 + 12 + 3 + 2 * 13 + 15
) (
    input  wire                clk,
    input  wire                rst,
    // load port
    input  wire                ld_valid,
    input  wire [31:0]         ld_data,
    input  wire                ld_go,
    output wire                ready,
    // span writes
    output wire                fb_wr_en,
    output wire [WAW-1:0]      fb_wr_addr,
    output wire [SPAN_W*8-1:0] fb_wr_data,
    output wire [SPAN_W-1:0]   fb_wr_mask,
    output wire                idle,
    output wire                ev_span_written,
    output wire [CNT_W-1:0]    ev_pixels
);
    reg [DESC_W-1:0] desc_q;
    always @(posedge clk) begin
        if (ld_valid) begin
            desc_q <= {desc_q[DESC_W-33:0], ld_data};
        end
    end

    wire is_line;
    wire [7:0] color;
    wire signed [35:0] e0, e1, e2, sx0, sx1, sx2, sy0, sy1, sy2;
    wire [2:0] top_left;
    wire [COL_W-1:0] col_lo, col_hi;
    wire [7:0] row_lo, row_hi;
    wire signed [11:0] line_x, line_y;
    wire [11:0] line_n;
    wire xmajor, xneg, yneg;
    wire [12:0] two_a_major, two_a_minor;
    wire signed [14:0] line_err;
    assign {is_line, color, e0, e1, e2, sx0, sx1, sx2, sy0, sy1, sy2, top_left, col_lo, col_hi,
            row_lo, row_hi, line_x, line_y, line_n, xmajor, xneg, yneg, two_a_major, two_a_minor,
            line_err} = desc_q;

    wire ev_span_visit;
    wire unused_z_rd_en, unused_z_wr_en;
    wire [WAW-1:0] unused_z_rd_addr, unused_z_wr_addr;
    wire [SPAN_W*16-1:0] unused_z_wr_data;
    wire [SPAN_W-1:0] unused_z_wr_mask;

    gpu_span_walker #(.SPAN_W(SPAN_W), .ENABLE_ZBUF(0)) u_walker (
        .clk(clk), .rst(rst),
        .in_valid(ld_go), .in_ready(ready), .in_is_line(is_line), .in_color(color),
        .in_e0(e0), .in_e1(e1), .in_e2(e2), .in_sx0(sx0), .in_sx1(sx1), .in_sx2(sx2),
        .in_sy0(sy0), .in_sy1(sy1), .in_sy2(sy2), .in_top_left(top_left),
        .in_col_lo(col_lo), .in_col_hi(col_hi), .in_row_lo(row_lo), .in_row_hi(row_hi),
        .in_line_x(line_x), .in_line_y(line_y), .in_line_n(line_n), .in_line_xmajor(xmajor),
        .in_line_xneg(xneg), .in_line_yneg(yneg), .in_line_two_a_major(two_a_major),
        .in_line_two_a_minor(two_a_minor), .in_line_err(line_err),
        .in_z_start(52'sd0), .in_z_dx(40'sd0), .in_z_dy(40'sd0), .ztest(1'b0),
        .z_rd_en(unused_z_rd_en), .z_rd_addr(unused_z_rd_addr), .z_rd_data({(SPAN_W * 16){1'b0}}),
        .z_wr_en(unused_z_wr_en), .z_wr_addr(unused_z_wr_addr), .z_wr_data(unused_z_wr_data),
        .z_wr_mask(unused_z_wr_mask),
        .fb_wr_en(fb_wr_en), .fb_wr_addr(fb_wr_addr), .fb_wr_data(fb_wr_data),
        .fb_wr_mask(fb_wr_mask), .idle(idle),
        .ev_span_visit(ev_span_visit), .ev_span_written(ev_span_written), .ev_pixels(ev_pixels)
    );
    wire unused_visit = ev_span_visit;
endmodule

`default_nettype wire
