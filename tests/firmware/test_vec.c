/*
 * test_vec.c — rotations and their conventions, matrix arithmetic against double, the vertex
 * transform's stated error, face normals, and a million accumulated small rotations staying
 * orthonormal and on course (re-orthonormalisation).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "test_util.h"
#include "unit.h"
#include "math/vec.h"

static double mat_err_vs(const mat3 *m, const double r[3][3])
{
    double e = 0.0;

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            e = fmax(e, fabs(ud(m->m[i][j]) - r[i][j]));
        }
    }
    return e;
}

static double det3(const double m[3][3])
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

void test_vec_rotation_conventions(void)
{
    const vec3 x = v3(1, 0, 0);
    const vec3 y = v3(0, 1, 0);
    const vec3 z = v3(0, 0, 1);
    mat3 r;
    vec3 p;

    /* About y, +z turns towards +x; about x, +y towards +z; about z, +x towards +y. */
    r = mat3_rotation(1, FX_ANGLE_DEG(90));
    p = mat3_apply(&r, z);
    CHECK(fabs(rd(p.x) - 1.0) < 1e-4 && fabs(rd(p.z)) < 1e-4);
    r = mat3_rotation(0, FX_ANGLE_DEG(90));
    p = mat3_apply(&r, y);
    CHECK(fabs(rd(p.z) - 1.0) < 1e-4 && fabs(rd(p.y)) < 1e-4);
    r = mat3_rotation(2, FX_ANGLE_DEG(90));
    p = mat3_apply(&r, x);
    CHECK(fabs(rd(p.y) - 1.0) < 1e-4 && fabs(rd(p.x)) < 1e-4);
    /* Rx(pitch) Ry(yaw) equals the product of the two single rotations. */
    for (int i = 0; i < 500; i++) {
        const fx_angle yaw = (fx_angle)unit_rand();
        const fx_angle pitch = (fx_angle)unit_rand();
        const mat3 ry = mat3_rotation(1, yaw);
        const mat3 rx = mat3_rotation(0, pitch);
        const mat3 prod = mat3_mul(&rx, &ry);
        const mat3 direct = mat3_from_yaw_pitch(yaw, pitch);
        double ref[3][3];

        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                ref[a][b] = ud(prod.m[a][b]);
            }
        }
        CHECK(mat_err_vs(&direct, ref) < 4 * TEST_UNIT_ULP + 1e-9);
        /* table sines and cosines are each within 1e-4: s^2 + c^2 within 3e-4 of 1, and a row
         * of products of two such within 6e-4 */
        CHECK(mat_ortho_err(&direct) < 6e-4);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* mat3_mul and mat3_apply against double on the same (quantised) inputs: one rounding. */
void test_vec_mat3_vs_double(void)
{
    for (int i = 0; i < 2000; i++) {
        const mat3 a = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        const mat3 b = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        const mat3 c = mat3_mul(&a, &b);
        const vec3 p = v3(((int32_t)(unit_rand() % 4000u) - 2000) / 3.0,
                          ((int32_t)(unit_rand() % 4000u) - 2000) / 3.0,
                          ((int32_t)(unit_rand() % 4000u) - 2000) / 3.0);
        const vec3 q = mat3_apply(&a, p);
        double ref[3][3];

        for (int r = 0; r < 3; r++) {
            double qr = 0.0;

            for (int s = 0; s < 3; s++) {
                ref[r][s] = 0.0;
                for (int k = 0; k < 3; k++) {
                    ref[r][s] += ud(a.m[r][k]) * ud(b.m[k][s]);
                }
                qr += ud(a.m[r][s]) * rd((s == 0) ? p.x : ((s == 1) ? p.y : p.z));
            }
            CHECK(fabs(rd((r == 0) ? q.x : ((r == 1) ? q.y : q.z)) - qr) <=
                  0.5 * TEST_REAL_ULP + 1e-4 * (REAL_IS_FIXED ? 0.0 : 1.0));
        }
        CHECK(mat_err_vs(&c, ref) <= 0.5 * TEST_UNIT_ULP + (REAL_IS_FIXED ? 1e-12 : 3e-7));
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* vec.h: xf_apply is low by less than 3 units of 2^-16 (fixed), for |p| < 8192, |t| < 4096. */
void test_vec_xf_apply_error(void)
{
    double worst_lo = 0.0;
    double worst_hi = 0.0;

    for (int i = 0; i < 100000; i++) {
        xf_affine xf;
        const double range = (i & 1) ? 8000.0 : 50.0;
        const vec3 p = v3(((double)unit_rand() / 4294967296.0 - 0.5) * 2.0 * range,
                          ((double)unit_rand() / 4294967296.0 - 0.5) * 2.0 * range,
                          ((double)unit_rand() / 4294967296.0 - 0.5) * 2.0 * range);
        vec3 out;
        double o[3];

        xf.r = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        xf.t = v3(((double)unit_rand() / 4294967296.0 - 0.5) * 8000.0, 12.5, -4000.0);
        out = xf_apply(&xf, p);
        o[0] = rd(out.x);
        o[1] = rd(out.y);
        o[2] = rd(out.z);
        for (int r = 0; r < 3; r++) {
            const double exact = ud(xf.r.m[r][0]) * rd(p.x) + ud(xf.r.m[r][1]) * rd(p.y) +
                                 ud(xf.r.m[r][2]) * rd(p.z) + rd((r == 0) ? xf.t.x : ((r == 1) ? xf.t.y : xf.t.z));
            const double e = o[r] - exact;

            worst_lo = fmin(worst_lo, e);
            worst_hi = fmax(worst_hi, e);
        }
    }
#if REAL_IS_FIXED
    if (!(worst_lo > -3.0 / 65536.0 && worst_hi <= 1e-12)) {
        unit_fail(__FILE__, __LINE__, "xf_apply error range [%g, %g] units of 2^-16, stated (-3, 0]",
                  worst_lo * 65536.0, worst_hi * 65536.0);
    }
#else
    CHECK(worst_lo > -2e-3 && worst_hi < 2e-3);  /* float: relative 6e-8 of values up to ~18000 */
#endif
}

/* vec.h: xf_apply_box gives exactly xf_apply's result for each of the eight corners, in the
 * documented corner order, for random boxes within the transform's range rule. */
void test_vec_xf_apply_box_exact(void)
{
    for (int i = 0; i < 20000; i++) {
        xf_affine xf;
        const double range = (i & 1) ? 4000.0 : 2.0;
        const vec3 lo = v3(-((double)unit_rand() / 4294967296.0) * range,
                           -((double)unit_rand() / 4294967296.0) * range,
                           ((double)unit_rand() / 4294967296.0 - 0.5) * range);
        const vec3 hi = v3(((double)unit_rand() / 4294967296.0) * range,
                           ((double)unit_rand() / 4294967296.0) * range,
                           ((double)unit_rand() / 4294967296.0) * range);
        vec3 corner[8];

        xf.r = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        xf.t = v3(((double)unit_rand() / 4294967296.0 - 0.5) * 8000.0, 12.5, -4000.0);
        xf_apply_box(&xf, lo, hi, corner);
        for (int k = 0; k < 8; k++) {
            const vec3 want = xf_apply(&xf, vec3_make((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y,
                                                      (k & 4) ? hi.z : lo.z));

            if (corner[k].x != want.x || corner[k].y != want.y || corner[k].z != want.z) {
                unit_fail(__FILE__, __LINE__, "xf_apply_box corner %d differs from xf_apply", k);
                return;
            }
        }
    }
}

void test_vec_triangle_normal(void)
{
    uvec3 n;

    /* (b - a) x (c - a) for a = 0, b = +y, c = +x is -z. */
    n = vec3_triangle_normal(v3(0, 0, 0), v3(0, 1, 0), v3(1, 0, 0));
    CHECK(fabs(ud(n.z) + 1.0) < 1e-6 && fabs(ud(n.x)) < 1e-6 && fabs(ud(n.y)) < 1e-6);
    /* Far from the origin and large: the exact int64 cross product does not overflow. */
    n = vec3_triangle_normal(v3(-8000, 8000, 8000), v3(8000, 8000, 8000), v3(-8000, 8000, -8000));
    CHECK(fabs(ud(n.y) - 1.0) < 1e-6);
    /* Tiny: still a unit vector. */
    n = vec3_triangle_normal(v3(0, 0, 0), v3(0, 0, 0.001), v3(0.001, 0, 0));
    CHECK(fabs(ud(n.y) - 1.0) < 1e-4);
    /* Degenerate: zero. */
    n = vec3_triangle_normal(v3(1, 1, 1), v3(2, 2, 2), v3(3, 3, 3));
    CHECK(ud(n.x) == 0.0 && ud(n.y) == 0.0 && ud(n.z) == 0.0);
    for (int i = 0; i < 2000; i++) {
        const vec3 a = v3((int32_t)(unit_rand() % 200u) - 100, (int32_t)(unit_rand() % 200u) - 100, 3);
        const vec3 b = v3((int32_t)(unit_rand() % 200u) - 100, -7, (int32_t)(unit_rand() % 200u) - 100);
        const vec3 c = v3(5, (int32_t)(unit_rand() % 200u) - 100, (int32_t)(unit_rand() % 200u) - 100);
        const double e1[3] = {rd(b.x) - rd(a.x), rd(b.y) - rd(a.y), rd(b.z) - rd(a.z)};
        const double e2[3] = {rd(c.x) - rd(a.x), rd(c.y) - rd(a.y), rd(c.z) - rd(a.z)};
        double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
        const double len = sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);

        if (len < 1.0) {
            continue;
        }
        n = vec3_triangle_normal(a, b, c);
        CHECK(fabs(ud(n.x) - cr[0] / len) < 1e-6 && fabs(ud(n.y) - cr[1] / len) < 1e-6 &&
              fabs(ud(n.z) - cr[2] / len) < 1e-6);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* The fixed-point direction (vec.c's vec_direction64, reached through vec3_triangle_normal) is the
 * same bit for bit as the plain method it replaced: halve until every component is below 2^30 in
 * magnitude, a bit-by-bit square root, three divisions. Cross products of every magnitude. */
#if REAL_IS_FIXED
static uint32_t ref_isqrt64(uint64_t v)
{
    uint64_t root = 0;
    uint64_t bit = (uint64_t)1 << 62;

    while (bit > v) {
        bit >>= 2;
    }
    while (bit != 0u) {
        if (v >= root + bit) {
            v -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root;
}

static uvec3 ref_direction64(int64_t x, int64_t y, int64_t z)
{
    uvec3 u = {0, 0, 0};
    const int64_t lim = (int64_t)1 << 30;

    while (x >= lim || x <= -lim || y >= lim || y <= -lim || z >= lim || z <= -lim) {
        x /= 2;
        y /= 2;
        z /= 2;
    }
    const uint64_t len = ref_isqrt64((uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z));
    if (len != 0u) {
        u.x = (unit_t)((x * Q30_ONE) / (int64_t)len);
        u.y = (unit_t)((y * Q30_ONE) / (int64_t)len);
        u.z = (unit_t)((z * Q30_ONE) / (int64_t)len);
    }
    return u;
}
#endif

void test_vec_direction_exact(void)
{
#if REAL_IS_FIXED
    for (int i = 0; i < 20000; i++) {
        int32_t c[6];

        for (int k = 0; k < 6; k++) {
            const int32_t magnitude = (int32_t)((unit_rand() >> (unit_rand() % 32u)) / 2u);

            c[k] = (unit_rand() & 1u) ? -magnitude : magnitude;
        }
        const vec3 b = {c[0], c[1], c[2]};
        const vec3 d = {c[3], c[4], c[5]};
        const uvec3 got = vec3_triangle_normal(vec3_make(0, 0, 0), b, d);
        const uvec3 want = ref_direction64((int64_t)b.y * d.z - (int64_t)b.z * d.y,
                                           (int64_t)b.z * d.x - (int64_t)b.x * d.z,
                                           (int64_t)b.x * d.y - (int64_t)b.y * d.x);

        CHECK_EQ(got.x, want.x);
        CHECK_EQ(got.y, want.y);
        CHECK_EQ(got.z, want.z);
    }
#endif
}

/*
 * 10^6 small rotations accumulated into one matrix, re-orthonormalised after each (as the scenes
 * and the object-mode camera do). Compared with the same recurrence in double precision from the
 * same quantised step: the matrix stays orthonormal to the format's precision and its orientation
 * does not drift away from the exact composition.
 */
void test_vec_million_rotations(void)
{
    const mat3 step_y = mat3_rotation(1, 119);   /* 0.65 degrees */
    const mat3 step_x = mat3_rotation(0, 47);    /* 0.26 degrees */
    const mat3 step = mat3_mul(&step_y, &step_x);
    mat3 r = mat3_identity();
    double s[3][3];
    double ref[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double worst_ortho = 0.0;

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            s[i][j] = ud(step.m[i][j]);
        }
    }
    for (int n = 1; n <= 1000000; n++) {
        double t[3][3];

        r = mat3_mul(&step, &r);
        mat3_renormalize(&r);
        /* The reference: the same step, exact product, renormalised by Gram-Schmidt. */
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                t[i][j] = s[i][0] * ref[0][j] + s[i][1] * ref[1][j] + s[i][2] * ref[2][j];
            }
        }
        for (int i = 0; i < 3; i++) {
            double len;

            for (int k = 0; k < i; k++) {
                const double d = t[i][0] * t[k][0] + t[i][1] * t[k][1] + t[i][2] * t[k][2];

                t[i][0] -= d * t[k][0];
                t[i][1] -= d * t[k][1];
                t[i][2] -= d * t[k][2];
            }
            len = sqrt(t[i][0] * t[i][0] + t[i][1] * t[i][1] + t[i][2] * t[i][2]);
            for (int j = 0; j < 3; j++) {
                ref[i][j] = t[i][j] / len;
            }
        }
        if (n % 100000 == 0) {
            worst_ortho = fmax(worst_ortho, mat_ortho_err(&r));
        }
    }
    {
        const double drift = mat_err_vs(&r, ref);
        double m[3][3];

        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[i][j] = ud(r.m[i][j]);
            }
        }
        printf("  million rotations (%s): orthonormality %.2e, drift from exact %.2e, det %.9f\n",
               REAL_BACKEND_NAME, worst_ortho, drift, det3(m));
        CHECK(worst_ortho < (REAL_IS_FIXED ? 1e-7 : 1e-6));  /* ~100 ulp of q2_30 */
        CHECK(fabs(det3(m) - 1.0) < 1e-6);
        CHECK(drift < (REAL_IS_FIXED ? 1e-3 : 1e-2));
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* The fixed backend's mat3_from_yaw_pitch takes a shortcut (table values scaled by 2^14, products
 * by vec_sincos_mul); it must equal Rx(pitch) Ry(yaw) written with the generic unit arithmetic
 * (unit_from_q16, unit_mul, unit_sub), entry for entry, over a grid of angles that includes every
 * table point and the quarter turns. The float backend has no shortcut (it is that arithmetic), so
 * there the test has nothing to compare; its accuracy is test_vec_yaw_pitch_accuracy's. */
void test_vec_yaw_pitch_exact(void)
{
#if REAL_IS_FIXED
    uint32_t bad = 0;

    for (uint32_t y = 0; y < 65536u; y += 61u) {
        for (uint32_t p = 0; p < 65536u; p += 509u) {
            const fx_angle ya = (fx_angle)y;
            const fx_angle pa = (fx_angle)(p + (y & 255u));
            const unit_t sy = unit_from_q16(fx_sin(ya));
            const unit_t cy = unit_from_q16(fx_cos(ya));
            const unit_t sp = unit_from_q16(fx_sin(pa));
            const unit_t cp = unit_from_q16(fx_cos(pa));
            const mat3 m = mat3_from_yaw_pitch(ya, pa);

            bad += m.m[0][0] != cy;
            bad += m.m[0][1] != 0;
            bad += m.m[0][2] != sy;
            bad += m.m[1][0] != unit_mul(sp, sy);
            bad += m.m[1][1] != cp;
            bad += m.m[1][2] != unit_sub(0, unit_mul(sp, cy));
            bad += m.m[2][0] != unit_sub(0, unit_mul(cp, sy));
            bad += m.m[2][1] != sp;
            bad += m.m[2][2] != unit_mul(cp, cy);
        }
    }
    CHECK_EQ(bad, 0);
#endif
}

/* mat3_from_yaw_pitch against Rx(pitch) Ry(yaw) formed in double from first principles: Ry turns
 * +z towards +x (its columns are Ry e_x = (cos, 0, -sin), Ry e_y = e_y, Ry e_z = (sin, 0, cos)),
 * Rx turns +y towards +z, angles are turn fractions of 65536. Tolerance: the sine table is within
 * 1e-4 (test_fixed), an entry is a sine or cosine or the product of two, so within
 * 2e-4 + 2^-29 of the exact value (measured: see the printed maximum). */
void test_vec_yaw_pitch_accuracy(void)
{
    double worst = 0.0;

    for (uint32_t y = 0; y < 65536u; y += 61u) {
        for (uint32_t p = 0; p < 65536u; p += 509u) {
            const fx_angle ya = (fx_angle)y;
            const fx_angle pa = (fx_angle)(p + (y & 255u));
            const double a = 2.0 * TEST_PI * (double)ya / 65536.0;
            const double b = 2.0 * TEST_PI * (double)pa / 65536.0;
            const double ry[3][3] = {{cos(a), 0.0, sin(a)}, {0.0, 1.0, 0.0}, {-sin(a), 0.0, cos(a)}};
            const double rx[3][3] = {{1.0, 0.0, 0.0}, {0.0, cos(b), -sin(b)}, {0.0, sin(b), cos(b)}};
            const mat3 m = mat3_from_yaw_pitch(ya, pa);

            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    const double want = rx[r][0] * ry[0][c] + rx[r][1] * ry[1][c] +
                                        rx[r][2] * ry[2][c];
                    const double err = fabs(ud(m.m[r][c]) - want);

                    worst = (err > worst) ? err : worst;
                }
            }
        }
    }
    printf("  mat3_from_yaw_pitch: max error %.3g against double\n", worst);
    CHECK(worst <= 2e-4 + 1.0 / 536870912.0);
}
