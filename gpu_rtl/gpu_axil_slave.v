// gpu_axil_slave: AXI4-Lite (32-bit) slave to gpu_top's native bus (gpu_regs), e.g. for MicroBlaze.
//
// Contract: the AW and W channels are independent (either may come first, with any delay between
// them); each is taken into a one-entry holding register (s_axi_awready = that register is empty),
// and a write is executed once both halves are held and no earlier B response is still waiting.
// One read address is held the same way. Every valid (BVALID, RVALID) is raised without looking at
// the matching ready and held, with its data and response, until accepted. Responses come in order:
// one write and one read are executed at a time.
//   write: AW and W accepted in clock 0 -> native write in clock 1 -> BVALID in clock 2. With BREADY
//          high, one write every 2 clocks.
//   read:  AR accepted in clock 0 -> native read in clock 1 -> RVALID (bus_rdata) in clock 2.
//   error: the contract allows aligned 32-bit words only. A write with s_axi_wstrb != 4'b1111 never
//          reaches the GPU and is answered BRESP = SLVERR. Every other answer is OKAY (the GPU has no
//          address that refuses an access; reads of write-only windows return 0).
// Arbitration: the native bus takes one access per clock. When a write and a read are both ready to
// go, they alternate (the one not served last goes first), so neither channel can starve the other.
// Addresses are byte addresses in the 128 KiB window; bits [1:0] and AxPROT are ignored.
`default_nettype none

module gpu_axil_slave (
    input  wire        clk,
    input  wire        rst,            // synchronous, active high
    // AXI4-Lite slave: write address
    input  wire        s_axi_awvalid,
    output wire        s_axi_awready,
    input  wire [16:0] s_axi_awaddr,   // byte address in the window, bits [1:0] ignored
    input  wire [2:0]  s_axi_awprot,   // ignored
    // write data
    input  wire        s_axi_wvalid,
    output wire        s_axi_wready,
    input  wire [31:0] s_axi_wdata,
    input  wire [3:0]  s_axi_wstrb,    // must be 4'b1111, else SLVERR
    // write response
    output reg         s_axi_bvalid,
    input  wire        s_axi_bready,
    output reg  [1:0]  s_axi_bresp,    // OKAY, or SLVERR for a partial write
    // read address
    input  wire        s_axi_arvalid,
    output wire        s_axi_arready,
    input  wire [16:0] s_axi_araddr,   // byte address in the window, bits [1:0] ignored
    input  wire [2:0]  s_axi_arprot,   // ignored
    // read data
    output wire        s_axi_rvalid,
    input  wire        s_axi_rready,
    output wire [31:0] s_axi_rdata,
    output wire [1:0]  s_axi_rresp,    // always OKAY
    // to gpu_top's native bus
    output wire        bus_valid,
    output wire        bus_write,
    output wire [16:2] bus_addr,
    output wire [31:0] bus_wdata,
    input  wire [31:0] bus_rdata,
    input  wire        bus_rvalid
);
    localparam [1:0] RESP_OKAY = 2'b00;
    localparam [1:0] RESP_SLVERR = 2'b10;

    // Holding registers, one entry per address/data channel.
    reg        aw_full_q, w_full_q, ar_full_q;
    reg [16:2] aw_addr_q, ar_addr_q;
    reg [31:0] w_data_q;
    reg [3:0]  w_strb_q;
    // Read answer: rd_wait_q while the native read is out; the data is passed straight through in the
    // clock bus_rvalid comes back, and held in rdata_q (rvalid_q) if the master is not ready then.
    reg        rd_wait_q, rvalid_q;
    reg [31:0] rdata_q;
    reg        last_read_q;  // the previous native-bus grant went to a read

    assign s_axi_awready = !aw_full_q;
    assign s_axi_wready  = !w_full_q;
    assign s_axi_arready = !ar_full_q;

    wire wr_ready = aw_full_q && w_full_q && !s_axi_bvalid;
    wire rd_ready = ar_full_q && !rd_wait_q && !rvalid_q;
    wire grant_wr = wr_ready && !(rd_ready && !last_read_q);
    wire grant_rd = rd_ready && !grant_wr;
    wire wr_refuse = w_strb_q != 4'b1111;

    assign bus_valid = (grant_wr && !wr_refuse) || grant_rd;
    assign bus_write = grant_wr;
    assign bus_addr  = grant_wr ? aw_addr_q : ar_addr_q;
    assign bus_wdata = w_data_q;

    wire rd_answer = rd_wait_q && bus_rvalid;
    assign s_axi_rvalid = rvalid_q || rd_answer;
    assign s_axi_rdata  = rvalid_q ? rdata_q : bus_rdata;
    assign s_axi_rresp  = RESP_OKAY;

    always @(posedge clk) begin
        if (rst) begin
            aw_full_q <= 1'b0;
            w_full_q <= 1'b0;
            ar_full_q <= 1'b0;
            aw_addr_q <= 15'd0;
            ar_addr_q <= 15'd0;
            w_data_q <= 32'd0;
            w_strb_q <= 4'd0;
            s_axi_bvalid <= 1'b0;
            s_axi_bresp <= RESP_OKAY;
            rd_wait_q <= 1'b0;
            rvalid_q <= 1'b0;
            rdata_q <= 32'd0;
            last_read_q <= 1'b0;
        end else begin
            if (s_axi_awvalid && s_axi_awready) begin
                aw_full_q <= 1'b1;
                aw_addr_q <= s_axi_awaddr[16:2];
            end else if (grant_wr) begin
                aw_full_q <= 1'b0;
            end
            if (s_axi_wvalid && s_axi_wready) begin
                w_full_q <= 1'b1;
                w_data_q <= s_axi_wdata;
                w_strb_q <= s_axi_wstrb;
            end else if (grant_wr) begin
                w_full_q <= 1'b0;
            end
            if (s_axi_arvalid && s_axi_arready) begin
                ar_full_q <= 1'b1;
                ar_addr_q <= s_axi_araddr[16:2];
            end else if (grant_rd) begin
                ar_full_q <= 1'b0;
            end

            if (grant_wr) begin
                s_axi_bvalid <= 1'b1;
                s_axi_bresp <= wr_refuse ? RESP_SLVERR : RESP_OKAY;
            end else if (s_axi_bready) begin
                s_axi_bvalid <= 1'b0;
            end

            if (grant_rd) begin
                rd_wait_q <= 1'b1;
            end else if (bus_rvalid) begin
                rd_wait_q <= 1'b0;
            end
            if (rd_answer && !rvalid_q) begin
                rvalid_q <= !s_axi_rready;
                rdata_q <= bus_rdata;
            end else if (s_axi_rready) begin
                rvalid_q <= 1'b0;
            end

            if (grant_wr || grant_rd) begin
                last_read_q <= grant_rd;
            end
        end
    end

    wire unused = &{1'b0, s_axi_awaddr[1:0], s_axi_araddr[1:0], s_axi_awprot, s_axi_arprot};

`ifdef FORMAL
    // ---- formal properties (tests/formal/gpu_axil_slave.sby: proved by induction) ----
    // The bus rules, assumed and asserted, are in tests/formal/gpu_axil_slave_check.sv (ZipCPU's
    // faxil_slave way), with a model of the accepted requests; here, the invariants that tie the
    // holding registers and the read answer to that model.
    wire        f_past_valid;
    wire [1:0]  f_aw_n, f_w_n, f_ar_n, f_rd_state;
    wire [16:2] f_aw_addr0, f_aw_addr1, f_ar_addr0, f_ar_addr1;
    wire [31:0] f_w_data0, f_w_data1, f_rdata;
    wire [3:0]  f_w_strb0, f_w_strb1;
    gpu_axil_slave_check f_check (
        .clk(clk), .rst(rst),
        .s_axi_awvalid(s_axi_awvalid), .s_axi_awready(s_axi_awready), .s_axi_awaddr(s_axi_awaddr),
        .s_axi_awprot(s_axi_awprot),
        .s_axi_wvalid(s_axi_wvalid), .s_axi_wready(s_axi_wready), .s_axi_wdata(s_axi_wdata),
        .s_axi_wstrb(s_axi_wstrb),
        .s_axi_bvalid(s_axi_bvalid), .s_axi_bready(s_axi_bready), .s_axi_bresp(s_axi_bresp),
        .s_axi_arvalid(s_axi_arvalid), .s_axi_arready(s_axi_arready), .s_axi_araddr(s_axi_araddr),
        .s_axi_arprot(s_axi_arprot),
        .s_axi_rvalid(s_axi_rvalid), .s_axi_rready(s_axi_rready), .s_axi_rdata(s_axi_rdata),
        .s_axi_rresp(s_axi_rresp),
        .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr), .bus_wdata(bus_wdata),
        .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid),
        .f_past_valid(f_past_valid),
        .f_aw_n(f_aw_n), .f_aw_addr0(f_aw_addr0), .f_aw_addr1(f_aw_addr1),
        .f_w_n(f_w_n), .f_w_data0(f_w_data0), .f_w_data1(f_w_data1), .f_w_strb0(f_w_strb0),
        .f_w_strb1(f_w_strb1),
        .f_ar_n(f_ar_n), .f_ar_addr0(f_ar_addr0), .f_ar_addr1(f_ar_addr1),
        .f_rd_state(f_rd_state), .f_rdata(f_rdata)
    );
    // A write is held (aw_full_q, w_full_q) until it is made, then answered (s_axi_bvalid): the
    // queued writes are the answered one, if any, then the held one. Likewise a read is held
    // (ar_full_q), then out (rd_wait_q: gpu_regs answers now) or answered and waiting (rvalid_q).
    wire f_rd_out = rd_wait_q || rvalid_q;
    always @(*) begin
        if (f_past_valid) begin
            assert(f_aw_n == {1'b0, aw_full_q} + {1'b0, s_axi_bvalid});
            assert(f_w_n == {1'b0, w_full_q} + {1'b0, s_axi_bvalid});
            if (aw_full_q) assert(aw_addr_q == (s_axi_bvalid ? f_aw_addr1 : f_aw_addr0));
            if (w_full_q) begin
                assert(w_data_q == (s_axi_bvalid ? f_w_data1 : f_w_data0));
                assert(w_strb_q == (s_axi_bvalid ? f_w_strb1 : f_w_strb0));
            end
            assert(f_ar_n == {1'b0, ar_full_q} + {1'b0, f_rd_out});
            if (ar_full_q) assert(ar_addr_q == (f_rd_out ? f_ar_addr1 : f_ar_addr0));
            assert(rd_wait_q == (f_rd_state == 2'd1));
            assert(rvalid_q == (f_rd_state == 2'd2));
            if (rvalid_q) assert(rdata_q == f_rdata);
        end
    end
`endif
endmodule

`default_nettype wire
