// gpu_framebuffer: two 320x240 banks of 8-bit palette indices, one drawn (back), one shown (front).
//
// Contract: each bank is stored as words of SPAN_W pixels (a span: SPAN_W neighbours in one row, the
// first at a multiple of SPAN_W), so the rasterizer writes a whole span per clock with a per-pixel
// mask and never reads. The write port always targets the back bank, the read port always the front
// bank; the read port takes a pixel index (y*320 + x) and returns that pixel one cycle later. swap
// (one-cycle pulse) exchanges the banks on the clock edge; a read issued on that edge still comes from
// the old front. front is the bank being shown (STATUS.FRONT).
`default_nettype none

module gpu_framebuffer #(
    parameter integer SPAN_W = 8,    // pixels per word; divides 320
    localparam integer PIXELS = 320 * 240,
    localparam integer WORDS = PIXELS / SPAN_W,
    localparam integer WAW = $clog2(WORDS),
    localparam integer PAW = $clog2(PIXELS),
    localparam integer LANE_AW = (SPAN_W > 1) ? $clog2(SPAN_W) : 1
) (
    input  wire                clk,
    input  wire                rst,
    // bank control
    input  wire                swap,       // exchange front and back
    output wire                front,      // bank currently shown
    // write port (rasterizer, back bank): one span
    input  wire                wr_en,
    input  wire [WAW-1:0]      wr_addr,    // span index: y * 320/SPAN_W + x/SPAN_W
    input  wire [SPAN_W*8-1:0] wr_data,    // pixel i of the span in bits [8i +: 8]
    input  wire [SPAN_W-1:0]   wr_mask,    // pixels to write
    // read port (scan-out, front bank): one pixel
    input  wire                rd_en,
    input  wire [PAW-1:0]      rd_addr,    // pixel index y*320 + x
    output wire [7:0]          rd_data
);
    reg front_q;
    reg rd_bank_q;                 // bank the pending read data comes from
    reg [LANE_AW-1:0] rd_lane_q;   // pixel of the word it is
    wire [SPAN_W*8-1:0] bank0_rd_data;
    wire [SPAN_W*8-1:0] bank1_rd_data;
    wire [WAW-1:0] rd_word = WAW'(rd_addr / PAW'(SPAN_W));
    wire [LANE_AW-1:0] rd_lane = (SPAN_W > 1) ? LANE_AW'(rd_addr % PAW'(SPAN_W)) : {LANE_AW{1'b0}};

    always @(posedge clk) begin
        if (rst) begin
            front_q <= 1'b0;
        end else if (swap) begin
            front_q <= ~front_q;
        end
        if (rd_en) begin
            rd_bank_q <= front_q;
            rd_lane_q <= rd_lane;
        end
    end

    gpu_ram #(.DEPTH(WORDS), .WIDTH(SPAN_W * 8), .LANES(SPAN_W)) u_bank0 (
        .clk(clk),
        .wr_en(wr_en && front_q), .wr_addr(wr_addr), .wr_data(wr_data), .wr_mask(wr_mask),
        .rd_en(rd_en && !front_q), .rd_addr(rd_word), .rd_data(bank0_rd_data)
    );

    gpu_ram #(.DEPTH(WORDS), .WIDTH(SPAN_W * 8), .LANES(SPAN_W)) u_bank1 (
        .clk(clk),
        .wr_en(wr_en && !front_q), .wr_addr(wr_addr), .wr_data(wr_data), .wr_mask(wr_mask),
        .rd_en(rd_en && front_q), .rd_addr(rd_word), .rd_data(bank1_rd_data)
    );

    wire [SPAN_W*8-1:0] word = rd_bank_q ? bank1_rd_data : bank0_rd_data;
    assign front   = front_q;
    assign rd_data = word[rd_lane_q * 8 +: 8];
endmodule

`default_nettype wire
