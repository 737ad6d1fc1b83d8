// gpu_framebuffer: two banks of FB_WIDTH x FB_HEIGHT 8-bit palette indices (the build's frame),
// one drawn (back), one shown (front).
//
// Contract: each bank is stored as words of SPAN_W pixels (a span: SPAN_W neighbours in one row, the
// first at a multiple of SPAN_W), so the rasterizer writes a whole span per clock with a per-pixel
// mask and never reads. The write port always targets the back bank, the read port always the front
// bank; the read port takes a pixel index (y * FB_WIDTH + x) and returns that pixel one clk_pix
// cycle later. swap (one-cycle pulse) exchanges the banks on the clk edge; front is the bank being
// shown (STATUS.FRONT).
//
// Two clock domains: writes and swap on clk (the system clock), reads on clk_pix (the scan-out's).
// The read side selects its bank by front_pix, front crossed by gpu_cdc_sync: it follows a swap two
// or three clk_pix cycles later. That is safe because swaps happen only at vertical blank (gpu_raster
// waits for vblank_start), 45 lines before the scan-out reads a visible pixel again, and the one bit
// is constant while it crosses. Until then a blanking read may come from the new back bank: its data
// is never shown.
//
// Write mask (ENABLE_WMASK): a pixel is two 4-bit planes, bits [3:0] (plane 0) and [7:4] (plane
// 1), each with its own write enable: the RAM's lanes are 4 bits, and lane 2i + p of a word (pixel
// i's plane p) is written when wr_mask[i] and wr_planes[p] are both set; both banks then share one
// RAM (g_merged, below) instead of the main + tail split. The planes a batch does
// not write keep their contents without being read (no read-modify-write, no stall), the clear
// included. Without it the lanes are the 8-bit pixels and wr_planes is ignored (today's one plane).
// Cost in block RAM: a 4-bit lane needs a write enable of its own, which the ECP5's 18/36-bit
// block RAM modes give per 9 bits only, so yosys maps the lanes to narrower modes; README.md ("The
// anaglyph on the write mask") has the measured EBR and LUT counts.
//
// Block RAM economy: a bank of FB_WIDTH * FB_HEIGHT / SPAN_W words is not a multiple of the 1024-word depth
// 36 Kb block RAMs come in, and a tool that rounds it up wastes a whole column of them (20 instead of
// 19 per bank at SPAN_W = 8). So each bank is a main part of whole 1024-word blocks plus a small tail
// RAM.
`default_nettype none

module gpu_framebuffer #(
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,      // the frame
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,  // pixels per word; divides FB_WIDTH
    parameter integer ENABLE_WMASK = gpu_pkg::GPU_DEFAULT_ENABLE_WMASK,  // two 4-bit planes (above)
    localparam integer PIXELS = FB_WIDTH * FB_HEIGHT,
    localparam integer WORDS = PIXELS / SPAN_W,
    localparam integer MAIN_WORDS = (WORDS / 1024) * 1024,
    localparam integer TAIL_WORDS = WORDS - MAIN_WORDS,
    localparam integer WAW = $clog2(WORDS),
    localparam integer PAW = $clog2(PIXELS),
    localparam integer LANE_AW = (SPAN_W > 1) ? $clog2(SPAN_W) : 1,
    localparam integer LANES = (ENABLE_WMASK != 0) ? 2 * SPAN_W : SPAN_W  // RAM write lanes a word
) (
    input  wire                clk,        // system clock: writes, swap
    input  wire                rst,        // synchronous to clk
    input  wire                clk_pix,    // scan-out clock: reads
    // bank control
    input  wire                swap,       // exchange front and back
    output wire                front,      // bank currently shown
    // write port (rasterizer, back bank): one span
    input  wire                wr_en,
    input  wire [WAW-1:0]      wr_addr,    // span index: y * FB_WIDTH / SPAN_W + x / SPAN_W
    input  wire [SPAN_W*8-1:0] wr_data,    // pixel i of the span in bits [8i +: 8]
    input  wire [SPAN_W-1:0]   wr_mask,    // pixels to write
    input  wire [1:0]          wr_planes,  // planes to write, {bits [7:4], bits [3:0]} (ENABLE_WMASK)
    // read port (scan-out, front bank): one pixel, clk_pix domain
    input  wire                rd_en,
    input  wire [PAW-1:0]      rd_addr,    // pixel index y * FB_WIDTH + x
    output wire [7:0]          rd_data
);
    reg front_q;
    reg rd_bank_q;                 // bank the pending read data comes from
    reg rd_tail_q;                 // ... and whether from its tail part
    reg [LANE_AW-1:0] rd_lane_q;   // pixel of the word it is
    wire [WAW-1:0] rd_word = WAW'(rd_addr / PAW'(SPAN_W));
    wire [LANE_AW-1:0] rd_lane = (SPAN_W > 1) ? LANE_AW'(rd_addr % PAW'(SPAN_W)) : {LANE_AW{1'b0}};
    wire rd_in_tail = rd_word >= WAW'(MAIN_WORDS);
    wire wr_in_tail = wr_addr >= WAW'(MAIN_WORDS);

    always @(posedge clk) begin
        if (rst) begin
            front_q <= 1'b0;
        end else if (swap) begin
            front_q <= ~front_q;
        end
    end

    wire front_pix;
    gpu_cdc_sync u_front_sync (.clk(clk_pix), .in(front_q), .out(front_pix));

    always @(posedge clk_pix) begin
        if (rd_en) begin
            rd_bank_q <= front_pix;
            rd_tail_q <= rd_in_tail;
            rd_lane_q <= rd_lane;
        end
    end

    wire [SPAN_W*8-1:0] word;  // the read word, one clk_pix cycle after rd_en

    genvar lane, bank;
    generate
        if (ENABLE_WMASK != 0) begin : g_merged
            // Both banks in one RAM of 2 x WORDS words, bank b at words [b * WORDS, (b + 1) *
            // WORDS): a 4-bit lane is then a column 2 x WORDS deep, which yosys maps to 4K x 4
            // block RAMs with less rounding than two columns of WORDS (19200 nibbles = 4.7 blocks
            // at SPAN_W = 8: 5 per lane and plane, 80 in all, where two banks apart take 3 + 3
            // and a tail; README.md has the counts). The write port addresses the back bank, the
            // read port the front one: never the same word but for the blanking reads after a swap.
            localparam integer MAW = $clog2(2 * WORDS);
            wire [LANES-1:0] lane_mask;
            for (lane = 0; lane < SPAN_W; lane = lane + 1) begin : g_lane
                assign lane_mask[2 * lane]     = wr_mask[lane] && wr_planes[0];
                assign lane_mask[2 * lane + 1] = wr_mask[lane] && wr_planes[1];
            end
            wire [MAW-1:0] wr_word = front_q ? MAW'(wr_addr) : MAW'(wr_addr) + MAW'(WORDS);
            wire [MAW-1:0] rd_word_m = front_pix ? MAW'(rd_word) + MAW'(WORDS) : MAW'(rd_word);
            gpu_ram #(.DEPTH(2 * WORDS), .WIDTH(SPAN_W * 8), .LANES(LANES)) u_both (
                .wr_clk(clk), .rd_clk(clk_pix),
                .wr_en(wr_en), .wr_addr(wr_word), .wr_data(wr_data), .wr_mask(lane_mask),
                .rd_en(rd_en), .rd_addr(rd_word_m), .rd_data(word)
            );
            wire unused_split = rd_bank_q | rd_tail_q | wr_in_tail | rd_in_tail;
        end else begin : g_split
            wire [SPAN_W*8-1:0] main_rd_data [0:1];
            wire [SPAN_W*8-1:0] tail_rd_data [0:1];
            wire unused_planes = |wr_planes;
            for (bank = 0; bank < 2; bank = bank + 1) begin : g_bank
                // Bank b is the back bank (written) when front is !b, and the front bank (read) when b.
                wire wr_this = wr_en && (front_q != bank[0]);
                wire rd_this = rd_en && (front_pix == bank[0]);
                gpu_ram #(.DEPTH(MAIN_WORDS), .WIDTH(SPAN_W * 8), .LANES(SPAN_W)) u_main (
                    .wr_clk(clk), .rd_clk(clk_pix),
                    .wr_en(wr_this && !wr_in_tail), .wr_addr($clog2(MAIN_WORDS)'(wr_addr)),
                    .wr_data(wr_data), .wr_mask(wr_mask),
                    .rd_en(rd_this && !rd_in_tail), .rd_addr($clog2(MAIN_WORDS)'(rd_word)),
                    .rd_data(main_rd_data[bank])
                );
                if (TAIL_WORDS > 0) begin : g_tail
                    localparam integer TAW = (TAIL_WORDS > 1) ? $clog2(TAIL_WORDS) : 1;
                    gpu_ram #(.DEPTH(TAIL_WORDS), .WIDTH(SPAN_W * 8), .LANES(SPAN_W)) u_tail (
                        .wr_clk(clk), .rd_clk(clk_pix),
                        .wr_en(wr_this && wr_in_tail), .wr_addr(TAW'(wr_addr - WAW'(MAIN_WORDS))),
                        .wr_data(wr_data), .wr_mask(wr_mask),
                        .rd_en(rd_this && rd_in_tail), .rd_addr(TAW'(rd_word - WAW'(MAIN_WORDS))),
                        .rd_data(tail_rd_data[bank])
                    );
                end else begin : g_no_tail
                    assign tail_rd_data[bank] = {(SPAN_W * 8){1'b0}};
                end
            end
            assign word = rd_tail_q ? tail_rd_data[rd_bank_q] : main_rd_data[rd_bank_q];
        end
    endgenerate

    assign front   = front_q;
    assign rd_data = word[rd_lane_q * 8 +: 8];
endmodule

`default_nettype wire
