// sdram_wb_burst_check: formal properties of sdram_wb_burst (soc_rtl/litedram/sdram_wb_burst.v),
// the CPU's Wishbone port onto LiteDRAM's native port, from its ports (tests/formal/sdram_wb_burst.sby;
// make formal CHECK=sdram_wb_burst).
//
// ZipCPU's way, as gpu_wb_slave_check.sv: a property module the adapter instantiates in its `ifdef
// FORMAL block. It assumes the master's side and an abstract native port, asserts the adapter's
// side, keeps a small model of both (outstanding native reads, write lanes owed, one tracked write)
// and hands the model to the adapter's block, whose invariants tie its flops to it (yosys reads no
// hierarchical names). SDRAM_WB_BURST defined (this proof): the two partners' rules are assumed;
// undefined: asserted.
//
// A request is a clock with wb_cyc && wb_stb; it goes on while it stays high without an answer, and
// a clock with it high after an answer starts the next one (a burst's next beat).
// Master (assumed): rst in the first clock, no wb_cyc in the clock after it; Wishbone classic:
//   wb_we, wb_adr, wb_dat_w, wb_sel and wb_cti held while a request goes on. It may drop wb_stb or
//   wb_cyc before the answer (the request, or the burst, abandoned), start any request after an
//   answer (any address, CTI, direction: bursts unaligned, wrapping, ended early), raise wb_stb
//   without wb_cyc. init_done low in the clock after a reset (LiteDRAM's flop); once high it stays
//   high until the next.
// Native port (assumed): commands accepted at any clock (native_cmd_ready free); read data
//   returned in command order after any delay of a clock or more (native_rdata_valid only while
//   reads are outstanding), the data of one anyconst native address f_naddr always f_val (the
//   others free); write data taken (native_wdata_ready) only for write commands already accepted,
//   in order, after any delay.
// Adapter (asserted):
//   answers   wb_ack and wb_err only during a request, never both; before init_done no ack and no
//             native command, and wb_err exactly in a request's second clock; after it no wb_err.
//   reads     a read beat acked carries f_val in the lanes of f_naddr: the data of its own address,
//             never an earlier run's (so abandoned runs are drained) nor a neighbour's; at most
//             LINE_WORDS * RATIO reads outstanding; every native read is in the line of the
//             current read request (the last one while there is none), at or after its word —
//             never past the line's end — nor past its word if it says it is the last (CTI not
//             010: a single read reads one word, a burst ended early stops), and none while a
//             write request is on the bus or queued writes have commands still to send (a read
//             sees every earlier write).
//   writes    a write command only for a write already acked (never twice), its data whenever
//             data are owed; one tracked write (picked at its ack by a free signal) reaches the
//             native port as RATIO commands to its own native addresses in order, and its lanes of
//             data with their byte enables from wb_sel, each once.
// Covers: an 8-beat line burst answered in full, two read beats answered on consecutive clocks, a
// read answered after an abandoned burst, a tracked write's data taken, an error before init_done.
`default_nettype none

`ifdef SDRAM_WB_BURST
`define SDRAM_WB_BURST_ASSUME assume
`else
`define SDRAM_WB_BURST_ASSUME assert
`endif

module sdram_wb_burst_check #(
    parameter integer AW = 4,
    parameter integer NATIVE_DW = 16,
    parameter integer LINE_WORDS = 8,
    parameter integer WQ_DEPTH = 2,
    localparam integer RATIO = 32 / NATIVE_DW,
    localparam integer RW = $clog2(RATIO),
    localparam integer LNW = RW > 0 ? RW : 1,
    localparam integer NB = NATIVE_DW / 8,
    localparam integer NAW = AW + RW,
    localparam integer LW = $clog2(LINE_WORDS),
    localparam integer NI = LW + RW,
    localparam integer LINE_N = LINE_WORDS * RATIO,
    localparam integer PW = $clog2(RATIO * WQ_DEPTH + 1)   // write lanes owed: 0 .. RATIO * WQ_DEPTH
) (
    input  wire                 clk,
    input  wire                 rst,
    input  wire                 init_done,
    // the adapter's Wishbone port
    input  wire                 wb_cyc,
    input  wire                 wb_stb,
    input  wire                 wb_we,
    input  wire [AW-1:0]        wb_adr,
    input  wire [31:0]          wb_dat_w,
    input  wire [3:0]           wb_sel,
    input  wire [2:0]           wb_cti,
    input  wire [31:0]          wb_dat_r,
    input  wire                 wb_ack,
    input  wire                 wb_err,
    // its native port
    input  wire                 native_cmd_valid,
    input  wire                 native_cmd_ready,
    input  wire                 native_cmd_we,
    input  wire [NAW-1:0]       native_cmd_addr,
    input  wire                 native_wdata_valid,
    input  wire                 native_wdata_ready,
    input  wire [NATIVE_DW-1:0] native_wdata_data,
    input  wire [NB-1:0]        native_wdata_we,
    input  wire                 native_rdata_valid,
    input  wire                 native_rdata_ready,
    input  wire [NATIVE_DW-1:0] native_rdata_data,
    // the model, for the adapter's invariants
    output reg                  f_past_valid,   // not the first clock
    output reg                  f_busy,         // last clock had a request not answered
    output reg  [NI:0]          f_rd_out,       // native reads accepted, data not yet returned
    output reg  [LINE_N-1:0]    f_rq,           // ... bit i: the i-th oldest is to f_naddr
    output wire [NAW-1:0]       f_naddr,        // the tracked native address (anyconst)
    output wire [NATIVE_DW-1:0] f_val,          // ... its data (anyconst)
    output reg                  f_lastrd_valid, // a read request since reset
    output reg  [AW-1:0]        f_lastrd,       // ... the last one's address
    output reg  [2:0]           f_lastcti,      // ... and CTI
    output reg  [PW-1:0]        f_wc_owe,       // write lanes acked, command not yet accepted
    output reg  [PW-1:0]        f_wd_owe,       // write lanes commanded, data not yet taken
    output wire                 f_t_start,      // the write acked now is tracked
    output reg                  f_t_on,         // a tracked write is on its way
    output reg  [PW-1:0]        f_t_cpos,       // ... write commands still due before its first
    output reg  [LNW:0]         f_t_clane,      // ... its lanes commanded
    output reg  [PW-1:0]        f_t_dpos,       // ... data lanes still due before its first
    output reg  [LNW:0]         f_t_dlane,      // ... its lanes of data taken
    output reg  [AW-1:0]        f_t_adr,
    output reg  [31:0]          f_t_dat,
    output reg  [3:0]           f_t_sel
);
    wire req    = wb_cyc && wb_stb;
    wire rd_req = req && !wb_we;
    wire wr_req = req && wb_we;
    wire answer = wb_ack || wb_err;
    wire rd_fire = native_cmd_valid && native_cmd_ready && !native_cmd_we;
    wire wc_fire = native_cmd_valid && native_cmd_ready && native_cmd_we;
    wire wd_take = native_wdata_ready;

    (* anyconst *) reg [NAW-1:0]       f_naddr_c;
    (* anyconst *) reg [NATIVE_DW-1:0] f_val_c;
    (* anyseq *)   reg                 f_pick;       // tracks the write acked now (if none is)
    assign f_naddr = f_naddr_c;
    assign f_val = f_val_c;

    initial begin
        f_past_valid = 1'b0;
        f_busy = 1'b0;
        f_rd_out = '0;
        f_rq = '0;
        f_lastrd_valid = 1'b0;
        f_lastrd = '0;
        f_lastcti = '0;
        f_wc_owe = '0;
        f_wd_owe = '0;
        f_t_on = 1'b0;
        f_t_cpos = '0;
        f_t_clane = '0;
        f_t_dpos = '0;
        f_t_dlane = '0;
        f_t_adr = '0;
        f_t_dat = '0;
        f_t_sel = '0;
    end

    // ---- the model ----
    wire [NI:0] f_rd_left = f_rd_out - (NI + 1)'(native_rdata_valid);   // after this clock's data
    reg [LINE_N-1:0] f_rq_d;
    always @(*) begin
        f_rq_d = native_rdata_valid ? f_rq >> 1 : f_rq;
        if (rd_fire) f_rq_d[f_rd_left[NI-1:0]] = native_cmd_addr == f_naddr;
    end
    localparam [LNW:0] LANES = (LNW + 1)'(RATIO);
    assign f_t_start = f_past_valid && !rst && wb_ack && wb_we && f_pick && !f_t_on;
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        if (rst) begin
            f_busy <= 1'b0;
            f_rd_out <= '0;
            f_rq <= '0;
            f_lastrd_valid <= 1'b0;
            f_wc_owe <= '0;
            f_wd_owe <= '0;
            f_t_on <= 1'b0;
        end else begin
            f_busy <= req && !answer;
            f_rd_out <= f_rd_left + (NI + 1)'(rd_fire);
            f_rq <= f_rq_d;
            if (rd_req) begin
                f_lastrd_valid <= 1'b1;
                f_lastrd <= wb_adr;
                f_lastcti <= wb_cti;
            end
            f_wc_owe <= f_wc_owe + (wb_ack && wb_we ? PW'(RATIO) : '0) - PW'(wc_fire);
            f_wd_owe <= f_wd_owe + PW'(wc_fire) - PW'(wd_take);
            if (f_t_start) begin
                f_t_on <= 1'b1;
                f_t_adr <= wb_adr;
                f_t_dat <= wb_dat_w;
                f_t_sel <= wb_sel;
                f_t_cpos <= f_wc_owe - PW'(wc_fire);
                f_t_clane <= '0;
                f_t_dpos <= f_wc_owe + f_wd_owe - PW'(wd_take);
                f_t_dlane <= '0;
            end else if (f_t_on) begin
                if (wc_fire) begin
                    if (f_t_cpos != '0) f_t_cpos <= f_t_cpos - 1'b1;
                    else if (f_t_clane != LANES) f_t_clane <= f_t_clane + 1'b1;
                end
                if (wd_take) begin
                    if (f_t_dpos != '0) f_t_dpos <= f_t_dpos - 1'b1;
                    else begin
                        f_t_dlane <= f_t_dlane + 1'b1;
                        if (f_t_dlane == LANES - 1'b1) f_t_on <= 1'b0;   // its last lane: done
                    end
                end
            end
        end
    end

    // ---- the master (Wishbone B4 classic) and init_done ----
    always @(*) begin
        if (!f_past_valid) `SDRAM_WB_BURST_ASSUME(rst && !init_done);
    end
    always @(posedge clk) begin
        if (!f_past_valid || $past(rst)) `SDRAM_WB_BURST_ASSUME(!wb_cyc && !init_done);
        if (f_past_valid && !$past(rst) && $past(init_done)) `SDRAM_WB_BURST_ASSUME(init_done);
        if (f_busy && req) begin
            `SDRAM_WB_BURST_ASSUME(wb_we == $past(wb_we));
            `SDRAM_WB_BURST_ASSUME(wb_adr == $past(wb_adr));
            `SDRAM_WB_BURST_ASSUME(wb_dat_w == $past(wb_dat_w));
            `SDRAM_WB_BURST_ASSUME(wb_sel == $past(wb_sel));
            `SDRAM_WB_BURST_ASSUME(wb_cti == $past(wb_cti));
        end
    end

    // ---- the native port: data only for what was asked, reads in order ----
    always @(*) begin
        if (native_rdata_valid) `SDRAM_WB_BURST_ASSUME(f_rd_out != '0);
        if (native_rdata_valid && f_rq[0]) `SDRAM_WB_BURST_ASSUME(native_rdata_data == f_val);
        if (native_wdata_ready) `SDRAM_WB_BURST_ASSUME(f_wd_owe != '0);
    end

    // ---- the adapter ----
    wire [AW-1:0] f_L = rd_req ? wb_adr : f_lastrd;   // the read request the native reads serve
    wire [2:0] f_L_cti = rd_req ? wb_cti : f_lastcti;
    wire [NAW-1:0] f_t_lane_addr = (NAW'(f_t_adr) << RW) | NAW'(f_t_clane);
    wire [NAW-1:0] f_L_first = NAW'(f_L) << RW;
    integer r;
    always @(*) begin
        if (f_past_valid) begin
            // answers only during a request, one at a time
            if (wb_ack) assert(req);
            if (wb_err) assert(req);
            assert(!(wb_ack && wb_err));
            // before init_done: refused in the second clock, nothing reaches LiteDRAM
            if (!init_done) begin
                assert(!wb_ack && !native_cmd_valid);
                assert(wb_err == (f_busy && req));
            end else begin
                assert(!wb_err);
            end
            // a read beat carries its own address's data
            if (wb_ack && !wb_we) begin
                for (r = 0; r < RATIO; r = r + 1) begin
                    if (((NAW'(wb_adr) << RW) | NAW'(r)) == f_naddr) assert(wb_dat_r[r*NATIVE_DW +: NATIVE_DW] == f_val);
                end
            end
            // native reads: room for their data, in the line of the read request from its word on,
            // after every queued write's commands
            if (rd_fire) assert(f_rd_left != (NI + 1)'(LINE_N));
            if (native_cmd_valid && !native_cmd_we) begin
                assert(!wr_req && f_wc_owe == '0);
                assert(rd_req || f_lastrd_valid);
                assert(native_cmd_addr[NAW-1:NI] == f_L[AW-1:LW]);
                assert(native_cmd_addr >= f_L_first);
                // once the master says a request is its last, nothing past its word
                if (f_L_cti != 3'b010) begin
                    assert((NAW + 1)'(native_cmd_addr) < (NAW + 1)'(f_L_first) + (NAW + 1)'(RATIO));
                end
            end
            // writes: commands only for acked writes, data whenever owed; the tracked one in order
            if (native_cmd_valid && native_cmd_we) assert(f_wc_owe != '0);
            if (f_wd_owe != '0) assert(native_wdata_valid);
            if (f_t_on && f_t_cpos == '0 && f_t_clane != LANES && native_cmd_valid && native_cmd_we) begin
                assert(native_cmd_addr == f_t_lane_addr);
            end
            if (f_t_on && f_t_dpos == '0 && wd_take) begin
                assert(native_wdata_data == f_t_dat[f_t_dlane[LNW-1:0] * NATIVE_DW +: NATIVE_DW]);
                assert(native_wdata_we == f_t_sel[f_t_dlane[LNW-1:0] * NB +: NB]);
            end
            assert(native_rdata_ready);
        end
    end

    // ---- covers ----
    reg [3:0] f_beats = '0;     // read beats of an incrementing burst acked since its start
    reg       f_abandoned = 1'b0;
    reg       f_rd_ack_q = 1'b0;
    always @(posedge clk) begin
        f_rd_ack_q <= !rst && wb_ack && !wb_we;
        if (rst || (wb_ack && (wb_we || wb_cti != 3'b010))) f_beats <= '0;
        else if (wb_ack) f_beats <= f_beats + 1'b1;
        f_abandoned <= !rst && (f_abandoned || (f_busy && !req)
                                || (wb_ack && !wb_we && wb_cti == 3'b111 && wb_adr[LW-1:0] != '1));
    end
    always @(*) begin
        if (f_past_valid && !rst) begin
            cover(wb_ack && !wb_we && wb_cti == 3'b111 && f_beats == 4'(LINE_WORDS - 1));
            cover(wb_ack && !wb_we && f_rd_ack_q);
            cover(f_abandoned && wb_ack && !wb_we);
            cover(wd_take && f_t_on);
            cover(wb_err);
        end
    end
endmodule

`undef SDRAM_WB_BURST_ASSUME
`default_nettype wire
