/*
 * sin_sizes/main.c — the sine-table cases of the firmware's unit tests (test_fixed.c,
 * test_cam_path.c) at one table size, FW_SIN_TABLE_BITS as compiled (tests/firmware/sin_sizes.sh
 * builds it at 6, 8 and 10): the error bound and the entries of that size's table, and the camera
 * path's own sine unchanged by it. Prints "N passed, N failed".
 */
#include <stdarg.h>
#include <stdio.h>

#include "app/cam_path_sin.h"
#include "math/fixed.h"
#include "unit.h"

static int failures;

void unit_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;

    printf("FAIL %s:%d: ", file, line);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    failures++;
}

/* Angles where this size's fx_sin differs from the 256-entry function (the path's): 0 exactly at
 * the default size, many at the others — the knob changes the firmware's sine, not the path's. */
static void test_size_changes_fx_sin_only(void)
{
    uint32_t differ = 0;

    for (uint32_t a = 0; a < FX_TURN; a++) {
        differ += cam_path_sin(a) != fx_sin((fx_angle)a);
    }
    printf("FW_SIN_TABLE_BITS=%d: %u entries, error bound %.3g, %u of 65536 angles differ from the "
           "256-entry sine\n", FW_SIN_TABLE_BITS, FX_SIN_ENTRIES, FX_SIN_ERR_BOUND, differ);
    if ((FW_SIN_TABLE_BITS == 8) != (differ == 0u)) {
        unit_fail(__FILE__, __LINE__, "%u angles differ at FW_SIN_TABLE_BITS=%d", differ,
                  FW_SIN_TABLE_BITS);
    }
}

int main(void)
{
    void (*cases[])(void) = {test_fx_sin_cos_exact_points, test_fx_sin_cos_vs_libm,
                             test_fx_sin_table_entries, test_fx_angle_wrap,
                             test_cam_path_sin_entries, test_cam_path_sin_is_fx_sin,
                             test_size_changes_fx_sin_only};
    unsigned failed = 0;
    const unsigned n = sizeof cases / sizeof cases[0];

    for (unsigned i = 0; i < n; i++) {
        const int before = failures;

        fx_overflow_clear();
        cases[i]();
        failed += failures != before;
    }
    printf("%u passed, %u failed\n", n - failed, failed);
    return failed != 0u;
}
