/*
 * vec.h — 3-vectors, rotation matrices and affine transforms on the backend of real.h. Pure code.
 *
 * Coordinate frame (model, world and view alike): x right, y up, z forward (away from the camera).
 * Cross products use the usual formula a x b = (ay bz - az by, az bx - ax bz, ax by - ay bx); with
 * it, the outward normal of a mesh face (a, b, c) is (b - a) x (c - a) (mesh.h).
 *
 * Types:
 *   vec3   positions and offsets (real_t; fixed: q16_16).
 *   uvec3  directions of length ~1 (unit_t; fixed: q2_30): normals, light, camera axes.
 *   mat3   rotations, row-major, entries unit_t: out.x = m[0][0] x + m[0][1] y + m[0][2] z.
 *   xf_affine  p' = r p + t: model -> view in one step.
 *
 * Fixed-point range rules (each function states its own): dot products and matrix applications
 * accumulate exactly in int64 and round once. A vec3 fed to them must have |component| < 16384
 * (raw < 2^30) so that three products with a unit entry (< 2^30) stay below 2^62.
 */
#ifndef VEC_H
#define VEC_H

#include "math/fixed.h"
#include "math/real.h"

typedef struct {
    real_t x;
    real_t y;
    real_t z;
} vec3;

typedef struct {
    unit_t x;
    unit_t y;
    unit_t z;
} uvec3;

typedef struct {
    unit_t m[3][3];
} mat3;

typedef struct {
    mat3 r;
    vec3 t;
} xf_affine;

static inline vec3 vec3_make(real_t x, real_t y, real_t z)
{
    vec3 v = {x, y, z};

    return v;
}

static inline vec3 vec3_add(vec3 a, vec3 b)
{
    return vec3_make(real_add(a.x, b.x), real_add(a.y, b.y), real_add(a.z, b.z));
}

static inline vec3 vec3_sub(vec3 a, vec3 b)
{
    return vec3_make(real_sub(a.x, b.x), real_sub(a.y, b.y), real_sub(a.z, b.z));
}

/* v * u, u a unit-format factor (|u| < 2). */
static inline vec3 vec3_scale(vec3 v, unit_t u)
{
    return vec3_make(real_scale(v.x, u), real_scale(v.y, u), real_scale(v.z, u));
}

/* v * s, s a real. */
static inline vec3 vec3_mul(vec3 v, real_t s)
{
    return vec3_make(real_mul(v.x, s), real_mul(v.y, s), real_mul(v.z, s));
}

/* d * u: a distance along a direction. */
static inline vec3 vec3_along(uvec3 u, real_t d)
{
    return vec3_make(real_scale(d, u.x), real_scale(d, u.y), real_scale(d, u.z));
}

/* v . u as a real (|v_i| < 16384). Fixed: |v_i| < 2^30 raw, |u_i| <= 2^30, so each product is
 * below 2^60 and the sum below 2^62; rounded once, saturated (and counted) if it leaves q16_16. */
static inline real_t vec3_dot_unit(vec3 v, uvec3 u)
{
#if REAL_IS_FIXED
    const int64_t acc = (int64_t)v.x * u.x + (int64_t)v.y * u.y + (int64_t)v.z * u.z;

    return fx_sat64((acc + ((int64_t)1 << 29)) >> Q30_FRAC_BITS);
#else
    return v.x * u.x + v.y * u.y + v.z * u.z;
#endif
}

/* v . u where a few 2^-16 do not matter (culling tests, with a margin): fixed point sums the
 * three high words of (4 v_i) u_i, each (v_i 2^18)(u_i 2^30) / 2^32 = v_i u_i 2^16, floored: low
 * by less than 3 units of 2^-16. Needs |v_i| < 8192 (4 v_i fits int32). Float: vec3_dot_unit. */
static inline real_t vec3_dot_unit_fast(vec3 v, uvec3 u)
{
#if REAL_IS_FIXED
    return fx_mulh(v.x * 4, u.x) + fx_mulh(v.y * 4, u.y) + fx_mulh(v.z * 4, u.z);
#else
    return v.x * u.x + v.y * u.y + v.z * u.z;
#endif
}

/* a . b as a unit (|.| < 2 for directions); same arithmetic as vec3_dot_unit. */
static inline unit_t uvec3_dot(uvec3 a, uvec3 b)
{
#if REAL_IS_FIXED
    const int64_t acc = (int64_t)a.x * b.x + (int64_t)a.y * b.y + (int64_t)a.z * b.z;

    return fx_sat64((acc + ((int64_t)1 << 29)) >> Q30_FRAC_BITS);
#else
    return a.x * b.x + a.y * b.y + a.z * b.z;
#endif
}
uvec3 uvec3_cross(uvec3 a, uvec3 b);
/* |v| (|v_i| < 16384). */
real_t vec3_length(vec3 v);
/* v / |v|; {0, 0, 0} for v = 0. |v_i| < 16384. */
uvec3 vec3_direction(vec3 v);
/* u / |u| for a direction that has drifted from unit length; {0, 0, 0} for u = 0. */
uvec3 uvec3_normalize(uvec3 u);
/* The direction of u[0] + ... + u[n-1] (n <= 64 unit vectors): a vertex normal averaged from the
 * normals of the faces around it; {0, 0, 0} when they cancel. Fixed: summed exactly in int64. */
uvec3 uvec3_mean_direction(const uvec3 *u, uint32_t n);
/* Unit normal of (b - a) x (c - a); {0, 0, 0} for a degenerate triangle. Coordinates within
 * +-8192 (the fixed backend forms the cross product exactly in int64: edges < 2^30 raw, products
 * < 2^60, differences < 2^61). */
uvec3 vec3_triangle_normal(vec3 a, vec3 b, vec3 c);

mat3 mat3_identity(void);
/* a * b. Fixed: each entry sums three products below 2^60 (|entries| <= 1 + small), rounded
 * once; saturates (and counts) only if an entry leaves [-2, 2). */
mat3 mat3_mul(const mat3 *a, const mat3 *b);
mat3 mat3_transpose(const mat3 *a);
/* m * v (|v_i| < 16384 for the fixed backend). */
vec3 mat3_apply(const mat3 *m, vec3 v);
uvec3 mat3_apply_unit(const mat3 *m, uvec3 v);
/* m^T * v, without forming the transpose (takes a direction into the frame m rotates from). */
uvec3 mat3_apply_transposed_unit(const mat3 *m, uvec3 v);
/* The same for m a rotation and v a unit vector where 2^-27 does not matter (lighting, once per
 * object): fixed point sums the high words of the products, (m 2^30)(v 2^30) / 2^32 each, and
 * scales by 4: an entry is low by less than 3 * 2^-28 and stays within q2_30 because each row of
 * m^T times v is within [-1, 1]. Float: mat3_apply_transposed_unit. */
static inline uvec3 mat3_apply_transposed_unit_fast(const mat3 *m, uvec3 v)
{
#if REAL_IS_FIXED
    const unit_t(*a)[3] = m->m;
    uvec3 out;

    out.x = (fx_mulh(a[0][0], v.x) + fx_mulh(a[1][0], v.y) + fx_mulh(a[2][0], v.z)) * 4;
    out.y = (fx_mulh(a[0][1], v.x) + fx_mulh(a[1][1], v.y) + fx_mulh(a[2][1], v.z)) * 4;
    out.z = (fx_mulh(a[0][2], v.x) + fx_mulh(a[1][2], v.y) + fx_mulh(a[2][2], v.z)) * 4;
    return out;
#else
    return mat3_apply_transposed_unit(m, v);
#endif
}
/* Row i of m as a direction. */
uvec3 mat3_row(const mat3 *m, int i);

/* Rotation by angle a about axis 0 (x), 1 (y) or 2 (z). A positive angle turns the next axis
 * towards the one after: about x, +y towards +z; about y, +z towards +x; about z, +x towards +y. */
mat3 mat3_rotation(int axis, fx_angle a);
/* Rx(pitch) * Ry(yaw): turn by yaw about y, then by pitch about x. */
mat3 mat3_from_yaw_pitch(fx_angle yaw, fx_angle pitch);

/*
 * Re-orthonormalise a rotation that has accumulated rounding (Premerlani and Bizard's direction
 * cosine matrix renormalisation): with rows X, Y and e = X . Y, X' = X - (e/2) Y, Y' = Y - (e/2) X,
 * Z' = X' x Y', then each row v is scaled by (3 - v . v) / 2, the first Newton step of
 * 1/sqrt(v . v) around 1. Both corrections are quadratic in the error, so applying it after every
 * small rotation keeps the matrix orthonormal to the format's precision indefinitely (tested over
 * 10^6 rotations). Valid for a matrix already close to a rotation (row errors << 1).
 */
void mat3_renormalize(mat3 *m);

/*
 * The per-vertex transform p' = r p + t, the pipeline's hottest loop.
 * Fixed: each term is one `mulh` of the q2_30 entry with the q16_16 coordinate pre-scaled by 4:
 * (m 2^30)(v 2^18) / 2^32 = m v 2^16, already q16_16. Needs |p_i| < 8192 (so 4 p_i fits int32)
 * and |t_i| < 4096; the sum is then below |p| + |t| < 2^30.2 raw, no overflow, and no saturation
 * check is needed. Each mulh floors: the result is low by less than 3 units of 2^-16 (error in
 * (-3, 0] raw), which is 4.6e-5 view units. Float: 9 multiplies and 9 adds.
 */
static inline vec3 xf_apply(const xf_affine *xf, vec3 p)
{
    vec3 out;
#if REAL_IS_FIXED
    const int32_t x4 = p.x * 4;
    const int32_t y4 = p.y * 4;
    const int32_t z4 = p.z * 4;
    const unit_t(*m)[3] = xf->r.m;

    out.x = fx_mulh(m[0][0], x4) + fx_mulh(m[0][1], y4) + fx_mulh(m[0][2], z4) + xf->t.x;
    out.y = fx_mulh(m[1][0], x4) + fx_mulh(m[1][1], y4) + fx_mulh(m[1][2], z4) + xf->t.y;
    out.z = fx_mulh(m[2][0], x4) + fx_mulh(m[2][1], y4) + fx_mulh(m[2][2], z4) + xf->t.z;
#else
    const unit_t(*m)[3] = xf->r.m;

    out.x = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + xf->t.x;
    out.y = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + xf->t.y;
    out.z = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + xf->t.z;
#endif
    return out;
}

/* The point xf takes to the origin, for a rotation r: -r^T t (a model-to-view transform's eye, in
 * model space). |t_i| < 4096 as for xf_apply; fixed point within 3 units of 2^-16 (1/20000 of a
 * unit: what the painter's walks place by it, render.c and scene.c, see no difference). */
vec3 xf_eye(const xf_affine *xf);

/* a * b for per-frame composition (view times object rotation), where a result is used once and
 * never accumulated: fixed point takes each product's high word (mulh, floored) instead of the
 * exact int64 sum, so an entry is low by less than 3 * 2^-28 (~1e-8) — invisible, and 5x cheaper.
 * Accumulating rotations (spin, object mode) use the exact mat3_mul. Float: same as mat3_mul.
 * Inline: once per object per frame. */
static inline mat3 mat3_compose(const mat3 *a, const mat3 *b)
{
#if REAL_IS_FIXED
    /* (a 2^30)(b 2^30) / 2^32 = a b 2^28 per term. For rotations a row times a column is within
     * [-1, 1] (+ rounding), so the sum is within 2^28 and * 4 within q2_30. Written out with b's
     * columns in locals (b is read once, no loop overhead): the same arithmetic as a loop over
     * i, j, at about 100 instructions instead of 170 (once per object per frame). */
    const unit_t b00 = b->m[0][0], b01 = b->m[0][1], b02 = b->m[0][2];
    const unit_t b10 = b->m[1][0], b11 = b->m[1][1], b12 = b->m[1][2];
    const unit_t b20 = b->m[2][0], b21 = b->m[2][1], b22 = b->m[2][2];
    mat3 r;

    for (int i = 0; i < 3; i++) {
        const unit_t ai0 = a->m[i][0];
        const unit_t ai1 = a->m[i][1];
        const unit_t ai2 = a->m[i][2];

        r.m[i][0] = (fx_mulh(ai0, b00) + fx_mulh(ai1, b10) + fx_mulh(ai2, b20)) * 4;
        r.m[i][1] = (fx_mulh(ai0, b01) + fx_mulh(ai1, b11) + fx_mulh(ai2, b21)) * 4;
        r.m[i][2] = (fx_mulh(ai0, b02) + fx_mulh(ai1, b12) + fx_mulh(ai2, b22)) * 4;
    }
    return r;
#else
    return mat3_mul(a, b);
#endif
}

/*
 * xf_apply of the eight corners of the box [lo, hi], corner i taking hi on axis k when bit k of i
 * is set (x: bit 0, y: bit 1, z: bit 2). Fixed: xf_apply's nine per-axis terms are the only parts
 * that differ between corners, so 18 mulh (each axis at lo and at hi) serve all eight, summed in
 * int32 without overflow under xf_apply's range rule: bit-exact with xf_apply (measured on the
 * cubes: 184 instructions for the eight corners, against about 32 per corner through xf_apply).
 * Float: xf_apply per corner.
 */
void xf_apply_box(const xf_affine *xf, vec3 lo, vec3 hi, vec3 out[8]);

#endif /* VEC_H */
