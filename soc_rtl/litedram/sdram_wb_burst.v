// sdram_wb_burst: the CPU's Wishbone B4 classic port onto a LiteDRAM native user port, with the
// rest of a cache line read ahead for incrementing bursts and writes posted.
//
// Why (docs/sdram.md): LiteDRAM 2024.12's own Wishbone port (LiteDRAMWishbone2Native) ignores CTI
// and BTE: one native command per Wishbone request, the next only after the answer, so an 8-word
// line refill costs 8 full read latencies (133 clocks). A native port of the PHY's width (16 bits)
// takes a command every clock and returns read data in command order, so a line can stream.
//
// Contract (one Wishbone word is RATIO = 32 / NATIVE_DW native words, the low half first):
//   reads   A request with wb_cti == 3'b010 (incrementing burst, BTE linear: VexRiscv's line
//           refills, 8 words from a 32-byte boundary) starts a *run*: native read commands for its
//           word and every word after it up to the end of its LINE_WORDS line (never further, so
//           never past the SDRAM's end), one a clock as native_cmd_ready allows. Any other CTI
//           (000 classic, 111 end) reads the one word. The data go into a line buffer (the FIFO:
//           written in native order, read in beat order; distributed RAM or flops, no block RAM).
//           A read of the run's next word is acked as soon as its last native word is in: in the
//           very clock it arrives (from native_rdata_data), or at once if it is already buffered,
//           so one beat a clock at best. The first command goes out in the request's first clock;
//           with LiteDRAM 2024.12's HalfRateGENSDRPHY at CL 2 (its inputs registered:
//           gen_litedram.py) and a 32-bit port the first beat is acked in the request's 7th or 8th
//           clock (row open), the rest one a clock: an 8-word line in 14-15 clocks (22-23 with
//           the full-rate PHY and a 16-bit port, one beat every 2 clocks; tests/sdram/litedram.sh
//           measures it).
//           The run ends when its last word is acked. It is abandoned — its outstanding reads
//           drained (discarded) before any other request is served — when an acked beat says it is
//           the last (wb_cti != 010) before the run's end, when a request asks for anything but
//           the run's next word (another address, a write), or when wb_cyc falls. wb_stb low with
//           wb_cyc high is a wait state: the run waits. No read is issued while a request for
//           anything else is on the bus, nor past a requested word that says it is the last.
//   writes  Single words (CTI ignored: VexRiscv's D$ is write-through and never bursts writes)
//           with lanes from wb_sel, posted: acked in the request's first clock while the write
//           queue (WQ_DEPTH words) has room and no read run is open, then sent as RATIO native
//           writes (wdata_we the lanes of wb_sel) in order, one command a clock: a store every
//           RATIO clocks once the queue is full. A read starts only after every queued
//           write's commands have gone out: LiteDRAM keeps one port's commands in order (its
//           crossbar locks a port to one bank machine while a command of it waits there, and a
//           bank machine serves its FIFO in order), so the read sees every earlier write.
//   errors  Before init_done (LiteDRAM ignores its ports until the power-up sequence is done) a
//           request gets wb_err in its second clock and reaches no native port. init_done must not
//           fall again except by rst.
//   native  LiteDRAM's user port at the controller's width: rdata is never held back (its crossbar
//           has no rdata ready: native_rdata_ready is 1), the write data is taken on wdata_ready,
//           which follows each write command's turn in the controller (wdata_valid is high
//           whenever queued data waits). At most LINE_WORDS * RATIO reads are outstanding: the
//           buffer has room for every one.
`default_nettype none

module sdram_wb_burst #(
    parameter integer AW = 23,           // Wishbone word address bits: the SDRAM holds 4 << AW bytes
    parameter integer NATIVE_DW = 16,    // LiteDRAM's native port: 16 (the PHY's, no converter) or 32
    parameter integer LINE_WORDS = 8,    // the caches' line (32 bytes): where a burst's read-ahead stops
    parameter integer WQ_DEPTH = 4,      // posted writes held (a power of two): stores at the pins' rate
    localparam integer RATIO = 32 / NATIVE_DW,          // native words per Wishbone word
    localparam integer RW = $clog2(RATIO),              // native address bits below a Wishbone word's
    localparam integer LNW = RW > 0 ? RW : 1,           // a lane number's width
    localparam integer NB = NATIVE_DW / 8,              // native byte lanes
    localparam integer NAW = AW + RW,                   // native word address bits
    localparam integer LW = $clog2(LINE_WORDS),         // word offset within a line
    localparam integer NI = LW + RW,                    // native index within a line
    localparam integer LINE_N = LINE_WORDS * RATIO,     // native words in a line
    localparam integer QW = $clog2(WQ_DEPTH)            // write queue index
) (
    input  wire                 clk,
    input  wire                 rst,                 // synchronous, active high (with LiteDRAM's)
    input  wire                 init_done,           // LiteDRAM serves its ports (power-up sequence done)
    // ---- Wishbone B4 classic slave (the CPU's SDRAM region)
    input  wire                 wb_cyc,
    input  wire                 wb_stb,              // this slave selected (the decoder's)
    input  wire                 wb_we,
    input  wire [AW-1:0]        wb_adr,              // word address in the SDRAM
    input  wire [31:0]          wb_dat_w,
    input  wire [3:0]           wb_sel,              // byte lanes of a write
    input  wire [2:0]           wb_cti,              // 3'b010: another beat follows at wb_adr + 1
    output wire [31:0]          wb_dat_r,            // valid with wb_ack of a read
    output wire                 wb_ack,
    output wire                 wb_err,              // only before init_done
    // ---- LiteDRAM native user port: commands
    output reg                  native_cmd_valid,
    input  wire                 native_cmd_ready,
    output reg                  native_cmd_we,
    output reg  [NAW-1:0]       native_cmd_addr,     // native word address
    // ---- write data, one per write command, in order
    output wire                 native_wdata_valid,
    input  wire                 native_wdata_ready,  // the controller takes the oldest write's data now
    output wire [NATIVE_DW-1:0] native_wdata_data,
    output wire [NB-1:0]        native_wdata_we,     // byte enables
    // ---- read data, one per read command, in order
    input  wire                 native_rdata_valid,
    output wire                 native_rdata_ready,  // always 1: LiteDRAM cannot wait
    input  wire [NATIVE_DW-1:0] native_rdata_data
);
    generate if (RATIO * NATIVE_DW != 32 || RATIO > 2 || (1 << LW) != LINE_WORDS || LW > AW
                 || (1 << QW) != WQ_DEPTH || QW < 1) begin : g_bad_params
        $error("sdram_wb_burst: NATIVE_DW 16 or 32, LINE_WORDS and WQ_DEPTH (>= 2) powers of two");
    end endgenerate

    wire req    = wb_cyc && wb_stb;
    wire rd_req = req && !wb_we;
    wire wr_req = req && wb_we;
    wire burst  = wb_cti == 3'b010;

    // ---- the read run ----
    localparam [1:0] IDLE = 2'd0,    // no run: no read outstanding
                     RUN = 2'd1,     // a run: its next word is line_q:head_q
                     DRAIN = 2'd2;   // an abandoned run: discarding its outstanding reads
    reg [1:0]     st_q = IDLE, st_d;
    reg [AW-LW-1:0] line_q = '0, line_d;   // the run's line
    reg [LW:0]    head_q = '0, head_d;     // the next word to answer (offset in the line)
    reg [NI:0]    issue_q = '0, issue_d;   // the next native read to command (index in the line)
    reg [NI:0]    fill_q = '0, fill_d;     // the next native read to arrive
    reg [NI:0]    end_q = '0, end_d;       // where the run's commands stop (LINE_N for a burst)
    reg [NATIVE_DW-1:0] rbuf [0:LINE_N-1]; // the line buffer, by native index

    wire [NI:0] head_n   = (NI + 1)'(head_q) << RW;      // the head word's first native index
    wire [NI:0] head_end = head_n + (NI + 1)'(RATIO);    // ... and the one after its last
    wire [AW-1:0] head_adr = {line_q, head_q[LW-1:0]};
    wire [NI:0] start_n  = (NI + 1)'(wb_adr[LW-1:0]) << RW;  // a new run's first native index
    // The request asks for the run's next word; it is answered once the word's last native word
    // is in (or arrives now: the data bypass the buffer).
    wire match = rd_req && st_q == RUN && wb_adr == head_adr;
    wire arrive_last = native_rdata_valid && fill_q + 1'b1 == head_end;
    wire hit = match && (fill_q >= head_end || arrive_last);
    // A request for anything else, or the master gone: the run is abandoned.
    wire abandon = st_q == RUN && ((req && !match) || !wb_cyc);

    // ---- the write queue ----
    reg [AW-1:0]  wq_adr [0:WQ_DEPTH-1];
    reg [31:0]    wq_dat [0:WQ_DEPTH-1];
    reg [3:0]     wq_sel [0:WQ_DEPTH-1];
    reg [QW:0]    wq_tail_q = '0;          // the next entry to fill
    reg [QW:0]    wq_cmd_q = '0;           // the oldest entry whose commands are not all sent
    reg [LNW-1:0] wq_clane_q = '0;         // ... its next lane
    reg [QW:0]    wq_dat_q = '0;           // the oldest entry whose data are not all taken
    reg [LNW-1:0] wq_dlane_q = '0;         // ... its next lane
    wire [QW:0] wq_used = wq_tail_q - wq_dat_q;
    wire wq_full = wq_used == (QW + 1)'(WQ_DEPTH);
    wire wq_cmds = wq_cmd_q != wq_tail_q;  // write commands still to send
    localparam [LNW-1:0] LAST_LANE = LNW'(RATIO - 1);

    wire start_rd = rd_req && st_q == IDLE && init_done && !wq_cmds;
    wire wr_accept = wr_req && st_q == IDLE && init_done && !wq_full;

    // ---- the native command: queued writes first, then the run's reads, or a new run's first ----
    // The run's reads stop while a request for anything else is on the bus, and go no further than
    // the requested word once the master says it is its last (CTI not 010; end_q from then on).
    wire [NI:0] issue_end = match && !burst ? head_end : end_q;
    wire run_issue = st_q == RUN && issue_q < issue_end && !(req && !match);
    wire [QW-1:0] wq_ci = wq_cmd_q[QW-1:0];
    always @(*) begin
        native_cmd_valid = 1'b0;
        native_cmd_we = 1'b0;
        native_cmd_addr = {line_q, issue_q[NI-1:0]};
        if (wq_cmds) begin
            native_cmd_valid = 1'b1;
            native_cmd_we = 1'b1;
            native_cmd_addr = (NAW'(wq_adr[wq_ci]) << RW) | NAW'(wq_clane_q);
        end else if (run_issue) begin
            native_cmd_valid = 1'b1;
        end else if (start_rd) begin
            native_cmd_valid = 1'b1;
            native_cmd_addr = NAW'(wb_adr) << RW;
        end
    end
    wire cmd_fire = native_cmd_valid && native_cmd_ready;

    // ---- the run's next state ----
    always @(*) begin
        st_d = st_q;
        line_d = line_q;
        head_d = head_q;
        issue_d = issue_q;
        fill_d = fill_q;
        end_d = end_q;
        if (st_q != IDLE && native_rdata_valid) fill_d = fill_q + 1'b1;
        case (st_q)
            IDLE: if (start_rd) begin
                st_d = RUN;
                line_d = wb_adr[AW-1:LW];
                head_d = {1'b0, wb_adr[LW-1:0]};
                fill_d = start_n;
                issue_d = start_n + (NI + 1)'(cmd_fire);
                end_d = burst ? (NI + 1)'(LINE_N) : start_n + (NI + 1)'(RATIO);
            end
            RUN: begin
                if (run_issue && cmd_fire) issue_d = issue_q + 1'b1;
                if (match && !burst) end_d = head_end;   // the master's last word: the run's too
                if (hit) begin
                    head_d = head_q + 1'b1;
                    // The run's last word answered, or the master's: reads past it (only when the
                    // master ended its burst early) are dropped; with none, IDLE at once (below).
                    if (head_end == end_q || !burst) st_d = DRAIN;
                end else if (abandon) begin
                    st_d = DRAIN;
                end
            end
            default: ;  // DRAIN: no command; the reads still due arrive and are dropped
        endcase
        if (st_d == DRAIN && fill_d == issue_d) st_d = IDLE;   // nothing left to drop
    end

    always @(posedge clk) begin
        if (rst) begin
            st_q <= IDLE;
        end else begin
            st_q <= st_d;
        end
        line_q <= line_d;
        head_q <= head_d;
        issue_q <= issue_d;
        fill_q <= fill_d;
        end_q <= end_d;
        if (st_q == RUN && native_rdata_valid) rbuf[fill_q[NI-1:0]] <= native_rdata_data;
    end

    // The answer: the head word from the buffer, its last native word from the port if it arrives now.
    wire [NI-1:0] head_last = head_end[NI-1:0] - 1'b1;
    genvar r;
    generate for (r = 0; r < RATIO; r = r + 1) begin : g_lane
        if (r == RATIO - 1) begin : g_last
            assign wb_dat_r[r*NATIVE_DW +: NATIVE_DW] = fill_q[NI-1:0] == head_last && native_rdata_valid
                                                        ? native_rdata_data : rbuf[head_last];
        end else begin : g_buffered
            assign wb_dat_r[r*NATIVE_DW +: NATIVE_DW] = rbuf[head_n[NI-1:0] | NI'(r)];
        end
    end endgenerate
    assign native_rdata_ready = 1'b1;

    // ---- the write queue's pointers ----
    // A queued write's command goes whenever the port is ready (the command is valid whenever writes
    // wait): written without cmd_fire, which also holds a new read's request from the bus, so that
    // no path runs from the bus's request into the queue's pointers (the USB build's, 19.4 ns).
    wire wq_cmd_fire = wq_cmds && native_cmd_ready;
    wire wq_dat_fire = native_wdata_ready && native_wdata_valid;
    wire [QW-1:0] wq_di = wq_dat_q[QW-1:0];
    always @(posedge clk) begin
        if (wr_accept) begin
            wq_adr[wq_tail_q[QW-1:0]] <= wb_adr;
            wq_dat[wq_tail_q[QW-1:0]] <= wb_dat_w;
            wq_sel[wq_tail_q[QW-1:0]] <= wb_sel;
        end
        if (rst) begin
            wq_tail_q <= '0;
            wq_cmd_q <= '0;
            wq_clane_q <= '0;
            wq_dat_q <= '0;
            wq_dlane_q <= '0;
        end else begin
            if (wr_accept) wq_tail_q <= wq_tail_q + 1'b1;
            if (wq_cmd_fire) begin
                wq_clane_q <= wq_clane_q == LAST_LANE ? '0 : wq_clane_q + 1'b1;
                if (wq_clane_q == LAST_LANE) wq_cmd_q <= wq_cmd_q + 1'b1;
            end
            if (wq_dat_fire) begin
                wq_dlane_q <= wq_dlane_q == LAST_LANE ? '0 : wq_dlane_q + 1'b1;
                if (wq_dlane_q == LAST_LANE) wq_dat_q <= wq_dat_q + 1'b1;
            end
        end
    end
    assign native_wdata_valid = wq_dat_q != wq_tail_q;
    wire [31:0] wq_dat_head = wq_dat[wq_di];
    wire [3:0]  wq_sel_head = wq_sel[wq_di];
    assign native_wdata_data = wq_dat_head[wq_dlane_q * NATIVE_DW +: NATIVE_DW];
    assign native_wdata_we = wq_sel_head[wq_dlane_q * NB +: NB];

    // ---- answers ----
    // Before init_done: err in a request's second clock (the flop marks its first).
    reg early_err_q = 1'b0;
    always @(posedge clk) begin
        if (rst) early_err_q <= 1'b0;
        else     early_err_q <= req && !init_done && !early_err_q;
    end
    assign wb_ack = wr_accept || hit;
    assign wb_err = early_err_q && req && !init_done;

`ifdef FORMAL
    // ---- formal properties (tests/formal/sdram_wb_burst.sby: proved by induction) ----
    // The bus and native-port properties, assumed and asserted, are in
    // tests/formal/sdram_wb_burst_check.sv; here, the invariants that tie the flops to its model.
    localparam integer PW = $clog2(RATIO * WQ_DEPTH + 1);
    wire                 f_past_valid, f_busy, f_lastrd_valid, f_t_start, f_t_on;
    wire [NI:0]          f_rd_out;
    wire [LINE_N-1:0]    f_rq;
    wire [NAW-1:0]       f_naddr;
    wire [NATIVE_DW-1:0] f_val;
    wire [AW-1:0]        f_lastrd, f_t_adr;
    wire [2:0]           f_lastcti;
    wire [PW-1:0]        f_wc_owe, f_wd_owe, f_t_cpos, f_t_dpos;
    wire [LNW:0]         f_t_clane, f_t_dlane;
    wire [31:0]          f_t_dat;
    wire [3:0]           f_t_sel;
    sdram_wb_burst_check #(
        .AW(AW), .NATIVE_DW(NATIVE_DW), .LINE_WORDS(LINE_WORDS), .WQ_DEPTH(WQ_DEPTH)
    ) f_check (
        .clk(clk), .rst(rst), .init_done(init_done),
        .wb_cyc(wb_cyc), .wb_stb(wb_stb), .wb_we(wb_we), .wb_adr(wb_adr), .wb_dat_w(wb_dat_w),
        .wb_sel(wb_sel), .wb_cti(wb_cti), .wb_dat_r(wb_dat_r), .wb_ack(wb_ack), .wb_err(wb_err),
        .native_cmd_valid(native_cmd_valid), .native_cmd_ready(native_cmd_ready),
        .native_cmd_we(native_cmd_we), .native_cmd_addr(native_cmd_addr),
        .native_wdata_valid(native_wdata_valid), .native_wdata_ready(native_wdata_ready),
        .native_wdata_data(native_wdata_data), .native_wdata_we(native_wdata_we),
        .native_rdata_valid(native_rdata_valid), .native_rdata_ready(native_rdata_ready),
        .native_rdata_data(native_rdata_data),
        .f_past_valid(f_past_valid), .f_busy(f_busy), .f_rd_out(f_rd_out), .f_rq(f_rq),
        .f_naddr(f_naddr), .f_val(f_val), .f_lastrd_valid(f_lastrd_valid), .f_lastrd(f_lastrd),
        .f_lastcti(f_lastcti),
        .f_wc_owe(f_wc_owe), .f_wd_owe(f_wd_owe), .f_t_start(f_t_start), .f_t_on(f_t_on),
        .f_t_cpos(f_t_cpos), .f_t_clane(f_t_clane), .f_t_dpos(f_t_dpos), .f_t_dlane(f_t_dlane),
        .f_t_adr(f_t_adr), .f_t_dat(f_t_dat), .f_t_sel(f_t_sel)
    );

    // The tracked write's queue entry; how the run began (a single read's run is its one word).
    reg [QW:0] f_t_idx = '0;
    reg        f_burst_run = 1'b0;
    always @(posedge clk) begin
        if (f_t_start) f_t_idx <= wq_tail_q;
        if (start_rd) f_burst_run <= burst;
    end
    wire [QW:0] f_t_crel = f_t_idx - wq_cmd_q;     // its place after the oldest entry to command
    wire [QW:0] f_t_drel = f_t_idx - wq_dat_q;     // ... after the oldest with data to send
    wire [QW:0] f_cmds = wq_tail_q - wq_cmd_q;     // entries with commands to send
    wire [QW:0] f_sent = wq_cmd_q - wq_dat_q;      // entries commanded, data still to send
    wire [NI-1:0] f_nidx = f_naddr[NI-1:0];        // the tracked address's index in its line
`ifndef SDRAM_WB_BURST_PORTS_ONLY   // (the bmc task: the check's properties alone)
    integer i;
    always @(*) begin
        if (f_past_valid) begin
            // the run: its outstanding reads are the model's, in order (the tracked one where its
            // index says), its buffered words the tracked data, its counters in order
            assert(st_q != 2'd3);
            if (st_q == IDLE) begin
                assert(f_rd_out == '0);
            end else begin
                assert(fill_q <= issue_q && issue_q <= (NI + 1)'(LINE_N) && end_q <= (NI + 1)'(LINE_N));
                assert(f_rd_out == issue_q - fill_q);
            end
            for (i = 0; i < LINE_N; i = i + 1) begin
                assert(f_rq[i] == ((NI + 1)'(i) < f_rd_out
                                   && {line_q, NI'(fill_q + (NI + 1)'(i))} == f_naddr));
            end
            if (st_q == RUN) begin
                assert(head_n <= fill_q && head_end <= end_q);
                // a single read: its word; a burst: its line, or up to the word its master said
                // was its last
                // where the run's reads end: the line's end, or the word the master said was its
                // last (the one it asks for now); a single read's run is its word; reads past the
                // end only after the master said so (dropped when its word is answered)
                assert(end_q == (NI + 1)'(LINE_N) || end_q == head_end);
                if (!f_burst_run) assert(end_q == head_end);
                if (f_lastcti != 3'b010) assert(f_lastrd == head_adr && end_q == head_end);
                if (issue_q > end_q) assert(end_q == head_end && f_burst_run);
                assert(f_lastrd_valid && f_lastrd[AW-1:LW] == line_q
                       && (LW + 1)'(f_lastrd[LW-1:0]) <= head_q);
                if (f_naddr[NAW-1:NI] == line_q && (NI + 1)'(f_nidx) >= head_n
                    && (NI + 1)'(f_nidx) < fill_q) begin
                    assert(rbuf[f_nidx] == f_val);
                end
            end
            if (st_q == DRAIN) assert(fill_q < issue_q);
            // before init_done nothing has started; the err flop marks a request's first clock
            if (!init_done) begin
                assert(st_q == IDLE && wq_tail_q == wq_dat_q);
                assert(early_err_q == f_busy);
            end
            // the write queue: pointers in order, the model's lanes owed
            assert(wq_used <= (QW + 1)'(WQ_DEPTH) && f_sent <= wq_used);
            assert(wq_clane_q <= LAST_LANE && wq_dlane_q <= LAST_LANE);
            if (f_cmds == '0) assert(wq_clane_q == '0);
            if (wq_used == '0) assert(wq_dlane_q == '0);
            if (f_cmds != '0) assert(st_q == IDLE);
            assert(8'(f_wc_owe) == 8'(f_cmds) * 8'(RATIO) - 8'(wq_clane_q));
            assert(8'(f_wd_owe) == 8'(f_sent) * 8'(RATIO) + 8'(wq_clane_q) - 8'(wq_dlane_q));
            // the tracked write: still queued, its entry unchanged, at the place the model says
            if (f_t_on) begin
                assert(f_t_drel < wq_used);
                assert(wq_dat[f_t_idx[QW-1:0]] == f_t_dat && wq_sel[f_t_idx[QW-1:0]] == f_t_sel);
                if (f_t_clane != (LNW + 1)'(RATIO)) begin
                    assert(f_t_crel < f_cmds && wq_adr[f_t_idx[QW-1:0]] == f_t_adr);
                    if (f_t_clane == '0) begin
                        assert(8'(f_t_cpos) == 8'(f_t_crel) * 8'(RATIO) - 8'(wq_clane_q));
                    end else begin
                        assert(f_t_crel == '0 && (LNW + 1)'(wq_clane_q) == f_t_clane && f_t_cpos == '0);
                    end
                end else begin
                    assert(f_t_drel < f_sent && f_t_cpos == '0);
                end
                assert(f_t_dlane != (LNW + 1)'(RATIO));
                if (f_t_dlane == '0) begin
                    assert(8'(f_t_dpos) == 8'(f_t_drel) * 8'(RATIO) - 8'(wq_dlane_q));
                end else begin
                    assert(f_t_drel == '0 && (LNW + 1)'(wq_dlane_q) == f_t_dlane && f_t_dpos == '0);
                end
            end
        end
    end
`endif
`endif
endmodule

`default_nettype wire
