/*
 * cam_path_sin.h — the camera path's own sine (app/cam_path.h), independent of the firmware's
 * sine table: math/fixed.h's fx_sin is an accuracy knob of `make bench-error`
 * (FW_SIN_TABLE_BITS), and a path placed with it would show every table size different views, so
 * that the knob's error would include a different camera. This one is the default table's
 * function exactly — 256 entries per turn, round(65536 sin(2 pi i / 256)), linear interpolation
 * as fx_sin does it — with the entries computed instead of stored: bit-identical to fx_sin at
 * FW_SIN_TABLE_BITS = 8 for all 65536 angles (tests/firmware/test_cam_path.c), so the path's
 * views are the ones it always had. Integers only, so that both backends, on the host and on rv32,
 * compute the same.
 */
#ifndef CAM_PATH_SIN_H
#define CAM_PATH_SIN_H

#include <stdint.h>

/* round(65536 sin(pi j / 128)) for j = 0..64 (the first quadrant), from its Taylor series to x^13,
 * evaluated by Horner in Q30: x = pi j / 128 <= pi / 2 < 1.58 is below 2^31 in Q30, x^2 < 2.5 and
 * every Horner factor 1 - x^2 t / k lies in (0.58, 1] (k >= 6, 0 < t <= 1), so each product of two
 * Q30 values is below 2^63 and nothing overflows int64. Truncation error of the series below
 * (pi/2)^15 / 15! = 8e-10, the Q30 roundings below 10 * 2^-30 = 1e-8: 7e-4 of a Q16 unit, while
 * no exact value of the 65 lies closer than 0.04 of a unit to a rounding tie, so the rounding to
 * Q16 is always the exact value's. */
static inline int32_t cam_path_sin_entry(uint32_t j)
{
    static const uint32_t k[6] = {156u, 110u, 72u, 42u, 20u, 6u};  /* (2n)(2n+1), n = 6 .. 1 */
    const int64_t one = (int64_t)1 << 30;
    const int64_t x = 3373259426LL * (int64_t)j / 128;  /* round(pi 2^30) = 3373259426 */
    const int64_t x2 = (x * x) >> 30;
    int64_t t = one;

    for (int n = 0; n < 6; n++) {
        t = one - ((x2 * t) >> 30) / (int64_t)k[n];
    }
    return (int32_t)((((x * t) >> 30) + ((int64_t)1 << 13)) >> 14);
}

/* Entry i (0..256) of the 256-entry table, by the quadrant symmetries of sin. */
static inline int32_t cam_path_sin_table(uint32_t i)
{
    uint32_t j = i & 127u;
    int32_t v;

    if (j > 64u) {
        j = 128u - j;
    }
    v = cam_path_sin_entry(j);
    return (i & 128u) ? -v : v;
}

/* sin of a turn fraction (65536 = one turn) in Q16.16, as fx_sin at 256 entries. The same range
 * argument: neighbouring entries differ by at most 1608, times a fraction < 256. */
static inline int32_t cam_path_sin(uint32_t a)
{
    const uint32_t i = (a & 0xFFFFu) >> 8;
    const int32_t frac = (int32_t)(a & 0xFFu);
    const int32_t s0 = cam_path_sin_table(i);
    const int32_t s1 = cam_path_sin_table(i + 1u);

    return s0 + (((s1 - s0) * frac + 128) >> 8);
}

static inline int32_t cam_path_cos(uint32_t a)
{
    return cam_path_sin(a + 16384u);
}

#endif /* CAM_PATH_SIN_H */
