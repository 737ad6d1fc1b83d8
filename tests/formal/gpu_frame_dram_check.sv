// gpu_frame_dram_check: formal properties of gpu_frame_dram (gpu_rtl/gpu_frame_dram.v), the frames
// in external memory: the strips' flushes into the back frame and the scan-out's row fetches, on
// LiteDRAM's native port (tests/formal/gpu_frame_dram.sby; make formal CHECK=gpu_frame_dram).
//
// A wrapper: the module's inputs are this module's, free at every clock under the assumptions
// below; the port's traffic is counted here and checked against a model of the flush (one tracked
// span). One clock: clk_pix is clk here, so the line schedule's crossing (gpu_cdc_pulse) and the
// underflow marks' (gpu_cdc_sync) run as on one clock; those primitives have their own proofs
// across two unrelated clocks (gpu_cdc_pulse.sby, gpu_cdc_sync.sby). Small frame, the same in
// native words at every port width NATIVE_DW (32: the SoC's, 16: the sby's bmc16 task): spans of
// two native words (SPAN_W = 2 * NATIVE_DW / 8), rows of two spans, 2 rows (16 x 2 pixels at 32
// bits, 8 x 2 at 16), frames at native words 8 and 16.
//
// Assumed (the strip buffer, the raster and LiteDRAM):
//   rst in the first clock, then at any clock;
//   flush    a valid/ready stream: once fr_valid is high it stays high, with fr_addr and fr_data,
//            until a clock with fr_ready (gpu_strip_buffer's proved property); fr_addr any span
//            of the frame (its FB_WORDS fill fr_addr's two bits);
//   swap     front changes only into a clock with fr_idle high (gpu_raster's S_CLOSE waits for
//            it, and no flush comes until the swap is done);
//   display  show_row and fetch_row rows of the frame when valid, rd_x a pixel of the row when
//            rd_en; everything else free;
//   port     write data is taken only on its command's turn (a data beat taken only after more
//            write commands than beats were accepted); read data comes only for a read command
//            accepted and not yet answered (LiteDRAM answers a port's reads in order); its data
//            marks each pixel: answer k of a run of rows (ROW_NW answers each, one fetch at a time)
//            holds in byte b the value 1 + pixel (k % ROW_NW) * PX_NW + b of the row, whatever
//            the row (the line buffer's words are then only 0, never written, or those).
// Asserted (the port's contract, gpu_frame_dram's header):
//   hold     a command presented and not taken is presented in the next clock, its kind and
//            address unchanged;
//   order    the tracked span (any one, the f_k-th taken) goes out as write commands number
//            f_k * 2 and f_k * 2 + 1 of the run, at its first native word of the back frame and
//            the next, and as data beats of the same numbers, its low word then its high word,
//            every byte enabled: every span taken is written once, in order, where it belongs,
//            none dropped;
//   back     every write command addresses the frame not shown;
//   reads    every read command addresses the frame shown, inside it;
//   counts   no write command or data beat beyond the spans taken; fr_idle exactly when every
//            taken span's data has gone; fr_ready low exactly when SPAN_Q spans wait (the queue
//            refuses only when full);
//   pixel    the clock after rd_en, rd_data is pixel rd_x of a row (1 + rd_x) or 0 (a word not
//            yet fetched): the word rd_x / PX_NW, the byte rd_x % PX_NW of it.
// Covers: a read command right after a write that had waited (the write held while the read came);
// a row fetched whole; four spans written in full with cmd_ready toggling; the row's last pixel
// (the last byte of its last word) read back from the line buffer.
`default_nettype none

module gpu_frame_dram_check #(
    parameter integer NATIVE_DW = 32,              // the port's width (the sby's tasks set it)
    localparam integer PX_NW = NATIVE_DW / 8,      // pixels a native word
    localparam integer SPAN_NW = 2,                // native words a span
    localparam integer SPAN_W = SPAN_NW * PX_NW,
    localparam integer FB_WIDTH = 2 * SPAN_W,
    localparam integer FB_HEIGHT = 2,
    localparam integer NAW = 6,
    localparam integer FRAME_BASE = 8,
    localparam integer FB_WORDS = FB_WIDTH * FB_HEIGHT / SPAN_W,
    localparam integer FAW = $clog2(FB_WORDS),
    localparam integer FRAME_NW = FB_WIDTH * FB_HEIGHT / PX_NW,
    localparam integer ROW_NW = FB_WIDTH / PX_NW,
    localparam integer SPAN_Q = 4,
    localparam integer DW = SPAN_W * 8,
    localparam integer ROW_W = gpu_pkg::ROW_W,
    localparam integer X_W = gpu_pkg::X_W,
    localparam integer CW = 6                      // the counters: wide enough for the depth
) (
    input wire             clk,
    input wire             rst,
    input wire             fr_valid,
    input wire [FAW-1:0]   fr_addr,
    input wire [DW-1:0]    fr_data,
    input wire             front,
    input wire             vblank_start,
    input wire             line_stb,
    input wire             show_valid,
    input wire [ROW_W-1:0] show_row,
    input wire             fetch_valid,
    input wire [ROW_W-1:0] fetch_row,
    input wire             rd_en,
    input wire [X_W-1:0]   rd_x,
    input wire             rd_row_odd,
    input wire             cmd_ready,
    input wire             wdata_ready,
    input wire             rdata_valid,
    input wire [NATIVE_DW-1:0] rdata_data
);
    wire           fr_ready, fr_idle, rd_invalid;
    wire [31:0]    underflows;
    wire [7:0]     rd_data;
    wire           cmd_valid, cmd_we, wdata_valid, rdata_ready;
    wire [NAW-1:0] cmd_addr;
    wire [NATIVE_DW-1:0] wdata_data;
    wire [PX_NW-1:0] wdata_we;
    gpu_frame_dram #(.FB_WIDTH(FB_WIDTH), .FB_HEIGHT(FB_HEIGHT), .SPAN_W(SPAN_W),
                     .NATIVE_DW(NATIVE_DW), .NAW(NAW), .FRAME_BASE(FRAME_BASE)) dut (
        .clk(clk), .rst(rst), .clk_pix(clk), .rst_pix(rst),
        .fr_valid(fr_valid), .fr_ready(fr_ready), .fr_addr(fr_addr), .fr_data(fr_data), .fr_idle(fr_idle),
        .front(front), .vblank_start(vblank_start), .underflows(underflows),
        .line_stb(line_stb), .show_valid(show_valid), .show_row(show_row), .fetch_valid(fetch_valid),
        .fetch_row(fetch_row), .rd_en(rd_en), .rd_x(rd_x), .rd_row_odd(rd_row_odd), .rd_data(rd_data),
        .rd_invalid(rd_invalid),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_we(cmd_we), .cmd_addr(cmd_addr),
        .wdata_valid(wdata_valid), .wdata_ready(wdata_ready), .wdata_data(wdata_data), .wdata_we(wdata_we),
        .rdata_valid(rdata_valid), .rdata_ready(rdata_ready), .rdata_data(rdata_data)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;

    // ---- the port's traffic, counted ----
    wire f_push = fr_valid && fr_ready;
    wire f_wcmd_fire = cmd_valid && cmd_ready && cmd_we;
    wire f_rcmd_fire = cmd_valid && cmd_ready && !cmd_we;
    wire f_beat = wdata_valid && wdata_ready;
    reg [CW-1:0] f_spans = '0, f_wcmds = '0, f_beats = '0, f_rcmds = '0, f_answers = '0;
    always @(posedge clk) begin
        if (rst) begin
            f_spans <= '0;
            f_wcmds <= '0;
            f_beats <= '0;
            f_rcmds <= '0;
            f_answers <= '0;
        end else begin
            f_spans <= f_spans + CW'(f_push);
            f_wcmds <= f_wcmds + CW'(f_wcmd_fire);
            f_beats <= f_beats + CW'(f_beat);
            f_rcmds <= f_rcmds + CW'(f_rcmd_fire);
            f_answers <= f_answers + CW'(rdata_valid);
        end
    end

    // Native word k of a row as the memory answers it here: byte b marks pixel k * PX_NW + b.
    function automatic [NATIVE_DW-1:0] f_row_word(input [CW-1:0] k);
        integer b;
        begin
            for (b = 0; b < PX_NW; b = b + 1) f_row_word[8 * b +: 8] = 8'(k * CW'(PX_NW) + CW'(b) + 1'b1);
        end
    endfunction

    function automatic [NAW-1:0] f_bank_base(input bank);
        f_bank_base = NAW'(FRAME_BASE) + (bank ? NAW'(FRAME_NW) : NAW'(0));
    endfunction

    // ---- assumptions ----
    always @(*) begin
        if (!f_past_valid) assume(rst);
        if (show_valid) assume(show_row < ROW_W'(FB_HEIGHT));
        if (fetch_valid) assume(fetch_row < ROW_W'(FB_HEIGHT));
        if (rd_en) assume(rd_x < X_W'(FB_WIDTH));
        if (wdata_ready) assume(f_beats < f_wcmds);
        if (rdata_valid) assume(f_answers < f_rcmds);
        if (rdata_valid) assume(rdata_data == f_row_word(f_answers % CW'(ROW_NW)));
    end
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst) && !rst) begin
            if ($past(fr_valid && !fr_ready)) begin
                assume(fr_valid);
                assume(fr_addr == $past(fr_addr));
                assume(fr_data == $past(fr_data));
            end
            if (front != $past(front)) assume(fr_idle);
        end
    end

    // ---- the tracked span: the f_k-th taken ----
    (* anyconst *) reg [2:0] f_k;
    reg           f_have = 1'b0;     // it has been taken
    reg [NAW-1:0] f_addr = '0;       // its first native word
    reg [DW-1:0]  f_data = '0;
    always @(posedge clk) begin
        if (rst) begin
            f_have <= 1'b0;
        end else if (f_push && f_spans == CW'(f_k)) begin
            f_have <= 1'b1;
            f_addr <= f_bank_base(!front) + NAW'(SPAN_NW) * NAW'(fr_addr);
            f_data <= fr_data;
        end
    end
    wire [CW-1:0] f_first = CW'(f_k) * CW'(SPAN_NW);   // its first write's number in the run

    // ---- assertions ----
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst) && !rst && $past(cmd_valid && !cmd_ready)) begin
            assert(cmd_valid);
            assert(cmd_we == $past(cmd_we));
            assert(cmd_addr == $past(cmd_addr));
        end
    end
    always @(*) begin
        if (!rst) begin
            // order: the tracked span's commands and beats
            if (f_wcmd_fire && f_wcmds >= f_first && f_wcmds < f_first + CW'(SPAN_NW)) begin
                assert(f_have);
                assert(cmd_addr == f_addr + NAW'(f_wcmds - f_first));
            end
            if (f_beat && f_beats >= f_first && f_beats < f_first + CW'(SPAN_NW)) begin
                assert(f_have);
                assert(wdata_data == f_data[NATIVE_DW * (f_beats - f_first) +: NATIVE_DW]);
                assert(wdata_we == {PX_NW{1'b1}});
            end
            // back: writes into the frame not shown, reads inside the frame shown
            if (cmd_valid && cmd_we) begin
                assert(cmd_addr >= f_bank_base(!front) && cmd_addr < f_bank_base(!front) + NAW'(FRAME_NW));
            end
            if (cmd_valid && !cmd_we) begin
                assert(cmd_addr >= NAW'(FRAME_BASE) && cmd_addr < NAW'(FRAME_BASE + 2 * FRAME_NW));
            end
            // counts
            if (cmd_valid && cmd_we) assert(f_wcmds < f_spans * CW'(SPAN_NW));
            if (wdata_valid) assert(f_beats < f_spans * CW'(SPAN_NW));
            assert(f_wcmds <= f_spans * CW'(SPAN_NW));
            assert(fr_idle == (f_beats == f_spans * CW'(SPAN_NW)));
            assert(fr_ready == (f_spans - (f_beats >> 1) < CW'(SPAN_Q)));  // SPAN_NW = 2 beats a span
            assert(rdata_ready);
        end
    end

    // pixel: the line buffer's read, a clock after rd_en (its word and the byte in it)
    always @(posedge clk) begin
        if (f_past_valid && $past(rd_en)) assert(rd_data == 8'd0 || rd_data == 8'($past(rd_x)) + 8'd1);
    end

    // ---- covers ----
    reg f_write_held = 1'b0;   // the last clock presented a write that was not taken
    reg f_held_taken = 1'b0;   // the last clock took a write that had waited
    reg [2:0] f_toggles = '0;  // cmd_ready changes while writes were presented
    reg f_prev_cmd_ready = 1'b0;
    reg f_read_last = 1'b0;    // the last clock read the row's last pixel
    always @(posedge clk) begin
        f_read_last <= rd_en && rd_x == X_W'(FB_WIDTH - 1);
        f_write_held <= !rst && cmd_valid && cmd_we && !cmd_ready;
        f_held_taken <= !rst && f_write_held && f_wcmd_fire;
        f_prev_cmd_ready <= cmd_ready;
        if (rst) f_toggles <= '0;
        else if (cmd_valid && cmd_we && cmd_ready != f_prev_cmd_ready && f_toggles != 3'd7) f_toggles <= f_toggles + 1'b1;
    end
    always @(*) begin
        if (!rst) begin
            cover(f_held_taken && f_rcmd_fire);
            cover(f_answers == CW'(ROW_NW) && f_rcmds == CW'(ROW_NW));
            cover(f_beats == CW'(4 * SPAN_NW) && fr_idle && f_toggles >= 3'd3);
            cover(f_read_last && rd_data != 8'd0);
        end
    end
endmodule

`default_nettype wire
