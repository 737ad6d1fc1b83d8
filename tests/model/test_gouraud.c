/*
 * test_gouraud.c - unit tests of the model's Gouraud triangles (contract
 * "Gouraud intensity", build option ENABLE_GOURAUD): the intensity plane is
 * the depth plane's formula on VTX_I, each pixel's colour PRIM_COLOR + level
 * (mod 256), level = i >> 12, plus one with CTRL_DITHER where the fraction
 * bits (i >> 8) & 15 exceed the 4x4 Bayer threshold of (x & 3, y & 3), at
 * most 15. Checked on hand-computed pixels: constant intensities (dither
 * density exactly frac / 16), the top of the range (no level 16), a linear
 * ramp whose plane is exact, the colour wrap, either winding, and a GPU built
 * without Gouraud refusing the kind with ERR_KIND. test_gouraud_probe: the
 * shade probe (a measurement aid, not the contract) records i(p) of every
 * Gouraud pixel and "none" for anything else, and the unquantised scan-out
 * mixes the ramp's two entries around i(p).
 */
#include <math.h>
#include <stdlib.h>

#include "model_test.h"

#define CL (GPU_CTRL_CLEAR_MASK)
#define DI (GPU_CTRL_DITHER_MASK)

static uint32_t g_tag = 0x3000;

/* The standard 4x4 Bayer matrix, [y & 3][x & 3], written out here again. */
static const int bayer[4][4] = {
    { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 },
};

static void set_vtxi(gpu_model *m, uint32_t i, int32_t x, int32_t y, uint32_t inten)
{
    gpu_model_write(m, GPU_WIN_VTX + (i * GPU_VTX_WORDS + GPU_VTX_X_WORD) * 4u,
                    (((uint32_t)x & GPU_VTX_X_MASK) << GPU_VTX_X_LSB) |
                        (((uint32_t)y & GPU_VTX_Y_MASK) << GPU_VTX_Y_LSB));
    gpu_model_write(m, GPU_WIN_VTX + (i * GPU_VTX_WORDS + GPU_VTX_I_WORD) * 4u,
                    (inten & GPU_VTX_I_MASK) << GPU_VTX_I_LSB);
}

/* The whole screen as two Gouraud triangles on the pixel corners, the
 * intensity of corner (x, y) in Q12.4 given by f. */
static void set_screen(gpu_model *m, uint32_t (*f)(int32_t x, int32_t y), uint32_t color,
                       bool flip)
{
    const int32_t w = 16 * GPU_FB_WIDTH, h = 16 * GPU_FB_HEIGHT;
    set_vtxi(m, 0, 0, 0, f(0, 0));
    set_vtxi(m, 1, w, 0, f(w, 0));
    set_vtxi(m, 2, w, h, f(w, h));
    set_vtxi(m, 3, 0, h, f(0, h));
    if (flip) {  /* the other winding: the GPU swaps v1 and v2 back */
        test_set_prim(m, 0, 0, 2, 1, color, GPU_PRIM_KIND_TRI_GOURAUD);
        test_set_prim(m, 1, 0, 3, 2, color, GPU_PRIM_KIND_TRI_GOURAUD);
    } else {
        test_set_prim(m, 0, 0, 1, 2, color, GPU_PRIM_KIND_TRI_GOURAUD);
        test_set_prim(m, 1, 0, 2, 3, color, GPU_PRIM_KIND_TRI_GOURAUD);
    }
}

/* The intensity g_const everywhere: at the corners (set_screen) and the pixel centres
 * (mismatches). */
static uint32_t g_const;
static uint32_t constant(int32_t x, int32_t y)
{
    (void)x;
    (void)y;
    return g_const;
}

/* i = 8 x (x in Q12.4): IA = 2^16 * 8 exactly, IB = 0, so at the centre
 * 16 px + 8 of pixel px, i = 128 px + 64. */
static uint32_t ramp(int32_t x, int32_t y)
{
    (void)y;
    return (uint32_t)(8 * x);
}

static int expected(uint32_t i, int px, int py, int base, bool dither)
{
    int level = (int)(i >> 12);
    if (dither && (int)((i >> 8) & 15u) > bayer[py & 3][px & 3] && level < 15) {
        level++;
    }
    return (base + level) & 0xFF;
}

static uint32_t mismatches(const gpu_model *m, uint32_t (*pixel_i)(int32_t, int32_t), int base,
                           bool dither)
{
    uint32_t bad = 0;
    for (int y = 0; y < (int)GPU_FB_HEIGHT; y++) {
        for (int x = 0; x < (int)GPU_FB_WIDTH; x++) {
            bad += gpu_model_back(m)[y * GPU_FB_WIDTH + x] !=
                   expected(pixel_i(x, y), x, y, base, dither);
        }
    }
    return bad;
}

static uint32_t ramp_at(int32_t x, int32_t y)
{
    (void)y;
    return (uint32_t)(128 * x + 64);
}

void test_gouraud(void)
{
    gpu_model_config cfg = { 8, true, false, 0, 0, 0, false, true, 0, 0, 0 };  /* zbuf_bits 0: the default; no write mask */
    gpu_model *m = malloc(sizeof *m);
    if (m == NULL) {
        CHECK(false);
        return;
    }
    gpu_model_reset_config(m, &cfg);
    CHECK(gpu_model_read(m, GPU_REG_CAPS) & GPU_CAPS_GOURAUD_MASK);

    /* Constant 5 + 10/16: level 5 everywhere undithered; dithered, level 6
     * exactly where 10 > the threshold, i.e. 10 of every 16 pixels. */
    g_const = 0x5A00;
    set_screen(m, constant, 0x30, false);
    test_batch(m, CL, 0, 4, 0, 2, 0, g_tag++);
    CHECK_EQ(gpu_model_read(m, GPU_REG_ERRORS), 0);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_PIXELS), GPU_MODEL_FB_PIXELS);
    CHECK_EQ(mismatches(m, constant, 0x30, false), 0);
    test_batch(m, CL | DI, 0, 4, 0, 2, 0, g_tag++);
    CHECK_EQ(mismatches(m, constant, 0x30, true), 0);
    {
        uint32_t up = 0;
        for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
            up += gpu_model_back(m)[i] == 0x36;
        }
        CHECK_EQ(up, GPU_MODEL_FB_PIXELS / 16u * 10u);
    }

    /* The top: 15 + 15/16 never dithers up to a 16th level. */
    g_const = 0xFFFF;
    set_screen(m, constant, 0x40, false);
    test_batch(m, CL | DI, 0, 4, 0, 2, 0, g_tag++);
    CHECK_EQ(mismatches(m, constant, 0x40, true), 0);
    CHECK_EQ(gpu_model_back(m)[0], 0x4F);

    /* The colour wraps: 250 + 10. */
    g_const = 0xA000;
    set_screen(m, constant, 250, false);
    test_batch(m, CL, 0, 4, 0, 2, 0, g_tag++);
    CHECK_EQ(gpu_model_back(m)[1234], 4);

    /* A ramp across the screen, both windings, dither off and on: pixel px
     * at i = 128 px + 64 (e.g. px 100: 12864 = level 3, fraction 2). */
    for (int flip = 0; flip < 2; flip++) {
        set_screen(m, ramp, 0x10, flip != 0);
        test_batch(m, CL, 0, 4, 0, 2, 0, g_tag++);
        CHECK_EQ(mismatches(m, ramp_at, 0x10, false), 0);
        CHECK_EQ(gpu_model_back(m)[100], 0x13);
        test_batch(m, CL | DI, 0, 4, 0, 2, 0, g_tag++);
        CHECK_EQ(mismatches(m, ramp_at, 0x10, true), 0);
    }

    /* A flat triangle is untouched by VTX_I and CTRL_DITHER. */
    g_const = 0x7777;
    set_screen(m, constant, 0x20, false);
    test_set_prim(m, 0, 0, 1, 2, 0x20, GPU_PRIM_KIND_TRI);
    test_set_prim(m, 1, 0, 2, 3, 0x20, GPU_PRIM_KIND_TRI);
    test_batch(m, CL | DI, 0, 4, 0, 2, 0, g_tag++);
    CHECK_EQ(gpu_model_back(m)[777], 0x20);

    /* Without ENABLE_GOURAUD the kind is refused and nothing is drawn. */
    cfg.gouraud = false;
    gpu_model_reset_config(m, &cfg);
    CHECK(!(gpu_model_read(m, GPU_REG_CAPS) & GPU_CAPS_GOURAUD_MASK));
    set_screen(m, constant, 0x30, false);
    test_batch(m, CL | DI, 0, 4, 0, 2, 7, g_tag++);
    CHECK(gpu_model_read(m, GPU_REG_ERRORS) & GPU_ERR_KIND_MASK);
    CHECK_EQ(gpu_model_read(m, GPU_REG_PERF_TRIS_REJECTED), 2);
    CHECK_EQ(gpu_model_back(m)[0], 7);
    free(m);
}

/* Channel c (0 R, 1 G, 2 B) of ramp entry k of test_gouraud_probe's palette:
 * R = k, G = 5, B = 15 - k (RGB444). */
static int probe_channel(int k, int c)
{
    return c == 0 ? k : (c == 1 ? 5 : 15 - k);
}

void test_gouraud_probe(void)
{
    gpu_model_config cfg = { 8, true, false, 0, 0, 0, false, true, 0, 0, 0 };
    gpu_model *m = malloc(sizeof *m);
    gpu_model_shade_probe *probe = malloc(sizeof *probe);
    uint8_t *rgb = malloc((size_t)GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3u);
    if (m == NULL || probe == NULL || rgb == NULL) {
        CHECK(false);
        free(m);
        free(probe);
        free(rgb);
        return;
    }
    gpu_model_reset_config(m, &cfg);
    gpu_model_attach_shade_probe(m, probe);
    for (uint32_t k = 0; k < 16u; k++) {
        gpu_model_write(m, GPU_WIN_PALETTE + 4u * (0x10u + k),
                        (uint32_t)(probe_channel((int)k, 0) << 8 | probe_channel((int)k, 1) << 4 |
                                   probe_channel((int)k, 2)));
    }

    /* The ramp, dithered, swapped to the front: pixel px at i = 128 px + 64. */
    set_screen(m, ramp, 0x10, false);
    test_batch(m, CL | DI | GPU_CTRL_SWAP_MASK, 0, 4, 0, 2, 0, g_tag++);
    uint32_t bad_words = 0, bad_rgb = 0;
    gpu_model_scanout_unquantised(m, rgb);
    for (int y = 0; y < (int)GPU_FB_HEIGHT; y++) {
        for (int x = 0; x < (int)GPU_FB_WIDTH; x++) {
            const uint32_t i = ramp_at(x, y);
            bad_words += probe->px[m->front][y * GPU_FB_WIDTH + x] !=
                         (GPU_MODEL_PROBE_SHADED | 0x10u << 16 | i);
            for (int c = 0; c < 3; c++) {
                /* Entry k and k + 1 mixed by the fraction: 17 (k + f (k+1 - k)). */
                const int k = (int)(i >> 12);
                const double f = (double)(i & 0xFFFu) / 4096.0;
                const double v = 17.0 * (probe_channel(k, c) + f * (probe_channel(k + 1, c) - probe_channel(k, c)));
                bad_rgb += rgb[((size_t)(2 * y + 1) * GPU_MODEL_SCREEN_W + (size_t)(2 * x + 1)) * 3u + (size_t)c] !=
                           (uint8_t)floor(v + 0.5);
            }
        }
    }
    CHECK_EQ(bad_words, 0);
    CHECK_EQ(bad_rgb, 0);
    /* The frame itself is the dithered one, untouched by the probe. */
    CHECK_EQ(gpu_model_front(m)[100], 0x13 + (((12864u >> 8) & 15u) > (unsigned)bayer[0][0]));

    /* The top of the range shows entry 15 exactly; a flat triangle and a
     * clear record "none" and scan out as their palette index. */
    g_const = 0xFFFF;
    set_screen(m, constant, 0x10, false);
    test_batch(m, CL | GPU_CTRL_SWAP_MASK, 0, 4, 0, 1, 0, g_tag++);  /* the upper-right half only */
    gpu_model_scanout_unquantised(m, rgb);
    {
        const size_t shaded = ((size_t)1 * GPU_MODEL_SCREEN_W + 600) * 3u;  /* pixel (300, 0) */
        const size_t cleared = ((size_t)400 * GPU_MODEL_SCREEN_W + 20) * 3u;  /* pixel (10, 200) */
        CHECK_EQ(rgb[shaded + 0], 15 * 17);
        CHECK_EQ(rgb[shaded + 2], 0);
        CHECK_EQ(probe->px[m->front][200 * GPU_FB_WIDTH + 10], 0);
        CHECK_EQ(rgb[cleared + 0], 0);  /* palette entry 0: black */
    }
    test_set_prim(m, 0, 0, 1, 2, 0x18, GPU_PRIM_KIND_TRI);
    test_batch(m, CL | GPU_CTRL_SWAP_MASK, 0, 4, 0, 1, 0, g_tag++);
    CHECK_EQ(probe->px[m->front][0 * GPU_FB_WIDTH + 300], 0);
    gpu_model_scanout_unquantised(m, rgb);
    CHECK_EQ(rgb[((size_t)1 * GPU_MODEL_SCREEN_W + 600) * 3u + 0], 8 * 17);
    free(rgb);
    free(probe);
    free(m);
}
