// soc_wb_arbiter_check: formal properties of soc_wb_arbiter (soc_rtl/soc_wb_arbiter.v) from its
// ports, in the manner of ZipCPU's fwb_slave/fwb_master (tests/formal/soc_wb_arbiter.sby; make formal).
// The properties that name the grant are in the module's `ifdef FORMAL block (exclusive, held for
// the whole cycle, work-conserving, round robin on a tie, answers to the owner only).
//
// Environment (assumed): rst in the first clock; each master follows Wishbone B4 classic as the
// core's buses do (soc_wb_arbiter_port below): no request after a reset clock, stb only within cyc,
// a request (stb with we, adr, dat_w, sel, cti) held unchanged until its ack or err, an answered
// beat with cti 3'b010 followed by the next beat in the next clock (VexRiscv's line bursts, on which
// soc_ram's read-ahead counts), cti one of 000, 010, 111. The slave answers a request only while it
// is on the bus (ack or err, never both), after any number of clocks (task prove) or at most
// SLAVE_WAIT clocks after its first (task bounded, which also lets each cycle have at most
// MASTER_BEATS beats and cyc equal stb, as on both of VexRiscv's buses).
// Properties (asserted): the same rules on all three ports, each from the side the arbiter drives;
// the bus carries one master's request, all of it (cyc, stb, we, adr, dat_w, sel, cti), and a
// master with cyc never finds it idle; every answer on the bus goes to exactly one master, the
// one whose request the bus carries, with the slave's ack, err and dat_r, the other master gets
// dat_r 0 and no answer; so each beat of a master is seen once on the bus and answered once on its
// own port, nothing lost or duplicated. Task bounded: no starvation, each master's request answered
// at most MAX_WAIT = MASTER_BEATS * (SLAVE_WAIT + 1) + SLAVE_WAIT clocks after its first (one whole
// cycle of the other master, then its own beat), and a cover reaches that bound.
`default_nettype none

module soc_wb_arbiter_check #(
    parameter integer SLAVE_WAIT   = 0,  // > 0: the slave answers at most this many clocks late
    parameter integer MASTER_BEATS = 0   // > 0: a master's cycle has at most this many beats
) (
    input wire        clk,
    input wire        rst,
    input wire        m0_cyc, m0_stb, m0_we,
    input wire [29:0] m0_adr,
    input wire [31:0] m0_dat_w,
    input wire [3:0]  m0_sel,
    input wire [2:0]  m0_cti,
    input wire        m1_cyc, m1_stb, m1_we,
    input wire [29:0] m1_adr,
    input wire [31:0] m1_dat_w,
    input wire [3:0]  m1_sel,
    input wire [2:0]  m1_cti,
    input wire [31:0] s_dat_r,
    input wire        s_ack, s_err
);
    localparam integer MAX_WAIT = SLAVE_WAIT > 0 && MASTER_BEATS > 0
                                ? MASTER_BEATS * (SLAVE_WAIT + 1) + SLAVE_WAIT : 0;

    wire [31:0] m0_dat_r, m1_dat_r, s_dat_w;
    wire        m0_ack, m0_err, m1_ack, m1_err, s_cyc, s_stb, s_we;
    wire [29:0] s_adr;
    wire [3:0]  s_sel;
    wire [2:0]  s_cti;
    soc_wb_arbiter dut (
        .clk(clk), .rst(rst),
        .m0_cyc(m0_cyc), .m0_stb(m0_stb), .m0_we(m0_we), .m0_adr(m0_adr), .m0_dat_w(m0_dat_w),
        .m0_sel(m0_sel), .m0_cti(m0_cti), .m0_dat_r(m0_dat_r), .m0_ack(m0_ack), .m0_err(m0_err),
        .m1_cyc(m1_cyc), .m1_stb(m1_stb), .m1_we(m1_we), .m1_adr(m1_adr), .m1_dat_w(m1_dat_w),
        .m1_sel(m1_sel), .m1_cti(m1_cti), .m1_dat_r(m1_dat_r), .m1_ack(m1_ack), .m1_err(m1_err),
        .s_cyc(s_cyc), .s_stb(s_stb), .s_we(s_we), .s_adr(s_adr), .s_dat_w(s_dat_w),
        .s_sel(s_sel), .s_cti(s_cti), .s_dat_r(s_dat_r), .s_ack(s_ack), .s_err(s_err)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;
    always @(*) if (!f_past_valid) assume(rst);

    // Each port's whole request, and its rules: masters' requests assumed, the arbiter's answers to
    // them asserted; on the bus the arbiter's request asserted, the slave's answers assumed.
    wire [69:0] m0_req = {m0_we, m0_adr, m0_dat_w, m0_sel, m0_cti};
    wire [69:0] m1_req = {m1_we, m1_adr, m1_dat_w, m1_sel, m1_cti};
    wire [69:0] s_req  = {s_we, s_adr, s_dat_w, s_sel, s_cti};
    wire [3:0]  m0_wait, m1_wait;
    wire [2:0]  m0_beats, m1_beats;
    soc_wb_arbiter_port #(.DUT_ANSWERS(1), .MAX_WAIT(MAX_WAIT), .MAX_BEATS(MASTER_BEATS)) p_m0 (
        .clk(clk), .rst(rst), .cyc(m0_cyc), .stb(m0_stb), .req(m0_req), .cti(m0_cti),
        .ack(m0_ack), .err(m0_err), .f_wait(m0_wait), .f_beats(m0_beats)
    );
    soc_wb_arbiter_port #(.DUT_ANSWERS(1), .MAX_WAIT(MAX_WAIT), .MAX_BEATS(MASTER_BEATS)) p_m1 (
        .clk(clk), .rst(rst), .cyc(m1_cyc), .stb(m1_stb), .req(m1_req), .cti(m1_cti),
        .ack(m1_ack), .err(m1_err), .f_wait(m1_wait), .f_beats(m1_beats)
    );
    soc_wb_arbiter_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT), .MAX_BEATS(0)) p_s (
        .clk(clk), .rst(rst), .cyc(s_cyc), .stb(s_stb), .req(s_req), .cti(s_cti),
        .ack(s_ack), .err(s_err), .f_wait(), .f_beats()
    );

    wire m0_answer = m0_ack || m0_err;
    wire m1_answer = m1_ack || m1_err;
    wire s_answer  = s_ack || s_err;
    wire m0_on_bus = {s_cyc, s_stb, s_req} == {m0_cyc, m0_stb, m0_req};
    wire m1_on_bus = {s_cyc, s_stb, s_req} == {m1_cyc, m1_stb, m1_req};

    always @(*) begin
        // One owner: the bus is one master's signals, all of them, and never idle while a master
        // has cyc.
        assert(m0_on_bus || m1_on_bus);
        assert(s_cyc == (m0_cyc || m1_cyc));
        // Every answer on the bus goes to exactly one master (not lost, not duplicated) ...
        assert(s_answer == (m0_answer || m1_answer));
        assert(!(m0_answer && m1_answer));
        // ... to the one whose request the bus carries, unchanged; the other sees dat_r 0.
        if (m0_answer) assert(m0_on_bus && m0_ack == s_ack && m0_err == s_err && m0_dat_r == s_dat_r);
        if (m1_answer) assert(m1_on_bus && m1_ack == s_ack && m1_err == s_err && m1_dat_r == s_dat_r);
        assert((m0_dat_r | m1_dat_r) == s_dat_r && (m0_dat_r == 32'd0 || m1_dat_r == 32'd0));
    end

    // Covers, out of reset: a beat answered on each master's port, with ack and with err; a beat
    // with cti 111 (a burst's last) after an earlier one, on each; both masters served twice in
    // one run; task bounded (and cover): the bound on a wait reached, a whole cycle of the other
    // master first.
    wire f_run = f_past_valid && !rst;
    always @(*) begin
        cover(f_run && m0_ack && m0_beats == 3'd0);
        cover(f_run && m1_ack && m1_beats == 3'd0);
        cover(f_run && m0_err);
        cover(f_run && m1_err);
        cover(f_run && m0_ack && m0_cti == 3'b111 && m0_beats != 3'd0);
        cover(f_run && m1_ack && m1_cti == 3'b111 && m1_beats != 3'd0);
        cover(f_run && m0_beats >= 3'd2 && m1_beats >= 3'd2);
        if (MAX_WAIT > 0) begin
            cover(f_run && m0_answer && m0_wait == MAX_WAIT);
            cover(f_run && m1_answer && m1_wait == MAX_WAIT);
        end
    end
endmodule

// soc_wb_arbiter_port: the Wishbone B4 classic rules of one port, both sides of it (ZipCPU's
// fwb_slave when DUT_ANSWERS is 1: the port's master is the environment, so its requests are
// assumed and the answers asserted; fwb_master when 0: the reverse).
//   requests: none in the clock after a reset clock; stb only within cyc; a request, stb and req
//             held unchanged until its ack or err; after an answered beat with cti 3'b010 the next
//             beat in the next clock; cti 000, 010 or 111 with stb; MAX_BEATS > 0: cyc equals stb
//             and a cycle ends after MAX_BEATS answered beats.
//   answers:  ack or err only to a request in this clock, never both; MAX_WAIT > 0: at most
//             MAX_WAIT clocks after the request's first.
module soc_wb_arbiter_port #(
    parameter integer DUT_ANSWERS = 1,  // 1: the DUT answers on this port; 0: the DUT requests
    parameter integer RW = 70,          // bits of a request besides cyc and stb
    parameter integer MAX_WAIT = 0,     // > 0: the answer's latest clock after the request's first
    parameter integer MAX_BEATS = 0     // > 0: at most this many beats a cycle, and cyc equals stb
) (
    input  wire          clk,
    input  wire          rst,
    input  wire          cyc,
    input  wire          stb,
    input  wire [RW-1:0] req,
    input  wire [2:0]    cti,
    input  wire          ack,
    input  wire          err,
    output reg  [3:0]    f_wait,   // clocks the request has waited before this one (saturating)
    output reg  [2:0]    f_beats   // answered beats since reset (saturating, for covers)
);
// Statements, no `;` after them: a rule of the port's master, and of its slave.
`define SOC_WB_REQUEST(p) begin if (DUT_ANSWERS != 0) begin assume(p); end else begin assert(p); end end
`define SOC_WB_ANSWER(p)  begin if (DUT_ANSWERS != 0) begin assert(p); end else begin assume(p); end end
    reg f_past_valid = 1'b0;
    reg f_prev_rst, f_held, f_burst;  // last clock: rst; a request left unanswered; a burst beat answered
    reg [RW-1:0] f_prev_req;
    reg [3:0] f_cycle_beats;          // answered beats in this cycle (saturating)
    wire answer = ack || err;
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_prev_rst   <= rst;
        f_held       <= cyc && stb && !answer;
        f_burst      <= cyc && stb && answer && cti == 3'b010;
        f_prev_req   <= req;
        if (rst || !(cyc && stb) || answer) f_wait <= 4'd0;
        else if (f_wait != 4'd15)           f_wait <= f_wait + 4'd1;
        if (rst)                                    f_beats <= 3'd0;
        else if (cyc && stb && answer && f_beats != 3'd7) f_beats <= f_beats + 3'd1;
        if (rst || !cyc)                                     f_cycle_beats <= 4'd0;
        else if (stb && answer && f_cycle_beats != 4'd15)    f_cycle_beats <= f_cycle_beats + 4'd1;
    end

    always @(*) begin
        if (f_past_valid) begin
            if (f_prev_rst) `SOC_WB_REQUEST(!cyc)
            else if (f_held) `SOC_WB_REQUEST(cyc && stb && req == f_prev_req)
            else if (f_burst) `SOC_WB_REQUEST(cyc && stb)
        end
        if (stb) `SOC_WB_REQUEST(cyc && (cti == 3'b000 || cti == 3'b010 || cti == 3'b111))
        if (MAX_BEATS > 0) begin
            `SOC_WB_REQUEST(cyc == stb)
            if (f_past_valid && f_cycle_beats >= MAX_BEATS) `SOC_WB_REQUEST(!cyc)
        end
        if (answer) `SOC_WB_ANSWER(cyc && stb)
        `SOC_WB_ANSWER(!(ack && err))
        if (MAX_WAIT > 0 && f_past_valid && cyc && stb && f_wait >= MAX_WAIT) `SOC_WB_ANSWER(answer)
    end
`undef SOC_WB_REQUEST
`undef SOC_WB_ANSWER
endmodule

`default_nettype wire
