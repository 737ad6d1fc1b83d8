// gpu_plane_setup.v — one interpolated plane of a triangle (the depth plane, contract "Depth", or
// the intensity plane, "Gouraud intensity": the same formula on VTX_Z or VTX_I), set up beside
// gpu_prim_setup's stages A and B:
//
//   numerators  nA = dv1 dy2 - dv2 dy1, nB = dv2 dx1 - dv1 dx2 (dv: the corners' values less v0's),
//               below 2^33 in magnitude, from stage A's corners and registered on a_load, as the
//               area is (multiplied in the dividers' inputs they held the ECP5 board build's system
//               clock to 43.6 MHz against 50);
//   gradients   A, B = sat32(trunc(2^16 n / area)) by two gpu_div, started in the first clock of
//               stage B that asserts need, valid ceil(31 / DIV_QBITS) + 1 clocks later; `ready`
//               holds stage B until start is registered two clocks after that (at once when the
//               triangle does not need the plane);
//   outputs     start = 2^16 v0 + A off_x + B off_y at lane 0 of the first span; dx, dy = 16 A,
//               16 B, the steps per pixel. Valid while `ready` and stage B holds the triangle.
`default_nettype none

module gpu_plane_setup #(
    parameter integer DIV_QBITS = 2,   // quotient bits per divider clock (gpu_div QBITS)
    parameter integer START_W = gpu_pkg::Z_W,      // the start value's width (Z_W, I_W)
    parameter integer STEP_W = gpu_pkg::ZSTEP_W    // the steps' width (ZSTEP_W, ISTEP_W)
) (
    input  wire                      clk,
    input  wire                      rst,
    // stage A: the corners' values and the area's differences, taken when stage B takes the triangle
    input  wire                      a_load,
    input  wire [15:0]               a_v0,
    input  wire [15:0]               a_v1,
    input  wire [15:0]               a_v2,
    input  wire signed [16:0]        a_d01x,       // x1 - x0, Q12.4
    input  wire signed [16:0]        a_d01y,
    input  wire signed [16:0]        a_d02x,
    input  wire signed [16:0]        a_d02y,
    // stage B: the triangle being held
    input  wire                      b_need,       // it needs this plane (held until b_next)
    input  wire                      b_next,       // stage B is empty or hands its triangle on
    input  wire signed [34:0]        b_area,       // its signed area, the divisor
    input  wire [15:0]               b_v0,         // v0's value
    input  wire signed [17:0]        b_off_x,      // lane 0 of the first span minus v0, Q12.4
    input  wire signed [17:0]        b_off_y,
    output wire                      ready,
    output wire signed [START_W-1:0] start,
    output wire signed [STEP_W-1:0]  dx,
    output wire signed [STEP_W-1:0]  dy
);
    wire signed [16:0] dv1 = 17'({1'b0, a_v1}) - 17'({1'b0, a_v0});
    wire signed [16:0] dv2 = 17'({1'b0, a_v2}) - 17'({1'b0, a_v0});
    wire signed [34:0] num_a_w = dv1 * a_d02y - dv2 * a_d01y;  // operands widen to 35 bits first
    wire signed [34:0] num_b_w = dv2 * a_d01x - dv1 * a_d02x;
    reg signed [34:0] num_a_q, num_b_q;
    always @(posedge clk) begin
        if (a_load) begin
            num_a_q <= num_a_w;
            num_b_q <= num_b_w;
        end
    end

    reg started_q;                     // this triangle's division has been started
    wire div_start = b_need && !started_q;
    wire valid_a, valid_b;             // the quotients are ready (both dividers take the same time)
    wire signed [31:0] grad_a, grad_b;
    gpu_div #(.QBITS(DIV_QBITS)) u_div_a (.clk(clk), .rst(rst), .start(div_start),
        .dividend(51'(num_a_q) <<< 16), .divisor(b_area), .valid(valid_a), .quotient(grad_a));
    gpu_div #(.QBITS(DIV_QBITS)) u_div_b (.clk(clk), .rst(rst), .start(div_start),
        .dividend(51'(num_b_q) <<< 16), .divisor(b_area), .valid(valid_b), .quotient(grad_b));
    always @(posedge clk) begin
        if (rst || b_next) begin
            started_q <= 1'b0;
        end else if (div_start) begin
            started_q <= 1'b1;
        end
    end
    // Timeline in stage B: clock 0 starts both dividers from the registered numerators, the next
    // STEPS clocks develop the quotients; in the clock they are valid the two products are
    // registered, in the next their sum with v0 (start), and in the one after stage C takes start
    // and the steps (the quotients hold until the next start, a clock later at the earliest):
    // STEPS + 4 clocks a triangle that needs the plane. The two registers are the board's: from
    // the quotient's register through its sign, the multipliers and the sum into stage C was one
    // path, 49.3 MHz on the ULX3S 25F against its 50 MHz system clock.
    reg signed [START_W-1:0] prod_a_q, prod_b_q, start_q;
    reg [1:0] stage_q;                 // 0: quotients not valid yet, 1: products held, 2: start held
    always @(posedge clk) begin
        prod_a_q <= START_W'(grad_a) * START_W'(b_off_x);
        prod_b_q <= START_W'(grad_b) * START_W'(b_off_y);
        start_q <= (START_W'($signed({1'b0, b_v0})) <<< 16) + prod_a_q + prod_b_q;
        if (rst || b_next || !started_q || !valid_a) begin
            stage_q <= 2'd0;
        end else if (stage_q != 2'd2) begin
            stage_q <= stage_q + 2'd1;
        end
    end
    assign ready = !b_need || stage_q == 2'd2;
    assign start = start_q;
    assign dx = STEP_W'(grad_a) <<< 4;
    assign dy = STEP_W'(grad_b) <<< 4;
    wire unused_valid_b = valid_b;
endmodule
