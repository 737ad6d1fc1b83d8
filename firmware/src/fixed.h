/*
 * fixed.h — fixed-point arithmetic for a CPU without an FPU (rv32im). Pure code, host-testable.
 *
 * Formats (the name says the format):
 *   q16_16    int32_t, value = raw / 2^16. Range [-32768, 32768), step 1/65536 (1.5e-5).
 *   fx_angle  uint16_t turn fraction, value = raw / 65536 turns (65536 = 360 degrees). Angle
 *             arithmetic wraps modulo one turn for free in uint16_t.
 *
 * Overflow policy: every operation whose result can leave the q16_16 range saturates to
 * FX_MAX / FX_MIN and increments a sticky overflow counter (fx_overflow_count()), like a DSP's
 * sticky Q flag. Callers check the counter where a range argument says overflow cannot happen —
 * a non-zero count means that argument was wrong. The counter is the only state in this module.
 *
 * Rounding: fx_mul and fx_div round to nearest (ties away from zero for fx_div, up for fx_mul).
 * Right shifts of negative values are arithmetic (GCC and Clang guarantee it).
 */
#ifndef FIXED_H
#define FIXED_H

#include <stdint.h>

typedef int32_t q16_16;
typedef uint16_t fx_angle;

#define FX_FRAC_BITS 16
#define FX_ONE       ((q16_16)0x00010000)
#define FX_HALF      ((q16_16)0x00008000)
#define FX_MAX       ((q16_16)INT32_MAX)
#define FX_MIN       ((q16_16)INT32_MIN)

/* Integer -> q16_16; |i| must be <= 32767. */
#define FX_FROM_INT(i) ((q16_16)((int32_t)(i) * 65536))
/* Compile-time constant from a decimal literal, rounded: FX_CONST(0.25). Constant expressions
 * only — with a run-time argument it would pull in soft-float. */
#define FX_CONST(d) ((q16_16)((d) * 65536.0 + (((d) >= 0) ? 0.5 : -0.5)))

/* One full turn, and compile-time angle constants. */
#define FX_TURN         65536u
#define FX_ANGLE_DEG(d) ((fx_angle)((uint32_t)((d) * 65536.0 / 360.0 + 0.5) & 0xFFFFu))

/* Slow path of saturation: counts the overflow and returns the clamped value. */
q16_16 fx_saturate(int64_t v);

/* Sticky overflow counter: saturating operations since the last fx_overflow_clear(). */
uint32_t fx_overflow_count(void);
void fx_overflow_clear(void);

/* int64 -> q16_16 raw value, saturating (and counting) when out of range. */
static inline q16_16 fx_sat64(int64_t v)
{
    if (v > (int64_t)INT32_MAX || v < (int64_t)INT32_MIN) {
        return fx_saturate(v);
    }
    return (q16_16)v;
}

static inline q16_16 fx_add(q16_16 a, q16_16 b)
{
    return fx_sat64((int64_t)a + b);  /* |a + b| <= 2^32: exact in int64 */
}

static inline q16_16 fx_sub(q16_16 a, q16_16 b)
{
    return fx_sat64((int64_t)a - b);
}

/*
 * a * b, rounded to nearest.
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
 * out of range or b == 0. Uses one 64/32-bit division (a libgcc call on rv32). */
q16_16 fx_div(q16_16 a, q16_16 b);

/* 1 / b, same rules as fx_div. */
static inline q16_16 fx_recip(q16_16 b)
{
    return fx_div(FX_ONE, b);
}

/* Sine and cosine of a turn fraction, from a 256-entry-per-turn table with linear
 * interpolation. Result in [-1.0, 1.0] as q16_16. Max error against the exact value is below
 * 1e-4 (interpolation (2*pi/256)^2/8 = 7.5e-5, plus table and interpolation rounding 2.3e-5);
 * tests/firmware checks every one of the 65536 angles. Never overflows. */
q16_16 fx_sin(fx_angle a);
q16_16 fx_cos(fx_angle a);

#endif /* FIXED_H */
