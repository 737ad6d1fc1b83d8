// gpu_strip_buffer_check: formal properties of gpu_strip_buffer (gpu_rtl/gpu_strip_buffer.v), the
// strip renderer's two banks and their flush to the frame's write port, from its ports
// (tests/formal/gpu_strip_buffer.sby; make formal CHECK=gpu_strip_buffer).
//
// A wrapper, not a property module instantiated by the RTL: gpu_strip_buffer has no `ifdef FORMAL
// block. Its inputs are this module's (free at every clock, under the assumptions below); a model
// of the flush from the ports (the span due next, one tracked word) is asserted against its
// outputs. For induction the invariants at the end tie its flops, and its banks' words after
// memory_map, to the model: yosys reads no hierarchical names, so they are wires f_q_* left
// undriven here and connected by the .sby's script (connect -set, after prep -flatten).
// GPU_STRIP_BUFFER_PORTS_ONLY defined (task bmc, where the broken copies run): the ports'
// properties alone, without the invariants, so each broken copy is caught by the contract.
//
// Raster (assumed): rst in the first clock, then at any clock; flush only while bank_busy is 0,
//   with flush_words 1 .. WORDS and the strip inside the frame (flush_base + flush_words <=
//   FRAME_WORDS); no draw (wr_en) into a busy bank (a draw into the bank in the clock of its
//   flush pulse is allowed: it lands before the flush's first read); wr_addr a span of the strip;
//   draw_bank, wr_data, wr_mask, wr_planes and the frame's fr_ready free.
// Strip buffer (asserted):
//   stream   once fr_valid is high it stays high, with fr_addr and fr_data, until a clock with
//            fr_ready (or a reset);
//   flush    fr_valid only during a flush; the span presented is always the next one due: frame
//            span flush_base + i for the i-th (so the spans move in order, each once: none dropped,
//            none duplicated, none without a flush, whatever fr_ready does), and the tracked word
//            f_idx of the bank moves with the value its bank held when the flush started (the
//            check's shadow of that word, every draw's lanes mirrored into it: its pixel mask and,
//            with ENABLE_WMASK, the planes of wr_planes);
//   clear    a flush leaves each span it moved holding flush_colour in every pixel: the tracked
//            word, flushed again before it is drawn, moves as that colour (the shadow takes it at
//            the flush's pulse; the flush moves the value from before). A reset in the middle
//            of a flush leaves the words it had not read as they were and the others cleared:
//            the tracked word of that bank is then unknown (not checked) until a draw writes
//            all of it or a flush clears it again;
//   busy     bank_busy is exactly the flushed bank's bit from the clock after the flush pulse to
//            the clock after its last span moved (so a flush moves exactly flush_words spans);
//   timing   a span is presented in every clock from the third after the flush pulse until the
//            last has moved (no bubble, whatever fr_ready did); a flush of N spans none of which
//            waited for fr_ready is done (bank_busy low) at the latest N + 3 clocks after its pulse.
// Covers: a whole flush of WORDS spans at full rate, a span every clock; a flush of 4 or more spans
// with fr_ready toggling; two flushes back to back, one of each bank; the tracked word moved with
// drawn (non-zero) data.
`default_nettype none

module gpu_strip_buffer_check #(
    parameter integer WORDS = 6,
    parameter integer FRAME_WORDS = 32,
    parameter integer SPAN_W = 2,
    parameter integer ENABLE_WMASK = 1,
    localparam integer SAW = (WORDS > 1) ? $clog2(WORDS) : 1,
    localparam integer FAW = $clog2(FRAME_WORDS),
    localparam integer DW = SPAN_W * 8
) (
    input wire              clk,
    input wire              rst,
    input wire              draw_bank,
    input wire              wr_en,
    input wire [SAW-1:0]    wr_addr,
    input wire [DW-1:0]     wr_data,
    input wire [SPAN_W-1:0] wr_mask,
    input wire [1:0]        wr_planes,
    input wire              flush,
    input wire              flush_bank,
    input wire [FAW-1:0]    flush_base,
    input wire [SAW:0]      flush_words,
    input wire [7:0]        flush_colour,
    input wire              fr_ready
);
    wire [1:0]     bank_busy;
    wire           fr_valid;
    wire [FAW-1:0] fr_addr;
    wire [DW-1:0]  fr_data;
    gpu_strip_buffer #(.WORDS(WORDS), .FRAME_WORDS(FRAME_WORDS), .SPAN_W(SPAN_W),
                       .ENABLE_WMASK(ENABLE_WMASK)) dut (
        .clk(clk), .rst(rst),
        .draw_bank(draw_bank), .wr_en(wr_en), .wr_addr(wr_addr), .wr_data(wr_data),
        .wr_mask(wr_mask), .wr_planes(wr_planes),
        .flush(flush), .flush_bank(flush_bank), .flush_base(flush_base),
        .flush_words(flush_words), .flush_colour(flush_colour), .bank_busy(bank_busy),
        .fr_valid(fr_valid), .fr_ready(fr_ready), .fr_addr(fr_addr), .fr_data(fr_data)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;

    // ---- the raster's side (assumed) ----
    always @(*) begin
        if (!f_past_valid) assume(rst);
        if (flush) begin
            assume(bank_busy == 2'b00);
            assume(flush_words != '0 && flush_words <= (SAW + 1)'(WORDS));
            assume(32'(flush_base) + 32'(flush_words) <= FRAME_WORDS);
        end
        if (wr_en) begin
            assume(!bank_busy[draw_bank]);
            assume(wr_addr < SAW'(WORDS));
        end
    end

    // ---- the tracked word: a shadow of word f_idx of each bank ----
    (* anyconst *) reg [SAW-1:0] f_idx;
    always @(*) assume(f_idx < SAW'(WORDS));
    reg [DW-1:0] f_wbits;   // the bits a draw stores: its pixels' (and with ENABLE_WMASK planes')
    integer p;
    always @(*) begin
        for (p = 0; p < SPAN_W; p = p + 1) begin
            if (ENABLE_WMASK != 0)
                f_wbits[8 * p +: 8] = {{4{wr_mask[p] && wr_planes[1]}},
                                       {4{wr_mask[p] && wr_planes[0]}}};
            else
                f_wbits[8 * p +: 8] = {8{wr_mask[p]}};
        end
    end
    reg  [DW-1:0] f_shadow0 = '0, f_shadow1 = '0;   // power-on contents are zero (gpu_ram)
    wire [DW-1:0] f_drawn = ((draw_bank ? f_shadow1 : f_shadow0) & ~f_wbits) | (wr_data & f_wbits);
    wire          f_draw_idx = wr_en && wr_addr == f_idx;
    // The word as a flush of bank b finds it: with a draw in the flush pulse's clock.
    wire [DW-1:0] f_start0 = (f_draw_idx && !draw_bank) ? f_drawn : f_shadow0;
    wire [DW-1:0] f_start1 = (f_draw_idx && draw_bank) ? f_drawn : f_shadow1;
    // A flush that reaches the word leaves it the flush's colour (a flush pulse is never in a
    // reset's clock by the check's use of rst below: the pulse is taken only without it).
    wire          f_clear_idx = flush && !rst && (SAW + 1)'(f_idx) < flush_words;
    wire [DW-1:0] f_cleared = {SPAN_W{flush_colour}};
    reg           f_known0 = 1'b1, f_known1 = 1'b1;   // the shadow holds the word
    wire          f_draw_all = f_draw_idx && f_wbits == {DW{1'b1}};
    always @(posedge clk) begin   // the banks have no reset: neither has the shadow
        if (f_clear_idx && !flush_bank) f_shadow0 <= f_cleared;
        else if (f_draw_idx && !draw_bank) f_shadow0 <= f_drawn;
        if (f_clear_idx && flush_bank) f_shadow1 <= f_cleared;
        else if (f_draw_idx && draw_bank) f_shadow1 <= f_drawn;
        if (rst && f_job && !f_bank) f_known0 <= 1'b0;
        else if ((f_clear_idx && !flush_bank) || (f_draw_all && !draw_bank)) f_known0 <= 1'b1;
        if (rst && f_job && f_bank) f_known1 <= 1'b0;
        else if ((f_clear_idx && flush_bank) || (f_draw_all && draw_bank)) f_known1 <= 1'b1;
    end

    // ---- the flush, from the ports ----
    reg            f_job = 1'b0;       // a flush is running (from the clock after its pulse)
    reg            f_bank = 1'b0;
    reg  [FAW-1:0] f_base = '0;
    reg  [SAW:0]   f_words = '0;
    reg  [SAW:0]   f_moved = '0;       // spans moved so far: the one presented is the next
    reg  [DW-1:0]  f_snap = '0;        // the tracked word as the flush found it
    reg            f_snap_known = 1'b1;
    reg  [3:0]     f_age = '0;         // clocks since the pulse (1 in the first busy clock),
                                       // saturating
    reg            f_waited = 1'b0;    // a span presented waited for fr_ready
    wire           f_move = fr_valid && fr_ready;
    wire           f_last = f_move && f_moved + 1'b1 == f_words;
    // for the covers
    reg            f_toggled = 1'b0;   // fr_ready changed in every clock while a span was presented
    reg            f_prev_fr_ready = 1'b0;
    reg            f_done = 1'b0;      // the last clock moved a flush's last span
    reg            f_b2b = 1'b0;       // this flush started the clock its predecessor's bank fell,
                                       // of the other bank
    always @(posedge clk) begin
        f_prev_fr_ready <= fr_ready;
        f_done <= !rst && f_job && f_last;
        if (rst) begin
            f_job <= 1'b0;
            f_moved <= '0;
        end else if (flush) begin
            f_job <= 1'b1;
            f_bank <= flush_bank;
            f_base <= flush_base;
            f_words <= flush_words;
            f_moved <= '0;
            f_snap <= flush_bank ? f_start1 : f_start0;
            f_snap_known <= flush_bank ? (f_known1 || (f_draw_all && draw_bank))
                                       : (f_known0 || (f_draw_all && !draw_bank));
            f_age <= 4'd1;
            f_waited <= 1'b0;
            f_toggled <= 1'b1;
            f_b2b <= f_done && flush_bank != f_bank;
        end else if (f_job) begin
            if (f_move) f_moved <= f_moved + 1'b1;
            if (f_last) f_job <= 1'b0;
            if (f_age != 4'd15) f_age <= f_age + 4'd1;
            if (fr_valid && !fr_ready) f_waited <= 1'b1;
            if (fr_valid && fr_ready == f_prev_fr_ready) f_toggled <= 1'b0;
        end
    end
    wire [FAW-1:0] f_moved_f = FAW'(f_moved);
    wire [FAW-1:0] f_due = f_base + f_moved_f;   // the frame span due next

    // ---- the strip buffer's side (asserted) ----
    always @(*) begin
        if (f_past_valid) begin
            assert(bank_busy == (!f_job ? 2'b00 : f_bank ? 2'b10 : 2'b01));
            if (fr_valid) begin
                assert(f_job);
                assert(fr_addr == f_due);
                if (f_moved == (SAW + 1)'(f_idx) && f_snap_known) assert(fr_data == f_snap);
            end
            if (f_job) begin
                assert(f_moved < f_words);
                if (f_age >= 4'd3) assert(fr_valid);
                if (!f_waited) assert(32'(f_age) <= 32'(f_words) + 2);
            end
        end
    end
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst) && $past(fr_valid && !fr_ready)) begin
            assert(fr_valid);
            assert(fr_addr == $past(fr_addr));
            assert(fr_data == $past(fr_data));
        end
    end

    // ---- covers ----
    always @(*) begin
        if (f_past_valid && !rst && f_job && f_last) begin
            cover(f_words == (SAW + 1)'(WORDS) && !f_waited && f_age == 4'(WORDS + 2));
            cover(f_words >= (SAW + 1)'(4) && f_toggled && f_waited && !f_prev_fr_ready);
            cover(f_b2b);
        end
        if (f_past_valid && !rst && f_job && f_move && f_moved == (SAW + 1)'(f_idx))
            cover(f_bank && fr_data != '0);
    end

`ifndef GPU_STRIP_BUFFER_PORTS_ONLY
    // ---- invariants: the strip buffer's flops (connected by the .sby) against the model ----
    wire           f_q_job, f_q_job_bank, f_q_inflight, f_q_tail_valid;
    wire [SAW:0]   f_q_issue_left, f_q_move_left;
    wire [SAW-1:0] f_q_rd_addr;
    wire [FAW-1:0] f_q_rd_frame, f_q_inflight_frame, f_q_tail_addr;
    wire [7:0]     f_q_colour;                                  // the colour the flush leaves
    wire [DW-1:0]  f_q_tail_data, f_q_rd_data;                  // rd_data: the banks' RAM's read word
    wire [WORDS*DW-1:0] f_q_mem0, f_q_mem1;                     // each bank's words, i at [i*DW]

    wire [1:0]     f_q_held = 2'(fr_valid) + 2'(f_q_tail_valid) + 2'(f_q_inflight);
    wire [SAW:0]   f_issued = f_moved + (SAW + 1)'(f_q_held);   // reads issued in this flush
    wire [SAW:0]   f_idx_w = (SAW + 1)'(f_idx);
    wire [SAW:0]   f_in_idx = f_moved + (SAW + 1)'(fr_valid) + (SAW + 1)'(f_q_tail_valid);
    always @(*) begin
        if (f_past_valid) begin
            // the tracked word in its bank: the shadow's, but as the flush found it until the
            // flush has read it
            if (f_job && !f_bank && f_idx_w >= f_issued) begin
                if (f_snap_known) assert(f_q_mem0[f_idx * DW +: DW] == f_snap);
            end else if (f_known0) assert(f_q_mem0[f_idx * DW +: DW] == f_shadow0);
            if (f_job && f_bank && f_idx_w >= f_issued) begin
                if (f_snap_known) assert(f_q_mem1[f_idx * DW +: DW] == f_snap);
            end else if (f_known1) assert(f_q_mem1[f_idx * DW +: DW] == f_shadow1);
            assert(f_q_job == f_job);
            if (!f_job) begin
                assert(!fr_valid && !f_q_tail_valid && !f_q_inflight);
                assert(f_q_issue_left == '0 && f_q_move_left == '0);
            end else begin
                assert(f_q_job_bank == f_bank);
                assert(f_words != '0 && f_words <= (SAW + 1)'(WORDS));
                assert(32'(f_base) + 32'(f_words) <= FRAME_WORDS);
                if (f_idx_w >= f_words) begin
                    assert(f_snap_known == (f_bank ? f_known1 : f_known0));
                    assert(f_snap == (f_bank ? f_shadow1 : f_shadow0));
                end else begin
                    assert(f_bank ? f_known1 : f_known0);
                    assert((f_bank ? f_shadow1 : f_shadow0) == {SPAN_W{f_q_colour}});
                end
                assert(f_q_move_left == f_words - f_moved);
                assert(f_q_held <= 2'd2);
                assert(!f_q_tail_valid || fr_valid);
                assert(f_issued <= f_words && f_q_issue_left == f_words - f_issued);
                assert(f_q_rd_addr == SAW'(f_issued));
                assert(f_q_rd_frame == f_base + FAW'(f_issued));
                if (f_q_tail_valid) assert(f_q_tail_addr == f_due + 1'b1);
                if (f_q_tail_valid && f_moved + 1'b1 == f_idx_w && f_snap_known) assert(f_q_tail_data == f_snap);
                if (f_q_inflight) assert(f_q_inflight_frame == f_base + FAW'(f_in_idx));
                if (f_q_inflight && f_in_idx == f_idx_w && f_snap_known)
                    assert(f_q_rd_data == f_snap);
                // timing: nothing in the first clock, the first read's word arriving in the
                // second, then a span presented with the next behind it (or none left to read)
                if (f_age == 4'd1) assert(f_q_held == 2'd0 && f_moved == '0);
                if (f_age == 4'd2) assert(!fr_valid && f_q_inflight && f_moved == '0);
                if (f_age >= 4'd3)
                    assert(fr_valid && (f_q_tail_valid || f_q_inflight || f_q_issue_left == '0));
                if (!f_waited && f_age >= 4'd3) assert(f_moved == (SAW + 1)'(f_age - 4'd3));
            end
        end
    end
`endif
endmodule

`default_nettype wire
