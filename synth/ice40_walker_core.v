// ice40_walker_core: the span walker (gpu_span_walker, SPAN_W = 4) behind a narrow load port, for
// place-and-route on an iCE40 HX8K. The whole rasterizer does not fit that part: its triangle set-up
// needs eight 18x18 multipliers, which the HX8K, having no DSP blocks, would build from ~10k LUTs
// (7-series maps them to DSP48s). The walker is the part that runs every clock, so its fmax is the
// one that bounds the fill rate. Synthesis and timing only; the GPU is gpu_rtl/gpu_top.v.
//
// Load port: each ld_valid shifts ld_data into a descriptor register (a gpu_pkg::desc_t, 32 bits a
// load, the first word loaded ending up in the most significant bits); ld_go hands the descriptor to
// the walker. The walker is built without depth (ENABLE_ZBUF = 0) and Gouraud (ENABLE_GOURAUD = 0), so
// its depth and intensity fields are tied to 0 here: they are the descriptor's most significant
// bits, the end of the shift chain, and synthesis removes them. Span writes leave on fb_wr_*.
`default_nettype none

module ice40_walker_core #(
    parameter integer SPAN_W = 4,                                      // the iCE40 build's span width
    localparam integer WAW = $clog2(gpu_pkg::GPU_FB_PIXELS / SPAN_W),
    localparam integer CNT_W = $clog2(SPAN_W + 1)
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
    gpu_pkg::desc_t desc_q;
    localparam integer DESC_W = $bits(desc_q);  // yosys 0.23 takes $bits of a variable, not of a type
    always @(posedge clk) begin
        if (ld_valid) begin
            desc_q <= {desc_q[DESC_W-33:0], ld_data};
        end
    end

    gpu_pkg::desc_t walker_desc;
    always @(*) begin
        walker_desc = desc_q;
        walker_desc.z_start = '0;
        walker_desc.z_dx = '0;
        walker_desc.z_dy = '0;
        walker_desc.shaded = 1'b0;   // built without Gouraud (ENABLE_GOURAUD = 0): no intensity
        walker_desc.i_start = '0;
        walker_desc.i_dx = '0;
        walker_desc.i_dy = '0;
    end

    wire ev_span_visit;
    wire unused_z_rd_en, unused_z_wr_en;
    wire [WAW-1:0] unused_z_rd_addr, unused_z_wr_addr;
    wire [SPAN_W*16-1:0] unused_z_wr_data;
    wire [SPAN_W-1:0] unused_z_wr_mask;

    gpu_span_walker #(.SPAN_W(SPAN_W), .ENABLE_ZBUF(0)) u_walker (
        .clk(clk), .rst(rst),
        .in_valid(ld_go), .in_ready(ready), .in_desc(walker_desc), .ztest(1'b0), .dither(1'b0),
        .row_first('0), .row_last(gpu_pkg::ROW_W'(gpu_pkg::GPU_FB_HEIGHT - 1)), .rows_empty(1'b0),
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
