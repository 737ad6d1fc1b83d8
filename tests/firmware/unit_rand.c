/*
 * unit_rand.c — the unit tests' deterministic pseudo-random numbers (unit.h: xorshift32), one
 * definition for every runner (unit_main.c, sin_sizes/main.c).
 */
#include "unit.h"

static uint32_t unit_rng = 0x12345678u;

uint32_t unit_rand(void)
{
    unit_rng ^= unit_rng << 13;
    unit_rng ^= unit_rng >> 17;
    unit_rng ^= unit_rng << 5;
    return unit_rng;
}

void unit_srand(uint32_t seed)
{
    unit_rng = (seed != 0u) ? seed : 1u;
}
