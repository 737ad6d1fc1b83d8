/*
 * test_lines.c - unit tests of the model's line rule (contract "Line rule
 * (exact)"): endpoint pixels by arithmetic shift, the Bresenham variant with
 * the first endpoint drawn and the last not, every octant and direction, the
 * tie e == 0, guard-band endpoints, zero length, index and kind checks,
 * counters, and closed polygons drawing each vertex once.
 *
 * Every pixel list below was stepped by hand through
 *   ax >= ay: e = 2ay - ax; repeat n: plot; if e > 0 { Y += sy; e -= 2ax };
 *             e += 2ay; X += sx
 *   else:     the same with the roles of x and y exchanged;
 * the e sequences are in the comments.
 */
#include <stdlib.h>
#include <string.h>

#include "model_test.h"

/* Q12.4 of a point `sub` sixteenths into pixel n (0 <= sub <= 15). */
#define Q(n, sub) (16 * (n) + (sub))

static gpu_model *g_m;

/* One line from (x0, y0) to (x1, y1) (Q12.4) in colour 1 on a back buffer
 * cleared to 0, alone in its batch.  Returns PERF_PIXELS. */
static uint32_t line(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    static uint32_t tag = 0x1000;
    test_set_vtx(g_m, 0, x0, y0);
    test_set_vtx(g_m, 1, x1, y1);
    test_set_prim(g_m, 0, 0, 1, 0, 1, GPU_PRIM_KIND_LINE);
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 0, 2, 0, 1, 0, tag++);
    return gpu_model_read(g_m, GPU_REG_PERF_PIXELS);
}

/* The same between pixel positions, with sub-pixel offsets that must not
 * matter (endpoints are the pixels holding the vertices). */
static uint32_t line_px(int x0, int y0, int x1, int y1)
{
    return line(Q(x0, 3), Q(y0, 12), Q(x1, 15), Q(y1, 0));
}

/* Counters of a drawn line of n steps with `on` on-screen plots. */
#define CHECK_LINE_PERF(n, on) \
    CHECK_PERF6(g_m, 1, 1, 0, (on), (n), 0); \
    CHECK_EQ(gpu_model_read(g_m, GPU_REG_ERRORS), 0)

/* The line just drawn (`pixels` is line()'s PERF_PIXELS) covers exactly the listed pixels in
 * colour 1; with _PERF also its counters for n steps. */
#define CHECK_DRAWN(pixels, list)                                    \
    CHECK_EQ((pixels), sizeof(list) / sizeof((list)[0]));            \
    CHECK_PIXELS(g_m, list, 1, 0)
#define CHECK_DRAWN_PERF(pixels, list, n) \
    CHECK_DRAWN(pixels, list);            \
    CHECK_LINE_PERF(n, sizeof(list) / sizeof((list)[0]))

/* ------------------------------------------------------ hand examples */

static void test_hand_lines(void)
{
    /* x-major, right and down: pixel (2,3) -> (8,5), vertices (37,57) ->
     * (143,80): X0 = 37>>4 = 2, Y0 = 57>>4 = 3, X1 = 143>>4 = 8,
     * Y1 = 80>>4 = 5.  dx 6, dy 2, n 6, e = 4 - 6 = -2:
     *   plot (2,3) e -2 -> 2;  plot (3,3) e 2 > 0: Y 4, e -10 -> -6;
     *   plot (4,4) -> -2;      plot (5,4) -> 2;
     *   plot (6,4) e 2 > 0: Y 5, -10 -> -6;  plot (7,5) -> -2.
     * (8,5), the last endpoint, is not drawn. */
    static const int a[][2] = { { 2, 3 }, { 3, 3 }, { 4, 4 },
                                { 5, 4 }, { 6, 4 }, { 7, 5 } };
    CHECK_DRAWN_PERF(line(37, 57, 143, 80), a, 6);

    /* The same reversed, (8,5) -> (2,3): sx = sy = -1, e = -2:
     *   plot (8,5) -> 2;  plot (7,5) e > 0: Y 4, -> -6;  plot (6,4) -> -2;
     *   plot (5,4) -> 2;  plot (4,4) e > 0: Y 3, -> -6;  plot (3,3). */
    static const int ar[][2] = { { 8, 5 }, { 7, 5 }, { 6, 4 },
                                 { 5, 4 }, { 4, 4 }, { 3, 3 } };
    CHECK_DRAWN_PERF(line(143, 80, 37, 57), ar, 6);

    /* y-major, (20,20) -> (23,27): dx 3, dy 7, n 7, e = 6 - 7 = -1:
     *   plot (20,20) -> 5;  plot (20,21) e > 0: X 21, e -9 -> -3;
     *   plot (21,22) -> 3;  plot (21,23) e > 0: X 22, -11 -> -5;
     *   plot (22,24) -> 1;  plot (22,25) e > 0: X 23, -13 -> -7;
     *   plot (23,26). */
    static const int b[][2] = { { 20, 20 }, { 20, 21 }, { 21, 22 },
                                { 21, 23 }, { 22, 24 }, { 22, 25 },
                                { 23, 26 } };
    CHECK_DRAWN_PERF(line_px(20, 20, 23, 27), b, 7);

    /* Reversed, (23,27) -> (20,20), e = -1:
     *   plot (23,27) -> 5;  plot (23,26) e > 0: X 22, -> -3;
     *   plot (22,25) -> 3;  plot (22,24) e > 0: X 21, -> -5;
     *   plot (21,23) -> 1;  plot (21,22) e > 0: X 20, -> -7;
     *   plot (20,21). */
    static const int br[][2] = { { 23, 27 }, { 23, 26 }, { 22, 25 },
                                 { 22, 24 }, { 21, 23 }, { 21, 22 },
                                 { 20, 21 } };
    CHECK_DRAWN(line_px(23, 27, 20, 20), br);

    /* The tie e == 0 does not step: (10,10) -> (14,12), dx 4, dy 2,
     * e = 4 - 4 = 0:
     *   plot (10,10) e 0: no step -> 4;  plot (11,10) e > 0: Y 11, -4 -> 0;
     *   plot (12,11) e 0 -> 4;           plot (13,11). */
    static const int t[][2] = { { 10, 10 }, { 11, 10 }, { 12, 11 },
                                { 13, 11 } };
    CHECK_DRAWN_PERF(line_px(10, 10, 14, 12), t, 4);
    /* Reversed it is not the mirror image: (14,12) -> (10,10), e = 0:
     *   plot (14,12) -> 4;  plot (13,12) e > 0: Y 11, -> 0;
     *   plot (12,11) -> 4;  plot (11,11). */
    static const int tr[][2] = { { 14, 12 }, { 13, 12 }, { 12, 11 },
                                 { 11, 11 } };
    CHECK_DRAWN(line_px(14, 12, 10, 10), tr);
    /* y-major tie: (30,10) -> (32,14), dx 2, dy 4, e = 4 - 4 = 0:
     *   plot (30,10) -> 4;  plot (30,11) e > 0: X 31, -> 0;
     *   plot (31,12) -> 4;  plot (31,13). */
    static const int ty[][2] = { { 30, 10 }, { 30, 11 }, { 31, 12 },
                                 { 31, 13 } };
    CHECK_DRAWN(line_px(30, 10, 32, 14), ty);
}

/* All eight octants from pixel (100,100): |d| = (5,2) is x-major, (2,5)
 * y-major.  e starts at 4 - 5 = -1 in both; the sequence does not depend on
 * the signs, so the plots are (100 + sx*u, 100 + sy*v) with
 *   x-major (u,v): (0,0) e -1 -> 3; (1,0) e > 0: step, -7 -> -3;
 *                  (2,1) -> 1; (3,1) e > 0: step, -9 -> -5; (4,2)
 *   y-major: the same with u and v exchanged. */
static void test_octants(void)
{
    static const int xmaj[5][2] = { { 0, 0 }, { 1, 0 }, { 2, 1 },
                                    { 3, 1 }, { 4, 2 } };
    static const int sgn[4][2] = { { 1, 1 }, { -1, 1 }, { -1, -1 },
                                   { 1, -1 } };
    for (int s = 0; s < 4; s++) {
        int sx = sgn[s][0], sy = sgn[s][1];
        int want[5][2];
        /* the x-major octant, then the y-major one (u and v exchanged) */
        for (int ymaj = 0; ymaj < 2; ymaj++) {
            const int dx = ymaj ? 2 : 5, dy = ymaj ? 5 : 2;
            for (int k = 0; k < 5; k++) {
                want[k][0] = 100 + sx * xmaj[k][ymaj];
                want[k][1] = 100 + sy * xmaj[k][!ymaj];
            }
            CHECK_EQ(line_px(100, 100, 100 + dx * sx, 100 + dy * sy), 5);
            if (!CHECK_PIXELS(g_m, want, 1, 0)) {
                printf("  %c-major octant sx %d sy %d\n", ymaj ? 'y' : 'x', sx, sy);
            }
            CHECK_LINE_PERF(5, 5);
        }
    }

    /* One negative octant written out: (100,100) -> (95,98). */
    static const int neg[][2] = { { 100, 100 }, { 99, 100 }, { 98, 99 },
                                  { 97, 99 }, { 96, 98 } };
    line_px(100, 100, 95, 98);
    CHECK_PIXELS(g_m, neg, 1, 0);

    /* Axis-aligned and diagonal lines, both directions.  Horizontal: dy 0,
     * e = -ax never > 0; vertical: y-major with e = -ay; diagonal: ax = ay
     * takes the x-major branch with e = ay > 0 at every step. */
    static const int h[][2] = { { 50, 60 }, { 51, 60 }, { 52, 60 } };
    static const int hr[][2] = { { 53, 60 }, { 52, 60 }, { 51, 60 } };
    static const int v[][2] = { { 50, 60 }, { 50, 61 }, { 50, 62 } };
    static const int vr[][2] = { { 50, 63 }, { 50, 62 }, { 50, 61 } };
    static const int d1[][2] = { { 50, 60 }, { 51, 61 }, { 52, 62 } };
    static const int d2[][2] = { { 50, 60 }, { 49, 61 }, { 48, 62 } };
    static const int d3[][2] = { { 50, 60 }, { 49, 59 }, { 48, 58 } };
    static const int d4[][2] = { { 50, 60 }, { 51, 59 }, { 52, 58 } };
    CHECK_DRAWN(line_px(50, 60, 53, 60), h);
    CHECK_DRAWN(line_px(53, 60, 50, 60), hr);
    CHECK_DRAWN(line_px(50, 60, 50, 63), v);
    CHECK_DRAWN(line_px(50, 63, 50, 60), vr);
    CHECK_DRAWN(line_px(50, 60, 53, 63), d1);
    CHECK_DRAWN(line_px(50, 60, 47, 63), d2);
    CHECK_DRAWN(line_px(50, 60, 47, 57), d3);
    CHECK_DRAWN(line_px(50, 60, 53, 57), d4);
    /* One step: only the first endpoint. */
    static const int one[][2] = { { 7, 9 } };
    CHECK_DRAWN_PERF(line_px(7, 9, 8, 10), one, 1);
}

/* -------------------------------------- endpoints, guard band, clipping */

static void test_line_guard_band(void)
{
    /* Sub-pixel positions inside the endpoint pixels do not matter. */
    for (int sub = 0; sub < 16; sub += 5) {
        static const int a[][2] = { { 2, 3 }, { 3, 3 }, { 4, 4 },
                                    { 5, 4 }, { 6, 4 }, { 7, 5 } };
        line(Q(2, sub), Q(3, 15 - sub), Q(8, 15 - sub), Q(5, sub));
        CHECK_PIXELS(g_m, a, 1, 0);
    }

    /* Negative coordinates: X = x >> 4 is a floor.  x = -1 and -16 are in
     * pixel -1, x = -17 in pixel -2.  Lines from there to pixel 3 of row 0
     * step 4 or 5 times, the on-screen plots are (0,0), (1,0), (2,0). */
    static const int r0[][2] = { { 0, 0 }, { 1, 0 }, { 2, 0 } };
    CHECK_DRAWN_PERF(line(-1, 8, Q(3, 8), 8), r0, 4);
    CHECK_EQ(line(-16, 8, Q(3, 8), 8), 3);
    CHECK_LINE_PERF(4, 3);
    CHECK_DRAWN_PERF(line(-17, 8, Q(3, 8), 8), r0, 5);
    /* Same in y: y = -49 is pixel -4 (-3.0625 floors to -4); down column 5
     * to pixel row 2: plots rows -4..1, on screen (5,0), (5,1). */
    static const int c5[][2] = { { 5, 0 }, { 5, 1 } };
    CHECK_DRAWN_PERF(line(Q(5, 0), -49, Q(5, 8), Q(2, 0)), c5, 6);

    /* A slanted line entering at the corner: (-41,-1) is pixel (-3,-1),
     * (79,47) is pixel (4,2).  dx 7, dy 3, e = 6 - 7 = -1:
     *   (-3,-1) -> 5; (-2,-1) e > 0: Y 0, -9 -> -3; (-1,0) -> 3;
     *   (0,0) e > 0: Y 1, -11 -> -5; (1,1) -> 1; (2,1) e > 0: Y 2, -> -7;
     *   (3,2).  On screen: (0,0), (1,1), (2,1), (3,2). */
    static const int corner[][2] = { { 0, 0 }, { 1, 1 }, { 2, 1 }, { 3, 2 } };
    CHECK_DRAWN_PERF(line(-41, -1, 79, 47), corner, 7);
    /* Reversed: (4,2) -> (-3,-1), e = -1:
     *   (4,2) -> 5; (3,2) e > 0: Y 1, -> -3; (2,1) -> 3; (1,1) e > 0: Y 0,
     *   -> -5; (0,0) -> 1; (-1,0) e > 0: Y -1 -> -7; (-2,-1).
     * On screen: (4,2), (3,2), (2,1), (1,1), (0,0). */
    static const int cornerr[][2] = { { 4, 2 }, { 3, 2 }, { 2, 1 },
                                      { 1, 1 }, { 0, 0 } };
    CHECK_DRAWN_PERF(line(79, 47, -41, -1), cornerr, 7);

    /* Right and bottom edges: pixel (317,239) -> (323,239) plots 317..322,
     * of which 317..319 are on screen; (300,237) -> (300,243) plots rows
     * 237..242, on screen 237..239. */
    static const int re[][2] = { { 317, 239 }, { 318, 239 }, { 319, 239 } };
    CHECK_DRAWN_PERF(line_px(317, 239, 323, 239), re, 6);
    static const int be[][2] = { { 300, 237 }, { 300, 238 }, { 300, 239 } };
    CHECK_DRAWN_PERF(line_px(300, 237, 300, 243), be, 6);

    /* Across the whole screen from guard band to guard band: row 100 from
     * pixel -3 to 400 (403 steps, plots -3..399), column 50 from row -10 to
     * 300 (310 steps). */
    CHECK_EQ(line(Q(-3, 0), Q(100, 4), Q(400, 9), Q(100, 15)), 320);
    CHECK_LINE_PERF(403, 320);
    CHECK_EQ(test_back_px(g_m, 0, 100), 1);
    CHECK_EQ(test_back_px(g_m, 319, 100), 1);
    CHECK_EQ(test_back_px(g_m, 0, 99), 0);
    CHECK_EQ(line(Q(50, 1), Q(-10, 0), Q(50, 2), Q(300, 0)), 240);
    CHECK_LINE_PERF(310, 240);

    /* The int16 extremes: (-32768,-32768) is pixel (-2048,-2048),
     * (32767,32767) pixel (2047,2047).  ax = ay = 4095: a diagonal whose
     * on-screen plots are (k,k) for k = 0..239. */
    CHECK_EQ(line(-32768, -32768, 32767, 32767), 240);
    CHECK_LINE_PERF(4095, 240);
    int diag = 0;
    for (int k = 0; k < 240; k++) {
        diag += test_back_px(g_m, k, k) == 1;
    }
    CHECK_EQ(diag, 240);
    /* The other diagonal, from (32767,-32768) to (-32768,32767): pixel
     * (2047,-2048) -> (-2048,2047): X + Y = -1 throughout: never on screen,
     * but stepped through (4095 samples) and drawn. */
    CHECK_EQ(line(32767, -32768, -32768, 32767), 0);
    CHECK_LINE_PERF(4095, 0);

    /* Entirely off screen: still drawn (only zero length is rejected),
     * n samples, 0 pixels. */
    CHECK_EQ(line(Q(-100, 0), Q(-5, 0), Q(400, 0), Q(-5, 0)), 0);
    CHECK_LINE_PERF(500, 0);
    CHECK_EQ(line(Q(330, 0), Q(10, 0), Q(330, 0), Q(100, 0)), 0);
    CHECK_LINE_PERF(90, 0);
}

/* ------------------------------------------ rejection, indices, kinds */

/* Vertices 0.. at the listed Q12.4 (x, y), primitives 0.. as listed (i0, i1, i2, colour, kind). */
static void load(gpu_model *m, const int32_t (*vtx)[2], size_t n_vtx, const uint32_t (*prims)[5],
                 size_t n_prims)
{
    for (size_t i = 0; i < n_vtx; i++) {
        test_set_vtx(m, (uint32_t)i, vtx[i][0], vtx[i][1]);
    }
    for (size_t i = 0; i < n_prims; i++) {
        test_set_prim(m, (uint32_t)i, prims[i][0], prims[i][1], prims[i][2], prims[i][3],
                      prims[i][4]);
    }
}

#define KIND_LINE GPU_PRIM_KIND_LINE
#define KIND_TRI  GPU_PRIM_KIND_TRI
#define LOAD(m, vtx, prims) \
    load((m), (vtx), sizeof(vtx) / sizeof((vtx)[0]), (prims), sizeof(prims) / sizeof((prims)[0]))

static bool back_all_zero(void)
{
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        if (gpu_model_back(g_m)[i] != 0) {
            return false;
        }
    }
    return true;
}

static void test_line_reject(void)
{
    /* Zero length: the same vertex twice, or two vertices in one pixel, or
     * a negative pixel (-1 holds -16..-1).  Rejected, no flag, nothing. */
    static const int32_t zero[][4] = {
        { Q(5, 0), Q(5, 0), Q(5, 0), Q(5, 0) },
        { Q(5, 1), Q(5, 2), Q(5, 14), Q(5, 15) },
        { Q(319, 15), Q(239, 15), Q(319, 0), Q(239, 0) },
        { -16, -1, -1, -16 },
        { -32768, 32767, -32761, 32752 },
    };
    for (size_t i = 0; i < sizeof zero / sizeof zero[0]; i++) {
        CHECK_EQ(line(zero[i][0], zero[i][1], zero[i][2], zero[i][3]), 0);
        CHECK_PERF6(g_m, 1, 0, 1, 0, 0, 0);
        CHECK_EQ(gpu_model_read(g_m, GPU_REG_ERRORS), 0);
        CHECK(back_all_zero());
    }

    /* Index checks use I0 and I1 only: I2 = 0xFFFF is fine for a line,
     * I0 or I1 = VTX_COUNT is ERR_VTX_INDEX. */
    static const int32_t idx_vtx[][2] = { { Q(1, 0), Q(1, 0) }, { Q(4, 0), Q(1, 0) } };
    static const uint32_t idx_prims[][5] = {
        { 0, 1, 0xFFFF, 7, KIND_LINE }, { 2, 1, 0, 8, KIND_LINE },
        { 0, 2, 0, 8, KIND_LINE },      { 0xFFFF, 0, 1, 8, KIND_LINE },
    };
    LOAD(g_m, idx_vtx, idx_prims);
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 0, 2, 0, 1, 0, 0x50);
    static const int ok[][2] = { { 1, 1 }, { 2, 1 }, { 3, 1 } };
    CHECK_PIXELS(g_m, ok, 7, 0);
    CHECK_LINE_PERF(3, 3);
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 0, 2, 1, 3, 0, 0x51);
    CHECK_EQ(gpu_model_read(g_m, GPU_REG_ERRORS), GPU_ERR_VTX_INDEX_MASK);
    CHECK_PERF6(g_m, 3, 0, 3, 0, 0, 0);
    CHECK(back_all_zero());
    /* Relative to VTX_BASE: vertices 10 and 11. */
    test_set_vtx(g_m, 10, Q(1, 0), Q(2, 0));
    test_set_vtx(g_m, 11, Q(3, 0), Q(2, 0));
    test_set_prim(g_m, 4, 0, 1, 0x1234, 9, GPU_PRIM_KIND_LINE);
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 10, 2, 4, 1, 0, 0x52);
    static const int rel[][2] = { { 1, 2 }, { 2, 2 } };
    CHECK_PIXELS(g_m, rel, 9, 0);
    CHECK_LINE_PERF(2, 2);

    /* A GPU built without lines: ERR_KIND, rejected, checked before the
     * indices (a line with a bad index reports only ERR_KIND). */
    gpu_model *nl = test_new_model_cfg(4, false, true);
    static const int32_t nl_vtx[][2] = { { Q(1, 0), Q(1, 0) }, { Q(4, 0), Q(1, 0) },
                                         { Q(1, 0), Q(4, 0) } };
    static const uint32_t nl_prims[][5] = {
        { 0, 1, 0, 7, KIND_LINE }, { 0, 5, 0, 7, KIND_LINE }, { 0, 1, 2, 3, KIND_TRI },
    };
    LOAD(nl, nl_vtx, nl_prims);
    test_batch(nl, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 3, 0, 0x53);
    CHECK_EQ(gpu_model_read(nl, GPU_REG_ERRORS), GPU_ERR_KIND_MASK);
    CHECK_EQ(gpu_model_read(nl, GPU_REG_PERF_TRIS_IN), 3);
    CHECK_EQ(gpu_model_read(nl, GPU_REG_PERF_TRIS_DRAWN), 1);
    CHECK_EQ(gpu_model_read(nl, GPU_REG_PERF_TRIS_REJECTED), 2);
    CHECK_EQ(test_back_px(nl, 2, 1), 3); /* the triangle, not the line */
    CHECK_EQ(test_back_px(nl, 3, 1), 0);
    free(nl);
}

/* ---------------------------------------------- polygons, batches */

/* The closed polygon through the centres of the n listed pixels, one line from each vertex to the
 * next (the last back to the first) in colour 4, in one batch of its own. */
static void closed_polygon(const int (*px)[2], uint32_t n, uint32_t tag)
{
    for (uint32_t k = 0; k < n; k++) {
        test_set_vtx(g_m, k, Q(px[k][0], 8), Q(px[k][1], 8));
        test_set_prim(g_m, k, k, (k + 1) % n, 0, 4, GPU_PRIM_KIND_LINE);
    }
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 0, n, 0, n, 0, tag);
}

static void test_polygons(void)
{
    /* A closed square of four lines through pixels (10,10) (20,10) (20,20)
     * (10,20): each line draws its first corner and not its last, so the
     * 40 border pixels of the 11 x 11 square are each written once. */
    static const int square[][2] = { { 10, 10 }, { 20, 10 }, { 20, 20 }, { 10, 20 } };
    closed_polygon(square, 4, 0x60);
    int border[40][2];
    int n = 0;
    for (int y = 10; y <= 20; y++) {
        for (int x = 10; x <= 20; x++) {
            if (x == 10 || x == 20 || y == 10 || y == 20) {
                border[n][0] = x;
                border[n][1] = y;
                n++;
            }
        }
    }
    CHECK_EQ(n, 40);
    test_check_pixels(g_m, (const int (*)[2])border, n, 4, 0, __FILE__,
                      __LINE__);
    CHECK_PERF6(g_m, 4, 4, 0, 40, 40, 0);

    /* Closed polygons with slanted edges, each line in a batch of its own,
     * accumulating how often each pixel is written: every vertex pixel
     * exactly once, and the batch counters add up. */
    static const int poly[][2] = {
        { 30, 30 }, { 40, 34 }, { 33, 45 },                 /* triangle */
        { 100, 50 }, { 130, 60 }, { 125, 90 }, { 90, 95 }, { 80, 70 },
    };
    static const int start[] = { 0, 3 }, count[] = { 3, 5 };
    uint16_t *acc = calloc(GPU_MODEL_FB_PIXELS, sizeof *acc);
    if (acc == NULL) {
        exit(2);
    }
    for (int p = 0; p < 2; p++) {
        memset(acc, 0, GPU_MODEL_FB_PIXELS * sizeof *acc);
        uint32_t pixels = 0;
        for (int k = 0; k < count[p]; k++) {
            const int *a = poly[start[p] + k];
            const int *b = poly[start[p] + (k + 1) % count[p]];
            pixels += line_px(a[0], a[1], b[0], b[1]);
            for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
                acc[i] += gpu_model_back(g_m)[i] != 0;
            }
        }
        for (int k = 0; k < count[p]; k++) {
            const int *a = poly[start[p] + k];
            CHECK_EQ(acc[a[1] * (int)GPU_FB_WIDTH + a[0]], 1);
        }
        uint32_t sum = 0;
        for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
            sum += acc[i];
        }
        CHECK_EQ(sum, pixels);
    }
    free(acc);
    /* The triangle's lines again, in one batch: n = max(10,4) + max(7,11)
     * + max(3,15) = 36 steps, all on screen. */
    closed_polygon(poly, 3, 0x62);
    CHECK_PERF6(g_m, 3, 3, 0, 36, 36, 0);

    /* Lines and triangles in one batch, in order: a later primitive
     * overwrites an earlier one, whatever its kind.  A triangle over pixels
     * (1..3, 1), (1..2, 2), (1, 3) (colour 5), then a line through row 1
     * (colour 6), then the triangle again (colour 7) over a line in row 4
     * (colour 8, drawn after). */
    static const int32_t mix_vtx[][2] = {
        { 16, 16 }, { 80, 16 }, { 16, 80 }, { Q(0, 0), Q(1, 0) },
        { Q(6, 0), Q(1, 0) }, { Q(0, 0), Q(4, 0) }, { Q(6, 0), Q(4, 0) },
    };
    static const uint32_t mix_prims[][5] = {
        { 0, 1, 2, 5, KIND_TRI }, { 3, 4, 0, 6, KIND_LINE },
        { 5, 6, 0, 8, KIND_LINE }, { 0, 1, 2, 7, KIND_TRI },
    };
    LOAD(g_m, mix_vtx, mix_prims);
    test_batch(g_m, GPU_CTRL_CLEAR_MASK, 0, 7, 0, 4, 0, 0x61);
    CHECK_EQ(test_back_px(g_m, 0, 1), 6);
    CHECK_EQ(test_back_px(g_m, 1, 1), 7);
    CHECK_EQ(test_back_px(g_m, 3, 1), 7);
    CHECK_EQ(test_back_px(g_m, 4, 1), 6);
    CHECK_EQ(test_back_px(g_m, 5, 1), 6);
    CHECK_EQ(test_back_px(g_m, 6, 1), 0);
    CHECK_EQ(test_back_px(g_m, 5, 4), 8);
    /* Counters: triangles 6 px / 16 samples / 3 spans (SPAN_W 8) each,
     * lines 6 px / 6 samples each. */
    CHECK_PERF6(g_m, 4, 4, 0, 6 + 6 + 6 + 6, 16 + 6 + 6 + 16, 3 + 3);
}

void test_lines(void)
{
    g_m = test_new_model(); /* default build: lines on, SPAN_W 8 */
    test_hand_lines();
    test_octants();
    test_line_guard_band();
    test_line_reject();
    test_polygons();
    free(g_m);
}
