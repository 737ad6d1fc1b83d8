/*
 * test_cam_path.c — the camera path's own sine (app/cam_path_sin.h): the path of `make
 * bench-error` must be the same whatever the firmware's sine table (FW_SIN_TABLE_BITS) is, and the
 * same as before the path had a sine of its own.
 */
#include <math.h>
#include <stdint.h>

#include "app/cam_path_sin.h"
#include "math/fixed.h"
#include "unit.h"

#define PI 3.14159265358979323846

/* Every computed entry is the exact value rounded (the 256-entry table's definition). */
void test_cam_path_sin_entries(void)
{
    for (uint32_t i = 0; i <= 256u; i++) {
        const long want = lround(65536.0 * sin(2.0 * PI * (double)i / 256.0));

        if (cam_path_sin_table(i) != (int32_t)want) {
            unit_fail(__FILE__, __LINE__, "cam_path_sin_table(%u) = %d, want %ld", i,
                      cam_path_sin_table(i), want);
            return;
        }
    }
}

/* At the default table size the path's sine is fx_sin, bit for bit, at every angle: the views
 * are those the path had when it used fx_sin. (Other sizes: tests/firmware/sin_sizes.sh checks
 * that fx_sin then differs, while this function cannot: it does not read the table.) */
void test_cam_path_sin_is_fx_sin(void)
{
#if FW_SIN_TABLE_BITS == 8
    for (uint32_t a = 0; a < FX_TURN; a++) {
        if (cam_path_sin(a) != fx_sin((fx_angle)a) || cam_path_cos(a) != fx_cos((fx_angle)a)) {
            unit_fail(__FILE__, __LINE__, "angle %u: cam_path %d/%d, fx %d/%d", a, cam_path_sin(a),
                      cam_path_cos(a), fx_sin((fx_angle)a), fx_cos((fx_angle)a));
            return;
        }
    }
#endif
    /* Angles wrap as fx_angle does (cam_path passes signed pitches as uint32_t). */
    CHECK_EQ(cam_path_sin((uint32_t)-16384), -65536);
    CHECK_EQ(cam_path_sin(65536u + 100u), cam_path_sin(100u));
}
