// div_tb: gpu_div against exact integer division — sat32(trunc(n / d)) for n of N_W = 51 bits and
// d of D_W = 35 bits signed (the depth set-up's operands), on the boundaries of saturation and of
// the operand ranges and on random operands of every magnitude; also the latency (valid STEPS + 1
// clocks after start) and a start that abandons a division in progress.
//     div_tb [RANDOM_COUNT]     (built by tests/rtl/div.sh)
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "Vgpu_div.h"
#include "verilated.h"

typedef __int128 i128;

static const int N_W = 51, D_W = 35;
static const int64_t N_MIN = -(int64_t(1) << (N_W - 1)), N_MAX = (int64_t(1) << (N_W - 1)) - 1;
static const int64_t D_MIN = -(int64_t(1) << (D_W - 1)), D_MAX = (int64_t(1) << (D_W - 1)) - 1;

static int32_t reference(int64_t n, int64_t d)
{
    i128 q = i128(n) / i128(d);  // C++ truncates toward zero
    if (q > INT32_MAX) return INT32_MAX;
    if (q < INT32_MIN) return INT32_MIN;
    return int32_t(q);
}

static Vgpu_div *dut;
static uint64_t failures = 0, checked = 0;
static int latency = -1;

static void tick()
{
    dut->clk = 0;
    dut->eval();
    dut->clk = 1;
    dut->eval();
}

static void set_operands(int64_t n, int64_t d)
{
    dut->dividend = uint64_t(n) & ((uint64_t(1) << N_W) - 1);
    dut->divisor = uint64_t(d) & ((uint64_t(1) << D_W) - 1);
}

static void check(int64_t n, int64_t d)
{
    set_operands(n, d);
    dut->start = 1;
    tick();
    dut->start = 0;
    int clocks = 1;
    while (!dut->valid) {
        tick();
        if (++clocks > 100) {
            std::printf("div_tb: no valid for n=%lld d=%lld\n", (long long)n, (long long)d);
            std::exit(1);
        }
    }
    if (latency < 0) latency = clocks;
    if (clocks != latency) {
        std::printf("div_tb: latency %d, expected %d\n", clocks, latency);
        failures++;
    }
    const int32_t got = int32_t(dut->quotient), want = reference(n, d);
    checked++;
    if (got != want && failures++ < 10) {
        std::printf("div_tb: %lld / %lld: got %d, want %d\n", (long long)n, (long long)d, got, want);
    }
    tick();  // valid holds until the next start
    if (!dut->valid || int32_t(dut->quotient) != want) {
        std::printf("div_tb: the quotient did not hold\n");
        failures++;
    }
}

int main(int argc, char **argv)
{
    const long count = argc > 1 ? std::atol(argv[1]) : 200000;
    dut = new Vgpu_div;
    dut->rst = 1;
    dut->start = 0;
    tick();
    dut->rst = 0;
    tick();

    // Boundaries: extreme operands, and quotients at and around +-2^31 (where saturation starts).
    const int64_t ds[] = {1, -1, 2, -2, 3, 7, -7, 65536, 12345679, D_MAX, D_MIN, D_MAX - 1, D_MIN + 1,
                          int64_t(1) << 19, (int64_t(1) << 19) + 1, (int64_t(1) << 20) - 1};
    for (int64_t d : ds) {
        const int64_t ns[] = {0, 1, -1, N_MAX, N_MIN, N_MAX - 1, N_MIN + 1, d, -d, d - 1, 1 - d};
        for (int64_t n : ns) check(n, d);
        for (int64_t k = -3; k <= 3; k++) {
            const i128 edges[] = {i128(d) << 31, -(i128(d) << 31), (i128(d) << 31) - d, -((i128(d) << 31) - d),
                                  (i128(d) << 31) + d, -((i128(d) << 31) + d)};
            for (i128 e : edges) {
                const i128 n = e + k;
                if (n >= N_MIN && n <= N_MAX) check(int64_t(n), d);
            }
        }
    }
    // A start while busy abandons the division in progress.
    set_operands(N_MAX, 3);
    dut->start = 1;
    tick();
    dut->start = 0;
    for (int i = 0; i < 5; i++) tick();
    check(-1000000007, 13);

    // Random operands of random magnitudes (so small and large quotients are both common).
    std::mt19937_64 rng(12345);
    for (long i = 0; i < count; i++) {
        const int nb = int(rng() % N_W), db = int(rng() % D_W);
        int64_t n = int64_t(rng() & ((uint64_t(1) << nb) - 1 + (uint64_t(1) << nb)));  // < 2^(nb+1)
        int64_t d = int64_t(rng() & ((uint64_t(1) << db) - 1 + (uint64_t(1) << db)));
        n = std::min<int64_t>(n, N_MAX);
        d = std::min<int64_t>(d, D_MAX);
        if (rng() & 1) n = -n;
        if (rng() & 1) d = -d;
        if (d == 0) d = 1;
        check(n, d);
    }
    delete dut;
    std::printf("div_tb: %llu divisions, latency %d clocks, %llu wrong\n", (unsigned long long)checked, latency,
                (unsigned long long)failures);
    return failures == 0 ? 0 : 1;
}
