// gpu_div: sequential signed division for the depth-plane gradients, saturated to 32 bits.
//
// Contract: start (one-cycle pulse, at any time; a division in progress is abandoned) takes dividend
// and divisor (divisor != 0). valid rises STEPS + 1 clocks after the start clock and stays high, with
// quotient = sat32(trunc(dividend / divisor)), until the next start; trunc rounds toward zero and
// sat32 clamps to -2^31 .. 2^31-1, exactly as contract/gpu-contract.md ("Depth") defines ZA and ZB.
// Throughput: one division per STEPS + 1 clocks (STEPS = ceil(31 / QBITS); 16 with QBITS = 2).
//
// Method: restoring division of the magnitudes, QBITS quotient bits per clock (radix 2^QBITS), in the
// remainder-shift form: the partial remainder r < |d| is shifted left by QBITS with the next dividend
// bits, and the digit is the number of multiples m|d| (m = 1 .. 2^QBITS - 1, formed once at start)
// that do not exceed it — 2^QBITS - 1 subtractors as wide as the divisor, no wide shifter.
// Saturation is recognised up front: |q| >= 2^31 exactly when floor(|n| / 2^31) >= |d|. Otherwise
// |q| < 2^31 <= 2^(STEPS * QBITS), so the remainder left above the low STEPS * QBITS dividend bits,
// |n| >> (STEPS * QBITS), is already below |d|: the invariant r < |d| holds from the first step on and
// every digit fits QBITS bits.
`default_nettype none

module gpu_div #(
    parameter integer N_W = 51,    // dividend bits, signed
    parameter integer D_W = 35,    // divisor bits, signed
    parameter integer QBITS = 2,   // quotient bits per clock: 2^QBITS - 1 subtractors of D_W + QBITS
                                   // bits; 2 gives 16 steps (17 clocks a division), 1 gives 31 (32)
    localparam integer STEPS = (31 + QBITS - 1) / QBITS,
    localparam integer Q_W = STEPS * QBITS,      // quotient bits developed (>= 31)
    localparam integer R_W = D_W + QBITS,        // a shifted remainder: below 2^QBITS |d| <= 2^(R_W-1)
    localparam integer M = (1 << QBITS) - 1,     // multiples of |d| compared per step
    localparam integer C_W = $clog2(STEPS + 1),
    localparam integer S_W = (N_W > D_W) ? N_W : D_W  // the saturation compare
) (
    input  wire                  clk,
    input  wire                  rst,
    input  wire                  start,
    input  wire signed [N_W-1:0] dividend,
    input  wire signed [D_W-1:0] divisor,
    output reg                   valid,
    output reg  signed [31:0]    quotient
);
    reg [C_W-1:0] steps_q;             // steps still to go; 0 = idle
    reg [D_W-1:0] rem_q;               // partial remainder, below |d|
    reg [Q_W-1:0] low_q;               // dividend bits not yet shifted in, next ones on top
    reg [R_W-1:0] mult_q [1:M];        // m |d|
    reg [30:0] quo_q;                  // the digits so far (those above bit 30 are 0, or saturate)
    reg negative_q, saturate_q;

    // m |d| by shifts and adds (m is an elaboration-time constant): no multiplier for a constant.
    function automatic [R_W-1:0] times(input [D_W-1:0] v, input integer n);
        integer b;
        begin
            times = {R_W{1'b0}};
            for (b = 0; b < QBITS; b = b + 1) begin
                if (((n >> b) & 1) != 0) begin
                    times = times + (R_W'(v) << b);
                end
            end
        end
    endfunction

    wire [N_W-1:0] n_mag = dividend[N_W-1] ? N_W'(-dividend) : N_W'(dividend);
    wire [D_W-1:0] d_mag = divisor[D_W-1] ? D_W'(-divisor) : D_W'(divisor);

    // One step: r' = r * 2^QBITS + next bits; digit = #{m : m |d| <= r'}; r = r' - digit |d|.
    wire [R_W-1:0] shifted = {rem_q, low_q[Q_W-1 -: QBITS]};
    reg [QBITS-1:0] digit;
    reg [D_W-1:0] rem_next;            // below |d| again
    reg [R_W:0] diff;
    integer m;
    always @(*) begin
        digit = {QBITS{1'b0}};
        rem_next = D_W'(shifted);
        for (m = 1; m <= M; m = m + 1) begin
            diff = {1'b0, shifted} - {1'b0, mult_q[m]};
            if (!diff[R_W]) begin      // no borrow: m |d| <= r' (the multiples grow with m)
                digit = QBITS'(m);
                rem_next = D_W'(diff);
            end
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            steps_q <= {C_W{1'b0}};
            valid <= 1'b0;
        end else if (start) begin
            rem_q <= D_W'(n_mag >> Q_W);
            low_q <= Q_W'(n_mag);
            for (m = 1; m <= M; m = m + 1) begin
                mult_q[m] <= times(d_mag, m);
            end
            quo_q <= 31'd0;
            negative_q <= dividend[N_W-1] ^ divisor[D_W-1];
            saturate_q <= S_W'(n_mag >> 31) >= S_W'(d_mag);
            steps_q <= C_W'(STEPS);
            valid <= 1'b0;
        end else if (steps_q != {C_W{1'b0}}) begin
            rem_q <= rem_next;
            low_q <= low_q << QBITS;
            quo_q <= 31'({quo_q, digit});
            steps_q <= steps_q - 1'b1;
            valid <= steps_q == C_W'(1);
        end
    end

    always @(*) begin
        if (saturate_q) begin
            quotient = negative_q ? 32'sh8000_0000 : 32'sh7FFF_FFFF;
        end else begin
            quotient = negative_q ? -$signed({1'b0, quo_q}) : $signed({1'b0, quo_q});
        end
    end
endmodule

`default_nettype wire
