/*
 * proj.h — perspective projection of view-space points to the GPU's Q12.4 screen coordinates,
 * with the outcodes that drive culling and clipping. Pure code.
 *
 * Screen mapping: sx = cx + f x / z, sy = cy - f y / z (Q12.4: 1/16 px; y down), f = focal length.
 *
 * Frame: the GPU's own (FB_SIZE, read by gpu_init), any size up to the contract's largest,
 * GPU_FB_MAX_WIDTH x GPU_FB_MAX_HEIGHT (640 x 480); proj_setup_init takes it. Focal lengths are
 * given for a frame of the contract's default height (GPU_FB_HEIGHT, 240 lines) and scaled to the
 * frame's, so that a scene shows the same field of view at every size: 200 px at 240 lines is
 * 400 px at 480.
 *
 * Guard band: the GPU takes any Q12.4 coordinate (+-2048 px) and clips to its frame itself, so
 * the firmware only clips where a vertex would leave the band |f x / z| <= 1536 px,
 * |f y / z| <= 1536 px around the frame's centre. Such a vertex gets PROJ_OUT_GUARD and its
 * triangles go through clip.c against the band's four planes |x| = g z, |y| = g z,
 * g = 1536 / f; a stored offset is never beyond the band (a GUARD vertex's is clamped to it).
 * So sx lies within cx +- 1536 px: for the largest frame (cx = 320 px) -1216 .. 1856 px, 192 px
 * inside the Q12.4 range (PROJ_GUARD_FITS checks it for the contract's largest frame; at
 * 320 x 240, -1376 .. 1696 px, 352 px inside), and two vertices' coordinates differ by at most
 * 2 * 1536 * 16 = 49152 < 2^16, which keeps the GPU's edge-function differences in range at
 * every frame size.
 *
 * Near plane: z >= PROJ_NEAR (0.25 view units). A nearer vertex is not projected at all
 * (PROJ_OUT_NEAR); its triangles are cut by clip.c (Sutherland-Hodgman), so nothing behind the eye
 * is drawn and nothing crossing the plane vanishes. A vertex exactly on the plane is in front.
 *
 * Outcodes: LEFT/RIGHT/TOP/BOTTOM mean the vertex lies beyond the frame's outermost pixel centres
 * (sx < 8, sx > 16 (W - 1) + 8, ...), exactly the GPU's bounding-box rejection; FAR means z > far.
 * A triangle whose three vertices share one of those bits (or all have NEAR) covers no pixel
 * centre: frustum-culled per triangle.
 *
 * Fixed-point projection (the per-vertex cost that matters): no division.
 *   z (q16_16, >= 2^14 raw) is normalised, m = z << s with s in [1, 17];
 *   Y = fx_recip_mantissa(m) ~ 2^63 / m, so 1/z = Y 2^(s - 47);
 *   Q = mulhu(Y, f_q4 << k) = Y f_q4 / 2^(32 - k) < 2^31, with k = 19 for f_q4 < 4096 (every
 *   focal length at 240 lines) and k = 18 for f_q4 < 8192 (up to 255 px scaled to 480 lines:
 *   8160), so f_q4 / z = Q 2^(s - 15 - k); f_q4 >= 1024 (proj_setup_init clamps it), so Q >= 2^28.
 *   offset = x f_q4 / z = (x << 3) Q 2^(s - 34 - k) = mulh(x << 3, Q) >> (k + 2 - s), rounded.
 *   Needs |x|, |y| < 4096 view units (x << 3 fits int32; real.h's range rule). The shift is
 *   (k - 15) .. (k + 1); the floor in mulh costs at most 2^-(k - 15) of a Q12.4 unit (2^-4 at
 *   k = 19, 2^-3 at 18), Y and Q carry 2^-20.9 relative error (one Newton step, fixed.h; Q's own
 *   floor adds 2^-28), at most 24576 * 2^-20.9 = 0.013 units of the largest offset: the offset is
 *   within 0.5 + 2^-4 + 0.013 < 0.58 Q12.4 units (1/16 px) of f x / z at k = 19, within
 *   0.5 + 2^-3 + 0.013 < 0.64 at k = 18, i.e. of the exact projection of the given view point
 *   (tests/firmware checks it against double arithmetic at both frame sizes and both ends of the
 *   focal range).
 * Float: one division and four multiplies, rounded to nearest.
 *
 * Depths produced per vertex:
 *   depth  the painter's sort depth: z in 1/128 units, capped at PROJ_DEPTH_MAX = 21845 so that the
 *          sum of a triangle's three depths, its sort key, fits 16 bits. Resolution 1/128 unit;
 *          the cap is z = 170.7, beyond the far distance.
 *   zbuf   the GPU's VTX_Z for the optional depth buffer: 65535 (1 - near / z), 0 at the near
 *          plane, growing towards 65535 far away; linear in 1/z, so the GPU's screen-space
 *          interpolation of it is exact. Only computed when ps->zbuf (the depth test is on), and
 *          not at all in a build without the depth test (FW_WITH_DEPTH = 0).
 */
#ifndef PROJ_H
#define PROJ_H

#include <stdbool.h>
#include <stdint.h>

#include "config/build_options.h"
#include "gpu_regs.h"
#include "soc_map.h"
#include "math/vec.h"

#define PROJ_NEAR_Q16    16384            /* 0.25 view units: the fixed path relies on 2^14 */
#define PROJ_NEAR        REAL_C(0.25)
#define PROJ_GUARD_Q4    (1536 * 16)      /* guard band half-width, Q12.4 */
#define PROJ_DEPTH_MAX   21845u           /* 3 * 21845 = 65535 */
#define PROJ_DEPTH_SCALE 128              /* depth units per view unit */

/* Sub-pixel precision of projected vertices (FW_SUBPIXEL_BITS, config/build_options.h): the screen offsets
 * are rounded once, to the nearest multiple of PROJ_SUBPIXEL_STEP Q12.4 units. At the default 4
 * bits the step is 1 and every expression below folds back to the full-precision code. */
#if FW_SUBPIXEL_BITS < 0 || FW_SUBPIXEL_BITS > 4
#error "FW_SUBPIXEL_BITS must be 0..4 (Q12.4 screen coordinates carry 4 fraction bits)"
#endif
#define PROJ_SUBPIXEL_DROP (4 - FW_SUBPIXEL_BITS)
#define PROJ_SUBPIXEL_STEP ((int32_t)1 << PROJ_SUBPIXEL_DROP)

/* Pixel-centre limits of the frame in Q12.4 (contract: centres at 16 px + 8); the last ones are the
 * frame's, struct proj_setup's x_last and y_last. */
#define PROJ_X_FIRST 8
#define PROJ_Y_FIRST 8

/* Focal lengths are given for a frame of this many lines (the contract's default frame); 64 .. 255
 * px there. */
#define PROJ_FOCAL_REF_LINES ((int32_t)GPU_FB_HEIGHT)
#define PROJ_FOCAL_MIN_PX    64
#define PROJ_FOCAL_MAX_PX    255

/* The guard band and the largest frame's centre stay inside the Q12.4 range, +-2048 px, with room
 * for the rounding of clipped vertices (100 px is far more than it needs). */
#define PROJ_GUARD_FITS(w, h) \
    (PROJ_GUARD_Q4 / 16 + (int32_t)(w) / 2 + 100 <= 2048 && \
     PROJ_GUARD_Q4 / 16 + (int32_t)(h) / 2 + 100 <= 2048)
_Static_assert(PROJ_GUARD_FITS(GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT),
               "the guard band leaves the Q12.4 range at the contract's largest frame");
/* The largest focal length in Q12.4, scaled to the largest frame, is below 8192: Q's multiplier
 * focal_q4 << 18 fits 31 bits (the fixed projection's argument above). */
_Static_assert(16 * PROJ_FOCAL_MAX_PX * (int32_t)GPU_FB_MAX_HEIGHT / PROJ_FOCAL_REF_LINES < 8192,
               "the focal length at the largest frame needs another multiplier shift");

/* The bits are the contract's (soc_map.toml [[pu_out]]): the SoC's projection unit answers them. */
enum proj_outcode {
    PROJ_OUT_LEFT = SOC_PU_OUT_LEFT,
    PROJ_OUT_RIGHT = SOC_PU_OUT_RIGHT,
    PROJ_OUT_TOP = SOC_PU_OUT_TOP,
    PROJ_OUT_BOTTOM = SOC_PU_OUT_BOTTOM,
    PROJ_OUT_FAR = SOC_PU_OUT_FAR,
    PROJ_OUT_NEAR = SOC_PU_OUT_NEAR,    /* z < near: not projected */
    PROJ_OUT_GUARD = SOC_PU_OUT_GUARD,  /* beyond the guard band: sx/sy not usable */
};
#define PROJ_CULL_BITS (PROJ_OUT_LEFT | PROJ_OUT_RIGHT | PROJ_OUT_TOP | PROJ_OUT_BOTTOM | \
                        PROJ_OUT_FAR | PROJ_OUT_NEAR)
#define PROJ_CLIP_BITS (PROJ_OUT_NEAR | PROJ_OUT_GUARD)

struct proj_setup {
    int32_t focal_q4;   /* focal length, 1/16 px, scaled to the frame: 1024 .. 8160 */
    int32_t cx_q4;      /* the frame's centre, Q12.4 */
    int32_t cy_q4;
    int32_t x_last;     /* the frame's last pixel centres, Q12.4: 16 (W - 1) + 8, 16 (H - 1) + 8 */
    int32_t y_last;
    int32_t width;      /* the frame, pixels */
    int32_t height;
    real_t near;        /* PROJ_NEAR */
    real_t far;         /* beyond it: PROJ_OUT_FAR; 1 .. 160 view units */
    real_t guard_slope; /* g = PROJ_GUARD_Q4 / focal_q4: the band is |x|, |y| <= g z */
    uint32_t focal_hi;  /* fixed: focal_q4 << k, the multiplier forming Q (k = 19 or 18) */
    int32_t off_shift;  /* fixed: k + 2, the offset's shift is off_shift - s */
    bool zbuf;          /* compute VTX_Z (only the GPU's depth test reads it; 0 otherwise) */
    uvec3 edge_plane[4];  /* inward unit normals (view space) of the planes through the eye and
                           * the screen's left, right, top and bottom edges */
};

/* One projected vertex (12 bytes: see the assertion below). The batch fields belong to batch.c.
 * sx and sy come first and in this order: on a little-endian CPU the pair, read as one 32-bit
 * word, is already the GPU's first vertex word (batch.c uses that). */
struct proj_vertex {
    union {
        struct {
            int16_t sx;  /* Q12.4 */
            int16_t sy;
        };
        uint32_t sxy;    /* the pair as one word (little-endian: the GPU's first vertex word) */
    };
    union {
        struct {
            uint16_t zbuf;   /* GPU VTX_Z */
            uint16_t depth;  /* sort depth, <= PROJ_DEPTH_MAX */
        };
        uint32_t zd;         /* the pair as one word (little-endian), for one store */
    };
    union {
        struct {
            uint8_t batch_stamp;  /* batch.c: the last batch this vertex was written to (0: none) */
            uint8_t code;         /* enum proj_outcode bits */
            uint16_t batch_slot;  /* batch.c: its index in that batch's vertex buffer
                                   * (< GPU_VTX_CAP_MAX; read only when batch_stamp is the batch's) */
        };
        uint32_t tail;            /* the three as one word, for one store (little-endian) */
    };
};
/* 12 bytes a frame vertex (the frame's largest array with the primitives): the GPU's two words,
 * then an 8-bit batch stamp (batch.c clears the stamps when its counter wraps past 255, which
 * takes 255 batches of one frame), the outcode, and the slot. */
_Static_assert(sizeof(struct proj_vertex) == 12u, "proj_vertex: 12 bytes");

/* &vert[i] as a multiply and an add, for the loops that look vertices up by index: `size` is
 * sizeof(struct proj_vertex) made opaque with FW_AS_MULTIPLIER (config/hot_path.h) once, before
 * the loop. */
static inline const struct proj_vertex *proj_vertex_at(const struct proj_vertex *vert, uint32_t i,
                                                       uint32_t size)
{
    return (const struct proj_vertex *)(const void *)((const uint8_t *)vert + i * size);
}

/* The same for a loop that updates the vertex (batch.c's stamp and slot). */
static inline struct proj_vertex *proj_vertex_at_mut(struct proj_vertex *vert, uint32_t i,
                                                     uint32_t size)
{
    return (struct proj_vertex *)proj_vertex_at(vert, i, size);
}

/* Position and depths of a vertex as two word stores (little-endian: the two halfword pairs;
 * elsewhere field by field). sx, sy within int16; zbuf, depth within uint16. */
static inline void proj_vertex_store(struct proj_vertex *out, int32_t sx, int32_t sy,
                                     uint32_t zbuf, uint32_t depth)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    out->sxy = ((uint32_t)sx & 0xFFFFu) | ((uint32_t)sy << 16);
    out->zd = zbuf | (depth << 16);
#else
    out->sx = (int16_t)sx;
    out->sy = (int16_t)sy;
    out->zbuf = (uint16_t)zbuf;
    out->depth = (uint16_t)depth;
#endif
}

/* A new vertex's outcode, in no batch yet (stamp 0): one word store where little-endian. */
static inline void proj_vertex_store_code(struct proj_vertex *out, uint32_t code)
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    out->tail = code << 8;
#else
    out->batch_stamp = 0;
    out->code = (uint8_t)code;
#endif
}

/* A width x height frame (1 .. GPU_FB_MAX_WIDTH x 1 .. GPU_FB_MAX_HEIGHT) centred on
 * (width / 2, height / 2) px, with the given focal length (64 .. 255 px at PROJ_FOCAL_REF_LINES
 * lines, clamped, scaled to the frame's height). */
void proj_setup_init(struct proj_setup *ps, int32_t focal_px, real_t far, uint32_t width,
                     uint32_t height);

/* The projection proper; `inside` (a constant at every call, folded away) skips the near test,
 * the guard band and the outcodes for points known to be inside the screen frustum, between near
 * and far (render.c knows that from an object's bounding sphere). */
static inline __attribute__((always_inline)) void proj_point_impl(const struct proj_setup *ps,
                                                                  vec3 v, struct proj_vertex *out,
                                                                  bool inside)
{
    int32_t off_x;
    int32_t off_y;
    uint32_t zbuf;
    uint32_t depth;
    int32_t sx;
    int32_t sy;
    uint8_t code = 0;

    if (!inside && v.z < ps->near) {
        proj_vertex_store(out, 0, 0, 0, 0);
        proj_vertex_store_code(out, PROJ_OUT_NEAR);
        return;
    }
#if REAL_IS_FIXED
    {
        int32_t s;
        const uint32_t m = fx_normalize32((uint32_t)v.z, &s);  /* z >= 2^14: s in [1, 17] */
        const uint32_t y = fx_recip_mantissa(m);
        const int32_t q = (int32_t)fx_mulhu(y, ps->focal_hi);     /* < 2^31 */
        const int32_t sh = ps->off_shift - s + PROJ_SUBPIXEL_DROP;  /* 3 .. 24 */
        const int32_t half = (int32_t)1 << (sh - 1);
        const int32_t zsh = 33 - s;                            /* 16 .. 32 */

        off_x = ((fx_mulh(v.x * 8, q) + half) >> sh) * PROJ_SUBPIXEL_STEP;
        off_y = ((fx_mulh(v.y * 8, q) + half) >> sh) * PROJ_SUBPIXEL_STEP;
        /* near / z in 0.16 = Y 2^(s - 33) for near = 2^-2; <= 2^16 */
        zbuf = 0u;
        if (FW_WITH_DEPTH && ps->zbuf) {
            zbuf = (zsh >= 32) ? 0u : (y >> zsh);
            zbuf = (zbuf >= 65535u) ? 0u : 65535u - zbuf;
        }
        depth = (uint32_t)v.z >> 9;  /* q16_16 -> 1/128 units */
    }
#else
    {
        const float inv_z = 1.0f / v.z;
        /* In units of PROJ_SUBPIXEL_STEP: focal_q4 is a multiple of 16 at the reference height
         * (else the shift floors it by less than a sixteenth of a pixel), and a power-of-two
         * scale of k scales fx and fy exactly. */
        const float k = (float)(ps->focal_q4 >> PROJ_SUBPIXEL_DROP) * inv_z;
        /* keeps the conversions below in range */
        const float limit = 8.0f * PROJ_GUARD_Q4 / PROJ_SUBPIXEL_STEP;
        float fx = v.x * k;
        float fy = v.y * k;
        const float nz = ps->near * inv_z;
        const float fd = v.z * (float)PROJ_DEPTH_SCALE;

        fx = (fx > limit) ? limit : ((fx < -limit) ? -limit : fx);
        fy = (fy > limit) ? limit : ((fy < -limit) ? -limit : fy);
        off_x = real_round_int(fx) * PROJ_SUBPIXEL_STEP;
        off_y = real_round_int(fy) * PROJ_SUBPIXEL_STEP;
        zbuf = (!FW_WITH_DEPTH || !ps->zbuf || nz >= 1.0f) ? 0u : (uint32_t)(65535.0f * (1.0f - nz));
        depth = (fd >= (float)PROJ_DEPTH_MAX) ? PROJ_DEPTH_MAX : (uint32_t)fd;
    }
#endif
    depth = (depth > PROJ_DEPTH_MAX) ? PROJ_DEPTH_MAX : depth;
    if (inside) {
        proj_vertex_store(out, ps->cx_q4 + off_x, ps->cy_q4 - off_y, zbuf, depth);
        proj_vertex_store_code(out, 0u);
        return;
    }
    if (off_x > PROJ_GUARD_Q4 || off_x < -PROJ_GUARD_Q4 || off_y > PROJ_GUARD_Q4 ||
        off_y < -PROJ_GUARD_Q4) {
        code |= PROJ_OUT_GUARD;
        /* Keep the stored coordinates representable; a GUARD vertex is never drawn as is. */
        off_x = (off_x > PROJ_GUARD_Q4) ? PROJ_GUARD_Q4 : off_x;
        off_x = (off_x < -PROJ_GUARD_Q4) ? -PROJ_GUARD_Q4 : off_x;
        off_y = (off_y > PROJ_GUARD_Q4) ? PROJ_GUARD_Q4 : off_y;
        off_y = (off_y < -PROJ_GUARD_Q4) ? -PROJ_GUARD_Q4 : off_y;
    }
    sx = ps->cx_q4 + off_x;
    sy = ps->cy_q4 - off_y;
    /* Most vertices are on the screen: one unsigned range check per axis decides that. */
    if ((uint32_t)(sx - PROJ_X_FIRST) > (uint32_t)(ps->x_last - PROJ_X_FIRST)) {
        code |= (sx < PROJ_X_FIRST) ? PROJ_OUT_LEFT : PROJ_OUT_RIGHT;
    }
    if ((uint32_t)(sy - PROJ_Y_FIRST) > (uint32_t)(ps->y_last - PROJ_Y_FIRST)) {
        code |= (sy < PROJ_Y_FIRST) ? PROJ_OUT_TOP : PROJ_OUT_BOTTOM;
    }
    if (v.z > ps->far) {
        code |= PROJ_OUT_FAR;
    }
    proj_vertex_store(out, sx, sy, zbuf, depth);
    proj_vertex_store_code(out, code);
}

/* Project one view-space point (|x|, |y| < 4096, any z) into *out, with its outcode. Always
 * inlined: it is the body of the per-vertex loop. */
static inline __attribute__((always_inline)) void proj_point(const struct proj_setup *ps, vec3 v,
                                                             struct proj_vertex *out)
{
    proj_point_impl(ps, v, out, false);
}

/* The same for a point known to lie inside the screen frustum between near and far: no outcode
 * work (code 0). A point within half a pixel of a screen edge may then miss the LEFT/RIGHT/TOP/
 * BOTTOM bit proj_point would give it; the GPU finds no pixel centre there either. */
static inline __attribute__((always_inline)) void proj_point_inside(const struct proj_setup *ps,
                                                                    vec3 v,
                                                                    struct proj_vertex *out)
{
    proj_point_impl(ps, v, out, true);
}

/*
 * The contract's edge function E_v0v1(v2) = (x1 - x0)(y2 - y0) - (y1 - y0)(x2 - x0) on Q12.4
 * coordinates: positive for a front face (mesh.h). Inside the guard band the differences are
 * below 2^16 and the products below 2^32: int64.
 */
static inline int64_t proj_signed_area(const struct proj_vertex *a, const struct proj_vertex *b,
                                       const struct proj_vertex *c)
{
    return (int64_t)(b->sx - a->sx) * (c->sy - a->sy) - (int64_t)(b->sy - a->sy) * (c->sx - a->sx);
}

/*
 * The same edge function in 32 bits, for vertices of an object inside the screen frustum
 * (proj_point_inside): they project onto the frame, sx in 0 .. 16 W and sy in 0 .. 16 H Q12.4 up
 * to rounding; at the contract's largest frame (640 x 480: 10240 and 7680) each difference is
 * below 2^14 in magnitude, each product below 2^28 and their difference below 2^29: exact in
 * int32, the same value as proj_signed_area. Two `mul` instead of two 64-bit products and a 64-bit
 * compare.
 */
static inline int32_t proj_signed_area_inside(const struct proj_vertex *a,
                                              const struct proj_vertex *b,
                                              const struct proj_vertex *c)
{
    return (b->sx - a->sx) * (c->sy - a->sy) - (b->sy - a->sy) * (c->sx - a->sx);
}

#endif /* PROJ_H */
