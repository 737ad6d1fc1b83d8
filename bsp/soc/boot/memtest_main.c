/*
 * memtest_main.c — the SDRAM's full memory test as a program of its own (docs/sdram.md), in the
 * on-chip RAM of a build with SDRAM, in place of the boot program: on a board whose SDRAM is in
 * doubt, it tests every cell instead of the boot's quick test, pass after pass, and measures what
 * the CPU gets from the memory.
 *
 * It takes the pins and powers the SDRAM up (as boot.c), prints the CPU's bandwidth (consecutive
 * word stores, single and write-through; consecutive loads, each cache line an 8-word burst), then
 * runs memtest_full() over the range (bsp/soc/sdram/memtest.h) with a new seed each pass, one line
 * a pass. LEDs: the passes done (low 7 bits), or 0xE1 at the first failure, whose line names the
 * address, the pattern and the test; the program then writes 0xE1 to SYS EXIT and stops.
 * Build options: MEMTEST_PROGRAM_BYTES, the range from the SDRAM's base (0: the whole SDRAM, SYS
 * SDRAM_BYTES; a simulation tests less: every pass over 32 MiB is 570 M accesses); MEMTEST_PROGRAM_PASSES,
 * the passes before it exits with 0 (0: for ever).
 */
#include <stdint.h>

#include "memtest.h"
#include "say.h"
#include "sdram_init.h"
#include "soc_map.h"

#ifndef MEMTEST_PROGRAM_BYTES
#define MEMTEST_PROGRAM_BYTES 0u
#endif
#ifndef MEMTEST_PROGRAM_PASSES
#define MEMTEST_PROGRAM_PASSES 0u
#endif
#define MEMTEST_FAILED 0xE1u
#define BANDWIDTH_WORDS 4096u  /* 16 KiB: four times the data cache, so every load refills */

#define SYS_REG(r) (*(volatile uint32_t *)(uintptr_t)(SOC_SYS_BASE + SOC_SYS_REG_##r))

int main(void);

static uint32_t now(void)
{
    return SYS_REG(MTIME_LO);
}

void sdram_delay_ns(uint32_t ns)
{
    const uint32_t clocks = (uint32_t)(((uint64_t)ns * SYS_REG(CLK_HZ) + 999999999u) / 1000000000u);
    const uint32_t start = now();
    while (now() - start < clocks) {
    }
}

/* tests/soc/smoke_crt0.S's exit: the UART drained, then SYS EXIT. */
void smoke_exit(uint32_t code);
void smoke_exit(uint32_t code)
{
    say_drain();
    SYS_REG(EXIT) = code;
    for (;;) {
    }
}

/* "N.NN cycles a word (M.M MB/s)" at the build's clock. */
static void say_rate(uint32_t cycles, uint32_t words)
{
    const uint32_t hundredths = (uint32_t)(((uint64_t)cycles * 100u + words / 2u) / words);
    const uint32_t tenths_mbs = (uint32_t)((uint64_t)SYS_REG(CLK_HZ) * 4u * words / cycles / 100000u);
    say_dec(hundredths / 100u);
    say_char('.');
    say_char((char)('0' + hundredths / 10u % 10u));
    say_char((char)('0' + hundredths % 10u));
    say(" cycles a word (");
    say_dec(tenths_mbs / 10u);
    say_char('.');
    say_char((char)('0' + tenths_mbs % 10u));
    say(" MB/s)");
}

static void bandwidth(uint32_t bytes)
{
    volatile uint32_t *const block = (volatile uint32_t *)(uintptr_t)SOC_SDRAM_BASE;
    const uint32_t words = bytes / 4u < BANDWIDTH_WORDS ? bytes / 4u : BANDWIDTH_WORDS;
    uint32_t t = now();
    for (uint32_t i = 0; i < words; ++i) {
        block[i] = i * 0x9E3779B9u;
    }
    const uint32_t store_cycles = now() - t;
    uint32_t sum = 0;
    t = now();
    for (uint32_t i = 0; i < words; ++i) {
        sum += block[i];
    }
    const uint32_t load_cycles = now() - t;
    say("memtest: CPU stores, one word each: ");
    say_rate(store_cycles, words);
    say("\nmemtest: CPU loads, 8-word line refills: ");
    say_rate(load_cycles, words);
    say(sum == words * (words - 1u) / 2u * 0x9E3779B9u ? "\n" : " (read back WRONG)\n");
}

int main(void)
{
    sdram_take_pins();
    const uint32_t bytes = MEMTEST_PROGRAM_BYTES != 0u ? MEMTEST_PROGRAM_BYTES : SYS_REG(SDRAM_BYTES);
    say("memtest: SDRAM ");
    say_dec(SYS_REG(SDRAM_BYTES));
    say(" bytes, testing ");
    say_dec(bytes);
    say(" from ");
    say_hex(SOC_SDRAM_BASE);
    say_char('\n');
    sdram_init();
    bandwidth(bytes);

    char line[MEMTEST_FORMAT_SIZE];
    for (uint32_t pass = 1; MEMTEST_PROGRAM_PASSES == 0u || pass <= MEMTEST_PROGRAM_PASSES; ++pass) {
        const uint32_t t = now();
        const struct memtest_result r = memtest_full(SOC_SDRAM_BASE, bytes, pass);
        const uint32_t cycles = now() - t;  /* wraps after 86 s at 50 MHz: the whole chip's pass */
        memtest_format(&r, line, sizeof line);
        say("pass ");
        say_dec(pass);
        say(": ");
        say(line);
        say(", ");
        say_dec(cycles);
        say(" cycles\n");
        if (!r.ok) {
            SYS_REG(LEDS) = MEMTEST_FAILED;
            return (int)MEMTEST_FAILED;
        }
        SYS_REG(LEDS) = pass & 0x7Fu;
    }
    return 0;
}
