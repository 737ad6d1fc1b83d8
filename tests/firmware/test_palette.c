/*
 * test_palette.c — material ramps and the flat-lighting rule.
 */
#include <stdint.h>

#include "render/mesh.h"
#include "render/palette.h"
#include "test_util.h"
#include "unit.h"

void test_palette_ramps(void)
{
    uint16_t pal[PAL_ENTRIES];

    CHECK_EQ(PAL_RGB444(0xF, 0xA, 0x5), 0xFA5u);  /* the palette window's RGB444: R in 11:8 */
    palette_build(pal);
    CHECK_EQ(pal[PAL_INDEX(MAT_RED, 15u)], PAL_RGB444(15, 3, 2));  /* full light: the material */
    CHECK_EQ(pal[PAL_INDEX(MAT_ANAGLYPH_LEFT, 15u)], PAL_RGB444(15, 0, 0));
    CHECK_EQ(pal[PAL_INDEX(MAT_ANAGLYPH_RIGHT, 15u)], PAL_RGB444(0, 15, 15));
    CHECK_EQ(pal[PAL_WHITE], PAL_RGB444(15, 15, 15));
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

/* The Gouraud intensity (Q4.12) is the flat level before rounding down: I >> 12 is exactly
 * palette_light_level's level for the same normal, I never exceeds PAL_INTENSITY_MAX (level 15.0),
 * and I / 4096 is within 2^-10 of the exact ambient + (15 - ambient) max(0, n . l). */
void test_palette_light_intensity(void)
{
    struct palette_light pl;
    const uvec3 up = u3(0, 1, 0);

    palette_light_init(&pl, up, 4);
    CHECK(palette_light_intensity(&pl, up) <= PAL_INTENSITY_MAX);
    CHECK(palette_light_intensity(&pl, up) >= PAL_INTENSITY_MAX - 8u);  /* 15.0, low by rounding */
    CHECK_EQ(palette_light_intensity(&pl, u3(0, -1, 0)), 4u << 12);      /* facing away: ambient */
    palette_light_init(&pl, up, 15);
    CHECK_EQ(palette_light_intensity(&pl, up), PAL_INTENSITY_MAX);
    for (int i = 0; i < 10000; i++) {
        const double a = 2.0 * TEST_PI * (double)unit_rand() / 4294967296.0;
        const double b = TEST_PI * (double)unit_rand() / 4294967296.0;
        const uvec3 n = u3(sin(a) * sin(b), cos(a), sin(a) * cos(b));
        const double c = cos(a);
        const uint32_t amb = unit_rand() % 16u;
        const double exact = amb + (15.0 - amb) * (c > 0 ? c : 0);
        uint32_t inten;

        palette_light_init(&pl, up, amb);
        inten = palette_light_intensity(&pl, n);
        CHECK(inten <= PAL_INTENSITY_MAX);
        CHECK_EQ(inten >> 12, palette_light_level(&pl, n));
        CHECK(fabs((double)inten / 4096.0 - exact) < 1.0 / 1024.0);
    }
}

/* A vertex normal is the direction of the sum of the faces' unit normals around it (in fixed
 * point summed exactly in int64): known cases, cancelling normals, and random fans of up to 8
 * against double precision; then the Q1.14 form a mesh stores, within 2^-14 per component. */
void test_vertex_normal_average(void)
{
    uvec3 n[8];
    uvec3 m;
    int16_t q[3];

    n[0] = u3(0, 1, 0);
    n[1] = u3(1, 0, 0);
    m = uvec3_mean_direction(n, 2);
    CHECK(fabs(ud(m.x) - 0.70710678) < 1e-6 && fabs(ud(m.y) - 0.70710678) < 1e-6 &&
          fabs(ud(m.z)) < 1e-6);
    n[1] = u3(0, -1, 0);
    m = uvec3_mean_direction(n, 2);  /* they cancel: no direction */
    CHECK(ud(m.x) == 0.0 && ud(m.y) == 0.0 && ud(m.z) == 0.0);
    m = uvec3_mean_direction(n, 1);
    CHECK(fabs(ud(m.y) - 1.0) < 1e-6);
    for (int t = 0; t < 2000; t++) {
        const uint32_t count = 1u + unit_rand() % 8u;
        double sx = 0, sy = 0, sz = 0, len;

        for (uint32_t i = 0; i < count; i++) {
            /* A fan of faces around an up-facing vertex: normals within 60 degrees of +y. */
            const double a = 2.0 * TEST_PI * (double)unit_rand() / 4294967296.0;
            const double b = (TEST_PI / 3.0) * (double)unit_rand() / 4294967296.0;

            n[i] = u3(sin(b) * cos(a), cos(b), sin(b) * sin(a));
            sx += ud(n[i].x);
            sy += ud(n[i].y);
            sz += ud(n[i].z);
        }
        len = sqrt(sx * sx + sy * sy + sz * sz);
        m = uvec3_mean_direction(n, count);
        CHECK(fabs(ud(m.x) - sx / len) < 1e-6 && fabs(ud(m.y) - sy / len) < 1e-6 &&
              fabs(ud(m.z) - sz / len) < 1e-6);
        mesh_normal_to_q14(m, q);
        m = mesh_q14_normal(q, 0);
        CHECK(fabs(ud(m.x) - sx / len) < 1.0 / 16384.0 &&
              fabs(ud(m.y) - sy / len) < 1.0 / 16384.0 &&
              fabs(ud(m.z) - sz / len) < 1.0 / 16384.0);
    }
}
