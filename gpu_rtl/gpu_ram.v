// gpu_ram: simple dual-port synchronous RAM, one write port with lane enables and one read port,
// each on its own clock (the same clock for every RAM but the framebuffer's, read by the scan-out).
//
// Contract: a write with wr_en stores the lanes of wr_data whose wr_mask bit is set (lane i is bits
// [i*WIDTH/LANES +: WIDTH/LANES]) at wr_addr on the clock edge; the other lanes keep their contents, so
// a span of pixels is written without reading it first. A read with rd_en presents mem[rd_addr] on
// rd_data after that rd_clk edge (one cycle latency) and holds it while rd_en is low. With one clock,
// reading and writing the same address in one cycle returns the old data; with two, a read of the
// word being written is undefined (the framebuffer never reads the bank it writes). Power-on contents are zero (FPGA RAM honours
// initial values; it has no reset, so neither does this). Written in the template that yosys and
// Vivado map to block RAM with byte-write enables, or to LUT RAM when DISTRIBUTED is set.
`default_nettype none

module gpu_ram #(
    parameter integer DEPTH = 1024,       // words
    parameter integer WIDTH = 32,         // bits per word
    parameter integer LANES = 1,          // independently writable lanes per word (WIDTH % LANES == 0)
    parameter integer DISTRIBUTED = 0,    // 1: LUT RAM, for small tables that would waste a block RAM
    localparam integer AW = (DEPTH > 1) ? $clog2(DEPTH) : 1,
    localparam integer LANE_W = WIDTH / LANES
) (
    // write port
    input  wire             wr_clk,
    input  wire             wr_en,
    input  wire [AW-1:0]    wr_addr,
    input  wire [WIDTH-1:0] wr_data,
    input  wire [LANES-1:0] wr_mask,
    // read port
    input  wire             rd_clk,
    input  wire             rd_en,
    input  wire [AW-1:0]    rd_addr,
    output reg  [WIDTH-1:0] rd_data
);
    integer i;
    initial begin
        rd_data = {WIDTH{1'b0}};
    end

    // One template for both kinds: DISTRIBUTED chooses only the ram_style attribute (a constant
    // expression, which yosys and Vivado evaluate per instance).
    (* ram_style = (DISTRIBUTED != 0) ? "distributed" : "block" *) reg [WIDTH-1:0] mem [0:DEPTH-1];
    initial begin
        for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
    end
    always @(posedge wr_clk) begin
        for (i = 0; i < LANES; i = i + 1) begin
            if (wr_en && wr_mask[i]) mem[wr_addr][i*LANE_W +: LANE_W] <= wr_data[i*LANE_W +: LANE_W];
        end
    end
    always @(posedge rd_clk) begin
        if (rd_en) rd_data <= mem[rd_addr];
    end
endmodule

`default_nettype wire
