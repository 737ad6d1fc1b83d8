/*
 * image_test.c — the boot image's checks (bsp/soc/boot/boot_image.c) against images written by
 * bsp/soc/mkimage.py (tests/boot/image.sh): the reader and the writer are separate code, so a
 * layout they disagree on fails here. Then every way an image can be wrong, each made from the
 * good one, with the status the boot program must report.
 *
 *   image_test IMAGE MEM_BASE MEM_BYTES LOAD BYTES ENTRY
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "boot_image.h"
#include "model/crc32.h"
#include "soc_map.h"

static int cases;
static int failures;

static void expect(const char *what, enum boot_image_status got, enum boot_image_status want)
{
    ++cases;
    if (got != want) {
        ++failures;
        printf("image_test: FAIL %s: %s, want %s\n", what, boot_image_status_text(got), boot_image_status_text(want));
    } else {
        printf("image_test: ok %s: %s\n", what, boot_image_status_text(got));
    }
}

/* CRC-32 a bit at a time, from the polynomial: the reference the table-driven code must match. */
static uint32_t crc32_bitwise(const uint8_t *p, size_t n)
{
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) {
        crc ^= p[i];
        for (int b = 0; b < 8; ++b) {
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
    }
    return ~crc;
}

/* crc32_update at every start alignment and length up to 70 bytes, whole and split in two at every
 * point (the slice tables' word loop, its byte head and tail), and the standard check value. */
static void check_crc(void)
{
    static uint8_t buf[80];
    uint32_t x = 0x12345678u;
    for (size_t i = 0; i < sizeof buf; ++i) {
        x = x * 1103515245u + 12345u;
        buf[i] = (uint8_t)(x >> 24);
    }
    int wrong = 0;
    for (size_t start = 0; start < 4; ++start) {
        for (size_t n = 0; n <= 70; ++n) {
            const uint32_t want = crc32_bitwise(buf + start, n);
            wrong += crc32_update(0u, buf + start, n) != want;
            for (size_t cut = 0; cut <= n; ++cut) {
                wrong += crc32_update(crc32_update(0u, buf + start, cut), buf + start + cut, n - cut) != want;
            }
        }
    }
    wrong += crc32_update(0u, (const uint8_t *)"123456789", 9) != 0xCBF43926u;
    ++cases;
    if (wrong != 0) {
        ++failures;
        printf("image_test: FAIL crc32_update: %d results differ from the bit-by-bit CRC\n", wrong);
    } else {
        printf("image_test: ok crc32_update = the bit-by-bit CRC at every alignment, length and split\n");
    }
}

static void reseal(uint32_t h[BOOT_IMAGE_HEADER_WORDS])
{
    uint8_t bytes[4 * BOOT_IMAGE_WORD_HEADER_CRC];
    for (int i = 0; i < BOOT_IMAGE_WORD_HEADER_CRC; ++i) {
        for (int b = 0; b < 4; ++b) {
            bytes[4 * i + b] = (uint8_t)(h[i] >> (8 * b));
        }
    }
    h[BOOT_IMAGE_WORD_HEADER_CRC] = crc32_update(0u, bytes, sizeof bytes);
}

int main(int argc, char **argv)
{
    if (argc != 7) {
        fprintf(stderr, "usage: image_test IMAGE MEM_BASE MEM_BYTES LOAD BYTES ENTRY\n");
        return 2;
    }
    const uint32_t base = (uint32_t)strtoul(argv[2], NULL, 0), mem = (uint32_t)strtoul(argv[3], NULL, 0);
    const uint32_t load = (uint32_t)strtoul(argv[4], NULL, 0), bytes = (uint32_t)strtoul(argv[5], NULL, 0);
    const uint32_t entry = (uint32_t)strtoul(argv[6], NULL, 0);
    FILE *f = fopen(argv[1], "rb");
    if (f == NULL) {
        perror(argv[1]);
        return 2;
    }
    static uint8_t file[1 << 20];
    const size_t n = fread(file, 1, sizeof file, f);
    fclose(f);
    if (n < SOC_BOOT_IMAGE_HEADER_BYTES) {
        fprintf(stderr, "image_test: %s is %zu bytes, shorter than a header\n", argv[1], n);
        return 1;
    }
    uint32_t good[BOOT_IMAGE_HEADER_WORDS];
    for (int i = 0; i < BOOT_IMAGE_HEADER_WORDS; ++i) {
        good[i] = (uint32_t)file[4 * i] | (uint32_t)file[4 * i + 1] << 8 | (uint32_t)file[4 * i + 2] << 16 |
                  (uint32_t)file[4 * i + 3] << 24;
    }
    uint8_t *payload = file + SOC_BOOT_IMAGE_HEADER_BYTES;
    check_crc();

    /* The writer's image as the boot program reads it. */
    ++cases;
    if (good[BOOT_IMAGE_WORD_LOAD] != load || good[BOOT_IMAGE_WORD_BYTES] != bytes || good[BOOT_IMAGE_WORD_ENTRY] != entry ||
        n != SOC_BOOT_IMAGE_HEADER_BYTES + bytes) {
        ++failures;
        printf("image_test: FAIL header fields: load 0x%08x bytes %u entry 0x%08x (file %zu bytes), want 0x%08x %u 0x%08x\n",
               good[BOOT_IMAGE_WORD_LOAD], good[BOOT_IMAGE_WORD_BYTES], good[BOOT_IMAGE_WORD_ENTRY], n, load, bytes, entry);
    }
    expect("good image, header", boot_image_check_header(good, base, mem), BOOT_IMAGE_OK);
    expect("good image, payload", boot_image_check_payload(good, payload), BOOT_IMAGE_OK);

    uint32_t h[BOOT_IMAGE_HEADER_WORDS];
#define MUTATE(what, stmt, want)                                   \
    do {                                                           \
        memcpy(h, good, sizeof h);                                 \
        stmt;                                                      \
        expect(what, boot_image_check_header(h, base, mem), want); \
    } while (0)
    MUTATE("erased flash", memset(h, 0xFF, sizeof h), BOOT_IMAGE_NO_MAGIC);
    MUTATE("magic off by one bit", h[BOOT_IMAGE_WORD_MAGIC] ^= 1u, BOOT_IMAGE_NO_MAGIC);
    MUTATE("load address bit flipped", h[BOOT_IMAGE_WORD_LOAD] ^= 0x100u, BOOT_IMAGE_BAD_HEADER_CRC);
    MUTATE("header CRC bit flipped", h[BOOT_IMAGE_WORD_HEADER_CRC] ^= 0x80000000u, BOOT_IMAGE_BAD_HEADER_CRC);
    MUTATE("header size wrong", (h[BOOT_IMAGE_WORD_HEADER_BYTES] = 64u, reseal(h)), BOOT_IMAGE_BAD_LAYOUT);
    MUTATE("reserved word set", (h[BOOT_IMAGE_WORD_RESERVED] = 1u, reseal(h)), BOOT_IMAGE_BAD_LAYOUT);
    MUTATE("payload not whole words", (h[BOOT_IMAGE_WORD_BYTES] -= 2u, reseal(h)), BOOT_IMAGE_BAD_LAYOUT);
    MUTATE("empty payload", (h[BOOT_IMAGE_WORD_BYTES] = 0u, reseal(h)), BOOT_IMAGE_BAD_LAYOUT);
    MUTATE("load below the memory", (h[BOOT_IMAGE_WORD_LOAD] = base - 4u, reseal(h)), BOOT_IMAGE_OUTSIDE_MEMORY);
    MUTATE("payload past the memory's end", (h[BOOT_IMAGE_WORD_LOAD] = base + mem - bytes + 4u, reseal(h)),
           BOOT_IMAGE_OUTSIDE_MEMORY);
    MUTATE("payload wrapping past 2^32", (h[BOOT_IMAGE_WORD_LOAD] = 0xFFFFFF00u, h[BOOT_IMAGE_WORD_ENTRY] = 0xFFFFFF00u, reseal(h)),
           BOOT_IMAGE_OUTSIDE_MEMORY);
    MUTATE("entry before the payload", (h[BOOT_IMAGE_WORD_ENTRY] = load - 4u, reseal(h)), BOOT_IMAGE_ENTRY_OUTSIDE);
    MUTATE("entry at the payload's end", (h[BOOT_IMAGE_WORD_ENTRY] = load + bytes, reseal(h)), BOOT_IMAGE_ENTRY_OUTSIDE);
    MUTATE("entry not a word", (h[BOOT_IMAGE_WORD_ENTRY] = entry + 2u, reseal(h)), BOOT_IMAGE_ENTRY_OUTSIDE);
    MUTATE("last word of the memory", (h[BOOT_IMAGE_WORD_LOAD] = base + mem - bytes, h[BOOT_IMAGE_WORD_ENTRY] = base + mem - bytes, reseal(h)),
           BOOT_IMAGE_OK);

    payload[bytes / 2] ^= 0x10u;  /* one bit of the copy wrong */
    expect("payload bit flipped", boot_image_check_payload(good, payload), BOOT_IMAGE_BAD_PAYLOAD_CRC);
    payload[bytes / 2] ^= 0x10u;
    payload[bytes - 1] ^= 0x01u;  /* the last byte: the CRC covers all of it */
    expect("last payload byte flipped", boot_image_check_payload(good, payload), BOOT_IMAGE_BAD_PAYLOAD_CRC);

    if (failures != 0) {
        printf("image_test: %d of %d cases FAILED\n", failures, cases);
        return 1;
    }
    printf("image_test: ok %d cases\n", cases);
    return 0;
}
