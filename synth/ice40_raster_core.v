// ice40_raster_core: the rasterizer (gpu_raster with its vertex and index RAMs) behind a narrow load
// port, for place-and-route on an iCE40 HX8K, whose 128 Kb of block RAM cannot hold the 1.2 Mb of
// framebuffers: the span write port leaves the chip as pins instead. Synthesis and timing only; the
// full GPU is gpu_rtl/gpu_top.v.
//
// Load port: ld_addr 0..5 = CTRL, VTX_BASE, VTX_COUNT, TRI_BASE, TRI_COUNT, CLEAR_COLOR; 6 = DOORBELL
// (starts the batch); 7 = RESET; 8 / 10 set the vertex / index word pointer; 9 / 11 write a vertex
// word 0 / an index word at the pointer and advance it. rd_sel picks a counter or status word.
`default_nettype none

module ice40_raster_core #(
    parameter integer SPAN_W = 4,
    parameter integer VTX_CAP = 1024,
    parameter integer TRI_CAP = 512,
    localparam integer VI_W = $clog2(VTX_CAP),
    localparam integer TI_W = $clog2(TRI_CAP),
    localparam integer WAW = $clog2(320 * 240 / SPAN_W)
) (
    input  wire                clk,
    input  wire                rst,
    // load port
    input  wire                ld_valid,
    input  wire [3:0]          ld_addr,
    input  wire [31:0]         ld_data,
    // readout
    input  wire [3:0]          rd_sel,
    output reg  [31:0]         rd_data,
    // span writes to an external framebuffer
    output wire                fb_wr_en,
    output wire [WAW-1:0]      fb_wr_addr,
    output wire [SPAN_W*8-1:0] fb_wr_data,
    output wire [SPAN_W-1:0]   fb_wr_mask,
    input  wire                vblank_start,
    output wire                swap,
    output wire                busy
);
    reg ctrl_clear, ctrl_swap, start, soft_reset;
    reg [31:0] vtx_base, vtx_count, tri_base, tri_count, tag;
    reg [7:0] clear_color;
    reg [VI_W-1:0] vtx_ptr;
    reg [TI_W:0] idx_ptr;

    always @(posedge clk) begin
        start <= 1'b0;
        soft_reset <= 1'b0;
        if (rst) begin
            ctrl_clear <= 1'b0;
            ctrl_swap <= 1'b0;
            vtx_ptr <= {VI_W{1'b0}};
            idx_ptr <= {(TI_W + 1){1'b0}};
        end else if (ld_valid) begin
            case (ld_addr)
                4'd0: {ctrl_swap, ctrl_clear} <= ld_data[1:0];
                4'd1: vtx_base <= ld_data;
                4'd2: vtx_count <= ld_data;
                4'd3: tri_base <= ld_data;
                4'd4: tri_count <= ld_data;
                4'd5: clear_color <= ld_data[7:0];
                4'd6: begin
                    tag <= ld_data;
                    start <= 1'b1;
                end
                4'd7: soft_reset <= 1'b1;
                4'd8: vtx_ptr <= ld_data[VI_W-1:0];
                4'd9: vtx_ptr <= vtx_ptr + 1'b1;
                4'd10: idx_ptr <= ld_data[TI_W:0];
                4'd11: idx_ptr <= idx_ptr + 1'b1;
                default: ;
            endcase
        end
    end

    wire vtx_rd_en, idx_rd_en;
    wire [VI_W-1:0] vtx_rd_addr;
    wire [TI_W-1:0] idx_rd_addr;
    wire [31:0] vtx_rd_data;
    wire [63:0] idx_rd_data;

    gpu_ram #(.DEPTH(VTX_CAP), .WIDTH(32)) u_vtx (
        .clk(clk), .wr_en(ld_valid && ld_addr == 4'd9), .wr_addr(vtx_ptr), .wr_data(ld_data),
        .wr_mask(1'b1), .rd_en(vtx_rd_en), .rd_addr(vtx_rd_addr), .rd_data(vtx_rd_data)
    );
    gpu_ram #(.DEPTH(TRI_CAP), .WIDTH(64), .LANES(2)) u_idx (
        .clk(clk), .wr_en(ld_valid && ld_addr == 4'd11), .wr_addr(idx_ptr[TI_W:1]),
        .wr_data({ld_data, ld_data}), .wr_mask({idx_ptr[0], !idx_ptr[0]}),
        .rd_en(idx_rd_en), .rd_addr(idx_rd_addr), .rd_data(idx_rd_data)
    );

    wire [31:0] done_seq, frame_count, busy_cycles, tris_in, tris_drawn, tris_rejected, pixels;
    wire [31:0] samples, spans_written, spans_visited;
    wire [2:0] errors;

    gpu_raster #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .SPAN_W(SPAN_W), .ENABLE_LINES(1)) u_raster (
        .clk(clk), .rst(rst), .soft_reset(soft_reset),
        .start(start), .ctrl_clear(ctrl_clear), .ctrl_swap(ctrl_swap),
        .vtx_base(vtx_base), .vtx_count(vtx_count), .tri_base(tri_base), .tri_count(tri_count),
        .clear_color(clear_color), .doorbell_tag(tag),
        .busy(busy), .done_seq(done_seq), .frame_count(frame_count), .errors(errors),
        .perf_busy_cycles(busy_cycles), .perf_tris_in(tris_in), .perf_tris_drawn(tris_drawn),
        .perf_tris_rejected(tris_rejected), .perf_pixels(pixels), .perf_samples(samples),
        .perf_spans_written(spans_written), .perf_spans_visited(spans_visited),
        .idx_rd_en(idx_rd_en), .idx_rd_addr(idx_rd_addr), .idx_rd_data(idx_rd_data),
        .vtx_rd_en(vtx_rd_en), .vtx_rd_addr(vtx_rd_addr), .vtx_rd_data(vtx_rd_data),
        .fb_wr_en(fb_wr_en), .fb_wr_addr(fb_wr_addr), .fb_wr_data(fb_wr_data),
        .fb_wr_mask(fb_wr_mask), .vblank_start(vblank_start), .swap(swap)
    );

    always @(posedge clk) begin
        case (rd_sel)
            4'd0: rd_data <= done_seq;
            4'd1: rd_data <= frame_count;
            4'd2: rd_data <= {29'd0, errors};
            4'd3: rd_data <= busy_cycles;
            4'd4: rd_data <= tris_in;
            4'd5: rd_data <= tris_drawn;
            4'd6: rd_data <= tris_rejected;
            4'd7: rd_data <= pixels;
            4'd8: rd_data <= samples;
            4'd9: rd_data <= spans_written;
            4'd10: rd_data <= spans_visited;
            default: rd_data <= 32'd0;
        endcase
    end
endmodule

`default_nettype wire
