// gpu_raster: the batch engine — count and strip checks, fast clear, primitive pipeline
// (gpu_prim_setup -> gpu_span_walker), the strips' opening and closing, swap at vertical blank,
// counters.
//
// Contract: start (one-cycle pulse) begins a batch described by the batch inputs, which hold still
// until busy falls; soft_reset abandons it at once (RESET register). Steps and counters follow
// contract/gpu-contract.md ("A batch, and the frame handshake"). The clear writes SPAN_W pixels per clock;
// primitives are set up at one per 3 clocks while earlier ones are drawn at one span per clock.
//
// Strip builds (STRIP_ROWS > 0, contract "The strip buffer"): the raster keeps the open strip (its
// index, its bank of gpu_strip_buffer, its first span and size in the frame, whether its depths are
// cleared) and checks each batch against the rules in S_CHECK. A batch that opens a strip waits in
// S_OPEN until the other bank's flush is over, then flushes the open strip's bank and draws into the
// other; CTRL.SWAP closes the open strip in S_CLOSE and waits there until no flush runs. The frame
// addresses it puts out stay the frame's: gpu_core takes strip_base off them. A batch with
// CTRL.WALK goes from S_DRAIN back to S_CHECK on the next strip's rows while the frame has one, so
// one doorbell draws a frame of strips (the setup fetches every primitive again for each; counters
// and errors add up; a strip that breaks a rule ends the walk as an error ends a batch).
// The clear off the drawing's path: each flush leaves its bank filled with CLEAR_COLOR as it is
// then (flush_colour), and the raster remembers, per bank, that colour and the spans it covers. A
// batch that opens a strip in a bank so filled, clearing it to the same colour, draws at once: its
// clear is already done (S_CLEAR is skipped; a frame of strips pays no clear clocks but the first
// two strips' after reset and those whose colour changed).
// The depth clear off the path too: a batch that clears the strip's depths whole (ZCLEAR over all
// its rows) only advances z_epoch; gpu_core's depth buffer tags each span with the epoch it was
// last written in, and a span of another epoch reads as cleared (the walker then writes all of
// it). The tags are Z_EPOCH_BITS bits: before an epoch would come round again (every
// 2^Z_EPOCH_BITS - 2 whole clears; and after reset, when the tags are unknown) S_SCRUB writes tag
// 0, which no epoch is, to every span of the depth buffer: with the default 9 bits (a 2048 x 9
// block RAM holds the tags of a strip of up to 2,048 spans) at 640 x 480 in strips of 16, 1,280
// clocks every 17 frames.
//
// The descriptor between the two is one gpu_pkg::desc_t; the widths of its fields and their range
// arguments are in gpu_pkg.sv. The assertion below checks the edge values' bound (EDGE_NEED_W bits)
// on every descriptor in simulation.
`default_nettype none

module gpu_raster #(
    parameter integer VTX_CAP = gpu_pkg::GPU_VTX_CAP,              // build options: see gpu_top
    parameter integer TRI_CAP = gpu_pkg::GPU_TRI_CAP,
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,
    parameter integer ENABLE_LINES = gpu_pkg::GPU_DEFAULT_ENABLE_LINES,
    parameter integer ENABLE_ZBUF = gpu_pkg::GPU_DEFAULT_ENABLE_ZBUF,
    parameter integer ZBUF_BITS = gpu_pkg::GPU_DEFAULT_ZBUF_BITS,
    parameter integer ENABLE_GOURAUD = gpu_pkg::GPU_DEFAULT_ENABLE_GOURAUD,
    parameter integer STRIP_ROWS = gpu_pkg::GPU_DEFAULT_STRIP_ROWS,
    parameter integer Z_EPOCH_BITS = gpu_pkg::GPU_DEFAULT_Z_EPOCH_BITS,   // 2 .. 16
    localparam integer VI_W = $clog2(VTX_CAP),
    localparam integer TI_W = $clog2(TRI_CAP),
    localparam integer WORDS = FB_WIDTH * FB_HEIGHT / SPAN_W,   // spans in a frame
    localparam integer WAW = $clog2(WORDS),
    localparam integer CNT_W = $clog2(SPAN_W + 1),
    localparam integer ROW_W = gpu_pkg::ROW_W,
    localparam integer COLS = FB_WIDTH / SPAN_W,                // spans in a row
    localparam integer STRIP_L = (STRIP_ROWS > 1) ? $clog2(STRIP_ROWS) : 0,  // log2 of the rows
    localparam integer STRIP_WORDS = ((STRIP_ROWS > 0 && STRIP_ROWS < FB_HEIGHT) ? STRIP_ROWS : FB_HEIGHT) * COLS,
    localparam integer SAW = (STRIP_WORDS > 1) ? $clog2(STRIP_WORDS) : 1
) (
    input  wire                clk,
    input  wire                rst,
    input  wire                soft_reset,   // abandon the batch (RESET register)
    // batch (from gpu_regs)
    input  wire                start,
    input  wire                ctrl_clear,
    input  wire                ctrl_swap,
    input  wire                ctrl_ztest,
    input  wire                ctrl_zclear,
    input  wire                ctrl_dither,
    input  wire                ctrl_walk,    // draw the batch again for each strip after its rows'
    input  wire [31:0]         vtx_base,
    input  wire [31:0]         vtx_count,
    input  wire [31:0]         tri_base,
    input  wire [31:0]         tri_count,
    input  wire [7:0]          clear_color,
    input  wire [31:0]         strip,        // STRIP: {last row, first row} (contract "Strips")
    input  wire                planes_all,   // FB_WRITE_MASK writes both planes
    input  wire [31:0]         doorbell_tag,
    // status and counters (to gpu_regs)
    output wire                busy,
    output reg  [31:0]         done_seq,
    output reg  [31:0]         frame_count,
    output reg  [3:0]          errors,       // {ERR_STRIP, ERR_KIND, ERR_COUNT, ERR_VTX_INDEX}
    output gpu_pkg::perf_t     perf,         // the PERF_* counters
    // index RAM read port (both words of a primitive)
    output wire                idx_rd_en,
    output wire [TI_W-1:0]     idx_rd_addr,
    input  wire [63:0]         idx_rd_data,
    // vertex RAM read port (word 0 of a vertex)
    output wire                vtx_rd_en,
    output wire [VI_W-1:0]     vtx_rd_addr,
    input  wire [31:0]         vtx_rd_data,
    input  wire [15:0]         vz_rd_data,   // the vertex's depth (ENABLE_ZBUF)
    input  wire [15:0]         vi_rd_data,   // the vertex's intensity (ENABLE_GOURAUD)
    // depth buffer (ENABLE_ZBUF)
    output wire                z_rd_en,
    output wire [WAW-1:0]      z_rd_addr,
    input  wire [SPAN_W*16-1:0] z_rd_data,
    input  wire                z_rd_cleared, // the span read is of an older epoch (strip builds)
    output wire                z_wr_en,
    output wire [WAW-1:0]      z_wr_addr,
    output wire [SPAN_W*16-1:0] z_wr_data,
    output wire [SPAN_W-1:0]   z_wr_mask,
    output wire [Z_EPOCH_BITS-1:0] z_epoch,     // the depth clears' epoch (strip builds)
    output wire                z_scrub,      // write tag 0 at the strip's span z_scrub_addr
    output wire [SAW-1:0]      z_scrub_addr,
    // framebuffer write port (back bank, one span)
    output wire                fb_wr_en,
    output wire [WAW-1:0]      fb_wr_addr,
    output wire [SPAN_W*8-1:0] fb_wr_data,
    output wire [SPAN_W-1:0]   fb_wr_mask,
    // the strip buffer (STRIP_ROWS > 0): the bank drawn, the flush of a closed strip
    output wire [WAW-1:0]      strip_base,   // the open strip's first span in the frame
    output wire                draw_bank,
    output wire                flush,
    output wire                flush_bank,
    output wire [WAW-1:0]      flush_base,
    output wire [SAW:0]        flush_words,
    output wire [7:0]          flush_colour, // the colour the flush leaves in the bank
    input  wire [1:0]          bank_busy,
    input  wire                frame_idle,   // every flushed span is in the frame (external frames)
    // buffer swap
    input  wire                vblank_start,
    output wire                swap
);
    localparam [3:0] S_IDLE = 4'd0, S_CHECK = 4'd1, S_CLEAR = 4'd2, S_DRAW = 4'd3, S_DRAIN = 4'd4,
                     S_VBLANK = 4'd5, S_FINISH = 4'd6, S_OPEN = 4'd7, S_CLOSE = 4'd8, S_SCRUB = 4'd9;
    // A swap first closes the open strip (S_CLOSE) where there is a strip buffer.
    localparam [3:0] S_SWAP = (STRIP_ROWS > 0) ? S_CLOSE : S_VBLANK;
    reg [3:0] state_q;
    reg [WAW-1:0] clear_addr_q;
    wire pipe_rst = rst || soft_reset;

    // ---- the batch's rows (contract "Strips"), taken with start: STRIP's first row and its last
    // clamped to the frame; none when the first is after the last. The clear covers their spans,
    // words first_row * COLS .. (last_row + 1) * COLS - 1 (multiplications by a constant).
    wire [15:0] strip_first = strip[gpu_pkg::GPU_STRIP_FIRST_LSB +: 16];
    wire [15:0] strip_last = strip[gpu_pkg::GPU_STRIP_LAST_LSB +: 16];
    wire [15:0] strip_last_in = (strip_last > 16'(FB_HEIGHT - 1)) ? 16'(FB_HEIGHT - 1) : strip_last;
    wire strip_none = strip_first > strip_last_in;
    reg [ROW_W-1:0] row_first_q, row_last_q;
    reg rows_empty_q;
    reg [WAW-1:0] clear_last_q;
    // CTRL.WALK (strip builds): after the batch's rows, the next strip's rows, while the frame has
    // one; the batch runs again from S_CHECK on them.
    wire [ROW_W:0] walk_first = (ROW_W + 1)'(({1'b0, row_last_q} >> STRIP_L) + 1'b1) << STRIP_L;
    wire [ROW_W:0] walk_end = walk_first + (ROW_W + 1)'(STRIP_ROWS - 1);
    wire [ROW_W-1:0] walk_last = (walk_end > (ROW_W + 1)'(FB_HEIGHT - 1)) ? ROW_W'(FB_HEIGHT - 1)
                                                                         : walk_end[ROW_W-1:0];
    wire walk_next = STRIP_ROWS > 0 && ctrl_walk && !rows_empty_q
                  && walk_first <= (ROW_W + 1)'(FB_HEIGHT - 1);

    // ---- the strip buffer's state and rules (STRIP_ROWS > 0; contract "The strip buffer") ----
    reg open_q;                     // a strip is open: its index, bank, first span, spans
    reg [ROW_W-1:0] open_strip_q;
    reg open_bank_q;
    reg [WAW-1:0] open_base_q;
    reg [SAW:0] open_words_q;
    reg open_zclear_q;              // its depths have been cleared since it was opened
    // The batch's strip (in S_CHECK, from the rows taken at start): its rows in one strip, all of
    // them, whether it opens the strip, whether its depths are cleared after it.
    wire [ROW_W-1:0] batch_strip = row_first_q >> STRIP_L;
    wire one_strip = (row_last_q >> STRIP_L) == batch_strip;
    wire [ROW_W:0] strip_end_row = ({1'b0, batch_strip} << STRIP_L) + (ROW_W + 1)'(STRIP_ROWS - 1);
    wire whole_strip = (row_first_q & ROW_W'(STRIP_ROWS - 1)) == '0
                    && ((ROW_W + 1)'(row_last_q) == strip_end_row || row_last_q == ROW_W'(FB_HEIGHT - 1));
    wire opens = !open_q || open_strip_q != batch_strip;
    wire zclear_after = (!opens && open_zclear_q) || (zclear && whole_strip);
    wire strip_error = STRIP_ROWS > 0 && !rows_empty_q
                    && (!one_strip || (opens && !(ctrl_clear && whole_strip && planes_all))
                        || (ztest && !zclear_after));
    wire opening = STRIP_ROWS > 0 && !rows_empty_q && opens;
    wire other_busy = bank_busy[!open_bank_q];
    // What each bank's last flush left in it: its first bank_words_q spans hold bank_colour_q
    // (bank_filled_q), until the bank is drawn into again.
    reg [1:0] bank_filled_q;
    reg [7:0] bank_colour_q [0:1];
    reg [SAW:0] bank_words_q [0:1];
    wire [SAW:0] batch_words = (SAW + 1)'(clear_last_q - clear_addr_q) + 1'b1;
    wire new_bank = !open_bank_q;   // the bank a strip opening now draws into
    wire prefilled = bank_filled_q[new_bank] && bank_colour_q[new_bank] == clear_color
                  && bank_words_q[new_bank] >= batch_words;
    // What the batch's S_CLEAR writes: the colour, the depths (from S_CHECK, less what is done).
    reg clear_colour_q, clear_depth_q;
    // The depth epoch: 1 .. EPOCH_LAST current, EPOCH_UNKNOWN after reset (the tags not scrubbed).
    localparam [Z_EPOCH_BITS-1:0] EPOCH_UNKNOWN = {Z_EPOCH_BITS{1'b1}};
    localparam [Z_EPOCH_BITS-1:0] EPOCH_LAST = EPOCH_UNKNOWN - 1'b1;
    reg [Z_EPOCH_BITS-1:0] epoch_q;
    reg scrub_q;                    // the batch scrubs the tags first (S_SCRUB)
    reg [SAW-1:0] scrub_addr_q;

    // ---- front end and back end ----
    wire setup_idle, walker_idle;
    wire desc_valid, desc_ready;
    gpu_pkg::desc_t desc;
    wire walker_z_wr_en;
    wire [WAW-1:0] walker_z_wr_addr;
    wire [SPAN_W*16-1:0] walker_z_wr_data;
    wire [SPAN_W-1:0] walker_z_wr_mask;
    wire ztest = ENABLE_ZBUF != 0 && ctrl_ztest;
    wire zclear = ENABLE_ZBUF != 0 && ctrl_zclear;
    // The batch's clears, as S_CHECK finds them: a whole clear of the strip's depths is the next
    // epoch, or a scrub first (which sets epoch 1 when it is over); what is left runs in S_CLEAR.
    wire z_by_epoch = STRIP_ROWS > 0 && zclear && whole_strip && !rows_empty_q;
    wire scrub_first = z_by_epoch && epoch_q >= EPOCH_LAST;
    wire clear_colour = ctrl_clear && !rows_empty_q;
    wire clear_depth = zclear && !rows_empty_q && !z_by_epoch;
    wire ev_prim_in, ev_drawn, ev_err_kind, ev_err_index, ev_span_visit, ev_span_written;
    wire [1:0] ev_rejected;
    wire [gpu_pkg::SAMPLES_W-1:0] ev_samples;
    wire [CNT_W-1:0] ev_pixels;
    wire walker_wr_en;
    wire [WAW-1:0] walker_wr_addr;
    wire [SPAN_W*8-1:0] walker_wr_data;
    wire [SPAN_W-1:0] walker_wr_mask;

    gpu_prim_setup #(.VTX_CAP(VTX_CAP), .TRI_CAP(TRI_CAP), .FB_WIDTH(FB_WIDTH), .SPAN_W(SPAN_W),
                     .ENABLE_LINES(ENABLE_LINES), .ENABLE_ZBUF(ENABLE_ZBUF),
                     .ENABLE_GOURAUD(ENABLE_GOURAUD)) u_setup (
        .clk(clk), .rst(pipe_rst),
        .start(state_q == S_CHECK && !count_error && !strip_error), .vtx_base(vtx_base), .vtx_count(vtx_count),
        .tri_base(tri_base), .tri_count(tri_count), .ctrl_ztest(ztest), .row_first(row_first_q),
        .row_last(row_last_q), .rows_empty(rows_empty_q), .idle(setup_idle),
        .idx_rd_en(idx_rd_en), .idx_rd_addr(idx_rd_addr), .idx_rd_data(idx_rd_data),
        .vtx_rd_en(vtx_rd_en), .vtx_rd_addr(vtx_rd_addr), .vtx_rd_data(vtx_rd_data),
        .vz_rd_data(vz_rd_data), .vi_rd_data(vi_rd_data), .out_valid(desc_valid), .out_ready(desc_ready), .out_desc(desc),
        .ev_prim_in(ev_prim_in), .ev_rejected(ev_rejected), .ev_drawn(ev_drawn),
        .ev_samples(ev_samples), .ev_err_kind(ev_err_kind), .ev_err_index(ev_err_index)
    );

    // The walker does not start on a descriptor until the clear is over (the setup may run ahead).
    wire walk_enable = state_q == S_DRAW || state_q == S_DRAIN;

    gpu_span_walker #(.FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT), .SPAN_W(SPAN_W), .ENABLE_ZBUF(ENABLE_ZBUF), .ZBUF_BITS(ZBUF_BITS),
                      .ENABLE_GOURAUD(ENABLE_GOURAUD)) u_walker (
        .clk(clk), .rst(pipe_rst),
        .in_valid(desc_valid && walk_enable), .in_ready(walker_ready), .in_desc(desc), .ztest(ztest),
        .dither(ENABLE_GOURAUD != 0 && ctrl_dither), .row_first(row_first_q), .row_last(row_last_q),
        .rows_empty(rows_empty_q),
        .z_rd_en(z_rd_en), .z_rd_addr(z_rd_addr), .z_rd_data(z_rd_data), .z_rd_cleared(z_rd_cleared),
        .z_wr_en(walker_z_wr_en), .z_wr_addr(walker_z_wr_addr), .z_wr_data(walker_z_wr_data),
        .z_wr_mask(walker_z_wr_mask),
        .fb_wr_en(walker_wr_en), .fb_wr_addr(walker_wr_addr), .fb_wr_data(walker_wr_data),
        .fb_wr_mask(walker_wr_mask), .idle(walker_idle),
        .ev_span_visit(ev_span_visit), .ev_span_written(ev_span_written), .ev_pixels(ev_pixels)
    );
    wire walker_ready;
    assign desc_ready = walker_ready && walk_enable;

    // ---- framebuffer port: the clear or the walker ----
    wire clearing = state_q == S_CLEAR;
    wire fb_clearing = clearing && clear_colour_q;
    assign fb_wr_en   = fb_clearing || walker_wr_en;
    assign fb_wr_addr = clearing ? clear_addr_q : walker_wr_addr;
    assign fb_wr_data = clearing ? {SPAN_W{clear_color}} : walker_wr_data;
    assign fb_wr_mask = clearing ? {SPAN_W{1'b1}} : walker_wr_mask;
    // ... and the depth buffer: its clear (all 0xFFFF) runs beside the colour clear.
    wire zclearing = clearing && clear_depth_q;
    assign z_wr_en   = zclearing || walker_z_wr_en;
    assign z_wr_addr = zclearing ? clear_addr_q : walker_z_wr_addr;
    assign z_wr_data = zclearing ? {(SPAN_W * 16){1'b1}} : walker_z_wr_data;
    assign z_wr_mask = zclearing ? {SPAN_W{1'b1}} : walker_z_wr_mask;

    assign z_epoch = epoch_q;
    assign z_scrub = state_q == S_SCRUB;
    assign z_scrub_addr = scrub_addr_q;
    // After the opening and the scrub: the clear, if anything is left to clear.
    wire [3:0] after_scrub = (clear_colour_q || clear_depth_q) ? S_CLEAR : S_DRAW;

    // ---- batch sequencing ----
    wire [32:0] vtx_end = {1'b0, vtx_base} + {1'b0, vtx_count};
    wire [32:0] tri_end = {1'b0, tri_base} + {1'b0, tri_count};
    wire count_error = vtx_end > 33'(VTX_CAP) || tri_end > 33'(TRI_CAP);
    // The setup saw start in S_CHECK; from S_DRAIN on, idle means every primitive is written.
    wire pipeline_empty = setup_idle && walker_idle && !walker_wr_en;

    assign busy = start || (state_q != S_IDLE);
    assign swap = (state_q == S_VBLANK) && vblank_start;

    // Opening: the open strip's bank is flushed as the other becomes the drawn one. Closing: the
    // drawn bank is flushed once the other's flush is over.
    wire open_now = state_q == S_OPEN && !other_busy;
    wire close_now = state_q == S_CLOSE && open_q && !other_busy;
    assign flush = (open_now || close_now) && open_q;
    assign flush_bank = open_bank_q;
    assign flush_base = open_base_q;
    assign flush_words = open_words_q;
    assign flush_colour = clear_color;
    assign draw_bank = open_bank_q;
    assign strip_base = open_base_q;

    always @(posedge clk) begin
        if (rst || soft_reset) begin
            state_q <= S_IDLE;
            open_q <= 1'b0;  // RESET drops the open strip; a flush that runs goes on
            if (rst) begin
                done_seq <= 32'd0;
                frame_count <= 32'd0;
                errors <= 4'd0;
                perf <= '0;
                open_bank_q <= 1'b0;
                open_strip_q <= '0;
                open_base_q <= '0;
                open_words_q <= '0;
                open_zclear_q <= 1'b0;
                bank_filled_q <= 2'b00;
                epoch_q <= EPOCH_UNKNOWN;
            end
        end else begin
            if (flush) begin
                bank_filled_q[flush_bank] <= 1'b1;
                bank_colour_q[flush_bank] <= clear_color;
                bank_words_q[flush_bank] <= open_words_q;
            end
            if (state_q != S_IDLE && state_q != S_VBLANK && state_q != S_FINISH && state_q != S_CLOSE) begin
                perf.busy_cycles <= perf.busy_cycles + 32'd1;
            end
            perf.tris_in <= perf.tris_in + 32'(ev_prim_in);
            perf.tris_drawn <= perf.tris_drawn + 32'(ev_drawn);
            perf.tris_rejected <= perf.tris_rejected + 32'(ev_rejected);
            perf.samples <= perf.samples + 32'(ev_samples);
            perf.pixels <= perf.pixels + 32'(ev_pixels);
            perf.spans_written <= perf.spans_written + 32'(ev_span_written);
            perf.spans_visited <= perf.spans_visited + 32'(ev_span_visit);
            if (ev_err_index) errors[0] <= 1'b1;
            if (ev_err_kind) errors[2] <= 1'b1;
            case (state_q)
                S_IDLE: if (start) begin
                    errors <= 4'd0;
                    perf <= '0;
                    perf.busy_cycles <= 32'd1;
                    row_first_q <= ROW_W'(strip_first);  // meaningful unless rows_empty_q
                    row_last_q <= ROW_W'(strip_last_in);
                    rows_empty_q <= strip_none;
                    clear_addr_q <= WAW'(32'(strip_first[ROW_W-1:0]) * COLS);
                    clear_last_q <= WAW'(32'(strip_last_in[ROW_W-1:0]) * COLS + (COLS - 1));
                    state_q <= S_CHECK;
                end
                S_CHECK: begin
                    if (count_error || strip_error) begin
                        errors[1] <= count_error;
                        errors[3] <= strip_error;
                        state_q <= ctrl_swap ? S_SWAP : S_FINISH;
                    end else begin
                        if (STRIP_ROWS > 0 && !rows_empty_q) begin
                            open_zclear_q <= zclear_after;
                        end
                        clear_colour_q <= clear_colour;
                        clear_depth_q <= clear_depth;
                        scrub_q <= scrub_first;
                        scrub_addr_q <= '0;
                        if (z_by_epoch && !scrub_first) begin
                            epoch_q <= epoch_q + 1'b1;
                        end
                        state_q <= opening ? S_OPEN : scrub_first ? S_SCRUB
                                 : (clear_colour || clear_depth) ? S_CLEAR : S_DRAW;
                    end
                end
                S_OPEN: if (!other_busy) begin
                    // The whole strip is the batch's rows: the clear's words are the strip's.
                    open_q <= 1'b1;
                    open_strip_q <= batch_strip;
                    open_bank_q <= !open_bank_q;
                    open_base_q <= clear_addr_q;
                    open_words_q <= batch_words;
                    // Drawn into from now on: what its flush left is gone.
                    bank_filled_q[new_bank] <= 1'b0;
                    clear_colour_q <= !prefilled;
                    state_q <= scrub_q ? S_SCRUB : (!prefilled || clear_depth_q) ? S_CLEAR : S_DRAW;
                end
                S_SCRUB: begin
                    scrub_addr_q <= scrub_addr_q + 1'b1;
                    if (scrub_addr_q == SAW'(STRIP_WORDS - 1)) begin
                        epoch_q <= Z_EPOCH_BITS'(1);
                        state_q <= after_scrub;
                    end
                end
                S_CLEAR: begin
                    clear_addr_q <= clear_addr_q + 1'b1;
                    if (clear_addr_q == clear_last_q) begin
                        state_q <= S_DRAW;
                    end
                end
                S_DRAW: state_q <= S_DRAIN;  // from here the walker takes descriptors; S_DRAIN waits
                                             // for setup and walker to be idle (the setup started in S_CHECK)
                S_DRAIN: if (pipeline_empty) begin
                    if (walk_next) begin
                        row_first_q <= walk_first[ROW_W-1:0];
                        row_last_q <= walk_last;
                        clear_addr_q <= WAW'(32'(walk_first[ROW_W-1:0]) * COLS);
                        clear_last_q <= WAW'(32'(walk_last) * COLS + (COLS - 1));
                        state_q <= S_CHECK;
                    end else begin
                        state_q <= ctrl_swap ? S_SWAP : S_FINISH;
                    end
                end
                S_CLOSE: begin  // the swap's wait for the strips (none without a strip buffer)
                    if (close_now) begin
                        open_q <= 1'b0;
                    end else if (!open_q && bank_busy == 2'b00 && frame_idle) begin
                        state_q <= S_VBLANK;
                    end
                end
                S_VBLANK: if (vblank_start) begin
                    frame_count <= frame_count + 32'd1;
                    state_q <= S_FINISH;
                end
                S_FINISH: begin
                    done_seq <= doorbell_tag;
                    state_q <= S_IDLE;
                end
                default: state_q <= S_IDLE;
            endcase
        end
    end

`ifndef SYNTHESIS
    // The range argument (gpu_pkg), checked: every edge value handed to the walker fits
    // EDGE_NEED_W bits signed.
    localparam signed [gpu_pkg::EDGE_W-1:0] EDGE_LIMIT = gpu_pkg::EDGE_W'(1) <<< (gpu_pkg::EDGE_NEED_W - 1);
    always @(posedge clk) begin
        if (!rst && desc_valid && desc_ready && !desc.is_line) begin
            assert (desc.e0 < EDGE_LIMIT && desc.e0 >= -EDGE_LIMIT
                 && desc.e1 < EDGE_LIMIT && desc.e1 >= -EDGE_LIMIT
                 && desc.e2 < EDGE_LIMIT && desc.e2 >= -EDGE_LIMIT)
                else $error("gpu_raster: edge value exceeds EDGE_NEED_W bits");
        end
    end
`endif
endmodule

`default_nettype wire
