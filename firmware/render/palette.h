/*
 * palette.h — the 256-entry palette as 16 materials x 16 light levels, and the flat-shading rule
 * that maps a face's lighting to a level. Pure code.
 *
 * Index = 16 * material + shade. Material 0 is not lit: its entries are fixed colours (background,
 * crosshair). Materials 14 and 15 are the anaglyph ramps (pure red, pure cyan). Shade 15 is the
 * material's full colour, shade s is (s + 1)/16 of it: a channel c (0..15) becomes
 * round(c * (s + 1) / 16).
 *
 * Lighting (flat, per face): one directional light plus ambient,
 *   shade = ambient + (15 - ambient) * max(0, n . l)      (rounded down to a level)
 * with n the face's unit normal and l the unit vector towards the light, both in the same frame.
 */
#ifndef PALETTE_H
#define PALETTE_H

#include <stdint.h>

#include "config/build_options.h"
#include "math/real.h"
#include "math/vec.h"

#define PAL_SHADES     16u
#define PAL_MATERIALS  16u
#define PAL_ENTRIES    256u

#define PAL_INDEX(material, shade) ((uint8_t)(((material) << 4) | (shade)))

/* A palette entry as the GPU's palette window holds it (contract/gpu-contract.md, PALETTE):
 * RGB444 from 4-bit channels, R in bits 11:8. The palette builds its entries in that format and
 * the driver loads them as they are, so the format is the palette's, not the driver's. */
#define PAL_RGB444(r, g, b) ((((uint32_t)(r) & 0xFu) << 8) | (((uint32_t)(g) & 0xFu) << 4) | \
                             ((uint32_t)(b) & 0xFu))

/* Material 0: fixed colours. */
#define PAL_BLACK      PAL_INDEX(0u, 0u)
#define PAL_SKY        PAL_INDEX(0u, 1u)  /* clear colour */
#define PAL_WHITE      PAL_INDEX(0u, 2u)  /* crosshair */
#define PAL_NIGHT      PAL_INDEX(0u, 3u)  /* clear colour of the anaglyph view */

/* Lit materials. */
enum pal_material {
    MAT_NONE = 0,
    MAT_RED = 1,
    MAT_GREEN = 2,
    MAT_BLUE = 3,
    MAT_YELLOW = 4,
    MAT_CYAN = 5,
    MAT_MAGENTA = 6,
    MAT_ORANGE = 7,
    MAT_WHITE = 8,
    MAT_GRASS = 9,
    MAT_DIRT = 10,
    MAT_STONE = 11,
    MAT_SAND = 12,
    MAT_WATER = 13,
    MAT_ANAGLYPH_LEFT = 14,   /* red: the left eye's image */
    MAT_ANAGLYPH_RIGHT = 15,  /* cyan: the right eye's image */
};

/* Fill pal[PAL_ENTRIES] with RGB444 words. */
void palette_build(uint16_t pal[PAL_ENTRIES]);

/*
 * The anaglyph through the GPU's write mask (CAPS_WMASK): an index is two eyes at once, the high
 * nibble the left eye's level (red), the low nibble the right eye's (green and blue: cyan), each
 * eye's pass writing its own plane only. Level 0 is the background (black), 1 .. 15 an object's
 * light level, PAL_ANAGLYPH_LEVEL of its shade (shade 0 becomes 1, so a face is never taken for
 * the background). Index (l << 4) | r is RGB444 (l, r, r).
 */
void palette_build_anaglyph(uint16_t pal[PAL_ENTRIES]);
#define PAL_ANAGLYPH_BACKGROUND 0x00u
#define PAL_ANAGLYPH_LEVEL(shade) (((shade) == 0u) ? 1u : (shade))
/* A level in both nibbles: whichever plane a pass writes gets it. */
#define PAL_ANAGLYPH_BOTH(level) ((uint8_t)((level) * 0x11u))

/*
 * One object's light, prepared so that a face's level costs three multiplies:
 *   level = ambient + floor((15 - ambient) * max(0, n . l))      (clamped to 15)
 * Fixed: the light is stored pre-scaled, s = (15 - ambient) l in Q5.27 (|s_i| <= 15 * 2^27 < 2^31);
 * with the normal in q2_30, mulh(n_i, s_i) = n_i s_i 2^25 (Q7.25, floored), and the three terms
 * sum to below 3 * 15 * 2^25 < 2^31: no overflow. The level is that sum >> 25.
 * Float: the same formula on floats, truncated.
 */
struct palette_light {
#if REAL_IS_FIXED
    int32_t scaled[3];  /* (15 - ambient) l, Q5.27 */
#else
    float scaled[3];    /* (15 - ambient) l */
#endif
    uint32_t ambient;
};

static inline void palette_light_init(struct palette_light *pl, uvec3 l, uint32_t ambient)
{
    const uint32_t span = 15u - ((ambient > 15u) ? 15u : ambient);

    pl->ambient = 15u - span;
#if REAL_IS_FIXED
    /* q2_30 -> Q5.27 is >> 3; times span <= 15 keeps |.| <= 15 * 2^27. */
    pl->scaled[0] = (l.x >> 3) * (int32_t)span;
    pl->scaled[1] = (l.y >> 3) * (int32_t)span;
    pl->scaled[2] = (l.z >> 3) * (int32_t)span;
#else
    pl->scaled[0] = l.x * (float)span;
    pl->scaled[1] = l.y * (float)span;
    pl->scaled[2] = l.z * (float)span;
#endif
}

static inline uint32_t palette_light_level(const struct palette_light *pl, uvec3 n)
{
#if !FW_WITH_LIGHTING
    (void)pl;
    (void)n;
    return 15u;  /* built without lighting: the material's full level */
#else
    uint32_t level = pl->ambient;
#if REAL_IS_FIXED
    const int32_t d = fx_mulh(n.x, pl->scaled[0]) + fx_mulh(n.y, pl->scaled[1]) +
                      fx_mulh(n.z, pl->scaled[2]);

    if (d > 0) {
        level += (uint32_t)d >> 25;
    }
#else
    const float d = n.x * pl->scaled[0] + n.y * pl->scaled[1] + n.z * pl->scaled[2];

    if (d > 0.0f) {
        level += (uint32_t)d;
    }
#endif
    return (level > 15u) ? 15u : level;
#endif
}

/* The largest VTX_I the firmware writes: level 15.0 in the GPU's Q4.12 (contract, "Gouraud
 * intensity"), the material's full colour, as the flat rule's top level. */
#define PAL_INTENSITY_MAX (15u << 12)

/*
 * The same light as a Gouraud vertex intensity, Q4.12 (VTX_I): the level before rounding down,
 *   I = 4096 (ambient + (15 - ambient) max(0, n . l))      (at most PAL_INTENSITY_MAX)
 * so that I >> 12 is exactly palette_light_level's level for the same normal (the GPU's undithered
 * level of a vertex) and the fraction is what the GPU interpolates and dithers. Fixed: the sum d is
 * the level's Q7.25 (palette_light_level: 0 <= d < 15 * 2^25 when positive), and d >> 13 its
 * Q.12, below 15 * 2^12; plus ambient * 2^12 <= 15 * 2^12 the total stays below 2^17, clamped to
 * PAL_INTENSITY_MAX. Float: the same on floats, truncated to Q4.12.
 */
static inline uint32_t palette_light_intensity(const struct palette_light *pl, uvec3 n)
{
#if !FW_WITH_LIGHTING
    (void)pl;
    (void)n;
    return PAL_INTENSITY_MAX;
#else
    uint32_t inten = pl->ambient << 12;
#if REAL_IS_FIXED
    const int32_t d = fx_mulh(n.x, pl->scaled[0]) + fx_mulh(n.y, pl->scaled[1]) +
                      fx_mulh(n.z, pl->scaled[2]);

    if (d > 0) {
        inten += (uint32_t)d >> 13;
    }
#else
    const float d = n.x * pl->scaled[0] + n.y * pl->scaled[1] + n.z * pl->scaled[2];

    if (d > 0.0f) {
        inten += (uint32_t)(d * 4096.0f);
    }
#endif
    return (inten > PAL_INTENSITY_MAX) ? PAL_INTENSITY_MAX : inten;
#endif
}

#endif /* PALETTE_H */
