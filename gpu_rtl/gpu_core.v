// gpu_core: the GPU without its display — bus slave, vertex/index/palette RAMs, rasterizer and the
// double framebuffer. A display reads the front framebuffer and the palette through their read
// ports (clk_pix domain) and says when vertical blank starts (vblank_start, clk domain): gpu_top's is
// gpu_vga behind a clock crossing; another display (a DVI encoder of its own timing, or the
// simulator's window, which shows the front bank after each swap) may take its place.
//
// Contract: contract/gpu-contract.md. The CPU writes buffers and registers over the bus and rings
// DOORBELL; the core clears and draws into the back buffer, and when CTRL.SWAP asks for it waits for
// the next vblank_start to swap (frame_swapped pulses), then reports DONE_SEQ. vblank_start is a
// one-cycle pulse in the clk domain, at most one per swap taken; a display pulses it when the front
// bank may change without a visible tear. The read ports have one cycle of latency: fb_rd_addr is a
// pixel of the front bank (row-major, FB_WIDTH a row), pal_rd_addr a palette entry, RGB444. The
// palette is written on clk and read on clk_pix without a handshake (gpu_top says why that is
// enough). Build options leave out what a scene does not need and are reported in CAPS. The build
// parameters (capacities and options; defaults, like the frame size, from the contract) are
// declared once, in contract/gpu_build_params.vh, generated from contract/gpu_contract.toml. What a
// build option costs: ENABLE_ZBUF 1.2 Mb more block RAM (ZBUF_BITS / 16 of it: 76,800 bits a depth
// bit kept) and a 16-bit VTX_Z RAM; ENABLE_WMASK 4-bit framebuffer lanes; ENABLE_GOURAUD a 16-bit
// VTX_I RAM, two dividers and the intensity lanes.
//
// STRIP_ROWS > 0 (contract "The strip buffer"): the rasterizer draws into gpu_strip_buffer, whose
// flush writes each closed strip to the back frame through fb_wr_ready's handshake; the depth buffer
// holds one strip, each span tagged with the epoch of its last write (Z_EPOCH_BITS; gpu_raster
// advances the epoch where it would clear the strip's depths). The rasterizer's addresses are the
// frame's; the open strip's first span (strip_base) is taken off them here.
//
// FRAME_DRAM = 1 (contract "Frames in external memory"; needs STRIP_ROWS): the frames are not here.
// The strip buffer's flush leaves as the frame stream fb_wr_* (valid/ready) for gpu_frame_dram,
// which also reads the front frame (front) for the display, counts its underflows
// (scanout_underflows, the SCANOUT_UNDERFLOWS register) and says when every flushed span has
// gone to the memory (fb_wr_idle: a swap waits for it); the read port fb_rd_* is then unused and
// reads 0.
`include "contract/gpu_build_params.vh"
`default_nettype none

module gpu_core #(
    `GPU_BUILD_PARAMS,                   // capacities and build options (contract/gpu_build_params.vh)
    localparam integer VI_W = $clog2(VTX_CAP),
    localparam integer TI_W = $clog2(TRI_CAP),
    localparam integer VTX_AW = $clog2(VTX_CAP * 2),
    localparam integer IDX_AW = $clog2(TRI_CAP * 2),
    localparam integer FB_WORDS = FB_WIDTH * FB_HEIGHT / SPAN_W,  // spans in a frame
    localparam integer FB_WAW = $clog2(FB_WORDS),
    localparam integer FB_PAW = $clog2(FB_WIDTH * FB_HEIGHT),
    localparam integer COLS = FB_WIDTH / SPAN_W,
    // the strip buffer's spans (a strip of STRIP_ROWS rows, the frame's at most), and the depth
    // buffer's: a strip's or the frame's
    localparam integer STRIP_WORDS = ((STRIP_ROWS > 0 && STRIP_ROWS < FB_HEIGHT) ? STRIP_ROWS : FB_HEIGHT) * COLS,
    localparam integer SAW = (STRIP_WORDS > 1) ? $clog2(STRIP_WORDS) : 1,
    localparam integer Z_WORDS = (STRIP_ROWS > 0) ? STRIP_WORDS : FB_WORDS,
    localparam integer ZAW = (Z_WORDS > 1) ? $clog2(Z_WORDS) : 1
) (
    input  wire        clk,           // system clock: bus, rasterizer, framebuffer writes
    input  wire        rst,           // synchronous to clk, active high
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
    // the display: vertical blank (clk domain), the read ports (clk_pix domain)
    input  wire        vblank_start,  // one-cycle pulse: the front bank may change now
    input  wire        clk_pix,       // the read ports' clock (may be clk itself)
    input  wire        fb_rd_en,
    input  wire [FB_PAW-1:0] fb_rd_addr,
    output wire [7:0]  fb_rd_data,
    input  wire        pal_rd_en,
    input  wire [7:0]  pal_rd_addr,
    output wire [11:0] pal_rd_data,
    // the back frame's writes (strip builds: a flush waits while fb_wr_ready is low; a frame in
    // block RAM takes one every clock, gpu_top ties it high; a simulation may throttle it); with
    // FRAME_DRAM the stream itself, for the external frame memory
    input  wire        fb_wr_ready,
    output wire        fb_wr_valid,
    output wire [FB_WAW-1:0] fb_wr_addr_out,
    output wire [SPAN_W*8-1:0] fb_wr_data_out,
    input  wire        fb_wr_idle,    // FRAME_DRAM: every span taken has gone to the memory
    output wire        front_bank,    // the frame shown (STATUS.FRONT)
    input  wire [31:0] scanout_underflows  // FRAME_DRAM: the display's underflows, else 0
);
    localparam [31:0] CAPS = (32'(SPAN_W) << gpu_pkg::GPU_CAPS_SPAN_W_LSB)
                           | (32'(ENABLE_LINES != 0) << gpu_pkg::GPU_CAPS_LINES_LSB)
                           | (32'(ENABLE_ZBUF != 0) << gpu_pkg::GPU_CAPS_ZBUF_LSB)
                           | (32'(ENABLE_WMASK != 0) << gpu_pkg::GPU_CAPS_WMASK_LSB)
                           | (32'(ENABLE_ZBUF != 0 ? ZBUF_BITS : 0) << gpu_pkg::GPU_CAPS_ZBUF_BITS_LSB)
                           | (32'(ENABLE_GOURAUD != 0) << gpu_pkg::GPU_CAPS_GOURAUD_LSB);

    // Batch description and status between the register block and the rasterizer.
    wire        ctrl_clear, ctrl_swap, ctrl_ztest, ctrl_zclear, ctrl_dither, ctrl_walk, start, soft_reset;
    wire        busy, front, swap;
    wire [31:0] vtx_base, vtx_count, tri_base, tri_count, doorbell_tag, done_seq, frame_count;
    wire [31:0] strip;                    // STRIP: the batch's rows
    wire [7:0]  clear_color;
    wire [3:0]  raster_errors;
    gpu_pkg::perf_t perf;                 // the PERF_* counters

    // RAM ports.
    wire              vtx_wr_en, idx_wr_en, pal_wr_en;
    wire [VTX_AW-1:0] vtx_wr_addr;
    wire [IDX_AW-1:0] idx_wr_addr;
    wire [7:0]        pal_wr_addr;
    wire              vtx_rd_en, idx_rd_en, fb_wr_en;
    wire [VI_W-1:0]   vtx_rd_addr;
    wire [TI_W-1:0]   idx_rd_addr;
    wire [31:0]       vtx_rd_data;
    wire [63:0]       idx_rd_data;
    wire [FB_WAW-1:0] fb_wr_addr;
    wire [SPAN_W*8-1:0] fb_wr_data;
    wire [SPAN_W-1:0] fb_wr_mask;
    wire [1:0] fb_wmask;  // FB_WRITE_MASK's planes, stable while busy like the other batch registers
    // The strip buffer's side of the rasterizer (STRIP_ROWS > 0).
    wire [FB_WAW-1:0] strip_base, flush_base;
    wire draw_bank, flush, flush_bank;
    wire [SAW:0] flush_words;
    wire [7:0] flush_colour;
    wire [1:0] bank_busy;

    gpu_regs #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT),
               .STRIP_ROWS(STRIP_ROWS), .CAPS(CAPS),
               .ENABLE_WMASK(ENABLE_WMASK)) u_regs (
        .clk(clk), .rst(rst),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .ctrl_clear(ctrl_clear), .ctrl_swap(ctrl_swap), .ctrl_ztest(ctrl_ztest),
        .ctrl_zclear(ctrl_zclear), .ctrl_dither(ctrl_dither), .ctrl_walk(ctrl_walk), .vtx_base(vtx_base), .vtx_count(vtx_count),
        .tri_base(tri_base), .tri_count(tri_count), .clear_color(clear_color), .fb_wmask(fb_wmask),
        .strip(strip), .doorbell_tag(doorbell_tag), .start(start), .soft_reset(soft_reset),
        .vtx_wr_en(vtx_wr_en), .vtx_wr_addr(vtx_wr_addr), .idx_wr_en(idx_wr_en),
        .idx_wr_addr(idx_wr_addr), .pal_wr_en(pal_wr_en), .pal_wr_addr(pal_wr_addr),
        .busy(busy), .front(front), .done_seq(done_seq), .frame_count(frame_count),
        .raster_errors(raster_errors), .perf(perf),
        .scanout_underflows(FRAME_DRAM != 0 ? scanout_underflows : 32'd0)
    );

    // Depth: the vertices' z (word 1) and the depth buffer exist only in a build that tests depth.
    wire [15:0] vz_rd_data;
    wire z_rd_en, z_wr_en;
    wire [FB_WAW-1:0] z_rd_addr, z_wr_addr;  // frame spans (the strip's: less strip_base)
    wire [SPAN_W*16-1:0] z_rd_data, z_wr_data;
    wire [SPAN_W-1:0] z_wr_mask;
    wire z_rd_cleared;                       // the span read is of an older epoch (strips)
    wire [Z_EPOCH_BITS-1:0] z_epoch;
    wire z_scrub;
    wire [SAW-1:0] z_scrub_addr;
    generate
        if (ZBUF_BITS < 1 || ZBUF_BITS > 16) begin : g_bad_zbuf_bits
            // Elaboration stops here, with this name in the error: there is no such module.
            gpu_core_ZBUF_BITS_must_be_1_to_16 u_bad ();
        end
        if (Z_EPOCH_BITS < 2 || Z_EPOCH_BITS > 16) begin : g_bad_z_epoch_bits
            // Elaboration stops here, with this name in the error: there is no such module.
            gpu_core_Z_EPOCH_BITS_must_be_2_to_16 u_bad ();
        end
        if (ENABLE_ZBUF != 0) begin : g_zbuf
            gpu_ram #(.DEPTH(VTX_CAP), .WIDTH(16)) u_vtx_z_ram (
                .wr_clk(clk), .rd_clk(clk),
                .wr_en(vtx_wr_en && vtx_wr_addr[0] == 1'b1), .wr_addr(vtx_wr_addr[VTX_AW-1:1]),
                .wr_data(bus_wdata[gpu_pkg::GPU_VTX_Z_LSB +: 16]), .wr_mask(1'b1),
                .rd_en(vtx_rd_en), .rd_addr(vtx_rd_addr), .rd_data(vz_rd_data)
            );
            wire [FB_WAW-1:0] z_base = (STRIP_ROWS > 0) ? strip_base : {FB_WAW{1'b0}};
            // The depth memory holds the top ZBUF_BITS bits of each lane's depth (the walker keeps
            // only those, the rest are 0): ZBUF_BITS / 16 of the block RAM of a full buffer.
            wire [SPAN_W*ZBUF_BITS-1:0] zm_wr_data, zm_rd_data;
            for (genvar l = 0; l < SPAN_W; l = l + 1) begin : g_lane
                assign zm_wr_data[l*ZBUF_BITS +: ZBUF_BITS] = z_wr_data[l*16 + 16 - ZBUF_BITS +: ZBUF_BITS];
                if (ZBUF_BITS < 16) begin : g_pad
                    wire unused_low = |z_wr_data[l*16 +: 16 - ZBUF_BITS];  // always 0: not stored
                    assign z_rd_data[l*16 +: 16] = {zm_rd_data[l*ZBUF_BITS +: ZBUF_BITS], {(16 - ZBUF_BITS){1'b0}}};
                end else begin : g_full
                    assign z_rd_data[l*16 +: 16] = zm_rd_data[l*ZBUF_BITS +: ZBUF_BITS];
                end
            end
            gpu_ram #(.DEPTH(Z_WORDS), .WIDTH(SPAN_W * ZBUF_BITS), .LANES(SPAN_W)) u_depth (
                .wr_clk(clk), .rd_clk(clk),
                .wr_en(z_wr_en), .wr_addr(ZAW'(z_wr_addr - z_base)), .wr_data(zm_wr_data), .wr_mask(z_wr_mask),
                .rd_en(z_rd_en), .rd_addr(ZAW'(z_rd_addr - z_base)), .rd_data(zm_rd_data)
            );
            if (STRIP_ROWS > 0) begin : g_epochs
                // Each span's epoch: the z_epoch of its last write (gpu_raster says why), 0 after
                // a scrub. A span of another epoch reads as cleared.
                wire [Z_EPOCH_BITS-1:0] epoch_rd;
                gpu_ram #(.DEPTH(Z_WORDS), .WIDTH(Z_EPOCH_BITS)) u_depth_epochs (
                    .wr_clk(clk), .rd_clk(clk),
                    .wr_en(z_wr_en || z_scrub),
                    .wr_addr(z_scrub ? ZAW'(z_scrub_addr) : ZAW'(z_wr_addr - z_base)),
                    .wr_data(z_scrub ? {Z_EPOCH_BITS{1'b0}} : z_epoch), .wr_mask(1'b1),
                    .rd_en(z_rd_en), .rd_addr(ZAW'(z_rd_addr - z_base)), .rd_data(epoch_rd)
                );
                assign z_rd_cleared = epoch_rd != z_epoch;
            end else begin : g_no_epochs
                assign z_rd_cleared = 1'b0;
                wire unused_epochs = z_scrub | (|z_scrub_addr) | (|z_epoch);
            end
        end else begin : g_no_zbuf
            assign vz_rd_data = 16'd0;
            assign z_rd_data = {(SPAN_W * 16){1'b0}};
            assign z_rd_cleared = 1'b0;
            wire unused_epochs = z_scrub | (|z_scrub_addr) | (|z_epoch);
            wire unused_z = z_rd_en | z_wr_en | (|z_rd_addr) | (|z_wr_addr) | (|z_wr_data) | (|z_wr_mask);
        end
    endgenerate

    // Gouraud: the vertices' intensity (word 1, VTX_I) exists only in a build that shades.
    wire [15:0] vi_rd_data;
    generate
        if (ENABLE_GOURAUD != 0) begin : g_gouraud
            gpu_ram #(.DEPTH(VTX_CAP), .WIDTH(16)) u_vtx_i_ram (
                .wr_clk(clk), .rd_clk(clk),
                .wr_en(vtx_wr_en && vtx_wr_addr[0] == 1'b1), .wr_addr(vtx_wr_addr[VTX_AW-1:1]),
                .wr_data(bus_wdata[gpu_pkg::GPU_VTX_I_LSB +: 16]), .wr_mask(1'b1),
                .rd_en(vtx_rd_en), .rd_addr(vtx_rd_addr), .rd_data(vi_rd_data)
            );
        end else begin : g_no_gouraud
            assign vi_rd_data = 16'd0;
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

    gpu_raster #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT), .SPAN_W(SPAN_W),
                 .ENABLE_LINES(ENABLE_LINES), .ENABLE_ZBUF(ENABLE_ZBUF), .ZBUF_BITS(ZBUF_BITS),
                 .ENABLE_GOURAUD(ENABLE_GOURAUD), .STRIP_ROWS(STRIP_ROWS), .Z_EPOCH_BITS(Z_EPOCH_BITS)) u_raster (
        .clk(clk), .rst(rst), .soft_reset(soft_reset),
        .start(start), .ctrl_clear(ctrl_clear), .ctrl_swap(ctrl_swap), .ctrl_ztest(ctrl_ztest),
        .ctrl_zclear(ctrl_zclear), .ctrl_dither(ctrl_dither), .ctrl_walk(ctrl_walk), .vtx_base(vtx_base), .vtx_count(vtx_count),
        .tri_base(tri_base), .tri_count(tri_count),
        .clear_color(clear_color), .strip(strip), .planes_all(fb_wmask == 2'b11),
        .doorbell_tag(doorbell_tag),
        .busy(busy), .done_seq(done_seq), .frame_count(frame_count), .errors(raster_errors),
        .perf(perf),
        .idx_rd_en(idx_rd_en), .idx_rd_addr(idx_rd_addr), .idx_rd_data(idx_rd_data),
        .vtx_rd_en(vtx_rd_en), .vtx_rd_addr(vtx_rd_addr), .vtx_rd_data(vtx_rd_data),
        .vz_rd_data(vz_rd_data), .vi_rd_data(vi_rd_data), .z_rd_en(z_rd_en), .z_rd_addr(z_rd_addr), .z_rd_data(z_rd_data),
        .z_rd_cleared(z_rd_cleared), .z_epoch(z_epoch), .z_scrub(z_scrub), .z_scrub_addr(z_scrub_addr),
        .z_wr_en(z_wr_en), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data), .z_wr_mask(z_wr_mask),
        .fb_wr_en(fb_wr_en), .fb_wr_addr(fb_wr_addr), .fb_wr_data(fb_wr_data),
        .fb_wr_mask(fb_wr_mask), .strip_base(strip_base), .draw_bank(draw_bank), .flush(flush),
        .flush_bank(flush_bank), .flush_base(flush_base), .flush_words(flush_words),
        .flush_colour(flush_colour), .bank_busy(bank_busy), .frame_idle(FRAME_DRAM == 0 || fb_wr_idle),
        .vblank_start(vblank_start), .swap(swap)
    );

    // The back frame's writes: the rasterizer's, or the strip buffer's flushes.
    wire frame_wr_en;
    wire [FB_WAW-1:0] frame_wr_addr;
    wire [SPAN_W*8-1:0] frame_wr_data;
    wire [SPAN_W-1:0] frame_wr_mask;
    wire [1:0] frame_wr_planes;
    generate
        if (STRIP_ROWS > 0) begin : g_strips
            if ((STRIP_ROWS & (STRIP_ROWS - 1)) != 0 || STRIP_ROWS > FB_HEIGHT) begin : g_bad_strip_rows
                // Elaboration stops here, with this name in the error: there is no such module.
                gpu_core_STRIP_ROWS_must_be_a_power_of_two_up_to_FB_HEIGHT u_bad ();
            end
            wire fr_valid;
            gpu_strip_buffer #(.WORDS(STRIP_WORDS), .FRAME_WORDS(FB_WORDS), .SPAN_W(SPAN_W),
                               .ENABLE_WMASK(ENABLE_WMASK)) u_strips (
                .clk(clk), .rst(rst),
                .draw_bank(draw_bank), .wr_en(fb_wr_en), .wr_addr(SAW'(fb_wr_addr - strip_base)),
                .wr_data(fb_wr_data), .wr_mask(fb_wr_mask), .wr_planes(fb_wmask),
                .flush(flush), .flush_bank(flush_bank), .flush_base(flush_base),
                .flush_words(flush_words), .flush_colour(flush_colour), .bank_busy(bank_busy),
                .fr_valid(fr_valid), .fr_ready(fb_wr_ready), .fr_addr(frame_wr_addr),
                .fr_data(frame_wr_data)
            );
            assign frame_wr_en = fr_valid && fb_wr_ready;
            assign fb_wr_valid = fr_valid;
            assign frame_wr_mask = {SPAN_W{1'b1}};
            assign frame_wr_planes = 2'b11;
        end else begin : g_frame
            assign bank_busy = 2'b00;
            assign frame_wr_en = fb_wr_en;
            assign frame_wr_addr = fb_wr_addr;
            assign frame_wr_data = fb_wr_data;
            assign frame_wr_mask = fb_wr_mask;
            assign frame_wr_planes = fb_wmask;
            assign fb_wr_valid = fb_wr_en;
            wire unused_strips = fb_wr_ready | draw_bank | flush | flush_bank | (|flush_base)
                               | (|flush_words) | (|flush_colour) | (|strip_base);
        end
    endgenerate

    assign fb_wr_addr_out = frame_wr_addr;
    assign fb_wr_data_out = frame_wr_data;
    assign front_bank = front;
    generate
        if (FRAME_DRAM != 0) begin : g_frame_dram
            if (STRIP_ROWS == 0) begin : g_bad_frame_dram
                // Elaboration stops here, with this name in the error: there is no such module.
                gpu_core_FRAME_DRAM_needs_STRIP_ROWS u_bad ();
            end
            // The frames are external: the front bank is kept here, as gpu_framebuffer keeps it.
            reg front_q;
            always @(posedge clk) begin
                if (rst) front_q <= 1'b0;
                else if (swap) front_q <= ~front_q;
            end
            assign front = front_q;
            assign fb_rd_data = 8'd0;
            wire unused_frame = frame_wr_en | (|frame_wr_mask) | (|frame_wr_planes) | fb_rd_en
                              | (|fb_rd_addr) | clk_pix;
        end else begin : g_frame_bram
            gpu_framebuffer #(.FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT), .SPAN_W(SPAN_W),
                              .ENABLE_WMASK(ENABLE_WMASK)) u_framebuffer (
                .clk(clk), .rst(rst), .clk_pix(clk_pix),
                .swap(swap), .front(front),
                .wr_en(frame_wr_en), .wr_addr(frame_wr_addr), .wr_data(frame_wr_data),
                .wr_mask(frame_wr_mask), .wr_planes(frame_wr_planes),
                .rd_en(fb_rd_en), .rd_addr(fb_rd_addr), .rd_data(fb_rd_data)
            );
            wire unused_idle = fb_wr_idle;
        end
    endgenerate


    assign frame_swapped = swap;
    assign error = |raster_errors;
endmodule

`default_nettype wire
