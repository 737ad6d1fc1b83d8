/*
 * memtest.c — the SDRAM memory test (memtest.h). Freestanding: no library call, no division
 * outside memtest_format(), no floating point; the memory under test is reached only through the
 * MEMTEST_* access macros, so a host test compiles this file with a faulty memory behind them.
 */
#include "memtest.h"

#if !defined(MEMTEST_READ32) && !defined(MEMTEST_WRITE32) && !defined(MEMTEST_WRITE16) && \
    !defined(MEMTEST_WRITE8)
/* volatile: every access must reach the memory, in program order, none merged or left out. */
#define MEMTEST_READ32(addr)         (*(volatile const uint32_t *)(uintptr_t)(addr))
#define MEMTEST_WRITE32(addr, value) (*(volatile uint32_t *)(uintptr_t)(addr) = (uint32_t)(value))
#define MEMTEST_WRITE16(addr, value) (*(volatile uint16_t *)(uintptr_t)(addr) = (uint16_t)(value))
#define MEMTEST_WRITE8(addr, value)  (*(volatile uint8_t *)(uintptr_t)(addr) = (uint8_t)(value))
#elif !defined(MEMTEST_READ32) || !defined(MEMTEST_WRITE32) || !defined(MEMTEST_WRITE16) || \
    !defined(MEMTEST_WRITE8)
/* Half a fake memory would send the other accesses to addresses that do not exist on the host. */
#error "define all four of MEMTEST_READ32, MEMTEST_WRITE32, MEMTEST_WRITE16, MEMTEST_WRITE8, or none"
#endif

/* The address test's two values: every bit differs between them, and neither is 0 or all 1s,
 * which a missing or floating memory tends to return. */
#define MEMTEST_PATTERN     0xaaaaaaaau
#define MEMTEST_ANTIPATTERN 0x55555555u

/* xorshift32's state must not be 0 (it would stay 0): seed 0 stands for this. */
#define MEMTEST_SEED_FOR_ZERO 0x6d2b79f5u

static const char memtest_name_data_bus[] = "data bus";
static const char memtest_name_address_bus[] = "address bus";
static const char memtest_name_byte_lanes[] = "byte lanes";
static const char memtest_name_walking_bits[] = "walking bits";
static const char memtest_name_random[] = "random fill";
static const char memtest_name_quick[] = "quick";
static const char memtest_name_full[] = "full";

static struct memtest_result memtest_start(const char *test, uintptr_t base, size_t bytes, uint32_t seed)
{
    struct memtest_result r = {
        .ok = true,
        .test = test,
        .refused = NULL,
        .address_bit = -1,
        .other_bit = -1,
        .base = base,
        .bytes = bytes,
        .seed = seed,
    };
    return r;
}

/* Checks the range before anything is accessed; names the first bad argument in r->refused.
 * aligned_power_of_two: the address test's needs (memtest.h). */
static bool memtest_refused(struct memtest_result *r, bool aligned_power_of_two)
{
    const uintptr_t base = r->base;
    const size_t bytes = r->bytes;
    const char *why = NULL;

    if ((base & 3u) != 0u) {
        why = "base is not word aligned";
    } else if (bytes == 0u) {
        why = "bytes is zero";
    } else if ((bytes & 3u) != 0u) {
        why = "bytes is not a multiple of 4";
    } else if (base + (uintptr_t)(bytes - 1u) < base) {
        why = "the range wraps past the end of the address space";
    } else if (aligned_power_of_two && (bytes & (bytes - 1u)) != 0u) {
        why = "bytes is not a power of two";
    } else if (aligned_power_of_two && (base & (uintptr_t)(bytes - 1u)) != 0u) {
        why = "base is not a multiple of bytes";
    }
    if (why == NULL) {
        return false;
    }
    r->ok = false;
    r->refused = why;
    return true;
}

/* Records the first failure; returns false so that a test can `return memtest_fail(...)`. */
static bool memtest_fail(struct memtest_result *r, const char *test, uintptr_t address, uint32_t expected,
                         uint32_t actual)
{
    r->ok = false;
    r->test = test;
    r->address = address;
    r->expected = expected;
    r->actual = actual;
    return false;
}

/* One word read back against what it should hold. */
static bool memtest_check(struct memtest_result *r, const char *test, uintptr_t address, uint32_t expected)
{
    const uint32_t actual = MEMTEST_READ32(address);

    if (actual != expected) {
        return memtest_fail(r, test, address, expected, actual);
    }
    return true;
}

/* The bit number of a power of two. */
static int8_t memtest_bit_of(size_t power_of_two)
{
    int8_t bit = 0;

    while (power_of_two > 1u) {
        power_of_two >>= 1;
        bit++;
    }
    return bit;
}

static bool memtest_run_data_bus(struct memtest_result *r)
{
    const uintptr_t word = r->base;

    r->tests++;
    /* Walking 1s find a line stuck at 0 (its 1 is lost), one stuck at 1 (set where only another
     * bit should be) and a short (two bits where one was written, or none). Walking 0s find the
     * same from the other side, should a line fail only against a bus full of 1s. */
    for (uint32_t bit = 0; bit < 32u; bit++) {
        const uint32_t ones = 1u << bit;

        MEMTEST_WRITE32(word, ones);
        if (!memtest_check(r, memtest_name_data_bus, word, ones)) {
            return false;
        }
    }
    for (uint32_t bit = 0; bit < 32u; bit++) {
        const uint32_t zeros = ~(1u << bit);

        MEMTEST_WRITE32(word, zeros);
        if (!memtest_check(r, memtest_name_data_bus, word, zeros)) {
            return false;
        }
    }
    return true;
}

static bool memtest_run_address_bus(struct memtest_result *r)
{
    const uintptr_t base = r->base;
    const size_t bytes = r->bytes;
    uint32_t value;

    r->tests++;
    /* The pattern at every power-of-two offset, then the antipattern at offset 0: any offset that
     * reaches the same word as offset 0 (its line stuck high or low, or shorted to a line that is
     * 0 in both addresses) now reads the antipattern. */
    for (size_t offset = 4u; offset < bytes; offset <<= 1) {
        MEMTEST_WRITE32(base + offset, MEMTEST_PATTERN);
    }
    MEMTEST_WRITE32(base, MEMTEST_ANTIPATTERN);
    for (size_t offset = 4u; offset < bytes; offset <<= 1) {
        value = MEMTEST_READ32(base + offset);
        if (value != MEMTEST_PATTERN) {
            r->address_bit = memtest_bit_of(offset);
            return memtest_fail(r, memtest_name_address_bus, base + offset, MEMTEST_PATTERN, value);
        }
    }
    MEMTEST_WRITE32(base, MEMTEST_PATTERN);

    /* The antipattern at one offset at a time: offset 0 changing means that line reaches offset
     * 0's word; another offset changing means the two lines are shorted (a wired OR: both offsets
     * reach the word with both bits set, which offset 0 does not). */
    for (size_t test = 4u; test < bytes; test <<= 1) {
        MEMTEST_WRITE32(base + test, MEMTEST_ANTIPATTERN);
        value = MEMTEST_READ32(base);
        if (value != MEMTEST_PATTERN) {
            r->address_bit = memtest_bit_of(test);
            return memtest_fail(r, memtest_name_address_bus, base, MEMTEST_PATTERN, value);
        }
        for (size_t offset = 4u; offset < bytes; offset <<= 1) {
            if (offset == test) {
                continue;
            }
            value = MEMTEST_READ32(base + offset);
            if (value != MEMTEST_PATTERN) {
                r->address_bit = memtest_bit_of(test);
                r->other_bit = memtest_bit_of(offset);
                return memtest_fail(r, memtest_name_address_bus, base + offset, MEMTEST_PATTERN, value);
            }
        }
        MEMTEST_WRITE32(base + test, MEMTEST_PATTERN);
    }
    return true;
}

/* The byte-lane test on one word. Each pass pairs a background with store values that differ from
 * it in every byte, and whose bytes differ from each other within a half-word, so a store landing
 * in the wrong lane, or in one lane too many, changes the word read back. */
static bool memtest_lanes_of_word(struct memtest_result *r, uintptr_t word)
{
    static const struct {
        uint32_t background;
        uint8_t byte;
        uint16_t half;
    } passes[2] = {
        { 0x00000000u, 0xa5u, 0xc33cu },
        { 0xffffffffu, 0x5au, 0x3cc3u },
    };

    for (uint32_t p = 0; p < 2u; p++) {
        const uint32_t background = passes[p].background;

        for (uint32_t lane = 0; lane < 4u; lane++) {
            const uint32_t shift = 8u * lane;
            const uint32_t expected = (background & ~(0xffu << shift)) | ((uint32_t)passes[p].byte << shift);

            MEMTEST_WRITE32(word, background);
            MEMTEST_WRITE8(word + lane, passes[p].byte);
            if (!memtest_check(r, memtest_name_byte_lanes, word, expected)) {
                r->address = word + lane;
                r->store_bytes = 1u;
                return false;
            }
        }
        for (uint32_t half = 0; half < 2u; half++) {
            const uint32_t shift = 16u * half;
            const uint32_t expected =
                (background & ~(0xffffu << shift)) | ((uint32_t)passes[p].half << shift);

            MEMTEST_WRITE32(word, background);
            MEMTEST_WRITE16(word + 2u * half, passes[p].half);
            if (!memtest_check(r, memtest_name_byte_lanes, word, expected)) {
                r->address = word + 2u * half;
                r->store_bytes = 2u;
                return false;
            }
        }
    }
    return true;
}

static bool memtest_run_byte_lanes(struct memtest_result *r)
{
    r->tests++;
    if (!memtest_lanes_of_word(r, r->base)) {
        return false;
    }
    /* The last word too: the chip's masks are shared by every address, but not the path to them
     * (another bank, the other end of a row). */
    if (r->bytes > 4u && !memtest_lanes_of_word(r, r->base + (r->bytes - 4u))) {
        return false;
    }
    return true;
}

static bool memtest_run_walking_bits(struct memtest_result *r)
{
    const uintptr_t base = r->base;
    const size_t bytes = r->bytes;

    r->tests++;
    /* Write the whole range before reading any of it: each word then waits a pass in its cells,
     * among neighbours holding other bits. */
    for (uint32_t pass = 0; pass < 32u; pass++) {
        uint32_t n = pass;

        for (size_t offset = 0; offset < bytes; offset += 4u) {
            MEMTEST_WRITE32(base + offset, 1u << (n & 31u));
            n++;
        }
        n = pass;
        for (size_t offset = 0; offset < bytes; offset += 4u) {
            if (!memtest_check(r, memtest_name_walking_bits, base + offset, 1u << (n & 31u))) {
                return false;
            }
            n++;
        }
    }
    return true;
}

/* Marsaglia's xorshift32 (13, 17, 5): period 2^32 - 1 over the non-zero states, a few
 * instructions a word on rv32im. */
static uint32_t memtest_xorshift32(uint32_t *state)
{
    uint32_t x = *state;

    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

static uint32_t memtest_random_start(uint32_t seed)
{
    return seed != 0u ? seed : MEMTEST_SEED_FOR_ZERO;
}

/* The random fill over the first r->random_bytes of the range. */
static bool memtest_run_random(struct memtest_result *r)
{
    const uintptr_t base = r->base;
    const size_t bytes = r->random_bytes;

    r->tests++;
    /* The second pass complements the first: a cell bit that sticks at the value the first pass
     * happened to write there is caught by the second. */
    for (uint32_t pass = 0; pass < 2u; pass++) {
        const uint32_t invert = pass == 0u ? 0u : 0xffffffffu;
        uint32_t state = memtest_random_start(r->seed);

        for (size_t offset = 0; offset < bytes; offset += 4u) {
            MEMTEST_WRITE32(base + offset, memtest_xorshift32(&state) ^ invert);
        }
        state = memtest_random_start(r->seed);
        for (size_t offset = 0; offset < bytes; offset += 4u) {
            if (!memtest_check(r, memtest_name_random, base + offset, memtest_xorshift32(&state) ^ invert)) {
                return false;
            }
        }
    }
    return true;
}

struct memtest_result memtest_data_bus(uintptr_t base, size_t bytes)
{
    struct memtest_result r = memtest_start(memtest_name_data_bus, base, bytes, 0u);

    if (!memtest_refused(&r, false)) {
        (void)memtest_run_data_bus(&r);
    }
    return r;
}

struct memtest_result memtest_address_bus(uintptr_t base, size_t bytes)
{
    struct memtest_result r = memtest_start(memtest_name_address_bus, base, bytes, 0u);

    if (!memtest_refused(&r, true)) {
        (void)memtest_run_address_bus(&r);
    }
    return r;
}

struct memtest_result memtest_byte_lanes(uintptr_t base, size_t bytes)
{
    struct memtest_result r = memtest_start(memtest_name_byte_lanes, base, bytes, 0u);

    if (!memtest_refused(&r, false)) {
        (void)memtest_run_byte_lanes(&r);
    }
    return r;
}

struct memtest_result memtest_walking_bits(uintptr_t base, size_t bytes)
{
    struct memtest_result r = memtest_start(memtest_name_walking_bits, base, bytes, 0u);

    if (!memtest_refused(&r, false)) {
        (void)memtest_run_walking_bits(&r);
    }
    return r;
}

struct memtest_result memtest_random(uintptr_t base, size_t bytes, uint32_t seed)
{
    struct memtest_result r = memtest_start(memtest_name_random, base, bytes, seed);

    if (!memtest_refused(&r, false)) {
        r.random_bytes = bytes;
        (void)memtest_run_random(&r);
    }
    return r;
}

struct memtest_result memtest_quick(uintptr_t base, size_t bytes, uint32_t seed)
{
    struct memtest_result r = memtest_start(memtest_name_quick, base, bytes, seed);

    if (memtest_refused(&r, true)) {
        return r;
    }
    r.random_bytes = bytes < MEMTEST_QUICK_RANDOM_BYTES ? bytes : MEMTEST_QUICK_RANDOM_BYTES;
    if (memtest_run_data_bus(&r) && memtest_run_address_bus(&r) && memtest_run_byte_lanes(&r)) {
        (void)memtest_run_random(&r);
    }
    return r;
}

struct memtest_result memtest_full(uintptr_t base, size_t bytes, uint32_t seed)
{
    struct memtest_result r = memtest_start(memtest_name_full, base, bytes, seed);

    if (memtest_refused(&r, true)) {
        return r;
    }
    r.random_bytes = bytes;
    if (memtest_run_data_bus(&r) && memtest_run_address_bus(&r) && memtest_run_byte_lanes(&r) &&
        memtest_run_random(&r)) {
        (void)memtest_run_walking_bits(&r);
    }
    return r;
}

/* ---- memtest_format: a line of text without printf ---- */

/* The line so far: characters past size - 1 are counted, not stored. */
struct memtest_text {
    char *buf;
    size_t size;
    size_t len;
};

static void memtest_put_char(struct memtest_text *t, char c)
{
    if (t->len + 1u < t->size) {
        t->buf[t->len] = c;
    }
    t->len++;
}

static void memtest_put_str(struct memtest_text *t, const char *s)
{
    while (*s != '\0') {
        memtest_put_char(t, *s);
        s++;
    }
}

/* "0x" and the low `digits` hex digits of v, lower case. */
static void memtest_put_hex_digits(struct memtest_text *t, uintptr_t v, uint32_t digits)
{
    static const char hex[] = "0123456789abcdef";

    memtest_put_str(t, "0x");
    for (uint32_t i = digits; i > 0u; i--) {
        memtest_put_char(t, hex[(v >> (4u * (i - 1u))) & 0xfu]);
    }
}

/* An address or a size: 8 digits, or 16 when it does not fit in 32 bits (a 64-bit host). */
static void memtest_put_hex_address(struct memtest_text *t, uintptr_t v)
{
    /* Two shifts by 16: a single shift by 32 is undefined where uintptr_t has 32 bits. */
    memtest_put_hex_digits(t, v, ((v >> 16) >> 16) != 0u ? 2u * (uint32_t)sizeof v : 8u);
}

/* A word: always 8 digits, so that two words line up bit for bit. */
static void memtest_put_hex_word(struct memtest_text *t, uint32_t v)
{
    memtest_put_hex_digits(t, v, 8u);
}

/* A seed: as few digits as it needs. */
static void memtest_put_hex_short(struct memtest_text *t, uint32_t v)
{
    uint32_t digits = 1u;

    while (digits < 8u && (v >> (4u * digits)) != 0u) {
        digits++;
    }
    memtest_put_hex_digits(t, v, digits);
}

static void memtest_put_dec(struct memtest_text *t, size_t v)
{
    char digits[3u * sizeof v];  /* enough for any size_t: 2.41 decimal digits a byte */
    uint32_t n = 0;

    do {
        digits[n] = (char)('0' + (v % 10u));
        v /= 10u;
        n++;
    } while (v != 0u);
    while (n > 0u) {
        n--;
        memtest_put_char(t, digits[n]);
    }
}

/* A size in the largest binary unit that divides it: "32 MiB", "256 KiB", "1000 bytes". */
static void memtest_put_size(struct memtest_text *t, size_t bytes)
{
    if (bytes != 0u && bytes % (1024u * 1024u) == 0u) {
        memtest_put_dec(t, bytes / (1024u * 1024u));
        memtest_put_str(t, " MiB");
    } else if (bytes != 0u && bytes % 1024u == 0u) {
        memtest_put_dec(t, bytes / 1024u);
        memtest_put_str(t, " KiB");
    } else {
        memtest_put_dec(t, bytes);
        memtest_put_str(t, " bytes");
    }
}

static void memtest_put_result(struct memtest_text *t, const struct memtest_result *r)
{
    memtest_put_str(t, "memtest: ");
    memtest_put_str(t, r->test != NULL ? r->test : "?");

    if (r->refused != NULL) {
        memtest_put_str(t, " refused (base ");
        memtest_put_hex_address(t, r->base);
        memtest_put_str(t, ", bytes ");
        memtest_put_hex_address(t, (uintptr_t)r->bytes);
        memtest_put_str(t, "): ");
        memtest_put_str(t, r->refused);
        return;
    }

    if (r->ok) {
        memtest_put_str(t, " ok (");
        memtest_put_size(t, r->bytes);
        memtest_put_str(t, " at ");
        memtest_put_hex_address(t, r->base);
        memtest_put_str(t, ", ");
        memtest_put_dec(t, r->tests);
        memtest_put_str(t, r->tests == 1u ? " test" : " tests");
        if (r->random_bytes != 0u && r->random_bytes < r->bytes) {
            memtest_put_str(t, ", random fill over the first ");
            memtest_put_size(t, r->random_bytes);
        }
        if (r->random_bytes != 0u) {
            memtest_put_str(t, ", seed ");
            memtest_put_hex_short(t, r->seed);
        }
        memtest_put_char(t, ')');
        return;
    }

    memtest_put_str(t, " FAILED at ");
    memtest_put_hex_address(t, r->address);
    /* Byte lanes: the word was not written whole, so it is what the word should hold. */
    memtest_put_str(t, r->store_bytes != 0u ? ": expected " : ": wrote ");
    memtest_put_hex_word(t, r->expected);
    memtest_put_str(t, " read ");
    memtest_put_hex_word(t, r->actual);
    if (r->address_bit >= 0 && r->other_bit >= 0) {
        memtest_put_str(t, " (address bits ");
        memtest_put_dec(t, (size_t)r->address_bit);
        memtest_put_str(t, " and ");
        memtest_put_dec(t, (size_t)r->other_bit);
        memtest_put_str(t, " shorted)");
    } else if (r->address_bit >= 0) {
        memtest_put_str(t, " (address bit ");
        memtest_put_dec(t, (size_t)r->address_bit);
        memtest_put_str(t, " stuck or shorted)");
    } else if (r->store_bytes == 1u) {
        memtest_put_str(t, " (after a byte store)");
    } else if (r->store_bytes == 2u) {
        memtest_put_str(t, " (after a half-word store)");
    }
}

size_t memtest_format(const struct memtest_result *r, char *buf, size_t size)
{
    struct memtest_text t = { .buf = buf, .size = size, .len = 0u };

    memtest_put_result(&t, r);
    if (size > 0u) {
        t.buf[t.len < size ? t.len : size - 1u] = '\0';
    }
    return t.len;
}
