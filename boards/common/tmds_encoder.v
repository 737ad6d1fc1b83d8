// tmds_encoder: one DVI 1.0 TMDS channel encoder (8b/10b transition-minimised, DC-balanced).
//
// Contract: clocked by the pixel clock; one symbol per clk_pix. At every clock edge the inputs of
// that edge are encoded and `symbol` holds the result until the next edge (latency: one clk_pix,
// the output register). `symbol` is the 10-bit word as the DVI 1.0 spec numbers it: bit 0 is the
// first bit on the wire. rst_pix is synchronous, active high; it clears the running disparity and
// outputs the ctrl=00 control token.
//
// de = 1: data period, `data` is encoded by the DVI 1.0 algorithm (section 3.2.2):
//   stage 1, transition minimisation: q_m[0] = D[0], q_m[i] = q_m[i-1] XNOR D[i] when the byte has
//     more than four ones (or exactly four and D[0] = 0), else XOR; q_m[8] = 1 for XOR, 0 for XNOR.
//   stage 2, DC balance against the running disparity cnt (ones minus zeros sent so far in this
//     data period): bits 7:0 are sent inverted (and bit 9 set) when that moves cnt towards 0.
// de = 0: control period, `ctrl` selects a token and cnt is reset to 0:
//   ctrl 00 -> 1101010100, 01 -> 0010101011, 10 -> 0101010100, 11 -> 1010101011.
`default_nettype none

module tmds_encoder (
    // pixel clock domain
    input  wire       clk_pix,
    input  wire       rst_pix,
    // video in: data enable, control bits (c1, c0), pixel byte
    input  wire       de,
    input  wire [1:0] ctrl,
    input  wire [7:0] data,
    // encoded symbol, registered, bit 0 first on the wire
    output reg  [9:0] symbol
);
    // Count of ones in a byte, 0..8, as an adder tree.
    function [3:0] ones8(input [7:0] v);
        reg [1:0] p0, p1, p2, p3;
        reg [2:0] s0, s1;
        begin
            p0 = {1'b0, v[0]} + {1'b0, v[1]};
            p1 = {1'b0, v[2]} + {1'b0, v[3]};
            p2 = {1'b0, v[4]} + {1'b0, v[5]};
            p3 = {1'b0, v[6]} + {1'b0, v[7]};
            s0 = {1'b0, p0} + {1'b0, p1};
            s1 = {1'b0, p2} + {1'b0, p3};
            ones8 = {1'b0, s0} + {1'b0, s1};
        end
    endfunction

    // Stage 1: transition minimisation.
    wire [3:0] n1_d = ones8(data);
    wire use_xnor = (n1_d > 4'd4) || ((n1_d == 4'd4) && !data[0]);
    reg  [7:0] q_m;
    always @(*) begin : minimise
        integer i;
        q_m[0] = data[0];
        for (i = 1; i < 8; i = i + 1) begin
            q_m[i] = use_xnor ? ~(q_m[i-1] ^ data[i]) : (q_m[i-1] ^ data[i]);
        end
    end
    wire q_m8 = ~use_xnor;  // 1: XOR was used

    // Stage 2: DC balance.
    // cnt is the running disparity (ones minus zeros) of the 10-bit data symbols sent since the last
    // control period. Range: -8..+8, always even. Argument: q_m[7:0] has disparity
    // d = N1 - N0 in -8..+8 (even). From cnt = 0 (or d = 0) the update is cnt +- d, in -8..+8. For
    // cnt > 0 (2..8): if d > 0 the word is inverted, cnt' = cnt + 2*q_m[8] - d <= 8 + 2 - 2 = 8 and
    // >= 2 + 0 - 8 = -6; if d < 0 it is sent as is, cnt' = cnt - 2*~q_m[8] + d <= 8 - 0 - 2 = 6 and
    // >= 2 - 2 - 8 = -8. cnt < 0 is the mirror image. So |cnt| <= 8 by induction (an exhaustive
    // search over all bytes from every reachable cnt gives exactly {-8,-6,...,+8}). Five signed bits
    // (-16..15) hold it; the updates below are exact in 5-bit two's complement because the true
    // result is always in range.
    reg  signed [4:0] cnt;
    wire [3:0] n1_q = ones8(q_m);
    wire [3:0] n0_q = 4'd8 - n1_q;
    wire signed [4:0] disp_q = $signed({1'b0, n1_q}) - $signed({1'b0, n0_q});  // N1 - N0 of q_m
    wire signed [4:0] two_q_m8 = q_m8 ? 5'sd2 : 5'sd0;                         // 2 * q_m[8]
    wire signed [4:0] two_not_q_m8 = q_m8 ? 5'sd0 : 5'sd2;                     // 2 * ~q_m[8]
    wire cnt_zero = (cnt == 5'sd0);
    wire cnt_pos = !cnt[4] && !cnt_zero;
    wire cnt_neg = cnt[4];

    // One adder: the branch only selects the symbol and the disparity step.
    reg [9:0] sym_d;
    reg signed [4:0] step_d;
    always @(*) begin
        if (cnt_zero || (n1_q == n0_q)) begin
            sym_d = {~q_m8, q_m8, q_m8 ? q_m : ~q_m};
            step_d = q_m8 ? disp_q : -disp_q;
        end else if ((cnt_pos && (n1_q > n0_q)) || (cnt_neg && (n0_q > n1_q))) begin
            sym_d = {1'b1, q_m8, ~q_m};
            step_d = two_q_m8 - disp_q;
        end else begin
            sym_d = {1'b0, q_m8, q_m};
            step_d = disp_q - two_not_q_m8;
        end
    end
    reg [9:0] token;
    always @(*) begin
        case (ctrl)
            2'b00:   token = 10'b1101010100;
            2'b01:   token = 10'b0010101011;
            2'b10:   token = 10'b0101010100;
            default: token = 10'b1010101011;
        endcase
    end

    always @(posedge clk_pix) begin
        if (rst_pix) begin
            cnt <= 5'sd0;
            symbol <= 10'b1101010100;
        end else begin
            cnt <= de ? (cnt + step_d) : 5'sd0;
            symbol <= de ? sym_d : token;
        end
    end
`ifdef FORMAL
    // ---- formal (tests/formal/dvi_tx.sby): the range argument above, once a reset has been seen ----
    reg f_reset_seen = 1'b0;
    always @(posedge clk_pix) if (rst_pix) f_reset_seen <= 1'b1;
    always @(*) if (f_reset_seen) assert(!cnt[0] && cnt >= -5'sd8 && cnt <= 5'sd8);
`endif
endmodule

`default_nettype wire
