// tiny: a small design that makes nextpnr-ecp5 use every cell of the board's placed-and-routed
// netlist that cosim/netlist/ecp5_routed models, synthesized, placed and routed by
// tests/boards/netlist_routed_cells.sh and simulated cycle by cycle against this RTL
// (tests/boards/netlist_routed/tiny_tb.sv). What each part is for:
//   cnt    a 16-bit counter with an enable: a CCU2 carry chain (nextpnr's feed-in with its
//          unconnected LUT inputs at 1), flip-flops with CE
//   acc    a subtraction, a carry chain whose carry-in is the constant 1; cleared by the reset
//   lfsr   a 16-bit LFSR: flip-flops fed straight from flip-flops (SD 0, data on M); reset to a
//          value with ones and zeros (REGSET SET and RESET, LSR)
//   mem    a 16x8 RAM with an asynchronous read and initial contents: two TRELLIS_DPR16X4, i.e.
//          DPRAM LUTs, a TRELLIS_RAMW and RAMW_BLOCK placeholders, INITVAL in nextpnr's LUT order
//   wide   a 32:1 multiplexer: LUT5s and LUT6s (the OFX of K0 and K1 LUTs: PFUMX and L6MUX21)
//   hold   a register enabled by a low signal (CEMUX INV)
//   oddr   two ODDRX1F outputs (SIOLOGIC, TRELLIS_IO with DATAMUX_ODDR IOLDO); the clock on a
//          global buffer (DCCA); inputs and outputs through TRELLIS_IO
`default_nettype none
module tiny (
    input  wire       clk_25mhz,
    input  wire       btn_fire1,    // synchronous reset
    input  wire       ftdi_txd,     // data mixed into the RAM and the registers
    output wire [7:0] led,
    output wire       ftdi_rxd,
    output wire       wifi_gpio0,
    output wire [1:0] gpdi_dp
);
    wire clk = clk_25mhz;
    reg rst = 1'b1, din = 1'b0;
    always @(posedge clk) begin
        rst <= btn_fire1;
        din <= ftdi_txd;
    end

    reg [15:0] lfsr = 16'hACE1;
    always @(posedge clk)
        if (rst)
            lfsr <= 16'hACE1;
        else
            lfsr <= {lfsr[14:0], lfsr[15] ^ lfsr[13] ^ lfsr[12] ^ lfsr[10] ^ din};

    reg [15:0] cnt = 16'd0;
    always @(posedge clk)
        if (lfsr[3] | din)
            cnt <= cnt + 16'd1;

    reg [11:0] acc = 12'd0;
    always @(posedge clk)
        if (rst)
            acc <= 12'd0;
        else
            acc <= acc - {lfsr[7:0], cnt[3:0]};

    reg [7:0] mem [0:15];
    integer i;
    initial
        for (i = 0; i < 16; i = i + 1)
            mem[i] = i * 37 + 11;
    always @(posedge clk)
        if (lfsr[0] & ~rst)
            mem[lfsr[7:4]] <= lfsr[15:8] ^ {7'd0, din} ^ cnt[7:0];
    wire [7:0] rd = mem[cnt[3:0] ^ acc[3:0]];

    wire [31:0] pool = {lfsr, cnt} ^ {acc, acc[11:0], cnt[15:8]};
    wire wide = pool[{lfsr[9], cnt[6:3]}];
    reg wide_q = 1'b0;
    always @(posedge clk)
        wide_q <= wide ^ rd[0];

    reg [7:0] hold = 8'h5A;
    wire hold_off = lfsr[5] & lfsr[6];
    always @(posedge clk)
        if (!hold_off)
            hold <= rd ^ acc[11:4];

    ODDRX1F u_oddr0 (.SCLK(clk), .RST(1'b0), .D0(lfsr[0]), .D1(cnt[0]), .Q(gpdi_dp[0]));
    ODDRX1F u_oddr1 (.SCLK(clk), .RST(1'b0), .D0(hold[0] ^ hold[7]), .D1(acc[0]), .Q(gpdi_dp[1]));

    assign led = rd ^ hold;
    assign ftdi_rxd = wide_q;
    assign wifi_gpio0 = (cnt > {4'd0, acc}) ^ (^hold);
endmodule
`default_nettype wire
