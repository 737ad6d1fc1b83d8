/*
 * test_memset.c — the rv32 platforms' memset (bsp/rv32/memset.c), built here under another name,
 * against the host C library's: every start alignment and length up to 80 bytes, some longer,
 * every fill byte's low 8 bits (the int is converted to unsigned char), the bytes around the range
 * untouched and the destination returned.
 */
#include <string.h>

#include "unit.h"

#define BSP_MEMSET_NAME rv32_memset_under_test
#include "rv32/memset.c"

void test_rv32_memset(void)
{
    static unsigned char got[600];
    static unsigned char want[600];
    static const size_t long_lengths[] = {127, 128, 129, 255, 256, 257, 511};
    static const int fills[] = {0, 0x5A, 0xFF, 0x1A5, -1};

    for (size_t f = 0; f < sizeof fills / sizeof fills[0]; f++) {
        for (size_t start = 0; start < 8; start++) {
            for (size_t len = 0; len <= 80 + sizeof long_lengths / sizeof long_lengths[0]; len++) {
                const size_t n = len <= 80 ? len : long_lengths[len - 81];

                for (size_t i = 0; i < sizeof got; i++) {
                    got[i] = want[i] = (unsigned char)(i * 7u + 3u);
                }
                CHECK(rv32_memset_under_test(got + start, fills[f], n) == got + start);
                memset(want + start, fills[f], n);
                CHECK(memcmp(got, want, sizeof got) == 0);
            }
        }
    }
}
