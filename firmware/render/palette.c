/*
 * palette.c — see palette.h.
 */
#include "render/palette.h"

#include "config/hot_path.h"

/* Full-light colour of each material, RGB 0..15 per channel. */
static const uint8_t pal_material_rgb[PAL_MATERIALS][3] = {
    {0, 0, 0},     /* 0: fixed colours, see palette_build */
    {15, 3, 2},    /* red */
    {3, 13, 3},    /* green */
    {3, 6, 15},    /* blue */
    {15, 13, 2},   /* yellow */
    {2, 13, 14},   /* cyan */
    {13, 3, 13},   /* magenta */
    {15, 8, 1},    /* orange */
    {14, 14, 14},  /* white */
    {5, 12, 3},    /* grass */
    {9, 6, 3},     /* dirt */
    {9, 9, 10},    /* stone */
    {14, 13, 8},   /* sand */
    {2, 6, 13},    /* water */
    {15, 0, 0},    /* anaglyph left: red */
    {0, 15, 15},   /* anaglyph right: cyan */
};

FW_BUILD_ONCE void palette_build(uint16_t pal[PAL_ENTRIES])
{
    for (uint32_t m = 0; m < PAL_MATERIALS; m++) {
        for (uint32_t s = 0; s < PAL_SHADES; s++) {
            const uint8_t *c = pal_material_rgb[m];
            /* round(c * (s + 1) / 16): c <= 15, so the product is at most 240. */
            const uint32_t r = (c[0] * (s + 1u) + 8u) / 16u;
            const uint32_t g = (c[1] * (s + 1u) + 8u) / 16u;
            const uint32_t b = (c[2] * (s + 1u) + 8u) / 16u;

            pal[PAL_INDEX(m, s)] = (uint16_t)PAL_RGB444(r, g, b);
        }
    }
    for (uint32_t s = 0; s < PAL_SHADES; s++) {
        pal[PAL_INDEX(0u, s)] = (uint16_t)PAL_RGB444(0, 0, 0);
    }
    pal[PAL_SKY] = (uint16_t)PAL_RGB444(0x2, 0x3, 0x6);
    pal[PAL_WHITE] = (uint16_t)PAL_RGB444(0xF, 0xF, 0xF);
    pal[PAL_NIGHT] = (uint16_t)PAL_RGB444(0x0, 0x0, 0x0);
}

FW_BUILD_ONCE void palette_build_anaglyph(uint16_t pal[PAL_ENTRIES])
{
    for (uint32_t i = 0; i < PAL_ENTRIES; i++) {
        const uint32_t left = i >> 4;
        const uint32_t right = i & 0xFu;

        pal[i] = (uint16_t)PAL_RGB444(left, right, right);
    }
}
