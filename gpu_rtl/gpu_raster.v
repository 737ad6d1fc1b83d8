// gpu_raster: runs one batch — optional clear, then each primitive of the index buffer — into the
// back framebuffer, then the optional swap at vertical blank.
//
// Contract: start (one-cycle pulse) begins a batch described by the batch inputs, which must hold still
// until busy falls. Primitives are fetched from the index RAM (2 words each) and their vertices from
// the vertex RAM (word 0 of each), both with one-cycle read latency. Triangles follow the exact rule of
// docs/gpu-contract.md: edge functions at pixel centres, either winding, top-left fill rule, bounding
// box of pixel centres clamped to the screen. Throughput: one pixel centre per clock while traversing;
// about 10 clocks of fetch and setup per primitive; the clear writes one pixel per clock.
//
// Widths: vertex coordinates are signed Q12.4 (16 bits). Coordinate differences need 17 bits; the
// offset of an on-screen pixel centre from a vertex also fits 17 bits (-32759 .. 37880); products fit
// 33 bits and edge values 34 bits. EDGE_W = 36 leaves two bits of margin, and every edge value held
// during traversal equals the direct evaluation at an on-screen pixel centre, so stepping cannot
// overflow either. The assertions at the bottom check the 34-bit bound in simulation.
`default_nettype none

module gpu_raster #(
    parameter integer VTX_CAP = 1024,
    parameter integer TRI_CAP = 1024,
    localparam integer VTX_AW = $clog2(VTX_CAP * 2),
    localparam integer IDX_AW = $clog2(TRI_CAP * 2),
    localparam integer FB_W = 320,
    localparam integer FB_H = 240,
    localparam integer FB_AW = $clog2(FB_W * FB_H),
    localparam integer EDGE_W = 36
) (
    input  wire              clk,
    input  wire              rst,
    // batch (from gpu_regs)
    input  wire              start,
    input  wire              ctrl_clear,
    input  wire              ctrl_swap,
    input  wire [31:0]       vtx_base,
    input  wire [31:0]       vtx_count,
    input  wire [31:0]       tri_base,
    input  wire [31:0]       tri_count,
    input  wire [7:0]        clear_color,
    input  wire [31:0]       doorbell_tag,
    // status and counters (to gpu_regs)
    output wire              busy,
    output reg  [31:0]       done_seq,
    output reg  [31:0]       frame_count,
    output reg  [2:0]        errors,        // {ERR_KIND, ERR_COUNT, ERR_VTX_INDEX}
    output reg  [31:0]       perf_busy_cycles,
    output reg  [31:0]       perf_tris_in,
    output reg  [31:0]       perf_tris_drawn,
    output reg  [31:0]       perf_tris_rejected,
    output reg  [31:0]       perf_pixels,
    output reg  [31:0]       perf_samples,
    // index RAM read port
    output wire              idx_rd_en,
    output wire [IDX_AW-1:0] idx_rd_addr,
    input  wire [31:0]       idx_rd_data,
    // vertex RAM read port
    output wire              vtx_rd_en,
    output wire [VTX_AW-1:0] vtx_rd_addr,
    input  wire [31:0]       vtx_rd_data,
    // framebuffer write port (back bank)
    output reg               fb_wr_en,
    output reg  [FB_AW-1:0]  fb_wr_addr,
    output reg  [7:0]        fb_wr_data,
    // buffer swap
    input  wire              vblank_start,
    output wire              swap
);
`include "gpu_regs.vh"

    localparam [3:0] S_IDLE = 4'd0, S_CHECK = 4'd1, S_CLEAR = 4'd2, S_PRIM = 4'd3,
                     S_IDX0 = 4'd4, S_IDX1 = 4'd5, S_V0 = 4'd6, S_V1 = 4'd7, S_V2 = 4'd8,
                     S_SETUP1 = 4'd9, S_SETUP2 = 4'd10, S_SETUP3 = 4'd11, S_TRAVERSE = 4'd12,
                     S_DRAWN = 4'd13, S_VBLANK = 4'd14, S_FINISH = 4'd15;
    localparam integer VI_W = $clog2(VTX_CAP);      // vertex index within the RAM
    localparam integer TI_W = $clog2(TRI_CAP);      // primitive index within the RAM
    localparam integer PRIM_W = $clog2(TRI_CAP + 1);

    reg [3:0] state_q;
    reg [PRIM_W-1:0] prim_q;          // primitive of the batch being processed
    reg [FB_AW-1:0] clear_addr_q;

    // Primitive being set up.
    reg [15:0] i0_q, i1_q;
    reg [7:0]  color_q;
    reg signed [15:0] x0_q, y0_q, x1_q, y1_q, x2_q, y2_q;   // Q12.4
    reg signed [34:0] area_q;                               // twice the signed area, in 1/256 px^2
    reg signed [12:0] px0_q, px1_q, py0_q, py1_q;           // clamped pixel bounding box

    // Traversal state: three edge functions, their row starts and steps.
    reg signed [EDGE_W-1:0] e_q [0:2];
    reg signed [EDGE_W-1:0] erow_q [0:2];
    reg signed [EDGE_W-1:0] stepx_q [0:2];
    reg signed [EDGE_W-1:0] stepy_q [0:2];
    reg [2:0] top_left_q;
    reg [8:0] x_q;
    reg [7:0] y_q;
    reg [FB_AW-1:0] addr_q, row_addr_q;

    // ---- Fetch: decode the primitive words ----
    wire [15:0] i2_w   = idx_rd_data[GPU_PRIM_I2_LSB +: GPU_PRIM_I2_WIDTH];
    wire [7:0]  kind_w = idx_rd_data[GPU_PRIM_KIND_LSB +: GPU_PRIM_KIND_WIDTH];
    wire kind_ok = kind_w == GPU_PRIM_KIND_TRI;
    wire index_ok = (32'(i0_q) < vtx_count) && (32'(i1_q) < vtx_count) && (32'(i2_w) < vtx_count);
    wire [TI_W-1:0] prim_index = tri_base[TI_W-1:0] + TI_W'(prim_q);
    function automatic [VTX_AW-1:0] vtx_word_addr(input [VI_W-1:0] index);
        vtx_word_addr = {vtx_base[VI_W-1:0] + index, 1'b0};
    endfunction
    // RAM reads are issued from the current state so the data arrives in the next one.
    assign idx_rd_en   = (state_q == S_PRIM) || (state_q == S_IDX0);
    assign idx_rd_addr = {prim_index, state_q == S_IDX0};
    assign vtx_rd_en   = (state_q == S_IDX1) || (state_q == S_V0) || (state_q == S_V1);
    assign vtx_rd_addr = vtx_word_addr(state_q == S_V0 ? i1_q[VI_W-1:0] : i0_q[VI_W-1:0]);  // i0_q holds i2 in S_V1
    wire signed [15:0] vx_w = vtx_rd_data[GPU_VTX_X_LSB +: GPU_VTX_X_WIDTH];
    wire signed [15:0] vy_w = vtx_rd_data[GPU_VTX_Y_LSB +: GPU_VTX_Y_WIDTH];

    // ---- Setup 1: area and bounding box ----
    function automatic signed [15:0] min3(input signed [15:0] a, input signed [15:0] b, input signed [15:0] c);
        min3 = (a < b) ? ((a < c) ? a : c) : ((b < c) ? b : c);
    endfunction
    function automatic signed [15:0] max3(input signed [15:0] a, input signed [15:0] b, input signed [15:0] c);
        max3 = (a > b) ? ((a > c) ? a : c) : ((b > c) ? b : c);
    endfunction
    // First pixel whose centre (16p + 8) is >= v: ceil((v - 8) / 16) = floor((v + 7) / 16).
    function automatic signed [12:0] first_centre(input signed [15:0] v);
        reg signed [16:0] t;
        begin
            t = 17'(v) + 17'sd7;
            first_centre = 13'(t >>> 4);
        end
    endfunction
    // Last pixel whose centre is <= v: floor((v - 8) / 16).
    function automatic signed [12:0] last_centre(input signed [15:0] v);
        reg signed [16:0] t;
        begin
            t = 17'(v) - 17'sd8;
            last_centre = 13'(t >>> 4);
        end
    endfunction
    function automatic signed [12:0] clamp_lo(input signed [12:0] v);
        clamp_lo = (v < 13'sd0) ? 13'sd0 : v;
    endfunction
    function automatic signed [12:0] clamp_hi(input signed [12:0] v, input signed [12:0] hi);
        clamp_hi = (v > hi) ? hi : v;
    endfunction

    wire signed [16:0] d01x = 17'(x1_q) - 17'(x0_q);
    wire signed [16:0] d01y = 17'(y1_q) - 17'(y0_q);
    wire signed [16:0] d02x = 17'(x2_q) - 17'(x0_q);
    wire signed [16:0] d02y = 17'(y2_q) - 17'(y0_q);
    wire signed [34:0] area_w = d01x * d02y - d01y * d02x;  // operands widen to 35 bits first

    // ---- Setup 3: edge function of edge a->b at the first pixel centre ----
    wire signed [17:0] pcx = 18'({px0_q, 4'd8});  // 16 * px0 + 8
    wire signed [17:0] pcy = 18'({py0_q, 4'd8});
    function automatic signed [EDGE_W-1:0] edge_start(input signed [15:0] ax, input signed [15:0] ay,
                                                      input signed [15:0] bx, input signed [15:0] by,
                                                      input signed [17:0] px, input signed [17:0] py);
        reg signed [17:0] dx, dy, ox, oy;
        begin
            dx = 18'(bx) - 18'(ax);
            dy = 18'(by) - 18'(ay);
            ox = px - 18'(ax);
            oy = py - 18'(ay);
            edge_start = dx * oy - dy * ox;  // operands widen to EDGE_W bits first
        end
    endfunction
    function automatic top_left(input signed [15:0] ax, input signed [15:0] ay,
                                input signed [15:0] bx, input signed [15:0] by);
        top_left = (by < ay) || ((by == ay) && (bx > ax));
    endfunction
    // Stepping one pixel right adds -dy * 16; one row down adds dx * 16.
    function automatic signed [EDGE_W-1:0] step_right(input signed [15:0] ay, input signed [15:0] by);
        step_right = (EDGE_W'(ay) - EDGE_W'(by)) <<< 4;
    endfunction
    function automatic signed [EDGE_W-1:0] step_down(input signed [15:0] ax, input signed [15:0] bx);
        step_down = (EDGE_W'(bx) - EDGE_W'(ax)) <<< 4;
    endfunction

    // ---- Traversal: coverage test ----
    function automatic covered(input signed [EDGE_W-1:0] e, input tl);
        covered = (e > 0) || (tl && (e == 0));
    endfunction
    wire pixel_covered = covered(e_q[0], top_left_q[0]) && covered(e_q[1], top_left_q[1])
               && covered(e_q[2], top_left_q[2]);
    wire last_x = {4'd0, x_q} == px1_q;
    wire last_y = {5'd0, y_q} == py1_q;

    wire [32:0] vtx_end = {1'b0, vtx_base} + {1'b0, vtx_count};
    wire [32:0] tri_end = {1'b0, tri_base} + {1'b0, tri_count};

    assign busy = start || (state_q != S_IDLE);
    assign swap = (state_q == S_VBLANK) && vblank_start;

    integer k;
    always @(posedge clk) begin
        if (rst) begin
            state_q <= S_IDLE;
            done_seq <= 32'd0;
            frame_count <= 32'd0;
            errors <= 3'd0;
            perf_busy_cycles <= 32'd0;
            perf_tris_in <= 32'd0;
            perf_tris_drawn <= 32'd0;
            perf_tris_rejected <= 32'd0;
            perf_pixels <= 32'd0;
            perf_samples <= 32'd0;
            fb_wr_en <= 1'b0;
        end else begin
            fb_wr_en <= 1'b0;
            if (state_q != S_IDLE && state_q != S_VBLANK && state_q != S_FINISH) begin
                perf_busy_cycles <= perf_busy_cycles + 32'd1;
            end
            case (state_q)
                S_IDLE: if (start) begin
                    errors <= 3'd0;
                    perf_busy_cycles <= 32'd1;
                    perf_tris_in <= 32'd0;
                    perf_tris_drawn <= 32'd0;
                    perf_tris_rejected <= 32'd0;
                    perf_pixels <= 32'd0;
                    perf_samples <= 32'd0;
                    prim_q <= {PRIM_W{1'b0}};
                    clear_addr_q <= {FB_AW{1'b0}};
                    state_q <= S_CHECK;
                end
                S_CHECK: begin
                    if (vtx_end > 33'(VTX_CAP) || tri_end > 33'(TRI_CAP)) begin
                        errors[1] <= 1'b1;
                        state_q <= S_DRAWN;
                    end else begin
                        state_q <= ctrl_clear ? S_CLEAR : S_PRIM;
                    end
                end
                S_CLEAR: begin
                    fb_wr_en <= 1'b1;
                    fb_wr_addr <= clear_addr_q;
                    fb_wr_data <= clear_color;
                    clear_addr_q <= clear_addr_q + 1'b1;
                    if (clear_addr_q == FB_AW'(FB_W * FB_H - 1)) begin
                        state_q <= S_PRIM;
                    end
                end
                S_PRIM: begin
                    if (32'(prim_q) == tri_count) begin
                        state_q <= S_DRAWN;
                    end else begin
                        state_q <= S_IDX0;
                    end
                end
                S_IDX0: begin  // word 0 arrives: I0, I1
                    i0_q <= idx_rd_data[GPU_PRIM_I0_LSB +: GPU_PRIM_I0_WIDTH];
                    i1_q <= idx_rd_data[GPU_PRIM_I1_LSB +: GPU_PRIM_I1_WIDTH];
                    state_q <= S_IDX1;
                end
                S_IDX1: begin  // word 1 arrives: I2, colour, kind
                    perf_tris_in <= perf_tris_in + 32'd1;
                    color_q <= idx_rd_data[GPU_PRIM_COLOR_LSB +: GPU_PRIM_COLOR_WIDTH];
                    if (!kind_ok) begin
                        errors[2] <= 1'b1;
                        perf_tris_rejected <= perf_tris_rejected + 32'd1;
                        prim_q <= prim_q + 1'b1;
                        state_q <= S_PRIM;
                    end else if (!index_ok) begin
                        errors[0] <= 1'b1;
                        perf_tris_rejected <= perf_tris_rejected + 32'd1;
                        prim_q <= prim_q + 1'b1;
                        state_q <= S_PRIM;
                    end else begin
                        i0_q <= i2_w;  // i0 is consumed; keep i2 for the third vertex read
                        state_q <= S_V0;
                    end
                end
                S_V0: begin
                    x0_q <= vx_w;
                    y0_q <= vy_w;
                    state_q <= S_V1;
                end
                S_V1: begin
                    x1_q <= vx_w;
                    y1_q <= vy_w;
                    state_q <= S_V2;
                end
                S_V2: begin
                    x2_q <= vx_w;
                    y2_q <= vy_w;
                    state_q <= S_SETUP1;
                end
                S_SETUP1: begin
                    area_q <= area_w;
                    px0_q <= clamp_lo(first_centre(min3(x0_q, x1_q, x2_q)));
                    px1_q <= clamp_hi(last_centre(max3(x0_q, x1_q, x2_q)), 13'(FB_W - 1));
                    py0_q <= clamp_lo(first_centre(min3(y0_q, y1_q, y2_q)));
                    py1_q <= clamp_hi(last_centre(max3(y0_q, y1_q, y2_q)), 13'(FB_H - 1));
                    state_q <= S_SETUP2;
                end
                S_SETUP2: begin
                    if (area_q == 35'sd0 || px0_q > px1_q || py0_q > py1_q) begin
                        perf_tris_rejected <= perf_tris_rejected + 32'd1;
                        prim_q <= prim_q + 1'b1;
                        state_q <= S_PRIM;
                    end else begin
                        if (area_q < 35'sd0) begin  // make the winding positive: swap v1 and v2
                            x1_q <= x2_q;
                            y1_q <= y2_q;
                            x2_q <= x1_q;
                            y2_q <= y1_q;
                        end
                        state_q <= S_SETUP3;
                    end
                end
                S_SETUP3: begin
                    perf_tris_drawn <= perf_tris_drawn + 32'd1;
                    e_q[0] <= edge_start(x0_q, y0_q, x1_q, y1_q, pcx, pcy);
                    e_q[1] <= edge_start(x1_q, y1_q, x2_q, y2_q, pcx, pcy);
                    e_q[2] <= edge_start(x2_q, y2_q, x0_q, y0_q, pcx, pcy);
                    erow_q[0] <= edge_start(x0_q, y0_q, x1_q, y1_q, pcx, pcy);
                    erow_q[1] <= edge_start(x1_q, y1_q, x2_q, y2_q, pcx, pcy);
                    erow_q[2] <= edge_start(x2_q, y2_q, x0_q, y0_q, pcx, pcy);
                    stepx_q[0] <= step_right(y0_q, y1_q);
                    stepx_q[1] <= step_right(y1_q, y2_q);
                    stepx_q[2] <= step_right(y2_q, y0_q);
                    stepy_q[0] <= step_down(x0_q, x1_q);
                    stepy_q[1] <= step_down(x1_q, x2_q);
                    stepy_q[2] <= step_down(x2_q, x0_q);
                    top_left_q <= {top_left(x2_q, y2_q, x0_q, y0_q), top_left(x1_q, y1_q, x2_q, y2_q),
                                   top_left(x0_q, y0_q, x1_q, y1_q)};
                    x_q <= px0_q[8:0];
                    y_q <= py0_q[7:0];
                    row_addr_q <= FB_AW'({py0_q[7:0], 8'd0}) + FB_AW'({py0_q[7:0], 6'd0});
                    addr_q <= FB_AW'({py0_q[7:0], 8'd0}) + FB_AW'({py0_q[7:0], 6'd0}) + FB_AW'(px0_q[8:0]);
                    state_q <= S_TRAVERSE;
                end
                S_TRAVERSE: begin
                    perf_samples <= perf_samples + 32'd1;
                    if (pixel_covered) begin
                        fb_wr_en <= 1'b1;
                        fb_wr_addr <= addr_q;
                        fb_wr_data <= color_q;
                        perf_pixels <= perf_pixels + 32'd1;
                    end
                    if (!last_x) begin
                        x_q <= x_q + 9'd1;
                        addr_q <= addr_q + 1'b1;
                        for (k = 0; k < 3; k = k + 1) begin
                            e_q[k] <= e_q[k] + stepx_q[k];
                        end
                    end else if (!last_y) begin
                        x_q <= px0_q[8:0];
                        y_q <= y_q + 8'd1;
                        row_addr_q <= row_addr_q + FB_AW'(FB_W);
                        addr_q <= row_addr_q + FB_AW'(FB_W) + FB_AW'(px0_q[8:0]);
                        for (k = 0; k < 3; k = k + 1) begin
                            erow_q[k] <= erow_q[k] + stepy_q[k];
                            e_q[k] <= erow_q[k] + stepy_q[k];
                        end
                    end else begin
                        prim_q <= prim_q + 1'b1;
                        state_q <= S_PRIM;
                    end
                end
                S_DRAWN: state_q <= ctrl_swap ? S_VBLANK : S_FINISH;
                S_VBLANK: if (vblank_start) begin
                    frame_count <= frame_count + 32'd1;
                    state_q <= S_FINISH;
                end
                S_FINISH: begin
                    done_seq <= doorbell_tag;
                    state_q <= S_IDLE;
                end
                default: state_q <= S_IDLE;
            endcase
        end
    end

`ifndef SYNTHESIS
    // Range argument, checked: edge values stay within 34 bits signed during traversal.
    always @(posedge clk) begin
        if (!rst && state_q == S_TRAVERSE) begin
            for (k = 0; k < 3; k = k + 1) begin
                assert (e_q[k] < (36'sd1 <<< 33) && e_q[k] >= -(36'sd1 <<< 33))
                    else $error("gpu_raster: edge value %0d exceeds 34 bits", e_q[k]);
            end
        end
    end
`endif
endmodule

`default_nettype wire
