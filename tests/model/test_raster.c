/*
 * test_raster.c - unit tests of the model's triangle rule (contract
 * "Triangle rule (exact)"): hand-computed coverage, the top-left fill rule at
 * and +-1/16 px around pixel centres, winding independence, zero area,
 * exact-once coverage of shared edges (split squares, fans, a random mesh),
 * the guard band, off-screen and thin triangles, and seeded random triangles
 * against an independent brute-force reference written in this file.
 */
#include <stdlib.h>
#include <string.h>

#include "model_test.h"

#define W ((int)GPU_FB_WIDTH)
#define H ((int)GPU_FB_HEIGHT)
#define NPIX ((int)GPU_MODEL_FB_PIXELS)

/* Q12.4 coordinate of the centre of pixel n. */
#define CTR(n) (16 * (n) + 8)

/* cos(2*pi*i/64) * 1024, rounded: directions for the fan tests without
 * needing libm.  sin(2*pi*i/64) = COS64[(i + 48) % 64]. */
static const int32_t COS64[64] = {
     1024,  1019,  1004,   980,   946,   903,   851,   792,
      724,   650,   569,   483,   392,   297,   200,   100,
        0,  -100,  -200,  -297,  -392,  -483,  -569,  -650,
     -724,  -792,  -851,  -903,  -946,  -980, -1004, -1019,
    -1024, -1019, -1004,  -980,  -946,  -903,  -851,  -792,
     -724,  -650,  -569,  -483,  -392,  -297,  -200,  -100,
        0,   100,   200,   297,   392,   483,   569,   650,
      724,   792,   851,   903,   946,   980,  1004,  1019,
};

/* floor(sqrt(v)) for v >= 0. */
static int64_t isqrt(int64_t v)
{
    int64_t r = 0;
    while ((r + 1) * (r + 1) <= v) {
        r++;
    }
    return r;
}

/* Move a Q12.4 coordinate onto the nearest-below pixel centre's grid
 * (16k + 8), without shifting negative numbers. */
static int32_t snap_centre(int32_t v)
{
    int32_t mod = ((v % 16) + 16) % 16;
    return v - mod + 8;
}

static gpu_model *g_m; /* one model reused by all raster tests */

/* Draw xy with colour 1 on a cleared (0) back buffer; return PERF_PIXELS. */
static uint32_t draw(const int32_t xy[6])
{
    return test_draw_one(g_m, xy, 1);
}

static uint32_t perf(uint32_t reg)
{
    return gpu_model_read(g_m, reg);
}

/* Add the current back-buffer coverage (pixels != 0) into acc. */
static void accumulate(uint16_t *acc)
{
    const uint8_t *fb = gpu_model_back(g_m);
    for (int i = 0; i < NPIX; i++) {
        acc[i] += fb[i] != 0;
    }
}

static uint16_t *new_acc(void)
{
    uint16_t *acc = calloc((size_t)NPIX, sizeof *acc);
    if (acc == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    return acc;
}

/* Check the back buffer equals a list of covered pixels (colour 1), all
 * other pixels 0. */
static void check_exact(const int (*pix)[2], int n, int line)
{
    uint8_t *want = calloc((size_t)NPIX, 1);
    if (want == NULL) {
        exit(2);
    }
    for (int i = 0; i < n; i++) {
        want[pix[i][1] * W + pix[i][0]] = 1;
    }
    const uint8_t *fb = gpu_model_back(g_m);
    int bad = 0;
    for (int i = 0; i < NPIX; i++) {
        if (fb[i] != want[i]) {
            if (bad < 8) {
                printf("  pixel (%d,%d): got %u want %u\n", i % W, i / W,
                       fb[i], want[i]);
            }
            bad++;
        }
    }
    test_check_eq(bad, 0, __FILE__, line, "coverage matches the hand list");
    free(want);
}

#define CHECK_EXACT(list) \
    check_exact((list), (int)(sizeof(list) / sizeof((list)[0])), __LINE__)

/* ------------------------------------------------- hand-computed examples */

static void test_hand(void)
{
    /* Pixel-unit vertices (1,1), (5,1), (1,5): interior x >= 1, y >= 1,
     * x + y <= 6.  Centres (n + 1/2): left/top edges x = 1, y = 1 hit no
     * centre; the hypotenuse x + y = 6 passes through the centres of
     * px + py = 5, which lie on a right/bottom (not top-left) edge and are
     * not drawn.  So px, py >= 1 and px + py <= 4: six pixels.
     * Box: ceil((16-8)/16) = 1 .. floor((80-8)/16) = 4 -> 4 x 4 samples. */
    static const int32_t t1[6] = { 16, 16, 80, 16, 16, 80 };
    static const int px1[][2] = { { 1, 1 }, { 2, 1 }, { 3, 1 },
                                  { 1, 2 }, { 2, 2 }, { 1, 3 } };
    CHECK_EQ(draw(t1), 6);
    CHECK_EXACT(px1);
    CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 16);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_IN), 1);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_REJECTED), 0);
    CHECK_EQ(perf(GPU_REG_ERRORS), 0);

    /* Off-grid vertices (1.25,0.25), (6.25,2.5), (1.875,5.625) px; no pixel
     * centre lies on an edge.  Box: x ceil(12/16)=1 .. floor(92/16)=5,
     * y ceil(-4/16)=0 .. floor(82/16)=5 -> 5 x 6 = 30 samples.
     *   row 0: .#......   row 1: .###....   row 2: ..####..
     *   row 3: ..###...   row 4: ..#.....   rows 5+: empty        */
    static const int32_t t2[6] = { 20, 4, 100, 40, 30, 90 };
    static const int px2[][2] = {
        { 1, 0 }, { 1, 1 }, { 2, 1 }, { 3, 1 }, { 2, 2 }, { 3, 2 },
        { 4, 2 }, { 5, 2 }, { 2, 3 }, { 3, 3 }, { 4, 3 }, { 2, 4 },
    };
    CHECK_EQ(draw(t2), 12);
    CHECK_EXACT(px2);
    CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 30);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
}

/* --------------------------------------------------------- top-left rule */

static void test_top_left(void)
{
    /* Triangle with its corner on the centre of pixel (0,0) and edges
     * x = 0.5 (left), y = 0.5 (top), x + y = 5 (right side): centres on the
     * left and top edges are drawn, those on the hypotenuse are not.
     * Covered: px, py >= 0, px + py <= 3: 10 pixels. */
    static const int32_t a[6] = { CTR(0), CTR(0), CTR(0), CTR(4),
                                  CTR(4), CTR(0) };
    static const int pa[][2] = {
        { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 }, { 0, 1 },
        { 1, 1 }, { 2, 1 }, { 0, 2 }, { 1, 2 }, { 0, 3 },
    };
    CHECK_EQ(draw(a), 10);
    CHECK_EXACT(pa);

    /* Its mirror: edges x = 4.5 (right), y = 4.5 (bottom), x + y = 5 (now a
     * left/top edge).  Centres on the right and bottom edges are not drawn,
     * those on the hypotenuse are: px, py <= 3 and px + py >= 4: 6 pixels.
     * Together with the first: the 4 x 4 square, each pixel once. */
    static const int32_t b[6] = { CTR(4), CTR(4), CTR(4), CTR(0),
                                  CTR(0), CTR(4) };
    static const int pb[][2] = { { 3, 1 }, { 2, 2 }, { 3, 2 },
                                 { 1, 3 }, { 2, 3 }, { 3, 3 } };
    CHECK_EQ(draw(b), 6);
    CHECK_EXACT(pb);

    /* Axis-aligned rectangles [x0,x1] x [y0,y1] split along a diagonal, with
     * each side on a row/column of centres or 1/16 px either side of it.
     * The rule gives exactly the centres c with x0 <= c.x < x1 and
     * y0 <= c.y < y1 (left/top inclusive, right/bottom exclusive), each
     * covered once by the two halves. */
    const int32_t d[3] = { -1, 0, 1 };
    for (int ix0 = 0; ix0 < 3; ix0++) {
        for (int ix1 = 0; ix1 < 3; ix1++) {
            for (int iy0 = 0; iy0 < 3; iy0++) {
                for (int iy1 = 0; iy1 < 3; iy1++) {
                    int32_t x0 = CTR(10) + d[ix0], x1 = CTR(14) + d[ix1];
                    int32_t y0 = CTR(20) + d[iy0], y1 = CTR(23) + d[iy1];
                    for (int diag = 0; diag < 2; diag++) {
                        int32_t t[2][6];
                        if (diag == 0) { /* split along (x0,y0)-(x1,y1) */
                            int32_t u[2][6] = {
                                { x0, y0, x1, y0, x1, y1 },
                                { x0, y0, x1, y1, x0, y1 },
                            };
                            memcpy(t, u, sizeof t);
                        } else { /* split along (x1,y0)-(x0,y1) */
                            int32_t u[2][6] = {
                                { x0, y0, x1, y0, x0, y1 },
                                { x1, y0, x1, y1, x0, y1 },
                            };
                            memcpy(t, u, sizeof t);
                        }
                        uint16_t *acc = new_acc();
                        draw(t[0]);
                        accumulate(acc);
                        draw(t[1]);
                        accumulate(acc);
                        int bad = 0;
                        for (int py = 0; py < H; py++) {
                            for (int px = 0; px < W; px++) {
                                bool in = CTR(px) >= x0 && CTR(px) < x1 &&
                                          CTR(py) >= y0 && CTR(py) < y1;
                                bad += acc[py * W + px] != (in ? 1 : 0);
                            }
                        }
                        if (!CHECK_EQ(bad, 0)) {
                            printf("  rect x %d..%d y %d..%d diag %d\n", x0,
                                   x1, y0, y1, diag);
                        }
                        free(acc);
                    }
                }
            }
        }
    }

    /* A single vertical left edge through centres, moved by 1/16 px: column
     * 10 is drawn at x = CTR(10) and CTR(10) - 1, not at CTR(10) + 1. */
    for (int s = -1; s <= 1; s++) {
        int32_t t[6] = { CTR(10) + s, CTR(0), CTR(10) + s, CTR(8),
                         CTR(20), CTR(4) };
        draw(t);
        CHECK_EQ(test_back_px(g_m, 10, 4), s <= 0 ? 1 : 0);
        CHECK_EQ(test_back_px(g_m, 11, 4), 1);
    }
    /* A vertical right edge through centres: drawn only when moved right. */
    for (int s = -1; s <= 1; s++) {
        int32_t t[6] = { CTR(10) + s, CTR(0), CTR(0), CTR(4),
                         CTR(10) + s, CTR(8) };
        draw(t);
        CHECK_EQ(test_back_px(g_m, 10, 4), s > 0 ? 1 : 0);
        CHECK_EQ(test_back_px(g_m, 9, 4), 1);
    }
    /* A horizontal top edge (dy = 0, dx > 0 after orientation) vs bottom. */
    for (int s = -1; s <= 1; s++) {
        int32_t top[6] = { CTR(0), CTR(10) + s, CTR(8), CTR(10) + s,
                           CTR(4), CTR(20) };
        draw(top);
        CHECK_EQ(test_back_px(g_m, 4, 10), s <= 0 ? 1 : 0);
        int32_t bot[6] = { CTR(0), CTR(10) + s, CTR(4), CTR(0),
                           CTR(8), CTR(10) + s };
        draw(bot);
        CHECK_EQ(test_back_px(g_m, 4, 10), s > 0 ? 1 : 0);
    }
}

/* ------------------------------------------------------------ zero area */

static void test_zero_area(void)
{
    static const int32_t cases[][6] = {
        { 100, 100, 200, 150, 300, 200 },          /* collinear, slanted */
        { 100, 100, 100, 100, 100, 100 },          /* one point */
        { 100, 100, 100, 100, 400, 300 },          /* two equal vertices */
        { 40, CTR(5), 400, CTR(5), 200, CTR(5) },  /* horizontal on centres */
        { CTR(5), 40, CTR(5), 400, CTR(5), 200 },  /* vertical on centres */
        { -32768, -32768, 32767, 32767, 0, 0 },    /* huge, collinear */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const int32_t *t = cases[i];
        CHECK_EQ(draw(t), 0);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_REJECTED), 1);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 0);
        CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 0);
        CHECK_EQ(perf(GPU_REG_ERRORS), 0);
        int nonzero = 0;
        for (int p = 0; p < NPIX; p++) {
            nonzero += gpu_model_back(g_m)[p] != 0;
        }
        CHECK_EQ(nonzero, 0);
    }
    /* Moving the last one's third vertex by 1/16 px gives area
     * 65535 * 32767 - 65535 * 32768 = -65535: a huge sliver along the
     * diagonal, which is drawn (box = whole screen). */
    static const int32_t sliver[6] = { -32768, -32768, 32767, 32767, 0, -1 };
    draw(sliver);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
    CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), (uint32_t)NPIX);
}

/* ------------------------------------------------- shared edges, meshes */

/* Draw each triangle alone into the (cleared) model and count how many
 * triangles cover each pixel. */
static uint16_t *coverage_of(const int32_t (*tris)[6], int n,
                             uint32_t *pixel_sum)
{
    uint16_t *acc = new_acc();
    *pixel_sum = 0;
    for (int i = 0; i < n; i++) {
        *pixel_sum += draw(tris[i]);
        accumulate(acc);
    }
    return acc;
}

static void test_fans(void)
{
    /* Eight triangles around the centre of pixel (160,120), to ring points
     * 12 px away along the axes and diagonals: every edge runs through
     * pixel centres.  The union is the square |dx|,|dy| <= 12 px around the
     * centre; each centre strictly inside is covered exactly once, and
     * nothing is covered twice (including the centre vertex itself). */
    const int32_t cx = CTR(160), cy = CTR(120), r = 12 * 16;
    const int32_t ring[8][2] = {
        { r, 0 }, { r, r }, { 0, r }, { -r, r },
        { -r, 0 }, { -r, -r }, { 0, -r }, { r, -r },
    };
    int32_t tris[8][6];
    for (int k = 0; k < 8; k++) {
        int j = (k + 1) % 8;
        int32_t t[6] = { cx, cy, cx + ring[k][0], cy + ring[k][1],
                         cx + ring[j][0], cy + ring[j][1] };
        memcpy(tris[k], t, sizeof t);
    }
    uint32_t sum;
    uint16_t *acc = coverage_of((const int32_t (*)[6])tris, 8, &sum);
    int over = 0, missing = 0, total = 0;
    for (int py = 0; py < H; py++) {
        for (int px = 0; px < W; px++) {
            uint16_t c = acc[py * W + px];
            over += c > 1;
            total += c;
            if (abs(px - 160) < 12 && abs(py - 120) < 12) {
                missing += c != 1;
            }
        }
    }
    CHECK_EQ(over, 0);
    CHECK_EQ(missing, 0);
    CHECK_EQ(acc[120 * W + 160], 1);
    /* Square side 24 px with centres on its boundary: half-open rule gives
     * 24 x 24 pixels. */
    CHECK_EQ(total, 24 * 24);
    CHECK_EQ(sum, (uint32_t)total);
    free(acc);

    /* Random fans: 5 seeds, 6..16 ring points in jittered directions (of 64)
     * and radii around a pixel centre, some snapped onto pixel centres.
     * Every pixel well inside the ring's inscribed circle is covered exactly
     * once, and no pixel twice. */
    test_srand(0xFA11u);
    for (int seed = 0; seed < 5; seed++) {
        int n = test_rand_range(6, 16);
        int32_t fan[16][6];
        int32_t pts[16][2];
        int dir[16];
        int32_t fx = CTR(test_rand_range(60, 260));
        int32_t fy = CTR(test_rand_range(60, 180));
        int64_t rmin2 = INT64_MAX;
        for (int k = 0; k < n; k++) {
            /* Direction index in [64k/n, 64(k+1)/n): strictly increasing. */
            int lo = 64 * k / n, hi = 64 * (k + 1) / n - 1;
            dir[k] = test_rand_range(lo, hi);
            int32_t rad = 16 * test_rand_range(20, 50) + test_rand_range(0, 15);
            int32_t x = fx + rad * COS64[dir[k]] / 1024;
            int32_t y = fy + rad * COS64[(dir[k] + 48) % 64] / 1024;
            if (test_rand() % 2) { /* snap onto a pixel centre */
                x = snap_centre(x);
                y = snap_centre(y);
            }
            pts[k][0] = x;
            pts[k][1] = y;
            int64_t d2 = (int64_t)(x - fx) * (x - fx) +
                         (int64_t)(y - fy) * (y - fy);
            rmin2 = d2 < rmin2 ? d2 : rmin2;
        }
        int gap = 0; /* largest angular gap, in 1/64 turns */
        for (int k = 0; k < n; k++) {
            int j = (k + 1) % n;
            int g = (dir[j] - dir[k] + 64) % 64;
            gap = g > gap ? g : gap;
            int32_t t[6] = { fx, fy, pts[k][0], pts[k][1], pts[j][0],
                             pts[j][1] };
            memcpy(fan[k], t, sizeof t);
        }
        /* The fan is a star polygon; it contains the disc of radius
         * rmin * cos(gap / 2) (half-gap rounded up, so cos is a lower
         * bound).  3 px of margin cover snapping and table rounding. */
        int64_t inner = isqrt(rmin2) * COS64[(gap + 1) / 2] / 1024 - 48;
        acc = coverage_of((const int32_t (*)[6])fan, n, &sum);
        over = 0;
        missing = 0;
        total = 0;
        for (int py = 0; py < H; py++) {
            for (int px = 0; px < W; px++) {
                uint16_t c = acc[py * W + px];
                int64_t dx = CTR(px) - fx, dy = CTR(py) - fy;
                over += c > 1;
                total += c;
                if (dx * dx + dy * dy < inner * inner) {
                    missing += c != 1;
                }
            }
        }
        CHECK(gap < 32 && inner > 16 * 10); /* the test itself is sound */
        CHECK_EQ(over, 0);
        CHECK_EQ(missing, 0);
        CHECK_EQ(acc[(fy / 16) * W + (fx / 16)], 1);
        CHECK_EQ(sum, (uint32_t)total);
        free(acc);
    }
}

/* A jittered grid mesh whose border lies in the guard band: every screen
 * pixel must be covered by exactly one triangle. */
static void test_mesh(void)
{
    enum { CW = 10, CH = 8 }; /* cells */
    static int32_t vx[CH + 1][CW + 1], vy[CH + 1][CW + 1];
    static int32_t tris[CW * CH * 2][6];
    test_srand(0x3E5Bu);
    for (int round = 0; round < 3; round++) {
        for (int j = 0; j <= CH; j++) {
            for (int i = 0; i <= CW; i++) {
                /* Cells of 40 x 40 px from (-40,-40) px; borders fixed. */
                int32_t x = 16 * (-40 + 40 * i);
                int32_t y = 16 * (-40 + 40 * j);
                if (i > 0 && i < CW && j > 0 && j < CH) {
                    /* +-9 px (+ snapping) keeps every 40 px cell convex,
                     * so either diagonal splits it into two triangles. */
                    x += test_rand_range(-16 * 9, 16 * 9);
                    y += test_rand_range(-16 * 9, 16 * 9);
                    if (test_rand() % 2) {
                        x = snap_centre(x); /* onto a pixel centre */
                        y = snap_centre(y);
                    }
                }
                if (round == 2 && j == 0) {
                    y = -32768; /* guard-band extremes on the border */
                }
                if (round == 2 && i == CW) {
                    x = 32767;
                }
                vx[j][i] = x;
                vy[j][i] = y;
            }
        }
        int n = 0;
        for (int j = 0; j < CH; j++) {
            for (int i = 0; i < CW; i++) {
                int32_t ax = vx[j][i], ay = vy[j][i];
                int32_t bx = vx[j][i + 1], by = vy[j][i + 1];
                int32_t cx = vx[j + 1][i + 1], cy = vy[j + 1][i + 1];
                int32_t dx = vx[j + 1][i], dy = vy[j + 1][i];
                /* Random diagonal and random winding per triangle. */
                int32_t t0[6], t1[6];
                if (test_rand() % 2) {
                    int32_t u0[6] = { ax, ay, bx, by, cx, cy };
                    int32_t u1[6] = { ax, ay, cx, cy, dx, dy };
                    memcpy(t0, u0, sizeof t0);
                    memcpy(t1, u1, sizeof t1);
                } else {
                    int32_t u0[6] = { ax, ay, bx, by, dx, dy };
                    int32_t u1[6] = { bx, by, cx, cy, dx, dy };
                    memcpy(t0, u0, sizeof t0);
                    memcpy(t1, u1, sizeof t1);
                }
                if (test_rand() % 2) {
                    int32_t s[6] = { t0[0], t0[1], t0[4], t0[5], t0[2],
                                     t0[3] };
                    memcpy(t0, s, sizeof s);
                }
                memcpy(tris[n++], t0, sizeof t0);
                memcpy(tris[n++], t1, sizeof t1);
            }
        }
        uint32_t sum;
        uint16_t *acc = coverage_of((const int32_t (*)[6])tris, n, &sum);
        int bad = 0;
        for (int p = 0; p < NPIX; p++) {
            if (acc[p] != 1 && bad++ < 5) {
                printf("  mesh round %d: pixel (%d,%d) covered %u times\n",
                       round, p % W, p / W, acc[p]);
            }
        }
        CHECK_EQ(bad, 0);
        CHECK_EQ(sum, (uint32_t)NPIX);
        free(acc);
    }
}

/* --------------------------------------------- guard band, off screen */

static bool all_back(uint8_t v)
{
    for (int p = 0; p < NPIX; p++) {
        if (gpu_model_back(g_m)[p] != v) {
            return false;
        }
    }
    return true;
}

static void test_guard_band(void)
{
    /* Triangles with vertices at the int16 extremes that contain the whole
     * screen: every pixel drawn, box clamped to the screen, no overflow. */
    static const int32_t big[][6] = {
        { -32768, -32768, 32767, -32768, 0, 32767 },
        { -32768, -32768, 0, 32767, 32767, -32768 },
        { -32768, 32767, 32767, 32767, 0, -32768 },
        { -32768, -32768, 32767, 0, -32768, 32767 },
        { 32767, 32767, -32768, 0, 32767, -32768 },
    };
    for (size_t i = 0; i < sizeof big / sizeof big[0]; i++) {
        CHECK_EQ(draw(big[i]), (uint32_t)NPIX);
        CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), (uint32_t)NPIX);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
        CHECK(all_back(1));
    }

    /* Off screen: box with no pixel centre on the screen -> rejected, no
     * error, no samples.  Includes boxes ending just short of the first /
     * last centre (x max = 7 < 8, x min = 5113 > 5112). */
    static const int32_t off[][6] = {
        { -32768, 0, -100, 0, -200, 1000 },         /* left */
        { -100, 0, 7, 100, -200, 1000 },            /* left, max x = 7 */
        { 5113, 0, 6000, 100, 32767, 1000 },        /* right, min x = 5113 */
        { 0, -500, 1000, -9, 300, -32768 },         /* above */
        { 0, 3833, 1000, 4000, 300, 32767 },        /* below, min y = 3833 */
        { 5200, 4000, 32767, 32767, 6000, 32000 },  /* below right */
        { 9, 9, 23, 9, 9, 23 },                     /* between centres */
    };
    for (size_t i = 0; i < sizeof off / sizeof off[0]; i++) {
        CHECK_EQ(draw(off[i]), 0);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_REJECTED), 1);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 0);
        CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 0);
        CHECK_EQ(perf(GPU_REG_ERRORS), 0);
        CHECK(all_back(0));
    }

    /* Boxes that just reach the first / last centre are not rejected. */
    static const int32_t edge[][6] = {
        { -100, 0, 8, 100, -200, 1000 },      /* max x = 8 = CTR(0) */
        { 5112, 0, 6000, 100, 32767, 1000 },  /* min x = 5112 = CTR(319) */
    };
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        draw(edge[i]);
        CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
        CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 1u * (uint32_t)(1000 - 8) / 16 + 1);
    }

    /* A thin sliver between y = 0.4x and y = 1 + 0.375x (Q12.4) whose box
     * holds the centres of (0,0), (1,0), (2,0) but which covers none: it
     * counts as drawn, with 0 pixels and 3 samples. */
    static const int32_t sliver[6] = { 0, 0, 40, 16, 0, 1 };
    CHECK_EQ(draw(sliver), 0);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_DRAWN), 1);
    CHECK_EQ(perf(GPU_REG_PERF_TRIS_REJECTED), 0);
    CHECK_EQ(perf(GPU_REG_PERF_SAMPLES), 3);
}

/* ------------------------------------- random triangles vs a reference */

/*
 * Reference rasterizer, structured differently from the model on purpose:
 * each edge as the expanded line equation A*x + B*y + C, orientation handled
 * by reversing the edges instead of swapping vertices, the box found by
 * scanning the screen for centres inside the vertex extremes, and coverage by
 * testing every screen pixel.
 */
typedef struct {
    int64_t a, b, c;
    bool top_left;
} ref_edge;

static ref_edge ref_make_edge(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    ref_edge e = { ay - by, bx - ax, ax * by - ay * bx,
                   (by - ay) < 0 || ((by - ay) == 0 && (bx - ax) > 0) };
    return e;
}

typedef struct {
    bool drawn;
    uint32_t pixels;
    uint32_t samples;
} ref_result;

static ref_result ref_raster(const int32_t t[6], uint8_t *fb)
{
    ref_result r = { false, 0, 0 };
    int64_t x[3] = { t[0], t[2], t[4] }, y[3] = { t[1], t[3], t[5] };
    int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    memset(fb, 0, (size_t)NPIX);
    if (area == 0) {
        return r;
    }
    ref_edge e[3];
    for (int k = 0; k < 3; k++) {
        int j = (k + 1) % 3;
        e[k] = area > 0 ? ref_make_edge(x[k], y[k], x[j], y[j])
                        : ref_make_edge(x[j], y[j], x[k], y[k]);
    }
    int64_t lox = x[0], hix = x[0], loy = y[0], hiy = y[0];
    for (int k = 1; k < 3; k++) {
        lox = x[k] < lox ? x[k] : lox;
        hix = x[k] > hix ? x[k] : hix;
        loy = y[k] < loy ? y[k] : loy;
        hiy = y[k] > hiy ? y[k] : hiy;
    }
    uint32_t cols = 0, rows = 0;
    for (int px = 0; px < W; px++) {
        cols += CTR(px) >= lox && CTR(px) <= hix;
    }
    for (int py = 0; py < H; py++) {
        rows += CTR(py) >= loy && CTR(py) <= hiy;
    }
    if (cols == 0 || rows == 0) {
        return r;
    }
    r.drawn = true;
    r.samples = cols * rows;
    for (int py = 0; py < H; py++) {
        for (int px = 0; px < W; px++) {
            bool in = true;
            for (int k = 0; k < 3 && in; k++) {
                int64_t v = e[k].a * CTR(px) + e[k].b * CTR(py) + e[k].c;
                in = v > 0 || (v == 0 && e[k].top_left);
            }
            if (in) {
                fb[py * W + px] = 1;
                r.pixels++;
            }
        }
    }
    return r;
}

/* A random triangle of one of several flavours that stress the rule. */
static void random_tri(int32_t t[6], int flavour)
{
    int32_t cx = test_rand_range(-32, W + 32) * 16;
    int32_t cy = test_rand_range(-32, H + 32) * 16;
    for (int k = 0; k < 3; k++) {
        int32_t x, y;
        switch (flavour) {
        case 0: /* small, anywhere near the screen, any sub-pixel */
            x = cx + test_rand_range(-16 * 24, 16 * 24);
            y = cy + test_rand_range(-16 * 24, 16 * 24);
            break;
        case 1: /* vertices on pixel centres or pixel corners */
            x = cx + 8 * test_rand_range(-40, 40);
            y = cy + 8 * test_rand_range(-40, 40);
            break;
        case 2: /* anywhere in the full Q12.4 range */
            x = test_rand_range(-32768, 32767);
            y = test_rand_range(-32768, 32767);
            break;
        default: /* screen-sized, near the screen */
            x = test_rand_range(-16 * 100, 16 * (W + 100));
            y = test_rand_range(-16 * 100, 16 * (H + 100));
            break;
        }
        t[2 * k] = x < -32768 ? -32768 : (x > 32767 ? 32767 : x);
        t[2 * k + 1] = y < -32768 ? -32768 : (y > 32767 ? 32767 : y);
    }
    if (flavour == 1 && test_rand() % 4 == 0) {
        /* Make it degenerate: v2 on the line v0 v1 (maybe off the segment). */
        int32_t k = test_rand_range(-2, 2);
        int32_t x = t[0] + k * (t[2] - t[0]);
        int32_t y = t[1] + k * (t[3] - t[1]);
        if (x >= -32768 && x <= 32767 && y >= -32768 && y <= 32767) {
            t[4] = x;
            t[5] = y;
        }
    }
}

static void test_random_vs_reference(void)
{
    uint8_t *ref = malloc((size_t)NPIX);
    uint8_t *got = malloc((size_t)NPIX);
    if (ref == NULL || got == NULL) {
        exit(2);
    }
    test_srand(0xC0FFEEu);
    int mismatches = 0, drawn = 0;
    const int n = 4000;
    for (int i = 0; i < n; i++) {
        int32_t t[6];
        random_tri(t, i % 4);
        ref_result r = ref_raster(t, ref);
        uint32_t pixels = draw(t);
        bool ok = pixels == r.pixels &&
                  perf(GPU_REG_PERF_SAMPLES) == r.samples &&
                  perf(GPU_REG_PERF_TRIS_DRAWN) == (r.drawn ? 1u : 0u) &&
                  perf(GPU_REG_PERF_TRIS_REJECTED) == (r.drawn ? 0u : 1u) &&
                  memcmp(gpu_model_back(g_m), ref, (size_t)NPIX) == 0;
        drawn += r.drawn;
        if (!ok && mismatches++ < 5) {
            printf("  reference mismatch: (%d,%d) (%d,%d) (%d,%d): model %u "
                   "px %u samples, reference %u px %u samples\n",
                   t[0], t[1], t[2], t[3], t[4], t[5], pixels,
                   perf(GPU_REG_PERF_SAMPLES), r.pixels, r.samples);
        }
        if (!ok) {
            continue;
        }

        /* Invariances: the other winding and rotated vertex order draw the
         * identical pixels and counters. */
        memcpy(got, gpu_model_back(g_m), (size_t)NPIX);
        int32_t rev[6] = { t[0], t[1], t[4], t[5], t[2], t[3] };
        int32_t rot[6] = { t[2], t[3], t[4], t[5], t[0], t[1] };
        CHECK_EQ(draw(rev), pixels);
        CHECK(memcmp(gpu_model_back(g_m), got, (size_t)NPIX) == 0);
        CHECK_EQ(draw(rot), pixels);
        CHECK(memcmp(gpu_model_back(g_m), got, (size_t)NPIX) == 0);
    }
    CHECK_EQ(mismatches, 0);
    CHECK(drawn > n / 4); /* the mix really exercises drawing */
    free(ref);
    free(got);
}

/* Moving a triangle by whole pixels moves its coverage by as many pixels
 * (the rule depends only on positions relative to the centres). */
static void test_translation(void)
{
    uint8_t *a = malloc((size_t)NPIX);
    if (a == NULL) {
        exit(2);
    }
    test_srand(0x7EA5u);
    int bad = 0;
    for (int i = 0; i < 300; i++) {
        int32_t t[6];
        int32_t ox = 16 * test_rand_range(40, 80);
        int32_t oy = 16 * test_rand_range(40, 80);
        for (int k = 0; k < 3; k++) {
            t[2 * k] = ox + test_rand_range(0, 16 * 30);
            t[2 * k + 1] = oy + test_rand_range(0, 16 * 30);
        }
        uint32_t p0 = draw(t);
        memcpy(a, gpu_model_back(g_m), (size_t)NPIX);
        int sx = test_rand_range(-30, 100), sy = test_rand_range(-30, 60);
        int32_t u[6] = { t[0] + 16 * sx, t[1] + 16 * sy, t[2] + 16 * sx,
                         t[3] + 16 * sy, t[4] + 16 * sx, t[5] + 16 * sy };
        uint32_t p1 = draw(u);
        bad += p0 != p1;
        for (int py = 0; py < H; py++) {
            for (int px = 0; px < W; px++) {
                int qx = px + sx, qy = py + sy;
                if (qx >= 0 && qx < W && qy >= 0 && qy < H) {
                    bad += a[py * W + px] != test_back_px(g_m, qx, qy);
                }
            }
        }
    }
    CHECK_EQ(bad, 0);
    free(a);
}

/* 51200 triangles (100 full batches of TRI_CAP) through the bus in full batches, shaped like a scene: a
 * strip over a random walk of vertices (small triangles, steps up to 24 px,
 * some degenerate) with an occasional jump anywhere in the Q12.4 range
 * (huge triangles).  The counters stay consistent; this also shows the
 * model is fast enough for co-simulation-sized runs. */
static void test_bulk(void)
{
    gpu_model *m = test_new_model();
    test_srand(0xB01Cu);
    uint32_t in = 0, drawn = 0, rejected = 0, bad_pixels = 0;
    const uint32_t per_batch = GPU_TRI_CAP; /* 512 */
    for (uint32_t b = 0; b < 100; b++) {
        int32_t x = 16 * 160, y = 16 * 120;
        for (uint32_t v = 0; v < GPU_VTX_CAP; v++) {
            if (test_rand() % 64 == 0) {
                x = test_rand_range(-32768, 32767);
                y = test_rand_range(-32768, 32767);
            } else {
                /* Step, then drift back towards the screen centre so the
                 * walk stays mostly on screen after a jump. */
                x += test_rand_range(-16 * 24, 16 * 24);
                y += test_rand_range(-16 * 24, 16 * 24);
                x += (16 * 160 - x) / 8;
                y += (16 * 120 - y) / 8;
            }
            test_set_vtx(m, v, x, y);
        }
        for (uint32_t p = 0; p < per_batch; p++) {
            test_set_prim(m, p, p, p + 1, p + 2, test_rand() & 0xFFu,
                          GPU_PRIM_KIND_TRI);
        }
        test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, 0, GPU_VTX_CAP,
                   0, per_batch, 0, b + 1);
        in += gpu_model_read(m, GPU_REG_PERF_TRIS_IN);
        drawn += gpu_model_read(m, GPU_REG_PERF_TRIS_DRAWN);
        rejected += gpu_model_read(m, GPU_REG_PERF_TRIS_REJECTED);
        bad_pixels += gpu_model_read(m, GPU_REG_PERF_PIXELS) >
                      gpu_model_read(m, GPU_REG_PERF_SAMPLES);
    }
    CHECK_EQ(in, 100u * per_batch);
    CHECK_EQ(drawn + rejected, in);
    CHECK(drawn > in / 2);
    CHECK_EQ(bad_pixels, 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 100);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 100);
    free(m);
}

void test_raster(void)
{
    g_m = test_new_model();
    test_hand();
    test_top_left();
    test_zero_area();
    test_fans();
    test_mesh();
    test_guard_band();
    test_random_vs_reference();
    test_translation();
    test_bulk();
    free(g_m);
}
