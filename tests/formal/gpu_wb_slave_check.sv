// gpu_wb_slave_check: formal properties of gpu_wb_slave (gpu_rtl/gpu_wb_slave.v), a Wishbone B4
// classic slave, from its ports (tests/formal/gpu_wb_slave.sby; make formal).
//
// ZipCPU's way (its fwb_slave.v): a property module the slave instantiates in its `ifdef FORMAL
// block. It assumes the master's side and the native partner's, asserts the slave's, keeps a small
// model of the bus (which clock of a request this is, what the slave owes) and hands the model to
// the slave's block, whose invariants tie its flops to it (yosys reads no hierarchical names).
// GPU_WB_SLAVE defined (this proof): the two partners' rules are assumed; undefined (a larger proof
// that includes the slave with its real partners): they are asserted.
//
// A request is a clock with wb_cyc && wb_stb; it goes on while it stays high without an answer
// (wb_ack or wb_err), and a clock with it high after an answer starts the next one.
// Master (assumed): reset in the first clock; no wb_cyc in the clock after a reset; Wishbone
//   classic: wb_we, wb_adr, wb_dat_w and wb_sel held while a request goes on. It may drop wb_stb
//   or wb_cyc before the answer (the slave's contract: the request is abandoned), hold wb_stb into
//   the next request, or raise wb_stb without wb_cyc.
// Native partner, gpu_regs' contract (assumed): bus_rvalid exactly one clock after a read
//   (bus_valid && !bus_write), never after a reset clock; bus_rdata is free.
// Slave (asserted): wb_ack and wb_err only during a request, never both; no answer in a request's
//   first clock, and an answer in its second (one answer per request, each within two clocks);
//   wb_err exactly for a write with wb_sel != 4'b1111, wb_ack for the rest, a read's with the
//   partner's bus_rvalid and wb_dat_r = bus_rdata. Native side: bus_valid only in a request's first
//   clock (at most one access per request, none without one), and there exactly when the request
//   is not refused, with the request's direction, address and (for a write) data; a partial write
//   never reaches bus_valid.
// Covers: a read, a write and a refused write answered; two requests answered with wb_stb held
// (one access per two clocks); a read answered after an abandoned request.
`default_nettype none

`ifdef GPU_WB_SLAVE
`define GPU_WB_SLAVE_ASSUME assume
`else
`define GPU_WB_SLAVE_ASSUME assert
`endif

module gpu_wb_slave_check (
    input  wire        clk,
    input  wire        rst,
    // the slave's Wishbone port
    input  wire        wb_cyc,
    input  wire        wb_stb,
    input  wire        wb_we,
    input  wire [16:2] wb_adr,
    input  wire [31:0] wb_dat_w,
    input  wire [3:0]  wb_sel,
    input  wire [31:0] wb_dat_r,
    input  wire        wb_ack,
    input  wire        wb_err,
    // its native port
    input  wire        bus_valid,
    input  wire        bus_write,
    input  wire [16:2] bus_addr,
    input  wire [31:0] bus_wdata,
    input  wire [31:0] bus_rdata,
    input  wire        bus_rvalid,
    // the model, for the slave's invariants
    output reg         f_past_valid,  // not the first clock
    output reg         f_wr_due,      // last clock was a write request's first: answered now if held
    output reg         f_refused_due, // ... and that write was refused
    output reg         f_rd_due       // last clock was a read request's first
);
    wire request = wb_cyc && wb_stb;
    wire answer  = wb_ack || wb_err;
    wire refused = wb_we && wb_sel != 4'b1111;

    reg f_busy;      // a request was made last clock and not answered: this one is its continuation
    reg f_rd_issued; // a native read last clock (gpu_regs answers it now)
    reg f_abandoned; // a request has been dropped before its answer (since the last reset)
    initial begin
        f_past_valid = 1'b0;
        f_busy = 1'b0;
        f_wr_due = 1'b0;
        f_refused_due = 1'b0;
        f_rd_due = 1'b0;
        f_rd_issued = 1'b0;
        f_abandoned = 1'b0;
    end
    wire first = request && !f_busy;  // a request's first clock

    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_busy <= !rst && request && !answer;
        f_wr_due <= !rst && first && wb_we;
        f_refused_due <= !rst && first && refused;
        f_rd_due <= !rst && first && !wb_we;
        f_rd_issued <= !rst && bus_valid && !bus_write;
        f_abandoned <= !rst && (f_abandoned || (f_busy && !request));
    end

    // ---- the master (Wishbone B4 classic) ----
    always @(*) begin
        if (!f_past_valid) `GPU_WB_SLAVE_ASSUME(rst);
    end
    always @(posedge clk) begin
        if (!f_past_valid || $past(rst)) `GPU_WB_SLAVE_ASSUME(!wb_cyc);
    end
    always @(posedge clk) begin
        if (f_busy && request) begin
            `GPU_WB_SLAVE_ASSUME(wb_we == $past(wb_we));
            `GPU_WB_SLAVE_ASSUME(wb_adr == $past(wb_adr));
            `GPU_WB_SLAVE_ASSUME(wb_dat_w == $past(wb_dat_w));
            `GPU_WB_SLAVE_ASSUME(wb_sel == $past(wb_sel));
        end
    end

    // ---- the native partner (gpu_regs: a read's answer one clock later) ----
    always @(*) begin
        `GPU_WB_SLAVE_ASSUME(bus_rvalid == f_rd_issued);
    end

    // ---- the slave ----
    always @(*) begin
        // no answer without a request, and one answer at a time
        if (wb_ack) assert(request);
        if (wb_err) assert(request);
        assert(!(wb_ack && wb_err));
        if (f_past_valid) begin
            // one answer per request: none in its first clock (so none left over from an earlier
            // request), and one in its second (the contract's latency, with gpu_regs' reads)
            if (first) assert(!answer);
            if (f_busy && request) assert(answer);
            // the answer's kind, from what the request was (its signals are held)
            if (wb_err) assert(f_refused_due);
            if (wb_ack) assert(f_wr_due ? !f_refused_due : f_rd_due);
            if (wb_ack && !wb_we) assert(bus_rvalid && wb_dat_r == bus_rdata);
            // the native access: in a request's first clock only, exactly when not refused
            if (bus_valid) assert(first);
            if (first) assert(bus_valid == !refused);
            if (bus_valid) begin
                assert(bus_write == wb_we && bus_addr == wb_adr);
                if (bus_write) assert(bus_wdata == wb_dat_w && wb_sel == 4'b1111);
            end
        end
    end

    // ---- covers ----
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst) && !rst) begin
            cover(wb_ack && !wb_we);
            cover(wb_ack && wb_we);
            cover(wb_err);
            // two answers two clocks apart with the request held between them
            cover(answer && $past(request) && $past(answer, 2) && $past(request, 2));
            cover(f_abandoned && wb_ack && !wb_we);
        end
    end
endmodule

`undef GPU_WB_SLAVE_ASSUME
`default_nettype wire
