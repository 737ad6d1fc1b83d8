// gpu_div: sequential signed division for the depth-plane gradients, saturated to 32 bits.
//
// Contract: start (one-cycle pulse, while not busy) takes dividend and divisor (divisor != 0);
// done pulses 32 clocks after the start clock, with quotient = sat32(trunc(dividend / divisor)), trunc rounding toward
// zero and sat32 clamping to -2^31 .. 2^31-1, exactly as docs/gpu-contract.md ("Depth") defines ZA
// and ZB. Radix-2 restoring division of the magnitudes, one quotient bit per clock; a quotient whose
// magnitude reaches 2^31 is recognised up front (|n| >= 2^31 |d|) and saturated.
`default_nettype none

module gpu_div #(
    parameter integer N_W = 51,  // dividend bits, signed
    parameter integer D_W = 35   // divisor bits, signed
) (
    input  wire                  clk,
    input  wire                  rst,
    input  wire                  start,
    input  wire signed [N_W-1:0] dividend,
    input  wire signed [D_W-1:0] divisor,
    output wire                  busy,
    output reg                   done,
    output reg  signed [31:0]    quotient
);
    localparam integer R_W = D_W + 32;  // room for the divisor shifted by up to 30 (and the dividend)
    reg [5:0] step_q;                  // quotient bit being decided, 31 .. 0; 63 = idle
    reg [R_W-1:0] rem_q;               // |dividend| minus what has been taken out
    reg [R_W-1:0] div_q;               // |divisor|
    reg [30:0] quo_q;
    reg negative_q, saturate_q;

    wire [N_W-1:0] n_mag = dividend[N_W-1] ? N_W'(-dividend) : N_W'(dividend);
    wire [D_W-1:0] d_mag = divisor[D_W-1] ? D_W'(-divisor) : D_W'(divisor);
    wire [R_W-1:0] shifted = div_q << step_q[4:0];
    wire take = step_q < 6'd31 && rem_q >= shifted;

    assign busy = step_q != 6'd63;

    always @(posedge clk) begin
        done <= 1'b0;
        if (rst) begin
            step_q <= 6'd63;
        end else if (start && !busy) begin
            rem_q <= R_W'(n_mag);
            div_q <= R_W'(d_mag);
            quo_q <= 31'd0;
            negative_q <= dividend[N_W-1] ^ divisor[D_W-1];
            // |q| >= 2^31 exactly when |n| >= 2^31 * |d|.
            saturate_q <= (R_W + 31)'(n_mag) >= ((R_W + 31)'(d_mag) << 31);
            step_q <= 6'd30;
        end else if (busy) begin
            if (take) begin
                rem_q <= rem_q - shifted;
                quo_q[step_q[4:0]] <= 1'b1;
            end
            if (step_q == 6'd0) begin
                step_q <= 6'd63;
                done <= 1'b1;
            end else begin
                step_q <= step_q - 6'd1;
            end
        end
    end

    // The quotient is read in the clock done is high, from the final quo_q.
    always @(*) begin
        if (saturate_q) begin
            quotient = negative_q ? 32'sh8000_0000 : 32'sh7FFF_FFFF;
        end else begin
            quotient = negative_q ? -$signed({1'b0, quo_q}) : $signed({1'b0, quo_q});
        end
    end
endmodule

`default_nettype wire
