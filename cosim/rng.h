// rng: the seeded generator of the harness's random tests (`gpusim random`, `gpusim list-roundtrip`):
// splitmix64, small and the same on every host, so a seed names the same run everywhere.
#ifndef RNG_H
#define RNG_H

#include <cstdint>

struct Rng {
    uint64_t state;

    uint64_t next()
    {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }  // 0 .. n-1
    int32_t range(int32_t lo, int32_t hi)  // lo .. hi, both included
    {
        return lo + static_cast<int32_t>(below(static_cast<uint32_t>(hi - lo + 1)));
    }
    bool chance(uint32_t percent) { return below(100) < percent; }
};

#endif
