// gpu_framebuffer: two 320x240 banks of 8-bit palette indices, one drawn (back), one shown (front).
//
// Contract: the write port always targets the back bank, the read port always the front bank.
// swap (one-cycle pulse) exchanges them on the clock edge; a read issued on that same edge still comes
// from the old front. Read latency is one cycle, as gpu_ram. front is the bank being shown (STATUS.FRONT).
`default_nettype none

module gpu_framebuffer #(
    parameter integer PIXELS = 320 * 240,
    localparam integer AW = $clog2(PIXELS)
) (
    input  wire          clk,
    input  wire          rst,
    // bank control
    input  wire          swap,        // exchange front and back
    output wire          front,       // bank currently shown
    // write port (rasterizer, back bank)
    input  wire          wr_en,
    input  wire [AW-1:0] wr_addr,
    input  wire [7:0]    wr_data,
    // read port (scan-out, front bank)
    input  wire          rd_en,
    input  wire [AW-1:0] rd_addr,
    output wire [7:0]    rd_data
);
    reg front_q;
    reg rd_bank_q;  // bank the pending read data comes from
    wire [7:0] bank0_rd_data;
    wire [7:0] bank1_rd_data;

    always @(posedge clk) begin
        if (rst) begin
            front_q <= 1'b0;
        end else if (swap) begin
            front_q <= ~front_q;
        end
        if (rd_en) begin
            rd_bank_q <= front_q;
        end
    end

    gpu_ram #(.DEPTH(PIXELS), .WIDTH(8)) u_bank0 (
        .clk(clk),
        .wr_en(wr_en && front_q), .wr_addr(wr_addr), .wr_data(wr_data),
        .rd_en(rd_en && !front_q), .rd_addr(rd_addr), .rd_data(bank0_rd_data)
    );

    gpu_ram #(.DEPTH(PIXELS), .WIDTH(8)) u_bank1 (
        .clk(clk),
        .wr_en(wr_en && !front_q), .wr_addr(wr_addr), .wr_data(wr_data),
        .rd_en(rd_en && front_q), .rd_addr(rd_addr), .rd_data(bank1_rd_data)
    );

    assign front   = front_q;
    assign rd_data = rd_bank_q ? bank1_rd_data : bank0_rd_data;
endmodule

`default_nettype wire
