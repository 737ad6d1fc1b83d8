/*
 * memtest.h — the SDRAM memory test's pure core: bus, byte-lane and cell tests over a range of
 * memory, each returning the first failure as data, and one line of text for the UART.
 *
 * Two callers share it: the boot firmware runs memtest_quick() before anything lives in the
 * SDRAM, and a program of its own runs memtest_full(). Both print memtest_format()'s line and show
 * the outcome on a LED; that edge is theirs. Nothing here touches hardware other than the memory
 * under test, and that only through four macros (memtest.c), so a host test can put a faulty
 * memory behind them (tests/sdram/memtest_test.c):
 *
 *   MEMTEST_READ32(addr)           one aligned 32-bit load   (addr: a uintptr_t byte address)
 *   MEMTEST_WRITE32(addr, value)   one aligned 32-bit store
 *   MEMTEST_WRITE16(addr, value)   one aligned 16-bit store  (the byte-lane test only)
 *   MEMTEST_WRITE8(addr, value)    one 8-bit store           (the byte-lane test only)
 *
 * Left undefined where memtest.c is compiled, they are volatile loads and stores; a caller that
 * defines one must define all four.
 *
 * The order and the first three tests follow the idea of Michael Barr's "Software-Based Memory
 * Testing" (Embedded Systems Programming, 2000): the data bus first, on one word, since every
 * other test needs it; then the address bus, on a word per address line, since the cell tests
 * need distinct addresses; then the cells. A test stops at its first failure, so a broken bus is
 * reported as itself and not as millions of bad cells.
 *
 * Addresses: the byte-lane test assumes a little-endian CPU (byte address a holds bits
 * 8 * (a % 4) .. + 7 of its word), as RISC-V is. The address test reports byte-address bits; with
 * LiteDRAM's default row-bank-column mapping of the board's x16 IS42S16160G behind a 32-bit port,
 * byte-address bit 1 is column A0 (inside every word access), bits 2..9 columns A1..A8, bits
 * 10..11 the bank, bits 12..24 rows A0..A12 — the controller's configuration decides, not this file.
 */
#ifndef MEMTEST_H
#define MEMTEST_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* memtest_quick()'s random fill covers the first this many bytes (or the whole range if smaller).
 * With LiteDRAM's row-bank-column mapping a 4 KiB step is one row of each of the four banks, so
 * 256 KiB writes every column of rows 0..63 in every bank; the address test has already toggled
 * every address line over the whole size. It costs 4 accesses a word (two passes, a write and a
 * read each): 262,144 accesses, about 53 ms at 50 MHz and 10 clocks an access — the whole quick
 * test on 32 MiB is 262,967 accesses. Each word is read back 65,535 accesses (some 13 ms) after its
 * write, far less than the 64 ms refresh period, so the quick test cannot see a cell that loses
 * its charge: memtest_full() can. */
#ifndef MEMTEST_QUICK_RANDOM_BYTES  /* a build may test less: make test's scene runs (socsim.mk SOC_BOOT_FAST_HEX) */
#define MEMTEST_QUICK_RANDOM_BYTES (256u * 1024u)
#endif

/* A buffer this large always holds memtest_format()'s whole line and its terminating NUL. */
#define MEMTEST_FORMAT_SIZE 160u

struct memtest_result {
    bool ok;                /* every check passed (false also when refused) */
    const char *test;       /* static: the test that failed or refused, else the one that ran
                               ("quick", "full", or a single test's name) */
    const char *refused;    /* static: NULL, or why the arguments were refused, naming the bad
                               one ("bytes is not a power of two"); nothing was accessed then */

    /* The first failure (zero when ok or refused). */
    uintptr_t address;      /* the failing byte address: the word read back wrong, or for the
                               byte-lane test the sub-word store whose word read back wrong */
    uint32_t expected;      /* the word written (or, byte lanes, the word expected after the store) */
    uint32_t actual;        /* the word read back */
    int8_t address_bit;     /* address test: the byte-address bit at fault, else -1 */
    int8_t other_bit;       /* address test: the bit it is shorted to when it can tell, else -1 */
    uint8_t store_bytes;    /* byte-lane test: the failing store's width (1 or 2), else 0 */

    /* What ran. */
    uintptr_t base;         /* the range tested */
    size_t bytes;
    size_t random_bytes;    /* the prefix of the range the random fill covered (0: none) */
    uint32_t tests;         /* tests run, the failing one included */
    uint32_t seed;          /* the random fill's seed */
};

/*
 * The tests. Each takes a range [base, base + bytes): base word aligned, bytes a non-zero multiple
 * of 4 within the address space. memtest_address_bus(), memtest_quick() and memtest_full() also
 * need bytes a power of two and base a multiple of bytes (so that base + 2^k differs from base in
 * address bit k alone). Otherwise a test refuses: it accesses nothing and returns ok false with
 * `refused` naming the bad argument, rather than test some other range. The tests overwrite the
 * whole range (the data-bus test only its first word, the address test its first word and one per
 * address bit, the byte-lane test its first and last words).
 */

/* Data bus, on the first word: a 1 walking through 32 zeros, then a 0 through 32 ones, each
 * written and read back. A data line stuck at 0 loses its walking 1, one stuck at 1 shows up in
 * every pattern where it should be 0, and two shorted lines read back both set or both clear
 * when only one should be. 128 accesses. It cannot see a line that floats and keeps the value
 * just written (nothing else drives the bus between the store and the load); the random fill,
 * which reads each word long after writing it, does. */
struct memtest_result memtest_data_bus(uintptr_t base, size_t bytes);

/* Address bus: 0xaaaaaaaa at each power-of-two word offset (4, 8, .. bytes / 2), 0x55555555 at
 * offset 0; every offset must still hold 0xaaaaaaaa. A line stuck high or low makes 2^k and 0 the
 * same word (so does a line shorted to a line that is 0 in both): offset 2^k reads 0x55555555 and
 * bit k is reported. Then each offset 2^k in turn gets 0x55555555 while offset 0 and the others
 * must keep 0xaaaaaaaa: 2^j reading it back means lines j and k are shorted together. Lines
 * above the range are not tested (test the whole chip for them); bits 0 and 1 select bytes within
 * the word (the byte-lane test). About (log2(bytes) - 2)^2 accesses: 623 for 32 MiB. */
struct memtest_result memtest_address_bus(uintptr_t base, size_t bytes);

/* Byte lanes, on the first and the last word: a known word (all 0s, then all 1s), one byte or
 * half-word store into it, then the whole word read back must show that byte or half-word changed
 * and nothing else. Word stores enable every byte, so only sub-word stores exercise the byte
 * enables (the SDRAM's DQM masks): an enable stuck off drops the store, one stuck on lets it write
 * a neighbour too, swapped enables or lanes put it in the wrong byte. 72 accesses. */
struct memtest_result memtest_byte_lanes(uintptr_t base, size_t bytes);

/* Walking bits over the range, 32 passes: in pass p the word at word index n holds
 * 1 << ((n + p) % 32), so each word has its 1 in every bit once and neighbouring words differ;
 * the whole range is written, then read back. Catches cells stuck at 0 or 1 and bits of a word
 * (or neighbouring words) that disturb each other. 64 accesses a word: 537 M for 32 MiB, about
 * 110 s at 50 MHz — the full test's long part. Words 32 apart hold the same values, so it is no
 * test of the addressing (the address test and the random fill are). */
struct memtest_result memtest_walking_bits(uintptr_t base, size_t bytes);

/* Random fill: xorshift32 from seed (0 stands for 0x6d2b79f5: xorshift's state must not be 0)
 * written over the whole range, then regenerated and compared; then again with every word
 * complemented, so each bit of each cell has held both values. A sequence that does not repeat
 * within 2^32 - 1 words catches any two addresses that reach the same cell (the later write shows
 * at the earlier address), cells that lose or take a value, and, since each word is read a whole
 * pass after it was written (over a second for 32 MiB), cells that lose their charge when refresh
 * is missing or too slow. 4 accesses a word. */
struct memtest_result memtest_random(uintptr_t base, size_t bytes, uint32_t seed);

/* The boot test: data bus, address bus over the whole range, byte lanes, and the random fill
 * over the first MEMTEST_QUICK_RANDOM_BYTES (that constant says why and what it costs). A bad
 * cell beyond that prefix is not found. Stops at the first failure. */
struct memtest_result memtest_quick(uintptr_t base, size_t bytes, uint32_t seed);

/* Every test over the whole range: data bus, address bus, byte lanes, random fill (broad and
 * cheap, so a fault shows early), walking bits (thorough and long). Stops at the first failure.
 * About 570 M accesses for 32 MiB: two minutes at 50 MHz. */
struct memtest_result memtest_full(uintptr_t base, size_t bytes, uint32_t seed);

/*
 * One line of text (no newline) for r into buf, NUL-terminated, truncated to size - 1 characters
 * (nothing is written when size is 0). Returns the length of the whole line, as snprintf() does,
 * so a return of size or more means it was truncated. For example:
 *
 *   memtest: quick ok (32 MiB at 0x40000000, 4 tests, random fill over the first 256 KiB, seed 0x1234)
 *   memtest: address bus FAILED at 0x40001000: wrote 0xaaaaaaaa read 0x55555555 (address bit 12 stuck or shorted)
 *   memtest: byte lanes FAILED at 0x40000002: expected 0x00a50000 read 0x00000000 (after a byte store)
 *   memtest: address bus refused (base 0x40000000, bytes 0x00300000): bytes is not a power of two
 */
size_t memtest_format(const struct memtest_result *r, char *buf, size_t size);

#endif /* MEMTEST_H */
