// gpu_frame_dram: the two frames in external memory (FRAME_DRAM builds: the SDRAM through a
// LiteDRAM native user port) — the strips' flushes written in, the front frame read out a line
// ahead of the display into an on-chip line buffer.
//
// Contract:
// - Flush port (clk): the strip buffer's valid/ready stream of frame spans (gpu_strip_buffer's
//   frame port). A span taken goes to the back frame (bank !front) as SPAN_NW native writes of
//   PX_NW pixels each, every byte enabled, the span's pixels in address order; fr_ready falls only
//   while the SPAN_Q-entry queue is full, so a memory that is slow stalls the flush and loses
//   nothing. fr_idle is high when every taken span's writes have had their data taken by the port:
//   a later read on the same port (LiteDRAM keeps one port's commands in order) sees them. The
//   swap waits for it (gpu_raster S_CLOSE).
// - Frames: a native word is NATIVE_DW bits, PX_NW = NATIVE_DW / 8 pixels. Bank b's pixel (x, y)
//   is byte p = y * FB_WIDTH + x of the native words from FRAME_BASE + b * FRAME_NW on, the
//   lowest-addressed byte in bits 7:0 (LiteDRAM's native words are little-endian): native word
//   FRAME_BASE + b * FRAME_NW + p / PX_NW, bits [8 * (p % PX_NW) +: 8].
// - Line schedule (clk_pix, gpu_vga): line_stb pulses once a display line, in its horizontal blank;
//   with it and until the next, show_* names the frame row the next display line shows and
//   fetch_* the row after it, each valid or not. The rows cross as bundled data: they change only
//   with line_stb, and the clk side samples them when line_stb's pulse has crossed (gpu_cdc_pulse),
//   two or three clocks later, by when they have been stable for at least a clock.
// - Line buffer: two slots of one frame row each, slot = row & 1. A fetch reads the front frame's
//   row into its slot (ROW_NW native words); the display reads the slot of its row, a pixel a
//   clk_pix cycle (rd_x: pixel rd_x % PX_NW of the slot's word rd_x / PX_NW; rd_row_odd, the row's
//   parity), with one cycle of latency, and rd_invalid with it.
// - Underflow: when the line schedule names a row to show whose fetch has not completed, that row's
//   slot is marked invalid for the whole display line (the display shows it in a fixed colour,
//   never half a line) and underflows counts one (saturating). The mark crosses as a level per slot
//   (gpu_cdc_sync): it changes only at the line schedule's pulse, 160 pixels before the display
//   reads that slot, and stays while the line is shown.
// - Vertical blank (vblank_start, clk): every slot forgets its row, so a row of the last frame is
//   never taken for one of the next.
// - Native port: LiteDRAM's user port protocol (cmd valid/ready with we and a native word address;
//   write data valid/ready, taken in command order, each write's data after its command; read
//   data in command order, never held back: rdata_ready is 1). One fetch at a time: a row's
//   reads are all answered before the next row's first is sent.
// - Priority: a row's read commands go before any flush write (the display must not wait); the
//   flush writes take every command slot the reads leave. A command presented stays presented,
//   its address and kind unchanged, until the port takes it.
// - After reset, until the first vertical blank, no frame is shown: both slots read invalid and
//   nothing is counted (the display may start anywhere in a frame).
//
// Bandwidth (docs/strips.md): a row of FB_WIDTH pixels is ROW_NW read commands a display line
// (800 pixel clocks); at 640 x 480, a 25 MHz pixel clock and a 50 MHz system clock, 160 of the
// 1,600 clocks of a line with 32-bit native words (320 with 16-bit ones); the deadline is the next
// line's pulse (one line; two at 320 x 240). A frame's flush is FRAME_NW write commands, one a
// clock at most: 76,800 clocks at 640 x 480 with 32-bit words (153,600 with 16-bit ones).
`default_nettype none

module gpu_frame_dram #(
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,     // the frame
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W, // pixels per flushed span
    // The port's width, LiteDRAM's native user port's: 32 behind the SoC's half-rate SDR PHY (two
    // 16-bit beats of the SDRAM's pins a system clock), 16 behind a full-rate one. Any power-of-two
    // multiple of 8 bits up to a span (SPAN_W * 8): a span is whole native words.
    parameter integer NATIVE_DW = 32,
    parameter integer NAW = 24,                             // native word address bits
    parameter integer FRAME_BASE = 0,                       // native word address of frame 0
    localparam integer PX_NW = NATIVE_DW / 8,               // pixels a native word
    localparam integer PXW = $clog2(PX_NW),                 // a pixel's index in its native word
    localparam integer PX_LANE_W = (PX_NW > 1) ? PXW : 1,   // ... as a register (1 bit at PX_NW 1)
    localparam integer SPAN_NW = SPAN_W / PX_NW,            // native words a span
    localparam integer FB_WORDS = FB_WIDTH * FB_HEIGHT / SPAN_W,
    localparam integer FAW = $clog2(FB_WORDS),
    localparam integer FRAME_NW = FB_WIDTH * FB_HEIGHT / PX_NW,
    localparam integer ROW_NW = FB_WIDTH / PX_NW,           // native words a row
    localparam integer RIW = $clog2(ROW_NW),                // a native word's index in its row
    localparam integer LANE_W = (SPAN_NW > 1) ? $clog2(SPAN_NW) : 1,
    localparam integer SPAN_Q = 4,                          // spans queued for writing
    localparam integer QW = $clog2(SPAN_Q),
    localparam integer DW = SPAN_W * 8,
    localparam integer ROW_W = gpu_pkg::ROW_W,
    localparam integer X_W = gpu_pkg::X_W
) (
    input  wire                 clk,           // system clock: flushes, fetches, the port
    input  wire                 rst,           // synchronous to clk
    input  wire                 clk_pix,       // the display's clock: the line buffer's reads
    input  wire                 rst_pix,       // synchronous to clk_pix
    // ---- flushes (clk): the strip buffer's frame port
    input  wire                 fr_valid,
    output wire                 fr_ready,
    input  wire [FAW-1:0]       fr_addr,       // frame span: y * FB_WIDTH / SPAN_W + x / SPAN_W
    input  wire [DW-1:0]        fr_data,       // pixel i of the span in bits [8i +: 8]
    output wire                 fr_idle,       // every taken span's data has gone to the port
    input  wire                 front,         // the frame shown (STATUS.FRONT); flushes go to the other
    input  wire                 vblank_start,  // one-clock pulse: the display is past the frame's last row
    output reg  [31:0]          underflows,    // rows shown before they were fetched, saturating
    // ---- the display (clk_pix): line schedule and line buffer reads
    input  wire                 line_stb,
    input  wire                 show_valid,
    input  wire [ROW_W-1:0]     show_row,
    input  wire                 fetch_valid,
    input  wire [ROW_W-1:0]     fetch_row,
    input  wire                 rd_en,
    input  wire [X_W-1:0]       rd_x,
    input  wire                 rd_row_odd,    // the row's parity: its slot
    output wire [7:0]           rd_data,
    output reg                  rd_invalid,    // the row was not fetched in time: show the fixed colour
    // ---- the native port (clk)
    output wire                 cmd_valid,
    input  wire                 cmd_ready,
    output wire                 cmd_we,
    output wire [NAW-1:0]       cmd_addr,
    output wire                 wdata_valid,
    input  wire                 wdata_ready,
    output wire [NATIVE_DW-1:0] wdata_data,
    output wire [NATIVE_DW/8-1:0] wdata_we,
    input  wire                 rdata_valid,
    output wire                 rdata_ready,
    input  wire [NATIVE_DW-1:0] rdata_data
);
    generate if (NATIVE_DW < 8 || PX_NW * 8 != NATIVE_DW || (1 << PXW) != PX_NW
                 || SPAN_NW < 1 || SPAN_NW * PX_NW != SPAN_W || (1 << LANE_W) < SPAN_NW
                 || (SPAN_NW > 1 && (1 << LANE_W) != SPAN_NW) || ROW_NW * PX_NW != FB_WIDTH
                 || FRAME_BASE + 2 * FRAME_NW > (1 << NAW)) begin : g_bad_params
        // Elaboration stops here, with this name in the error: there is no such module.
        gpu_frame_dram_needs_power_of_two_byte_native_words_whole_spans_and_both_frames_in_NAW u_bad ();
    end endgenerate

    // A constant times a variable by shifts and adds of the constant's set bits: no multiplier.
    function automatic [NAW-1:0] times(input integer k, input [NAW-1:0] v);
        integer b;
        begin
            times = {NAW{1'b0}};
            for (b = 0; b < 31; b = b + 1) begin
                if (((k >> b) & 1) != 0) times = times + (v << b);
            end
        end
    endfunction
    function automatic [NAW-1:0] bank_base(input bank);
        bank_base = NAW'(FRAME_BASE) + (bank ? NAW'(FRAME_NW) : {NAW{1'b0}});
    endfunction

    // ---- the line schedule, crossed ----
    wire sched;  // clk: the display's pulse has crossed; the rows are stable
    gpu_cdc_pulse u_sched (
        .clk_src(clk_pix), .rst_src(rst_pix), .src_pulse(line_stb), .clk_dst(clk), .dst_pulse(sched)
    );

    // ---- the fetcher and the slots (clk) ----
    localparam [ROW_W-1:0] NO_ROW = {ROW_W{1'b1}};  // beyond any frame's rows
    reg [ROW_W-1:0] slot_row_q [0:1];   // the row each slot holds or is being filled with
    reg [1:0]       slot_full_q;        // ... and whether all of it has arrived
    reg [1:0]       slot_bad_q;         // shown as invalid on its current display line
    reg             synced_q;           // a vertical blank has passed since reset: rows are checked
    reg             pend_q;             // a fetch asked for and not yet started
    reg [ROW_W-1:0] pend_row_q;
    reg [ROW_W-1:0] last_asked_q;       // the last row asked for: a row shown twice is asked twice
    reg             busy_q;             // a fetch is running: reads outstanding or to send
    reg             slot_q;             // its slot
    reg [RIW:0]     reads_left_q;       // read commands still to send
    reg [RIW-1:0]   fill_q;             // the native word of the row the next answer is
    reg [NAW-1:0]   rd_addr_q;          // the next read command's address

    wire shown_ok = slot_full_q[show_row[0]] && slot_row_q[show_row[0]] == show_row;
    wire read_go = busy_q && reads_left_q != {(RIW + 1){1'b0}};  // a read command waits
    // A write command presented and not taken is presented again (the port's payload holds until
    // taken); a read that comes meanwhile goes next.
    reg hold_write_q;
    wire read_sel = read_go && !hold_write_q;
    wire read_fire = read_sel && cmd_ready;
    wire start = !busy_q && pend_q;
    wire last_answer = rdata_valid && fill_q == RIW'(ROW_NW - 1);

    always @(posedge clk) begin
        if (rst) begin
            slot_row_q[0] <= NO_ROW;
            slot_row_q[1] <= NO_ROW;
            slot_full_q <= 2'b00;
            slot_bad_q <= 2'b11;  // until the first vertical blank: no frame is being shown yet
            synced_q <= 1'b0;
            pend_q <= 1'b0;
            pend_row_q <= NO_ROW;
            last_asked_q <= NO_ROW;
            busy_q <= 1'b0;
            slot_q <= 1'b0;
            reads_left_q <= {(RIW + 1){1'b0}};
            fill_q <= {RIW{1'b0}};
            rd_addr_q <= {NAW{1'b0}};
            underflows <= 32'd0;
        end else begin
            if (vblank_start) begin
                synced_q <= 1'b1;
                slot_row_q[0] <= NO_ROW;
                slot_row_q[1] <= NO_ROW;
                last_asked_q <= NO_ROW;
            end
            if (start) begin
                pend_q <= 1'b0;
                busy_q <= 1'b1;
                slot_q <= pend_row_q[0];
                slot_row_q[pend_row_q[0]] <= pend_row_q;
                slot_full_q[pend_row_q[0]] <= 1'b0;
                reads_left_q <= (RIW + 1)'(ROW_NW);
                fill_q <= {RIW{1'b0}};
                rd_addr_q <= bank_base(front) + times(ROW_NW, NAW'(pend_row_q));
            end
            if (read_fire) begin
                reads_left_q <= reads_left_q - 1'b1;
                rd_addr_q <= rd_addr_q + 1'b1;
            end
            if (rdata_valid) begin
                fill_q <= fill_q + 1'b1;
            end
            if (last_answer) begin
                busy_q <= 1'b0;
                slot_full_q[slot_q] <= 1'b1;
            end
            if (sched) begin
                if (show_valid && synced_q) begin
                    slot_bad_q[show_row[0]] <= !shown_ok;
                    if (!shown_ok && underflows != 32'hFFFF_FFFF) underflows <= underflows + 32'd1;
                end
                if (fetch_valid && fetch_row != last_asked_q) begin
                    pend_q <= 1'b1;
                    pend_row_q <= fetch_row;
                    last_asked_q <= fetch_row;
                end
            end
        end
    end

    // ---- the line buffer: written on clk, read on clk_pix ----
    // A slot is a row's native words as they came (ROW_NW of them, ROW_NW <= 2^RIW); the display
    // reads the word of its pixel and picks the pixel's byte a clock later, as the word arrives.
    wire [NATIVE_DW-1:0] lb_word;
    reg [PX_LANE_W-1:0] rd_lane_q;  // the pixel of the word read: rd_x % PX_NW (0 at PX_NW 1)
    gpu_ram #(.DEPTH(2 << RIW), .WIDTH(NATIVE_DW)) u_lines (
        .wr_clk(clk), .rd_clk(clk_pix),
        .wr_en(rdata_valid), .wr_addr({slot_q, fill_q}), .wr_data(rdata_data), .wr_mask(1'b1),
        .rd_en(rd_en), .rd_addr({rd_row_odd, RIW'(rd_x >> PXW)}), .rd_data(lb_word)
    );
    wire [1:0] slot_bad_pix;
    gpu_cdc_sync #(.WIDTH(2)) u_bad_sync (.clk(clk_pix), .in(slot_bad_q), .out(slot_bad_pix));
    always @(posedge clk_pix) begin
        if (rst_pix) begin
            rd_invalid <= 1'b0;
        end else if (rd_en) begin
            rd_invalid <= slot_bad_pix[rd_row_odd];
        end
    end
    always @(posedge clk_pix) begin
        if (rd_en) rd_lane_q <= PX_LANE_W'(rd_x) & PX_LANE_W'(PX_NW - 1);
    end
    assign rd_data = lb_word[rd_lane_q * 8 +: 8];

    // ---- the flush queue: spans in, native writes out ----
    reg [NAW-1:0] q_addr [0:SPAN_Q-1];   // the span's first native word
    reg [DW-1:0]  q_data [0:SPAN_Q-1];
    reg [QW:0]    tail_q, cmd_q, dat_q;  // push; next command's span; next data's span
    reg [LANE_W-1:0] cmd_lane_q, dat_lane_q;
    localparam [LANE_W-1:0] LAST_LANE = LANE_W'(SPAN_NW - 1);

    wire push = fr_valid && fr_ready;
    wire write_go = cmd_q != tail_q && !read_sel;
    wire write_fire = write_go && cmd_ready;
    wire data_fire = wdata_valid && wdata_ready;

    always @(posedge clk) begin
        if (push) begin
            q_addr[tail_q[QW-1:0]] <= bank_base(!front) + times(SPAN_NW, NAW'(fr_addr));
            q_data[tail_q[QW-1:0]] <= fr_data;
        end
    end
    always @(posedge clk) begin
        if (rst) begin
            tail_q <= {(QW + 1){1'b0}};
            cmd_q <= {(QW + 1){1'b0}};
            dat_q <= {(QW + 1){1'b0}};
            cmd_lane_q <= {LANE_W{1'b0}};
            dat_lane_q <= {LANE_W{1'b0}};
            hold_write_q <= 1'b0;
        end else begin
            hold_write_q <= write_go && !cmd_ready;
            if (push) tail_q <= tail_q + 1'b1;
            if (write_fire) begin
                cmd_lane_q <= (cmd_lane_q == LAST_LANE) ? {LANE_W{1'b0}} : cmd_lane_q + 1'b1;
                if (cmd_lane_q == LAST_LANE) cmd_q <= cmd_q + 1'b1;
            end
            if (data_fire) begin
                dat_lane_q <= (dat_lane_q == LAST_LANE) ? {LANE_W{1'b0}} : dat_lane_q + 1'b1;
                if (dat_lane_q == LAST_LANE) dat_q <= dat_q + 1'b1;
            end
        end
    end

    assign fr_ready = (tail_q - dat_q) != (QW + 1)'(SPAN_Q);
    assign fr_idle = tail_q == dat_q;

    // ---- the port ----
    assign cmd_valid = read_sel || write_go;
    assign cmd_we = !read_sel;
    assign cmd_addr = read_sel ? rd_addr_q : q_addr[cmd_q[QW-1:0]] + NAW'(cmd_lane_q);
    // A span's data may wait before its commands have gone: LiteDRAM takes each write's data only
    // on its command's turn, in order (sdram_wb_burst does the same).
    assign wdata_valid = dat_q != tail_q;
    assign wdata_data = q_data[dat_q[QW-1:0]][dat_lane_q * NATIVE_DW +: NATIVE_DW];
    assign wdata_we = {(NATIVE_DW / 8){1'b1}};
    assign rdata_ready = 1'b1;
endmodule

`default_nettype wire
