// soc_wb_stage_check: formal properties of soc_wb_stage (soc_rtl/soc_wb_stage.v) from its ports
// (tests/formal/soc_wb_stage.sby; make formal).
//
// Environment (assumed): rst in the first clock. The master (the bus after the decoder) follows
// Wishbone B4 classic without abort: at most one slave selected (m_stb one-hot or zero), and a
// request (cyc && m_stb[k]) held with its we, adr, dat_w and sel until it is answered (slave k
// acks or errs). Each slave answers only while its own s_stb is high, never ack and err together, after
// any number of clocks (its first included: a combinational slave), or at most SLAVE_WAIT clocks
// after the clock its s_stb rose (task bounded).
// Properties (asserted):
//   slave side   at most one s_stb; s_cyc exactly when one is high; a request held, fields and
//                all, until its answer, and s_stb low in the clock after an answer (each request
//                reaches its slave once); while s_stb[k] is high the master asks slave k with the
//                same we, adr, dat_w and sel (the slave serves the master's request, nothing else);
//                s_stb rises only in the clock after the stage, idle, saw the master's request, and
//                then it is that request's (no request invented, none taken twice, none lost).
//   master side  an answer (a slave's ack or err: the decoder passes them on) only during the
//                master's request to that slave, never in the request's first clock (the stage's).
//   bounded      every request answered within SLAVE_WAIT + 1 clocks of its first.
// Covers: a request answered by ack and one by err; two requests back to back (the second taken
// in the clock after the first's answer); the bound reached.
`default_nettype none

module soc_wb_stage_check #(
    parameter integer N = 5,
    parameter integer AW = 4,
    parameter integer SLAVE_WAIT = 0   // > 0: every slave answers at most this many clocks late
) (
    input wire          clk,
    input wire          rst,
    input wire          cyc,
    input wire [N-1:0]  m_stb,
    input wire          we,
    input wire [AW-1:0] adr,
    input wire [31:0]   dat_w,
    input wire [3:0]    sel,
    input wire [N-1:0]  s_ack,
    input wire [N-1:0]  s_err
);
    wire [N-1:0]  s_stb;
    wire          s_cyc, s_we;
    wire [AW-1:0] s_adr;
    wire [31:0]   s_dat_w;
    wire [3:0]    s_sel;
    soc_wb_stage #(.N(N), .AW(AW)) dut (
        .clk(clk), .rst(rst),
        .cyc(cyc), .m_stb(m_stb), .we(we), .adr(adr), .dat_w(dat_w), .sel(sel),
        .s_cyc(s_cyc), .s_stb(s_stb), .s_we(s_we), .s_adr(s_adr), .s_dat_w(s_dat_w), .s_sel(s_sel),
        .s_answer(s_ack | s_err)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;
    always @(*) if (!f_past_valid) assume(rst);

    wire [N-1:0] req = {N{cyc}} & m_stb;         // the master's request, by slave
    wire [N-1:0] answers = s_ack | s_err;         // what the decoder passes on to the master
    wire         answer = answers != '0;

    // ---- last clock's view ----
    reg          f_was_rst = 1'b1;
    reg [N-1:0]  f_req_q = '0;
    reg          f_answer_q = 1'b0, f_idle_q = 1'b1;
    reg [N-1:0]  f_s_stb_q = '0;
    reg          f_we_q = 1'b0, f_s_we_q = 1'b0;
    reg [AW-1:0] f_adr_q = '0, f_s_adr_q = '0;
    reg [31:0]   f_dat_w_q = '0, f_s_dat_w_q = '0;
    reg [3:0]    f_sel_q = '0, f_s_sel_q = '0;
    reg [7:0]    f_wait = '0;                    // clocks the current request has waited
    always @(posedge clk) begin
        f_was_rst <= rst;
        f_req_q <= req;
        f_answer_q <= answer;
        f_idle_q <= !s_cyc;
        f_s_stb_q <= s_stb;
        f_we_q <= we;
        f_adr_q <= adr;
        f_dat_w_q <= dat_w;
        f_sel_q <= sel;
        f_s_we_q <= s_we;
        f_s_adr_q <= s_adr;
        f_s_dat_w_q <= s_dat_w;
        f_s_sel_q <= s_sel;
        f_wait <= (rst || req == '0 || answer) ? 8'd0 : f_wait + (f_wait != 8'hFF);
    end
    wire f_held = f_past_valid && !f_was_rst;    // last clock was out of reset
    // The master's request continues from last clock (not answered there).
    wire f_req_on = f_held && f_req_q != '0 && !f_answer_q;
    // The slave's request continues from last clock.
    wire f_s_on = f_held && f_s_stb_q != '0 && !f_answer_q;

    // ---- environment ----
    always @(*) begin
        assume($onehot0(m_stb));
        if (f_req_on) begin
            assume(req == f_req_q && we == f_we_q && adr == f_adr_q && dat_w == f_dat_w_q
                   && sel == f_sel_q);
        end
        assume((s_ack & ~s_stb) == '0 && (s_err & ~s_stb) == '0 && (s_ack & s_err) == '0);
    end
    // Task bounded: a slave answers at most SLAVE_WAIT clocks after its s_stb rose.
    reg [7:0] f_s_wait = '0;
    always @(posedge clk) f_s_wait <= (rst || s_stb == '0 || answer) ? 8'd0 : f_s_wait + (f_s_wait != 8'hFF);
    generate if (SLAVE_WAIT > 0) begin : g_slave_wait
        always @(*) if (!rst && s_stb != '0 && f_s_wait >= 8'(SLAVE_WAIT)) assume(answer);
    end endgenerate

    // ---- properties ----
    always @(*) begin
        if (f_past_valid && !rst) begin
            // the slave side
            assert($onehot0(s_stb));
            assert(s_cyc == (s_stb != '0));
            if (f_s_on) begin
                assert(s_stb == f_s_stb_q && s_we == f_s_we_q && s_adr == f_s_adr_q
                       && s_dat_w == f_s_dat_w_q && s_sel == f_s_sel_q);
            end
            if (f_held && f_answer_q) assert(s_stb == '0);
            if (s_stb != '0) begin
                assert(req == s_stb && s_we == we && s_adr == adr && s_dat_w == dat_w && s_sel == sel);
            end
            if (f_held && s_stb != '0 && (f_s_stb_q == '0 || f_answer_q)) begin
                assert(f_idle_q && f_req_q == s_stb);
            end
            if (f_held && f_idle_q && f_req_q != '0) assert(s_stb == f_req_q);
            // the master side
            assert((answers & ~req) == '0);
            if (!f_req_on) assert(!answer);
            // invariants for the induction: a request on the slave side is the master's, waiting
            if (s_stb != '0) assert(f_req_on);
        end
        if (SLAVE_WAIT > 0 && f_past_valid && !rst && req != '0) assert(f_wait <= 8'(SLAVE_WAIT + 1));
    end

    // ---- covers ----
    // The current request began in the clock right after an answer (back to back).
    reg f_b2b_q = 1'b0;
    wire f_b2b = f_req_on ? f_b2b_q : (f_held && f_answer_q && req != '0);
    always @(posedge clk) f_b2b_q <= !rst && f_b2b;
    always @(*) begin
        cover(f_past_valid && !rst && s_ack != '0);
        cover(f_past_valid && !rst && s_err != '0);
        cover(f_b2b && answer && f_wait == 8'd1);
        cover(f_past_valid && !rst && answer && f_wait == 8'(SLAVE_WAIT + 1));
    end
endmodule

`default_nettype wire
