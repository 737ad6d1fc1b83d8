// gpu_prim_setup: the rasterizer's front end — fetches primitives and their vertices, rejects the
// invalid and the empty, and turns each survivor into a descriptor for gpu_span_walker.
//
// Contract: start (one-cycle pulse) begins at primitive 0 of the batch described by the batch inputs,
// which hold still until idle. Descriptors leave in primitive order through out_valid/out_ready.
// Checks and arithmetic follow contract/gpu-contract.md exactly: kind, then vertex indices (no vertex
// outside the batch is ever read), then the triangle rule (area, winding swap, clamped bounding box of
// pixel centres, top-left edges) or the line rule. Throughput: one primitive per 3 clocks (the vertex
// RAM has one read port and a primitive needs three vertices); the index read of the next primitive
// and the setup arithmetic overlap with the vertex reads, so the walker is fed while it draws.
// The index words are decoded (kind and index checks, fields) into registers in the clock after they
// leave the RAM, and the check uses those: the RAM's output never reaches a comparator and the vertex
// RAM's read enable in one clock (the path that limited fmax on the ECP5). In the steady state that
// clock is F_V2's, so it costs nothing; the first primitive of a batch and the one after a rejected
// primitive wait one clock for it (F_DECODE).
// Latency from a primitive's index read to its descriptor: 7 clocks (the vertices pass a hand-off
// register before stage A). Rejected primitives take 2-3.
// A depth-tested triangle (ENABLE_ZBUF, CTRL.ZTEST) holds stage B for the depth-plane division:
// ceil(31 / DIV_QBITS) + 4 clocks (20; gpu_plane_setup), its throughput then; the fetch of the next primitives and
// the walk of the previous ones go on meanwhile, so large triangles hide it completely.
// A Gouraud triangle (ENABLE_GOURAUD, PRIM_KIND_TRI_GOURAUD) holds it the same way for the intensity
// plane's two divisions; they run beside the depth ones, so a triangle that is both waits once.
//
// Pipeline: fetch FSM -> hand-off (the vertices as read) -> stage A (vertices, box of pixel
// centres, differences) -> stage B (area, clamped box, line endpoints) -> stage C (the descriptor:
// edge values at the first span, steps, line Bresenham state, depth and intensity at the first span
// and their steps). A stage loads when it is empty or the stage after it moves; a full descriptor
// with out_ready low stalls everything behind.
//
// Widths: the descriptor is a gpu_pkg::desc_t; the range arguments of its fields (edge values need
// EDGE_NEED_W = 34 bits, EDGE_W = 36; the depth accumulator Z_W, the intensity one I_W) are in
// gpu_pkg.sv.
`default_nettype none

module gpu_prim_setup #(
    parameter integer VTX_CAP = gpu_pkg::GPU_VTX_CAP,              // build options: see gpu_top
    parameter integer TRI_CAP = gpu_pkg::GPU_TRI_CAP,
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,   // the frame's columns the box is clamped
                                                          // to (its rows: row_first .. row_last)
    parameter integer SPAN_W = gpu_pkg::GPU_DEFAULT_SPAN_W,
    parameter integer ENABLE_LINES = gpu_pkg::GPU_DEFAULT_ENABLE_LINES,
    parameter integer ENABLE_ZBUF = gpu_pkg::GPU_DEFAULT_ENABLE_ZBUF,  // depth-plane set-up (a division
                                         // per triangle while CTRL.ZTEST is on)
    parameter integer ENABLE_GOURAUD = gpu_pkg::GPU_DEFAULT_ENABLE_GOURAUD,  // intensity-plane set-up
                                         // (two more dividers, used by Gouraud triangles only)
    parameter integer DIV_QBITS = 2,     // quotient bits per clock of the depth dividers: a depth-
                                         // tested triangle holds stage B ceil(31 / DIV_QBITS) + 2
                                         // clocks (18 with 2; 1 halves the dividers' subtractors
                                         // and takes 33, 3 more than doubles them and takes 13)
    localparam integer VI_W = $clog2(VTX_CAP),
    localparam integer TI_W = $clog2(TRI_CAP),
    localparam integer PRIM_W = $clog2(TRI_CAP + 1),
    localparam integer COL_W = $clog2(FB_WIDTH / SPAN_W),  // span column
    localparam integer X_W = gpu_pkg::X_W,         // a pixel x on screen
    localparam integer ROW_W = gpu_pkg::ROW_W,     // a pixel row
    localparam integer SAMPLES_W = gpu_pkg::SAMPLES_W,
    localparam integer EDGE_W = gpu_pkg::EDGE_W,
    localparam integer STEP_W = gpu_pkg::STEP_W,   // edge steps
    localparam integer Z_W = gpu_pkg::Z_W,
    localparam integer ZSTEP_W = gpu_pkg::ZSTEP_W,
    localparam integer I_W = gpu_pkg::I_W,
    localparam integer ISTEP_W = gpu_pkg::ISTEP_W
) (
    input  wire                     clk,
    input  wire                     rst,
    // batch
    input  wire                     start,
    input  wire [31:0]              vtx_base,
    input  wire [31:0]              vtx_count,
    input  wire [31:0]              tri_base,
    input  wire [31:0]              tri_count,
    input  wire                     ctrl_ztest,
    input  wire [ROW_W-1:0]         row_first,     // the batch's STRIP rows, the last within the
    input  wire [ROW_W-1:0]         row_last,      // frame; rows_empty: none (every triangle is
    input  wire                     rows_empty,    // rejected)
    output wire                     idle,          // nothing fetched or in flight
    // index RAM (both words of a primitive at once)
    output wire                     idx_rd_en,
    output wire [TI_W-1:0]          idx_rd_addr,
    input  wire [63:0]              idx_rd_data,
    // vertex RAM (word 0: x, y)
    output wire                     vtx_rd_en,
    output wire [VI_W-1:0]          vtx_rd_addr,
    input  wire [31:0]              vtx_rd_data,
    input  wire [15:0]              vz_rd_data,    // the vertex's depth, read with it (ENABLE_ZBUF)
    input  wire [15:0]              vi_rd_data,    // its intensity, read with it (ENABLE_GOURAUD)
    // descriptor to the walker
    output reg                      out_valid,
    input  wire                     out_ready,
    output gpu_pkg::desc_t          out_desc,      // held while out_valid && !out_ready
    // events for the counters
    output reg                      ev_prim_in,
    output reg  [1:0]               ev_rejected,   // the fetch and stage B may both reject in one clock
    output reg                      ev_drawn,
    output reg  [SAMPLES_W-1:0]      ev_samples,
    output reg                      ev_err_kind,
    output reg                      ev_err_index
);
    // ------------------------------------------------------------------ fetch
    localparam [2:0] F_IDLE = 3'd0, F_ISSUE = 3'd1, F_CHECK = 3'd2, F_V1 = 3'd3, F_V2 = 3'd4,
                     F_DRAIN = 3'd5, F_DECODE = 3'd6;
    reg [2:0] fstate_q;
    reg [PRIM_W-1:0] prim_q;           // next primitive whose index words are read
    reg [15:0] i1_q, i2_q;
    reg [gpu_pkg::COLOR_W-1:0] color_q;
    reg is_line_q;
    reg signed [15:0] fx0_q, fy0_q, fx1_q, fy1_q;
    reg [15:0] fz0_q, fz1_q;
    reg [15:0] fi0_q, fi1_q;
    reg shade_q;                       // the primitive in fetch is a Gouraud triangle
    reg v2_pending_q;                  // vertex 2 (or a line's end) is on the RAM output for stage A
    reg v2_is_line_q;
    reg idx_was_read_q;                // F_V1 read the next primitive's index words

    wire more_prims = 32'(prim_q) < tri_count;
    // The index words as they leave the RAM (the clock after idx_rd_en) ...
    wire [15:0] w_i0 = idx_rd_data[gpu_pkg::GPU_PRIM_I0_LSB +: gpu_pkg::GPU_PRIM_I0_WIDTH];
    wire [15:0] w_i1 = idx_rd_data[gpu_pkg::GPU_PRIM_I1_LSB +: gpu_pkg::GPU_PRIM_I1_WIDTH];
    wire [15:0] w_i2 = idx_rd_data[32 + gpu_pkg::GPU_PRIM_I2_LSB +: gpu_pkg::GPU_PRIM_I2_WIDTH];
    wire [gpu_pkg::COLOR_W-1:0] w_color =
        idx_rd_data[32 + gpu_pkg::GPU_PRIM_COLOR_LSB +: gpu_pkg::GPU_PRIM_COLOR_WIDTH];
    wire [7:0]  w_kind = idx_rd_data[32 + gpu_pkg::GPU_PRIM_KIND_LSB +: gpu_pkg::GPU_PRIM_KIND_WIDTH];
    wire w_is_line = (w_kind == gpu_pkg::GPU_PRIM_KIND_LINE);
    wire w_is_shaded = (w_kind == gpu_pkg::GPU_PRIM_KIND_TRI_GOURAUD);
    wire w_kind_ok = (w_kind == gpu_pkg::GPU_PRIM_KIND_TRI) || (w_is_line && ENABLE_LINES != 0)
                  || (w_is_shaded && ENABLE_GOURAUD != 0);
    wire w_index_ok = (32'(w_i0) < vtx_count) && (32'(w_i1) < vtx_count)
                   && (w_is_line || 32'(w_i2) < vtx_count);
    // ... and decoded, one clock later, for F_CHECK.
    reg idx_fresh_q;                   // idx_rd_data holds words read in the previous clock
    reg [15:0] d_i0_q, d_i1_q, d_i2_q;
    reg [gpu_pkg::COLOR_W-1:0] d_color_q;
    reg d_is_line_q, d_kind_ok_q, d_index_ok_q, d_shaded_q;
    always @(posedge clk) begin
        idx_fresh_q <= idx_rd_en;
        if (idx_fresh_q) begin
            d_i0_q <= w_i0;
            d_i1_q <= w_i1;
            d_i2_q <= w_i2;
            d_color_q <= w_color;
            d_is_line_q <= w_is_line;
            d_shaded_q <= w_is_shaded;
            d_kind_ok_q <= w_kind_ok;
            d_index_ok_q <= w_index_ok;
        end
    end

    wire stage_h_free;                 // the hand-off registers can take the pending vertex set
    wire check_stall = (fstate_q == F_CHECK || fstate_q == F_DRAIN) && v2_pending_q && !stage_h_free;
    wire handoff = v2_pending_q && stage_h_free && (fstate_q == F_CHECK || fstate_q == F_DRAIN);
    wire decode = (fstate_q == F_CHECK) && !check_stall;
    wire reject_now = decode && !(d_kind_ok_q && d_index_ok_q);

    assign idx_rd_en = (fstate_q == F_ISSUE && more_prims) || (reject_now && more_prims)
                    || (fstate_q == F_V1 && more_prims);
    assign idx_rd_addr = tri_base[TI_W-1:0] + TI_W'(prim_q);

    wire [15:0] vtx_index = (fstate_q == F_CHECK) ? d_i0_q : (fstate_q == F_V1) ? i1_q : i2_q;
    assign vtx_rd_en = (decode && !reject_now) || fstate_q == F_V1 || (fstate_q == F_V2 && !is_line_q);
    assign vtx_rd_addr = vtx_base[VI_W-1:0] + vtx_index[VI_W-1:0];

    wire signed [15:0] vx = vtx_rd_data[gpu_pkg::GPU_VTX_X_LSB +: gpu_pkg::GPU_VTX_X_WIDTH];
    wire signed [15:0] vy = vtx_rd_data[gpu_pkg::GPU_VTX_Y_LSB +: gpu_pkg::GPU_VTX_Y_WIDTH];

    always @(posedge clk) begin
        if (rst) begin
            fstate_q <= F_IDLE;
            v2_pending_q <= 1'b0;
        end else begin
            if (handoff) begin
                v2_pending_q <= 1'b0;
            end
            case (fstate_q)
                F_IDLE: if (start) begin
                    prim_q <= {PRIM_W{1'b0}};
                    fstate_q <= F_ISSUE;
                end
                F_ISSUE: begin
                    if (more_prims) begin
                        prim_q <= prim_q + 1'b1;
                        fstate_q <= F_DECODE;
                    end else begin
                        fstate_q <= F_DRAIN;
                    end
                end
                F_DECODE: fstate_q <= F_CHECK;  // the words arrive; decoded at this clock's edge
                F_CHECK: if (!check_stall) begin
                    if (reject_now) begin
                        if (more_prims) begin
                            prim_q <= prim_q + 1'b1;
                            fstate_q <= F_DECODE;
                        end else begin
                            fstate_q <= F_DRAIN;
                        end
                    end else begin
                        i1_q <= d_i1_q;
                        i2_q <= d_i2_q;
                        color_q <= d_color_q;
                        is_line_q <= d_is_line_q;
                        shade_q <= d_shaded_q;
                        fstate_q <= F_V1;
                    end
                end
                F_V1: begin
                    fx0_q <= vx;
                    fy0_q <= vy;
                    fz0_q <= vz_rd_data;
                    fi0_q <= vi_rd_data;
                    if (more_prims) begin
                        prim_q <= prim_q + 1'b1;
                    end
                    fstate_q <= F_V2;
                end
                F_V2: begin
                    fx1_q <= vx;
                    fy1_q <= vy;
                    fz1_q <= vz_rd_data;
                    fi1_q <= vi_rd_data;
                    v2_pending_q <= 1'b1;
                    v2_is_line_q <= is_line_q;
                    // The next primitive's index words were read in F_V1 if there was one.
                    fstate_q <= idx_was_read_q ? F_CHECK : F_DRAIN;
                end
                F_DRAIN: if (!v2_pending_q || handoff) begin
                    fstate_q <= F_IDLE;
                end
                default: fstate_q <= F_IDLE;
            endcase
        end
    end

    // Whether F_V1 issued an index read (so F_CHECK follows F_V2).
    always @(posedge clk) begin
        if (fstate_q == F_V1) begin
            idx_was_read_q <= more_prims;
        end
    end

    // Events of the fetch stage.
    wire fetch_ev_in = decode;
    wire fetch_ev_reject = reject_now;

    // ------------------------------------------------------------------ stage A: three vertices
    // The box of pixel centres (stage A registers it, unclamped).
    function automatic signed [15:0] min3(input signed [15:0] a, input signed [15:0] b, input signed [15:0] c);
        min3 = (a < b) ? ((a < c) ? a : c) : ((b < c) ? b : c);
    endfunction
    function automatic signed [15:0] max3(input signed [15:0] a, input signed [15:0] b, input signed [15:0] c);
        max3 = (a > b) ? ((a > c) ? a : c) : ((b > c) ? b : c);
    endfunction
    // Pixels by their centres (16p + 8): with FIRST_CENTRE the first pixel whose centre is >= v,
    // floor((v + 7) / 16); with LAST_CENTRE the last one whose centre is <= v, floor((v - 8) / 16).
    localparam FIRST_CENTRE = 1'b1, LAST_CENTRE = 1'b0;
    function automatic signed [12:0] centre_pixel(input signed [15:0] v, input first);
        reg signed [16:0] t;
        begin
            t = first ? 17'(v) + 17'sd7 : 17'(v) - 17'sd8;
            centre_pixel = 13'(t >>> 4);
        end
    endfunction

    // The hand-off: the three vertices as they are, vertex 2 straight from the RAM (an EBR's clock
    // to out alone is 5.8 ns on the ECP5) into these flops; stage A forms the box and the
    // differences from them a clock later (issue #27: the RAM's output through the box's minimum,
    // maximum and rounding was the board's set-up path, 16.8-18.3 ns). A primitive's latency grows
    // by a clock, its rate not: the fetch hands off one every three clocks at best, and these
    // registers free whenever stage A takes their set.
    reg h_valid_q;
    reg h_is_line_q, h_shaded_q;
    reg [gpu_pkg::COLOR_W-1:0] h_color_q;
    reg signed [15:0] hx0_q, hy0_q, hx1_q, hy1_q, hx2_q, hy2_q;
    reg [15:0] hz0_q, hz1_q, hz2_q;
    reg [15:0] hi0_q, hi1_q, hi2_q;

    reg a_valid_q;
    reg a_is_line_q;
    reg [gpu_pkg::COLOR_W-1:0] a_color_q;
    reg signed [15:0] ax0_q, ay0_q, ax1_q, ay1_q, ax2_q, ay2_q;
    // The corners' differences from v0, Q12.4, registered with them: the area's and the planes'
    // products start from registers (the subtract in front of the area's product and its zero test
    // into b_drawable_q was the board's longest path).
    reg signed [16:0] d01x, d01y, d02x, d02y;
    // Its box of pixel centres, unclamped, also taken at the handoff: the minimum and maximum and
    // their rounding come off stage B's path (the clamp, the first span's centre and the corners'
    // offsets follow there).
    reg signed [12:0] a_rpx0, a_rpy0, a_rpx1, a_rpy1;
    reg [15:0] az0_q, az1_q, az2_q;
    reg a_shaded_q;
    reg [15:0] ai0_q, ai1_q, ai2_q;
    wire b_free;

    wire stage_a_free = !a_valid_q || b_free;   // stage A can take the hand-off's set
    assign stage_h_free = !h_valid_q || stage_a_free;

    always @(posedge clk) begin
        if (rst) begin
            h_valid_q <= 1'b0;
        end else if (stage_h_free) begin
            h_valid_q <= handoff;
            if (handoff) begin
                h_is_line_q <= v2_is_line_q;
                h_color_q <= color_q;
                hx0_q <= fx0_q;
                hy0_q <= fy0_q;
                hx1_q <= fx1_q;
                hy1_q <= fy1_q;
                hx2_q <= v2_is_line_q ? fx1_q : vx;   // the third corner: a line's end again
                hy2_q <= v2_is_line_q ? fy1_q : vy;
                hz0_q <= fz0_q;
                hz1_q <= fz1_q;
                hz2_q <= vz_rd_data;
                h_shaded_q <= shade_q;
                hi0_q <= fi0_q;
                hi1_q <= fi1_q;
                hi2_q <= vi_rd_data;
            end
        end
    end

    always @(posedge clk) begin
        if (rst) begin
            a_valid_q <= 1'b0;
        end else if (stage_a_free) begin
            a_valid_q <= h_valid_q;
            if (h_valid_q) begin
                a_is_line_q <= h_is_line_q;
                a_color_q <= h_color_q;
                ax0_q <= hx0_q;
                ay0_q <= hy0_q;
                ax1_q <= hx1_q;
                ay1_q <= hy1_q;
                ax2_q <= hx2_q;
                ay2_q <= hy2_q;
                d01x <= 17'(hx1_q) - 17'(hx0_q);
                d01y <= 17'(hy1_q) - 17'(hy0_q);
                d02x <= 17'(hx2_q) - 17'(hx0_q);
                d02y <= 17'(hy2_q) - 17'(hy0_q);
                a_rpx0 <= centre_pixel(min3(hx0_q, hx1_q, hx2_q), FIRST_CENTRE);
                a_rpy0 <= centre_pixel(min3(hy0_q, hy1_q, hy2_q), FIRST_CENTRE);
                a_rpx1 <= centre_pixel(max3(hx0_q, hx1_q, hx2_q), LAST_CENTRE);
                a_rpy1 <= centre_pixel(max3(hy0_q, hy1_q, hy2_q), LAST_CENTRE);
                az0_q <= hz0_q;
                az1_q <= hz1_q;
                az2_q <= hz2_q;
                a_shaded_q <= h_shaded_q;
                ai0_q <= hi0_q;
                ai1_q <= hi1_q;
                ai2_q <= hi2_q;
            end
        end
    end

    // ---------------------------------------- stage B: area, box, endpoints (and the planes' numerators)
    function automatic signed [12:0] clamp(input signed [12:0] v, input signed [12:0] lo,
                                           input signed [12:0] hi);
        clamp = (v < lo) ? lo : ((v > hi) ? hi : v);
    endfunction

    localparam signed [12:0] X_LAST = 13'(FB_WIDTH - 1);   // last pixel column
    // The box's rows: the strip's (contract "Strips"), the whole frame unless the firmware says.
    wire signed [12:0] y_first = 13'(row_first);
    wire signed [12:0] y_last = 13'(row_last);
    // Centre, Q12.4, of lane 0 of the span holding on-screen pixel column px, and of pixel row py.
    function automatic signed [17:0] span_centre_x(input [X_W-1:0] px);
        span_centre_x = 18'(32'(COL_W'(px / X_W'(SPAN_W))) * SPAN_W * 16 + 8);
    endfunction
    function automatic signed [17:0] row_centre_y(input [ROW_W-1:0] py);
        row_centre_y = 18'({py, 4'd8});
    endfunction

    // Stage A's box of pixel centres, unclamped and clamped to the screen's columns and the strip's
    // rows: px0 = max(0, raw), px1 = min(X_LAST, raw), py0 = max(y_first, raw), py1 = min(y_last,
    // raw). Empty when px0 > px1 or py0 > py1, i.e. when the raw box is empty or lies wholly off one
    // side of the screen or the strip. (row_first, row_last and rows_empty hold still for the
    // batch, so clamping here is clamping where the descriptor is made.)
    wire [X_W-1:0] a_px0 = X_W'(clamp(a_rpx0, 13'sd0, X_LAST));
    wire [X_W-1:0] a_px1 = X_W'(clamp(a_rpx1, 13'sd0, X_LAST));
    wire [ROW_W-1:0] a_py0 = ROW_W'(clamp(a_rpy0, y_first, y_last));
    wire [ROW_W-1:0] a_py1 = ROW_W'(clamp(a_rpy1, y_first, y_last));
    wire a_box_empty = a_rpx0 > a_rpx1 || a_rpy0 > a_rpy1 || a_rpx1 < 13'sd0
                    || a_rpy1 < y_first || a_rpx0 > X_LAST || a_rpy0 > y_last || rows_empty;
    // Centre, Q12.4, of lane 0 of the first span and of the first row.
    wire signed [17:0] a_pcx = span_centre_x(a_px0);
    wire signed [17:0] a_pcy = row_centre_y(a_py0);
    // Twice the signed area, and whether it is 0 (the products compared beside the subtract).
    wire signed [34:0] area_pa = 35'(d01x) * 35'(d02y), area_pb = 35'(d01y) * 35'(d02x);
    wire signed [34:0] area_w = area_pa - area_pb;
    wire a_area_nonzero = area_pa != area_pb;

    // Lines: endpoint pixels by arithmetic shift, their differences (Bresenham's set-up per the
    // contract follows in stage C).
    localparam integer PIX_W = gpu_pkg::PIX_W;  // a line endpoint pixel, signed
    localparam integer PIXD_W = PIX_W + 1;      // a difference of two
    wire signed [PIX_W-1:0] a_lx0 = PIX_W'(ax0_q >>> gpu_pkg::GPU_SUBPIXEL_BITS);
    wire signed [PIX_W-1:0] a_ly0 = PIX_W'(ay0_q >>> gpu_pkg::GPU_SUBPIXEL_BITS);
    wire signed [PIX_W-1:0] a_lx1 = PIX_W'(ax1_q >>> gpu_pkg::GPU_SUBPIXEL_BITS);
    wire signed [PIX_W-1:0] a_ly1 = PIX_W'(ay1_q >>> gpu_pkg::GPU_SUBPIXEL_BITS);
    wire signed [PIXD_W-1:0] a_ldx = PIXD_W'(a_lx1) - PIXD_W'(a_lx0);
    wire signed [PIXD_W-1:0] a_ldy = PIXD_W'(a_ly1) - PIXD_W'(a_ly0);
    wire a_line_empty = a_lx0 == a_lx1 && a_ly0 == a_ly1;   // no major step

    // Stage B keeps what stage C's arithmetic starts from in registers: the clamped box, each
    // corner's offset to lane 0 of the first span, each edge's differences, whether the primitive
    // is drawn at all. (The clamp, the span's centre and the offsets in front of stage C's
    // products held the board's system clock to 50 MHz; `drawable` fed ~500 clock enables.)
    reg b_valid_q;
    reg b_is_line_q;
    reg [gpu_pkg::COLOR_W-1:0] b_color_q;
    reg signed [15:0] bx0_q, by0_q, bx1_q, by1_q, bx2_q, by2_q;
    reg signed [34:0] b_area_q;
    reg b_drawable_q;                  // a line with a major step, a triangle of non-zero area
                                       // whose clamped box is not empty
    reg [X_W-1:0] b_px0_q, b_px1_q;    // the clamped box
    reg [ROW_W-1:0] b_py0_q, b_py1_q;
    // Lane 0 of the first span minus each corner, Q12.4: the edge values' offsets and (corner 0)
    // the planes' start offsets (g_z, g_i); 17 bits by gpu_pkg's argument (-32775 .. 43016 at
    // 640 x 480), 18 held. The edges' differences are 17 bits too.
    reg signed [17:0] b_ox0_q, b_oy0_q, b_ox1_q, b_oy1_q, b_ox2_q, b_oy2_q;
    // Each edge's differences in the triangle's given winding: v1 - v0, v2 - v1, v0 - v2.
    reg signed [17:0] b_dx01_q, b_dy01_q, b_dx12_q, b_dy12_q, b_dx20_q, b_dy20_q;
    reg signed [PIX_W-1:0] b_lx0_q, b_ly0_q;
    reg signed [PIXD_W-1:0] b_ldx_q, b_ldy_q;
    reg [15:0] bz0_q;                  // v0's depth: the depth plane's start (g_z)
    reg b_shaded_q;
    reg [15:0] bi0_q;                  // v0's intensity: the intensity plane's start (g_i)
    wire c_free;
    wire b_z_ready;                    // the depth and intensity gradients are known (or not needed)
    wire z_ready, i_ready;             // each of them
    assign b_z_ready = z_ready && i_ready;

    assign b_free = !b_valid_q || (c_free && b_z_ready);

    always @(posedge clk) begin
        if (rst) begin
            b_valid_q <= 1'b0;
        end else if (b_free) begin
            b_valid_q <= a_valid_q;
            if (a_valid_q) begin
                b_is_line_q <= a_is_line_q;
                b_color_q <= a_color_q;
                bx0_q <= ax0_q;
                by0_q <= ay0_q;
                bx1_q <= ax1_q;
                by1_q <= ay1_q;
                bx2_q <= ax2_q;
                by2_q <= ay2_q;
                b_area_q <= area_w;
                b_drawable_q <= a_is_line_q ? !a_line_empty : (a_area_nonzero && !a_box_empty);
                bz0_q <= az0_q;
                b_shaded_q <= a_shaded_q;
                bi0_q <= ai0_q;
                b_px0_q <= a_px0;
                b_px1_q <= a_px1;
                b_py0_q <= a_py0;
                b_py1_q <= a_py1;
                b_ox0_q <= a_pcx - 18'(ax0_q);
                b_oy0_q <= a_pcy - 18'(ay0_q);
                b_ox1_q <= a_pcx - 18'(ax1_q);
                b_oy1_q <= a_pcy - 18'(ay1_q);
                b_ox2_q <= a_pcx - 18'(ax2_q);
                b_oy2_q <= a_pcy - 18'(ay2_q);
                b_dx01_q <= 18'(d01x);  // stage A's v1 - v0
                b_dy01_q <= 18'(d01y);
                b_dx12_q <= 18'(ax2_q) - 18'(ax1_q);
                b_dy12_q <= 18'(ay2_q) - 18'(ay1_q);
                b_dx20_q <= 18'(ax0_q) - 18'(ax2_q);
                b_dy20_q <= 18'(ay0_q) - 18'(ay2_q);
                b_lx0_q <= a_lx0;
                b_ly0_q <= a_ly0;
                b_ldx_q <= a_ldx;
                b_ldy_q <= a_ldy;
            end
        end
    end

    // ------------------------------------------------------------------ stage C: the descriptor
    // Winding: with area < 0, v1 and v2 trade places so that the interior is where every E > 0.
    wire flip = b_area_q < 0;
    wire signed [15:0] tx0 = bx0_q, ty0 = by0_q;
    wire signed [15:0] tx1 = flip ? bx2_q : bx1_q, ty1 = flip ? by2_q : by1_q;
    wire signed [15:0] tx2 = flip ? bx1_q : bx2_q, ty2 = flip ? by1_q : by2_q;

    wire [COL_W-1:0] col_lo = COL_W'(b_px0_q / X_W'(SPAN_W));
    wire [COL_W-1:0] col_hi = COL_W'(b_px1_q / X_W'(SPAN_W));

    // Edge values at lane 0 of the first span: E_ab = (xb - xa)(py - ya) - (yb - ya)(px - xa), the
    // operands from stage B's registers. Flipped, the edges are v0v2, v2v1, v1v0, and E_ba = -E_ab
    // exactly (the cross product of b - a with a - b is 0): e0 = -E20, e1 = -E12, e2 = -E01, which
    // swaps the two products of the given winding's edge. Exact in EDGE_W bits either way.
    function automatic signed [EDGE_W-1:0] edge_value(input flip_edge,
                                                      input signed [17:0] dx, input signed [17:0] dy,
                                                      input signed [17:0] ox, input signed [17:0] oy);
        reg signed [17:0] p1, p2, q1, q2;
        begin
            p1 = flip_edge ? dy : dx;
            p2 = flip_edge ? ox : oy;
            q1 = flip_edge ? dx : dy;
            q2 = flip_edge ? oy : ox;
            edge_value = p1 * p2 - q1 * q2;  // operands widen to EDGE_W bits first
        end
    endfunction
    wire signed [17:0] e0_dx = flip ? b_dx20_q : b_dx01_q, e0_dy = flip ? b_dy20_q : b_dy01_q;
    wire signed [17:0] e0_ox = flip ? b_ox2_q : b_ox0_q, e0_oy = flip ? b_oy2_q : b_oy0_q;
    wire signed [17:0] e2_dx = flip ? b_dx01_q : b_dx20_q, e2_dy = flip ? b_dy01_q : b_dy20_q;
    wire signed [17:0] e2_ox = flip ? b_ox0_q : b_ox2_q, e2_oy = flip ? b_oy0_q : b_oy2_q;

    function automatic top_left(input signed [15:0] ax, input signed [15:0] ay,
                                input signed [15:0] bx, input signed [15:0] by);
        top_left = (by < ay) || ((by == ay) && (bx > ax));
    endfunction
    function automatic signed [STEP_W-1:0] step_right(input signed [15:0] ay, input signed [15:0] by);
        step_right = (STEP_W'(ay) - STEP_W'(by)) <<< gpu_pkg::GPU_SUBPIXEL_BITS;
    endfunction
    function automatic signed [STEP_W-1:0] step_down(input signed [15:0] ax, input signed [15:0] bx);
        step_down = (STEP_W'(bx) - STEP_W'(ax)) <<< gpu_pkg::GPU_SUBPIXEL_BITS;
    endfunction

    // Lines: Bresenham's set-up per the contract.
    wire [PIX_W-1:0] lax = PIX_W'(b_ldx_q < 0 ? -b_ldx_q : b_ldx_q);
    wire [PIX_W-1:0] lay = PIX_W'(b_ldy_q < 0 ? -b_ldy_q : b_ldy_q);
    wire lxmajor = lax >= lay;
    wire [PIX_W-1:0] lmaj = lxmajor ? lax : lay;
    wire [PIX_W-1:0] lmin = lxmajor ? lay : lax;

    wire c_load_valid = b_valid_q && b_drawable_q && b_z_ready;
    wire b_leaves = b_valid_q && c_free && b_z_ready;   // stage B hands on (or drops) its primitive
    assign c_free = !out_valid || out_ready;

    // ---- the depth plane (ENABLE_ZBUF) and the intensity plane (ENABLE_GOURAUD: the same formula
    // on VTX_I), each by its gpu_plane_setup while stage B holds the triangle ----
    wire a_load = b_free && a_valid_q;               // stage B takes stage A's triangle
    wire b_next = b_leaves || !b_valid_q;            // ... and hands it on, or holds none
    wire signed [Z_W-1:0] z_start_w;
    wire signed [ZSTEP_W-1:0] z_dx_w, z_dy_w;
    generate
        if (ENABLE_ZBUF != 0) begin : g_z
            gpu_plane_setup #(.DIV_QBITS(DIV_QBITS), .START_W(Z_W), .STEP_W(ZSTEP_W)) u_plane (
                .clk(clk), .rst(rst),
                .a_load(a_load), .a_v0(az0_q), .a_v1(az1_q), .a_v2(az2_q),
                .a_d01x(d01x), .a_d01y(d01y), .a_d02x(d02x), .a_d02y(d02y),
                .b_need(b_valid_q && !b_is_line_q && ctrl_ztest && b_drawable_q), .b_next(b_next),
                .b_area(b_area_q), .b_v0(bz0_q), .b_off_x(b_ox0_q), .b_off_y(b_oy0_q),
                .ready(z_ready), .start(z_start_w), .dx(z_dx_w), .dy(z_dy_w));
        end else begin : g_no_z
            assign z_ready = 1'b1;
            assign z_start_w = {Z_W{1'b0}};
            assign z_dx_w = {ZSTEP_W{1'b0}};
            assign z_dy_w = {ZSTEP_W{1'b0}};
            wire unused_z = ctrl_ztest | (|vz_rd_data) | (|bz0_q) | (|az1_q) | (|az2_q);
        end
    endgenerate

    wire signed [I_W-1:0] i_start_w;
    wire signed [ISTEP_W-1:0] i_dx_w, i_dy_w;
    generate
        if (ENABLE_GOURAUD != 0) begin : g_i
            // (Meaningless for a triangle that is not shaded: the walker then ignores them.)
            gpu_plane_setup #(.DIV_QBITS(DIV_QBITS), .START_W(I_W), .STEP_W(ISTEP_W)) u_plane (
                .clk(clk), .rst(rst),
                .a_load(a_load), .a_v0(ai0_q), .a_v1(ai1_q), .a_v2(ai2_q),
                .a_d01x(d01x), .a_d01y(d01y), .a_d02x(d02x), .a_d02y(d02y),
                .b_need(b_valid_q && !b_is_line_q && b_shaded_q && b_drawable_q), .b_next(b_next),
                .b_area(b_area_q), .b_v0(bi0_q), .b_off_x(b_ox0_q), .b_off_y(b_oy0_q),
                .ready(i_ready), .start(i_start_w), .dx(i_dx_w), .dy(i_dy_w));
        end else begin : g_no_i
            assign i_ready = 1'b1;
            assign i_start_w = {I_W{1'b0}};
            assign i_dx_w = {ISTEP_W{1'b0}};
            assign i_dy_w = {ISTEP_W{1'b0}};
            wire unused_i = (|vi_rd_data) | (|bi0_q) | (|ai1_q) | (|ai2_q) | b_shaded_q
                          | (|b_ox0_q) | (|b_oy0_q) | a_load | b_next;  // the depth plane's too, if built
        end
    endgenerate

    wire [X_W:0] box_w = (X_W + 1)'(b_px1_q) - (X_W + 1)'(b_px0_q) + 1'b1;      // 1 .. FB_WIDTH
    wire [ROW_W:0] box_h = (ROW_W + 1)'(b_py1_q) - (ROW_W + 1)'(b_py0_q) + 1'b1;  // 1 .. its height

    always @(posedge clk) begin
        if (rst) begin
            out_valid <= 1'b0;
        end else if (c_free) begin
            out_valid <= c_load_valid;
            if (c_load_valid) begin
                out_desc.is_line <= b_is_line_q;
                out_desc.color <= b_color_q;
                out_desc.e0 <= edge_value(flip, e0_dx, e0_dy, e0_ox, e0_oy);
                out_desc.e1 <= edge_value(flip, b_dx12_q, b_dy12_q, b_ox1_q, b_oy1_q);
                out_desc.e2 <= edge_value(flip, e2_dx, e2_dy, e2_ox, e2_oy);
                out_desc.sx0 <= step_right(ty0, ty1);
                out_desc.sx1 <= step_right(ty1, ty2);
                out_desc.sx2 <= step_right(ty2, ty0);
                out_desc.sy0 <= step_down(tx0, tx1);
                out_desc.sy1 <= step_down(tx1, tx2);
                out_desc.sy2 <= step_down(tx2, tx0);
                out_desc.top_left <= {top_left(tx2, ty2, tx0, ty0), top_left(tx1, ty1, tx2, ty2),
                                 top_left(tx0, ty0, tx1, ty1)};
                out_desc.col_lo <= gpu_pkg::DESC_COL_W'(col_lo);
                out_desc.col_hi <= gpu_pkg::DESC_COL_W'(col_hi);
                out_desc.row_lo <= b_py0_q;
                out_desc.row_hi <= b_py1_q;
                out_desc.line_x <= b_lx0_q;
                out_desc.line_y <= b_ly0_q;
                out_desc.line_n <= lmaj;
                out_desc.line_xmajor <= lxmajor;
                out_desc.line_xneg <= b_ldx_q < 0;
                out_desc.line_yneg <= b_ldy_q < 0;
                out_desc.line_two_a_major <= {lmaj, 1'b0};
                out_desc.line_two_a_minor <= {lmin, 1'b0};
                out_desc.line_err <= gpu_pkg::LERR_W'({lmin, 1'b0}) - gpu_pkg::LERR_W'(lmaj);
                out_desc.z_start <= z_start_w;
                out_desc.z_dx <= z_dx_w;
                out_desc.z_dy <= z_dy_w;
                out_desc.shaded <= ENABLE_GOURAUD != 0 && b_shaded_q && !b_is_line_q;
                out_desc.i_start <= i_start_w;
                out_desc.i_dx <= i_dx_w;
                out_desc.i_dy <= i_dy_w;
            end
        end
    end

    // ------------------------------------------------------------------ events
    always @(posedge clk) begin
        ev_prim_in <= !rst && fetch_ev_in;
        ev_err_kind <= !rst && fetch_ev_reject && !d_kind_ok_q;
        ev_err_index <= !rst && fetch_ev_reject && d_kind_ok_q;
        ev_rejected <= (!rst && fetch_ev_reject ? 2'd1 : 2'd0)
                     + (!rst && b_leaves && !b_drawable_q ? 2'd1 : 2'd0);
        ev_drawn <= !rst && c_free && c_load_valid;
        ev_samples <= (!rst && c_free && c_load_valid)
                    ? (b_is_line_q ? SAMPLES_W'(lmaj) : SAMPLES_W'(box_w) * SAMPLES_W'(box_h)) : {SAMPLES_W{1'b0}};
    end

    assign idle = (fstate_q == F_IDLE) && !h_valid_q && !a_valid_q && !b_valid_q && !out_valid;
endmodule

`default_nettype wire
