/*
 * memtest_test.c — the SDRAM memory test (bsp/soc/sdram/memtest.c) against a fake memory with
 * injected faults, on the host.
 *
 *   memtest_test [-v]      -v: a line per case, with the line memtest_format() made for it
 *
 * The MEMTEST_* access macros go through fake_read32() and friends: 1 MiB at 0x40000000 (32 MiB
 * for the cost case), and one fault at a time between the CPU's address and the cells. A good
 * memory must pass every test; each fault must be caught by the test meant for it, at the first
 * failing address the algorithm implies (worked out in each case's comment), with the address
 * bit where the address test can tell. The faults:
 *
 *   data bus      a line stuck at 0, stuck at 1, two lines shorted (wired AND, wired OR)
 *   address bus   a line stuck low (the word ignores it: aliasing) or high, two lines shorted
 *   byte lanes    a lane whose sub-word stores are dropped, two lanes swapped, an enable stuck on,
 *                 half-word stores with their bytes swapped.
 *                 Word stores enable every byte, so these break sub-word stores only (a lane
 *                 broken for word stores too is a data-bus fault, and is caught as one)
 *   cells         one bit of one word stuck, deep in the range; a word that loses its value once
 *                 N further accesses have passed since it was written (a crude refresh loss)
 *
 * plus arguments the tests must refuse without touching memory, memtest_format()'s line for every
 * kind of result, and its truncation into every buffer size. Exit 0 and a last line
 * `memtest_test: ok N cases` when every case passed.
 */
#include <inttypes.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the fake memory ---- */

#define FAKE_BASE   ((uintptr_t)0x40000000u)
#define FAKE_BYTES  (1024u * 1024u)
#define LARGE_BYTES (32u * 1024u * 1024u)  /* the board's SDRAM, for the quick test's cost */

/* One fault at a time (fault_clear() between cases). Address faults act on the byte offset
 * within the fake memory, data faults on the 32-bit bus in both directions. */
struct fault {
    uint32_t data_stuck0;       /* data lines stuck at 0 (mask) */
    uint32_t data_stuck1;       /* data lines stuck at 1 (mask) */
    int data_short_a;           /* two data lines shorted, -1: none */
    int data_short_b;
    bool data_short_or;         /* the short is a wired OR (else a wired AND) */
    uint32_t addr_stuck_low;    /* address lines stuck at 0 (mask of byte-offset bits) */
    uint32_t addr_stuck_high;   /* address lines stuck at 1 */
    int addr_short_a;           /* two address lines shorted, -1: none */
    int addr_short_b;
    bool addr_short_or;
    int lane_dropped;           /* sub-word stores to this byte lane are lost, -1: none */
    int lane_swap_a;            /* sub-word stores to lane a land in lane b and back, -1: none */
    int lane_swap_b;
    int lane_stuck_on;          /* this lane's enable is on for every sub-word store, -1: none */
    bool half_swapped;          /* half-word stores put their two bytes in each other's lane */
    long cell_offset;           /* a word with bits stuck, -1: none */
    uint32_t cell_mask;         /* its stuck bits */
    uint32_t cell_value;        /* and their value */
    long decay_offset;          /* a word that reads 0 once decay_after accesses have passed since
                                   its last write, -1: none */
    uint64_t decay_after;
};

static uint32_t *fake_mem;
static size_t fake_bytes = FAKE_BYTES;
static struct fault fault;
static uint64_t fake_accesses;
static uint64_t decay_written_at;

static void fault_clear(void)
{
    memset(&fault, 0, sizeof fault);
    fault.data_short_a = fault.data_short_b = -1;
    fault.addr_short_a = fault.addr_short_b = -1;
    fault.lane_dropped = fault.lane_swap_a = fault.lane_swap_b = fault.lane_stuck_on = -1;
    fault.cell_offset = fault.decay_offset = -1;
}

/* A fresh memory of `bytes` with every word garbage (a power-up state, not zeros, so that a
 * store that goes nowhere is not read back as a lucky 0). */
static void fake_reset(size_t bytes)
{
    uint32_t x = 0x9e3779b9u;

    fake_bytes = bytes;
    for (size_t i = 0; i < bytes / 4u; i++) {
        x = x * 1664525u + 1013904223u;
        fake_mem[i] = x;
    }
    fake_accesses = 0;
    decay_written_at = 0;
}

/* The word index a CPU address reaches through the address faults. An access outside the fake
 * memory is a bug of the test under test (no fault moves a CPU address): stop there. */
static size_t fake_word(uintptr_t addr)
{
    size_t offset;

    if (addr < FAKE_BASE || addr - FAKE_BASE >= fake_bytes) {
        fprintf(stderr, "memtest_test: access at 0x%" PRIxPTR " outside the fake memory\n", addr);
        exit(2);
    }
    offset = (size_t)(addr - FAKE_BASE) & ~(size_t)3u;
    offset &= ~(size_t)fault.addr_stuck_low;
    offset |= fault.addr_stuck_high;
    if (fault.addr_short_a >= 0) {
        const size_t a = (offset >> fault.addr_short_a) & 1u;
        const size_t b = (offset >> fault.addr_short_b) & 1u;
        const size_t both = fault.addr_short_or ? (a | b) : (a & b);

        offset &= ~(((size_t)1u << fault.addr_short_a) | ((size_t)1u << fault.addr_short_b));
        offset |= (both << fault.addr_short_a) | (both << fault.addr_short_b);
    }
    return (offset & (fake_bytes - 1u)) / 4u;
}

/* A word as the data bus carries it. */
static uint32_t fake_data_bus(uint32_t v)
{
    v &= ~fault.data_stuck0;
    v |= fault.data_stuck1;
    if (fault.data_short_a >= 0) {
        const uint32_t a = (v >> fault.data_short_a) & 1u;
        const uint32_t b = (v >> fault.data_short_b) & 1u;
        const uint32_t both = fault.data_short_or ? (a | b) : (a & b);

        v &= ~((1u << fault.data_short_a) | (1u << fault.data_short_b));
        v |= (both << fault.data_short_a) | (both << fault.data_short_b);
    }
    return v;
}

/* Stores the word as the cells keep it. */
static void fake_store(size_t word, uint32_t v)
{
    if (fault.cell_offset >= 0 && word == (size_t)fault.cell_offset / 4u) {
        v = (v & ~fault.cell_mask) | (fault.cell_value & fault.cell_mask);
    }
    if (fault.decay_offset >= 0 && word == (size_t)fault.decay_offset / 4u) {
        decay_written_at = fake_accesses;
    }
    fake_mem[word] = v;
}

static uint32_t fake_read32(uintptr_t addr)
{
    const size_t word = fake_word(addr);

    fake_accesses++;
    if (fault.decay_offset >= 0 && word == (size_t)fault.decay_offset / 4u &&
        fake_accesses - decay_written_at > fault.decay_after) {
        fake_mem[word] = 0u;  /* the charge is gone */
    }
    return fake_data_bus(fake_mem[word]);
}

static void fake_write32(uintptr_t addr, uint32_t value)
{
    fake_accesses++;
    fake_store(fake_word(addr), fake_data_bus(value));
}

/* A store of `width` bytes: the value in its lanes, merged into the word through the byte
 * enables as the lane faults leave them. */
static void fake_write_sub(uintptr_t addr, uint32_t value, uint32_t width)
{
    const size_t word = fake_word(addr);
    const uint32_t first = (uint32_t)(addr & 3u);
    uint32_t merged = fake_mem[word];

    fake_accesses++;
    if (fault.half_swapped && width == 2u) {
        value = ((value & 0xffu) << 8) | ((value >> 8) & 0xffu);
    }
    for (uint32_t i = 0; i < width; i++) {
        const uint32_t byte = (value >> (8u * i)) & 0xffu;
        uint32_t lane = first + i;

        if ((int)lane == fault.lane_dropped) {
            continue;
        }
        if ((int)lane == fault.lane_swap_a) {
            lane = (uint32_t)fault.lane_swap_b;
        } else if ((int)lane == fault.lane_swap_b) {
            lane = (uint32_t)fault.lane_swap_a;
        }
        merged = (merged & ~(0xffu << (8u * lane))) | (byte << (8u * lane));
        /* An enable stuck on writes its lane with what the bus carries there: the CPU repeats a
         * byte store's byte in every lane (VexRiscv does), so the same byte. */
        if (fault.lane_stuck_on >= 0 && (uint32_t)fault.lane_stuck_on != lane && width == 1u) {
            merged = (merged & ~(0xffu << (8u * (uint32_t)fault.lane_stuck_on))) |
                     (byte << (8u * (uint32_t)fault.lane_stuck_on));
        }
    }
    fake_store(word, fake_data_bus(merged));
}

static void fake_write16(uintptr_t addr, uint16_t value)
{
    fake_write_sub(addr, value, 2u);
}

static void fake_write8(uintptr_t addr, uint8_t value)
{
    fake_write_sub(addr, value, 1u);
}

#define MEMTEST_READ32(addr)         fake_read32(addr)
#define MEMTEST_WRITE32(addr, value) fake_write32((addr), (value))
#define MEMTEST_WRITE16(addr, value) fake_write16((addr), (value))
#define MEMTEST_WRITE8(addr, value)  fake_write8((addr), (value))
#include "memtest.c"

/* ---- cases ---- */

static bool verbose;
static unsigned cases;
static unsigned failures;
static const char *case_name;
static bool case_failed;

static void begin(const char *name)
{
    case_name = name;
    case_failed = false;
    cases++;
}

static void complain(int line, const char *fmt, ...)
{
    va_list ap;

    if (!case_failed) {
        failures++;
    }
    case_failed = true;
    fprintf(stderr, "FAILED %s (line %d): ", case_name, line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

#define CHECK(cond)                                  \
    do {                                             \
        if (!(cond)) {                               \
            complain(__LINE__, "%s", #cond);         \
        }                                            \
    } while (0)

#define CHECK_U(got, want)                                                                   \
    do {                                                                                     \
        const uint64_t got_ = (uint64_t)(got), want_ = (uint64_t)(want);                     \
        if (got_ != want_) {                                                                 \
            complain(__LINE__, "%s is 0x%" PRIx64 ", expected 0x%" PRIx64, #got, got_, want_); \
        }                                                                                    \
    } while (0)

static void end(const struct memtest_result *r)
{
    char line[MEMTEST_FORMAT_SIZE];

    memtest_format(r, line, sizeof line);
    if (verbose) {
        printf("%-4s %-58s %s\n", case_failed ? "FAIL" : "ok", case_name, line);
    }
}

/* What a case expects of a result: ok, or the failing test, address and words. */
struct expect {
    const char *test;      /* the failing test's name, NULL: ok */
    uintptr_t address;
    uint32_t expected;
    uint32_t actual;
    int address_bit;
    int other_bit;
    uint8_t store_bytes;
};

static void check_result(int line, const struct memtest_result *r, struct expect e)
{
    if (r->refused != NULL) {
        complain(line, "refused: %s", r->refused);
        return;
    }
    if (e.test == NULL) {
        if (!r->ok) {
            char text[MEMTEST_FORMAT_SIZE];

            memtest_format(r, text, sizeof text);
            complain(line, "expected ok, got: %s", text);
        }
        return;
    }
    if (r->ok) {
        complain(line, "expected %s to fail at 0x%" PRIxPTR ", got ok", e.test, e.address);
        return;
    }
    if (strcmp(r->test, e.test) != 0) {
        complain(line, "failed in %s, expected %s", r->test, e.test);
    }
    if (r->address != e.address) {
        complain(line, "failed at 0x%" PRIxPTR ", expected 0x%" PRIxPTR, r->address, e.address);
    }
    if (r->expected != e.expected || r->actual != e.actual) {
        complain(line, "wrote 0x%08" PRIx32 " read 0x%08" PRIx32 ", expected wrote 0x%08" PRIx32 " read 0x%08" PRIx32,
                 r->expected, r->actual, e.expected, e.actual);
    }
    if (r->address_bit != e.address_bit || r->other_bit != e.other_bit) {
        complain(line, "address bits %d, %d, expected %d, %d", r->address_bit, r->other_bit, e.address_bit,
                 e.other_bit);
    }
    if (r->store_bytes != e.store_bytes) {
        complain(line, "store width %u, expected %u", r->store_bytes, e.store_bytes);
    }
}

#define OK ((struct expect){ .test = NULL, .address_bit = -1, .other_bit = -1 })
#define FAILS(name, addr, wrote, read) \
    ((struct expect){ .test = (name), .address = (addr), .expected = (wrote), .actual = (read), \
                      .address_bit = -1, .other_bit = -1 })

#define SEED 0x1234u

enum which { QUICK, FULL, DATA_BUS, ADDRESS_BUS, BYTE_LANES, WALKING_BITS, RANDOM };

static const char *const which_name[] = {
    "quick", "full", "data bus", "address bus", "byte lanes", "walking bits", "random fill",
};

static struct memtest_result run(enum which w, uintptr_t base, size_t bytes)
{
    switch (w) {
    case QUICK:
        return memtest_quick(base, bytes, SEED);
    case FULL:
        return memtest_full(base, bytes, SEED);
    case DATA_BUS:
        return memtest_data_bus(base, bytes);
    case ADDRESS_BUS:
        return memtest_address_bus(base, bytes);
    case BYTE_LANES:
        return memtest_byte_lanes(base, bytes);
    case WALKING_BITS:
        return memtest_walking_bits(base, bytes);
    case RANDOM:
        return memtest_random(base, bytes, SEED);
    }
    abort();
}

/* One case: the fault already set, a fresh 1 MiB memory, one test, its expected result. */
static struct memtest_result fault_case(int line, const char *fault_name, enum which w, struct expect e)
{
    static char name[128];
    struct memtest_result r;

    snprintf(name, sizeof name, "%s: %s", fault_name, which_name[w]);
    begin(name);
    fake_reset(FAKE_BYTES);
    r = run(w, FAKE_BASE, FAKE_BYTES);
    check_result(line, &r, e);
    end(&r);
    return r;
}

/* The random fill's word at word index k of a pass (pass 1 complemented), as memtest.c makes it. */
static uint32_t random_word(uint32_t seed, size_t k, uint32_t pass)
{
    uint32_t state = memtest_random_start(seed);
    uint32_t x = 0;

    for (size_t i = 0; i <= k; i++) {
        x = memtest_xorshift32(&state);
    }
    return pass == 0u ? x : ~x;
}

/* Accesses each test makes, from its loops (memtest.h quotes them). */
static uint64_t cost_address_bus(size_t bytes)
{
    const uint64_t k = (uint64_t)memtest_bit_of(bytes) - 2u;

    return k * k + 4u * k + 2u;
}

static uint64_t cost_quick(size_t bytes)
{
    const size_t prefix = bytes < MEMTEST_QUICK_RANDOM_BYTES ? bytes : MEMTEST_QUICK_RANDOM_BYTES;

    return 128u + cost_address_bus(bytes) + 72u + (uint64_t)prefix;
}

static uint64_t cost_full(size_t bytes)
{
    return 128u + cost_address_bus(bytes) + 72u + (uint64_t)bytes + 16u * (uint64_t)bytes;
}

static void good_memory(void)
{
    struct memtest_result r;

    for (enum which w = QUICK; w <= RANDOM; w++) {
        fault_clear();
        r = fault_case(__LINE__, "good memory", w, OK);
        CHECK_U(r.tests, w == QUICK ? 4u : w == FULL ? 5u : 1u);
        if (w == QUICK) {
            CHECK_U(r.random_bytes, MEMTEST_QUICK_RANDOM_BYTES);
            CHECK_U(fake_accesses, cost_quick(FAKE_BYTES));
        } else if (w == FULL) {
            CHECK_U(r.random_bytes, FAKE_BYTES);
            CHECK_U(fake_accesses, cost_full(FAKE_BYTES));
        }
    }

    /* The board's 32 MiB: the quick test's cost is what memtest.h says, well under a second at
     * 50 MHz and 10 clocks an access. */
    begin("good memory, 32 MiB: quick, 262,967 accesses");
    fake_reset(LARGE_BYTES);
    r = memtest_quick(FAKE_BASE, LARGE_BYTES, SEED);
    check_result(__LINE__, &r, OK);
    CHECK_U(fake_accesses, cost_quick(LARGE_BYTES));
    CHECK_U(fake_accesses, 262967u);
    CHECK(fake_accesses * 10u < 50000000u / 10u);  /* under 0.1 s */
    CHECK_U(cost_full(LARGE_BYTES), 570426167u);
    end(&r);

    /* A range smaller than the quick test's bound: the random fill covers all of it. */
    begin("good memory, 64 KiB: quick fills it all");
    fake_reset(FAKE_BYTES);
    r = memtest_quick(FAKE_BASE, 64u * 1024u, SEED);
    check_result(__LINE__, &r, OK);
    CHECK_U(r.random_bytes, 64u * 1024u);
    end(&r);

    /* Seed 0 is a seed like any other (xorshift's forbidden state is not reached). */
    begin("good memory: random fill, seed 0");
    fake_reset(FAKE_BYTES);
    r = memtest_random(FAKE_BASE, FAKE_BYTES, 0u);
    check_result(__LINE__, &r, OK);
    CHECK(fake_mem[0] != 0u && fake_mem[1] != fake_mem[0]);
    end(&r);

    /* The walking bits and the random fill need no power of two. */
    begin("good memory, 768 KiB: walking bits and random fill");
    fake_reset(FAKE_BYTES);
    r = memtest_walking_bits(FAKE_BASE, 768u * 1024u);
    check_result(__LINE__, &r, OK);
    r = memtest_random(FAKE_BASE + 4u, 768u * 1024u, SEED);
    check_result(__LINE__, &r, OK);
    end(&r);
}

/* Data faults: the data-bus test finds each at the first word, on the first pattern that shows
 * it; quick and full stop there too (it runs first). */
static void data_faults(void)
{
    static const enum which runners[] = { DATA_BUS, QUICK, FULL };

    for (unsigned i = 0; i < 3u; i++) {
        /* Stuck at 0: the walking 1 reaches bit 5 and is lost. */
        fault_clear();
        fault.data_stuck0 = 1u << 5;
        fault_case(__LINE__, "data bit 5 stuck at 0", runners[i], FAILS("data bus", FAKE_BASE, 0x20u, 0u));

        /* Stuck at 1: the first pattern already shows it. */
        fault_clear();
        fault.data_stuck1 = 1u << 5;
        fault_case(__LINE__, "data bit 5 stuck at 1", runners[i], FAILS("data bus", FAKE_BASE, 0x1u, 0x21u));

        /* The top line: the last walking 1. */
        fault_clear();
        fault.data_stuck0 = 1u << 31;
        fault_case(__LINE__, "data bit 31 stuck at 0", runners[i],
                   FAILS("data bus", FAKE_BASE, 0x80000000u, 0u));

        /* Shorted, wired AND: a 1 on bit 9 alone is pulled down by bit 10. */
        fault_clear();
        fault.data_short_a = 9;
        fault.data_short_b = 10;
        fault_case(__LINE__, "data bits 9 and 10 shorted (AND)", runners[i],
                   FAILS("data bus", FAKE_BASE, 0x200u, 0u));

        /* Shorted, wired OR: bit 9 drags bit 10 up with it. */
        fault_clear();
        fault.data_short_a = 9;
        fault.data_short_b = 10;
        fault.data_short_or = true;
        fault_case(__LINE__, "data bits 9 and 10 shorted (OR)", runners[i],
                   FAILS("data bus", FAKE_BASE, 0x200u, 0x600u));
    }
}

static struct expect address_fails(uintptr_t address, uint32_t read, int bit, int other)
{
    struct expect e = FAILS("address bus", address, MEMTEST_PATTERN, read);

    e.address_bit = bit;
    e.other_bit = other;
    return e;
}

/* Address faults: the data-bus test passes (it uses one word, wherever it lands), the address
 * test finds them. */
static void address_faults(void)
{
    static const enum which runners[] = { ADDRESS_BUS, QUICK, FULL };
    struct memtest_result r;

    for (unsigned i = 0; i < 3u; i++) {
        /* A12 stuck low: offset 0x1000 is offset 0's word, so after the antipattern at 0 it
         * reads the antipattern; bits 2..11 pass before it. */
        fault_clear();
        fault.addr_stuck_low = 1u << 12;
        fault_case(__LINE__, "address bit 12 stuck low", runners[i],
                   address_fails(FAKE_BASE + 0x1000u, MEMTEST_ANTIPATTERN, 12, -1));

        /* A12 stuck high: offset 0 is offset 0x1000's word — the same report: software sees the
         * two words merge, not which way. */
        fault_clear();
        fault.addr_stuck_high = 1u << 12;
        fault_case(__LINE__, "address bit 12 stuck high", runners[i],
                   address_fails(FAKE_BASE + 0x1000u, MEMTEST_ANTIPATTERN, 12, -1));

        /* The lowest and the highest address lines of the range. */
        fault_clear();
        fault.addr_stuck_low = 1u << 2;
        fault_case(__LINE__, "address bit 2 stuck low", runners[i],
                   address_fails(FAKE_BASE + 0x4u, MEMTEST_ANTIPATTERN, 2, -1));
        fault_clear();
        fault.addr_stuck_high = 1u << 19;
        fault_case(__LINE__, "address bit 19 stuck high", runners[i],
                   address_fails(FAKE_BASE + 0x80000u, MEMTEST_ANTIPATTERN, 19, -1));

        /* A10 and A14 shorted, wired OR: offsets 0x400 and 0x4000 both reach 0x4400, offset 0
         * stays itself, so the first pass holds; the antipattern at 0x400 then shows at 0x4000. */
        fault_clear();
        fault.addr_short_a = 10;
        fault.addr_short_b = 14;
        fault.addr_short_or = true;
        r = fault_case(__LINE__, "address bits 10 and 14 shorted (OR)", runners[i],
                       address_fails(FAKE_BASE + 0x4000u, MEMTEST_ANTIPATTERN, 10, 14));
        CHECK(r.other_bit == 14);

        /* Wired AND: offset 0x400 alone becomes 0, which looks like a line stuck low. */
        fault_clear();
        fault.addr_short_a = 10;
        fault.addr_short_b = 14;
        fault_case(__LINE__, "address bits 10 and 14 shorted (AND)", runners[i],
                   address_fails(FAKE_BASE + 0x400u, MEMTEST_ANTIPATTERN, 10, -1));
    }

    /* The random fill alone sees aliasing too: the write to 0x1000 (word 1024) overwrites word 0,
     * which is read back first. */
    fault_clear();
    fault.addr_stuck_low = 1u << 12;
    fault_case(__LINE__, "address bit 12 stuck low", RANDOM,
               FAILS("random fill", FAKE_BASE, random_word(SEED, 0, 0), random_word(SEED, 1024, 0)));
}

static struct expect lanes_fail(uintptr_t address, uint32_t expected, uint32_t read, uint8_t width)
{
    struct expect e = FAILS("byte lanes", address, expected, read);

    e.store_bytes = width;
    return e;
}

/* Byte-lane faults break sub-word stores only: the bus tests and the word-wide cell tests pass,
 * the byte-lane test finds them on its first pass (background 0, byte 0xa5). */
static void lane_faults(void)
{
    static const enum which runners[] = { BYTE_LANES, QUICK, FULL };

    for (unsigned i = 0; i < 3u; i++) {
        /* Lane 2's byte store is lost: lanes 0 and 1 pass, the word stays 0. */
        fault_clear();
        fault.lane_dropped = 2;
        fault_case(__LINE__, "byte lane 2 stores dropped", runners[i],
                   lanes_fail(FAKE_BASE + 2u, 0x00a50000u, 0u, 1u));

        /* Lanes 0 and 1 swapped: the first byte store lands in lane 1. */
        fault_clear();
        fault.lane_swap_a = 0;
        fault.lane_swap_b = 1;
        fault_case(__LINE__, "byte lanes 0 and 1 swapped", runners[i],
                   lanes_fail(FAKE_BASE, 0x000000a5u, 0x0000a500u, 1u));

        /* Lane 3's enable stuck on: the byte store to lane 0 writes lane 3 too. */
        fault_clear();
        fault.lane_stuck_on = 3;
        fault_case(__LINE__, "byte lane 3 enable stuck on", runners[i],
                   lanes_fail(FAKE_BASE, 0x000000a5u, 0xa50000a5u, 1u));
    }

    /* Swapped lanes 2 and 3 are in the same half-word: the byte stores find them first (lane 2,
     * the first of the two); a half-word store would show them too, as its bytes trade places. */
    fault_clear();
    fault.lane_swap_a = 2;
    fault.lane_swap_b = 3;
    fault_case(__LINE__, "byte lanes 2 and 3 swapped", BYTE_LANES,
               lanes_fail(FAKE_BASE + 2u, 0x00a50000u, 0xa5000000u, 1u));

    /* Half-word stores with their bytes swapped: every byte store passes, the first half-word
     * store (0xc33c into the low half of 0) reads back 0x3cc3. */
    for (unsigned i = 0; i < 3u; i++) {
        fault_clear();
        fault.half_swapped = true;
        fault_case(__LINE__, "half-word stores byte-swapped", runners[i],
                   lanes_fail(FAKE_BASE, 0x0000c33cu, 0x00003cc3u, 2u));
    }

    /* Word stores cannot see them. */
    fault_clear();
    fault.lane_dropped = 2;
    fault_case(__LINE__, "byte lane 2 stores dropped", WALKING_BITS, OK);
    fault_clear();
    fault.lane_dropped = 2;
    fault_case(__LINE__, "byte lane 2 stores dropped", RANDOM, OK);
}

/* Cell faults: found by the cell tests at the cell, by the quick test only within its prefix. */
static void cell_faults(void)
{
    const size_t deep = 0xc3a5cu;    /* beyond the quick test's 256 KiB, no power of two */
    const size_t inside = 0x2a5a4u;  /* within it */
    uint32_t x;
    struct memtest_result r;

    /* Bit 9 stuck at 1 deep in the range: the quick test passes — the documented limit — the full
     * test's random fill finds it at the cell, in the pass that writes a 0 to bit 9 there. */
    x = random_word(SEED, deep / 4u, 0);
    x = (x & 0x200u) == 0u ? x : ~x;  /* the pass's word with bit 9 clear */
    fault_clear();
    fault.cell_offset = (long)deep;
    fault.cell_mask = fault.cell_value = 0x200u;
    fault_case(__LINE__, "bit 9 stuck at 1 at 0xc3a5c", QUICK, OK);
    fault_case(__LINE__, "bit 9 stuck at 1 at 0xc3a5c", FULL, FAILS("random fill", FAKE_BASE + deep, x, x | 0x200u));
    fault_case(__LINE__, "bit 9 stuck at 1 at 0xc3a5c", RANDOM, FAILS("random fill", FAKE_BASE + deep, x, x | 0x200u));
    /* The walking bits alone: pass 0 puts bit (0x30e97 % 32) = 23 there. */
    fault_case(__LINE__, "bit 9 stuck at 1 at 0xc3a5c", WALKING_BITS,
               FAILS("walking bits", FAKE_BASE + deep, 1u << 23, (1u << 23) | 0x200u));

    /* The same within the quick test's prefix: the quick test finds it. */
    x = random_word(SEED, inside / 4u, 0);
    x = (x & 0x200u) == 0u ? x : ~x;
    fault_clear();
    fault.cell_offset = (long)inside;
    fault.cell_mask = fault.cell_value = 0x200u;
    fault_case(__LINE__, "bit 9 stuck at 1 at 0x2a5a4", QUICK, FAILS("random fill", FAKE_BASE + inside, x, x | 0x200u));
    fault_case(__LINE__, "bit 9 stuck at 1 at 0x2a5a4", FULL, FAILS("random fill", FAKE_BASE + inside, x, x | 0x200u));

    /* A bit stuck at exactly what the first pass writes there: only the complemented pass sees it. */
    x = random_word(SEED, inside / 4u, 0);
    fault_clear();
    fault.cell_offset = (long)inside;
    fault.cell_mask = 1u << 17;
    fault.cell_value = x;
    r = fault_case(__LINE__, "bit 17 stuck at the first pass's value", RANDOM,
                   FAILS("random fill", FAKE_BASE + inside, ~x, ~x ^ (1u << 17)));
    CHECK(r.expected == random_word(SEED, inside / 4u, 1));

    /* A word that reads 0 once 1,000 accesses have passed since its write: each word of the fill is
     * read back (words - 1) accesses after its write — 65,535 in the quick test's prefix. */
    x = random_word(SEED, inside / 4u, 0);
    fault_clear();
    fault.decay_offset = (long)inside;
    fault.decay_after = 1000u;
    fault_case(__LINE__, "0x2a5a4 decays after 1,000 accesses", QUICK, FAILS("random fill", FAKE_BASE + inside, x, 0u));
    fault_case(__LINE__, "0x2a5a4 decays after 1,000 accesses", FULL, FAILS("random fill", FAKE_BASE + inside, x, 0u));
    fault_case(__LINE__, "0x2a5a4 decays after 1,000 accesses", RANDOM, FAILS("random fill", FAKE_BASE + inside, x, 0u));

    /* After 100,000: longer than the quick test's fill takes (it cannot see it, as memtest.h
     * says), shorter than a pass over 1 MiB (262,143 accesses): the full test sees it. */
    fault_clear();
    fault.decay_offset = (long)inside;
    fault.decay_after = 100000u;
    fault_case(__LINE__, "0x2a5a4 decays after 100,000 accesses", QUICK, OK);
    fault_case(__LINE__, "0x2a5a4 decays after 100,000 accesses", FULL, FAILS("random fill", FAKE_BASE + inside, x, 0u));
}

/* Bad arguments: refused, naming the argument, before a single access. */
static void refusals(void)
{
    static const struct {
        enum which w;
        uintptr_t base;
        size_t bytes;
        const char *why;
    } bad[] = {
        { QUICK, FAKE_BASE + 2u, FAKE_BYTES, "base is not word aligned" },
        { RANDOM, FAKE_BASE + 1u, 64u, "base is not word aligned" },
        { FULL, FAKE_BASE, 0u, "bytes is zero" },
        { DATA_BUS, FAKE_BASE, 6u, "bytes is not a multiple of 4" },
        { QUICK, FAKE_BASE, 768u * 1024u, "bytes is not a power of two" },
        { ADDRESS_BUS, FAKE_BASE, 768u * 1024u, "bytes is not a power of two" },
        { FULL, FAKE_BASE, 768u * 1024u, "bytes is not a power of two" },
        { ADDRESS_BUS, FAKE_BASE + 0x40000u, 512u * 1024u, "base is not a multiple of bytes" },
        { WALKING_BITS, UINTPTR_MAX - 0xfffu, 0x2000u, "the range wraps past the end of the address space" },
        { BYTE_LANES, UINTPTR_MAX - 0x3u, 8u, "the range wraps past the end of the address space" },
    };

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        static char name[128];
        struct memtest_result r;

        snprintf(name, sizeof name, "refused: %s, %s", which_name[bad[i].w], bad[i].why);
        begin(name);
        fake_reset(FAKE_BYTES);
        r = run(bad[i].w, bad[i].base, bad[i].bytes);
        CHECK(!r.ok);
        CHECK(r.refused != NULL && strcmp(r.refused, bad[i].why) == 0);
        CHECK(strcmp(r.test, which_name[bad[i].w]) == 0);
        CHECK_U(r.base, bad[i].base);
        CHECK_U(r.bytes, bad[i].bytes);
        CHECK_U(fake_accesses, 0u);
        end(&r);
    }
}

/* memtest_format into buffers of every size up to the line's length + 2: never past size (the
 * bytes after it keep their canary), always NUL-terminated, always the line's prefix, and the
 * whole line's length returned each time. */
static void check_truncation(int line, const struct memtest_result *r, const char *want)
{
    const size_t len = strlen(want);
    char buf[MEMTEST_FORMAT_SIZE + 16u];

    CHECK_U(memtest_format(r, NULL, 0u), len);
    for (size_t size = 0; size <= len + 2u && size + 8u <= sizeof buf; size++) {
        size_t kept;

        memset(buf, '#', sizeof buf);
        if (memtest_format(r, buf, size) != len) {
            complain(line, "size %zu: wrong length returned", size);
        }
        for (size_t i = size; i < size + 8u; i++) {
            if (buf[i] != '#') {
                complain(line, "size %zu: byte %zu written", size, i);
                break;
            }
        }
        if (size == 0u) {
            continue;
        }
        kept = size - 1u < len ? size - 1u : len;
        if (buf[kept] != '\0' || memcmp(buf, want, kept) != 0) {
            complain(line, "size %zu: '%.*s' is not the line's prefix", size, (int)kept, buf);
        }
    }
}

static void format_case(int line, const char *name, const struct memtest_result *r, const char *want)
{
    char buf[MEMTEST_FORMAT_SIZE];
    size_t len;

    begin(name);
    len = memtest_format(r, buf, sizeof buf);
    if (strcmp(buf, want) != 0) {
        complain(line, "got '%s', expected '%s'", buf, want);
    }
    CHECK(len < MEMTEST_FORMAT_SIZE);
    check_truncation(line, r, want);
    end(r);
}

static void formats(void)
{
    struct memtest_result r;

    fault_clear();
    fake_reset(FAKE_BYTES);
    r = memtest_quick(FAKE_BASE, FAKE_BYTES, SEED);
    format_case(__LINE__, "format: quick ok", &r,
                "memtest: quick ok (1 MiB at 0x40000000, 4 tests, random fill over the first 256 KiB, seed 0x1234)");

    r = memtest_quick(FAKE_BASE, 64u * 1024u, 0xdeadbeefu);
    format_case(__LINE__, "format: quick ok, all filled", &r,
                "memtest: quick ok (64 KiB at 0x40000000, 4 tests, seed 0xdeadbeef)");

    /* The board's size, as the brief's line (no 32 MiB fill needed to format it). */
    r = memtest_start("full", FAKE_BASE, LARGE_BYTES, 0x1234u);
    r.tests = 5u;
    r.random_bytes = LARGE_BYTES;
    format_case(__LINE__, "format: full ok, 32 MiB", &r, "memtest: full ok (32 MiB at 0x40000000, 5 tests, seed 0x1234)");

    r = memtest_data_bus(FAKE_BASE, 12u);
    format_case(__LINE__, "format: one test ok, no seed", &r, "memtest: data bus ok (12 bytes at 0x40000000, 1 test)");

    fault.addr_stuck_low = 1u << 12;
    r = memtest_quick(FAKE_BASE, FAKE_BYTES, SEED);
    format_case(__LINE__, "format: address bit", &r,
                "memtest: address bus FAILED at 0x40001000: wrote 0xaaaaaaaa read 0x55555555 "
                "(address bit 12 stuck or shorted)");

    fault_clear();
    fault.addr_short_a = 10;
    fault.addr_short_b = 14;
    fault.addr_short_or = true;
    r = memtest_full(FAKE_BASE, FAKE_BYTES, SEED);
    format_case(__LINE__, "format: address bits shorted", &r,
                "memtest: address bus FAILED at 0x40004000: wrote 0xaaaaaaaa read 0x55555555 "
                "(address bits 10 and 14 shorted)");

    fault_clear();
    fault.data_stuck1 = 1u << 5;
    r = memtest_quick(FAKE_BASE, FAKE_BYTES, SEED);
    format_case(__LINE__, "format: data bus", &r, "memtest: data bus FAILED at 0x40000000: wrote 0x00000001 read 0x00000021");

    fault_clear();
    fault.lane_dropped = 2;
    r = memtest_quick(FAKE_BASE, FAKE_BYTES, SEED);
    format_case(__LINE__, "format: byte store", &r,
                "memtest: byte lanes FAILED at 0x40000002: expected 0x00a50000 read 0x00000000 (after a byte store)");

    r = memtest_start("byte lanes", FAKE_BASE, FAKE_BYTES, 0u);
    r.ok = false;
    r.address = FAKE_BASE + 0xffffcu + 2u;
    r.expected = 0x3cc3ffffu;
    r.actual = 0xc33cffffu;
    r.store_bytes = 2u;
    format_case(__LINE__, "format: half-word store", &r,
                "memtest: byte lanes FAILED at 0x400ffffe: expected 0x3cc3ffff read 0xc33cffff (after a half-word store)");

    fault_clear();
    fault.decay_offset = 0x2a5a4;
    fault.decay_after = 1000u;
    r = memtest_random(FAKE_BASE, FAKE_BYTES, SEED);
    {
        char want[MEMTEST_FORMAT_SIZE];

        snprintf(want, sizeof want, "memtest: random fill FAILED at 0x4002a5a4: wrote 0x%08" PRIx32 " read 0x00000000",
                 random_word(SEED, 0x2a5a4u / 4u, 0));
        format_case(__LINE__, "format: random fill", &r, want);
    }

    fault_clear();
    r = memtest_address_bus(FAKE_BASE, 0x300000u);
    format_case(__LINE__, "format: refused", &r,
                "memtest: address bus refused (base 0x40000000, bytes 0x00300000): bytes is not a power of two");

    /* The longest line there is: 64-bit addresses on the host, the longest reason. */
    r = memtest_walking_bits(UINTPTR_MAX - 0xfffu, 0x2000u);
    {
        char want[MEMTEST_FORMAT_SIZE];

        snprintf(want, sizeof want,
                 "memtest: walking bits refused (base 0x%0*" PRIxPTR ", bytes 0x00002000): "
                 "the range wraps past the end of the address space",
                 UINTPTR_MAX > 0xffffffffu ? 16 : 8, UINTPTR_MAX - 0xfffu);
        format_case(__LINE__, "format: refused, longest line", &r, want);
    }
}

int main(int argc, char **argv)
{
    verbose = argc > 1 && strcmp(argv[1], "-v") == 0;
    fake_mem = malloc(LARGE_BYTES);
    if (fake_mem == NULL) {
        fprintf(stderr, "memtest_test: no memory for the fake SDRAM\n");
        return 2;
    }
    fault_clear();

    good_memory();
    data_faults();
    address_faults();
    lane_faults();
    cell_faults();
    refusals();
    formats();

    free(fake_mem);
    if (failures != 0u) {
        printf("memtest_test: %u of %u cases FAILED\n", failures, cases);
        return 1;
    }
    printf("memtest_test: ok %u cases\n", cases);
    return 0;
}
