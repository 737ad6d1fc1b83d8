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
//
// FRAME_DRAM = 1 (contract "Frames in external memory"): the frames are in the memory behind the
// native port (mem_*: LiteDRAM's user port protocol, MEM_DW-bit native words with MEM_DW / 8 byte
// enables, MEM_AW native word address bits, frame 0 at native word FRAME_BASE: a byte offset in the
// memory divided by MEM_DW / 8), and gpu_frame_dram stands between the core and the display: it
// writes the strips' flushes and reads the front frame a line ahead (gpu_vga's line schedule) into
// its line buffer, which gpu_vga scans. A third crossing then: the line schedule (bundled data
// with a gpu_cdc_pulse), and the line buffer's slots' underflow marks (levels, constant while their
// slot is read; gpu_frame_dram says why). Without it the port is idle: mem_cmd_valid and
// mem_wdata_valid stay low.
`include "contract/gpu_build_params.vh"
`default_nettype none

module gpu_top #(
    `GPU_BUILD_PARAMS,                   // capacities and build options, passed to gpu_core
    parameter integer PIX_DIV = 4,       // clk_pix clocks per VGA pixel (1 for a 25 MHz clk_pix)
    // FRAME_DRAM: the memory port's native word, the SoC's SDRAM port's (LiteDRAM behind its
    // half-rate PHY: 32 bits; 16 behind a full-rate one); gpu_frame_dram says which widths work.
    parameter integer MEM_DW = 32,
    parameter integer MEM_AW = 24,       // FRAME_DRAM: native word address bits of the memory port
    parameter integer FRAME_BASE = 0,    // FRAME_DRAM: native word address of frame 0 (frame 1 follows)
    localparam integer FB_PAW = $clog2(FB_WIDTH * FB_HEIGHT),
    localparam integer FB_WAW = $clog2(FB_WIDTH * FB_HEIGHT / SPAN_W)
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
    output wire [3:0]  vga_b,
    // the frames' memory port (FRAME_DRAM), clk domain: LiteDRAM's native user port, MEM_DW bits
    output wire                mem_cmd_valid,
    input  wire                mem_cmd_ready,
    output wire                mem_cmd_we,
    output wire [MEM_AW-1:0]   mem_cmd_addr,    // native (MEM_DW-bit) word address
    output wire                mem_wdata_valid,
    input  wire                mem_wdata_ready,
    output wire [MEM_DW-1:0]   mem_wdata_data,
    output wire [MEM_DW/8-1:0] mem_wdata_we,    // byte enables, byte i in bits [8i +: 8]
    input  wire                mem_rdata_valid,
    output wire                mem_rdata_ready,
    input  wire [MEM_DW-1:0]   mem_rdata_data
);
    // Between the core and its display: vertical blank, and the front bank's and palette's reads.
    wire vblank_start_sys, vblank_start_pix;
    wire fb_rd_en, pal_rd_en;
    wire [FB_PAW-1:0] fb_rd_addr;
    wire [7:0] fb_rd_data, pal_rd_addr;
    wire [11:0] pal_rd_data;
    wire [gpu_pkg::X_W-1:0] fb_rd_x;
    wire fb_rd_row_odd, fb_rd_invalid;
    wire line_stb, show_valid, fetch_valid;
    wire [gpu_pkg::ROW_W-1:0] show_row, fetch_row;
    // The frame stream and the external frames' state (FRAME_DRAM).
    wire fb_wr_ready, fb_wr_valid, fb_wr_idle, front_bank;
    wire [FB_WAW-1:0] fb_wr_addr;
    wire [SPAN_W*8-1:0] fb_wr_data;
    wire [31:0] scanout_underflows;
    wire [7:0] core_rd_data, dram_rd_data;

    gpu_core #(`GPU_BUILD_PARAMS_PASS) u_core (
        .clk(clk), .rst(rst),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .frame_swapped(frame_swapped), .error(error),
        .vblank_start(vblank_start_sys), .clk_pix(clk_pix),
        .fb_rd_en(fb_rd_en), .fb_rd_addr(fb_rd_addr), .fb_rd_data(core_rd_data),
        .pal_rd_en(pal_rd_en), .pal_rd_addr(pal_rd_addr), .pal_rd_data(pal_rd_data),
        .fb_wr_ready(fb_wr_ready), .fb_wr_valid(fb_wr_valid), .fb_wr_addr_out(fb_wr_addr),
        .fb_wr_data_out(fb_wr_data), .fb_wr_idle(fb_wr_idle), .front_bank(front_bank),
        .scanout_underflows(scanout_underflows)
    );

    // ---- the scan-out's clock domain ----
    wire rst_pix;
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_pix_sync (.clk(clk_pix), .in(rst), .out(rst_pix));
    gpu_cdc_pulse u_vblank_sync (
        .clk_src(clk_pix), .rst_src(rst_pix), .src_pulse(vblank_start_pix),
        .clk_dst(clk), .dst_pulse(vblank_start_sys)
    );

    generate
        if (FRAME_DRAM != 0) begin : g_frame_dram
            gpu_frame_dram #(.FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT), .SPAN_W(SPAN_W),
                             .NATIVE_DW(MEM_DW), .NAW(MEM_AW), .FRAME_BASE(FRAME_BASE)) u_frames (
                .clk(clk), .rst(rst), .clk_pix(clk_pix), .rst_pix(rst_pix),
                .fr_valid(fb_wr_valid), .fr_ready(fb_wr_ready), .fr_addr(fb_wr_addr),
                .fr_data(fb_wr_data), .fr_idle(fb_wr_idle), .front(front_bank),
                .vblank_start(vblank_start_sys), .underflows(scanout_underflows),
                .line_stb(line_stb), .show_valid(show_valid), .show_row(show_row),
                .fetch_valid(fetch_valid), .fetch_row(fetch_row),
                .rd_en(fb_rd_en), .rd_x(fb_rd_x), .rd_row_odd(fb_rd_row_odd),
                .rd_data(dram_rd_data), .rd_invalid(fb_rd_invalid),
                .cmd_valid(mem_cmd_valid), .cmd_ready(mem_cmd_ready), .cmd_we(mem_cmd_we),
                .cmd_addr(mem_cmd_addr), .wdata_valid(mem_wdata_valid),
                .wdata_ready(mem_wdata_ready), .wdata_data(mem_wdata_data), .wdata_we(mem_wdata_we),
                .rdata_valid(mem_rdata_valid), .rdata_ready(mem_rdata_ready),
                .rdata_data(mem_rdata_data)
            );
            assign fb_rd_data = dram_rd_data;
            wire unused_core_rd = |core_rd_data;
        end else begin : g_frame_bram
            // The frame is block RAM: it takes a span every clock; the memory port is idle.
            assign fb_wr_ready = 1'b1;
            assign fb_wr_idle = 1'b1;
            assign scanout_underflows = 32'd0;
            assign fb_rd_data = core_rd_data;
            assign fb_rd_invalid = 1'b0;
            assign dram_rd_data = 8'd0;
            assign mem_cmd_valid = 1'b0;
            assign mem_cmd_we = 1'b0;
            assign mem_cmd_addr = {MEM_AW{1'b0}};
            assign mem_wdata_valid = 1'b0;
            assign mem_wdata_data = {MEM_DW{1'b0}};
            assign mem_wdata_we = {(MEM_DW / 8){1'b0}};
            assign mem_rdata_ready = 1'b1;
            wire unused_mem = mem_cmd_ready | mem_wdata_ready | mem_rdata_valid | (|mem_rdata_data)
                            | fb_wr_valid | (|fb_wr_addr) | (|fb_wr_data) | front_bank | line_stb
                            | show_valid | (|show_row) | fetch_valid | (|fetch_row) | (|fb_rd_x)
                            | fb_rd_row_odd | (|dram_rd_data);
        end
    endgenerate

    gpu_vga #(.PIX_DIV(PIX_DIV), .FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT)) u_vga (
        .clk(clk_pix), .rst(rst_pix),
        .fb_rd_en(fb_rd_en), .fb_rd_addr(fb_rd_addr), .fb_rd_x(fb_rd_x), .fb_rd_row_odd(fb_rd_row_odd),
        .fb_rd_data(fb_rd_data), .fb_rd_invalid(fb_rd_invalid),
        .line_stb(line_stb), .show_valid(show_valid), .show_row(show_row),
        .fetch_valid(fetch_valid), .fetch_row(fetch_row),
        .pal_rd_en(pal_rd_en), .pal_rd_addr(pal_rd_addr), .pal_rd_data(pal_rd_data),
        .vblank_start(vblank_start_pix),
        .vga_pix_stb(vga_pix_stb), .vga_de(vga_de), .vga_hsync_n(vga_hsync_n), .vga_vsync_n(vga_vsync_n),
        .vga_r(vga_r), .vga_g(vga_g), .vga_b(vga_b)
    );
endmodule

`default_nettype wire
