// gpu_axil_slave_check: formal properties of gpu_axil_slave (gpu_rtl/gpu_axil_slave.v), an
// AXI4-Lite slave, from its ports (tests/formal/gpu_axil_slave.sby; make formal).
//
// ZipCPU's way (its faxil_slave.v): a property module the slave instantiates in its `ifdef FORMAL
// block. It assumes the master's side and the native partner's, asserts the slave's, and keeps a
// model of what the slave holds (the accepted addresses and data, in order) that it hands to the
// slave's block, whose invariants tie the slave's flops to it (yosys reads no hierarchical names).
// GPU_AXIL_SLAVE defined (this proof): the two partners' rules are assumed; undefined (a larger
// proof that includes the slave with its real partners): they are asserted.
//
// Master (assumed): reset in the first clock; no AWVALID, WVALID or ARVALID in the clock after a
//   reset; each VALID held until its READY, its payload (AxADDR, AxPROT, WDATA, WSTRB) stable while
//   VALID && !READY. BREADY and RREADY are free, and so is every VALID otherwise (AW and W in any
//   order, at any distance).
// Native partner, gpu_regs' contract (assumed): bus_rvalid exactly one clock after a read
//   (bus_valid && !bus_write), never after a reset clock; bus_rdata is free.
// Slave (asserted): no BVALID or RVALID in the clock after a reset; BVALID held until BREADY with
//   BRESP stable, RVALID held until RREADY with RDATA and RRESP stable; no B response without an
//   accepted AW and W, no R response without an accepted AR, one response per request, in order
//   (the model's queues never hold more than the slave can: two of each, one held and one
//   answered); BRESP = SLVERR exactly for a write whose WSTRB was not 4'b1111, RRESP = OKAY. Native
//   side: a write reaches bus_valid once, before its OKAY response, with its AW's address and its
//   W's data, and a refused write never; a read reaches it once, with its AR's address, and its
//   RDATA is what gpu_regs answered (passed through in the answer's clock, or held). No channel
//   starves: a complete write, or a read, waits at most two clocks for the native bus.
// Covers: a read, a write and a refused write complete (the response handshake); a write complete
// after a W was held without its AW; a write and a read both waiting for the native bus.
`default_nettype none

`ifdef GPU_AXIL_SLAVE
`define GPU_AXIL_SLAVE_ASSUME assume
`else
`define GPU_AXIL_SLAVE_ASSUME assert
`endif

module gpu_axil_slave_check (
    input  wire        clk,
    input  wire        rst,
    // the slave's AXI4-Lite port
    input  wire        s_axi_awvalid,
    input  wire        s_axi_awready,
    input  wire [16:0] s_axi_awaddr,
    input  wire [2:0]  s_axi_awprot,
    input  wire        s_axi_wvalid,
    input  wire        s_axi_wready,
    input  wire [31:0] s_axi_wdata,
    input  wire [3:0]  s_axi_wstrb,
    input  wire        s_axi_bvalid,
    input  wire        s_axi_bready,
    input  wire [1:0]  s_axi_bresp,
    input  wire        s_axi_arvalid,
    input  wire        s_axi_arready,
    input  wire [16:0] s_axi_araddr,
    input  wire [2:0]  s_axi_arprot,
    input  wire        s_axi_rvalid,
    input  wire        s_axi_rready,
    input  wire [31:0] s_axi_rdata,
    input  wire [1:0]  s_axi_rresp,
    // its native port
    input  wire        bus_valid,
    input  wire        bus_write,
    input  wire [16:2] bus_addr,
    input  wire [31:0] bus_wdata,
    input  wire [31:0] bus_rdata,
    input  wire        bus_rvalid,
    // the model, for the slave's invariants: queues of accepted requests not yet answered (the B
    // or R handshake), oldest in 0; an entry beyond a count is stale
    output reg         f_past_valid,   // not the first clock
    output reg  [1:0]  f_aw_n,         // AW accepted, their B not yet taken
    output reg  [16:2] f_aw_addr0,
    output reg  [16:2] f_aw_addr1,
    output reg  [1:0]  f_w_n,          // W accepted, their B not yet taken
    output reg  [31:0] f_w_data0,
    output reg  [31:0] f_w_data1,
    output reg  [3:0]  f_w_strb0,
    output reg  [3:0]  f_w_strb1,
    output reg  [1:0]  f_ar_n,         // AR accepted, their R not yet taken
    output reg  [16:2] f_ar_addr0,
    output reg  [16:2] f_ar_addr1,
    output reg  [1:0]  f_rd_state,     // the oldest read: 0 not made, 1 gpu_regs answers now,
                                       // 2 answered, its data in f_rdata
    output reg  [31:0] f_rdata
);
    localparam [1:0] RESP_OKAY = 2'b00;
    localparam [1:0] RESP_SLVERR = 2'b10;

    wire aw_hs = !rst && s_axi_awvalid && s_axi_awready;
    wire w_hs  = !rst && s_axi_wvalid && s_axi_wready;
    wire b_hs  = !rst && s_axi_bvalid && s_axi_bready;
    wire ar_hs = !rst && s_axi_arvalid && s_axi_arready;
    wire r_hs  = !rst && s_axi_rvalid && s_axi_rready;
    wire native_wr = bus_valid && bus_write;
    wire native_rd = bus_valid && !bus_write;

    reg f_wr_done;         // the oldest write has made its native write
    reg f_rd_issued;       // a native read last clock (gpu_regs answers it now)
    reg [1:0] f_wr_wait;   // clocks a complete write has waited for the native bus, up to 3
    reg [1:0] f_rd_wait;   // clocks a read has waited for the native bus, up to 3
    reg f_w_ahead;         // a W has been held without its AW (since the last reset)
    initial begin
        f_past_valid = 1'b0;
        f_aw_n = 2'd0;
        f_w_n = 2'd0;
        f_ar_n = 2'd0;
        f_rd_state = 2'd0;
        f_wr_done = 1'b0;
        f_rd_issued = 1'b0;
        f_wr_wait = 2'd0;
        f_rd_wait = 2'd0;
        f_w_ahead = 1'b0;
    end

    wire wr_complete = f_aw_n != 2'd0 && f_w_n != 2'd0;  // the oldest write has both halves
    wire wr_waiting = wr_complete && !s_axi_bvalid;      // ... and waits for the native bus
    wire rd_waiting = f_ar_n != 2'd0 && f_rd_state == 2'd0;
    wire strb_full0 = f_w_strb0 == 4'b1111;

    // The queues: pop the oldest at its response's handshake, push behind what is left.
    wire [1:0] aw_left = f_aw_n - {1'b0, b_hs};
    wire [1:0] w_left  = f_w_n - {1'b0, b_hs};
    wire [1:0] ar_left = f_ar_n - {1'b0, r_hs};
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_rd_issued <= !rst && native_rd;
        if (rst) begin
            f_aw_n <= 2'd0;
            f_w_n <= 2'd0;
            f_ar_n <= 2'd0;
            f_rd_state <= 2'd0;
            f_wr_done <= 1'b0;
            f_wr_wait <= 2'd0;
            f_rd_wait <= 2'd0;
            f_w_ahead <= 1'b0;
        end else begin
            if (b_hs) f_aw_addr0 <= f_aw_addr1;
            if (aw_hs && aw_left == 2'd0) f_aw_addr0 <= s_axi_awaddr[16:2];
            if (aw_hs && aw_left == 2'd1) f_aw_addr1 <= s_axi_awaddr[16:2];
            f_aw_n <= aw_left + {1'b0, aw_hs};

            if (b_hs) begin
                f_w_data0 <= f_w_data1;
                f_w_strb0 <= f_w_strb1;
            end
            if (w_hs && w_left == 2'd0) begin
                f_w_data0 <= s_axi_wdata;
                f_w_strb0 <= s_axi_wstrb;
            end
            if (w_hs && w_left == 2'd1) begin
                f_w_data1 <= s_axi_wdata;
                f_w_strb1 <= s_axi_wstrb;
            end
            f_w_n <= w_left + {1'b0, w_hs};

            if (r_hs) f_ar_addr0 <= f_ar_addr1;
            if (ar_hs && ar_left == 2'd0) f_ar_addr0 <= s_axi_araddr[16:2];
            if (ar_hs && ar_left == 2'd1) f_ar_addr1 <= s_axi_araddr[16:2];
            f_ar_n <= ar_left + {1'b0, ar_hs};

            if (native_wr) f_wr_done <= 1'b1;
            else if (b_hs) f_wr_done <= 1'b0;

            if (native_rd) f_rd_state <= 2'd1;
            else if (r_hs) f_rd_state <= 2'd0;
            else if (f_rd_state == 2'd1) f_rd_state <= 2'd2;
            if (f_rd_state == 2'd1) f_rdata <= bus_rdata;

            f_wr_wait <= !wr_waiting ? 2'd0 : (f_wr_wait == 2'd3) ? 2'd3 : f_wr_wait + 2'd1;
            f_rd_wait <= !rd_waiting ? 2'd0 : (f_rd_wait == 2'd3) ? 2'd3 : f_rd_wait + 2'd1;
            if (f_w_n > f_aw_n) f_w_ahead <= 1'b1;
        end
    end

    // ---- the master (AXI4-Lite) ----
    always @(*) begin
        if (!f_past_valid) `GPU_AXIL_SLAVE_ASSUME(rst);
    end
    always @(posedge clk) begin
        if (!f_past_valid || $past(rst)) begin
            `GPU_AXIL_SLAVE_ASSUME(!s_axi_awvalid);
            `GPU_AXIL_SLAVE_ASSUME(!s_axi_wvalid);
            `GPU_AXIL_SLAVE_ASSUME(!s_axi_arvalid);
        end else begin
            if ($past(s_axi_awvalid && !s_axi_awready)) begin
                `GPU_AXIL_SLAVE_ASSUME(s_axi_awvalid);
                `GPU_AXIL_SLAVE_ASSUME($stable(s_axi_awaddr) && $stable(s_axi_awprot));
            end
            if ($past(s_axi_wvalid && !s_axi_wready)) begin
                `GPU_AXIL_SLAVE_ASSUME(s_axi_wvalid);
                `GPU_AXIL_SLAVE_ASSUME($stable(s_axi_wdata) && $stable(s_axi_wstrb));
            end
            if ($past(s_axi_arvalid && !s_axi_arready)) begin
                `GPU_AXIL_SLAVE_ASSUME(s_axi_arvalid);
                `GPU_AXIL_SLAVE_ASSUME($stable(s_axi_araddr) && $stable(s_axi_arprot));
            end
        end
    end

    // ---- the native partner (gpu_regs: a read's answer one clock later) ----
    always @(*) begin
        `GPU_AXIL_SLAVE_ASSUME(bus_rvalid == f_rd_issued);
    end

    // ---- the slave ----
    always @(posedge clk) begin
        if (f_past_valid && $past(rst)) begin
            assert(!s_axi_bvalid);
            assert(!s_axi_rvalid);
        end
        if (f_past_valid && !$past(rst)) begin
            // a response held until taken, unchanged
            if ($past(s_axi_bvalid && !s_axi_bready)) begin
                assert(s_axi_bvalid);
                assert($stable(s_axi_bresp));
            end
            if ($past(s_axi_rvalid && !s_axi_rready)) begin
                assert(s_axi_rvalid);
                assert($stable(s_axi_rdata) && $stable(s_axi_rresp));
            end
        end
    end
    always @(*) begin
        if (f_past_valid) begin
            // one response per request: queues that never overflow (so nothing accepted beyond
            // what the slave holds), and no response without its request
            if (aw_hs) assert(aw_left != 2'd2);
            if (w_hs) assert(w_left != 2'd2);
            if (ar_hs) assert(ar_left != 2'd2);
            if (s_axi_bvalid) assert(wr_complete);
            if (s_axi_rvalid) assert(f_ar_n != 2'd0 && f_rd_state != 2'd0);
            assert(f_rd_state != 2'd3);  // the model's own invariant (a state it never enters)
            // the write's answer: SLVERR exactly when its WSTRB was partial; an OKAY write was made
            // on the native bus (once: see below), a refused one never; BVALID follows at once
            if (s_axi_bvalid) begin
                assert(s_axi_bresp == (strb_full0 ? RESP_OKAY : RESP_SLVERR));
                assert(f_wr_done == strb_full0);
            end
            if (f_wr_done) assert(s_axi_bvalid);
            // the native write: the oldest write, complete, not yet answered nor made, full WSTRB
            if (native_wr) begin
                assert(wr_waiting && !f_wr_done && strb_full0);
                assert(bus_addr == f_aw_addr0 && bus_wdata == f_w_data0);
            end
            // the native read: the oldest read, not yet made; its data passed through in the
            // clock gpu_regs answers it, then held
            if (native_rd) assert(rd_waiting && bus_addr == f_ar_addr0);
            if (f_rd_state == 2'd1) assert(s_axi_rvalid && s_axi_rdata == bus_rdata);
            if (f_rd_state == 2'd2) assert(s_axi_rvalid && s_axi_rdata == f_rdata);
            if (s_axi_rvalid) assert(s_axi_rresp == RESP_OKAY);
            // neither channel starves
            assert(f_wr_wait < 2'd2 || !wr_waiting);
            assert(f_rd_wait < 2'd2 || !rd_waiting);
        end
    end

    // ---- covers ----
    always @(*) begin
        if (f_past_valid && !rst) begin
            cover(r_hs);
            cover(b_hs && s_axi_bresp == RESP_OKAY);
            cover(b_hs && s_axi_bresp == RESP_SLVERR);
            cover(b_hs && f_w_ahead);
            cover(wr_waiting && rd_waiting);
        end
    end
endmodule

`undef GPU_AXIL_SLAVE_ASSUME
`default_nettype wire
