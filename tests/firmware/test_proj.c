/*
 * test_proj.c — the projection against a double-precision reference (error in 1/16 px), the
 * whole vertex path (transform + projection) against double, outcodes, the near plane (a vertex
 * exactly on it is in front), the guard band, and the depths.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "render/proj.h"
#include "test_util.h"
#include "unit.h"

static double rnd(double lo, double hi)
{
    return lo + (hi - lo) * ((double)unit_rand() / 4294967296.0);
}

/* The frames and focal lengths the projection is checked at: the contract's default frame, the
 * largest (focal lengths scaled to 480 lines take the smaller multiplier shift, proj.h), and both
 * ends of the focal range. */
static const struct {
    uint32_t w, h;
    int32_t focal_px;
} frames[] = {
    {GPU_FB_WIDTH, GPU_FB_HEIGHT, 200},
    {GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT, 200},
    {GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT, 255},
    {GPU_FB_WIDTH, GPU_FB_HEIGHT, 64},
};
#define N_FRAMES (sizeof frames / sizeof frames[0])

static struct proj_setup frame_setup(unsigned k)
{
    struct proj_setup ps;

    proj_setup_init(&ps, frames[k].focal_px, to_real(160.0), frames[k].w, frames[k].h);
    return ps;
}

static struct proj_setup test_setup(void)
{
    return frame_setup(0);
}

/* The exact projection of a view point under ps, Q12.4. */
static double exact_sx(const struct proj_setup *ps, double x, double z)
{
    return ps->cx_q4 + ps->focal_q4 * x / z;
}

static double exact_sy(const struct proj_setup *ps, double y, double z)
{
    return ps->cy_q4 - ps->focal_q4 * y / z;
}

/* proj.h's bound on the error of a projected offset: 0.58 with the larger multiplier shift. */
static double proj_bound(const struct proj_setup *ps)
{
    return (REAL_IS_FIXED && ps->off_shift == 20) ? 0.64 : 0.58;
}

/*
 * proj.h states: for a view point with |x|, |y| < 4096 and near <= z, a projected vertex (not
 * beyond the guard band) lies within 0.58 sixteenths of a pixel of c + f x / z computed exactly.
 */
void test_proj_vs_double(void)
{
    for (unsigned k = 0; k < N_FRAMES; k++) {
        const struct proj_setup ps = frame_setup(k);
        const double bound = proj_bound(&ps);
        double worst = 0.0;
        int projected = 0;

        for (int i = 0; i < 150000; i++) {
            const double zmax = (i % 3 == 0) ? 1.0 : ((i % 3 == 1) ? 20.0 : 150.0);
            const vec3 v = v3(rnd(-40.0, 40.0) * (zmax / 20.0), rnd(-40.0, 40.0) * (zmax / 20.0),
                              rnd(0.25, zmax));
            const double x = rd(v.x);
            const double y = rd(v.y);
            const double z = rd(v.z);
            const double ex = exact_sx(&ps, x, z);
            const double ey = exact_sy(&ps, y, z);
            struct proj_vertex pv;

            proj_point(&ps, v, &pv);
            CHECK((pv.code & PROJ_OUT_NEAR) == 0);
            if ((pv.code & PROJ_OUT_GUARD) != 0) {
                /* Beyond the band: the exact offset says so too (up to the rounding). */
                CHECK(fabs(ex - ps.cx_q4) > PROJ_GUARD_Q4 - 1.0 ||
                      fabs(ps.cy_q4 - ey) > PROJ_GUARD_Q4 - 1.0);
                continue;
            }
            projected++;
            worst = fmax(worst, fmax(fabs(pv.sx - ex), fabs(pv.sy - ey)));
        }
        printf("  projection (%s, %ux%u, f %d px at %u lines): max error %.4f / 16 px over %d "
               "vertices (bound %.2f)\n", REAL_BACKEND_NAME, (unsigned)frames[k].w,
               (unsigned)frames[k].h, (int)frames[k].focal_px, (unsigned)PROJ_FOCAL_REF_LINES,
               worst, projected, bound);
        if (!(worst < bound)) {
            unit_fail(__FILE__, __LINE__, "projection error %.4f >= %.2f (1/16 px) at %ux%u",
                      worst, bound, (unsigned)frames[k].w, (unsigned)frames[k].h);
        }
        CHECK(projected > 40000);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* Focal lengths are scaled to the frame: the same field of view at every size (exactly twice
 * the focal length at twice the lines), a multiplier within 31 bits, and the limits of the
 * clamp. */
void test_proj_focal_scaling(void)
{
    struct proj_setup a;
    struct proj_setup b;

    proj_setup_init(&a, 200, to_real(160.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    proj_setup_init(&b, 200, to_real(160.0), 2u * GPU_FB_WIDTH, 2u * GPU_FB_HEIGHT);
    CHECK_EQ(a.focal_q4, 3200);
    CHECK_EQ(b.focal_q4, 6400);
    CHECK_EQ(a.off_shift, 21);
    CHECK_EQ(b.off_shift, 20);
    CHECK_EQ(b.cx_q4, 2 * a.cx_q4);
    CHECK_EQ(b.x_last, 16 * (2 * (int32_t)GPU_FB_WIDTH - 1) + 8);
    proj_setup_init(&b, 1000, to_real(160.0), GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT);
    CHECK(b.focal_q4 < 8192 && b.focal_hi < 0x80000000u);
    proj_setup_init(&b, 1, to_real(160.0), 16, 16);  /* a tiny frame keeps f_q4 >= 1024 */
    CHECK_EQ(b.focal_q4, 1024);
    /* A point seen at one frame lands at the same fraction of the other (within the rounding). */
    for (int i = 0; i < 1000; i++) {
        const double z = rnd(1.0, 100.0);
        const vec3 v = v3(rnd(-0.7, 0.7) * z, rnd(-0.5, 0.5) * z, z);
        struct proj_vertex pa;
        struct proj_vertex pb;

        proj_setup_init(&b, 200, to_real(160.0), 2u * GPU_FB_WIDTH, 2u * GPU_FB_HEIGHT);
        proj_point(&a, v, &pa);
        proj_point(&b, v, &pb);
        CHECK(abs(2 * pa.sx - pb.sx) <= 2 && abs(2 * pa.sy - pb.sy) <= 2);
    }
}

/* The whole vertex path, model space -> screen: rotation, translation and projection against
 * double, with the transform's error (< 3 units of 2^-16) scaled by f / z added to the bound. */
void test_proj_vertex_path_vs_double(void)
{
    double worst_margin = -1.0;

    for (int i = 0; i < 100000; i++) {
        const struct proj_setup ps = frame_setup((unsigned)i % N_FRAMES);
        xf_affine xf;
        const vec3 p = v3(rnd(-3, 3), rnd(-3, 3), rnd(-3, 3));
        vec3 view;
        struct proj_vertex pv;
        double e[3];

        xf.r = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        xf.t = v3(rnd(-2, 2), rnd(-2, 2), rnd(5.5, 30.0));
        view = xf_apply(&xf, p);
        proj_point(&ps, view, &pv);
        for (int r = 0; r < 3; r++) {
            e[r] = ud(xf.r.m[r][0]) * rd(p.x) + ud(xf.r.m[r][1]) * rd(p.y) +
                   ud(xf.r.m[r][2]) * rd(p.z) + rd(r == 0 ? xf.t.x : (r == 1 ? xf.t.y : xf.t.z));
        }
        {
            const double ex = exact_sx(&ps, e[0], e[2]);
            const double ey = exact_sy(&ps, e[1], e[2]);
            const double bound = proj_bound(&ps) + 3.0 * 3.0 / 65536.0 * ps.focal_q4 / e[2] * 1.5;
            const double err = fmax(fabs(pv.sx - ex), fabs(pv.sy - ey));

            worst_margin = fmax(worst_margin, err - bound);
        }
    }
    if (!(worst_margin < 0.0)) {
        unit_fail(__FILE__, __LINE__, "vertex path error exceeds its bound by %.4f / 16 px",
                  worst_margin);
    }
}

/* A vertex in front of the near plane is not projected; one exactly on it is, and lands where
 * f x / near puts it. */
void test_proj_near_plane(void)
{
    const struct proj_setup ps = test_setup();
    struct proj_vertex pv;

    proj_point(&ps, v3(0.1, 0.1, 0.25 - 1.0 / 65536.0), &pv);
    CHECK_EQ(pv.code, PROJ_OUT_NEAR);
    proj_point(&ps, v3(0.1, -0.05, -3.0), &pv);
    CHECK_EQ(pv.code, PROJ_OUT_NEAR);
    proj_point(&ps, v3(0.1, -0.05, 0.25), &pv);  /* exactly on the plane */
    CHECK((pv.code & PROJ_OUT_NEAR) == 0);
    CHECK(abs(pv.sx - (2560 + (int)lround(3200.0 * rd(to_real(0.1)) / 0.25))) <= 1);
    CHECK(abs(pv.sy - (1920 + (int)lround(3200.0 * 0.05 / 0.25))) <= 1);
    CHECK_EQ(pv.zbuf, 0);
}

/* Outcodes agree with the coordinates: LEFT exactly when sx < 8 (no pixel centre at or right of
 * it), RIGHT when sx > 16 (W - 1) + 8, TOP/BOTTOM likewise, FAR when z > far; at every frame. */
void test_proj_outcodes(void)
{
    for (int i = 0; i < 200000; i++) {
        const struct proj_setup ps = frame_setup((unsigned)i % N_FRAMES);
        const double z = rnd(0.3, 200.0);
        const vec3 v = v3(rnd(-1.2, 1.2) * z, rnd(-0.9, 0.9) * z, z);
        const int32_t w = (int32_t)ps.width;
        const int32_t h = (int32_t)ps.height;
        struct proj_vertex pv;

        proj_point(&ps, v, &pv);
        if ((pv.code & PROJ_OUT_GUARD) != 0) {
            continue;
        }
        CHECK(((pv.code & PROJ_OUT_LEFT) != 0) == (pv.sx < 8));
        CHECK(((pv.code & PROJ_OUT_RIGHT) != 0) == (pv.sx > 16 * (w - 1) + 8));
        CHECK(((pv.code & PROJ_OUT_TOP) != 0) == (pv.sy < 8));
        CHECK(((pv.code & PROJ_OUT_BOTTOM) != 0) == (pv.sy > 16 * (h - 1) + 8));
        CHECK(((pv.code & PROJ_OUT_FAR) != 0) == (rd(v.z) > 160.0));
    }
}

/* Beyond the guard band: flagged, coordinates clamped to the band (still int16), side codes
 * right. Inside it, even near its edge: not flagged. */
void test_proj_guard_band(void)
{
    for (unsigned k = 0; k < N_FRAMES; k++) {
        const struct proj_setup ps = frame_setup(k);
        const double f_px = ps.focal_q4 / 16.0;
        struct proj_vertex pv;

        proj_point(&ps, v3(-100.0, 0.0, 1.0), &pv);  /* f x / z = -6400 px or more */
        CHECK(pv.code & PROJ_OUT_GUARD);
        CHECK(pv.code & PROJ_OUT_LEFT);
        CHECK_EQ(pv.sx, ps.cx_q4 - PROJ_GUARD_Q4);
        proj_point(&ps, v3(4000.0, -4000.0, 0.25), &pv);  /* the largest offsets there are */
        CHECK(pv.code & PROJ_OUT_GUARD);
        CHECK((pv.code & (PROJ_OUT_RIGHT | PROJ_OUT_BOTTOM)) == (PROJ_OUT_RIGHT | PROJ_OUT_BOTTOM));
        CHECK_EQ(pv.sx, ps.cx_q4 + PROJ_GUARD_Q4);  /* within int16 at the largest frame */
        CHECK_EQ(pv.sy, ps.cy_q4 + PROJ_GUARD_Q4);
        proj_point(&ps, v3(1520.0 / f_px, 1520.0 / f_px, 1.0), &pv);  /* 1520 px: inside */
        CHECK((pv.code & PROJ_OUT_GUARD) == 0);
        CHECK(abs(pv.sx - (ps.cx_q4 + 24320)) <= 2);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* Sort depth: z in 1/128 units, capped so three fit 16 bits; GPU depth 65535 (1 - near/z). */
void test_proj_depths(void)
{
    struct proj_setup ps = test_setup();
    struct proj_vertex pv;

    ps.zbuf = true;
    proj_point(&ps, v3(0, 0, 1.0), &pv);
    CHECK_EQ(pv.depth, 128);
    CHECK(abs(pv.zbuf - 49151) <= 2);  /* 65535 * 0.75 */
    proj_point(&ps, v3(0, 0, 0.25), &pv);
    CHECK(pv.zbuf <= 2);
    proj_point(&ps, v3(0, 0, 2.5), &pv);
    CHECK_EQ(pv.depth, 320);
    CHECK(abs(pv.zbuf - 58981) <= 2);  /* 65535 * 0.9 */
    proj_point(&ps, v3(0, 0, 300.0), &pv);
    CHECK_EQ(pv.depth, PROJ_DEPTH_MAX);
    CHECK(3u * PROJ_DEPTH_MAX <= 0xFFFFu);
    {
        uint16_t last = 0;

        for (double z = 0.25; z < 150.0; z *= 1.01) {
            proj_point(&ps, v3(0, 0, z), &pv);
            CHECK(pv.zbuf >= last);  /* monotonic in z */
            last = pv.zbuf;
        }
    }
    ps.zbuf = false;
    proj_point(&ps, v3(0, 0, 2.5), &pv);
    CHECK_EQ(pv.zbuf, 0);
}

/* The shortcut for objects known to be inside the frustum gives the same position and depths as
 * the full projection, only without outcode work. */
void test_proj_inside_matches(void)
{
    struct proj_setup ps = test_setup();

    ps.zbuf = true;
    for (int i = 0; i < 100000; i++) {
        const double z = rnd(0.3, 150.0);
        const vec3 v = v3(rnd(-0.75, 0.75) * z, rnd(-0.55, 0.55) * z, z);
        struct proj_vertex a;
        struct proj_vertex b;

        proj_point(&ps, v, &a);
        proj_point_inside(&ps, v, &b);
        CHECK(a.sx == b.sx && a.sy == b.sy && a.zbuf == b.zbuf && a.depth == b.depth);
        CHECK_EQ(b.code, 0);
        CHECK((a.code & (PROJ_OUT_NEAR | PROJ_OUT_GUARD | PROJ_OUT_FAR)) == 0);
    }
}
