// soc_wb_arbiter: two Wishbone B4 masters onto one bus (m0: the CPU's instruction bus, m1: its data
// bus), no added latency.
//
// Contract: the master that holds the bus keeps it for as long as it holds m*_cyc (a whole cycle,
// e.g. an 8-beat cache-line burst, or back-to-back single accesses under one CYC); the other waits
// with its own signals held. When the bus is free, a lone requester gets it in the same clock (the
// grant is combinational: no wait state); when both request, the one that did not have it last goes
// first (round robin), so neither starves. The handover is also in the same clock: when the owner
// drops cyc, a waiting master drives the bus at once. The slave's ack/err/dat_r are routed to the
// owner only (the other sees 0). Pure wiring plus two flops; the slave side has CTI (incrementing
// bursts pass through), no BTE (both masters use linear bursts only, BTE = 0).
`default_nettype none

module soc_wb_arbiter (
    input  wire        clk,
    input  wire        rst,         // synchronous, active high
    // master 0 (priority on a tie after master 1 had the bus)
    input  wire        m0_cyc,
    input  wire        m0_stb,
    input  wire        m0_we,
    input  wire [29:0] m0_adr,      // word address (byte address [31:2])
    input  wire [31:0] m0_dat_w,
    input  wire [3:0]  m0_sel,
    input  wire [2:0]  m0_cti,      // 3'b010: more beats follow, 3'b111: last beat, 3'b000: classic
    output wire [31:0] m0_dat_r,
    output wire        m0_ack,
    output wire        m0_err,
    // master 1
    input  wire        m1_cyc,
    input  wire        m1_stb,
    input  wire        m1_we,
    input  wire [29:0] m1_adr,
    input  wire [31:0] m1_dat_w,
    input  wire [3:0]  m1_sel,
    input  wire [2:0]  m1_cti,
    output wire [31:0] m1_dat_r,
    output wire        m1_ack,
    output wire        m1_err,
    // the shared bus, to the address decoder
    output wire        s_cyc,
    output wire        s_stb,
    output wire        s_we,
    output wire [29:0] s_adr,
    output wire [31:0] s_dat_w,
    output wire [3:0]  s_sel,
    output wire [2:0]  s_cti,
    input  wire [31:0] s_dat_r,
    input  wire        s_ack,
    input  wire        s_err
);
    reg owner_q;   // the master granted in the last clock with a cycle on the bus
    reg busy_q;    // the bus was in a cycle last clock

    // The owner keeps the bus while its cyc stays high; otherwise pick: a lone requester, or on a tie
    // the one that is not owner_q.
    wire owner_cyc  = owner_q ? m1_cyc : m0_cyc;
    wire owner_busy = busy_q && owner_cyc;
    wire pick       = (m0_cyc && m1_cyc) ? !owner_q : m1_cyc;
    wire grant      = owner_busy ? owner_q : pick;   // 0: m0 drives the bus, 1: m1

    always @(posedge clk) begin
        if (rst) begin
            owner_q <= 1'b0;
            busy_q <= 1'b0;
        end else begin
            if (s_cyc) owner_q <= grant;
            busy_q <= s_cyc;
        end
    end

    assign s_cyc   = grant ? m1_cyc   : m0_cyc;
    assign s_stb   = grant ? m1_stb   : m0_stb;
    assign s_we    = grant ? m1_we    : m0_we;
    assign s_adr   = grant ? m1_adr   : m0_adr;
    assign s_dat_w = grant ? m1_dat_w : m0_dat_w;
    assign s_sel   = grant ? m1_sel   : m0_sel;
    assign s_cti   = grant ? m1_cti   : m0_cti;

    assign m0_ack   = !grant && s_ack;
    assign m0_err   = !grant && s_err;
    assign m0_dat_r = grant ? 32'd0 : s_dat_r;
    assign m1_ack   = grant && s_ack;
    assign m1_err   = grant && s_err;
    assign m1_dat_r = grant ? s_dat_r : 32'd0;

`ifdef FORMAL
    // ---- formal properties of the grant (tests/formal/soc_wb_arbiter.sby, proved by induction) ----
    // They name grant, which the checker (tests/formal/soc_wb_arbiter_check.sv: the Wishbone rules
    // of every port, routing, bounded waits, all from the ports) cannot: yosys reads no hierarchical
    // names. They hold whatever the inputs do, so they are asserted, never assumed.
    reg f_past_valid = 1'b0;
    reg f_cycle_q;      // last clock, out of reset, had a cycle on the bus
    reg f_grant_q;      // grant last clock
    reg f_last_q;       // the master granted in the last clock with a cycle on the bus ("had it last")
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_cycle_q    <= !rst && s_cyc;
        f_grant_q    <= grant;
        if (rst)        f_last_q <= 1'b0;
        else if (s_cyc) f_last_q <= grant;
    end
    // The master that owned last clock's cycle still holds its cyc: that cycle goes on.
    wire f_owner_holds = f_past_valid && f_cycle_q && (f_grant_q ? m1_cyc : m0_cyc);

    always @(*) begin
        // Work-conserving: a master with cyc never waits on an idle bus, so a waiting master gets
        // the bus in the first clock the other's cyc is low: it waits for one cycle of it at most.
        if (m0_cyc || m1_cyc) assert(s_cyc);
        // Held: the owner keeps the bus for its whole cycle, every beat of it.
        if (f_owner_holds) assert(grant == f_grant_q);
        // Round robin: both asking for a free bus, the one that did not have it last wins (m1
        // after reset).
        if (f_past_valid && !f_owner_holds && m0_cyc && m1_cyc) assert(grant == !f_last_q);
        // Answers reach the owner only; the other sees dat_r 0.
        if (grant)  assert(!m0_ack && !m0_err && m0_dat_r == 32'd0);
        if (!grant) assert(!m1_ack && !m1_err && m1_dat_r == 32'd0);
        // Invariants for the induction: the two flops are what the header says they are.
        if (f_past_valid) assert(busy_q == f_cycle_q && owner_q == f_last_q);
        // Covers: a handover in the same clock, either way; a tie on a free bus won by each master.
        cover(f_past_valid && f_cycle_q && !f_grant_q && !f_owner_holds && s_cyc && grant);
        cover(f_past_valid && f_cycle_q && f_grant_q && !f_owner_holds && s_cyc && !grant);
        cover(f_past_valid && !f_owner_holds && m0_cyc && m1_cyc && !grant);
        cover(f_past_valid && !f_owner_holds && m0_cyc && m1_cyc && grant);
    end
`endif
endmodule

`default_nettype wire
