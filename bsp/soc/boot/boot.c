/*
 * boot.c — the SoC's boot program: the on-chip RAM's image in a build whose firmware lives in the
 * SDRAM (docs/boot.md). From reset it
 *   1. takes the SDRAM's pins from LiteDRAM (whose refresher runs from reset, before the chip has
 *      finished powering up: bsp/soc/sdram/sdram_init.h) and runs the chip's power-up sequence;
 *   2. reads the firmware image's header from the flash (SOC_BOOT_FLASH_IMAGE_OFFSET) and checks it
 *      against the SDRAM (boot_image.h);
 *   3. runs the quick memory test over the whole SDRAM (bsp/soc/sdram/memtest.h) — nothing is
 *      rendered on memory that fails it — then copies the payload word by word (the flash streams
 *      consecutive words: soc_rtl/soc_spiflash.v) and checks the copy's CRC in the SDRAM;
 *   4. jumps to the image's entry (its crt0 sets up its own stack, data and .bss).
 * Each step prints a line on the UART; a failure prints why with its numbers, shows its code on the
 * LEDs and writes it to SYS EXIT (a simulator ends with it; a board keeps it on the LEDs), and
 * stops: the firmware never starts on a broken memory or a corrupt image.
 */
#include <stdint.h>

#include "boot_image.h"
#include "memtest.h"
#include "say.h"
#include "sdram_init.h"
#include "soc_map.h"

#define SYS_REG(r) (*(volatile uint32_t *)(uintptr_t)(SOC_SYS_BASE + SOC_SYS_REG_##r))

/* The failure codes, on the LEDs and as the exit status (docs/boot.md). */
enum boot_failure {
    BOOT_FAIL_NO_SDRAM = 0xE0,     /* a build without SDRAM: SYS SDRAM_BYTES reads 0 */
    BOOT_FAIL_MEMTEST = 0xE1,      /* the SDRAM failed the quick memory test */
    BOOT_FAIL_NO_IMAGE = 0xE2,     /* no image in the flash (wrong magic) */
    BOOT_FAIL_BAD_HEADER = 0xE3,   /* a header that is corrupt or does not fit the SDRAM */
    BOOT_FAIL_BAD_PAYLOAD = 0xE4,  /* the copy's CRC is not the header's */
};

void boot_main(void) __attribute__((noreturn));

static uint32_t now(void)
{
    return SYS_REG(MTIME_LO);
}

/* sdram_init's wait: the SYS cycle counter against the build's clock. */
void sdram_delay_ns(uint32_t ns)
{
    const uint32_t clocks = (uint32_t)(((uint64_t)ns * SYS_REG(CLK_HZ) + 999999999u) / 1000000000u);
    const uint32_t start = now();
    while (now() - start < clocks) {
    }
}

static void __attribute__((noreturn)) stop(enum boot_failure code)
{
    SYS_REG(LEDS) = (uint32_t)code;
    say_drain();
    SYS_REG(EXIT) = (uint32_t)code;
    for (;;) {
        __asm__ volatile("wfi");
    }
}

static void __attribute__((noreturn)) image_failure(enum boot_failure code, enum boot_image_status status,
                                                    const uint32_t header[BOOT_IMAGE_HEADER_WORDS])
{
    say("boot: FAILED: ");
    say(boot_image_status_text(status));
    say(" at flash ");
    say_hex(SOC_BOOT_FLASH_IMAGE_OFFSET);
    say(": magic ");
    say_hex(header[BOOT_IMAGE_WORD_MAGIC]);
    say(", load ");
    say_hex(header[BOOT_IMAGE_WORD_LOAD]);
    say(", bytes ");
    say_dec(header[BOOT_IMAGE_WORD_BYTES]);
    say(", entry ");
    say_hex(header[BOOT_IMAGE_WORD_ENTRY]);
    say("\n");
    stop(code);
}

void boot_main(void)
{
    sdram_take_pins();  /* again (boot_crt0.S did it first of all, within tREFI of reset) */
    const uint32_t sdram_bytes = SYS_REG(SDRAM_BYTES);
    say("boot: ");
    say_dec(SYS_REG(CLK_HZ));
    say(" Hz, on-chip RAM ");
    say_dec(SYS_REG(RAM_BYTES));
    say(" bytes, SDRAM ");
    say_dec(sdram_bytes);
    say(" bytes\n");
    if (sdram_bytes == 0u) {
        say("boot: FAILED: this build has no SDRAM to load the firmware into\n");
        stop(BOOT_FAIL_NO_SDRAM);
    }

    uint32_t t = now();
    const uint32_t mode = sdram_init();
    say("boot: SDRAM powered up, mode register ");
    say_hex(mode);
    say(", ");
    say_dec(now() - t);
    say(" cycles\n");

    /* The image's header first: it needs no SDRAM, so a missing or corrupt image is told at once. */
    const volatile uint32_t *const flash =
        (const volatile uint32_t *)(uintptr_t)(SOC_FLASH_BASE + SOC_BOOT_FLASH_IMAGE_OFFSET);
    uint32_t header[BOOT_IMAGE_HEADER_WORDS];
    for (uint32_t i = 0; i < BOOT_IMAGE_HEADER_WORDS; ++i) {
        header[i] = flash[i];
    }
    enum boot_image_status status = boot_image_check_header(header, SOC_SDRAM_BASE, sdram_bytes);
    if (status != BOOT_IMAGE_OK) {
        image_failure(status == BOOT_IMAGE_NO_MAGIC ? BOOT_FAIL_NO_IMAGE : BOOT_FAIL_BAD_HEADER, status, header);
    }

    t = now();
    const struct memtest_result test = memtest_quick(SOC_SDRAM_BASE, sdram_bytes, now());
    char line[MEMTEST_FORMAT_SIZE];
    memtest_format(&test, line, sizeof line);
    say("boot: ");
    say(line);
    say(", ");
    say_dec(now() - t);
    say(" cycles\n");
    if (!test.ok) {
        say("boot: FAILED: the SDRAM does not work; not starting the firmware\n");
        stop(BOOT_FAIL_MEMTEST);
    }

    t = now();
    volatile uint32_t *const load = (volatile uint32_t *)(uintptr_t)header[BOOT_IMAGE_WORD_LOAD];
    const uint32_t words = header[BOOT_IMAGE_WORD_BYTES] / 4u;
    const volatile uint32_t *const payload = flash + BOOT_IMAGE_HEADER_WORDS;
    for (uint32_t i = 0; i < words; ++i) {
        load[i] = payload[i];
    }
    const uint32_t copy_cycles = now() - t;
    t = now();
    status = boot_image_check_payload(header, (const uint8_t *)(uintptr_t)header[BOOT_IMAGE_WORD_LOAD]);
    const uint32_t crc_cycles = now() - t;
    if (status != BOOT_IMAGE_OK) {
        image_failure(BOOT_FAIL_BAD_PAYLOAD, status, header);
    }
    say("boot: image of ");
    say_dec(header[BOOT_IMAGE_WORD_BYTES]);
    say(" bytes from flash ");
    say_hex(SOC_BOOT_FLASH_IMAGE_OFFSET);
    say(" to ");
    say_hex(header[BOOT_IMAGE_WORD_LOAD]);
    say(" in ");
    say_dec(copy_cycles);
    say(" cycles, CRC ");
    say_hex(header[BOOT_IMAGE_WORD_PAYLOAD_CRC]);
    say(" checked in ");
    say_dec(crc_cycles);
    say(" cycles; starting at ");
    say_hex(header[BOOT_IMAGE_WORD_ENTRY]);
    say("\n");
    say_drain();

    /* RISC-V fetches code written by stores only after a fence.i (VexRiscv: it empties the
     * instruction cache, so no line of these addresses fetched before the copy survives). */
    __asm__ volatile("fence.i" ::: "memory");
    void (*const entry)(void) = (void (*)(void))(uintptr_t)header[BOOT_IMAGE_WORD_ENTRY];
    entry();
    for (;;) {
    }
}
