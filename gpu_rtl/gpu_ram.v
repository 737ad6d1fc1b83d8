// gpu_ram: simple dual-port synchronous RAM, one write port and one read port.
//
// Contract: a write with wr_en stores wr_data at wr_addr on the clock edge. A read with rd_en
// presents mem[rd_addr] on rd_data after that edge (one cycle latency) and holds it while rd_en is low.
// Reading and writing the same address in one cycle returns the old data. Power-on contents are zero
// (initial values are honoured by FPGA block RAM; there is no reset port, as block RAM has none).
// Written in the template that yosys and Vivado map to block RAM.
`default_nettype none

module gpu_ram #(
    parameter integer DEPTH = 1024,  // words
    parameter integer WIDTH = 32,    // bits per word
    localparam integer AW = (DEPTH > 1) ? $clog2(DEPTH) : 1
) (
    input  wire             clk,
    // write port
    input  wire             wr_en,
    input  wire [AW-1:0]    wr_addr,
    input  wire [WIDTH-1:0] wr_data,
    // read port
    input  wire             rd_en,
    input  wire [AW-1:0]    rd_addr,
    output reg  [WIDTH-1:0] rd_data
);
    reg [WIDTH-1:0] mem [0:DEPTH-1];

    integer i;
    initial begin
        for (i = 0; i < DEPTH; i = i + 1) begin
            mem[i] = {WIDTH{1'b0}};
        end
        rd_data = {WIDTH{1'b0}};
    end

    always @(posedge clk) begin
        if (wr_en) begin
            mem[wr_addr] <= wr_data;
        end
    end

    always @(posedge clk) begin
        if (rd_en) begin
            rd_data <= mem[rd_addr];
        end
    end
endmodule

`default_nettype wire
