// gpu_top: the GPU — bus slave, vertex/index/palette RAMs, rasterizer, double framebuffer, VGA out.
//
// Contract: contract/gpu-contract.md. The CPU writes buffers and registers over the bus and rings
// DOORBELL; the GPU clears and draws into the back buffer, swaps at vertical blank when asked, and
// reports DONE_SEQ. gpu_top is gpu_core (everything but the display) with gpu_vga as its display.
// Data path: bus -> gpu_regs -> vertex/index RAM -> gpu_raster (gpu_prim_setup -> gpu_span_walker)
// -> gpu_framebuffer (back) ... (front) -> gpu_vga -> palette -> VGA pins.
// Two clock domains: everything on clk but the scan-out — the framebuffer's and the palette's read
// ports and gpu_vga — on clk_pix, one pixel every PIX_DIV clk_pix cycles (a board gives a 25 MHz
// clk_pix and PIX_DIV 1; a simulation may tie clk_pix to clk). They cross in three places, each
// with its argument: vblank_start (gpu_cdc_pulse, one a frame), the front bank (gpu_cdc_sync in
// gpu_framebuffer: it changes only at vertical blank) and the reset (gpu_cdc_sync below: rst_pix
// follows rst two clk_pix cycles later). The palette is written on clk and read on clk_pix without
// a handshake: a palette write during the visible area may show one wrong colour for one pixel (the
// firmware writes it at start and when a scene changes). The build parameters (capacities and
// options, reported in CAPS) are gpu_core's, declared once in contract/gpu_build_params.vh.
`include "contract/gpu_build_params.vh"
`default_nettype none

module gpu_top #(
    `GPU_BUILD_PARAMS,                   // capacities and build options, passed to gpu_core
    parameter integer PIX_DIV = 4,       // clk_pix clocks per VGA pixel (1 for a 25 MHz clk_pix)
    localparam integer FB_PAW = $clog2(FB_WIDTH * FB_HEIGHT)
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
    // Between the core and its display: vertical blank, and the front bank's and palette's reads.
    wire vblank_start_sys, vblank_start_pix;
    wire fb_rd_en, pal_rd_en;
    wire [FB_PAW-1:0] fb_rd_addr;
    wire [7:0] fb_rd_data, pal_rd_addr;
    wire [11:0] pal_rd_data;

    gpu_core #(`GPU_BUILD_PARAMS_PASS) u_core (
        .clk(clk), .rst(rst),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .frame_swapped(frame_swapped), .error(error),
        .vblank_start(vblank_start_sys), .clk_pix(clk_pix),
        .fb_rd_en(fb_rd_en), .fb_rd_addr(fb_rd_addr), .fb_rd_data(fb_rd_data),
        .pal_rd_en(pal_rd_en), .pal_rd_addr(pal_rd_addr), .pal_rd_data(pal_rd_data),
        .fb_wr_ready(1'b1)  // the frame is block RAM: it takes a span every clock
    );

    // ---- the scan-out's clock domain ----
    wire rst_pix;
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_pix_sync (.clk(clk_pix), .in(rst), .out(rst_pix));
    gpu_cdc_pulse u_vblank_sync (
        .clk_src(clk_pix), .rst_src(rst_pix), .src_pulse(vblank_start_pix),
        .clk_dst(clk), .dst_pulse(vblank_start_sys)
    );

    gpu_vga #(.PIX_DIV(PIX_DIV), .FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT)) u_vga (
        .clk(clk_pix), .rst(rst_pix),
        .fb_rd_en(fb_rd_en), .fb_rd_addr(fb_rd_addr), .fb_rd_data(fb_rd_data),
        .pal_rd_en(pal_rd_en), .pal_rd_addr(pal_rd_addr), .pal_rd_data(pal_rd_data),
        .vblank_start(vblank_start_pix),
        .vga_pix_stb(vga_pix_stb), .vga_de(vga_de), .vga_hsync_n(vga_hsync_n), .vga_vsync_n(vga_vsync_n),
        .vga_r(vga_r), .vga_g(vga_g), .vga_b(vga_b)
    );
endmodule

`default_nettype wire
