/*
 * test_model.c - unit tests of the GPU golden model: the harness, the bus
 * (identity registers, windows, read/write rules) and the batch rules
 * (errors, counters, clear, swap, scan-out).  Raster rules: test_raster.c.
 *
 * Expected values come from contract/gpu-contract.md, computed by hand.
 */
#include <stdlib.h>
#include <string.h>

#include "model_test.h"

unsigned test_passed;
unsigned test_failed;

bool test_check(bool ok, const char *file, int line, const char *what)
{
    if (ok) {
        test_passed++;
    } else {
        test_failed++;
        printf("FAIL %s:%d: %s\n", file, line, what);
    }
    return ok;
}

bool test_check_eq(long long got, long long want, const char *file, int line,
                   const char *what)
{
    if (got == want) {
        test_passed++;
        return true;
    }
    test_failed++;
    printf("FAIL %s:%d: %s (got %lld = 0x%llx, want %lld = 0x%llx)\n", file,
           line, what, got, (unsigned long long)got, want,
           (unsigned long long)want);
    return false;
}

/* ------------------------------------------------------------ bus helpers */

static gpu_model *alloc_model(void)
{
    gpu_model *m = malloc(sizeof *m);
    if (m == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    /* Garbage, so a reset that forgets a field shows up. */
    memset(m, 0xA5, sizeof *m);
    return m;
}

gpu_model *test_new_model(void)
{
    gpu_model *m = alloc_model();
    gpu_model_reset(m);
    return m;
}

gpu_model *test_new_model_cfg(unsigned span_w, bool lines, bool zbuf)
{
    gpu_model *m = alloc_model();
    gpu_model_config cfg = { span_w, lines, zbuf, 0, 0, GPU_MODEL_DEFAULT_ZBUF_BITS, false, false, 0, 0, 0 }; /* capacities: the contract's; no write mask, flat only */
    gpu_model_reset_config(m, &cfg);
    return m;
}

void test_set_vtxz(gpu_model *m, uint32_t i, int32_t x, int32_t y,
                   uint32_t z)
{
    uint32_t w[GPU_VTX_WORDS] = { 0 };
    w[GPU_VTX_X_WORD] |= ((uint32_t)x & GPU_VTX_X_MASK) << GPU_VTX_X_LSB;
    w[GPU_VTX_Y_WORD] |= ((uint32_t)y & GPU_VTX_Y_MASK) << GPU_VTX_Y_LSB;
    w[GPU_VTX_Z_WORD] |= (z & GPU_VTX_Z_MASK) << GPU_VTX_Z_LSB;
    for (uint32_t k = 0; k < GPU_VTX_WORDS; k++) {
        gpu_model_write(m, GPU_WIN_VTX + (i * GPU_VTX_WORDS + k) * 4u, w[k]);
    }
}

void test_set_vtx(gpu_model *m, uint32_t i, int32_t x, int32_t y)
{
    test_set_vtxz(m, i, x, y, 0);
}

void test_set_prim(gpu_model *m, uint32_t i, uint32_t i0, uint32_t i1,
                   uint32_t i2, uint32_t color, uint32_t kind)
{
    uint32_t w[GPU_PRIM_WORDS] = { 0 };
    w[GPU_PRIM_I0_WORD] |= (i0 & GPU_PRIM_I0_MASK) << GPU_PRIM_I0_LSB;
    w[GPU_PRIM_I1_WORD] |= (i1 & GPU_PRIM_I1_MASK) << GPU_PRIM_I1_LSB;
    w[GPU_PRIM_I2_WORD] |= (i2 & GPU_PRIM_I2_MASK) << GPU_PRIM_I2_LSB;
    w[GPU_PRIM_COLOR_WORD] |= (color & GPU_PRIM_COLOR_MASK)
                              << GPU_PRIM_COLOR_LSB;
    w[GPU_PRIM_KIND_WORD] |= (kind & GPU_PRIM_KIND_MASK) << GPU_PRIM_KIND_LSB;
    for (uint32_t k = 0; k < GPU_PRIM_WORDS; k++) {
        gpu_model_write(m, GPU_WIN_IDX + (i * GPU_PRIM_WORDS + k) * 4u, w[k]);
    }
}

void test_batch(gpu_model *m, uint32_t ctrl, uint32_t vtx_base,
                uint32_t vtx_count, uint32_t tri_base, uint32_t tri_count,
                uint32_t clear_color, uint32_t tag)
{
    gpu_model_write(m, GPU_REG_CTRL, ctrl);
    gpu_model_write(m, GPU_REG_VTX_BASE, vtx_base);
    gpu_model_write(m, GPU_REG_VTX_COUNT, vtx_count);
    gpu_model_write(m, GPU_REG_TRI_BASE, tri_base);
    gpu_model_write(m, GPU_REG_TRI_COUNT, tri_count);
    gpu_model_write(m, GPU_REG_CLEAR_COLOR, clear_color);
    gpu_model_write(m, GPU_REG_DOORBELL, tag);
}

uint32_t test_draw_one(gpu_model *m, const int32_t xy[6], uint32_t color)
{
    static uint32_t tag = 1;
    for (uint32_t i = 0; i < 3; i++) {
        test_set_vtx(m, i, xy[2 * i], xy[2 * i + 1]);
    }
    test_set_prim(m, 0, 0, 1, 2, color, GPU_PRIM_KIND_TRI);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 1, 0, tag++);
    return gpu_model_read(m, GPU_REG_PERF_PIXELS);
}

uint8_t test_back_px(const gpu_model *m, int px, int py)
{
    return gpu_model_back(m)[py * (int)m->cfg.fb_width + px];
}

uint16_t test_z(const gpu_model *m, int px, int py)
{
    return m->zbuf[py * (int)m->cfg.fb_width + px];
}

bool test_check_pixels(const gpu_model *m, const int (*pix)[2], int n,
                       uint8_t color, uint8_t other, const char *file,
                       int line)
{
    uint8_t *want = malloc(GPU_MODEL_FB_PIXELS);
    if (want == NULL) {
        exit(2);
    }
    memset(want, other, GPU_MODEL_FB_PIXELS);
    for (int i = 0; i < n; i++) {
        want[pix[i][1] * (int)GPU_FB_WIDTH + pix[i][0]] = color;
    }
    const uint8_t *fb = gpu_model_back(m);
    int bad = 0;
    for (int i = 0; i < (int)GPU_MODEL_FB_PIXELS; i++) {
        if (fb[i] != want[i]) {
            if (bad < 8) {
                printf("  pixel (%d,%d): got %u want %u\n",
                       i % (int)GPU_FB_WIDTH, i / (int)GPU_FB_WIDTH, fb[i],
                       want[i]);
            }
            bad++;
        }
    }
    free(want);
    return test_check_eq(bad, 0, file, line, "pixels match the hand list");
}

void test_check_perf(const gpu_model *m, uint32_t in, uint32_t drawn,
                     uint32_t rejected, uint32_t pixels, uint32_t samples,
                     uint32_t spans, const char *file, int line)
{
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), in, file, line,
                  "PERF_TRIS_IN");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_TRIS_DRAWN), drawn, file,
                  line, "PERF_TRIS_DRAWN");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_TRIS_REJECTED), rejected,
                  file, line, "PERF_TRIS_REJECTED");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_PIXELS), pixels, file, line,
                  "PERF_PIXELS");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_SAMPLES), samples, file,
                  line, "PERF_SAMPLES");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_SPANS_WRITTEN), spans, file,
                  line, "PERF_SPANS_WRITTEN");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_BUSY_CYCLES), 0, file, line,
                  "PERF_BUSY_CYCLES");
    test_check_eq(gpu_model_read(m, GPU_REG_PERF_SPANS_VISITED), 0, file,
                  line, "PERF_SPANS_VISITED");
}

static uint32_t rng_state = 0x12345678u;

void test_srand(uint32_t seed)
{
    rng_state = seed ? seed : 1u;
}

uint32_t test_rand(void)
{
    uint32_t x = rng_state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    rng_state = x;
    return x;
}

int32_t test_rand_range(int32_t lo, int32_t hi)
{
    uint32_t span = (uint32_t)(hi - lo) + 1u;
    return lo + (int32_t)(test_rand() % span);
}

/* -------------------------------------------------------------- bus tests */

static bool buffer_all(const uint8_t *fb, uint8_t v)
{
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        if (fb[i] != v) {
            return false;
        }
    }
    return true;
}

/* Identity registers, reset state, read-only / write-only / unmapped rules. */
void test_bus(void)
{
    gpu_model *m = test_new_model();

    /* Identity. */
    CHECK_EQ(gpu_model_read(m, GPU_REG_ID), GPU_ID_VALUE);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VERSION), GPU_VERSION_VALUE);
    /* Default build options (the RTL defaults): SPAN_W 8, lines, no zbuf, the write mask. */
    uint32_t caps = gpu_model_read(m, GPU_REG_CAPS);
    CHECK_EQ(caps & GPU_CAPS_LINES_MASK, GPU_CAPS_LINES_MASK);
    CHECK_EQ(caps & GPU_CAPS_ZBUF_MASK, 0);
    CHECK_EQ(caps & GPU_CAPS_WMASK_MASK, GPU_CAPS_WMASK_MASK);
    CHECK_EQ((caps & GPU_CAPS_SPAN_W_MASK) >> GPU_CAPS_SPAN_W_LSB, 8);
    CHECK_EQ(caps, 0x805u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), GPU_VTX_CAP);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), GPU_TRI_CAP);
    CHECK_EQ(gpu_model_read(m, GPU_REG_TRI_CAP), 512);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VTX_CAP), 1024);
    CHECK_EQ(gpu_model_read(m, GPU_REG_VERSION), 0x00010005u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_SCANOUT_UNDERFLOWS), 0u);  /* no display to fall behind */
    CHECK_EQ(gpu_model_read(m, GPU_REG_FB_SIZE), 320u | (240u << 16));

    /* Power-on state: everything else zero, palette black, fbs 0. */
    const uint32_t zero_regs[] = {
        GPU_REG_CTRL, GPU_REG_VTX_BASE, GPU_REG_VTX_COUNT, GPU_REG_TRI_BASE,
        GPU_REG_TRI_COUNT, GPU_REG_CLEAR_COLOR, GPU_REG_DOORBELL,
        GPU_REG_RESET, GPU_REG_STATUS, GPU_REG_DONE_SEQ, GPU_REG_FRAME_COUNT,
        GPU_REG_ERRORS, GPU_REG_PERF_BUSY_CYCLES, GPU_REG_PERF_TRIS_IN,
        GPU_REG_PERF_TRIS_DRAWN, GPU_REG_PERF_TRIS_REJECTED,
        GPU_REG_PERF_PIXELS, GPU_REG_PERF_SAMPLES, GPU_REG_PERF_SPANS_WRITTEN,
        GPU_REG_PERF_SPANS_VISITED,
    };
    for (size_t i = 0; i < sizeof zero_regs / sizeof zero_regs[0]; i++) {
        CHECK_EQ(gpu_model_read(m, zero_regs[i]), 0);
    }
    /* The depth buffer powers on 0, like the framebuffers. */
    bool zero_z = true;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        zero_z = zero_z && m->zbuf[i] == 0;
    }
    CHECK(zero_z);
    CHECK(buffer_all(gpu_model_front(m), 0));
    CHECK(buffer_all(gpu_model_back(m), 0));
    CHECK(gpu_model_front(m) != gpu_model_back(m));
    bool black = true;
    for (uint32_t i = 0; i < GPU_PALETTE_ENTRIES; i++) {
        black = black && m->palette[i] == 0;
    }
    CHECK(black);

    /* Read-only registers ignore writes. */
    const uint32_t ro_regs[] = {
        GPU_REG_ID, GPU_REG_VERSION, GPU_REG_CAPS, GPU_REG_VTX_CAP,
        GPU_REG_TRI_CAP, GPU_REG_FB_SIZE, GPU_REG_STATUS, GPU_REG_DONE_SEQ,
        GPU_REG_FRAME_COUNT, GPU_REG_ERRORS, GPU_REG_PERF_BUSY_CYCLES,
        GPU_REG_PERF_TRIS_IN, GPU_REG_PERF_TRIS_DRAWN,
        GPU_REG_PERF_TRIS_REJECTED, GPU_REG_PERF_PIXELS, GPU_REG_PERF_SAMPLES,
        GPU_REG_PERF_SPANS_WRITTEN, GPU_REG_PERF_SPANS_VISITED,
    };
    uint32_t before[sizeof ro_regs / sizeof ro_regs[0]];
    for (size_t i = 0; i < sizeof ro_regs / sizeof ro_regs[0]; i++) {
        before[i] = gpu_model_read(m, ro_regs[i]);
        gpu_model_write(m, ro_regs[i], 0xDEADBEEFu);
    }
    for (size_t i = 0; i < sizeof ro_regs / sizeof ro_regs[0]; i++) {
        CHECK_EQ(gpu_model_read(m, ro_regs[i]), before[i]);
    }

    /* Batch registers and RESET read back what was written (all 32 bits);
     * CTRL keeps its four defined bits (see test_config.c). */
    const uint32_t rw_regs[] = {
        GPU_REG_VTX_BASE, GPU_REG_VTX_COUNT, GPU_REG_TRI_BASE,
        GPU_REG_TRI_COUNT, GPU_REG_CLEAR_COLOR, GPU_REG_RESET,
    };
    for (size_t i = 0; i < sizeof rw_regs / sizeof rw_regs[0]; i++) {
        gpu_model_write(m, rw_regs[i], 0x80000010u + (uint32_t)i);
        CHECK_EQ(gpu_model_read(m, rw_regs[i]), 0x80000010u + i);
    }
    gpu_model_write(m, GPU_REG_CTRL, 0x0000000Fu);
    CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), 0xF);

    /* Unaligned and unmapped accesses: writes ignored, reads 0. */
    gpu_model_reset(m);
    gpu_model_write(m, GPU_REG_CTRL + 1u, 3);
    gpu_model_write(m, GPU_REG_DOORBELL + 2u, 9); /* must not start a batch */
    CHECK_EQ(gpu_model_read(m, GPU_REG_CTRL), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DOORBELL), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ID + 1u), 0);
    gpu_model_write(m, 0x018u, 5);       /* hole in the register window */
    CHECK_EQ(gpu_model_read(m, 0x018u), 0);
    CHECK_EQ(gpu_model_read(m, 0x0FCu), 0);
    gpu_model_write(m, 0x080u, 5); /* just past PERF_SPANS_VISITED */
    CHECK_EQ(gpu_model_read(m, 0x080u), 0);
    CHECK_EQ(gpu_model_read(m, 0x200u), 0); /* between REGS and PALETTE */
    gpu_model_write(m, GPU_APERTURE_BYTES, 1);
    CHECK_EQ(gpu_model_read(m, GPU_APERTURE_BYTES), 0);
    CHECK_EQ(gpu_model_read(m, 0xFFFFFFFCu), 0);

    /* Write-only windows read 0 but keep what was written. */
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 7u, 0xFFFFFABCu);
    CHECK_EQ(gpu_model_read(m, GPU_WIN_PALETTE + 4u * 7u), 0);
    CHECK_EQ(m->palette[7], 0xABCu); /* only RGB444 [11:0] is kept */
    gpu_model_write(m, GPU_WIN_VTX + 4u * 5u, 0x12345678u);
    CHECK_EQ(gpu_model_read(m, GPU_WIN_VTX + 4u * 5u), 0);
    CHECK_EQ(m->vtx[5], 0x12345678u);
    gpu_model_write(m, GPU_WIN_IDX + 4u * 9u, 0x9ABCDEF0u);
    CHECK_EQ(gpu_model_read(m, GPU_WIN_IDX + 4u * 9u), 0);
    CHECK_EQ(m->idx[9], 0x9ABCDEF0u);
    /* Last word of each buffer is mapped; beyond it (still inside the
     * window) is not, and must not corrupt anything. */
    gpu_model_write(m, GPU_WIN_VTX + 4u * (GPU_VTX_CAP * GPU_VTX_WORDS - 1u),
                    0xAAu);
    CHECK_EQ(m->vtx[GPU_VTX_CAP * GPU_VTX_WORDS - 1u], 0xAAu);
    gpu_model_write(m, GPU_WIN_IDX + 4u * (GPU_TRI_CAP * GPU_PRIM_WORDS - 1u),
                    0xBBu);
    CHECK_EQ(m->idx[GPU_TRI_CAP * GPU_PRIM_WORDS - 1u], 0xBBu);
    /* Just past the 512-primitive index buffer (0x1000 bytes into the
     * window) and the vertex buffer: not aliased onto word 0. */
    gpu_model_write(m, GPU_WIN_IDX + GPU_TRI_CAP * GPU_PRIM_WORDS * 4u, 0x77u);
    gpu_model_write(m, GPU_WIN_VTX + GPU_VTX_CAP * GPU_VTX_WORDS * 4u, 0x77u);
    CHECK_EQ(m->idx[0], 0);
    CHECK_EQ(m->vtx[0], 0);
    gpu_model_write(m, GPU_WIN_VTX + GPU_WIN_VTX_BYTES - 4u, 1);
    gpu_model_write(m, GPU_WIN_IDX + GPU_WIN_IDX_BYTES - 4u, 1);
    gpu_model_write(m, GPU_WIN_PALETTE + GPU_WIN_PALETTE_BYTES, 1);
    CHECK(buffer_all(gpu_model_front(m), 0));
    CHECK(buffer_all(gpu_model_back(m), 0));

    /* Reset restores the power-on state. */
    gpu_model_reset(m);
    CHECK_EQ(m->palette[7], 0);
    CHECK_EQ(m->vtx[5], 0);

    free(m);
}

/* ------------------------------------------------------------ batch tests */

/* The small triangle below covers 6 pixels in rows 1..3, all in span 0 of
 * their row for SPAN_W 8 (pixels (1..3,1), (1..2,2), (1,3)): 3 spans per
 * drawing (the default build options). */
#define CHECK_PERF(m, in, drawn, rej, pix, smp) \
    test_check_perf((m), (in), (drawn), (rej), (pix), (smp), \
                    (pix) / 6u * 3u, __FILE__, __LINE__)

/* The 6-pixel triangle of test_raster.c's first hand test (pixels (1,1)..),
 * its vertices at vbase..vbase+2 and its primitive at index prim. */
static void put_small_tri(gpu_model *m, uint32_t vbase, uint32_t prim,
                          uint32_t color)
{
    test_set_vtx(m, vbase + 0, 16, 16);
    test_set_vtx(m, vbase + 1, 80, 16);
    test_set_vtx(m, vbase + 2, 16, 80);
    test_set_prim(m, prim, 0, 1, 2, color, GPU_PRIM_KIND_TRI);
}

static uint32_t count_px(const uint8_t *fb, uint8_t v)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        n += fb[i] == v;
    }
    return n;
}

static void test_errors(void)
{
    gpu_model *m = test_new_model();

    /* ERR_VTX_INDEX: index == VTX_COUNT is out of range; the other
     * primitives of the batch still draw.  Kind is checked first. */
    put_small_tri(m, 0, 0, 5);
    test_set_prim(m, 1, 0, 3, 2, 6, GPU_PRIM_KIND_TRI);  /* I1 == count */
    test_set_prim(m, 2, 0, 1, 0xFFFF, 7, GPU_PRIM_KIND_TRI);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 3, 0, 3, 0, 0x11);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_VTX_INDEX_MASK);
    CHECK_PERF(m, 3, 1, 2, 6, 16);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 6);
    CHECK_EQ(count_px(gpu_model_back(m), 6) + count_px(gpu_model_back(m), 7),
             0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0x11);

    /* Indices are relative to VTX_BASE: the same prim with VTX_BASE = 10
     * reads vertices 10..12. */
    gpu_model_reset(m);
    put_small_tri(m, 10, 0, 9);
    test_batch(m, 0, 10, 3, 0, 1, 0, 0x12);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_PERF(m, 1, 1, 0, 6, 16);
    CHECK_EQ(count_px(gpu_model_back(m), 9), 6);

    /* ERR_KIND: on a GPU built without lines a line is skipped, as are
     * unknown kinds; a line with a bad index reports only ERR_KIND (kind
     * comes first). */
    gpu_model *nl = test_new_model_cfg(8, false, false);
    put_small_tri(nl, 0, 0, 5);
    test_set_prim(nl, 1, 0, 1, 2, 6, GPU_PRIM_KIND_LINE);
    test_set_prim(nl, 2, 0, 1, 2, 7, 0x7Fu);
    test_set_prim(nl, 3, 0, 1, 2, 8, 0xFFu);
    test_set_prim(nl, 4, 0, 9, 2, 8, GPU_PRIM_KIND_LINE);
    test_batch(nl, 0, 0, 3, 1, 4, 0, 0x13);
    CHECK_EQ(gpu_model_read(nl, GPU_REG_ERRORS), GPU_ERR_KIND_MASK);
    CHECK_PERF(nl, 4, 0, 4, 0, 0);
    CHECK(buffer_all(gpu_model_back(nl), 0));
    free(nl);

    /* With lines (the default), unknown kinds (2, 0x7F, 0xFF) are still
     * ERR_KIND; kind 2 with a bad index too (kind first). */
    gpu_model_reset(m);
    put_small_tri(m, 0, 0, 5);
    test_set_prim(m, 1, 0, 1, 2, 6, 2u);
    test_set_prim(m, 2, 0, 1, 2, 7, 0x7Fu);
    test_set_prim(m, 3, 0, 1, 2, 8, 0xFFu);
    test_set_prim(m, 4, 0, 9, 2, 8, 2u);
    test_batch(m, 0, 0, 3, 1, 4, 0, 0x13);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_KIND_MASK);
    CHECK_PERF(m, 4, 0, 4, 0, 0);
    CHECK(buffer_all(gpu_model_back(m), 0));

    /* Both flags accumulate; the next clean batch clears them and PERF. */
    test_batch(m, 0, 0, 3, 0, 5, 0, 0x14);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_KIND_MASK);
    test_set_prim(m, 5, 0, 1, 3, 8, GPU_PRIM_KIND_TRI);
    test_batch(m, 0, 0, 3, 0, 6, 0, 0x15);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS),
             GPU_ERR_KIND_MASK | GPU_ERR_VTX_INDEX_MASK);
    test_batch(m, 0, 0, 3, 0, 1, 0, 0x16);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_PERF(m, 1, 1, 0, 6, 16);

    /* ERR_COUNT: nothing drawn, no clear, counters 0, but the swap and
     * DONE_SEQ still happen.  Exactly at capacity is fine. */
    struct {
        uint32_t vb, vc, tb, tc;
        bool bad;
    } cases[] = {
        { 0, GPU_VTX_CAP, 0, 1, false },
        { GPU_VTX_CAP - 3, 3, GPU_TRI_CAP - 1, 1, false },
        { 0, GPU_VTX_CAP + 1, 0, 1, true },
        { GPU_VTX_CAP - 2, 3, 0, 1, true },
        { 0, 3, 0, GPU_TRI_CAP + 1, true },
        { 0, 3, GPU_TRI_CAP, 1, true },
        { 0, 3, 1, GPU_TRI_CAP, true },
        /* 32-bit wrap-around must not pass the check. */
        { 0xFFFFFFFFu, 3, 0, 1, true },
        { 2, 0xFFFFFFFFu, 0, 1, true },
        { 0, 3, 0xFFFFFFFFu, 1, true },
        { 0, 3, 1, 0xFFFFFFFFu, true },
        { 0x80000000u, 0x80000000u, 0, 1, true },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gpu_model_reset(m);
        /* A valid triangle at the start and at the end of both buffers. */
        put_small_tri(m, 0, 0, 5);
        put_small_tri(m, GPU_VTX_CAP - 3, GPU_TRI_CAP - 1, 5);
        m->fb[1][0] = 0x42; /* back buffer marker: must survive ERR_COUNT */
        test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, cases[i].vb,
                   cases[i].vc, cases[i].tb, cases[i].tc, 3,
                   0x100u + (uint32_t)i);
        uint32_t err = gpu_model_read(m, GPU_REG_ERRORS);
        CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0x100u + i);
        CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 1);
        CHECK_EQ(gpu_model_read(m, GPU_REG_STATUS), GPU_STATUS_FRONT_MASK);
        if (cases[i].bad) {
            CHECK_EQ(err, GPU_ERR_COUNT_MASK);
            CHECK_PERF(m, 0, 0, 0, 0, 0);
            /* Old back (fb[1]) is now the front, unchanged. */
            CHECK_EQ(gpu_model_front(m)[0], 0x42);
            CHECK_EQ(count_px(gpu_model_front(m), 0),
                     GPU_MODEL_FB_PIXELS - 1u);
        } else {
            CHECK_EQ(err, 0);
            CHECK_PERF(m, 1, 1, 0, 6, 16);
            CHECK_EQ(count_px(gpu_model_front(m), 5), 6);
            CHECK_EQ(count_px(gpu_model_front(m), 3),
                     GPU_MODEL_FB_PIXELS - 6u);
        }
    }

    /* An empty batch is fine: clear only. */
    gpu_model_reset(m);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 4, 0x20);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_PERF(m, 0, 0, 0, 0, 0);
    CHECK(buffer_all(gpu_model_back(m), 4));

    /* An out-of-range index with VTX_COUNT 0 is still just ERR_VTX_INDEX. */
    put_small_tri(m, 0, 0, 5);
    test_batch(m, 0, 0, 0, 0, 1, 0, 0x21);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_VTX_INDEX_MASK);
    CHECK_PERF(m, 1, 0, 1, 0, 0);

    free(m);
}

static void test_clear_swap(void)
{
    gpu_model *m = test_new_model();

    /* Clear writes CLEAR_COLOR[7:0] into the back buffer only. */
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 0x1ABu, 1);
    CHECK(buffer_all(gpu_model_back(m), 0xAB));
    CHECK(buffer_all(gpu_model_front(m), 0));
    CHECK_EQ(gpu_model_read(m, GPU_REG_STATUS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DOORBELL), 1);

    /* Without CTRL_CLEAR the back buffer keeps its pixels; a triangle
     * draws over them; CTRL bits other than CLEAR/SWAP change nothing here
     * (ZTEST/ZCLEAR are ignored without a depth buffer, the others are not
     * even stored). */
    put_small_tri(m, 0, 0, 5);
    test_batch(m, 0xFFFFFFFCu, 0, 3, 0, 1, 0x00, 2);
    CHECK_EQ(count_px(gpu_model_back(m), 0xAB), GPU_MODEL_FB_PIXELS - 6u);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 6);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 0);

    /* Later primitives overwrite earlier ones: draw prim 0 in colour 5
     * then the same triangle as prim 1 in colour 6. */
    put_small_tri(m, 0, 1, 6);
    test_batch(m, 0, 0, 3, 0, 2, 0, 3);
    CHECK_EQ(count_px(gpu_model_back(m), 6), 6);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 0);
    CHECK_PERF(m, 2, 2, 0, 12, 32);
    /* ... TRI_BASE / TRI_COUNT select which primitives run. */
    test_batch(m, 0, 0, 3, 0, 1, 0, 4);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 6);
    test_batch(m, 0, 0, 3, 1, 1, 0, 4);
    CHECK_EQ(count_px(gpu_model_back(m), 6), 6);
    test_batch(m, 0, 0, 3, 0, 1, 0, 4);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 6);

    /* Swap: FRONT toggles, FRAME_COUNT counts, the drawn buffer is shown,
     * the new back buffer holds the old front's pixels (nothing copied). */
    const uint8_t *drawn = gpu_model_back(m);
    const uint8_t *shown = gpu_model_front(m);
    test_batch(m, GPU_CTRL_SWAP_MASK, 0, 0, 0, 0, 0, 5);
    CHECK_EQ(gpu_model_read(m, GPU_REG_STATUS), GPU_STATUS_FRONT_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 1);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 5);
    CHECK(gpu_model_front(m) == drawn);
    CHECK(gpu_model_back(m) == shown);
    CHECK(buffer_all(gpu_model_back(m), 0)); /* old front: power-on zeros */
    CHECK_EQ(count_px(gpu_model_front(m), 5), 6);

    /* Clear + draw + swap in one batch. */
    put_small_tri(m, 0, 0, 7);
    test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, 0, 3, 0, 1, 2, 6);
    CHECK_EQ(gpu_model_read(m, GPU_REG_STATUS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 2);
    CHECK_EQ(count_px(gpu_model_front(m), 7), 6);
    CHECK_EQ(count_px(gpu_model_front(m), 2), GPU_MODEL_FB_PIXELS - 6u);
    CHECK_EQ(count_px(gpu_model_back(m), 5), 6);   /* previous frame */
    CHECK_EQ(count_px(gpu_model_back(m), 0xAB), GPU_MODEL_FB_PIXELS - 6u);

    /* A tag of 0 (or a repeated tag) still runs a batch in the model. */
    test_batch(m, GPU_CTRL_SWAP_MASK, 0, 0, 0, 0, 0, 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_DONE_SEQ), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 3);
    gpu_model_write(m, GPU_REG_DOORBELL, 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_FRAME_COUNT), 4);

    free(m);
}

static void test_scanout(void)
{
    gpu_model *m = test_new_model();
    uint8_t *rgb = malloc((size_t)GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3);
    if (rgb == NULL) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }

    /* At reset the picture is black. */
    memset(rgb, 0x55, (size_t)GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3);
    gpu_model_scanout(m, rgb);
    bool black = true;
    for (size_t i = 0; i < (size_t)GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3;
         i++) {
        black = black && rgb[i] == 0;
    }
    CHECK(black);

    /* Palette: clear colour 1 = 0x1F8, triangle colour 5 = 0xF0A. */
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 1u, 0x1F8u);
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 5u, 0xF0Au);
    gpu_model_write(m, GPU_WIN_PALETTE + 4u * 255u, 0xFFFu);
    put_small_tri(m, 0, 0, 5);
    test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, 0, 3, 0, 1, 1, 1);
    /* One pixel of colour 255 in the corner, straight into the front. */
    m->fb[m->front][GPU_MODEL_FB_PIXELS - 1u] = 255;
    gpu_model_scanout(m, rgb);

    /* Every screen pixel must equal its framebuffer pixel's colour. */
    uint32_t bad = 0;
    const uint8_t *fb = gpu_model_front(m);
    for (uint32_t y = 0; y < GPU_MODEL_SCREEN_H; y++) {
        for (uint32_t x = 0; x < GPU_MODEL_SCREEN_W; x++) {
            uint8_t idx = fb[(y >> 1) * GPU_FB_WIDTH + (x >> 1)];
            const uint8_t *o = &rgb[(y * GPU_MODEL_SCREEN_W + x) * 3u];
            uint8_t want[3];
            switch (idx) {
            case 1:
                want[0] = 0x11; want[1] = 0xFF; want[2] = 0x88;
                break;
            case 5:
                want[0] = 0xFF; want[1] = 0x00; want[2] = 0xAA;
                break;
            case 255:
                want[0] = 0xFF; want[1] = 0xFF; want[2] = 0xFF;
                break;
            default:
                want[0] = 0x01; want[1] = 0x02; want[2] = 0x03; /* never */
                break;
            }
            bad += o[0] != want[0] || o[1] != want[1] || o[2] != want[2];
        }
    }
    CHECK_EQ(bad, 0);

    /* Spot checks of the 2x2 blocks: fb pixel (1,1) is covered -> screen
     * (2..3, 2..3); fb (0,0) is not -> screen (0..1, 0..1), (1,2) not. */
    for (uint32_t y = 2; y < 4; y++) {
        for (uint32_t x = 2; x < 4; x++) {
            CHECK_EQ(rgb[(y * GPU_MODEL_SCREEN_W + x) * 3u + 0], 0xFF);
            CHECK_EQ(rgb[(y * GPU_MODEL_SCREEN_W + x) * 3u + 2], 0xAA);
        }
    }
    CHECK_EQ(rgb[(1u * GPU_MODEL_SCREEN_W + 1u) * 3u + 1], 0xFF);
    CHECK_EQ(rgb[(3u * GPU_MODEL_SCREEN_W + 1u) * 3u + 1], 0xFF);
    CHECK_EQ(rgb[(479u * GPU_MODEL_SCREEN_W + 638u) * 3u + 0], 0xFF);
    CHECK_EQ(rgb[(478u * GPU_MODEL_SCREEN_W + 639u) * 3u + 1], 0xFF);
    CHECK_EQ(rgb[(477u * GPU_MODEL_SCREEN_W + 639u) * 3u + 0], 0x11);

    free(rgb);
    free(m);
}

/* ---- strips (contract "Strips") ---------------------------------------- */

/* Pixels of value v among the first n of fb. */
static size_t count_n(const uint8_t *fb, size_t n, uint8_t v)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        k += fb[i] == v;
    }
    return k;
}

/* A model with every feature, at the given frame. */
static gpu_model *strip_model(uint32_t w, uint32_t h)
{
    gpu_model *m = alloc_model();
    gpu_model_config cfg = { 8, true, true, 0, 0, 16, true, true, w, h, 0 };
    gpu_model_reset_config(m, &cfg);
    return m;
}

/* The same random scene into m: vertices with depths and intensities (some far beyond the frame),
 * flat and Gouraud triangles and lines. */
static void strip_scene(gpu_model *m, uint32_t seed, uint32_t nv, uint32_t np)
{
    const int32_t w16 = 16 * (int32_t)m->cfg.fb_width;
    const int32_t h16 = 16 * (int32_t)m->cfg.fb_height;

    test_srand(seed);
    for (uint32_t i = 0; i < nv; i++) {
        uint32_t word[GPU_VTX_WORDS] = { 0 };
        const int32_t x = test_rand_range(-w16 / 4, w16 + w16 / 4);
        const int32_t y = test_rand_range(-h16 / 4, h16 + h16 / 4);

        word[GPU_VTX_X_WORD] |= ((uint32_t)x & GPU_VTX_X_MASK) << GPU_VTX_X_LSB;
        word[GPU_VTX_Y_WORD] |= ((uint32_t)y & GPU_VTX_Y_MASK) << GPU_VTX_Y_LSB;
        word[GPU_VTX_Z_WORD] |= (test_rand() & GPU_VTX_Z_MASK) << GPU_VTX_Z_LSB;
        word[GPU_VTX_I_WORD] |= (test_rand() & GPU_VTX_I_MASK) << GPU_VTX_I_LSB;
        for (uint32_t k = 0; k < GPU_VTX_WORDS; k++) {
            gpu_model_write(m, GPU_WIN_VTX + (i * GPU_VTX_WORDS + k) * 4u, word[k]);
        }
    }
    for (uint32_t i = 0; i < np; i++) {
        const uint32_t kind = (i % 5u == 0u) ? GPU_PRIM_KIND_LINE
                            : ((i % 3u == 0u) ? GPU_PRIM_KIND_TRI_GOURAUD : GPU_PRIM_KIND_TRI);
        test_set_prim(m, i, test_rand() % nv, test_rand() % nv, test_rand() % nv,
                      16u * (1u + test_rand() % 14u), kind);
    }
}

/* One batch of the scene's primitives into the rows first .. last: clearing colour and depth
 * there, depth-tested, dithered. */
static void strip_batch(gpu_model *m, uint32_t nv, uint32_t np, uint32_t first, uint32_t last,
                        uint32_t tag)
{
    gpu_model_write(m, GPU_REG_STRIP, first | (last << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_CLEAR_MASK | GPU_CTRL_ZCLEAR_MASK | GPU_CTRL_ZTEST_MASK |
                  GPU_CTRL_DITHER_MASK, 0, nv, 0, np, 0x21, tag);
}

static void test_strips(void)
{
    static const uint32_t frames[][2] = { { GPU_FB_WIDTH, GPU_FB_HEIGHT },
                                          { GPU_FB_MAX_WIDTH, GPU_FB_MAX_HEIGHT } };

    for (unsigned f = 0; f < 2; f++) {
        const uint32_t w = frames[f][0];
        const uint32_t h = frames[f][1];
        const uint32_t heights[] = { 1, 7, 16, 64, h };
        gpu_model *whole = strip_model(w, h);
        gpu_model *strips = strip_model(w, h);
        const size_t px = (size_t)w * h;

        /* After reset: the whole frame; reads back all 32 bits. */
        CHECK_EQ(gpu_model_read(whole, GPU_REG_STRIP), (h - 1u) << GPU_STRIP_LAST_LSB);
        gpu_model_write(strips, GPU_REG_STRIP, 0xFFFF1234u);
        CHECK_EQ(gpu_model_read(strips, GPU_REG_STRIP), 0xFFFF1234u);

        /* The clear fills the strip's rows only; a last row beyond the frame is its last. */
        gpu_model_write(strips, GPU_REG_STRIP, 10u | (20u << GPU_STRIP_LAST_LSB));
        test_batch(strips, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 0xAB, 1);
        CHECK_EQ(count_n(gpu_model_back(strips), px, 0xAB), 11u * w);
        CHECK_EQ(test_back_px(strips, 0, 9), 0);
        CHECK_EQ(test_back_px(strips, (int)w - 1, 20), 0xAB);
        CHECK_EQ(test_back_px(strips, 0, 21), 0);
        gpu_model_write(strips, GPU_REG_STRIP, (h - 2u) | (0xFFFFu << GPU_STRIP_LAST_LSB));
        test_batch(strips, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 0xCD, 2);
        CHECK_EQ(test_back_px(strips, 3, (int)h - 2), 0xCD);
        CHECK_EQ(test_back_px(strips, 3, (int)h - 1), 0xCD);
        CHECK_EQ(test_back_px(strips, 3, (int)h - 3), 0);

        /* A first row after the last: nothing cleared or drawn, every triangle rejected (the 20
         * lines step through as if off screen: drawn, no pixel). */
        strip_scene(strips, 7, 64, 100);
        strip_batch(strips, 64, 100, 30, 29, 3);
        CHECK_EQ(count_n(gpu_model_back(strips), px, 0x21), 0);
        CHECK_EQ(gpu_model_read(strips, GPU_REG_PERF_PIXELS), 0);
        CHECK_EQ(gpu_model_read(strips, GPU_REG_PERF_TRIS_REJECTED), 80);

        /* The frame drawn as strips of every height equals the frame drawn whole (colour and
         * depth), several scenes. */
        for (uint32_t seed = 1; seed <= 3; seed++) {
            strip_scene(whole, seed, 64, 120);
            strip_scene(strips, seed, 64, 120);
            strip_batch(whole, 64, 120, 0, h - 1u, 10);
            for (size_t k = 0; k < sizeof heights / sizeof heights[0]; k++) {
                uint32_t tag = 100;

                memset((uint8_t *)gpu_model_back(strips), 0x5A, px);
                for (uint32_t r = 0; r < h; r += heights[k]) {
                    strip_batch(strips, 64, 120, r, r + heights[k] - 1u, tag++);
                }
                CHECK(memcmp(gpu_model_back(whole), gpu_model_back(strips), px) == 0);
                CHECK(memcmp(whole->zbuf, strips->zbuf, px * sizeof whole->zbuf[0]) == 0);
            }
            CHECK(count_n(gpu_model_back(whole), px, 0x21) < px / 2);  /* much was drawn */
        }
        free(whole);
        free(strips);
    }
}

/* A strip build (contract "The strip buffer"): the model draws the frame and checks the rules. */
static void test_strip_buffer(void)
{
    const uint32_t w = GPU_FB_MAX_WIDTH;
    const uint32_t h = GPU_FB_MAX_HEIGHT;
    const uint32_t clear_z = GPU_CTRL_CLEAR_MASK | GPU_CTRL_ZCLEAR_MASK;
    gpu_model *m = alloc_model();
    gpu_model *whole = strip_model(w, h);
    const size_t px = (size_t)w * h;

    /* STRIP_ROWS: a power of two up to the frame's height, else refused (0). */
    gpu_model_config cfg = { 8, true, true, 0, 0, 16, true, true, w, h, 64 };
    CHECK(gpu_model_config_error(&cfg) == NULL);
    gpu_model_reset_config(m, &cfg);
    CHECK_EQ(gpu_model_read(m, GPU_REG_STRIP_ROWS), 64);
    CHECK_EQ(gpu_model_read(whole, GPU_REG_STRIP_ROWS), 0);
    for (uint32_t bad = 0; bad < 3; bad++) {
        gpu_model_config c = cfg;
        c.strip_rows = (uint32_t[]){ 48, 512, 3 }[bad];
        CHECK(gpu_model_config_error(&c) != NULL);
        gpu_model_reset_config(m, &c);
        CHECK_EQ(gpu_model_read(m, GPU_REG_STRIP_ROWS), 0);
    }
    gpu_model_reset_config(m, &cfg);

    /* Each broken rule: ERR_STRIP, nothing cleared, the open strip kept. */
    struct { uint32_t first, last, ctrl, mask; } bad[] = {
        { 0, 64, GPU_CTRL_CLEAR_MASK, 3 },                              /* two strips */
        { 0, 63, 0, 3 },                                                /* opens without a clear */
        { 1, 63, GPU_CTRL_CLEAR_MASK, 3 },                              /* ... of part of it */
        { 64, 127, GPU_CTRL_CLEAR_MASK, 1 },                            /* ... of one plane */
        { 0, 63, GPU_CTRL_CLEAR_MASK | GPU_CTRL_ZTEST_MASK, 3 },        /* depths not cleared */
        { 0, 62, GPU_CTRL_CLEAR_MASK | GPU_CTRL_ZCLEAR_MASK | GPU_CTRL_ZTEST_MASK, 3 },
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        gpu_model_write(m, GPU_REG_FB_WRITE_MASK, bad[i].mask);
        gpu_model_write(m, GPU_REG_STRIP, bad[i].first | (bad[i].last << GPU_STRIP_LAST_LSB));
        test_batch(m, bad[i].ctrl, 0, 0, 0, 0, 0x77, 1u + (uint32_t)i);
        CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_STRIP_MASK);
        CHECK_EQ(count_n(gpu_model_back(m), px, 0x77), 0);
        CHECK_EQ(m->open_strip, -1);
    }
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 3);

    /* Opening the last strip (rows 448 .. 479: the frame ends inside it), a last row past the frame. */
    gpu_model_write(m, GPU_REG_STRIP, 448u | (0xFFFFu << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 0x33, 20);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(m->open_strip, 7);
    /* In the open strip: part of its rows, no clear, any planes; depth once cleared. */
    gpu_model_write(m, GPU_REG_STRIP, 450u | (460u << GPU_STRIP_LAST_LSB));
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 1);
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, 0, 0, 0, 0x44, 21);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(test_back_px(m, 5, 455), 0x34);
    gpu_model_write(m, GPU_REG_FB_WRITE_MASK, 3);
    test_batch(m, GPU_CTRL_ZTEST_MASK, 0, 0, 0, 0, 0, 22);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_STRIP_MASK);  /* a part is not all */
    gpu_model_write(m, GPU_REG_STRIP, 448u | (479u << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_ZCLEAR_MASK, 0, 0, 0, 0, 0, 23);
    gpu_model_write(m, GPU_REG_STRIP, 450u | (451u << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_ZTEST_MASK, 0, 0, 0, 0, 0, 24);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    /* A batch of no rows opens nothing; ERR_COUNT keeps the strip too. */
    gpu_model_write(m, GPU_REG_STRIP, 10u | (9u << GPU_STRIP_LAST_LSB));
    test_batch(m, 0, 0, 0, 0, 0, 0, 25);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(m->open_strip, 7);
    gpu_model_write(m, GPU_REG_STRIP, 0u | (63u << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_CLEAR_MASK, 0, GPU_VTX_CAP + 1u, 0, 0, 0, 26);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_COUNT_MASK);
    CHECK_EQ(m->open_strip, 7);
    /* A swap closes it (the next batch there must clear again); so does RESET. */
    gpu_model_write(m, GPU_REG_STRIP, 448u | (479u << GPU_STRIP_LAST_LSB));
    test_batch(m, GPU_CTRL_SWAP_MASK, 0, 0, 0, 0, 0, 27);
    CHECK_EQ(m->open_strip, -1);
    test_batch(m, 0, 0, 0, 0, 0, 0, 28);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_STRIP_MASK);
    test_batch(m, clear_z, 0, 0, 0, 0, 0, 29);
    CHECK_EQ(m->open_strip, 7);
    gpu_model_write(m, GPU_REG_RESET, 1);
    CHECK_EQ(m->open_strip, -1);

    /* A frame by the rules, in strips of 64 (depth-tested, each strip's batch cleared as it
     * opens, then a second batch into it), equals the same scene drawn whole. */
    strip_scene(whole, 5, 64, 120);
    strip_scene(m, 5, 64, 120);
    strip_batch(whole, 64, 120, 0, h - 1u, 40);
    for (uint32_t r = 0; r < h; r += 64) {
        strip_batch(m, 64, 120, r, r + 63u, 42);
        CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS) & GPU_ERR_STRIP_MASK, 0);
        gpu_model_write(m, GPU_REG_STRIP, r | ((r + 63u) << GPU_STRIP_LAST_LSB));
        test_batch(m, GPU_CTRL_ZTEST_MASK | GPU_CTRL_DITHER_MASK, 0, 64, 0, 120, 0x21, 43);
        CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS) & GPU_ERR_STRIP_MASK, 0);
    }
    gpu_model_write(whole, GPU_REG_STRIP, 0u | ((h - 1u) << GPU_STRIP_LAST_LSB));
    test_batch(whole, GPU_CTRL_ZTEST_MASK | GPU_CTRL_DITHER_MASK, 0, 64, 0, 120, 0x21, 44);
    CHECK(memcmp(gpu_model_back(whole), gpu_model_back(m), px) == 0);

    /* CTRL.WALK: one batch from the first strip draws every strip (the frame equals the same
     * scene drawn whole), its counters adding up over the 8 strips, STRIP kept as written; the
     * swap after the last strip. */
    strip_scene(whole, 6, 64, 120);
    strip_scene(m, 6, 64, 120);
    strip_batch(whole, 64, 120, 0, h - 1u, 50);
    memset((uint8_t *)gpu_model_back(m), 0x5A, px);
    gpu_model_write(m, GPU_REG_STRIP, 0u | (63u << GPU_STRIP_LAST_LSB));
    test_batch(m, clear_z | GPU_CTRL_ZTEST_MASK | GPU_CTRL_DITHER_MASK | GPU_CTRL_WALK_MASK, 0, 64,
               0, 120, 0x21, 51);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK(memcmp(gpu_model_back(whole), gpu_model_back(m), px) == 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), 8u * 120u);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), gpu_model_read(whole, GPU_REG_PERF_PIXELS));
    CHECK_EQ(gpu_model_read(m, GPU_REG_STRIP), 0u | (63u << GPU_STRIP_LAST_LSB));
    CHECK_EQ(m->open_strip, 7);
    /* From a later strip: that strip and the ones after it only; the rows above keep theirs. */
    memset((uint8_t *)gpu_model_back(m), 0x5A, px);
    gpu_model_write(m, GPU_REG_STRIP, 320u | (383u << GPU_STRIP_LAST_LSB));
    test_batch(m, clear_z | GPU_CTRL_ZTEST_MASK | GPU_CTRL_DITHER_MASK | GPU_CTRL_WALK_MASK |
                  GPU_CTRL_SWAP_MASK, 0, 64, 0, 120, 0x21, 52);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), 3u * 120u);
    CHECK_EQ(m->open_strip, -1);  /* swapped: closed */
    CHECK_EQ(count_n(gpu_model_front(m), 320u * w, 0x5A), 320u * w);
    CHECK(memcmp(gpu_model_back(whole) + 320u * w, gpu_model_front(m) + 320u * w,
                 px - 320u * w) == 0);
    /* A walk that breaks a rule in its first strip (part of it, no clear) draws nothing. */
    gpu_model_write(m, GPU_REG_STRIP, 1u | (63u << GPU_STRIP_LAST_LSB));
    test_batch(m, clear_z | GPU_CTRL_WALK_MASK, 0, 64, 0, 120, 0x21, 53);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), GPU_ERR_STRIP_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_IN), 0);
    /* On a GPU without a strip buffer WALK does nothing: one run of the rows. */
    gpu_model_write(whole, GPU_REG_STRIP, 0u | (63u << GPU_STRIP_LAST_LSB));
    test_batch(whole, GPU_CTRL_CLEAR_MASK | GPU_CTRL_WALK_MASK, 0, 64, 0, 120, 0x21, 54);
    CHECK_EQ(gpu_model_read(whole, GPU_REG_PERF_TRIS_IN), 120u);
    free(whole);
    free(m);
}

void test_batch_rules(void)
{
    test_errors();
    test_clear_swap();
    test_scanout();
    test_strips();
    test_strip_buffer();
}

int main(void)
{
    test_bus();
    test_batch_rules();
    test_raster();
    test_config();
    test_lines();
    test_depth();
    test_gouraud();
    test_gouraud_probe();
    printf("%u passed, %u failed\n", test_passed, test_failed);
    return test_failed ? 1 : 0;
}
