/*
 * vec.c — see vec.h. Backend-specific only where fixed point needs exact int64 accumulation.
 */
#include "math/vec.h"

#include "config/hot_path.h"

#if !REAL_IS_FIXED
#include <math.h>
#endif

#if REAL_IS_FIXED
/* Round a sum of products of a q2_30 and a qN value back to qN: (acc + 2^29) >> 30, saturated.
 * Callers keep |acc| < 2^62, so adding the rounding half cannot overflow. */
static inline int32_t vec_round30(int64_t acc)
{
    return fx_sat64((acc + ((int64_t)1 << 29)) >> Q30_FRAC_BITS);
}
#endif

real_t real_sqrt(real_t r)
{
#if REAL_IS_FIXED
    /* sqrt(r / 2^16) * 2^16 = sqrt(r * 2^16): r < 2^31 so r * 2^16 < 2^47, root < 2^24. */
    return (r <= 0) ? 0 : (real_t)fx_isqrt64((uint64_t)r << 16);
#else
    return (r <= 0.0f) ? 0.0f : sqrtf(r);
#endif
}

uvec3 uvec3_cross(uvec3 a, uvec3 b)
{
    uvec3 c;
#if REAL_IS_FIXED
    c.x = vec_round30((int64_t)a.y * b.z - (int64_t)a.z * b.y);
    c.y = vec_round30((int64_t)a.z * b.x - (int64_t)a.x * b.z);
    c.z = vec_round30((int64_t)a.x * b.y - (int64_t)a.y * b.x);
#else
    c.x = a.y * b.z - a.z * b.y;
    c.y = a.z * b.x - a.x * b.z;
    c.z = a.x * b.y - a.y * b.x;
#endif
    return c;
}

real_t vec3_length(vec3 v)
{
#if REAL_IS_FIXED
    /* |v_i| < 2^30 raw: squares < 2^60, sum < 2^62; sqrt of raw^2 is raw. */
    const uint64_t sq = (uint64_t)((int64_t)v.x * v.x) + (uint64_t)((int64_t)v.y * v.y) +
                        (uint64_t)((int64_t)v.z * v.z);

    return (real_t)fx_isqrt64(sq);
#else
    return sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
#endif
}

#if REAL_IS_FIXED
/* |v| (INT64_MIN's too). */
static inline uint64_t vec_mag64(int64_t v)
{
    return v < 0 ? 0u - (uint64_t)v : (uint64_t)v;
}

/* v / 2^k rounded toward zero: what k halvings (v /= 2) give, in one shift; k >= 1, and the caller
 * makes |v| / 2^k < 2^30, so the result is a 32-bit value. */
static __attribute__((noinline)) int32_t vec_div_pow2(int64_t v, int32_t k)
{
    const int32_t m = (int32_t)(vec_mag64(v) >> k);

    return v < 0 ? -m : m;
}

/* Bits in m (1 for 0: callers only compare it with 30), 64 for m >= 2^63. One normalisation of
 * the top non-zero word: the firmware's one-scene builds are sized to the byte (fw-fit). */
static int32_t vec_bit_length64(uint64_t m)
{
    const uint32_t hi = (uint32_t)(m >> 32);
    int32_t shift;

    (void)fx_normalize32((hi != 0u ? hi : (uint32_t)m) | 1u, &shift);  /* | 1: the top bit stays */
    return (hi != 0u ? 64 : 32) - shift;
}

/* Direction of an int64 vector (any common scale): shift it down until every component is below
 * 2^30 in magnitude (each halving rounds toward zero), then divide each by the length. The shift
 * loses at most 2^-30 relative precision. The halvings are counted, not looped: with M the largest
 * magnitude they run while floor(M / 2^j) >= 2^30, i.e. k = bit length of M - 30 times (looped,
 * up to 30 iterations of three 64-bit divisions on rv32: this function took 0.88 M of the
 * landscape's start-up instructions, 0.47 M now). */
static FW_BUILD_ONCE uvec3 vec_direction64(int64_t x, int64_t y, int64_t z)
{
    uvec3 u = {0, 0, 0};
    uint64_t len;
    uint64_t m = vec_mag64(x);

    m = vec_mag64(y) > m ? vec_mag64(y) : m;
    m = vec_mag64(z) > m ? vec_mag64(z) : m;
    const int32_t k = vec_bit_length64(m) - 30;
    if (k > 0) {
        x = vec_div_pow2(x, k);
        y = vec_div_pow2(y, k);
        z = vec_div_pow2(z, k);
    }
    len = fx_isqrt64((uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z));
    if (len == 0u) {
        return u;
    }
    /* |x| <= len, so x * 2^30 / len is within [-2^30, 2^30]: fits q2_30. */
    u.x = (unit_t)((x * Q30_ONE) / (int64_t)len);
    u.y = (unit_t)((y * Q30_ONE) / (int64_t)len);
    u.z = (unit_t)((z * Q30_ONE) / (int64_t)len);
    return u;
}
#endif

FW_BUILD_ONCE uvec3 vec3_direction(vec3 v)
{
#if REAL_IS_FIXED
    return vec_direction64(v.x, v.y, v.z);
#else
    const float len = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
    uvec3 u = {0.0f, 0.0f, 0.0f};

    if (len > 0.0f) {
        u.x = v.x / len;
        u.y = v.y / len;
        u.z = v.z / len;
    }
    return u;
#endif
}

FW_BUILD_ONCE uvec3 uvec3_normalize(uvec3 u)
{
#if REAL_IS_FIXED
    return vec_direction64(u.x, u.y, u.z);
#else
    return vec3_direction(vec3_make(u.x, u.y, u.z));
#endif
}

FW_BUILD_ONCE uvec3 uvec3_mean_direction(const uvec3 *u, uint32_t n)
{
#if REAL_IS_FIXED
    /* n <= 64 unit vectors of |u_i| <= 2^30 (q2_30, a little over 1 at most): sums below 2^37. */
    int64_t x = 0;
    int64_t y = 0;
    int64_t z = 0;

    for (uint32_t i = 0; i < n; i++) {
        x += u[i].x;
        y += u[i].y;
        z += u[i].z;
    }
    return vec_direction64(x, y, z);
#else
    vec3 s = vec3_make(0.0f, 0.0f, 0.0f);

    for (uint32_t i = 0; i < n; i++) {
        s.x += u[i].x;
        s.y += u[i].y;
        s.z += u[i].z;
    }
    return vec3_direction(s);
#endif
}

FW_BUILD_ONCE uvec3 vec3_triangle_normal(vec3 a, vec3 b, vec3 c)
{
#if REAL_IS_FIXED
    const int64_t e1x = (int64_t)b.x - a.x;
    const int64_t e1y = (int64_t)b.y - a.y;
    const int64_t e1z = (int64_t)b.z - a.z;
    const int64_t e2x = (int64_t)c.x - a.x;
    const int64_t e2y = (int64_t)c.y - a.y;
    const int64_t e2z = (int64_t)c.z - a.z;

    return vec_direction64(e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x);
#else
    const vec3 e1 = vec3_sub(b, a);
    const vec3 e2 = vec3_sub(c, a);

    return vec3_direction(vec3_make(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                                    e1.x * e2.y - e1.y * e2.x));
#endif
}

mat3 mat3_identity(void)
{
    mat3 m = {{{UNIT_ONE, 0, 0}, {0, UNIT_ONE, 0}, {0, 0, UNIT_ONE}}};

    return m;
}

mat3 mat3_mul(const mat3 *a, const mat3 *b)
{
    mat3 r;

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
#if REAL_IS_FIXED
            r.m[i][j] = vec_round30((int64_t)a->m[i][0] * b->m[0][j] +
                                    (int64_t)a->m[i][1] * b->m[1][j] +
                                    (int64_t)a->m[i][2] * b->m[2][j]);
#else
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] +
                        a->m[i][2] * b->m[2][j];
#endif
        }
    }
    return r;
}

mat3 mat3_transpose(const mat3 *a)
{
    mat3 r;

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            r.m[i][j] = a->m[j][i];
        }
    }
    return r;
}

vec3 mat3_apply(const mat3 *m, vec3 v)
{
    vec3 out;
    uvec3 row;

    row = mat3_row(m, 0);
    out.x = vec3_dot_unit(v, row);
    row = mat3_row(m, 1);
    out.y = vec3_dot_unit(v, row);
    row = mat3_row(m, 2);
    out.z = vec3_dot_unit(v, row);
    return out;
}

uvec3 mat3_apply_unit(const mat3 *m, uvec3 v)
{
    uvec3 out;

    out.x = uvec3_dot(mat3_row(m, 0), v);
    out.y = uvec3_dot(mat3_row(m, 1), v);
    out.z = uvec3_dot(mat3_row(m, 2), v);
    return out;
}

uvec3 mat3_apply_transposed_unit(const mat3 *m, uvec3 v)
{
    const uvec3 c0 = {m->m[0][0], m->m[1][0], m->m[2][0]};
    const uvec3 c1 = {m->m[0][1], m->m[1][1], m->m[2][1]};
    const uvec3 c2 = {m->m[0][2], m->m[1][2], m->m[2][2]};
    uvec3 out;

    out.x = uvec3_dot(c0, v);
    out.y = uvec3_dot(c1, v);
    out.z = uvec3_dot(c2, v);
    return out;
}

uvec3 mat3_row(const mat3 *m, int i)
{
    uvec3 r = {m->m[i][0], m->m[i][1], m->m[i][2]};

    return r;
}

mat3 mat3_rotation(int axis, fx_angle a)
{
    const unit_t s = unit_from_q16(fx_sin(a));
    const unit_t c = unit_from_q16(fx_cos(a));
    const int i = (axis + 1) % 3;  /* the axis turned by a positive angle ... */
    const int j = (axis + 2) % 3;  /* ... towards this one */
    mat3 r = mat3_identity();

    r.m[i][i] = c;
    r.m[i][j] = -s;
    r.m[j][i] = s;
    r.m[j][j] = c;
    return r;
}

#if REAL_IS_FIXED
/* unit_mul(unit_from_q16(a), unit_from_q16(b)) for table sines and cosines (|a|, |b| <= 2^16),
 * without its saturation checks: the product (a 2^14)(b 2^14) / 2^30, rounded, is
 * floor((a b + 2) / 4) — the same value — and |a b| <= 2^32 makes it at most 2^30: in range. */
static inline unit_t vec_sincos_mul(q16_16 a, q16_16 b)
{
    return (unit_t)(((int64_t)a * b + 2) >> 2);
}
#endif

mat3 mat3_from_yaw_pitch(fx_angle yaw, fx_angle pitch)
{
#if REAL_IS_FIXED
    /* Table values are within [-1, 1] (q16_16 |v| <= 2^16): * 2^14 is an exact q2_30, no
     * saturation check needed; the products as unit_mul would give them (vec_sincos_mul). */
    const q16_16 sy16 = fx_sin(yaw);
    const q16_16 cy16 = fx_cos(yaw);
    const q16_16 sp16 = fx_sin(pitch);
    const q16_16 cp16 = fx_cos(pitch);
    mat3 r;

    r.m[0][0] = cy16 * 16384;
    r.m[0][1] = 0;
    r.m[0][2] = sy16 * 16384;
    r.m[1][0] = vec_sincos_mul(sp16, sy16);
    r.m[1][1] = cp16 * 16384;
    r.m[1][2] = -vec_sincos_mul(sp16, cy16);
    r.m[2][0] = -vec_sincos_mul(cp16, sy16);
    r.m[2][1] = sp16 * 16384;
    r.m[2][2] = vec_sincos_mul(cp16, cy16);
    return r;
#else
    const unit_t sy = unit_from_q16(fx_sin(yaw));
    const unit_t cy = unit_from_q16(fx_cos(yaw));
    const unit_t sp = unit_from_q16(fx_sin(pitch));
    const unit_t cp = unit_from_q16(fx_cos(pitch));
    mat3 r;

    /*      | 1  0    0  |        |  cy  0  sy |
     * Rx = | 0  cp  -sp |   Ry = |  0   1  0  |   R = Rx Ry, written out: four products.
     *      | 0  sp   cp |        | -sy  0  cy |
     */
    r.m[0][0] = cy;
    r.m[0][1] = 0;
    r.m[0][2] = sy;
    r.m[1][0] = unit_mul(sp, sy);
    r.m[1][1] = cp;
    r.m[1][2] = unit_sub(0, unit_mul(sp, cy));
    r.m[2][0] = unit_sub(0, unit_mul(cp, sy));
    r.m[2][1] = sp;
    r.m[2][2] = unit_mul(cp, cy);
    return r;
#endif
}

/* v * (3 - v.v) / 2: one Newton step towards unit length. */
static FW_ONCE_A_FRAME uvec3 vec_renorm_length(uvec3 v)
{
    const unit_t k = unit_sub(UNIT_C(1.5), unit_mul(UNIT_C(0.5), uvec3_dot(v, v)));
    uvec3 r = {unit_mul(v.x, k), unit_mul(v.y, k), unit_mul(v.z, k)};

    return r;
}

FW_ONCE_A_FRAME void mat3_renormalize(mat3 *m)
{
    const uvec3 x = mat3_row(m, 0);
    const uvec3 y = mat3_row(m, 1);
    const unit_t half_err = unit_mul(uvec3_dot(x, y), UNIT_C(0.5));
    uvec3 xo;
    uvec3 yo;
    uvec3 zo;

    xo.x = unit_sub(x.x, unit_mul(half_err, y.x));
    xo.y = unit_sub(x.y, unit_mul(half_err, y.y));
    xo.z = unit_sub(x.z, unit_mul(half_err, y.z));
    yo.x = unit_sub(y.x, unit_mul(half_err, x.x));
    yo.y = unit_sub(y.y, unit_mul(half_err, x.y));
    yo.z = unit_sub(y.z, unit_mul(half_err, x.z));
    zo = uvec3_cross(xo, yo);
    xo = vec_renorm_length(xo);
    yo = vec_renorm_length(yo);
    zo = vec_renorm_length(zo);
    m->m[0][0] = xo.x;
    m->m[0][1] = xo.y;
    m->m[0][2] = xo.z;
    m->m[1][0] = yo.x;
    m->m[1][1] = yo.y;
    m->m[1][2] = yo.z;
    m->m[2][0] = zo.x;
    m->m[2][1] = zo.y;
    m->m[2][2] = zo.z;
}

vec3 xf_eye(const xf_affine *xf)
{
    const unit_t(*m)[3] = xf->r.m;
    const vec3 t = xf->t;
#if REAL_IS_FIXED
    /* Column j of r times t, as vec3_dot_unit_fast forms a dot product: |t_i| < 4096, so 4 t_i
     * fits int32, and each term is floored (the sum low by less than 3 units of 2^-16). */
    const int32_t x4 = t.x * 4;
    const int32_t y4 = t.y * 4;
    const int32_t z4 = t.z * 4;

    return vec3_make(-(fx_mulh(m[0][0], x4) + fx_mulh(m[1][0], y4) + fx_mulh(m[2][0], z4)),
                     -(fx_mulh(m[0][1], x4) + fx_mulh(m[1][1], y4) + fx_mulh(m[2][1], z4)),
                     -(fx_mulh(m[0][2], x4) + fx_mulh(m[1][2], y4) + fx_mulh(m[2][2], z4)));
#else
    return vec3_make(-(m[0][0] * t.x + m[1][0] * t.y + m[2][0] * t.z),
                     -(m[0][1] * t.x + m[1][1] * t.y + m[2][1] * t.z),
                     -(m[0][2] * t.x + m[1][2] * t.y + m[2][2] * t.z));
#endif
}

/* One output coordinate (row m of the transform, offset t) of the eight corners, written to
 * out[i] + offset: partial sums over z, then y, then x. */
static inline void xf_box_row(const unit_t m[3], int32_t t, const int32_t lo4[3],
                              const int32_t hi4[3], vec3 out[8], int row)
{
    const int32_t z0 = t + fx_mulh(m[2], lo4[2]);
    const int32_t z1 = t + fx_mulh(m[2], hi4[2]);
    const int32_t y_lo = fx_mulh(m[1], lo4[1]);
    const int32_t y_hi = fx_mulh(m[1], hi4[1]);
    const int32_t x_lo = fx_mulh(m[0], lo4[0]);
    const int32_t x_hi = fx_mulh(m[0], hi4[0]);
    const int32_t yz[4] = {z0 + y_lo, z0 + y_hi, z1 + y_lo, z1 + y_hi};  /* y bit + 2 z bit */

    for (int k = 0; k < 4; k++) {
        real_t *even = (row == 0) ? &out[2 * k].x : ((row == 1) ? &out[2 * k].y : &out[2 * k].z);
        real_t *odd = (row == 0) ? &out[2 * k + 1].x
                                 : ((row == 1) ? &out[2 * k + 1].y : &out[2 * k + 1].z);

        *even = yz[k] + x_lo;
        *odd = yz[k] + x_hi;
    }
}

void xf_apply_box(const xf_affine *xf, vec3 lo, vec3 hi, vec3 out[8])
{
#if REAL_IS_FIXED
    const int32_t lo4[3] = {lo.x * 4, lo.y * 4, lo.z * 4};
    const int32_t hi4[3] = {hi.x * 4, hi.y * 4, hi.z * 4};

    xf_box_row(xf->r.m[0], xf->t.x, lo4, hi4, out, 0);
    xf_box_row(xf->r.m[1], xf->t.y, lo4, hi4, out, 1);
    xf_box_row(xf->r.m[2], xf->t.z, lo4, hi4, out, 2);
#else
    for (int i = 0; i < 8; i++) {
        out[i] = xf_apply(xf, vec3_make((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                        (i & 4) ? hi.z : lo.z));
    }
#endif
}
