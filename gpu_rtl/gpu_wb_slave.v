// gpu_wb_slave: Wishbone B4 classic (32-bit) slave to gpu_top's native bus (gpu_regs).
//
// Contract: one native access per Wishbone request (a request is a cycle with wb_cyc && wb_stb while
// no earlier request of this slave is still being answered); each request is answered exactly once,
// by wb_ack or by wb_err, and never while wb_cyc && wb_stb is low. The master may hold wb_stb high
// from one request into the next or drop it between them; registered-feedback bursts (CTI/BTE) are
// served as classic cycles (this slave has no CTI port).
//   write: the native write is issued combinationally in the request's first cycle (gpu_regs takes
//          writes with no wait state); wb_ack follows in the next cycle.
//   read:  the native read is issued in the request's first cycle; wb_ack comes with bus_rvalid
//          (gpu_regs: one cycle later), wb_dat_r = bus_rdata. wb_sel is ignored for reads.
//   error: the contract allows aligned 32-bit words only. A write with wb_sel != 4'b1111 never
//          reaches the GPU and is answered with wb_err in the next cycle.
// Throughput: one access per 2 clocks (the classic handshake: request, then answer).
// A master that drops wb_cyc (or wb_stb) before the answer abandons the request: the native access
// may already have been made, its answer is swallowed, and the next request starts clean.
// Address bits [16:2] select a word of the GPU's 128 KiB window; the byte address bits do not exist.
`default_nettype none

module gpu_wb_slave (
    input  wire        clk,
    input  wire        rst,          // synchronous, active high
    // Wishbone B4 classic slave (32-bit data, byte address bits [16:2] of the GPU's 128 KiB window)
    input  wire        wb_cyc,       // bus cycle in progress
    input  wire        wb_stb,       // this slave is addressed
    input  wire        wb_we,        // write
    input  wire [16:2] wb_adr,       // word address within the window
    input  wire [31:0] wb_dat_w,     // write data
    input  wire [3:0]  wb_sel,       // byte lanes: 4'b1111 for a write, ignored for a read
    output wire [31:0] wb_dat_r,     // read data, valid with wb_ack
    output wire        wb_ack,       // request answered
    output wire        wb_err,       // request refused (partial write), not executed
    // to gpu_top's native bus
    output wire        bus_valid,
    output wire        bus_write,
    output wire [16:2] bus_addr,
    output wire [31:0] bus_wdata,
    input  wire [31:0] bus_rdata,
    input  wire        bus_rvalid
);
    reg wr_done_q;   // a write (or a refused write) was issued last cycle: answer it now
    reg wr_err_q;    // ... and it was refused
    reg rd_wait_q;   // a read was issued and bus_rvalid has not come back yet

    wire request = wb_cyc && wb_stb;
    // A request still being answered must not be issued again; a new one starts once it is.
    wire issue = request && !wr_done_q && !rd_wait_q;
    wire refuse = wb_we && wb_sel != 4'b1111;

    assign bus_valid = issue && !refuse;
    assign bus_write = wb_we;
    assign bus_addr  = wb_adr;
    assign bus_wdata = wb_dat_w;

    always @(posedge clk) begin
        if (rst) begin
            wr_done_q <= 1'b0;
            wr_err_q <= 1'b0;
            rd_wait_q <= 1'b0;
        end else begin
            wr_done_q <= issue && wb_we;
            wr_err_q <= issue && refuse;
            // Cleared by bus_rvalid even when the master has abandoned the request meanwhile.
            rd_wait_q <= rd_wait_q ? !bus_rvalid : (issue && !wb_we);
        end
    end

    assign wb_ack   = request && ((wr_done_q && !wr_err_q) || (rd_wait_q && bus_rvalid));
    assign wb_err   = request && wr_done_q && wr_err_q;
    assign wb_dat_r = bus_rdata;  // gpu_regs returns 0 outside a read's answer

`ifdef FORMAL
    // ---- formal properties (tests/formal/gpu_wb_slave.sby: proved by induction) ----
    // The bus rules, assumed and asserted, are in tests/formal/gpu_wb_slave_check.sv (ZipCPU's
    // fwb_slave way); here, the invariants that tie the flops to its model of the bus.
    wire f_past_valid, f_wr_due, f_refused_due, f_rd_due;
    gpu_wb_slave_check f_check (
        .clk(clk), .rst(rst),
        .wb_cyc(wb_cyc), .wb_stb(wb_stb), .wb_we(wb_we), .wb_adr(wb_adr), .wb_dat_w(wb_dat_w),
        .wb_sel(wb_sel), .wb_dat_r(wb_dat_r), .wb_ack(wb_ack), .wb_err(wb_err),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .f_past_valid(f_past_valid), .f_wr_due(f_wr_due), .f_refused_due(f_refused_due),
        .f_rd_due(f_rd_due)
    );
    // Each flop says what the last clock began: a write (refused or not) or a read, answered now
    // if the master still asks. So a request's first clock is exactly an issue.
    always @(*) begin
        if (f_past_valid) begin
            assert(wr_done_q == f_wr_due);
            assert(wr_err_q == f_refused_due);
            assert(rd_wait_q == f_rd_due);
        end
    end
`endif
endmodule

`default_nettype wire
