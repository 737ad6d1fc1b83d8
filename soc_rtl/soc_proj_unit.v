// soc_proj_unit: the firmware's per-vertex model-view transform and perspective projection in
// hardware, on the core's custom-function port (VexRiscv_FullCfu's CfuPlugin bus). Issue #27: the
// knot's projection took 82 instructions a vertex on the core (about 97 clocks by profile-fw's
// hazard estimate); here a vertex takes five custom instructions and the unit's 21 clocks, during
// which the core stores the last vertex's words and loads the next one's.
//
// Contract (instructions, registers and outcode bits: contract/soc_map.toml [[pu_op]], [[pu_reg]],
// [[pu_out]]; the firmware's side: firmware/render/proj_unit.h):
//   result   bit-exact with the firmware's fixed-point path: xf_apply (math/vec.h: each of the nine
//            products floor(m * 4v / 2^32) on its own, summed with the translation in 32 bits),
//            then proj_point_impl (render/proj.h) with one Newton step of fx_recip_mantissa
//            (math/fixed.h) from a seed table computed here from its defining formula, the
//            sub-pixel drop, the guard band, the outcodes and the depths. The RTL shares no code
//            with the firmware; tests/rtl/proj_unit_tb.cpp checks it against the firmware's C.
//   handshake every command is answered exactly once, in order (rsp_valid until rsp_ready), one
//            at a time: cmd_ready is high when no answer waits and no command is held. XY acts
//            at once (into next_x, next_y), also while a vertex is in progress; any other command
//            acts at once when the unit is idle, else is held until the vertex is done (21 clocks
//            after its Z). A command answers the clock after it acts: Z starts the vertex (its
//            XY's x and y) and answers 0, SXY, ZD and CODE answer the last vertex's words. An
//            unknown function (funct7 not 0, funct3 not an op) answers 0 and changes nothing.
//   range    the firmware's: |model coordinates| < 8192, |view x, y| < 4096 units, |translation|
//            < 4096, z >= the near plane for a vertex given as inside the frustum (proj.h,
//            vec.h). Outside it the unit computes what the firmware's int32 arithmetic does
//            (two's-complement wrap).
//
// Datapath: one 33 x 33 signed multiplier (operands registered, the product registered: a result
// two clocks after its operands), shared by the 14 products of a vertex on a fixed schedule (the
// step counter below, 21 steps: the last five round and shift the offsets, place them on the
// screen and form the outcodes, no adder or compare chained to another in a clock); the seed table is one 1024 x 16 ROM.
`default_nettype none

module soc_proj_unit (
    input  wire        clk,
    input  wire        rst,                 // synchronous, active high: idle, no answer pending
    // ---- command: from the core's execute stage
    input  wire        cmd_valid,
    output wire        cmd_ready,
    input  wire [9:0]  cmd_function_id,     // {funct7, funct3}
    input  wire [31:0] cmd_in0,             // rs1
    input  wire [31:0] cmd_in1,             // rs2
    // ---- answer: to the core's memory stage
    output reg         rsp_valid,
    input  wire        rsp_ready,
    output reg  [31:0] rsp_out              // rd
);
    localparam signed [31:0] PIX_FIRST_Q4 = 32'sd8;  // the first pixel centre, Q12.4 (the GPU contract)

    // ---- configuration (SET) ----
    // the transform at SET's indices (rotation M00 .. M22 q2_30 row-major, then TX .. TZ q16_16):
    // distributed RAM, read by the schedule
    reg        [31:0] xf [0:15];
    reg        [31:0] focal_hi;
    reg        [5:0]  off_shift;            // k + 2
    reg        [5:0]  subpix_drop;          // 4 - FW_SUBPIXEL_BITS
    reg        [15:0] cx, cy, x_last, y_last;
    reg signed [31:0] near_z, far_z;
    reg        [15:0] guard;
    reg        [14:0] depth_max;
    reg               zbuf_on;

    // ---- the vertex ----
    reg signed [31:0] next_x, next_y;       // XY's: the next vertex's, q16_16 (taken while busy)
    reg signed [31:0] vx, vy, vz;           // the vertex in progress, model space
    reg               in_frustum;           // Z's mode: the firmware's proj_point_inside
    reg signed [31:0] view_x, view_y, view_z;  // view space, q16_16 (xf_apply)
    reg        [31:0] view_acc;             // the sum being formed
    reg        [4:0]  lead;                 // leading zeros of view_z: fx_normalize32's s
    reg        [31:0] mant;                 // view_z << lead
    reg        [31:0] y0;                   // the seed, Q1.31
    reg        [31:0] recip;                // fx_recip_mantissa: ~2^63 / mant
    reg        [31:0] zratio;               // near / z in 0.16: recip >> (33 - lead)
    reg signed [31:0] q_r;                  // Q = mulhu(recip, focal_hi): f / z, for the y offset
    reg        [5:0]  shift;                // off_shift + drop - lead: 3 .. 24
    reg signed [31:0] off_x, off_y;
    reg        [31:0] sxy_r, zd_r;
    reg        [7:0]  code_r;

    reg               busy;
    reg        [4:0]  step;

    // the transform's registers: M00 .. M22 then TX .. TZ, in xf at their SET indices (below 16)
    localparam [3:0] XF_M = soc_pkg::SOC_PU_REG_M00[3:0];
    localparam [3:0] XF_T = soc_pkg::SOC_PU_REG_TX[3:0];
    localparam [4:0] XF_LAST = soc_pkg::SOC_PU_REG_TX + 5'd2;

    // ---- the multiplier: floor(a b / 2^32) of 32-bit operands, signed (mulh) or unsigned (mulhu)
    reg signed [32:0] mul_a, mul_b;
    wire signed [65:0] mul_p = mul_a * mul_b;   // bits 31:0 and 65:64 unused (lint.vlt)
    reg        [31:0] hi;
    always @(posedge clk) hi <= mul_p[63:32];

    function automatic [32:0] sgn(input [31:0] v);
        sgn = {v[31], v};
    endfunction
    function automatic [32:0] uns(input [31:0] v);
        uns = {1'b0, v};
    endfunction

    // ---- the seed table: min(65535, round(32768 / (0.5 + (i + 0.5) / 2048))) = round(2^27 / b),
    // b = 2049 + 2 i, formed as floor((2^28 + b) / 2b)
    reg [15:0] seed_rom [0:1023];
    reg [15:0] seed_q;
    integer i;
    reg [63:0] seed_i;
    initial begin
        for (i = 0; i < 1024; i = i + 1) begin
            seed_i = ((64'd1 << 28) + 64'd2049 + 64'd2 * i) / (64'd4098 + 64'd4 * i);
            seed_rom[i] = (seed_i > 64'd65535) ? 16'hFFFF : seed_i[15:0];
        end
    end
    always @(posedge clk) seed_q <= seed_rom[mant[30:21]];

    // ---- leading zeros of view_z (a vertex nearer than 2^-16 units has no use for more than 31)
    function automatic [4:0] clz32(input [31:0] v);
        integer b;
        clz32 = 5'd31;
        for (b = 0; b < 31; b = b + 1)
            if (v[b]) clz32 = ~b[4:0];          // 31 - b
    endfunction

    // ---- rounding the offsets: ((p + 2^(sh-1)) >> sh) << drop, arithmetic
    // one shifter for both: step 13 the depth buffer's near / z (logical), steps 17 and 18 the offsets
    reg  signed [31:0] half;                                  // 2^(shift - 1): rounds to nearest
    reg         [31:0] rounding;                              // an offset's product + half
    wire        [5:0]  zsh = 6'd33 - {1'b0, lead};            // near / z = recip 2^(s - 33)
    wire               sh_offsets = step[4];                  // steps 16 and after
    wire        [31:0] sh_in = sh_offsets ? rounding : recip;
    wire        [5:0]  sh_amt = sh_offsets ? shift : zsh;
    wire        [31:0] sh_fill = {32{sh_offsets && sh_in[31]}};      // arithmetic for the offsets
    wire        [63:0] sh_wide = {sh_fill, sh_in} >> sh_amt;
    wire        [31:0] shifted = sh_wide[31:0];
    wire signed [31:0] offset = $signed(shifted) <<< subpix_drop;

    // ---- the transform's sums: each row's first product with its translation, then the others
    wire        [3:0]  xf_term_at = XF_M + ((step == 5'd9) ? 4'd5 :          // the nine products:
                                             (step <= 5'd2) ? 4'd6 + step[3:0] :  // z row, x, y
                                             step[3:0] - 4'd3);
    wire        [31:0] xf_term = xf[xf_term_at];
    wire        [31:0] model_term = (step == 5'd0 || step == 5'd3 || step == 5'd6) ? vx :
                                    (step == 5'd1 || step == 5'd4 || step == 5'd7) ? vy : vz;
    wire               sum_first = step == 5'd2 || step == 5'd5 || step == 5'd8;
    wire        [3:0]  xf_t_at = XF_T + ((step == 5'd2) ? 4'd2 : (step == 5'd5) ? 4'd0 : 4'd1);  // TZ, TX, TY
    wire        [31:0] xf_t = xf[xf_t_at];
    wire        [31:0] view_sum = (sum_first ? xf_t : view_acc) + hi;



    // ---- the answer words from the offsets: step 18 the x offset (off_x) clamped to the guard
    // band and placed on the screen, step 19 the y offset, step 20 the outcodes from those registers
    wire               y_turn = step == 5'd19;
    wire signed [31:0] off_now = y_turn ? off_y : off_x;
    wire signed [31:0] g = {16'd0, guard};
    wire               out_band = off_now > g || off_now < -g;
    wire signed [31:0] clamped = in_frustum ? off_now : (off_now > g ? g : (off_now < -g ? -g : off_now));
    wire signed [31:0] screen = y_turn ? $signed({16'd0, cy}) - clamped : $signed({16'd0, cx}) + clamped;
    reg  signed [31:0] sx, sy;
    reg                out_guard;
    // one unsigned range check an axis, as the firmware's
    wire [31:0] col_from_first = sx - PIX_FIRST_Q4;
    wire [31:0] row_from_first = sy - PIX_FIRST_Q4;
    wire        off_cols = col_from_first > {16'd0, x_last} - 32'd8;
    wire        off_rows = row_from_first > {16'd0, y_last} - 32'd8;
    reg  [7:0]  code;
    always @(*) begin
        code = 8'd0;
        if (!in_frustum) begin
            code[soc_pkg::SOC_PU_OUT_GUARD] = out_guard;
            code[soc_pkg::SOC_PU_OUT_LEFT] = off_cols && sx < PIX_FIRST_Q4;
            code[soc_pkg::SOC_PU_OUT_RIGHT] = off_cols && !(sx < PIX_FIRST_Q4);
            code[soc_pkg::SOC_PU_OUT_TOP] = off_rows && sy < PIX_FIRST_Q4;
            code[soc_pkg::SOC_PU_OUT_BOTTOM] = off_rows && !(sy < PIX_FIRST_Q4);
            code[soc_pkg::SOC_PU_OUT_FAR] = view_z > far_z;
        end
    end
    wire [15:0] zbuf = !zbuf_on ? 16'd0 : ((zratio >= 32'd65535) ? 16'd0 : 16'hFFFF - zratio[15:0]);
    wire [31:0] depth_raw = view_z >> 9;                      // q16_16 to 1/128 units, unsigned
    wire [15:0] depth = (depth_raw > {17'd0, depth_max}) ? {1'b0, depth_max} : depth_raw[15:0];

    wire near_cut = !in_frustum && view_z < near_z;

    // ---- commands: taken at once when the unit can act on them (XY always; the others when it is
    // idle), else held until the vertex in progress is done
    reg        held;
    reg [9:0]  held_id;
    reg [31:0] held_in0, held_in1;
    assign cmd_ready = !held && !rsp_valid;
    wire       take = cmd_valid && cmd_ready;
    wire [9:0] op_id  = held ? held_id : cmd_function_id;
    wire [31:0] op_in0 = held ? held_in0 : cmd_in0;
    wire [31:0] op_in1 = held ? held_in1 : cmd_in1;
    wire [2:0] funct3 = op_id[2:0];
    wire       known = op_id[9:3] == 7'd0;
    wire       op_xy = known && funct3 == soc_pkg::SOC_PU_OP_XY;
    wire       act = (held || take) && (op_xy || !busy);     // the command acts in this clock

    always @(posedge clk)   // SET of a transform register (no reset: distributed RAM)
        if (act && known && funct3 == soc_pkg::SOC_PU_OP_SET && op_in1[4:0] <= XF_LAST)
            xf[op_in1[3:0]] <= op_in0;

    always @(posedge clk) begin
        if (rst) begin
            busy <= 1'b0;
            held <= 1'b0;
            rsp_valid <= 1'b0;
        end else begin
            if (rsp_valid && rsp_ready) rsp_valid <= 1'b0;
            if (take && !act) begin
                held <= 1'b1;
                held_id <= cmd_function_id;
                held_in0 <= cmd_in0;
                held_in1 <= cmd_in1;
            end
            if (act) begin
                held <= 1'b0;
                rsp_valid <= 1'b1;
                rsp_out <= !known                              ? 32'd0 :
                           (funct3 == soc_pkg::SOC_PU_OP_SXY)  ? sxy_r :
                           (funct3 == soc_pkg::SOC_PU_OP_ZD)   ? zd_r :
                           (funct3 == soc_pkg::SOC_PU_OP_CODE) ? {24'd0, code_r} : 32'd0;
                if (op_xy) begin
                    next_x <= op_in0;
                    next_y <= op_in1;
                end
                if (known && funct3 == soc_pkg::SOC_PU_OP_Z) begin
                    busy <= 1'b1;
                    step <= 5'd0;
                    vx <= next_x;
                    vy <= next_y;
                    vz <= op_in0;
                    in_frustum <= op_in1[0];
                end
                if (known && funct3 == soc_pkg::SOC_PU_OP_SET) begin
                    case (op_in1[4:0])
                        soc_pkg::SOC_PU_REG_FOCAL_HI:  focal_hi <= op_in0;
                        soc_pkg::SOC_PU_REG_OFF_SHIFT: begin off_shift <= op_in0[5:0]; subpix_drop <= op_in0[13:8]; end
                        soc_pkg::SOC_PU_REG_CENTRE:    {cy, cx} <= op_in0;
                        soc_pkg::SOC_PU_REG_LAST:      {y_last, x_last} <= op_in0;
                        soc_pkg::SOC_PU_REG_NEAR:      near_z <= op_in0;
                        soc_pkg::SOC_PU_REG_FAR:       far_z <= op_in0;
                        soc_pkg::SOC_PU_REG_LIMITS:    {zbuf_on, depth_max, guard} <= op_in0;
                        default: ;
                    endcase
                end
            end
            if (busy) begin
                step <= step + 5'd1;
                // The schedule: a product issued at step s is `hi` at step s + 2; the sums of the
                // view's z (steps 2-4), x (5-7) and y (8, 9, 11) in `view_sum`.
                if (step == 5'd4) view_z <= view_sum;
                if (step == 5'd7) view_x <= view_sum;
                if (step == 5'd11) view_y <= view_sum;
                if (step <= 5'd9 || step == 5'd11) view_acc <= view_sum;
                if (step <= 5'd7 || step == 5'd9) begin   // the nine products of the transform
                    mul_a <= sgn(xf_term);
                    mul_b <= sgn(model_term << 2);
                end
                case (step)
                    5'd5:  begin
                        lead <= clz32(view_z);
                        if (near_cut) begin         // not projected: the firmware's NEAR vertex
                            busy <= 1'b0;
                            sxy_r <= 32'd0;
                            zd_r <= 32'd0;
                            code_r <= 8'd0;
                            code_r[soc_pkg::SOC_PU_OUT_NEAR] <= 1'b1;
                        end
                    end
                    5'd6:  begin
                        mant <= view_z << lead;
                        shift <= off_shift + subpix_drop - {1'b0, lead};
                    end
                    5'd7:  half <= 32'sd1 <<< (shift - 6'd1);
                    5'd8:  begin mul_a <= uns(mant); mul_b <= uns({seed_q, 16'd0}); y0 <= {seed_q, 16'd0}; end
                    5'd10: begin mul_a <= uns(y0); mul_b <= uns(32'd0 - hi); end          // y (2 - mu y)
                    5'd12: begin mul_a <= uns({hi[30:0], 1'b0}); mul_b <= uns(focal_hi); recip <= {hi[30:0], 1'b0}; end
                    5'd13: zratio <= shifted;
                    5'd14: begin mul_a <= sgn(view_x << 3); mul_b <= sgn(hi); q_r <= hi; end
                    5'd15: begin mul_a <= sgn(view_y << 3); mul_b <= sgn(q_r); end
                    5'd16: rounding <= hi + half;                           // x's product
                    5'd17: begin off_x <= offset; rounding <= hi + half; end  // y's product
                    5'd18: begin off_y <= offset; sx <= screen; out_guard <= out_band; end
                    5'd19: begin sy <= screen; out_guard <= out_guard || out_band; end
                    5'd20: begin
                        busy <= 1'b0;
                        sxy_r <= {sy[15:0], sx[15:0]};
                        zd_r <= {depth, zbuf};
                        code_r <= code;
                    end
                    default: ;
                endcase
            end
        end
    end
endmodule

`default_nettype wire
