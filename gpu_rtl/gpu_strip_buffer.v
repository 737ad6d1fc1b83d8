// gpu_strip_buffer: the colour of the strip renderer (STRIP_ROWS > 0, contract "The strip buffer"):
// two banks of one strip each — the rasterizer draws into one while the other is written to the
// back frame — and the flush that writes a closed strip to the frame's write port in order.
//
// Contract:
// - Draw port: wr_* writes bank draw_bank at a span of the strip (row within the strip * COLS +
//   column), as gpu_framebuffer's write port does: a pixel mask, and with ENABLE_WMASK each pixel's
//   two 4-bit planes enabled by wr_planes. The rasterizer never draws into a bank being flushed.
// - Flush: flush (a one-cycle pulse) starts writing bank flush_bank's first flush_words spans, in
//   order, to the frame's spans flush_base, flush_base + 1, ...; bank_busy[flush_bank] is high
//   from the next clock until its last span has moved. One flush at a time: flush is only pulsed
//   while no bank is busy (gpu_raster waits for that).
// - Frame port: a valid/ready stream. A span moves on a clock with fr_valid and fr_ready; fr_valid
//   does not fall, nor do fr_addr and fr_data change, until the span has moved. fr_ready may stay
//   low for any time (a frame memory that is busy): the flush waits, nothing is dropped.
//
// - Clear on flush: the flush leaves each span it moves filled with flush_colour (taken with
//   flush), so a bank that has been flushed holds that colour in its first flush_words spans: the
//   next strip drawn into it needs no clear of its own when it clears to that colour (gpu_raster
//   keeps track of that).
//
// Both banks are one RAM, bank b at words b * 2^SAW + i: the drawn bank and the flushed one are
// never the same, so the raster's write port (A) and the flush's port (B: it reads a span and, on
// the same clock, writes the clear colour over it, reading the old word) never meet at one address,
// and a block RAM column holds both banks' lanes (at 640 x 480, 16 rows, SPAN_W 8 with the write
// mask: 16 DP16KD in true dual-port mode, as many as one write and one read port took; the padding
// to 2^SAW words costs no block RAM, whose depth is a power of two anyway). no_rw_check tells
// yosys that the ports never collide: without it, it cannot give port B's read the other port's
// same-clock write and maps the RAM to flip-flops.
//
// The flush reads the bank's block RAM one clock ahead: a read is issued only when the two-entry
// output queue will have room for its word when it arrives, so the stream moves a span every clock
// while fr_ready is high and stops without losing a word when it falls.
`default_nettype none

module gpu_strip_buffer #(
    parameter integer WORDS = 1280,        // spans in a strip: its rows times the spans in a row
    parameter integer FRAME_WORDS = 38400, // spans in the frame (the flush's addresses)
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,
    parameter integer ENABLE_WMASK = gpu_pkg::GPU_DEFAULT_ENABLE_WMASK,
    localparam integer SAW = (WORDS > 1) ? $clog2(WORDS) : 1,
    localparam integer FAW = $clog2(FRAME_WORDS),
    localparam integer LANES = (ENABLE_WMASK != 0) ? 2 * SPAN_W : SPAN_W,
    localparam integer DW = SPAN_W * 8
) (
    input  wire              clk,
    input  wire              rst,
    // draw port (the rasterizer)
    input  wire              draw_bank,
    input  wire              wr_en,
    input  wire [SAW-1:0]    wr_addr,     // span of the strip
    input  wire [DW-1:0]     wr_data,     // pixel i of the span in bits [8i +: 8]
    input  wire [SPAN_W-1:0] wr_mask,     // pixels to write
    input  wire [1:0]        wr_planes,   // planes to write, {bits [7:4], bits [3:0]} (ENABLE_WMASK)
    // flush
    input  wire              flush,
    input  wire              flush_bank,
    input  wire [FAW-1:0]    flush_base,  // the frame span of the strip's first
    input  wire [SAW:0]      flush_words, // spans to write, 1 .. WORDS
    input  wire [7:0]        flush_colour, // the colour each flushed span is left holding
    output wire [1:0]        bank_busy,
    // frame port (the back frame's writes)
    output wire              fr_valid,
    input  wire              fr_ready,
    output wire [FAW-1:0]    fr_addr,
    output wire [DW-1:0]     fr_data
);
    // ---- the two banks: one RAM ----
    wire [LANES-1:0] lane_mask;
    genvar lane;
    generate
        if (ENABLE_WMASK != 0) begin : g_planes
            for (lane = 0; lane < SPAN_W; lane = lane + 1) begin : g_lane
                assign lane_mask[2 * lane]     = wr_mask[lane] && wr_planes[0];
                assign lane_mask[2 * lane + 1] = wr_mask[lane] && wr_planes[1];
            end
        end else begin : g_pixels
            assign lane_mask = wr_mask;
            wire unused_planes = |wr_planes;
        end
    endgenerate

    reg              job_bank_q;          // the bank being flushed
    reg              job_q;               // a flush is running
    reg  [SAW:0]     issue_left_q;        // reads still to issue
    reg  [SAW-1:0]   rd_addr_q;           // the next span to read
    reg  [FAW-1:0]   rd_frame_q;          // ... and its frame span
    wire             rd_issue;
    wire [DW-1:0]    arriving;            // the word read, one clock after rd_issue

    reg  [7:0]       job_colour_q;        // the colour the flush leaves behind

    // The RAM, true dual-port (the template yosys maps to DP16KD; gpu_ram's has one write port).
    // Power-on contents are zero, as gpu_ram's.
    localparam integer LANE_W = DW / LANES;
    (* ram_style = "block", no_rw_check *) reg [DW-1:0] colour_mem [0:(2 << SAW) - 1];
    reg [DW-1:0] arriving_q;
    integer i;
    initial begin
        for (i = 0; i < (2 << SAW); i = i + 1) colour_mem[i] = {DW{1'b0}};
        arriving_q = {DW{1'b0}};
    end
    always @(posedge clk) begin  // port A: the raster draws by lanes
        for (i = 0; i < LANES; i = i + 1) begin
            if (wr_en && lane_mask[i]) colour_mem[{draw_bank, wr_addr}][i*LANE_W +: LANE_W] <= wr_data[i*LANE_W +: LANE_W];
        end
    end
    always @(posedge clk) begin  // port B: the flush reads a span and clears it on the same clock
        if (rd_issue) begin
            arriving_q <= colour_mem[{job_bank_q, rd_addr_q}];
            colour_mem[{job_bank_q, rd_addr_q}] <= {SPAN_W{job_colour_q}};
        end
    end
    assign arriving = arriving_q;

    // ---- the flush: reads one clock ahead into a two-entry queue ----
    reg            inflight_q;            // a read was issued last clock: its word arrives now
    reg  [FAW-1:0] inflight_frame_q;
    reg            head_valid_q, tail_valid_q;   // the queue: head is presented, tail behind it
    reg  [FAW-1:0] head_addr_q, tail_addr_q;
    reg  [DW-1:0]  head_data_q, tail_data_q;
    reg  [SAW:0]   move_left_q;           // spans still to move
    reg  [1:0]     busy_q;

    wire pop = head_valid_q && fr_ready;
    // Words held or on their way, less the one leaving now: issue while that leaves room.
    wire [1:0] held = 2'(head_valid_q) + 2'(tail_valid_q) + 2'(inflight_q) - 2'(pop);
    // Never in a reset's clock: a read clears the word it reads.
    assign rd_issue = !rst && job_q && issue_left_q != '0 && held < 2'd2;

    always @(posedge clk) begin
        if (rst) begin
            job_q <= 1'b0;
            job_bank_q <= 1'b0;
            issue_left_q <= '0;
            inflight_q <= 1'b0;
            head_valid_q <= 1'b0;
            tail_valid_q <= 1'b0;
            move_left_q <= '0;
            busy_q <= 2'b00;
        end else begin
            if (flush) begin
                job_q <= 1'b1;
                job_bank_q <= flush_bank;
                job_colour_q <= flush_colour;
                issue_left_q <= flush_words;
                move_left_q <= flush_words;
                rd_addr_q <= '0;
                rd_frame_q <= flush_base;
                busy_q[flush_bank] <= 1'b1;
            end else if (rd_issue) begin
                issue_left_q <= issue_left_q - 1'b1;
                rd_addr_q <= rd_addr_q + 1'b1;
                rd_frame_q <= rd_frame_q + 1'b1;
            end
            inflight_q <= rd_issue;
            inflight_frame_q <= rd_frame_q;

            // The queue: the head leaves on pop, the tail moves up, the arriving word goes to the
            // first free place.
            if (pop) begin
                head_valid_q <= tail_valid_q;
                head_addr_q <= tail_addr_q;
                head_data_q <= tail_data_q;
                tail_valid_q <= 1'b0;
            end
            if (inflight_q) begin
                if (!head_valid_q || (pop && !tail_valid_q)) begin
                    head_valid_q <= 1'b1;
                    head_addr_q <= inflight_frame_q;
                    head_data_q <= arriving;
                end else begin
                    tail_valid_q <= 1'b1;
                    tail_addr_q <= inflight_frame_q;
                    tail_data_q <= arriving;
                end
            end
            if (pop) begin
                move_left_q <= move_left_q - 1'b1;
                if (move_left_q == (SAW + 1)'(1)) begin
                    job_q <= 1'b0;
                    busy_q[job_bank_q] <= 1'b0;
                end
            end
        end
    end

    assign bank_busy = busy_q;
    assign fr_valid = head_valid_q;
    assign fr_addr = head_addr_q;
    assign fr_data = head_data_q;

`ifndef SYNTHESIS
    // The raster's side of the contract: no flush while one runs, no draw into the bank flushed.
    always @(posedge clk) begin
        if (!rst) begin
            assert (!(flush && busy_q != 2'b00)) else $error("gpu_strip_buffer: flush while a flush runs");
            assert (!(wr_en && busy_q[draw_bank])) else $error("gpu_strip_buffer: draw into a bank being flushed");
            assert (!(flush && (flush_words == '0 || flush_words > (SAW + 1)'(WORDS))))
                else $error("gpu_strip_buffer: flush of %0d spans", flush_words);
        end
    end
`endif
endmodule

`default_nettype wire
