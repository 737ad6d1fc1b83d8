/*
 * fixed.h — fixed-point arithmetic for a CPU without an FPU (rv32im). Pure code, host-testable.
 *
 * Formats (the name says the format):
 *   q16_16    int32_t, value = raw / 2^16. Range [-32768, 32768), step 1/65536 (1.5e-5).
 *             Positions and distances in world/view units.
 *   q2_30     int32_t, value = raw / 2^30. Range [-2, 2), step 9.3e-10. Unit quantities: rotation
 *             matrix entries, unit vectors (normals, light), cosines.
 *   fx_angle  uint16_t turn fraction, value = raw / 65536 turns (65536 = 360 degrees). Angle
 *             arithmetic wraps modulo one turn for free in uint16_t.
 *
 * Overflow policy: every operation whose result can leave its format's range saturates to the
 * int32 extremes and increments a sticky overflow counter (fx_overflow_count()), like a DSP's
 * sticky Q flag. Callers check the counter where a range argument says overflow cannot happen —
 * a non-zero count means that argument was wrong. The counter is the only state in this module.
 *
 * Rounding: fx_mul, q30_mul, q30_scale round to nearest (ties up); fx_div rounds ties away from
 * zero. fx_mulh/fx_mulhu floor (they are the bare rv32im high-word multiplies). Right shifts of
 * negative values are arithmetic (GCC and Clang guarantee it).
 */
#ifndef FIXED_H
#define FIXED_H

#include <stdint.h>

#include "config/hot_path.h"

typedef int32_t q16_16;
typedef int32_t q2_30;
typedef uint16_t fx_angle;

#define FX_FRAC_BITS 16
#define FX_ONE       ((q16_16)0x00010000)
#define FX_HALF      ((q16_16)0x00008000)
#define FX_MAX       ((q16_16)INT32_MAX)
#define FX_MIN       ((q16_16)INT32_MIN)

#define Q30_FRAC_BITS 30
#define Q30_ONE       ((q2_30)0x40000000)

/* Integer -> q16_16; |i| must be <= 32767. */
#define FX_FROM_INT(i) ((q16_16)((int32_t)(i) * 65536))
/* Compile-time constants from decimal literals, rounded: FX_CONST(0.25), Q30_CONST(0.7071).
 * Constant expressions only — with a run-time argument they would pull in soft-float.
 * Q30_CONST needs -2 <= d < 2. */
#define FX_CONST(d)  ((q16_16)((d) * 65536.0 + (((d) >= 0) ? 0.5 : -0.5)))
#define Q30_CONST(d) ((q2_30)((d) * 1073741824.0 + (((d) >= 0) ? 0.5 : -0.5)))

/* One full turn, and compile-time angle constants. */
#define FX_TURN         65536u
/* Negative angles wrap (FX_ANGLE_DEG(-35) = 65536 - 6372): rounded to a signed integer first, as
 * converting a negative double straight to uint32_t is undefined (GCC folds it to 0). */
#define FX_ANGLE_DEG(d) \
    ((fx_angle)((uint32_t)(int32_t)((d) * 65536.0 / 360.0 + (((d) >= 0) ? 0.5 : -0.5)) & 0xFFFFu))

/* Slow path of saturation: counts the overflow and returns the clamped value. */
int32_t fx_saturate(int64_t v);

/* Sticky overflow counter: saturating operations since the last fx_overflow_clear(). */
uint32_t fx_overflow_count(void);
void fx_overflow_clear(void);
/* Count one overflow found by a caller's own range check (an input outside a range argument). */
void fx_overflow_note(void);

/* int64 -> int32 raw value (of any format), saturating (and counting) when out of range. */
static inline int32_t fx_sat64(int64_t v)
{
    if (v > (int64_t)INT32_MAX || v < (int64_t)INT32_MIN) {
        return fx_saturate(v);
    }
    return (int32_t)v;
}

/* Same-format add/subtract (q16_16 or q2_30). |a +- b| <= 2^32: exact in int64, then saturated. */
static inline int32_t fx_add(int32_t a, int32_t b)
{
    return fx_sat64((int64_t)a + b);
}

static inline int32_t fx_sub(int32_t a, int32_t b)
{
    return fx_sat64((int64_t)a - b);
}

/*
 * q16_16 a * b, rounded to nearest.
 * Range: |a|, |b| <= 2^31 so |a*b| <= 2^62 and adding the rounding half (2^15) cannot overflow
 * the int64 intermediate. After the shift the result can need up to 47 bits (e.g. 200.0 * 200.0
 * = 40000.0 > 32768): fx_sat64 clamps and counts that case.
 */
static inline q16_16 fx_mul(q16_16 a, q16_16 b)
{
    return fx_sat64(((int64_t)a * b + FX_HALF) >> FX_FRAC_BITS);
}

/* Nearest integer (ties up). Never overflows: the result is within [-32768, 32768]. */
static inline int32_t fx_round_to_int(q16_16 a)
{
    return (a >> FX_FRAC_BITS) + ((a >> (FX_FRAC_BITS - 1)) & 1);
}

/* a / b, rounded to nearest (ties away from zero); saturates (and counts) when the quotient is
 * out of range or b == 0. Uses one 64/32-bit division (a libgcc call on rv32): for per-frame and
 * build-time work, not per vertex (the projection uses fx_recip_mantissa). */
q16_16 fx_div(q16_16 a, q16_16 b);

/* 1 / b, same rules as fx_div. */
static inline q16_16 fx_recip(q16_16 b)
{
    return fx_div(FX_ONE, b);
}

/* ---- q2_30 ---------------------------------------------------------------------------------- */

/* a * b in q2_30, rounded. |a|, |b| < 2 so |a*b| < 4: the product of two unit quantities
 * (<= 1 + small) stays inside [-2, 2); anything larger saturates and counts. The int64
 * intermediate (< 2^62 + 2^29) cannot overflow. */
static inline q2_30 q30_mul(q2_30 a, q2_30 b)
{
    return fx_sat64(((int64_t)a * b + ((int64_t)1 << 29)) >> Q30_FRAC_BITS);
}

/* q16_16 v scaled by the q2_30 factor u, rounded: v * u as q16_16. |v * u| <= 2 |v|, so it
 * saturates (and counts) only for |v| >= 16384 with |u| > 1. */
static inline q16_16 q30_scale(q16_16 v, q2_30 u)
{
    return fx_sat64(((int64_t)v * u + ((int64_t)1 << 29)) >> Q30_FRAC_BITS);
}

/* q16_16 -> q2_30 (exact; saturates and counts outside [-2, 2)). */
static inline q2_30 q30_from_q16(q16_16 v)
{
    return fx_sat64((int64_t)v * 16384);
}

/* q2_30 -> q16_16, rounded (never overflows). */
static inline q16_16 q30_to_q16(q2_30 u)
{
    return (u + 8192) >> 14;
}

/* ---- raw multiplies and the projection's reciprocal ---------------------------------------- */

/* floor(a * b / 2^32), signed: one `mulh` on rv32im. Exact (no overflow possible). */
static inline int32_t fx_mulh(int32_t a, int32_t b)
{
    return (int32_t)(((int64_t)a * b) >> 32);
}

/* floor(a * b / 2^32), unsigned: one `mulhu` on rv32im. */
static inline uint32_t fx_mulhu(uint32_t a, uint32_t b)
{
    return (uint32_t)(((uint64_t)a * b) >> 32);
}

/* Leading zeros of an 8-bit value (8 for 0), fx_normalize32's table (fixed.c). */
extern const uint8_t fx_clz8[256];

/* Shift x (> 0) left until bit 31 is set; *shift receives the count (0..31). rv32im has no
 * count-leading-zeros instruction, and libgcc's __clzsi2 is a call: a shift by 16 (seldom where it
 * counts: a projected depth below one view unit), one by 8 when the top byte is still 0, then the
 * top byte's leading zeros from a 256-byte table. Two branches, not five: on VexRiscv a taken
 * forward branch is a misprediction, and five compare-and-shift steps took one on about half of
 * them (the knot's projection: 9,275 taken forward branches a frame, 2,501 with the table). */
static inline uint32_t fx_normalize32(uint32_t x, int32_t *shift)
{
    int32_t s = 0;
    uint32_t top;
    uint32_t z;

    if (FW_UNLIKELY(x < 0x00010000u)) {
        x <<= 16;
        s = 16;
    }
    top = x >> 24;
    if (top == 0u) {  /* x >= 2^16 here: after this shift top >= 1 */
        x <<= 8;
        s += 8;
        top = x >> 24;
    }
    z = fx_clz8[top];  /* 0 .. 7 */
    *shift = s + (int32_t)z;
    return x << z;
}

/*
 * Reciprocal of a normalized mantissa without a divider: for m in [2^31, 2^32) (i.e. mu = m / 2^32
 * in [0.5, 1)), returns Y ~= 2^63 / m (i.e. 1/mu in Q1.31, within (2^31, 2^32)).
 * Method: a 1024-entry seed table on the 10 bits below the leading one (relative error below
 * 2^-11 + 2^-16), then one Newton-Raphson step y <- y (2 - mu y), which squares the relative error
 * to about 2^-21 (the step's two floors add a few units). Measured (tests/firmware, ~10^6
 * mantissas incl. both ends): Y is within 1039 units (relative 2^-20.98; the test allows 1100) of
 * floor(2^63/m); at m = 2^31 it returns 2^32 - 2 (2^32 does not fit). 2 multiplies, no division;
 * portable to cores without a hardware divider (MicroBlaze). A second step would bring Y within 2
 * units for 4 instructions more per vertex; the projection does not need it (proj.h: 2^-20.9 of
 * the largest offset, 1536 px, is 0.012 of a Q12.4 unit).
 * Range: the step forms P = mu y in Q1.31 (mulhu, < 2^32), D = 2 - mu y as 2^32 - P, and
 * y (2 - mu y) = mulhu(Y, D) * 2; the iterate stays below 2/mu <= 2^32, so nothing wraps.
 */
#define FX_RECIP_SEED_ENTRIES 1024u
extern const uint16_t fx_recip_seed[FX_RECIP_SEED_ENTRIES];

/* FW_RECIP_NEWTON_STEPS, an accuracy knob of `make bench-error` (default 1, the build above): 0
 * returns the seed itself (relative error 2^-11: the projection's offsets then within
 * 0.56 + 1536 * 16 * 2^-11 = 12.6 Q12.4 units, 0.8 px, of the exact ones; Y = seed << 16 <=
 * 65504 * 2^16 < 2^32 and proj.h's Q < 2^31 hold for any Y < 2^32), 2 takes a second step
 * (Y within a few units of 2^63 / m; each step keeps the iterate below 1/mu's 2^32 as argued
 * above, y (2 - mu y) <= 1/mu for every y). */
#ifndef FW_RECIP_NEWTON_STEPS
#define FW_RECIP_NEWTON_STEPS 1
#endif
#if FW_RECIP_NEWTON_STEPS < 0 || FW_RECIP_NEWTON_STEPS > 2
#error "FW_RECIP_NEWTON_STEPS must be 0, 1 or 2"
#endif

static inline uint32_t fx_recip_mantissa(uint32_t m)
{
    /* Y = 1/mu in Q1.31; the seed holds 1/mu in Q1.15. */
#if FW_RECIP_NEWTON_STEPS == 1
    const uint32_t y = (uint32_t)fx_recip_seed[(m >> 21) & (FX_RECIP_SEED_ENTRIES - 1u)] << 16;
    const uint32_t p = fx_mulhu(m, y);  /* mu * y in Q1.31, close to 2^31 */
    const uint32_t d = 0u - p;          /* 2 - mu * y in Q1.31: 2^32 - p, p in (0, 2^32) */

    return fx_mulhu(y, d) << 1;         /* y * (2 - mu * y) */
#else
    uint32_t y = (uint32_t)fx_recip_seed[(m >> 21) & (FX_RECIP_SEED_ENTRIES - 1u)] << 16;

    for (int i = 0; i < FW_RECIP_NEWTON_STEPS; i++) {
        y = fx_mulhu(y, 0u - fx_mulhu(m, y)) << 1;  /* the step above */
    }
    return y;
#endif
}

/* floor(sqrt(v)), exactly: a 32-bit root and one Newton step (fixed.c). Build-time and per-frame use. */
uint32_t fx_isqrt64(uint64_t v);

/* Sine and cosine of a turn fraction, from a table of N = FX_SIN_ENTRIES entries per turn with
 * linear interpolation. Result in [-1.0, 1.0] as q16_16. Never overflows.
 * Inline: a handful of instructions, called four times per object rotation per frame.
 * The top FW_SIN_TABLE_BITS bits of the angle pick the table segment, the low
 * FX_SIN_FRAC_BITS = 16 - FW_SIN_TABLE_BITS bits interpolate inside it.
 *
 * FW_SIN_TABLE_BITS, an accuracy knob of `make bench-error` (default 8: 256 entries, 1 KiB, the
 * build every other one is): 6 (64 entries, 260 bytes), 8 or 10 (1024 entries, 4 KiB). The cost
 * is the same handful of instructions at every size; the table's memory is what changes.
 * Error against the exact value, with h = 2*pi/N the segment: linear interpolation of sin is off
 * by at most h^2/8 (|sin''| <= 1), the entries by at most 2^-17 each (rounded, so their
 * interpolation too) and the final rounding by 2^-17: |error| <= h^2/8 + 2^-16 = FX_SIN_ERR_BOUND:
 *   N = 64: 1.22e-3   N = 256: 9.06e-5 (below 1e-4)   N = 1024: 2.00e-5.
 * tests/firmware checks every one of the 65536 angles against it, and every entry against libm.
 * Range: neighbouring entries differ by at most 65536 * 2*pi/N (6434 at N = 64), times a fraction
 * below 2^(16 - FW_SIN_TABLE_BITS): |delta * frac| < 65536 * 2*pi * 2^16 / N^2 <= 2^23, no
 * overflow at any size.
 * app/cam_path.h has a sine of its own (the 256-entry one, computed), so that a bench-error
 * camera path is the same whatever this knob says. */
#ifndef FW_SIN_TABLE_BITS
#define FW_SIN_TABLE_BITS 8
#endif
#if FW_SIN_TABLE_BITS != 6 && FW_SIN_TABLE_BITS != 8 && FW_SIN_TABLE_BITS != 10
#error "FW_SIN_TABLE_BITS must be 6, 8 or 10"
#endif
#define FX_SIN_ENTRIES   (1u << FW_SIN_TABLE_BITS)
#define FX_SIN_FRAC_BITS (16 - FW_SIN_TABLE_BITS)
/* h^2/8 + 2^-16 with h = 2 pi / N, i.e. pi^2 / (2 N^2) + 2^-16 (for tests: a double). */
#define FX_SIN_ERR_BOUND (0.5 * 3.14159265358979 * 3.14159265358979 / (double)FX_SIN_ENTRIES / \
                          (double)FX_SIN_ENTRIES + 1.0 / 65536.0)
extern const q16_16 fx_sin_table[FX_SIN_ENTRIES + 1u];

static inline q16_16 fx_sin(fx_angle a)
{
    const uint32_t i = (uint32_t)a >> FX_SIN_FRAC_BITS;
    const int32_t frac = (int32_t)(a & ((1u << FX_SIN_FRAC_BITS) - 1u));
    const q16_16 s0 = fx_sin_table[i];
    const q16_16 s1 = fx_sin_table[i + 1u];

    return s0 + (((s1 - s0) * frac + (1 << (FX_SIN_FRAC_BITS - 1))) >> FX_SIN_FRAC_BITS);
}

static inline q16_16 fx_cos(fx_angle a)
{
    return fx_sin((fx_angle)(a + FX_TURN / 4u));
}

#endif /* FIXED_H */
