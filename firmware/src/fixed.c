/*
 * fixed.c — out-of-line parts of the fixed-point module (see fixed.h for formats and rules).
 */
#include "fixed.h"

static uint32_t fx_overflows;  /* sticky overflow counter, see fixed.h */

q16_16 fx_saturate(int64_t v)
{
    fx_overflows++;
    return (v < 0) ? FX_MIN : FX_MAX;
}

uint32_t fx_overflow_count(void)
{
    return fx_overflows;
}

void fx_overflow_clear(void)
{
    fx_overflows = 0u;
}

/*
 * Range: |a| <= 2^31, so the numerator a * 2^16 is at most 2^47 in magnitude and adding |b|/2
 * (<= 2^30) stays far inside int64. The quotient can reach 2^47 (b small): fx_sat64 clamps it.
 */
q16_16 fx_div(q16_16 a, q16_16 b)
{
    int64_t num = (int64_t)a * FX_ONE;
    int64_t half = (int64_t)b / 2;

    if (b == 0) {
        return fx_saturate((a < 0) ? -1 : 1);
    }
    /* Round half away from zero: push the numerator away from zero by |b|/2 before truncating. */
    if ((num < 0) == (b < 0)) {
        num += half;
    } else {
        num -= half;
    }
    return fx_sat64(num / b);
}

/*
 * sin(2*pi*i/256) in q16_16 for i = 0..256 (the last entry repeats the first so interpolation
 * never wraps). Generated with: round(65536 * sin(2 * pi * i / 256)).
 */
static const q16_16 fx_sin_table[257] = {
    0, 1608, 3216, 4821, 6424, 8022, 9616, 11204,
    12785, 14359, 15924, 17479, 19024, 20557, 22078, 23586,
    25080, 26558, 28020, 29466, 30893, 32303, 33692, 35062,
    36410, 37736, 39040, 40320, 41576, 42806, 44011, 45190,
    46341, 47464, 48559, 49624, 50660, 51665, 52639, 53581,
    54491, 55368, 56212, 57022, 57798, 58538, 59244, 59914,
    60547, 61145, 61705, 62228, 62714, 63162, 63572, 63944,
    64277, 64571, 64827, 65043, 65220, 65358, 65457, 65516,
    65536, 65516, 65457, 65358, 65220, 65043, 64827, 64571,
    64277, 63944, 63572, 63162, 62714, 62228, 61705, 61145,
    60547, 59914, 59244, 58538, 57798, 57022, 56212, 55368,
    54491, 53581, 52639, 51665, 50660, 49624, 48559, 47464,
    46341, 45190, 44011, 42806, 41576, 40320, 39040, 37736,
    36410, 35062, 33692, 32303, 30893, 29466, 28020, 26558,
    25080, 23586, 22078, 20557, 19024, 17479, 15924, 14359,
    12785, 11204, 9616, 8022, 6424, 4821, 3216, 1608,
    0, -1608, -3216, -4821, -6424, -8022, -9616, -11204,
    -12785, -14359, -15924, -17479, -19024, -20557, -22078, -23586,
    -25080, -26558, -28020, -29466, -30893, -32303, -33692, -35062,
    -36410, -37736, -39040, -40320, -41576, -42806, -44011, -45190,
    -46341, -47464, -48559, -49624, -50660, -51665, -52639, -53581,
    -54491, -55368, -56212, -57022, -57798, -58538, -59244, -59914,
    -60547, -61145, -61705, -62228, -62714, -63162, -63572, -63944,
    -64277, -64571, -64827, -65043, -65220, -65358, -65457, -65516,
    -65536, -65516, -65457, -65358, -65220, -65043, -64827, -64571,
    -64277, -63944, -63572, -63162, -62714, -62228, -61705, -61145,
    -60547, -59914, -59244, -58538, -57798, -57022, -56212, -55368,
    -54491, -53581, -52639, -51665, -50660, -49624, -48559, -47464,
    -46341, -45190, -44011, -42806, -41576, -40320, -39040, -37736,
    -36410, -35062, -33692, -32303, -30893, -29466, -28020, -26558,
    -25080, -23586, -22078, -20557, -19024, -17479, -15924, -14359,
    -12785, -11204, -9616, -8022, -6424, -4821, -3216, -1608,
    0,
};

/*
 * Top 8 bits of the angle pick the table segment, the low 8 bits interpolate inside it.
 * Range: neighbouring entries differ by at most 1608 (= 65536 * 2*pi/256), times a fraction
 * < 256: |delta * frac| < 2^19, no overflow.
 */
q16_16 fx_sin(fx_angle a)
{
    uint32_t i = (uint32_t)a >> 8;
    int32_t frac = (int32_t)(a & 0xFFu);
    q16_16 s0 = fx_sin_table[i];
    q16_16 s1 = fx_sin_table[i + 1u];

    return s0 + (((s1 - s0) * frac + 128) >> 8);
}

q16_16 fx_cos(fx_angle a)
{
    return fx_sin((fx_angle)(a + FX_TURN / 4u));
}
