/*
 * test_palette.c — material ramps and the flat-lighting rule.
 */
#include <stdint.h>

#include "gpu/gpu.h"
#include "render/palette.h"
#include "test_util.h"
#include "unit.h"

void test_palette_ramps(void)
{
    uint16_t pal[PAL_ENTRIES];

    palette_build(pal);
    CHECK_EQ(pal[PAL_INDEX(MAT_RED, 15u)], GPU_RGB444(15, 3, 2));  /* full light: the material */
    CHECK_EQ(pal[PAL_INDEX(MAT_ANAGLYPH_LEFT, 15u)], GPU_RGB444(15, 0, 0));
    CHECK_EQ(pal[PAL_INDEX(MAT_ANAGLYPH_RIGHT, 15u)], GPU_RGB444(0, 15, 15));
    CHECK_EQ(pal[PAL_WHITE], GPU_RGB444(15, 15, 15));
    for (uint32_t m = 1; m < PAL_MATERIALS; m++) {
        for (uint32_t s = 1; s < PAL_SHADES; s++) {
            const uint16_t a = pal[PAL_INDEX(m, s - 1u)];
            const uint16_t b = pal[PAL_INDEX(m, s)];

            /* each channel grows with the level */
            CHECK((a & 0xF00u) <= (b & 0xF00u) && (a & 0x0F0u) <= (b & 0x0F0u) &&
                  (a & 0x00Fu) <= (b & 0x00Fu));
        }
    }
}

/* level = ambient + floor((15 - ambient) max(0, n . l)), clamped. */
void test_palette_light_levels(void)
{
    struct palette_light pl;
    const uvec3 up = u3(0, 1, 0);

    palette_light_init(&pl, up, 4);
    CHECK_EQ(palette_light_level(&pl, up), 15);  /* 4 + 11 * 1 */
    CHECK_EQ(palette_light_level(&pl, u3(0, -1, 0)), 4);  /* facing away: ambient */
    CHECK_EQ(palette_light_level(&pl, u3(1, 0, 0)), 4);   /* grazing */
    CHECK_EQ(palette_light_level(&pl, u3(0, 0.5, 0.8660254)), 4 + 5);  /* cos 60 */
    palette_light_init(&pl, up, 0);
    CHECK(palette_light_level(&pl, up) >= 14);
    palette_light_init(&pl, up, 15);
    CHECK_EQ(palette_light_level(&pl, up), 15);
    palette_light_init(&pl, up, 40);  /* out of range ambient: clamped */
    CHECK_EQ(palette_light_level(&pl, u3(0, -1, 0)), 15);
    for (int i = 0; i < 10000; i++) {
        const double a = 2.0 * TEST_PI * (double)unit_rand() / 4294967296.0;
        const double c = cos(a);
        const uvec3 n = u3(sin(a), c, 0);
        const uint32_t amb = unit_rand() % 16u;
        const double exact = amb + (15.0 - amb) * (c > 0 ? c : 0);
        uint32_t level;

        palette_light_init(&pl, up, amb);
        level = palette_light_level(&pl, n);
        CHECK(level <= 15u);
        CHECK(fabs((double)level - exact) < 1.0 + 1e-6);  /* floor, within one level */
    }
}
