// soc_ram: the SoC's on-chip RAM (code, data, stack) as a Wishbone B4 slave with incrementing bursts.
//
// Contract: RAM_BYTES / 4 words of 32 bits; wb_adr is the word index in the RAM (the decoder selects
// only addresses below RAM_BYTES). One port, one address (block RAM, one read-or-write per clock).
//   write: stored in the request's first clock, the lanes whose wb_sel bit is set; wb_ack next clock.
//   read, classic (wb_cti != 3'b010): the word is read in the request's first clock, wb_ack with it
//          in the next. A request every other clock: 2 clocks per access.
//   read, incrementing burst (wb_cti == 3'b010: another beat follows at wb_adr + 1, as VexRiscv's
//          cache-line refills say, ending with 3'b111): while beat k is acked the RAM already reads
//          k + 1, so the next ack follows at once: an 8-word line in 9 clocks from its request
//          instead of 16. The master must present beat k + 1 in the clock after beat k's ack
//          (Wishbone's registered-feedback rule; BTE linear only).
// Power-on contents: RAM_INIT ($readmemh: one 32-bit hex word per line, line n = word n, i.e. byte
// address 4n; the rest zero), or zero with RAM_INIT = ""; in simulation +ram_init=FILE overrides it
// at run time. No reset of the contents (FPGA block RAM).
// Written as one 32-bit memory with lane writes, the template yosys maps to ECP5 DP16KD blocks
// (2 KiB of byte data each: 96 for the default 192 KiB; see soc_rtl/README.md for the count).
`default_nettype none

module soc_ram #(
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // size; a multiple of 4
    parameter RAM_INIT = "",                                       // $readmemh file, "" = zeros
    localparam integer WORDS = RAM_BYTES / 4,
    localparam integer AW = $clog2(WORDS)
) (
    input  wire          clk,
    input  wire          rst,        // synchronous, active high (the handshake only, not the contents)
    // Wishbone B4 slave
    input  wire          wb_cyc,
    input  wire          wb_stb,     // selected by the decoder (cyc && stb && address in the RAM)
    input  wire          wb_we,
    input  wire [AW-1:0] wb_adr,     // word index
    input  wire [31:0]   wb_dat_w,
    input  wire [3:0]    wb_sel,     // byte lanes of a write
    input  wire [2:0]    wb_cti,     // 3'b010: incrementing burst, another beat follows
    output reg  [31:0]   wb_dat_r,   // valid with wb_ack
    output wire          wb_ack
);
    integer i;
    (* ram_style = "block" *) reg [31:0] mem [0:WORDS-1];
    initial wb_dat_r = 32'd0;
`ifdef SYNTHESIS
    // RAM_INIT, or no initial value, which the bitstream makes zero (an explicit zero loop costs
    // yosys 0.23 one $meminit per word: minutes and a GiB for 48 Ki words).
    initial begin
        if (RAM_INIT != "") $readmemh(RAM_INIT, mem);
    end
`else
    // Simulation: zeros, then RAM_INIT, then +ram_init=FILE from the simulator's command line if
    // given, so that one Verilated model runs any program (Verilated::commandArgs must be called).
    reg [8*1024-1:0] ram_init_arg;
    initial begin
        for (i = 0; i < WORDS; i = i + 1) mem[i] = 32'd0;
        if (RAM_INIT != "") $readmemh(RAM_INIT, mem);
        if ($value$plusargs("ram_init=%s", ram_init_arg)) $readmemh(ram_init_arg, mem);
    end
`endif

    reg ack_q;   // wb_ack: the word read last clock answers the current beat
    wire req = wb_cyc && wb_stb;
    // The beat acked now is a read with another beat after it: read that one now.
    wire burst_next = ack_q && req && !wb_we && wb_cti == 3'b010;
    wire [AW-1:0] addr = burst_next ? wb_adr + 1'b1 : wb_adr;   // = wb_adr whenever a write is stored
    wire wr = req && wb_we && !ack_q;

    always @(posedge clk) begin
        for (i = 0; i < 4; i = i + 1) begin
            if (wr && wb_sel[i]) mem[addr][i*8 +: 8] <= wb_dat_w[i*8 +: 8];
        end
        wb_dat_r <= mem[addr];
    end

    always @(posedge clk) begin
        if (rst) ack_q <= 1'b0;
        else     ack_q <= req && (!ack_q || burst_next);
    end
    assign wb_ack = ack_q && req;
endmodule

`default_nettype wire
