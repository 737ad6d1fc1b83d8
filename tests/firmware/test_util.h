/*
 * test_util.h — conversions between the pipeline's backend types (real.h) and double, so one test
 * source checks both the fixed-point and the float build against double-precision references.
 */
#ifndef TEST_UTIL_H
#define TEST_UTIL_H

#include <math.h>

#include "math/real.h"
#include "math/vec.h"

#define TEST_PI 3.14159265358979323846

static inline double rd(real_t r)
{
    return real_as_double(r);
}

static inline double ud(unit_t u)
{
    return unit_as_double(u);
}

/* d as the backend holds it: rounded to the nearest step of the fixed-point build (`one` is its
 * 1.0), as is in the float build. */
#if REAL_IS_FIXED
#define TEST_FROM_DOUBLE(type, d, one) ((type)llround((d) * (double)(one)))
#else
#define TEST_FROM_DOUBLE(type, d, one) ((type)(d))
#endif

static inline real_t to_real(double d)
{
    return TEST_FROM_DOUBLE(real_t, d, REAL_ONE);
}

static inline unit_t to_unit(double d)
{
    return TEST_FROM_DOUBLE(unit_t, d, UNIT_ONE);
}

/* max |M M^T - I| over the entries: how far a rotation is from orthonormal. */
static inline double mat_ortho_err(const mat3 *m)
{
    double e = 0.0;

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            double s = 0.0;

            for (int k = 0; k < 3; k++) {
                s += ud(m->m[i][k]) * ud(m->m[j][k]);
            }
            e = fmax(e, fabs(s - ((i == j) ? 1.0 : 0.0)));
        }
    }
    return e;
}

static inline vec3 v3(double x, double y, double z)
{
    return vec3_make(to_real(x), to_real(y), to_real(z));
}

static inline uvec3 u3(double x, double y, double z)
{
    uvec3 u = {to_unit(x), to_unit(y), to_unit(z)};

    return u;
}

/* One unit of the last place of real_t near 1 (fixed: 2^-16; float: ~6e-8). */
#if REAL_IS_FIXED
#define TEST_REAL_ULP (1.0 / 65536.0)
#define TEST_UNIT_ULP (1.0 / 1073741824.0)
#else
#define TEST_REAL_ULP 1.2e-7
#define TEST_UNIT_ULP 1.2e-7
#endif

#endif /* TEST_UTIL_H */
