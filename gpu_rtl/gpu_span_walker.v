// gpu_span_walker: the rasterizer's back end — walks each triangle span by span (SPAN_W pixels of a
// row per clock) and each line pixel by pixel, and writes the back framebuffer with a pixel mask.
//
// Contract: takes a descriptor from gpu_prim_setup when in_ready is high (while idle). Triangles:
// every pixel whose centre passes all three edge tests (E > 0, or E = 0 on a top-left edge) is written
// with the colour, exactly once, nothing else is. Lines: the contract's Bresenham steps, on-screen
// plots only. Writes leave on fb_wr_* one clock after the span is evaluated, two with ENABLE_ZBUF
// (the depth test's two stages, below).
//
// Traversal (why it is fast and still exact): a row of a triangle is one interval of pixels. Edges
// whose value grows to the right (step > 0) bound it on the left, those that shrink bound it on the
// right, flat ones pass or fail the whole row. From the column where the previous row started, the
// walker moves right over spans that fail a left-bounding edge in every pixel, moves left while the
// pixel just left of the span passes every left-bounding edge, and then scans right, writing, until
// the first pixel of the next span fails a right-bounding edge. Each test is monotonic along the row,
// so no covered pixel is skipped, no span is written twice, and a triangle costs about one clock per
// covered span plus one per row and per span the boundary moves. Bounding-box limits (col_lo..col_hi,
// row_lo..row_hi) stop the walk at the screen edge.
//
// Widths: the descriptor is a gpu_pkg::desc_t. Edge values at lanes -1 .. SPAN_W of any on-screen
// span are values at pixel centres within one pixel of the screen, inside the EDGE_NEED_W-bit bound
// argued in gpu_pkg.sv; EDGE_W = 36. The depth accumulator's bound (Z_W) is argued there too, and
// the intensity accumulator's (I_W), which is the same.
//
// Gouraud triangles (ENABLE_GOURAUD, desc.shaded): the Q16 intensity plane is stepped exactly as the
// depth plane is (the same adds, at the same places), each lane's value clamped to 0 .. 65535 (Q4.12)
// and its top byte kept with the span. In the write stage each lane's colour is the triangle's
// PRIM_COLOR plus its level: the intensity's bits 15..12, plus one where dithering is on and the
// fraction bits 11..8 exceed the 4x4 Bayer threshold of the pixel (x & 3, y & 3), at most 15
// (contract, "Gouraud intensity"). Flat triangles and lines keep their colour as it is.
`default_nettype none

module gpu_span_walker #(
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,               // the frame
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,           // build options: see gpu_top
    parameter integer ENABLE_ZBUF = gpu_pkg::GPU_DEFAULT_ENABLE_ZBUF, // depth test stage and depth-
                                                                      // buffer port
    parameter integer ZBUF_BITS = gpu_pkg::GPU_DEFAULT_ZBUF_BITS,     // depth bits kept (contract
                                                                      // "Depth"): the rest read 0
    parameter integer ENABLE_GOURAUD = gpu_pkg::GPU_DEFAULT_ENABLE_GOURAUD,  // intensity stepping and
                                                                      // the ramp/dither write stage
    localparam integer WORDS_PER_ROW = FB_WIDTH / SPAN_W,
    localparam integer COL_W = $clog2(WORDS_PER_ROW),                 // span column
    localparam integer WAW = $clog2(FB_WIDTH * FB_HEIGHT / SPAN_W),
    localparam integer LANE_AW = (SPAN_W > 1) ? $clog2(SPAN_W) : 1,
    localparam integer CNT_W = $clog2(SPAN_W + 1),
    localparam integer EDGE_W = gpu_pkg::EDGE_W,
    localparam integer STEP_W = gpu_pkg::STEP_W,                      // edge steps, sign-extended
    localparam integer Z_W = gpu_pkg::Z_W,
    localparam integer ZSTEP_W = gpu_pkg::ZSTEP_W,
    localparam integer I_W = gpu_pkg::I_W,
    localparam integer ISTEP_W = gpu_pkg::ISTEP_W,
    localparam integer ILVL_W = gpu_pkg::ILVL_W,
    localparam integer PIX_W = gpu_pkg::PIX_W,                        // line pixel coordinates
    localparam integer LERR_W = gpu_pkg::LERR_W,
    localparam integer ROW_W = gpu_pkg::ROW_W,
    localparam integer X_W = gpu_pkg::X_W                             // a pixel x on screen
) (
    input  wire                     clk,
    input  wire                     rst,
    // descriptor (see gpu_prim_setup)
    input  wire                     in_valid,
    output wire                     in_ready,
    input  gpu_pkg::desc_t          in_desc,      // the primitive; columns in its low COL_W bits
    input  wire                     ztest,        // CTRL.ZTEST of the batch
    input  wire                     dither,       // CTRL.DITHER of the batch (Gouraud triangles)
    input  wire [gpu_pkg::ROW_W-1:0] row_first,   // the batch's STRIP rows, the last within the
    input  wire [gpu_pkg::ROW_W-1:0] row_last,    // frame; rows_empty: none (lines plot nothing,
    input  wire                     rows_empty,   // the set-up rejects every triangle)
    // depth buffer (ENABLE_ZBUF): read the span's depths, write the winners'
    output wire                     z_rd_en,
    output wire [WAW-1:0]           z_rd_addr,
    input  wire [SPAN_W*16-1:0]     z_rd_data,
    input  wire                     z_rd_cleared, // with z_rd_data: the span's depths are cleared
                                                  // by epoch, not written (it reads as cleared)
    output wire                     z_wr_en,
    output wire [WAW-1:0]           z_wr_addr,
    output wire [SPAN_W*16-1:0]     z_wr_data,
    output wire [SPAN_W-1:0]        z_wr_mask,
    // framebuffer write port (back bank)
    output wire                     fb_wr_en,
    output wire [WAW-1:0]           fb_wr_addr,
    output wire [SPAN_W*8-1:0]      fb_wr_data,
    output wire [SPAN_W-1:0]        fb_wr_mask,
    // status and events
    output wire                     idle,
    output reg                      ev_span_visit,
    output reg                      ev_span_written,
    output wire [CNT_W-1:0]         ev_pixels
);
    localparam [1:0] S_IDLE = 2'd0, S_SEEK = 2'd1, S_SCAN = 2'd2, S_LINE = 2'd3;
    reg [1:0] state_q;

    reg [gpu_pkg::COLOR_W-1:0] color_q;
    // Edge values biased by the top-left rule: E at a non-top-left edge, E - 1 at the others (set
    // with the triangle, below), so that a pixel passes an edge exactly where its biased value is
    // >= 0 — one sign bit, where E > 0 || (top-left && E == 0) took a 36-bit zero test beside the
    // sign on the seek's path. The bias is an integer, the steps too: every lane's and row's value
    // keeps it exactly, and the range argument's two bits of margin hold the one unit.
    reg signed [EDGE_W-1:0] e_q [0:2];       // edges at lane 0 of the current span
    reg signed [EDGE_W-1:0] efirst_q [0:2];  // edges at lane 0 of the row's starting span
    reg signed [STEP_W-1:0] sx_q [0:2];      // steps at their exact width (gpu_pkg::STEP_W)
    reg signed [STEP_W-1:0] sy_q [0:2];
    // The lanes that decide the walk, kept as registers stepped beside e_q (the same adds at the
    // same places, so the same values mod 2^EDGE_W): the decision reads sign bits of registers, not
    // of 36-bit adds from e_q (those adds, the decision and its fan-out to every register the walk
    // steps were one loop, the board's longest path). Which lanes an edge needs follows from its
    // step's sign, fixed per triangle: a left-bounding edge (sx > 0) lanes -1 and SPAN_W - 1, a
    // right-bounding one (sx < 0) lane SPAN_W, a flat one lane 0 (e_q itself).
    reg signed [EDGE_W-1:0] pa_q [0:2];      // lane -1 if sx > 0, else lane SPAN_W
    reg signed [EDGE_W-1:0] pb_q [0:2];      // lane SPAN_W - 1
    reg signed [EDGE_W-1:0] pafirst_q [0:2]; // the same at the row's starting span
    reg signed [EDGE_W-1:0] pbfirst_q [0:2];
    reg [2:0] sx_pos_q, sx_neg_q;            // per edge: sx > 0, sx < 0
    reg [COL_W-1:0] col_q, col_first_q, col_lo_q, col_hi_q;
    reg [ROW_W-1:0] row_q, row_hi_q;
    reg [WAW-1:0] row_addr_q;                // word address of (col 0, row_q)

    // ---- lane evaluation: edge k at lane l is e + l * step (l = -1 .. SPAN_W) ----
    function automatic covered(input signed [EDGE_W-1:0] e_biased);
        covered = !e_biased[EDGE_W-1];
    endfunction
    // An edge value as e_q holds it: the top-left rule's bias (above) applied.
    function automatic signed [EDGE_W-1:0] biased(input signed [EDGE_W-1:0] e, input top_left);
        biased = top_left ? e : e - EDGE_W'(1);
    endfunction
    // v * n for an elaboration-time constant n >= 0, as shifts and adds: a generic multiplier here
    // would cost an FPGA a DSP (or, on an iCE40, hundreds of LUTs) per lane for nothing. Computed at the
    // depth accumulator's width (the widest operand); edge callers keep the low EDGE_W bits, which
    // hold the exact value by the range argument.
    function automatic signed [Z_W-1:0] times(input signed [Z_W-1:0] v, input integer n);
        integer b;
        begin
            times = {Z_W{1'b0}};
            for (b = 0; b < 8; b = b + 1) begin
                if (((n >> b) & 1) != 0) begin
                    times = times + (v <<< b);
                end
            end
        end
    endfunction
    function automatic signed [EDGE_W-1:0] edge_times(input signed [EDGE_W-1:0] v, input integer n);
        edge_times = EDGE_W'(times(Z_W'(v), n));
    endfunction

    reg [SPAN_W-1:0] lane_cov;              // pixels of this span inside the triangle
    reg [2:0] pass_left, pass_last, pass_next, pass_first;  // per edge: at lane -1, SPAN_W-1, SPAN_W, 0
    // Edge k at lane l (0 .. SPAN_W - 1) in lane_e[(k * SPAN_W + l) * EDGE_W +: EDGE_W]: lane l
    // is lane (l with its lowest set bit cleared) plus that bit times the step, one two-operand add
    // each (the same sums, mod 2^EDGE_W, as e + l * step), so yosys builds each as one carry chain.
    reg [3*SPAN_W*EDGE_W-1:0] lane_e;
    integer k, l;
    always @(*) begin
        lane_cov = {SPAN_W{1'b1}};
        for (k = 0; k < 3; k = k + 1) begin
            lane_e[(k * SPAN_W) * EDGE_W +: EDGE_W] = e_q[k];
            for (l = 1; l < SPAN_W; l = l + 1) begin
                lane_e[(k * SPAN_W + l) * EDGE_W +: EDGE_W] =
                    $signed(lane_e[(k * SPAN_W + (l & (l - 1))) * EDGE_W +: EDGE_W])
                    + edge_times(EDGE_W'(sx_q[k]), l - (l & (l - 1)));
            end
            for (l = 0; l < SPAN_W; l = l + 1) begin
                if (!covered(lane_e[(k * SPAN_W + l) * EDGE_W +: EDGE_W])) begin
                    lane_cov[l] = 1'b0;
                end
            end
            pass_left[k]  = covered(pa_q[k]);   // meaningful where sx > 0
            pass_first[k] = covered(e_q[k]);
            pass_last[k]  = covered(pb_q[k]);
            pass_next[k]  = covered(pa_q[k]);   // meaningful where sx < 0
        end
    end

    reg flat_fail, left_rejected, left_possible, right_done;
    always @(*) begin
        flat_fail = 1'b0;
        left_rejected = 1'b0;
        left_possible = col_q > col_lo_q;
        right_done = col_q == col_hi_q;
        for (k = 0; k < 3; k = k + 1) begin
            if (!sx_pos_q[k] && !sx_neg_q[k] && !pass_first[k]) begin
                flat_fail = 1'b1;
            end
            if (sx_pos_q[k]) begin  // bounds the row on the left
                if (!pass_last[k]) left_rejected = 1'b1;
                if (!pass_left[k]) left_possible = 1'b0;
            end
            if (sx_neg_q[k] && !pass_next[k]) begin  // bounds it on the right
                right_done = 1'b1;
            end
        end
    end

    wire seek = state_q == S_SEEK;
    wire scan = state_q == S_SCAN;
    wire row_empty = seek && (flat_fail || (left_rejected && col_q == col_hi_q));
    wire go_left = seek && !flat_fail && !left_rejected && left_possible;
    wire first_span = seek && !flat_fail && !left_rejected && !left_possible;
    wire draw_span = first_span || scan;
    wire row_end = row_empty || (draw_span && right_done);

    // ---- lines ----
    reg signed [PIX_W-1:0] lx_q, ly_q;
    reg [PIX_W-1:0] ln_q;
    reg lxmajor_q, lxneg_q, lyneg_q;
    reg [PIX_W:0] l2maj_q, l2min_q;
    reg signed [LERR_W-1:0] lerr_q;
    localparam signed [PIX_W-1:0] LINE_X_END = PIX_W'(FB_WIDTH);   // first column off screen
    localparam signed [PIX_W-1:0] PIX_ONE = 1;
    // On the screen's columns and the strip's rows (contract "Strips"; row_last <= FB_HEIGHT - 1).
    wire line_on_screen = lx_q >= 0 && lx_q < LINE_X_END && !rows_empty
                       && ly_q >= PIX_W'(row_first) && ly_q <= PIX_W'(row_last);
    wire [X_W-1:0] line_px = lx_q[X_W-1:0];
    // The row's first word, ly_q * WORDS_PER_ROW modulo 2^WAW: formed once at the line's start and
    // stepped with ly_q, so the plot's address is an add, not a product (a DSP's output was on the
    // 25F build's system path, 17.1 ns). Modulo 2^WAW it is exact for every ly_q, and on the
    // frame's rows (the only ones plotted) it is the address itself, below 2^WAW.
    reg [WAW-1:0] lrow_q;
    localparam [WAW-1:0] ROW_WORDS = WAW'(WORDS_PER_ROW);
    wire [WAW-1:0] line_addr = lrow_q + WAW'(32'(line_px) / SPAN_W);
    wire [LANE_AW-1:0] line_lane = (SPAN_W > 1) ? LANE_AW'(line_px % X_W'(SPAN_W)) : {LANE_AW{1'b0}};

    // ---- depth of each lane: clamp(floor(Zfix / 2^16), 0, 65535), Zfix stepped like the edges ----
    reg signed [Z_W-1:0] z_q, zfirst_q;
    reg signed [ZSTEP_W-1:0] zdx_q, zdy_q;
    reg ztest_q;
    function automatic [15:0] zclamp(input signed [Z_W-1:0] zfix);
        reg signed [Z_W-1:0] whole;
        begin
            whole = zfix >>> 16;
            zclamp = (whole < 0) ? 16'd0 : ((whole > 65535) ? 16'hFFFF : whole[15:0]);
        end
    endfunction
    // Only the top ZBUF_BITS bits are kept (the low ones forced to 0): comparing these is comparing
    // floor(z / 2^(16 - ZBUF_BITS)), the contract's zb(p), here and in the write-after-write bypass.
    localparam [15:0] Z_KEEP = 16'hFFFF << (16 - ZBUF_BITS);
    reg [SPAN_W*16-1:0] lane_z;
    always @(*) begin
        for (l = 0; l < SPAN_W; l = l + 1) begin
            lane_z[l*16 +: 16] = zclamp(z_q + times(Z_W'(zdx_q), l)) & Z_KEEP;
        end
    end

    // ---- intensity of each lane (ENABLE_GOURAUD): clamp(floor(Ifix / 2^16), 0, 65535), its top byte ----
    reg signed [I_W-1:0] i_q, ifirst_q;
    reg signed [ISTEP_W-1:0] idx_q, idy_q;
    reg shade_q;                             // the triangle is a Gouraud one
    function automatic [ILVL_W-1:0] iclamp_top(input signed [I_W-1:0] ifix);
        reg signed [I_W-1:0] whole;
        begin
            whole = ifix >>> 16;
            iclamp_top = (whole < 0) ? {ILVL_W{1'b0}}
                       : ((whole > 65535) ? {ILVL_W{1'b1}} : whole[15 -: ILVL_W]);
        end
    endfunction
    reg [SPAN_W*ILVL_W-1:0] lane_lvl;
    always @(*) begin
        for (l = 0; l < SPAN_W; l = l + 1) begin
            lane_lvl[l*ILVL_W +: ILVL_W] = iclamp_top(i_q + I_W'(times(Z_W'(idx_q), l)));
        end
    end
    wire signed [I_W-1:0] i_down = i_q + I_W'(idy_q);
    wire signed [I_W-1:0] ifirst_down = ifirst_q + I_W'(idy_q);

    // The next row's start from either candidate, both summed while the seek decides between them
    // (first_span), so that the decision meets a multiplexer, not an adder.
    wire signed [EDGE_W-1:0] e_down [0:2];
    wire signed [EDGE_W-1:0] efirst_down [0:2];
    genvar d;
    generate
        for (d = 0; d < 3; d = d + 1) begin : g_down
            assign e_down[d] = e_q[d] + EDGE_W'(sy_q[d]);
            assign efirst_down[d] = efirst_q[d] + EDGE_W'(sy_q[d]);
        end
    endgenerate
    wire signed [EDGE_W-1:0] pa_down [0:2], pafirst_down [0:2], pb_down [0:2], pbfirst_down [0:2];
    generate
        for (d = 0; d < 3; d = d + 1) begin : g_probe_down
            assign pa_down[d] = pa_q[d] + EDGE_W'(sy_q[d]);
            assign pafirst_down[d] = pafirst_q[d] + EDGE_W'(sy_q[d]);
            assign pb_down[d] = pb_q[d] + EDGE_W'(sy_q[d]);
            assign pbfirst_down[d] = pbfirst_q[d] + EDGE_W'(sy_q[d]);
        end
    endgenerate
    wire signed [Z_W-1:0] z_down = z_q + Z_W'(zdy_q);
    wire signed [Z_W-1:0] zfirst_down = zfirst_q + Z_W'(zdy_q);

    // ---- stage 2: the candidate span, written one clock after it was found ----
    reg cand_valid_q, cand_depth_q;      // a span to write; whether it is depth-tested
    reg [WAW-1:0] cand_addr_q;
    reg [SPAN_W*8-1:0] cand_data_q;
    reg [SPAN_W-1:0] cand_mask_q;
    reg [SPAN_W*16-1:0] cand_z_q;
    reg cand_shade_q;                    // a Gouraud triangle's span: colours from cand_lvl_q
    reg [SPAN_W*ILVL_W-1:0] cand_lvl_q;
    reg [1:0] cand_x_q, cand_y_q;        // the span's first pixel x & 3 and its row y & 3

    // A triangle's edges as loaded (biased by the top-left rule) and its steps, and probe A's lane.
    wire signed [EDGE_W-1:0] load_e [0:2];
    wire signed [STEP_W-1:0] load_sx [0:2];
    assign load_e[0] = biased(in_desc.e0, in_desc.top_left[0]);
    assign load_e[1] = biased(in_desc.e1, in_desc.top_left[1]);
    assign load_e[2] = biased(in_desc.e2, in_desc.top_left[2]);
    assign load_sx[0] = in_desc.sx0;
    assign load_sx[1] = in_desc.sx1;
    assign load_sx[2] = in_desc.sx2;
    function automatic signed [EDGE_W-1:0] probe_a(input signed [EDGE_W-1:0] e, input signed [STEP_W-1:0] sx);
        probe_a = (sx > 0) ? e - EDGE_W'(sx) : e + edge_times(EDGE_W'(sx), SPAN_W);
    endfunction

    assign in_ready = state_q == S_IDLE;
    assign idle = state_q == S_IDLE && !in_valid && !cand_valid_q && !late_busy;

    always @(posedge clk) begin
        if (rst) begin
            state_q <= S_IDLE;
            cand_valid_q <= 1'b0;
            ev_span_visit <= 1'b0;
            ev_span_written <= 1'b0;
        end else begin
            cand_valid_q <= 1'b0;
            ev_span_visit <= seek || scan;
            ev_span_written <= 1'b0;
            case (state_q)
                S_IDLE: if (in_valid) begin
                    color_q <= in_desc.color;
                    z_q <= in_desc.z_start;
                    zfirst_q <= in_desc.z_start;
                    zdx_q <= in_desc.z_dx;
                    zdy_q <= in_desc.z_dy;
                    ztest_q <= ztest && !in_desc.is_line;
                    i_q <= in_desc.i_start;
                    ifirst_q <= in_desc.i_start;
                    idx_q <= in_desc.i_dx;
                    idy_q <= in_desc.i_dy;
                    shade_q <= ENABLE_GOURAUD != 0 && in_desc.shaded && !in_desc.is_line;
                    if (in_desc.is_line) begin
                        lx_q <= in_desc.line_x;
                        ly_q <= in_desc.line_y;
                        lrow_q <= WAW'($signed(in_desc.line_y) * $signed(32'(WORDS_PER_ROW)));
                        ln_q <= in_desc.line_n;
                        lxmajor_q <= in_desc.line_xmajor;
                        lxneg_q <= in_desc.line_xneg;
                        lyneg_q <= in_desc.line_yneg;
                        l2maj_q <= in_desc.line_two_a_major;
                        l2min_q <= in_desc.line_two_a_minor;
                        lerr_q <= in_desc.line_err;
                        state_q <= S_LINE;
                    end else begin
                        for (k = 0; k < 3; k = k + 1) begin
                            e_q[k] <= load_e[k];
                            efirst_q[k] <= load_e[k];
                        end
                        sx_q[0] <= in_desc.sx0;
                        sx_q[1] <= in_desc.sx1;
                        sx_q[2] <= in_desc.sx2;
                        sy_q[0] <= in_desc.sy0;
                        sy_q[1] <= in_desc.sy1;
                        sy_q[2] <= in_desc.sy2;
                        for (k = 0; k < 3; k = k + 1) begin
                            pa_q[k] <= probe_a(load_e[k], load_sx[k]);
                            pafirst_q[k] <= probe_a(load_e[k], load_sx[k]);
                            pb_q[k] <= load_e[k] + edge_times(EDGE_W'(load_sx[k]), SPAN_W - 1);
                            pbfirst_q[k] <= load_e[k] + edge_times(EDGE_W'(load_sx[k]), SPAN_W - 1);
                            sx_pos_q[k] <= load_sx[k] > 0;
                            sx_neg_q[k] <= load_sx[k] < 0;
                        end
                        col_q <= COL_W'(in_desc.col_lo);
                        col_first_q <= COL_W'(in_desc.col_lo);
                        col_lo_q <= COL_W'(in_desc.col_lo);
                        col_hi_q <= COL_W'(in_desc.col_hi);
                        row_q <= in_desc.row_lo;
                        row_hi_q <= in_desc.row_hi;
                        row_addr_q <= WAW'(32'(in_desc.row_lo) * WORDS_PER_ROW);
                        state_q <= S_SEEK;
                    end
                end
                S_SEEK, S_SCAN: begin
                    // The candidate's fields are taken in every clock, valid or not: only its
                    // valid flag depends on the coverage (which waits for the edges' adds), so
                    // the coverage drives a few flops' inputs, not the enables of all of them
                    // (issue #27: that enable was the board's walker path, 16.8 ns). A candidate
                    // lives one clock; nothing reads its fields without its valid flag.
                    if (draw_span && lane_cov != {SPAN_W{1'b0}}) begin
                        cand_valid_q <= 1'b1;
                        ev_span_written <= 1'b1;
                    end
                    cand_depth_q <= ztest_q;
                    cand_addr_q <= row_addr_q + WAW'(col_q);
                    cand_data_q <= {SPAN_W{color_q}};
                    cand_mask_q <= lane_cov;
                    cand_z_q <= lane_z;
                    cand_shade_q <= shade_q;
                    cand_lvl_q <= lane_lvl;
                    cand_x_q <= 2'(32'(col_q) * SPAN_W);
                    cand_y_q <= row_q[1:0];
                    if (first_span) begin
                        col_first_q <= col_q;
                        for (k = 0; k < 3; k = k + 1) begin
                            efirst_q[k] <= e_q[k];
                            pafirst_q[k] <= pa_q[k];
                            pbfirst_q[k] <= pb_q[k];
                        end
                        zfirst_q <= z_q;
                        ifirst_q <= i_q;
                    end
                    if (row_end) begin
                        if (row_q == row_hi_q) begin
                            state_q <= S_IDLE;
                        end else begin
                            // The next row starts where this one's coverage started.
                            row_q <= row_q + 1'b1;
                            row_addr_q <= row_addr_q + WAW'(WORDS_PER_ROW);
                            col_q <= first_span ? col_q : col_first_q;
                            for (k = 0; k < 3; k = k + 1) begin
                                efirst_q[k] <= first_span ? e_down[k] : efirst_down[k];
                                e_q[k] <= first_span ? e_down[k] : efirst_down[k];
                                pafirst_q[k] <= first_span ? pa_down[k] : pafirst_down[k];
                                pa_q[k] <= first_span ? pa_down[k] : pafirst_down[k];
                                pbfirst_q[k] <= first_span ? pb_down[k] : pbfirst_down[k];
                                pb_q[k] <= first_span ? pb_down[k] : pbfirst_down[k];
                            end
                            zfirst_q <= first_span ? z_down : zfirst_down;
                            z_q <= first_span ? z_down : zfirst_down;
                            ifirst_q <= first_span ? i_down : ifirst_down;
                            i_q <= first_span ? i_down : ifirst_down;
                            state_q <= S_SEEK;
                        end
                    end else if (go_left) begin
                        col_q <= col_q - 1'b1;
                        for (k = 0; k < 3; k = k + 1) begin
                            e_q[k] <= e_q[k] - edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                            pa_q[k] <= pa_q[k] - edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                            pb_q[k] <= pb_q[k] - edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                        end
                        z_q <= z_q - times(Z_W'(zdx_q), SPAN_W);
                        i_q <= i_q - I_W'(times(Z_W'(idx_q), SPAN_W));
                    end else begin  // seeking right past a rejected span, or the scan's next span
                        col_q <= col_q + 1'b1;
                        for (k = 0; k < 3; k = k + 1) begin
                            e_q[k] <= e_q[k] + edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                            pa_q[k] <= pa_q[k] + edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                            pb_q[k] <= pb_q[k] + edge_times(EDGE_W'(sx_q[k]), SPAN_W);
                        end
                        z_q <= z_q + times(Z_W'(zdx_q), SPAN_W);
                        i_q <= i_q + I_W'(times(Z_W'(idx_q), SPAN_W));
                        if (draw_span) begin
                            state_q <= S_SCAN;
                        end
                    end
                end
                S_LINE: begin
                    cand_valid_q <= line_on_screen;   // the fields as for spans: every clock
                    cand_depth_q <= 1'b0;
                    cand_shade_q <= 1'b0;
                    cand_addr_q <= line_addr;
                    cand_data_q <= {SPAN_W{color_q}};
                    cand_mask_q <= SPAN_W'(1) << line_lane;
                    // Bresenham: step the minor axis when the error is positive, then the major one.
                    if (lerr_q > 0) begin
                        if (lxmajor_q) begin
                            ly_q <= lyneg_q ? ly_q - PIX_ONE : ly_q + PIX_ONE;
                            lrow_q <= lyneg_q ? lrow_q - ROW_WORDS : lrow_q + ROW_WORDS;
                        end else begin
                            lx_q <= lxneg_q ? lx_q - PIX_ONE : lx_q + PIX_ONE;
                        end
                    end
                    lerr_q <= lerr_q - ((lerr_q > 0) ? LERR_W'(l2maj_q) : {LERR_W{1'b0}}) + LERR_W'(l2min_q);
                    if (lxmajor_q) begin
                        lx_q <= lxneg_q ? lx_q - PIX_ONE : lx_q + PIX_ONE;
                    end else begin
                        ly_q <= lyneg_q ? ly_q - PIX_ONE : ly_q + PIX_ONE;
                        lrow_q <= lyneg_q ? lrow_q - ROW_WORDS : lrow_q + ROW_WORDS;
                    end
                    ln_q <= ln_q - 1'b1;
                    if (ln_q == PIX_W'(1)) begin
                        state_q <= S_IDLE;
                    end
                end
                default: state_q <= S_IDLE;
            endcase
        end
    end

    // ---- the depth test (ENABLE_ZBUF), over two clocks so that no clock holds the depth RAM's
    // output, the forwarding multiplexer, a 16-bit compare and the write enables together (in one
    // clock that path closed at 30.6 MHz on the ECP5):
    //   stage 2 (the candidate's clock, the RAM's data arriving) compares each lane's depth against
    //     the RAM's and against the last write's, which landed with the read's own edge and so is
    //     not in the data (the RAM returns what it held before that edge);
    //   stage 3 takes the last write's comparison where that write covered the lane at this
    //     address, the RAM's elsewhere, and writes colour and depth where the lane is covered and
    //     nearer: one multiplexer of registered bits before the enables.
    // That one write is all a read can miss: the spans of one triangle have distinct addresses, and
    // two triangles' spans are at least 2 clocks apart (the walker takes a descriptor in S_IDLE), so
    // when a span is read, an earlier span of the same address has left stage 2 (checked below).
    // Without the depth buffer, stage 2 writes (the candidate's coverage) and there is no stage 3.
    reg [SPAN_W-1:0] final_mask;
    wire wr_valid;                       // the write stage holds a span to write
    wire [WAW-1:0] wr_addr;
    wire [SPAN_W*8-1:0] wr_colors;       // its colours (the write stage's, below)
    wire late_busy;                      // stage 3 holds a span (the walker is not idle)
    wire [SPAN_W*8-1:0] wr_data;         // stage 2's colours: flat, or shaded (further below)
    generate
        if (ENABLE_ZBUF != 0) begin : g_z
            // The last depth write (one edge ago).
            reg last_wr_q;
            reg [WAW-1:0] last_addr_q;
            reg [SPAN_W-1:0] last_mask_q;
            reg [SPAN_W*16-1:0] last_z_q;
            // Stage 3: the span, its colours, and stage 2's comparisons.
            reg s3_valid_q, s3_depth_q;
            reg [WAW-1:0] s3_addr_q;
            reg [SPAN_W-1:0] s3_cov_q;
            reg [SPAN_W*16-1:0] s3_z_q;
            reg [SPAN_W*8-1:0] s3_data_q;
            reg [SPAN_W-1:0] s3_near_ram_q;   // nearer than the RAM's depth
            reg [SPAN_W-1:0] s3_near_last_q;  // nearer than the last write's
            reg [SPAN_W-1:0] s3_last_hit_q;   // lanes the last write covered, at this address
            // The span read as cleared by epoch (a strip build's depth clear, gpu_core): its RAM
            // words are stale, so its write writes every lane, the cleared value where no pixel
            // wins. A write at the read's own clock (the last one, at this address) made it
            // current: that write covered every lane, or the span was current before it.
            reg s3_stale_q;
            reg [SPAN_W-1:0] near_ram, near_last, last_hit;
            reg [SPAN_W*16-1:0] wr_z;
            always @(*) begin
                for (l = 0; l < SPAN_W; l = l + 1) begin
                    // a span cleared by epoch holds what a clear writes, whatever its RAM says
                    near_ram[l] = z_rd_cleared ? cand_z_q[l*16 +: 16] < Z_KEEP
                                               : cand_z_q[l*16 +: 16] < z_rd_data[l*16 +: 16];
                    near_last[l] = cand_z_q[l*16 +: 16] < last_z_q[l*16 +: 16];
                    last_hit[l] = last_wr_q && last_addr_q == cand_addr_q && last_mask_q[l];
                    final_mask[l] = s3_cov_q[l]
                                 && (!s3_depth_q || (s3_last_hit_q[l] ? s3_near_last_q[l] : s3_near_ram_q[l]));
                    wr_z[l*16 +: 16] = final_mask[l] ? s3_z_q[l*16 +: 16] : Z_KEEP;
                end
            end
            always @(posedge clk) begin
                if (rst) begin
                    s3_valid_q <= 1'b0;
                    last_wr_q <= 1'b0;
                end else begin
                    s3_valid_q <= cand_valid_q;
                    last_wr_q <= z_wr_en;
                end
                s3_depth_q <= cand_depth_q;
                s3_addr_q <= cand_addr_q;
                s3_cov_q <= cand_mask_q;
                s3_z_q <= cand_z_q;
                s3_data_q <= wr_data;
                s3_near_ram_q <= near_ram;
                s3_near_last_q <= near_last;
                s3_last_hit_q <= last_hit;
                s3_stale_q <= z_rd_cleared && !(last_wr_q && last_addr_q == cand_addr_q);
                last_addr_q <= s3_addr_q;
                last_mask_q <= z_wr_mask;
                last_z_q <= z_wr_data;
            end
            // The read is issued with the span it belongs to, so its data meets the candidate.
            assign z_rd_en = (seek || scan) && draw_span;
            assign z_rd_addr = row_addr_q + WAW'(col_q);
            assign z_wr_en = s3_valid_q && s3_depth_q && final_mask != {SPAN_W{1'b0}};
            assign z_wr_addr = s3_addr_q;
            assign z_wr_data = s3_stale_q ? wr_z : s3_z_q;
            assign z_wr_mask = s3_stale_q ? {SPAN_W{1'b1}} : final_mask;
            assign wr_valid = s3_valid_q;
            assign wr_addr = s3_addr_q;
            assign wr_colors = s3_data_q;
            assign late_busy = s3_valid_q;
`ifndef SYNTHESIS
            // The argument above, checked: a depth-tested read never meets a depth-tested span of
            // its address in stage 2 (whose write, an edge after the read's, nothing would forward).
            always @(posedge clk) begin
                if (!rst && z_rd_en && ztest_q) begin
                    assert (!(cand_valid_q && cand_depth_q && cand_addr_q == z_rd_addr))
                        else $error("gpu_span_walker: depth read of a span whose write is two edges away");
                end
            end
`endif
        end else begin : g_no_z
            always @(*) final_mask = cand_mask_q;
            assign z_rd_en = 1'b0;
            assign z_rd_addr = {WAW{1'b0}};
            assign z_wr_en = 1'b0;
            assign z_wr_addr = {WAW{1'b0}};
            assign z_wr_data = {(SPAN_W * 16){1'b0}};
            assign z_wr_mask = {SPAN_W{1'b0}};
            assign wr_valid = cand_valid_q;
            assign wr_addr = cand_addr_q;
            assign wr_colors = wr_data;
            assign late_busy = 1'b0;
            wire unused_z = cand_depth_q | (|cand_z_q) | (|z_rd_data) | z_rd_cleared;
        end
    endgenerate

`ifndef SYNTHESIS
    // The depth range argument (gpu_pkg, contract "Depth"), checked: the Q16 accumulator stays
    // below 2^(Z_NEED_W - 1) = 2^50 in magnitude at every lane of every span a depth-tested
    // triangle writes.
    localparam signed [Z_W-1:0] Z_LIMIT = Z_W'(1) <<< (gpu_pkg::Z_NEED_W - 1);
    always @(posedge clk) begin
        if (!rst && ztest_q && (seek || scan) && draw_span) begin
            for (k = 0; k < SPAN_W; k = k + 1) begin
                assert ((z_q + times(Z_W'(zdx_q), k)) < Z_LIMIT && (z_q + times(Z_W'(zdx_q), k)) > -Z_LIMIT)
                    else $error("gpu_span_walker: depth accumulator exceeds 2^50");
            end
        end
    end
`endif

    assign fb_wr_en = wr_valid && final_mask != {SPAN_W{1'b0}};
    assign fb_wr_addr = wr_addr;
    // ---- stage 2's colours: flat, or each lane's ramp level (dithered) over the base ----
    generate
        if (ENABLE_GOURAUD != 0) begin : g_i
            // The 4x4 Bayer matrix, row-major by (y & 3, x & 3): thresholds 0 .. 15, each once.
            localparam [63:0] BAYER = {4'd5, 4'd13, 4'd7, 4'd15,   // y = 3, x = 3 .. 0
                                       4'd9, 4'd1, 4'd11, 4'd3,    // y = 2
                                       4'd6, 4'd14, 4'd4, 4'd12,   // y = 1
                                       4'd10, 4'd2, 4'd8, 4'd0};   // y = 0
            reg [SPAN_W*8-1:0] shaded_data;
            reg [3:0] level, frac, threshold;
            reg [1:0] lx;
            reg up;
            integer n;
            always @(*) begin
                for (n = 0; n < SPAN_W; n = n + 1) begin
                    level = cand_lvl_q[n*ILVL_W + 4 +: 4];
                    frac = cand_lvl_q[n*ILVL_W +: 4];
                    lx = cand_x_q + 2'(n);
                    threshold = BAYER[{cand_y_q, lx} * 4 +: 4];
                    up = dither && frac > threshold && level != 4'd15;
                    shaded_data[n*8 +: 8] = cand_data_q[n*8 +: 8] + 8'(level) + 8'(up);
                end
            end
            assign wr_data = cand_shade_q ? shaded_data : cand_data_q;
        end else begin : g_no_i
            assign wr_data = cand_data_q;
            wire unused_i = dither | cand_shade_q | (|cand_lvl_q) | (|cand_x_q) | (|cand_y_q);
        end
    endgenerate
`ifndef SYNTHESIS
    // The intensity range argument (gpu_pkg, the depth plane's): below 2^50 at every lane of every
    // span a Gouraud triangle writes.
    localparam signed [I_W-1:0] I_LIMIT = I_W'(1) <<< (gpu_pkg::Z_NEED_W - 1);
    always @(posedge clk) begin
        if (!rst && shade_q && (seek || scan) && draw_span) begin
            for (k = 0; k < SPAN_W; k = k + 1) begin
                assert ((i_q + I_W'(times(Z_W'(idx_q), k))) < I_LIMIT
                        && (i_q + I_W'(times(Z_W'(idx_q), k))) > -I_LIMIT)
                    else $error("gpu_span_walker: intensity accumulator exceeds 2^50");
            end
        end
    end
`endif

    assign fb_wr_data = wr_colors;
    assign fb_wr_mask = final_mask;
    assign ev_pixels = wr_valid ? CNT_W'($countones(final_mask)) : {CNT_W{1'b0}};
endmodule

`default_nettype wire
