/*
 * boot_image.c — the boot image's header checks (boot_image.h).
 */
#include "boot_image.h"

#include <stddef.h>

#include "model/crc32.h"
#include "soc_map.h"

static uint32_t header_crc(const uint32_t header[BOOT_IMAGE_HEADER_WORDS])
{
    uint8_t bytes[4u * BOOT_IMAGE_WORD_HEADER_CRC];
    for (size_t i = 0; i < BOOT_IMAGE_WORD_HEADER_CRC; ++i) {
        for (size_t b = 0; b < 4u; ++b) {
            bytes[4u * i + b] = (uint8_t)(header[i] >> (8u * b));  /* little-endian, as in the flash */
        }
    }
    return crc32_update(0u, bytes, sizeof bytes);
}

enum boot_image_status boot_image_check_header(const uint32_t header[BOOT_IMAGE_HEADER_WORDS],
                                               uint32_t mem_base, uint32_t mem_bytes)
{
    if (header[BOOT_IMAGE_WORD_MAGIC] != SOC_BOOT_IMAGE_MAGIC) {
        return BOOT_IMAGE_NO_MAGIC;
    }
    if (header[BOOT_IMAGE_WORD_HEADER_CRC] != header_crc(header)) {
        return BOOT_IMAGE_BAD_HEADER_CRC;
    }
    const uint32_t load = header[BOOT_IMAGE_WORD_LOAD];
    const uint32_t bytes = header[BOOT_IMAGE_WORD_BYTES];
    const uint32_t entry = header[BOOT_IMAGE_WORD_ENTRY];
    if (header[BOOT_IMAGE_WORD_HEADER_BYTES] != SOC_BOOT_IMAGE_HEADER_BYTES || header[BOOT_IMAGE_WORD_RESERVED] != 0u ||
        load % 4u != 0u || bytes % 4u != 0u || bytes == 0u) {
        return BOOT_IMAGE_BAD_LAYOUT;
    }
    /* In 64-bit arithmetic: a load address near 2^32 must not wrap into the memory. */
    if (load < mem_base || (uint64_t)load + bytes > (uint64_t)mem_base + mem_bytes) {
        return BOOT_IMAGE_OUTSIDE_MEMORY;
    }
    if (entry < load || entry - load >= bytes || entry % 4u != 0u) {
        return BOOT_IMAGE_ENTRY_OUTSIDE;
    }
    return BOOT_IMAGE_OK;
}

enum boot_image_status boot_image_check_payload(const uint32_t header[BOOT_IMAGE_HEADER_WORDS],
                                                const uint8_t *payload)
{
    return crc32_update(0u, payload, header[BOOT_IMAGE_WORD_BYTES]) == header[BOOT_IMAGE_WORD_PAYLOAD_CRC]
               ? BOOT_IMAGE_OK
               : BOOT_IMAGE_BAD_PAYLOAD_CRC;
}

const char *boot_image_status_text(enum boot_image_status status)
{
    switch (status) {
    case BOOT_IMAGE_OK:
        return "image ok";
    case BOOT_IMAGE_NO_MAGIC:
        return "no firmware image (wrong magic)";
    case BOOT_IMAGE_BAD_HEADER_CRC:
        return "image header corrupt (CRC mismatch)";
    case BOOT_IMAGE_BAD_LAYOUT:
        return "image header malformed (size, alignment or reserved word)";
    case BOOT_IMAGE_OUTSIDE_MEMORY:
        return "image does not fit the SDRAM";
    case BOOT_IMAGE_ENTRY_OUTSIDE:
        return "image entry point outside its payload";
    case BOOT_IMAGE_BAD_PAYLOAD_CRC:
        return "image payload corrupt (CRC mismatch after the copy)";
    }
    return "unknown image status";
}
