// gpu_top: the GPU — bus slave, vertex/index/palette RAMs, rasterizer, double framebuffer, VGA out.
//
// Contract: contract/gpu-contract.md. The CPU writes buffers and registers over the bus and rings
// DOORBELL; the GPU clears and draws into the back buffer, swaps at vertical blank when asked, and
// reports DONE_SEQ. Data path: bus -> gpu_regs -> vertex/index RAM -> gpu_raster (gpu_prim_setup ->
// gpu_span_walker) -> gpu_framebuffer (back) ... (front) -> gpu_vga -> palette -> VGA pins.
// Two clock domains: everything on clk but the scan-out — the framebuffer's and the palette's read
// ports and gpu_vga — on clk_pix, one pixel every PIX_DIV clk_pix cycles (a board gives a 25 MHz
// clk_pix and PIX_DIV 1; a simulation may tie clk_pix to clk). They cross in three places, each
// with its argument: vblank_start (gpu_cdc_pulse, one a frame), the front bank (gpu_cdc_sync in
// gpu_framebuffer: it changes only at vertical blank) and the reset (gpu_cdc_sync below: rst_pix
// follows rst two clk_pix cycles later). The palette is written on clk and read on clk_pix without
// a handshake: a palette write during the visible area may show one wrong colour for one pixel (the
// firmware writes it at start and when a scene changes). Build options leave out what a scene does not need and
// are reported in CAPS; their defaults, the capacities and the frame size come from the contract
// (gpu_pkg::GPU_*, generated from contract/gpu_contract.toml).
`default_nettype none

module gpu_top #(
    // Capacities and build options; defaults from the contract (limits and [build] table).
    parameter integer VTX_CAP = gpu_pkg::GPU_VTX_CAP,                    // vertex buffer capacity
    parameter integer TRI_CAP = gpu_pkg::GPU_TRI_CAP,                    // index buffer capacity
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,              // pixels per clock: 1, 4, 8, 16
    parameter integer ENABLE_LINES = gpu_pkg::GPU_DEFAULT_ENABLE_LINES,  // line primitives (CAPS_LINES)
    parameter integer ENABLE_ZBUF = gpu_pkg::GPU_DEFAULT_ENABLE_ZBUF,    // 16-bit depth buffer (CAPS_ZBUF):
                                                                         // 1.2 Mb more block RAM
    parameter integer PIX_DIV = 4,       // clk_pix clocks per VGA pixel (1 for a 25 MHz clk_pix)
    localparam integer VI_W = $clog2(VTX_CAP),
    localparam integer TI_W = $clog2(TRI_CAP),
    localparam integer VTX_AW = $clog2(VTX_CAP * 2),
    localparam integer IDX_AW = $clog2(TRI_CAP * 2),
    localparam integer FB_WORDS = gpu_pkg::GPU_FB_PIXELS / SPAN_W,  // spans in a frame
    localparam integer FB_WAW = $clog2(FB_WORDS),
    localparam integer FB_PAW = $clog2(gpu_pkg::GPU_FB_PIXELS)
) (
    input  wire        clk,           // system clock: bus, rasterizer, framebuffer writes
    input  wire        rst,           // synchronous to clk, active high
    input  wire        clk_pix,       // scan-out clock (may be clk itself)
    // bus slave (see gpu_regs)
    input  wire        bus_valid,
    input  wire        bus_write,
    input  wire [16:2] bus_addr,
    input  wire [31:0] bus_wdata,
    output wire [31:0] bus_rdata,
    output wire        bus_rvalid,
    // status, clk domain (board LEDs)
    output wire        frame_swapped, // one cycle at each buffer swap
    output wire        error,         // ERRORS non-zero: the last batch refused something
    // VGA connector, clk_pix domain
    output wire        vga_pix_stb,   // outputs change on the clk_pix edge where this is high
    output wire        vga_de,        // visible area (for a DVI encoder)
    output wire        vga_hsync_n,
    output wire        vga_vsync_n,
    output wire [3:0]  vga_r,
    output wire [3:0]  vga_g,
    output wire [3:0]  vga_b
);
    localparam [31:0] CAPS = (32'(SPAN_W) << gpu_pkg::GPU_CAPS_SPAN_W_LSB)
                           | (32'(ENABLE_LINES != 0) << gpu_pkg::GPU_CAPS_LINES_LSB)
                           | (32'(ENABLE_ZBUF != 0) << gpu_pkg::GPU_CAPS_ZBUF_LSB);

    // Batch description and status between the register block and the rasterizer.
    wire        ctrl_clear, ctrl_swap, ctrl_ztest, ctrl_zclear, start, soft_reset;
    wire        busy, front, swap, vblank_start_sys, vblank_start_pix;
    wire [31:0] vtx_base, vtx_count, tri_base, tri_count, doorbell_tag, done_seq, frame_count;
    wire [7:0]  clear_color;
    wire [2:0]  raster_errors;
    gpu_pkg::perf_t perf;                 // the PERF_* counters

    // RAM ports.
    wire              vtx_wr_en, idx_wr_en, pal_wr_en;
    wire [VTX_AW-1:0] vtx_wr_addr;
    wire [IDX_AW-1:0] idx_wr_addr;
    wire [7:0]        pal_wr_addr;
    wire              vtx_rd_en, idx_rd_en, pal_rd_en, fb_rd_en, fb_wr_en;
    wire [VI_W-1:0]   vtx_rd_addr;
    wire [TI_W-1:0]   idx_rd_addr;
    wire [31:0]       vtx_rd_data;
    wire [63:0]       idx_rd_data;
    wire [7:0]        pal_rd_addr, fb_rd_data;
    wire [11:0]       pal_rd_data;
    wire [FB_PAW-1:0] fb_rd_addr;
    wire [FB_WAW-1:0] fb_wr_addr;
    wire [SPAN_W*8-1:0] fb_wr_data;
    wire [SPAN_W-1:0] fb_wr_mask;

    gpu_regs #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .CAPS(CAPS)) u_regs (
        .clk(clk), .rst(rst),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .ctrl_clear(ctrl_clear), .ctrl_swap(ctrl_swap), .ctrl_ztest(ctrl_ztest),
        .ctrl_zclear(ctrl_zclear), .vtx_base(vtx_base), .vtx_count(vtx_count),
        .tri_base(tri_base), .tri_count(tri_count), .clear_color(clear_color),
        .doorbell_tag(doorbell_tag), .start(start), .soft_reset(soft_reset),
        .vtx_wr_en(vtx_wr_en), .vtx_wr_addr(vtx_wr_addr), .idx_wr_en(idx_wr_en),
        .idx_wr_addr(idx_wr_addr), .pal_wr_en(pal_wr_en), .pal_wr_addr(pal_wr_addr),
        .busy(busy), .front(front), .done_seq(done_seq), .frame_count(frame_count),
        .raster_errors(raster_errors), .perf(perf)
    );

    // Depth: the vertices' z (word 1) and the depth buffer exist only in a build that tests depth.
    wire [15:0] vz_rd_data;
    wire z_rd_en, z_wr_en;
    wire [FB_WAW-1:0] z_rd_addr, z_wr_addr;
    wire [SPAN_W*16-1:0] z_rd_data, z_wr_data;
    wire [SPAN_W-1:0] z_wr_mask;
    generate
        if (ENABLE_ZBUF != 0) begin : g_zbuf
            gpu_ram #(.DEPTH(VTX_CAP), .WIDTH(16)) u_vtx_z_ram (
                .wr_clk(clk), .rd_clk(clk),
                .wr_en(vtx_wr_en && vtx_wr_addr[0] == 1'b1), .wr_addr(vtx_wr_addr[VTX_AW-1:1]),
                .wr_data(bus_wdata[gpu_pkg::GPU_VTX_Z_LSB +: 16]), .wr_mask(1'b1),
                .rd_en(vtx_rd_en), .rd_addr(vtx_rd_addr), .rd_data(vz_rd_data)
            );
            gpu_ram #(.DEPTH(FB_WORDS), .WIDTH(SPAN_W * 16), .LANES(SPAN_W)) u_depth (
                .wr_clk(clk), .rd_clk(clk),
                .wr_en(z_wr_en), .wr_addr(z_wr_addr), .wr_data(z_wr_data), .wr_mask(z_wr_mask),
                .rd_en(z_rd_en), .rd_addr(z_rd_addr), .rd_data(z_rd_data)
            );
        end else begin : g_no_zbuf
            assign vz_rd_data = 16'd0;
            assign z_rd_data = {(SPAN_W * 16){1'b0}};
            wire unused_z = z_rd_en | z_wr_en | (|z_rd_addr) | (|z_wr_addr) | (|z_wr_data) | (|z_wr_mask);
        end
    endgenerate

    // Vertex word 0 (x, y) is all the rasterizer reads for coverage.
    gpu_ram #(.DEPTH(VTX_CAP), .WIDTH(32)) u_vtx_xy_ram (
        .wr_clk(clk), .rd_clk(clk),
        .wr_en(vtx_wr_en && vtx_wr_addr[0] == 1'b0), .wr_addr(vtx_wr_addr[VTX_AW-1:1]),
        .wr_data(bus_wdata), .wr_mask(1'b1),
        .rd_en(vtx_rd_en), .rd_addr(vtx_rd_addr), .rd_data(vtx_rd_data)
    );

    // The two words of a primitive sit side by side so that one read returns both.
    gpu_ram #(.DEPTH(TRI_CAP), .WIDTH(64), .LANES(2)) u_idx_ram (
        .wr_clk(clk), .rd_clk(clk),
        .wr_en(idx_wr_en), .wr_addr(idx_wr_addr[IDX_AW-1:1]), .wr_data({bus_wdata, bus_wdata}),
        .wr_mask({idx_wr_addr[0], !idx_wr_addr[0]}),
        .rd_en(idx_rd_en), .rd_addr(idx_rd_addr), .rd_data(idx_rd_data)
    );

    gpu_ram #(.DEPTH(gpu_pkg::GPU_PALETTE_ENTRIES), .WIDTH(12), .DISTRIBUTED(1)) u_palette (
        .wr_clk(clk), .rd_clk(clk_pix),
        .wr_en(pal_wr_en), .wr_addr(pal_wr_addr), .wr_data(bus_wdata[11:0]), .wr_mask(1'b1),
        .rd_en(pal_rd_en), .rd_addr(pal_rd_addr), .rd_data(pal_rd_data)
    );

    gpu_raster #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .SPAN_W(SPAN_W),
                 .ENABLE_LINES(ENABLE_LINES), .ENABLE_ZBUF(ENABLE_ZBUF)) u_raster (
        .clk(clk), .rst(rst), .soft_reset(soft_reset),
        .start(start), .ctrl_clear(ctrl_clear), .ctrl_swap(ctrl_swap), .ctrl_ztest(ctrl_ztest),
        .ctrl_zclear(ctrl_zclear), .vtx_base(vtx_base), .vtx_count(vtx_count), .tri_base(tri_base), .tri_count(tri_count),
        .clear_color(clear_color), .doorbell_tag(doorbell_tag),
        .busy(busy), .done_seq(done_seq), .frame_count(frame_count), .errors(raster_errors),
        .perf(perf),
        .idx_rd_en(idx_rd_en), .idx_rd_addr(idx_rd_addr), .idx_rd_data(idx_rd_data),
        .vtx_rd_en(vtx_rd_en), .vtx_rd_addr(vtx_rd_addr), .vtx_rd_data(vtx_rd_data),
        .vz_rd_data(vz_rd_data), .z_rd_en(z_rd_en), .z_rd_addr(z_rd_addr), .z_rd_data(z_rd_data),
        .z_wr_en(z_wr_en), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data), .z_wr_mask(z_wr_mask),
        .fb_wr_en(fb_wr_en), .fb_wr_addr(fb_wr_addr), .fb_wr_data(fb_wr_data),
        .fb_wr_mask(fb_wr_mask), .vblank_start(vblank_start_sys), .swap(swap)
    );

    gpu_framebuffer #(.SPAN_W(SPAN_W)) u_framebuffer (
        .clk(clk), .rst(rst), .clk_pix(clk_pix),
        .swap(swap), .front(front),
        .wr_en(fb_wr_en), .wr_addr(fb_wr_addr), .wr_data(fb_wr_data), .wr_mask(fb_wr_mask),
        .rd_en(fb_rd_en), .rd_addr(fb_rd_addr), .rd_data(fb_rd_data)
    );

    // ---- the scan-out's clock domain ----
    wire rst_pix;
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_pix_sync (.clk(clk_pix), .in(rst), .out(rst_pix));
    gpu_cdc_pulse u_vblank_sync (
        .clk_src(clk_pix), .rst_src(rst_pix), .src_pulse(vblank_start_pix),
        .clk_dst(clk), .dst_pulse(vblank_start_sys)
    );

    gpu_vga #(.PIX_DIV(PIX_DIV)) u_vga (
        .clk(clk_pix), .rst(rst_pix),
        .fb_rd_en(fb_rd_en), .fb_rd_addr(fb_rd_addr), .fb_rd_data(fb_rd_data),
        .pal_rd_en(pal_rd_en), .pal_rd_addr(pal_rd_addr), .pal_rd_data(pal_rd_data),
        .vblank_start(vblank_start_pix),
        .vga_pix_stb(vga_pix_stb), .vga_de(vga_de), .vga_hsync_n(vga_hsync_n), .vga_vsync_n(vga_vsync_n),
        .vga_r(vga_r), .vga_g(vga_g), .vga_b(vga_b)
    );

    assign frame_swapped = swap;
    assign error = |raster_errors;
endmodule

`default_nettype wire
