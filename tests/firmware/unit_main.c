/*
 * unit_main.c — runs every case listed in unit.h and prints "N passed, N failed".
 */
#include <stdarg.h>
#include <stdio.h>

#include "math/fixed.h"
#include "unit.h"

static int unit_case_failures;
static const char *unit_case_name;

void unit_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;

    if (unit_case_failures < 5) {  /* a broken case should not flood the log */
        printf("FAIL %s: %s:%d: ", unit_case_name, file, line);
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
    }
    unit_case_failures++;
}

int main(void)
{
    struct {
        const char *name;
        void (*fn)(void);
    } cases[] = {
#define UNIT_ENTRY(name) {#name, name},
        UNIT_TESTS(UNIT_ENTRY)
#undef UNIT_ENTRY
    };
    unsigned passed = 0;
    unsigned failed = 0;

    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        unit_case_name = cases[i].name;
        unit_case_failures = 0;
        unit_srand(0x9E3779B9u + i);
        fx_overflow_clear();
        cases[i].fn();
        if (unit_case_failures == 0) {
            passed++;
        } else {
            failed++;
        }
    }
    printf("%u passed, %u failed\n", passed, failed);
    return failed == 0u ? 0 : 1;
}
