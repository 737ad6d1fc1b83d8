// gpu_pkg: what the GPU's modules share — the contract's constants, the datapath widths (each
// declared once, next to its range argument), the primitive descriptor and the performance counters.
//
// Contract constants: contract/gpu_regs.vh, generated from contract/gpu_contract.toml, is included
// here and nowhere else; modules name them gpu_pkg::GPU_* (register offsets, fields, the frame size
// default GPU_FB_WIDTH x GPU_FB_HEIGHT, the build-option defaults GPU_DEFAULT_*). Qualified names everywhere:
// yosys 0.23 accepts neither `import` in a module header nor in a module body, nor one package
// naming another's constants (see gpu_rtl/README.md, "Shared types").
//
// No logic here: types and constants only, so the modules stay what the contract headers describe.
`default_nettype none

package gpu_pkg;
`include "contract/gpu_regs.vh"  // relative to the repository root, where every tool runs

    // ---- datapath widths and their range arguments ----

    // Edge functions (gpu_prim_setup computes them, gpu_span_walker steps them): vertex coordinates
    // are signed Q12.4 in 16 bits, so a difference needs 17 bits; the pixel centres the walker
    // evaluates lie within one pixel of the screen (x in -1 .. FB_WIDTH, y in 0 .. FB_HEIGHT - 1),
    // so their offset from a vertex is in -32775 .. 37896 for the contract's frame and -32775 ..
    // 43016 for its largest (640 x 480), also 17 bits. Each product is below 2^32 in magnitude, an edge value below 2^33: EDGE_NEED_W = 34 bits
    // signed. EDGE_W = 36 leaves two bits of margin; gpu_raster asserts the 34-bit bound on every
    // descriptor in simulation.
    localparam integer EDGE_NEED_W = 34;
    localparam integer EDGE_W = 36;
    // An edge's steps (per pixel right, per row down) are 16 times a difference of two coordinates:
    // STEP_W = GPU_VTX_X_WIDTH + 1 + GPU_SUBPIXEL_BITS = 21 bits signed, exactly. They travel and
    // are held at that width, and widen (sign-extend) where they meet an edge value: synthesis then
    // sees how narrow the walker's lane multiples of a step are.
    localparam integer STEP_W = GPU_VTX_X_WIDTH + 1 + GPU_SUBPIXEL_BITS;

    // Depth plane (ENABLE_ZBUF): the Q16 depth accumulator, 2^16 z0 + ZA dx + ZB dy, stays below
    // 2^50 in magnitude at every pixel centre a depth-tested triangle covers (contract, "Depth"),
    // signed; gpu_span_walker asserts it. Its steps are 16 ZA and 16 ZB with |ZA|, |ZB| <= 2^31
    // (saturated quotients): |value| <= 2^35, signed.
    localparam integer Z_NEED_W = 51;
    localparam integer Z_W = 52;
    localparam integer ZSTEP_W = 40;

    // Intensity plane (ENABLE_GOURAUD): VTX_I is an unsigned 16-bit value like VTX_Z, and the
    // contract defines its plane with the depth plane's formula (contract, "Gouraud intensity"), so
    // the same argument bounds it: IA, IB saturated to 32 bits, the Q16 accumulator 2^16 i0 + IA dx
    // + IB dy below 2^50 at every pixel centre of the triangle's clamped box; the walker asserts it.
    // The accumulator and its steps take the depth plane's widths.
    localparam integer I_W = Z_W;
    localparam integer ISTEP_W = ZSTEP_W;
    // What a lane keeps of its clamped intensity (Q4.12): the level (bits 15..12) and the four
    // fraction bits the 4x4 dither threshold is compared with (bits 11..8).
    localparam integer ILVL_W = 8;

    // Lines: endpoint pixels are the Q12.4 coordinates shifted right by the sub-pixel bits, signed
    // PIX_W = 12 bits; a step count (the major delta, <= 4095) is PIX_W bits unsigned, twice a delta
    // PIX_W + 1. The Bresenham error starts at 2 minor - major and stays within +-2 * 4095, PIX_W + 2
    // bits signed; LERR_W keeps one bit spare.
    localparam integer PIX_W = GPU_VTX_X_WIDTH - GPU_SUBPIXEL_BITS;
    localparam integer LERR_W = PIX_W + 3;

    // Pixels on screen: x in 0 .. FB_WIDTH - 1, y in 0 .. FB_HEIGHT - 1 (the build's frame, at most
    // the contract's largest, GPU_FB_MAX_WIDTH x GPU_FB_MAX_HEIGHT): X_W and ROW_W bits for any.
    // The box of a triangle is carried in span columns and rows. A column is a pixel x divided by
    // SPAN_W; the descriptor carries it at the width SPAN_W = 1 needs, and a build with wider spans
    // uses the low $clog2(FB_WIDTH / SPAN_W) bits (the others are 0).
    localparam integer X_W = $clog2(GPU_FB_MAX_WIDTH);
    localparam integer ROW_W = $clog2(GPU_FB_MAX_HEIGHT);
    // A primitive's sample count (PERF_SAMPLES' increment): at most a whole frame's pixels.
    localparam integer SAMPLES_W = $clog2(GPU_FB_MAX_WIDTH * GPU_FB_MAX_HEIGHT + 1);
    localparam integer DESC_COL_W = X_W;
    localparam integer COLOR_W = GPU_PRIM_COLOR_WIDTH;

    // ---- the primitive descriptor: gpu_prim_setup -> gpu_span_walker, one per drawn primitive ----
    // Triangles use the edge and box fields, lines the line_* fields; the depth fields are 0 unless
    // the triangle is depth-tested, the intensity fields 0 unless it is a Gouraud triangle. The
    // intensity and depth fields come first (most significant), so that a user without them
    // (synth/ice40_walker_core.v) leaves bits that nothing reads at one end.
    typedef struct packed {
        logic                      shaded;            // a Gouraud triangle (PRIM_KIND_TRI_GOURAUD)
        logic signed [I_W-1:0]     i_start;           // Q16 intensity at lane 0 of the first span
        logic signed [ISTEP_W-1:0] i_dx;              // per pixel right (16 IA)
        logic signed [ISTEP_W-1:0] i_dy;              // per row down (16 IB)
        logic signed [Z_W-1:0]     z_start;           // Q16 depth at lane 0 of the first span
        logic signed [ZSTEP_W-1:0] z_dx;              // per pixel right (16 ZA)
        logic signed [ZSTEP_W-1:0] z_dy;              // per row down (16 ZB)
        logic                      is_line;
        logic [COLOR_W-1:0]        color;             // palette index
        logic signed [EDGE_W-1:0]  e0;                // edge values at lane 0 of the first span
        logic signed [EDGE_W-1:0]  e1;
        logic signed [EDGE_W-1:0]  e2;
        logic signed [STEP_W-1:0]  sx0;               // edge steps per pixel right
        logic signed [STEP_W-1:0]  sx1;
        logic signed [STEP_W-1:0]  sx2;
        logic signed [STEP_W-1:0]  sy0;               // edge steps per row down
        logic signed [STEP_W-1:0]  sy1;
        logic signed [STEP_W-1:0]  sy2;
        logic [2:0]                top_left;          // per edge: E = 0 counts as inside
        logic [DESC_COL_W-1:0]     col_lo;            // span columns of the clamped box
        logic [DESC_COL_W-1:0]     col_hi;
        logic [ROW_W-1:0]          row_lo;            // rows of the clamped box
        logic [ROW_W-1:0]          row_hi;
        logic signed [PIX_W-1:0]   line_x;            // first endpoint pixel
        logic signed [PIX_W-1:0]   line_y;
        logic [PIX_W-1:0]          line_n;            // steps
        logic                      line_xmajor;
        logic                      line_xneg;
        logic                      line_yneg;
        logic [PIX_W:0]            line_two_a_major;  // 2 * |major delta|
        logic [PIX_W:0]            line_two_a_minor;  // 2 * |minor delta|
        logic signed [LERR_W-1:0]  line_err;          // Bresenham error
    } desc_t;

    // ---- the performance counters of a batch: gpu_raster counts, gpu_regs reads them out as the
    // PERF_* registers (meanings in contract/gpu-registers.md) ----
    typedef struct packed {
        logic [31:0] busy_cycles;
        logic [31:0] tris_in;
        logic [31:0] tris_drawn;
        logic [31:0] tris_rejected;
        logic [31:0] pixels;
        logic [31:0] samples;
        logic [31:0] spans_written;
        logic [31:0] spans_visited;
    } perf_t;
endpackage

`default_nettype wire
