/*
 * test_depth.c - unit tests of the model's depth buffer (contract "Depth",
 * build option ENABLE_ZBUF): the fixed-point plane with trunc / sat32 /
 * floor / clamp at hand-computed pixels (including a triangle whose vertices
 * the winding swap exchanges and a guard-band vertex where trunc and floor
 * differ), saturation of ZA / ZB on thin slivers, the clamp at both ends,
 * CTRL_ZCLEAR, the strict less-than test with write-on-pass, occlusion in
 * both drawing orders, lines ignoring depth, and a GPU built without the
 * depth buffer ignoring CTRL_ZTEST / CTRL_ZCLEAR.
 *
 * All arithmetic below follows the contract's formulas:
 *   dx1 = x1 - x0, dy1 = y1 - y0, dz1 = z1 - z0 (and likewise dx2 ...)
 *   ZA = sat32(trunc(2^16 (dz1 dy2 - dz2 dy1) / area))
 *   ZB = sat32(trunc(2^16 (dz2 dx1 - dz1 dx2) / area))
 *   z(p) = clamp(floor((2^16 z0 + ZA (p.x - x0) + ZB (p.y - y0)) / 2^16),
 *                0, 65535),  p = (16 px + 8, 16 py + 8)
 * with v0, v1, v2 the vertices after the winding swap.
 */
#include <stdlib.h>
#include <string.h>

#include "model_test.h"

#define ZT (GPU_CTRL_ZTEST_MASK)
#define ZC (GPU_CTRL_ZCLEAR_MASK)
#define CL (GPU_CTRL_CLEAR_MASK)

static uint32_t g_tag = 0x2000;

/* Triangle `prim` from vertices vb..vb+2 given as x, y, z triples. */
static void set_tri(gpu_model *m, uint32_t vb, uint32_t prim,
                    const int32_t v[9], uint32_t color)
{
    for (uint32_t k = 0; k < 3; k++) {
        test_set_vtxz(m, vb + k, v[3 * k], v[3 * k + 1], (uint32_t)v[3 * k + 2]);
    }
    test_set_prim(m, prim, vb, vb + 1, vb + 2, color, GPU_PRIM_KIND_TRI);
}

/* The rectangle of pixels x0..x1-1, y0..y1-1 at constant depth z: two
 * triangles (prims prim, prim+1; vertices vb..vb+3) on the pixel corners,
 * split along the diagonal; the fill rule covers each pixel once. */
static void set_rect(gpu_model *m, uint32_t vb, uint32_t prim, int x0, int y0,
                     int x1, int y1, uint32_t z, uint32_t color)
{
    test_set_vtxz(m, vb + 0, 16 * x0, 16 * y0, z);
    test_set_vtxz(m, vb + 1, 16 * x1, 16 * y0, z);
    test_set_vtxz(m, vb + 2, 16 * x1, 16 * y1, z);
    test_set_vtxz(m, vb + 3, 16 * x0, 16 * y1, z);
    test_set_prim(m, prim, vb, vb + 1, vb + 2, color, GPU_PRIM_KIND_TRI);
    test_set_prim(m, prim + 1, vb, vb + 2, vb + 3, color, GPU_PRIM_KIND_TRI);
}

/* A model with the depth buffer keeping `bits` bits (SPAN_W 8, lines). */
static gpu_model *alloc_depth_model(unsigned bits)
{
    gpu_model *m = test_new_model_cfg(8, true, true);
    gpu_model_config cfg = m->cfg;

    cfg.zbuf_bits = bits;
    gpu_model_reset_config(m, &cfg);
    return m;
}

/* Run primitives 0..n-1 over vertices 0..nv-1. */
static void run(gpu_model *m, uint32_t ctrl, uint32_t nv, uint32_t n)
{
    test_batch(m, ctrl, 0, nv, 0, n, 0, g_tag++);
}

/* Triangle 0 (vertices 0..2 as x, y, z triples) alone, on colour and depth buffers just cleared,
 * with the depth test on. */
static void draw_ztest(gpu_model *m, const int32_t v[9], uint32_t color)
{
    set_tri(m, 0, 0, v, color);
    run(m, CL | ZC | ZT, 3, 1);
}

/* Pixels (xs * k, k), k0 <= k < k1, whose depth is not z or (when color >= 0) whose colour is
 * not color. */
static int off_diagonal(const gpu_model *m, int k0, int k1, int xs, uint16_t z, int color)
{
    int bad = 0;
    for (int k = k0; k < k1; k++) {
        bad += test_z(m, xs * k, k) != z;
        bad += color >= 0 && test_back_px(m, xs * k, k) != color;
    }
    return bad;
}

/* The square of pixels 0..9 x 0..9 (prims 0, 1) at depth z in colour `color`, alone, run with
 * ctrl. */
static void draw_square(gpu_model *m, uint32_t ctrl, uint32_t z, uint32_t color)
{
    set_rect(m, 0, 0, 0, 0, 10, 10, z, color);
    run(m, ctrl, 4, 2);
}

/* A pixel and the depth it must hold. */
struct z_at {
    int px, py;
    uint16_t z;
};

/* Each listed pixel holds its depth and (when color >= 0) colour `color`; `what` names the case in
 * a failure. */
static void check_z_at(const gpu_model *m, const struct z_at *want, size_t n, int color,
                       const char *what)
{
    for (size_t i = 0; i < n; i++) {
        if (!CHECK_EQ(test_z(m, want[i].px, want[i].py), want[i].z)) {
            printf("  %s pixel (%d,%d)\n", what, want[i].px, want[i].py);
        }
        if (color >= 0) {
            CHECK_EQ(test_back_px(m, want[i].px, want[i].py), color);
        }
    }
}

static uint32_t perf_pixels(const gpu_model *m)
{
    return gpu_model_read(m, GPU_REG_PERF_PIXELS);
}

/* Entries of the depth buffer different from v. */
static uint32_t z_not(const gpu_model *m, uint16_t v)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        n += m->zbuf[i] != v;
    }
    return n;
}

static uint32_t px_eq(const gpu_model *m, uint8_t v)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        n += gpu_model_back(m)[i] == v;
    }
    return n;
}

/* The occlusion pair: P = pixels 0..9 x 0..9 at depth 100 in colour 1 and Q = 5..14 x 5..14 at
 * 200 in colour 2, P drawn first or (q_first) Q, run with ctrl. */
static void draw_p_q(gpu_model *m, bool q_first, uint32_t ctrl)
{
    set_rect(m, q_first ? 4 : 0, q_first ? 2 : 0, 0, 0, 10, 10, 100, 1);
    set_rect(m, q_first ? 0 : 4, q_first ? 0 : 2, 5, 5, 15, 15, 200, 2);
    run(m, ctrl, 8, 4);
}

/* After draw_p_q: PERF_PIXELS, and the pixels of P's and of Q's colour. */
#define CHECK_P_Q(m, pixels, n_p, n_q)      \
    CHECK_EQ(perf_pixels(m), (pixels));     \
    CHECK_EQ(px_eq((m), 1), (n_p));         \
    CHECK_EQ(px_eq((m), 2), (n_q))

/* ------------------------------------------------ plane, by hand */

static void test_plane(void)
{
    gpu_model *m = test_new_model_cfg(8, true, true);

    /*
     * T1 = (0,0) z 1000, (160,0) z 2001, (0,320) z 5000; area = 160*320 =
     * 51200 > 0 (no swap).  dx1 160, dy1 0, dz1 1001; dx2 0, dy2 320,
     * dz2 4000.
     *   ZA = trunc(65536 * (1001*320 - 4000*0) / 51200)
     *      = trunc(65536 * 6.25625) = trunc(410009.6) = 410009
     *   ZB = 65536 * (4000*160 - 1001*0) / 51200 = 65536 * 12.5 = 819200
     *   z(px,py) = floor((65536000 + 410009 (16px+8) + 819200 (16py+8))
     *                    / 65536)
     * (0,0): 65536000 + 3280072 + 6553600     =  75369672 -> 1150
     * (3,2): 65536000 + 22960504 + 32768000   = 121264504 -> 1850
     * (5,1): 65536000 + 36080792 + 19660800   = 121277592 -> 1850
     * (1,5): 65536000 + 9840216 + 72089600    = 147465816 -> 2250
     * (8,0): 65536000 + 55761224 + 6553600    = 127850824 -> 1950
     * (0,17): 65536000 + 3280072 + 229376000  = 298192072 -> 4550
     * (4,8): 65536000 + 29520648 + 111411200  = 206467848 -> 3150
     * All seven centres are inside (x/160 + y/320 < 1).  The triangle
     * covers 100 pixels.
     */
    static const int32_t t1[9] = { 0, 0, 1000, 160, 0, 2001, 0, 320, 5000 };
    static const struct {
        int px, py;
        uint16_t z;
    } w1[] = { { 0, 0, 1150 }, { 3, 2, 1850 }, { 5, 1, 1850 },
               { 1, 5, 2250 }, { 8, 0, 1950 }, { 0, 17, 4550 },
               { 4, 8, 3150 } };
    draw_ztest(m, t1, 3);
    for (size_t i = 0; i < sizeof w1 / sizeof w1[0]; i++) {
        if (!CHECK_EQ(test_z(m, w1[i].px, w1[i].py), w1[i].z)) {
            printf("  T1 pixel (%d,%d)\n", w1[i].px, w1[i].py);
        }
        CHECK_EQ(test_back_px(m, w1[i].px, w1[i].py), 3);
    }
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(z_not(m, 0xFFFF), 100);
    CHECK_EQ(px_eq(m, 3), 100);
    CHECK_EQ(test_z(m, 10, 0), 0xFFFF); /* centre x 168 > 160: outside */

    /*
     * T3, given with negative winding and a vertex deep in the guard band:
     *   I0 (-30000,-12000) z 48000, I1 (3840,3552) z 32000,
     *   I2 (3120,2224) z 13000.
     * E_v0v1(v2) = 33840*14224 - 15552*33120 = -33742080 < 0: v1 and v2
     * (positions and depths) are exchanged:
     *   v0 (-30000,-12000,48000), v1 (3120,2224,13000), v2 (3840,3552,32000)
     *   dx1 33120, dy1 14224, dz1 -35000; dx2 33840, dy2 15552, dz2 -16000
     *   area = 33120*15552 - 14224*33840 = 515082240 - 481340160 = 33742080
     *   ZA = trunc(65536 * (-35000*15552 + 16000*14224) / 33742080)
     *      = trunc(65536 * -316736000 / 33742080) = trunc(-615184.67)
     *      = -615184          (floor would give -615185)
     *   ZB = trunc(65536 * (-16000*33120 + 35000*33840) / 33742080)
     *      = trunc(65536 * 654480000 / 33742080) = trunc(1271172.41)
     *      = 1271172
     * (0,56): p - v0 = (8 + 30000, 904 + 12000) = (30008, 12904):
     *   3145728000 - 615184*30008 + 1271172*12904
     *   = 3145728000 - 18460441472 + 16403203488 = 1088490016 -> 16609
     *   (with ZA floored: 1088460008 -> 16608, so trunc is visible here)
     * (1,57):   p - v0 = (30024, 12920)  -> 1098985824 -> 16769
     * (10,60):  p - v0 = (30168, 12968)  -> 1071415584 -> 16348
     * (100,150): (31608, 14408)          -> 2016038304 -> 30762
     * (200,200): (33208, 15208)          -> 2048681504 -> 31260
     * (239,221): (33832, 15544)          -> 2091920480 -> 31920
     */
    static const int32_t t3[9] = { -30000, -12000, 48000, 3840, 3552, 32000,
                                   3120,   2224,   13000 };
    static const struct z_at w3[] = { { 0, 56, 16609 },   { 1, 57, 16769 },   { 10, 60, 16348 },
                                      { 100, 150, 30762 }, { 200, 200, 31260 }, { 239, 221, 31920 } };
    draw_ztest(m, t3, 4);
    check_z_at(m, w3, sizeof w3 / sizeof w3[0], 4, "T3");
    uint32_t t3_pixels = perf_pixels(m);
    CHECK(t3_pixels > 10000);
    CHECK_EQ(z_not(m, 0xFFFF), t3_pixels);
    CHECK_EQ(test_z(m, 0, 54), 0xFFFF); /* outside: above its top edge */
    uint16_t *zsave = malloc(GPU_MODEL_FB_PIXELS * sizeof *zsave);
    if (zsave == NULL) {
        exit(2);
    }
    memcpy(zsave, m->zbuf, GPU_MODEL_FB_PIXELS * sizeof *zsave);

    /* The same vertices with I1 and I2 exchanged (positive winding, no
     * swap): the identical oriented triangle, so the identical depths. */
    static const int32_t t3s[9] = { -30000, -12000, 48000, 3120, 2224, 13000,
                                    3840,   3552,   32000 };
    draw_ztest(m, t3s, 4);
    CHECK_EQ(perf_pixels(m), t3_pixels);
    CHECK(memcmp(zsave, m->zbuf, GPU_MODEL_FB_PIXELS * sizeof *zsave) == 0);

    /* Rotated so that I0 is (3840,3552) z 32000: the same coverage, but v0
     * is the plane's origin, so the truncation error lands differently:
     *   (0,56) 16608, (1,57) 16768, (239,221) 31919; (10,60) 16348,
     *   (100,150) 30762, (200,200) 31260 unchanged. */
    static const int32_t t3r[9] = { 3840,   3552,   32000, 3120, 2224, 13000,
                                    -30000, -12000, 48000 };
    static const struct z_at w3r[] = { { 0, 56, 16608 },   { 1, 57, 16768 },   { 10, 60, 16348 },
                                       { 100, 150, 30762 }, { 200, 200, 31260 }, { 239, 221, 31919 } };
    draw_ztest(m, t3r, 4);
    CHECK_EQ(perf_pixels(m), t3_pixels);
    check_z_at(m, w3r, sizeof w3r / sizeof w3r[0], -1, "T3 rotated");
    free(zsave);

    /* A constant depth: ZA = ZB = 0 and z = z0 exactly, also 0 and 65534. */
    static const uint32_t consts[] = { 0, 1, 12345, 65534 };
    for (size_t i = 0; i < sizeof consts / sizeof consts[0]; i++) {
        set_rect(m, 0, 0, 3, 4, 9, 7, consts[i], 5);
        run(m, CL | ZC | ZT, 4, 2);
        CHECK_EQ(perf_pixels(m), 18);
        CHECK_EQ(z_not(m, 0xFFFF), 18);
        CHECK_EQ(test_z(m, 3, 4), consts[i]);
        CHECK_EQ(test_z(m, 8, 6), consts[i]);
    }
    free(m);
}

/* ------------------------------------- saturation and clamp on slivers */

static void test_saturation(void)
{
    gpu_model *m = test_new_model_cfg(8, true, true);

    /*
     * S1: I0 (1,0), I1 (1600,1600), I2 (0,0).  area = 1599*0 - 1600*(-1) =
     * 1600 > 0.  Edge v1->v2 runs along the diagonal through the centres
     * (c, c), c = 16k + 8, and is top-left (dy < 0); E_v0v1 = 1600 - c > 0
     * for k <= 99; E_v2v0 = c > 0.  Covered: (k, k), k = 0..99, nothing else
     * (the sliver is 1/16 px wide).  dx1 1599, dy1 1600, dx2 -1, dy2 0:
     *   ZA = trunc(65536 * (-dz2 * 1600) / 1600) = -65536 dz2
     *   ZB = trunc(65536 * (1599 dz2 + dz1) / 1600)
     * and p - v0 = (c - 1, c).
     *
     * (a) z = 30000, 65535, 65535 (dz1 = dz2 = 35535):
     *   ZA = -2328821760 -> sat -2^31;  ZB = 65536 * 35535 -> sat 2^31 - 1
     *   sum = 65536*30000 - 2^31 (c - 1) + (2^31 - 1) c
     *       = 65536*30000 + 2^31 - c  -> z = 30000 + 32767 = 62767
     *   (the exact plane gives 65535 on this edge)
     */
    static const int32_t s1a[9] = { 1, 0, 30000, 1600, 1600, 65535, 0, 0, 65535 };
    draw_ztest(m, s1a, 1);
    CHECK_PERF6(m, 1, 1, 0, 100, 10000, 100);
    CHECK_EQ(off_diagonal(m, 0, 100, 1, 62767, 1), 0);
    CHECK_EQ(z_not(m, 0xFFFF), 100);

    /* (b) z = 40000, 0, 0 (dz = -40000): ZA = 65536*40000 -> sat 2^31 - 1,
     *   ZB = -65536*40000 -> sat -2^31:
     *   sum = 65536*40000 + (2^31 - 1)(c - 1) - 2^31 c
     *       = 65536*40000 - 2^31 - c + 1 -> z = 40000 - 32769 = 7231
     *   (exact: 0). */
    static const int32_t s1b[9] = { 1, 0, 40000, 1600, 1600, 0, 0, 0, 0 };
    draw_ztest(m, s1b, 2);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(off_diagonal(m, 0, 100, 1, 7231, -1), 0);

    /* (c) z = 32768, 0, 0: ZA = 65536*32768 = 2^31 -> sat 2^31 - 1, ZB =
     *   -2^31 (fits): z = floor(32768 - 32769 + ...) = -1 -> clamp 0.  0 is
     *   less than the cleared 0xFFFF, so all 100 pixels are written with
     *   depth 0 (an unclamped -1 would wrap to 0xFFFF and fail the test). */
    static const int32_t s1c[9] = { 1, 0, 32768, 1600, 1600, 0, 0, 0, 0 };
    draw_ztest(m, s1c, 3);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(off_diagonal(m, 0, 100, 1, 0, 3), 0);

    /*
     * S2, a sliver of slope 1/2: I0 (9,8), I1 (1608,808), I2 (8,8).
     * area = 1599*0 - 800*(-1) = 800.  Edge v1->v2 (top-left, dy < 0) runs
     * through the centres (8 + 32k, 8 + 16k) = pixels (2k, k); E_v0v1 =
     * 1599*16k - 800*(32k - 1) = 800 - 16k > 0 for k <= 49; E_v2v0 = 16k
     * (top edge, dy = 0, dx > 0: k = 0 included).  Covered: (2k, k),
     * k = 0..49.  Box px 0..100, py 0..50: 5151 samples; one span per row.
     * dx1 1599, dy1 800, dx2 -1, dy2 0:
     *   ZA = -65536 dz2,  ZB = trunc(65536 (1599 dz2 + dz1) / 800)
     * and p - v0 = (32k - 1, 16k).  Unlike on S1, saturating only one of
     * them, or both to a ratio other than 1:-2, moves z far off the edge.
     *
     * (d) z = 60000, 40000, 40000 (dz = -20000): ZA = 1310720000 (fits),
     *   ZB = -2^17 * 20000 = -2621440000 -> sat -2^31.
     *   k = 0: 65536*60000 - 1310720000 -> z = 40000 (exact)
     *   k = 1: 65536*60000 + 1310720000*31 - 2^31*16
     *          = 3932160000 + 6272581632 -> 155712 -> clamp 65535.
     *   Every k >= 1 clamps to 65535, which is not less than the cleared
     *   0xFFFF: only (0,0) is written.  Spans still count all 50 rows.
     */
    static const int32_t s2d[9] = { 9, 8, 60000, 1608, 808, 40000, 8, 8, 40000 };
    draw_ztest(m, s2d, 4);
    CHECK_PERF6(m, 1, 1, 0, 1, 5151, 50);
    CHECK_EQ(test_z(m, 0, 0), 40000);
    CHECK_EQ(test_back_px(m, 0, 0), 4);
    CHECK_EQ(z_not(m, 0xFFFF), 1);
    CHECK_EQ(test_back_px(m, 2, 1), 0);
    CHECK_EQ(test_back_px(m, 98, 49), 0);

    /* (e) z = 10000, 30000, 30000 (dz = 20000): ZA = -1310720000,
     *   ZB = 2621440000 -> sat 2^31 - 1.
     *   k = 0: z = 10000 + 20000 = 30000 (exact)
     *   k = 1: 655360000 - 1310720000*31 + (2^31 - 1)*16
     *          = -5617221648 -> floor(-85712.0002) = -85713 -> clamp 0.
     *   All 50 are written (0 < 0xFFFF). */
    static const int32_t s2e[9] = { 9, 8, 10000, 1608, 808, 30000, 8, 8, 30000 };
    draw_ztest(m, s2e, 5);
    CHECK_PERF6(m, 1, 1, 0, 50, 5151, 50);
    CHECK_EQ(test_z(m, 0, 0), 30000);
    CHECK_EQ(off_diagonal(m, 1, 50, 2, 0, 5), 0);
    CHECK_EQ(z_not(m, 0xFFFF), 50);

    /* (f) z = 65535, 0, 0: ZA = 65536*65535 -> sat 2^31 - 1, ZB =
     *   -2^17*65535 -> sat -2^31.  k = 0, p - v0 = (-1, 0):
     *   floor((65536*65535 - (2^31 - 1)) / 65536) = floor(32767.00002) =
     *   32767 (exact: 0); k >= 1 clamps to 65535 and is not written. */
    static const int32_t s2f[9] = { 9, 8, 65535, 1608, 808, 0, 8, 8, 0 };
    draw_ztest(m, s2f, 6);
    CHECK_EQ(perf_pixels(m), 1);
    CHECK_EQ(test_z(m, 0, 0), 32767);
    CHECK_EQ(z_not(m, 0xFFFF), 1);

    /* Without ZTEST the same slivers draw every covered pixel and leave the
     * depth buffer alone. */
    run(m, CL, 3, 1);
    CHECK_EQ(perf_pixels(m), 50);
    CHECK_EQ(test_z(m, 0, 0), 32767);
    CHECK_EQ(test_back_px(m, 98, 49), 6);
    free(m);
}

/* ------------------------------------------- test, clear, occlusion */

static void test_ztest_rules(void)
{
    gpu_model *m = test_new_model_cfg(8, true, true);

    /* Power-on depth is 0: nothing is less, so ZTEST draws nothing, yet the
     * triangles count as drawn and their spans as written.  The 10 x 10
     * rectangle: upper triangle rows r = 0..9 px r..9 (spans {0,1} for
     * r <= 7, {1} for r = 8, 9: 18), lower rows 1..9 px 0..r-1 ({0} for
     * r <= 8, {0,1} for r = 9: 10): 28 spans, 55 + 45 pixels. */
    draw_square(m, CL | ZT, 0, 1);
    CHECK_EQ(z_not(m, 0), 0);
    CHECK_PERF6(m, 2, 2, 0, 0, 200, 28);
    CHECK_EQ(px_eq(m, 1), 0);

    /* ZCLEAR alone: every depth 0xFFFF, the colour buffer untouched. */
    test_batch(m, CL, 0, 0, 0, 0, 9, g_tag++);
    CHECK_EQ(px_eq(m, 9), GPU_MODEL_FB_PIXELS);
    test_batch(m, ZC, 0, 0, 0, 0, 0, g_tag++);
    CHECK_EQ(z_not(m, 0xFFFF), 0);
    CHECK_EQ(px_eq(m, 9), GPU_MODEL_FB_PIXELS);

    /* A depth of 0xFFFF is never less than the cleared value. */
    draw_square(m, ZT, 0xFFFF, 1);
    CHECK_PERF6(m, 2, 2, 0, 0, 200, 28);

    /* Strictly less, then replaced: 100 at 100; again at 100 (equal, not
     * written); at 101 (not written); at 99 (written). */
    draw_square(m, ZT, 100, 1);
    CHECK_PERF6(m, 2, 2, 0, 100, 200, 28);
    CHECK_EQ(test_z(m, 9, 9), 100);
    CHECK_EQ(z_not(m, 0xFFFF), 100);
    draw_square(m, ZT, 100, 2);
    CHECK_PERF6(m, 2, 2, 0, 0, 200, 28);
    CHECK_EQ(px_eq(m, 1), 100);
    draw_square(m, ZT, 101, 3);
    CHECK_EQ(perf_pixels(m), 0);
    CHECK_EQ(px_eq(m, 1), 100);
    CHECK_EQ(test_z(m, 0, 0), 100);
    draw_square(m, ZT, 99, 4);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(px_eq(m, 4), 100);
    CHECK_EQ(test_z(m, 5, 5), 99);

    /* Without ZTEST (depth buffer built): written regardless, depth kept. */
    draw_square(m, 0, 50000, 5);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(px_eq(m, 5), 100);
    CHECK_EQ(test_z(m, 5, 5), 99);

    /* CLEAR without ZCLEAR keeps the depths; the depth buffer is not
     * double-buffered, so it survives a swap. */
    run(m, CL | GPU_CTRL_SWAP_MASK, 0, 0);
    CHECK_EQ(test_z(m, 5, 5), 99);
    draw_square(m, ZT, 99, 6);
    CHECK_EQ(perf_pixels(m), 0);

    /* ERR_COUNT skips the depth clear too (the swap still happens). */
    test_batch(m, ZC | CL | GPU_CTRL_SWAP_MASK, 0, GPU_VTX_CAP + 1u, 0, 0, 0,
               g_tag++);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_COUNT_MASK);
    CHECK_EQ(test_z(m, 5, 5), 99);
    CHECK_EQ(z_not(m, 0xFFFF), 100);

    /* Occlusion, near first: P = pixels 0..9 x 0..9 at 100 (colour 1), Q =
     * 5..14 x 5..14 at 200 (colour 2): Q loses the 25 shared pixels. */
    draw_p_q(m, false, CL | ZC | ZT);
    CHECK_P_Q(m, 175, 100, 75);
    CHECK_EQ(test_back_px(m, 7, 7), 1);
    CHECK_EQ(test_back_px(m, 12, 7), 2);
    CHECK_EQ(test_z(m, 7, 7), 100);
    CHECK_EQ(test_z(m, 12, 12), 200);
    /* Far first: all 200 written, the near one wins the overlap. */
    draw_p_q(m, true, CL | ZC | ZT);
    CHECK_P_Q(m, 200, 100, 75);
    CHECK_EQ(test_z(m, 7, 7), 100);
    /* Without ZTEST the later one simply wins. */
    draw_p_q(m, true, CL | ZC);
    CHECK_P_Q(m, 200, 100, 75);
    CHECK_EQ(z_not(m, 0xFFFF), 0);
    draw_p_q(m, false, CL | ZC);
    CHECK_EQ(px_eq(m, 1), 75);
    CHECK_EQ(px_eq(m, 2), 100);

    /* Interpenetrating planes.  A = pixels 0..15 x 0..3 with depth 0 on
     * its left edge (x = 0) and 4096 on its right (x = 256), both halves
     * from v0 = (0,0,0): ZA = 65536 * 4096*64 / (256*64) = 1048576 (16 per
     * 1/16 px), ZB = 0, so z(px) = 16 * (16 px + 8) = 256 px + 128.  B =
     * the same pixels flat at 1920 = z(7), drawn after A: it is written
     * where 1920 < 256 px + 128, i.e. px >= 8; at px = 7 the depths are
     * equal and A stays. */
    test_set_vtxz(m, 0, 0, 0, 0);
    test_set_vtxz(m, 1, 256, 0, 4096);
    test_set_vtxz(m, 2, 256, 64, 4096);
    test_set_vtxz(m, 3, 0, 64, 0);
    test_set_prim(m, 0, 0, 1, 2, 1, GPU_PRIM_KIND_TRI);
    test_set_prim(m, 1, 0, 2, 3, 1, GPU_PRIM_KIND_TRI);
    set_rect(m, 4, 2, 0, 0, 16, 4, 1920, 2);
    run(m, CL | ZC | ZT, 8, 4);
    for (int px = 0; px < 16; px++) {
        CHECK_EQ(test_back_px(m, px, 2), px <= 7 ? 1 : 2);
        CHECK_EQ(test_z(m, px, 2), px <= 7 ? 256 * px + 128 : 1920);
    }
    CHECK_EQ(perf_pixels(m), 64 + 32);
    free(m);
}

/* ---------------------------------------------------- lines, no zbuf */

static void test_lines_and_absent(void)
{
    gpu_model *m = test_new_model_cfg(8, true, true);

    /* Lines neither test nor write depth: over a rectangle at depth 0 (so
     * no triangle could pass there), a line along row 5 from pixel -2 to 20
     * draws its 20 on-screen plots; the depths stay as they were. */
    set_rect(m, 0, 0, 0, 0, 10, 10, 0, 1);
    test_set_vtxz(m, 4, 16 * -2, 16 * 5 + 3, 0);
    test_set_vtxz(m, 5, 16 * 20 + 3, 16 * 5 + 9, 0);
    test_set_prim(m, 2, 4, 5, 0, 6, GPU_PRIM_KIND_LINE);
    run(m, CL | ZC | ZT, 6, 3);
    CHECK_PERF6(m, 3, 3, 0, 100 + 20, 200 + 22, 28);
    CHECK_EQ(test_back_px(m, 3, 5), 6);
    CHECK_EQ(test_back_px(m, 15, 5), 6);
    CHECK_EQ(test_back_px(m, 3, 4), 1);
    CHECK_EQ(test_z(m, 3, 5), 0);
    CHECK_EQ(test_z(m, 15, 5), 0xFFFF);
    CHECK_EQ(z_not(m, 0xFFFF), 100);
    /* Power-on depth 0 does not stop a line either. */
    gpu_model *m2 = test_new_model_cfg(4, true, true);
    test_set_vtx(m2, 0, 16, 16);
    test_set_vtx(m2, 1, 16 * 5, 16);
    test_set_prim(m2, 0, 0, 1, 0, 7, GPU_PRIM_KIND_LINE);
    test_batch(m2, ZT, 0, 2, 0, 1, 0, 1);
    CHECK_EQ(perf_pixels(m2), 4);
    CHECK_EQ(z_not(m2, 0), 0);
    free(m2);
    free(m);

    /* Built without the depth buffer: CTRL_ZTEST and CTRL_ZCLEAR are
     * stored (CTRL reads them back) but have no effect.  The depth array
     * stays 0, a triangle at any depth draws every covered pixel, again and
     * again. */
    m = test_new_model_cfg(8, true, false);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS) & GPU_CAPS_ZBUF_MASK, 0);
    draw_square(m, CL | ZC | ZT, 100, 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), CL | ZC | ZT);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(z_not(m, 0), 0);
    draw_square(m, ZC | ZT, 100, 2);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(px_eq(m, 2), 100);
    draw_square(m, ZT, 0xFFFF, 3);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(px_eq(m, 3), 100);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(z_not(m, 0), 0);
    /* The sliver S2 (d) of test_saturation: all 50 pixels drawn. */
    static const int32_t s2d[9] = { 9, 8, 60000, 1608, 808, 40000, 8, 8, 40000 };
    draw_ztest(m, s2d, 4);
    CHECK_PERF6(m, 1, 1, 0, 50, 5151, 50);
    CHECK_EQ(z_not(m, 0), 0);
    free(m);
}

/* ------------------------------------------------ fewer bits kept */

/* ZBUF_BITS = 8 (contract "Depth": zb = z >> 8): the buffer holds 0 .. 255,
 * ZCLEAR stores 255, and depths with the same top byte are not ordered. */
static void test_zbuf_bits(void)
{
    gpu_model *m = alloc_depth_model(8);

    CHECK_EQ(m->cfg.zbuf_bits, 8);
    CHECK_EQ((gpu_model_caps(m) & GPU_CAPS_ZBUF_BITS_MASK) >> GPU_CAPS_ZBUF_BITS_LSB, 8);
    test_batch(m, CL | ZC, 0, 0, 0, 0, 0, g_tag++);
    CHECK_EQ(z_not(m, 255), 0);

    /* 0x1234 stored as 0x12; 0x12FF and 0x1200 (same top byte) are not
     * nearer; 0x11FF is. */
    draw_square(m, ZT, 0x1234, 1);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(test_z(m, 3, 3), 0x12);
    draw_square(m, ZT, 0x1200, 2);
    CHECK_EQ(perf_pixels(m), 0);
    draw_square(m, ZT, 0x11FF, 3);
    CHECK_EQ(perf_pixels(m), 100);
    CHECK_EQ(test_z(m, 3, 3), 0x11);
    CHECK_EQ(px_eq(m, 3), 100);

    /* 0xFF00 .. 0xFFFF keep 255, the cleared value: never drawn. */
    test_batch(m, ZC, 0, 0, 0, 0, 0, g_tag++);
    draw_square(m, ZT, 0xFF00, 4);
    CHECK_EQ(perf_pixels(m), 0);
    draw_square(m, ZT, 0xFEFF, 4);
    CHECK_EQ(perf_pixels(m), 100);
    free(m);

    /* Out-of-range settings are replaced by 16 (as an unsupported SPAN_W
     * is by 8), and 16 reports 16 in CAPS. */
    m = alloc_depth_model(0);
    CHECK_EQ(m->cfg.zbuf_bits, 16);
    free(m);
    m = alloc_depth_model(17);
    CHECK_EQ(m->cfg.zbuf_bits, 16);
    CHECK_EQ((gpu_model_caps(m) & GPU_CAPS_ZBUF_BITS_MASK) >> GPU_CAPS_ZBUF_BITS_LSB, 16);
    free(m);
}

void test_depth(void)
{
    test_plane();
    test_saturation();
    test_ztest_rules();
    test_lines_and_absent();
    test_zbuf_bits();
}
