/* The SoC's SDRAM on socsim (socsim-sdram: soc_top with LiteDRAM's controller, the chip model on its
 * pins): bare metal from the on-chip RAM, as the boot code will run. Prints over the UART (the test
 * checks the text) and returns 0 to SYS EXIT when all passed, 1 at the first failure:
 *   1. SYS SDRAM_BYTES is the contract's size;
 *   2. a load from the SDRAM before its power-up sequence is refused (a bus error in SYS's record,
 *      the load reads 0) instead of hanging the CPU;
 *   3. the power-up sequence (bsp/soc/sdram/sdram_init.c) through LiteDRAM's control registers,
 *      the pins taken from the controller first of all (its refresher runs from reset);
 *   4. the quick memory test (bsp/soc/sdram/memtest.c) over the whole chip; on a failure its line
 *      and LEDS = 0xE1 (the board shows it), exit 1;
 *   5. a short program copied into the SDRAM and run from there (instruction cache refills from
 *      the SDRAM).
 * The CPU's bandwidth and the full test: the memory test program (bsp/soc/boot/memtest_main.c). */
#include <stdint.h>

#include "memtest.h"
#include "say.h"
#include "sdram_init.h"
#include "soc_map.h"

#define SOC_REG(base, off) (*(volatile uint32_t *)(uintptr_t)((base) + (off)))
#define SYS(r) SOC_REG(SOC_SYS_BASE, SOC_SYS_REG_##r)

#define LEDS_SDRAM_FAILED 0xE1u

static uint32_t now(void)
{
    return SYS(MTIME_LO);
}

/* sdram_init's wait: the SYS cycle counter against the build's clock. */
void sdram_delay_ns(uint32_t ns)
{
    const uint32_t clocks = (uint32_t)(((uint64_t)ns * SYS(CLK_HZ) + 999999999u) / 1000000000u);
    const uint32_t start = now();
    while (now() - start < clocks) {
    }
}

/* tests/soc/smoke_crt0.S calls it with main's return value: the UART drained, then SYS EXIT. */
void smoke_exit(uint32_t code);
void smoke_exit(uint32_t code)
{
    say_drain();
    SYS(EXIT) = code;
    for (;;) {
    }
}

static int fail(const char *what)
{
    say("sdram_test: FAILED: ");
    say(what);
    say_char('\n');
    SYS(LEDS) = LEDS_SDRAM_FAILED;
    return 1;
}

int main(void);
int main(void)
{
    sdram_take_pins();  /* first: LiteDRAM's refresher must not reach a chip still powering up */
    volatile uint32_t *const sdram = (volatile uint32_t *)(uintptr_t)SOC_SDRAM_BASE;
    const uint32_t bytes = SYS(SDRAM_BYTES);
    say("sdram_test: SDRAM_BYTES ");
    say_dec(bytes);
    say_char('\n');
    if (bytes != SOC_SDRAM_DEFAULT_BYTES) {
        return fail("SYS SDRAM_BYTES is not the contract's size");
    }

    /* Before the power-up sequence: refused, not hung. */
    SYS(BUS_ERR) = 0u;
    const uint32_t early = sdram[0];
    const uint32_t be = SYS(BUS_ERR);
    say("sdram_test: before init: read ");
    say_hex(early);
    say(", bus error ");
    say_hex(be);
    say(" at ");
    say_hex(SYS(BUS_ERR_ADDR));
    say_char('\n');
    if ((be & SOC_SYS_BUS_ERR_VALID_MASK) == 0u || early != 0u || SYS(BUS_ERR_ADDR) != SOC_SDRAM_BASE) {
        return fail("a load before the power-up sequence was not refused");
    }
    SYS(BUS_ERR) = 0u;

    const uint32_t t0 = now();
    const uint32_t mode = sdram_init();
    say("sdram_test: init: mode register ");
    say_hex(mode);
    say(" in ");
    say_dec(now() - t0);
    say(" cycles\n");

    const uint32_t t1 = now();
    const struct memtest_result r = memtest_quick(SOC_SDRAM_BASE, bytes, 0x5EEDu);
    const uint32_t test_cycles = now() - t1;
    char line[MEMTEST_FORMAT_SIZE];
    memtest_format(&r, line, sizeof line);
    say(line);
    say(" in ");
    say_dec(test_cycles);
    say(" cycles\n");
    if (!r.ok) {
        return fail("the quick memory test");
    }

    /* Code from the SDRAM: `addi a0, a0, 1; ret`, copied in and called (fence.i: the instruction
     * cache refills from the SDRAM). */
    volatile uint32_t *const code = sdram + 64u;
    code[0] = 0x00150513u;  /* addi a0, a0, 1 */
    code[1] = 0x00008067u;  /* jalr x0, 0(ra) */
    __asm__ volatile("fence.i" ::: "memory");
    uint32_t (*const from_sdram)(uint32_t) = (uint32_t (*)(uint32_t))(uintptr_t)code;
    const uint32_t got = from_sdram(41u);
    say("sdram_test: code in the SDRAM returned ");
    say_dec(got);
    say_char('\n');
    if (got != 42u) {
        return fail("code run from the SDRAM");
    }
    say("sdram_test: ok\n");
    return 0;
}
