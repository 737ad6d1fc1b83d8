/*
 * real.h — the arithmetic backend of the geometry pipeline, chosen at build time.
 *
 *   default            fixed point: real_t = q16_16 (positions, distances), unit_t = q2_30
 *                      (rotation entries, unit vectors, cosines). Saturating, with the sticky
 *                      overflow counter of fixed.h.
 *   -DFW_BACKEND_FLOAT=1  IEEE single precision: real_t = unit_t = float. On rv32im every
 *                      operation is a libgcc soft-float call; this backend exists to compare
 *                      error and cost with the fixed-point one (`make bench-fw`).
 *
 * Everything above this header (vectors, camera, clipping, scenes) is written once against these
 * names. The few kernels where the fixed backend needs a different algorithm, not just different
 * operators (the vertex transform, the projection), branch on REAL_IS_FIXED themselves.
 *
 * Ranges the fixed backend relies on (see firmware/README.md, "Number formats"):
 *   world points and the eye within +-1024 per axis, so |w - eye| <= 2 * 1024 * sqrt(3) = 3547 and
 *   every view coordinate stays within +-4096 (the projection pre-scales them by 8 into int32);
 *   model coordinates within +-8192 (the vertex transform pre-scales them by 4 into int32).
 */
#ifndef REAL_H
#define REAL_H

#include <stdint.h>

#include "math/fixed.h"

#if defined(FW_BACKEND_FLOAT) && FW_BACKEND_FLOAT
#define REAL_IS_FIXED 0
#define REAL_BACKEND_NAME "float"

typedef float real_t;
typedef float unit_t;

#define REAL_C(d) ((real_t)(d))
#define UNIT_C(d) ((unit_t)(d))
#define REAL_ZERO 0.0f
#define REAL_ONE  1.0f
#define UNIT_ONE  1.0f
#define REAL_HUGE 1.0e30f  /* "infinity" for distances (ray casting) */

static inline real_t real_from_int(int32_t i) { return (real_t)i; }
static inline real_t real_from_q16(q16_16 v) { return (real_t)v * (1.0f / 65536.0f); }
static inline q16_16 real_to_q16(real_t r)
{
    const float s = r * 65536.0f;

    if (s >= 2147483520.0f) {
        return INT32_MAX;
    }
    if (s <= -2147483648.0f) {
        return INT32_MIN;
    }
    return (q16_16)(s + ((s >= 0.0f) ? 0.5f : -0.5f));
}
static inline unit_t unit_from_q16(q16_16 v) { return (unit_t)v * (1.0f / 65536.0f); }
static inline real_t real_from_unit(unit_t u) { return u; }
static inline unit_t unit_from_real(real_t r) { return r; }

static inline real_t real_add(real_t a, real_t b) { return a + b; }
static inline real_t real_sub(real_t a, real_t b) { return a - b; }
static inline real_t real_mul(real_t a, real_t b) { return a * b; }
static inline real_t real_div(real_t a, real_t b) { return a / b; }
static inline real_t real_scale(real_t r, unit_t u) { return r * u; }
static inline unit_t unit_add(unit_t a, unit_t b) { return a + b; }
static inline unit_t unit_sub(unit_t a, unit_t b) { return a - b; }
static inline unit_t unit_mul(unit_t a, unit_t b) { return a * b; }
static inline real_t real_half(real_t a) { return a * 0.5f; }
static inline real_t real_abs(real_t a) { return (a < 0.0f) ? -a : a; }

/* floor(r) as an integer; |r| < 2^31. No libm: truncate, then step down for negatives. */
static inline int32_t real_floor_int(real_t r)
{
    const int32_t t = (int32_t)r;

    return ((real_t)t > r) ? t - 1 : t;
}

/* Nearest integer, ties away from zero. |r| < 2^31. */
static inline int32_t real_round_int(real_t r)
{
    return (int32_t)(r + ((r >= 0.0f) ? 0.5f : -0.5f));
}

#else /* fixed point */
#define REAL_IS_FIXED 1
#define REAL_BACKEND_NAME "fixed"

typedef q16_16 real_t;
typedef q2_30 unit_t;

#define REAL_C(d) FX_CONST(d)
#define UNIT_C(d) Q30_CONST(d)
#define REAL_ZERO 0
#define REAL_ONE  FX_ONE
#define UNIT_ONE  Q30_ONE
#define REAL_HUGE FX_MAX

static inline real_t real_from_int(int32_t i) { return FX_FROM_INT(i); }  /* |i| <= 32767 */
static inline real_t real_from_q16(q16_16 v) { return v; }
static inline q16_16 real_to_q16(real_t r) { return r; }
static inline unit_t unit_from_q16(q16_16 v) { return q30_from_q16(v); }
static inline real_t real_from_unit(unit_t u) { return q30_to_q16(u); }
static inline unit_t unit_from_real(real_t r) { return q30_from_q16(r); }

static inline real_t real_add(real_t a, real_t b) { return fx_add(a, b); }
static inline real_t real_sub(real_t a, real_t b) { return fx_sub(a, b); }
static inline real_t real_mul(real_t a, real_t b) { return fx_mul(a, b); }
static inline real_t real_div(real_t a, real_t b) { return fx_div(a, b); }
static inline real_t real_scale(real_t r, unit_t u) { return q30_scale(r, u); }
static inline unit_t unit_add(unit_t a, unit_t b) { return fx_add(a, b); }
static inline unit_t unit_sub(unit_t a, unit_t b) { return fx_sub(a, b); }
static inline unit_t unit_mul(unit_t a, unit_t b) { return q30_mul(a, b); }
static inline real_t real_half(real_t a) { return a / 2; }  /* rounds toward zero; exact for even raw */
static inline real_t real_abs(real_t a) { return (a < 0) ? fx_sub(0, a) : a; }

static inline int32_t real_floor_int(real_t r) { return r >> FX_FRAC_BITS; }
static inline int32_t real_round_int(real_t r) { return fx_round_to_int(r); }
#endif

/* A value as double, exactly (both backends' values are doubles' subsets): for tools that read
 * the pipeline's numbers on the host (the host build's scene export, the unit tests); nothing on
 * the target calls them. */
static inline double real_as_double(real_t r) { return (double)r / (double)REAL_ONE; }
static inline double unit_as_double(unit_t u) { return (double)u / (double)UNIT_ONE; }

/* Square root of r >= 0 (negative input gives 0). Build-time and per-frame use. */
real_t real_sqrt(real_t r);

#endif /* REAL_H */
