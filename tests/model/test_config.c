/*
 * test_config.c - unit tests of the model's build options and the contract
 * 1.1 register additions: CAPS per configuration, CTRL keeping its four
 * defined bits, the RESET register, and PERF_SPANS_WRITTEN (triangle rule,
 * "Spans") for every span width.
 *
 * Expected values come from contract/gpu-contract.md, computed by hand (the
 * arithmetic is in the comments).
 */
#include <stdlib.h>
#include <string.h>

#include "model_test.h"

/* ------------------------------------------------------------- CAPS */

static uint32_t caps_of(unsigned span_w, bool lines, bool zbuf)
{
    gpu_model *m = test_new_model_cfg(span_w, lines, zbuf);
    uint32_t caps = gpu_model_read(m, GPU_REG_CAPS);
    CHECK_EQ(caps, gpu_model_caps(m));
    free(m);
    return caps;
}

static void test_caps(void)
{
    /* CAPS = LINES [0] | ZBUF [1] | SPAN_W [15:8] | ZBUF_BITS [20:16] (16,
     * the default, with the depth buffer; 0 without). */
    CHECK_EQ(caps_of(1, false, false), 0x0100u);
    CHECK_EQ(caps_of(4, true, false), 0x0401u);
    CHECK_EQ(caps_of(8, true, false), 0x0801u); /* the RTL defaults, but the mask */
    CHECK_EQ(caps_of(8, false, true), 0x100802u);
    CHECK_EQ(caps_of(16, true, true), 0x101003u);
    CHECK_EQ(caps_of(16, false, false), 0x1000u);
    /* Field by field through the generated masks. */
    uint32_t c = caps_of(4, false, true);
    CHECK_EQ((c & GPU_CAPS_SPAN_W_MASK) >> GPU_CAPS_SPAN_W_LSB, 4);
    CHECK_EQ(c & GPU_CAPS_LINES_MASK, 0);
    CHECK_EQ(c & GPU_CAPS_ZBUF_MASK, GPU_CAPS_ZBUF_MASK);

    /* An unsupported span width falls back to the default 8. */
    CHECK_EQ(caps_of(3, false, false), 0x0800u);
    CHECK_EQ(caps_of(0, true, false), 0x0801u);
    CHECK_EQ(caps_of(32, false, true), 0x100802u);
    CHECK_EQ(caps_of(256 + 4, false, false), 0x0800u);

    gpu_model *m = test_new_model_cfg(16, false, true);
    CHECK_EQ(m->cfg.span_w, 16);
    CHECK(!m->cfg.lines);
    CHECK(m->cfg.zbuf);
    /* NULL: the defaults (SPAN_W 8, lines, the write mask [2]); gpu_model_reset: the defaults
     * again. */
    gpu_model_reset_config(m, NULL);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS), 0x0805u);
    gpu_model_config cfg = { 1, false, true, 0, 0, 12, false, false, 0, 0, 0 };
    gpu_model_reset_config(m, &cfg);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS), 0x0C0102u);
    gpu_model_reset(m);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS), 0x0805u);
    CHECK_EQ(m->cfg.span_w, 8);
    CHECK(m->cfg.lines);
    CHECK(!m->cfg.zbuf);

    /* reset_config is a power-on reset like gpu_model_reset: state from a
     * previous run is gone (zbuf, framebuffers, registers, counters). */
    cfg.span_w = 4;
    cfg.lines = true;
    cfg.zbuf = true;
    cfg.zbuf_bits = 16;
    gpu_model_reset_config(m, &cfg);
    test_set_vtxz(m, 0, 0, 0, 7);
    test_set_vtxz(m, 1, 800, 0, 7);
    test_set_vtxz(m, 2, 0, 800, 7);
    test_set_prim(m, 0, 0, 1, 2, 9, GPU_PRIM_KIND_TRI);
    test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_ZCLEAR_MASK |
                      GPU_CTRL_ZTEST_MASK,
               0, 3, 0, 1, 3, 0x77);
    gpu_model_write(m, GPU_REG_RESET, 5);
    CHECK_EQ(test_z(m, 0, 0), 7);
    CHECK_EQ(test_z(m, 319, 239), 0xFFFF);
    gpu_model_reset_config(m, &cfg);
    bool clean = true;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        clean = clean && m->zbuf[i] == 0 && m->fb[0][i] == 0 &&
                m->fb[1][i] == 0;
    }
    CHECK(clean);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_SPANS_WRITTEN), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS), 0x100403u);
    free(m);
}

/* ------------------------------------------------------------- CTRL */

static void test_ctrl(void)
{
    /* CTRL keeps CLEAR [0], SWAP [1], ZTEST [2], ZCLEAR [3], DITHER [4],
     * WALK [5]; other bits are not stored.  Same with and without the depth buffer
     * (without it ZTEST/ZCLEAR are stored but ignored, see test_depth.c). */
    static const uint32_t written_read[][2] = {
        { 0xFFFFFFFFu, 0x3F },
        { GPU_CTRL_ZTEST_MASK, 0x4 },
        { GPU_CTRL_ZCLEAR_MASK | 0x40u, 0x8 },
        { GPU_CTRL_WALK_MASK | 0x80u, 0x20 },
        { 0xFFFFFFC0u, 0 },
        { 0x5u, 0x5 },
    };
    for (int z = 0; z < 2; z++) {
        gpu_model *m = test_new_model_cfg(8, true, z != 0);
        for (size_t i = 0; i < sizeof written_read / sizeof written_read[0]; i++) {
            gpu_model_write(m, GPU_REG_CTRL, written_read[i][0]);
            if (!CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), written_read[i][1])) {
                printf("  CTRL written 0x%08X, %s depth buffer\n", (unsigned)written_read[i][0],
                       z ? "with" : "without");
            }
        }
        /* A batch does not change it. */
        gpu_model_write(m, GPU_REG_DOORBELL, 1);
        CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), 0x5);
        free(m);
    }
}

/* ------------------------------------------------------------ RESET */

static void test_reset_reg(void)
{
    gpu_model *m = test_new_model();

    /* A batch that leaves visible state everywhere: clear, a triangle, a
     * swap, an error flag. */
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 3u, 0x123u);
    test_set_vtx(m, 0, 16, 16);
    test_set_vtx(m, 1, 80, 16);
    test_set_vtx(m, 2, 16, 80);
    test_set_prim(m, 0, 0, 1, 2, 5, GPU_PRIM_KIND_TRI);
    test_set_prim(m, 1, 0, 1, 7, 5, GPU_PRIM_KIND_TRI); /* bad index */
    test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, 0, 3, 0, 2, 3,
               0x42);
    uint8_t *front = malloc(GPU_MODEL_FB_PIXELS);
    uint8_t *back = malloc(GPU_MODEL_FB_PIXELS);
    if (front == NULL || back == NULL) {
        exit(2);
    }
    memcpy(front, gpu_model_front(m), GPU_MODEL_FB_PIXELS);
    memcpy(back, gpu_model_back(m), GPU_MODEL_FB_PIXELS);
    const uint32_t regs[] = {
        GPU_REG_CTRL, GPU_REG_VTX_BASE, GPU_REG_VTX_COUNT, GPU_REG_TRI_BASE,
        GPU_REG_TRI_COUNT, GPU_REG_CLEAR_COLOR, GPU_REG_DOORBELL,
        GPU_REG_STATUS, GPU_REG_DONE_SEQ, GPU_REG_FRAME_COUNT,
        GPU_REG_ERRORS, GPU_REG_PERF_TRIS_IN, GPU_REG_PERF_TRIS_DRAWN,
        GPU_REG_PERF_TRIS_REJECTED, GPU_REG_PERF_PIXELS,
        GPU_REG_PERF_SAMPLES, GPU_REG_PERF_SPANS_WRITTEN,
    };
    enum { NREGS = sizeof regs / sizeof regs[0] };
    uint32_t before[NREGS];
    for (int i = 0; i < NREGS; i++) {
        before[i] = gpu_model_read(m, regs[i]);
    }
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_VTX_INDEX_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 1);

    /* RESET reads back what was written and, with no batch running (the
     * model never has one), changes nothing else: DONE_SEQ, ERRORS, the
     * counters, the buffers, the palette, FRAME_COUNT, STATUS all stay. */
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 0);
    gpu_model_write(m, GPU_REG_RESET, 0xCAFEF00Du);
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 0xCAFEF00Du);
    gpu_model_write(m, GPU_REG_RESET, 0xCAFEF00Du); /* same value again */
    gpu_model_write(m, GPU_REG_RESET, 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 1);
    int changed = 0;
    for (int i = 0; i < NREGS; i++) {
        changed += gpu_model_read(m, regs[i]) != before[i];
    }
    CHECK_EQ(changed, 0);
    CHECK(memcmp(front, gpu_model_front(m), GPU_MODEL_FB_PIXELS) == 0);
    CHECK(memcmp(back, gpu_model_back(m), GPU_MODEL_FB_PIXELS) == 0);
    CHECK_EQ(m->palette[3], 0x123u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ID), GPU_ID_VALUE);

    /* The next doorbell starts normally; RESET keeps its value. */
    test_batch(m, 0, 0, 3, 0, 1, 0, 0x43);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0x43);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 6);
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 1);
    /* Unaligned writes do not reach it. */
    gpu_model_write(m, GPU_REG_RESET + 1u, 0x99);
    CHECK_EQ(gpu_model_read(m, GPU_REG_RESET), 1);

    free(front);
    free(back);
    free(m);
}

/* ------------------------------------------------------------ spans */

/* Draw the primitives 0..n-1 (vertices 0..nv-1) with CLEAR and return
 * PERF_SPANS_WRITTEN. */
static uint32_t spans_of(gpu_model *m, uint32_t nv, uint32_t n)
{
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, nv, 0, n, 0, 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_SPANS_VISITED), 0);
    return gpu_model_read(m, GPU_REG_PERF_SPANS_WRITTEN);
}

/* Vertices 0..2 at Q12.4 (x0, y0), (x1, y1), (x2, y2). */
static void set_vtx3(gpu_model *m, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2,
                     int32_t y2)
{
    test_set_vtx(m, 0, x0, y0);
    test_set_vtx(m, 1, x1, y1);
    test_set_vtx(m, 2, x2, y2);
}

/* The rectangle (x0, y0) - (x1, y1) (Q12.4) as vertices 0..3 and two triangles split along the
 * diagonal: prim 0 (0, 1, 2) in colour 1, prim 1 (0, 2, 3) in colour 2. */
static void set_quad(gpu_model *m, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    set_vtx3(m, x0, y0, x1, y0, x1, y1);
    test_set_vtx(m, 3, x0, y1);
    test_set_prim(m, 0, 0, 1, 2, 1, GPU_PRIM_KIND_TRI);
    test_set_prim(m, 1, 0, 2, 3, 2, GPU_PRIM_KIND_TRI);
}

static void test_spans(void)
{
    static const unsigned widths[4] = { 1, 4, 8, 16 };

    /*
     * Rectangle x 96..288, y 32..64 (pixels 6..17 x 2..3; no pixel centre
     * on its border), split along its diagonal y = 32 + (x - 96) / 6 into
     *   A = (96,32) (288,32) (288,64)  above the diagonal,
     *   B = (96,32) (288,64) (96,64)   below it.
     * The diagonal meets row 2's centres (y = 40) at x = 144 and row 3's
     * (y = 56) at x = 240, between centres (136 | 152, 232 | 248), so
     *   A: row 2 px 9..17,  row 3 px 15..17   (12 pixels)
     *   B: row 2 px 6..8,   row 3 px 6..14    (12 pixels)
     * Spans (floor(px / W), row), counted per triangle:
     *   W=1:  A 9+3 = 12,                  B 3+9 = 12       -> 24
     *   W=4:  A {2,3,4}+{3,4} = 5,         B {1,2}+{1,2,3} = 5 -> 10
     *   W=8:  A {1,2}+{1,2} = 4,           B {0,1}+{0,1} = 4   -> 8
     *   W=16: A {0,1}+{0,1} = 4,           B {0}+{0} = 2       -> 6
     * (W=16 shows spans are counted per triangle: the union covers only 4.)
     * Box of each: px ceil(88/16)=6 .. floor(280/16)=17, py 2..3 = 24.
     */
    static const uint32_t want_rect[4] = { 24, 10, 8, 6 };
    static const uint32_t want_a[4] = { 12, 5, 4, 4 };

    /*
     * The off-grid triangle (20,4) (100,40) (30,90) of test_raster.c:
     *   row 0: px 1   row 1: px 1..3   row 2: px 2..5   row 3: px 2..4
     *   row 4: px 2
     *   W=1: 12; W=4: 1+1+2+2+1 = 7; W=8: 5; W=16: 5.
     */
    static const uint32_t want_t2[4] = { 12, 7, 5, 5 };

    /*
     * Partly left of the screen: (-100,0) (40,8) (-100,100) covers the
     * on-screen pixels (0,0), (1,0), (0,1) (centres (8,8), (24,8), (8,24)):
     *   W=1: 3; W=4, 8, 16: 2 (one span in each of rows 0 and 1).
     */
    static const uint32_t want_left[4] = { 3, 2, 2, 2 };

    /*
     * Right edge: rectangle x 4960..5120, y 0..16 (pixels 310..319 of row
     * 0), one triangle pair, A = top-right half, B = bottom-left half of a
     * 160 x 16 box: the diagonal y = x'/10 (x' = x - 4960) meets the row's
     * centre y = 8 at x' = 80 = the boundary between px 314 and 315
     * (centres x' = 72 and 88): A covers px 315..319, B px 310..314.
     *   W=1: 5+5 = 10
     *   W=4: A {78, 79} (312..315 | 316..319) = 2, B {77, 78} = 2 -> 4
     *   W=8: A {39} = 1, B {38, 39} (304..311 | 312..319) = 2      -> 3
     *   W=16: A {19} = 1, B {19} = 1                              -> 2
     */
    static const uint32_t want_right[4] = { 10, 4, 3, 2 };

    for (int k = 0; k < 4; k++) {
        gpu_model *m = test_new_model_cfg(widths[k], true, false);

        set_quad(m, 96, 32, 288, 64);
        CHECK_EQ(spans_of(m, 4, 2), want_rect[k]);
        CHECK_PERF6(m, 2, 2, 0, 24, 48, want_rect[k]);
        /* Only the other winding of A: the same. */
        test_set_prim(m, 0, 0, 2, 1, 1, GPU_PRIM_KIND_TRI);
        CHECK_EQ(spans_of(m, 4, 1), want_a[k]);

        set_vtx3(m, 20, 4, 100, 40, 30, 90);
        test_set_prim(m, 0, 0, 1, 2, 1, GPU_PRIM_KIND_TRI);
        CHECK_EQ(spans_of(m, 3, 1), want_t2[k]);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 12);

        set_vtx3(m, -100, 0, 40, 8, -100, 100);
        CHECK_EQ(spans_of(m, 3, 1), want_left[k]);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 3);

        set_quad(m, 4960, 0, 5120, 16);  /* prim 0 as it already is */
        CHECK_EQ(spans_of(m, 4, 2), want_right[k]);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 10);
        CHECK_EQ(test_back_px(m, 314, 0), 2);
        CHECK_EQ(test_back_px(m, 315, 0), 1);

        /* A rejected (zero-area / off-screen) triangle and a line add no
         * spans; a line after a triangle leaves the triangle's count. */
        set_vtx3(m, 20, 4, 100, 40, 30, 90);
        test_set_vtx(m, 3, -500, -500);
        test_set_prim(m, 0, 0, 1, 2, 1, GPU_PRIM_KIND_TRI);
        test_set_prim(m, 1, 0, 1, 1, 2, GPU_PRIM_KIND_TRI);  /* zero area */
        test_set_prim(m, 2, 3, 3, 3, 2, GPU_PRIM_KIND_TRI);  /* zero area */
        test_set_prim(m, 3, 0, 1, 0, 3, GPU_PRIM_KIND_LINE); /* 5 px line */
        CHECK_EQ(spans_of(m, 4, 4), want_t2[k]);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_DRAWN), 2);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_REJECTED), 2);

        /* The next batch starts the counter from 0; ERR_COUNT leaves 0. */
        CHECK_EQ(spans_of(m, 4, 0), 0);
        test_batch(m, 0, 0, 4, 0, GPU_TRI_CAP + 1u, 0, 2);
        CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_COUNT_MASK);
        CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_SPANS_WRITTEN), 0);

        free(m);
    }

    /* A screen-filling triangle: every row has 320 / W spans, 240 rows. */
    for (int k = 0; k < 4; k++) {
        gpu_model *m = test_new_model_cfg(widths[k], false, false);
        test_set_vtx(m, 0, -32768, -32768);
        test_set_vtx(m, 1, 32767, -32768);
        test_set_vtx(m, 2, 0, 32767);
        test_set_prim(m, 0, 0, 1, 2, 1, GPU_PRIM_KIND_TRI);
        CHECK_EQ(spans_of(m, 3, 1), 240u * (320u / widths[k]));
        free(m);
    }
}

/* ------------------------------------------------------- FB_WRITE_MASK */

/* The write mask (contract FB_WRITE_MASK): 3 after reset; keeps only its two plane bits; ignored
 * without the option; a clear and a triangle write only the chosen nibbles of each pixel. */
static void test_write_mask(void)
{
    static const int32_t tri[6] = {16 * 10, 16 * 10, 16 * 10, 16 * 50, 16 * 50, 16 * 10};
    gpu_model *m = test_new_model();
    gpu_model *plain = test_new_model_cfg(8, true, false);

    CHECK_EQ(gpu_model_read(m, GPU_REG_CAPS) & GPU_CAPS_WMASK_MASK, GPU_CAPS_WMASK_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_WRITE_MASK), 3u);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 0xFFFFFFF1u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_WRITE_MASK), GPU_WMASK_LO_MASK);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 0u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_WRITE_MASK), 0u);
    /* Without the option the register stays 3 and every bit is written. */
    CHECK_EQ(gpu_model_read(plain, GPU_REG_CAPS) & GPU_CAPS_WMASK_MASK, 0u);
    gpu_model_write(plain, GPU_REG_FB_WRITE_MASK, 1u);
    CHECK_EQ(gpu_model_read(plain, GPU_REG_FB_WRITE_MASK), 3u);

    /* Both planes: clear to 0x5A; then the high plane only: a clear to 0xC3 gives 0xCA; then
     * the low plane only, a triangle of colour 0x71 inside: 0xC1 there, 0xCA elsewhere; mask 0:
     * a clear changes nothing. PERF_PIXELS counts the covered pixels whatever the mask. */
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 3u);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 0, 0x5Au, 100);
    CHECK_EQ(test_back_px(m, 0, 0), 0x5Au);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, GPU_WMASK_HI_MASK);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 0, 0xC3u, 101);
    CHECK_EQ(test_back_px(m, 0, 0), 0xCAu);
    CHECK_EQ(test_back_px(m, 319, 239), 0xCAu);
    for (uint32_t i = 0; i < 3; i++) {
        test_set_vtx(m, i, tri[2 * i], tri[2 * i + 1]);
    }
    test_set_prim(m, 0, 0, 1, 2, 0x71u, GPU_PRIM_KIND_TRI);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, GPU_WMASK_LO_MASK);
    test_batch(m, 0, 0, 3, 0, 1, 0, 102);
    CHECK_EQ(test_back_px(m, 15, 15), 0xC1u);
    CHECK_EQ(test_back_px(m, 5, 5), 0xCAu);
    CHECK(gpu_model_read(m, GPU_REG_PERF_PIXELS) > 0u);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 0u);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 1, 0x00u, 103);
    CHECK_EQ(test_back_px(m, 15, 15), 0xC1u);
    CHECK_EQ(test_back_px(m, 5, 5), 0xCAu);
    CHECK(gpu_model_read(m, GPU_REG_PERF_PIXELS) > 0u);
    free(m);
    free(plain);
}

/* ------------------------------------------------------- capacities */

/* A GPU built with smaller buffers (contract: VTX_CAP / TRI_CAP are build
 * parameters, reported in the registers of those names): the registers, the
 * ERR_COUNT check (BASE + COUNT > CAP) and the window words past the capacity
 * (unmapped: ignored, not wrapped) follow the configured sizes. */
static void test_capacities(void)
{
    gpu_model *m = test_new_model();
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), GPU_VTX_CAP);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), GPU_TRI_CAP);

    gpu_model_config cfg = { 8, true, false, 32, 16, 0, false, false, 0, 0, 0 };
    CHECK(gpu_model_config_error(&cfg) == NULL);
    gpu_model_reset_config(m, &cfg);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), 32);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), 16);

    /* Vertices 0-2 a triangle of 8x8 pixels; vertex 32 and primitive 16 are
     * past the buffers: written to alias 0 if they wrapped, they are dropped. */
    test_set_vtx(m, 0, 0, 0);
    test_set_vtx(m, 1, 8 * 16, 0);
    test_set_vtx(m, 2, 0, 8 * 16);
    test_set_prim(m, 15, 0, 1, 2, 5, GPU_PRIM_KIND_TRI);
    test_set_vtx(m, 32, 200 * 16, 200 * 16); /* would be vertex 0 */
    test_set_prim(m, 16, 1, 1, 1, 9, GPU_PRIM_KIND_TRI); /* would be prim 0 */
    CHECK_EQ(m->vtx[32 * GPU_VTX_WORDS], 0); /* the array's word, not the GPU's */
    test_set_prim(m, 0, 0, 1, 2, 7, GPU_PRIM_KIND_TRI);
    /* The last vertex and primitive in range: drawn, no error. */
    test_batch(m, GPU_CTRL_CLEAR_MASK, 29, 3, 15, 1, 0, 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 32, 0, 16, 0, 2);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), 16);
    CHECK_EQ(gpu_model_back(m)[0], 5);          /* prim 15, drawn last */
    /* Prim 0 alone: still colour 7 on vertices 0-2 (a wrapped vertex 32 would
     * have moved vertex 0 off the pixel, a wrapped prim 16 made it colour 9). */
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 1, 0, 6);
    CHECK_EQ(gpu_model_back(m)[0], 7);
    /* One over either capacity: ERR_COUNT, nothing drawn; a full-size GPU
     * would have taken both batches. */
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 33, 0, 1, 3, 3);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_COUNT_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), 0);
    CHECK_EQ(gpu_model_back(m)[0], 7);          /* no clear either */
    test_batch(m, 0, 0, 3, 1, 16, 0, 4);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_COUNT_MASK);
    /* An index past VTX_COUNT is still ERR_VTX_INDEX, not ERR_COUNT. */
    test_set_prim(m, 1, 0, 1, 3, 7, GPU_PRIM_KIND_TRI);
    test_batch(m, 0, 0, 3, 1, 1, 0, 5);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_VTX_INDEX_MASK);

    /* 0: the contract's limits; above what the window holds (VTX_CAP_MAX):
     * refused by gpu_model_config_error, replaced by the contract's limit by
     * reset_config; up to it, taken (larger than the limit too). */
    gpu_model_config zero = { 8, true, false, 0, 0, 0, false, false, 0, 0, 0 };
    CHECK(gpu_model_config_error(&zero) == NULL);
    gpu_model_reset_config(m, &zero);
    CHECK_EQ(m->cfg.vtx_cap, GPU_VTX_CAP);
    CHECK_EQ(m->cfg.tri_cap, GPU_TRI_CAP);
    gpu_model_config big = { 8, true, false, GPU_VTX_CAP_MAX + 1u, 16, 0, false, false, 0, 0, 0 };
    CHECK(gpu_model_config_error(&big) != NULL);
    gpu_model_reset_config(m, &big);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), GPU_VTX_CAP);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), 16);
    big.vtx_cap = 32;
    big.tri_cap = GPU_TRI_CAP_MAX * 2u;
    CHECK(gpu_model_config_error(&big) != NULL);
    big.vtx_cap = GPU_VTX_CAP_MAX;
    big.tri_cap = GPU_TRI_CAP_MAX;
    CHECK(gpu_model_config_error(&big) == NULL);
    gpu_model_reset_config(m, &big);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), GPU_VTX_CAP_MAX);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), GPU_TRI_CAP_MAX);
    free(m);
}

/* ------------------------------------------------------------- frame size */

/* The largest frame (contract: FB_MAX_WIDTH x FB_MAX_HEIGHT, 640 x 480, shown
 * 1:1) follows the same rules with its own bounds: FB_SIZE, the clear, the
 * clamp of the box to the last column and row, the line's clip, and a
 * scan-out without the 2 x 2 blocks. Any other size is refused. */
static void test_frame_sizes(void)
{
    gpu_model *m = test_new_model();
    gpu_model_config cfg = m->cfg;
    cfg.fb_width = GPU_FB_MAX_WIDTH;
    cfg.fb_height = GPU_FB_MAX_HEIGHT;
    CHECK(gpu_model_config_error(&cfg) == NULL);
    gpu_model_reset_config(m, &cfg);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_SIZE), 640u | (480u << 16));

    /* A clear reaches every one of the 307,200 pixels, and nothing past them. */
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 7, 1);
    size_t sevens = 0;
    for (size_t i = 0; i < GPU_MODEL_MAX_FB_PIXELS; i++) {
        sevens += gpu_model_back(m)[i] == 7u;
    }
    CHECK_EQ(sevens, 640u * 480u);

    /* A triangle around the centre of pixel (639, 479), Q12.4 (10232, 7672),
     * reaching past the frame but not back to the centres of column 638
     * (x 10216) or row 478 (y 7656): the box clamps to the last column and
     * row, so that pixel alone is drawn (the hypotenuse passes x = 10393
     * there). */
    const int32_t corner[6] = {10225, 7665, 10400, 7665, 10225, 7840};
    CHECK_EQ(test_draw_one(m, corner, 9), 1);
    CHECK_EQ(test_back_px(m, 639, 479), 9);
    CHECK_EQ(test_back_px(m, 638, 479), 0);

    /* A line from pixel (600, 470) rightwards for 100 steps: the 40 plots
     * at x = 600 .. 639 are on screen. */
    test_set_vtx(m, 0, 600 * 16, 470 * 16);
    test_set_vtx(m, 1, 700 * 16, 470 * 16);
    test_set_prim(m, 0, 0, 1, 1, 5, GPU_PRIM_KIND_LINE);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 2, 0, 1, 0, 2);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), 40);
    CHECK_EQ(test_back_px(m, 639, 470), 5);

    /* Scan-out 1:1: the screen's pixel (639, 479) is the frame's, its
     * neighbour (638, 479) another. */
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 9u, 0xF00u);
    test_draw_one(m, corner, 9);
    test_batch(m, GPU_CTRL_SWAP_MASK, 0, 0, 0, 0, 0, 3);
    uint8_t *rgb = malloc(GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3u);
    CHECK(rgb != NULL);
    gpu_model_scanout(m, rgb);
    const size_t last = ((size_t)479 * GPU_MODEL_SCREEN_W + 639) * 3u;
    CHECK_EQ(rgb[last], 0xFF);
    CHECK_EQ(rgb[last - 3u], 0x00);
    free(rgb);

    /* The contract's frame draws none of it: the corner is off its screen. */
    gpu_model_reset(m);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_SIZE), 320u | (240u << 16));
    CHECK_EQ(test_draw_one(m, corner, 9), 0);

    /* Any other frame is refused, and replaced by the contract's. */
    cfg.fb_width = GPU_FB_MAX_WIDTH;
    cfg.fb_height = GPU_FB_HEIGHT;
    CHECK(gpu_model_config_error(&cfg) != NULL);
    gpu_model_reset_config(m, &cfg);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_SIZE), 320u | (240u << 16));
    free(m);
}

void test_config(void)
{
    test_caps();
    test_write_mask();
    test_capacities();
    test_ctrl();
    test_reset_reg();
    test_spans();
    test_frame_sizes();
}
