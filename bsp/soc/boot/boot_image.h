/*
 * boot_image.h — the firmware image the boot program copies from the flash into the SDRAM: its
 * header's layout and checks. Pure code (host-tested by tests/boot); bsp/soc/mkimage.py writes
 * images, independently of this file.
 *
 * An image is a header of SOC_BOOT_IMAGE_HEADER_BYTES (eight little-endian words, below) followed
 * by the payload: the program's bytes from its load address on (its text, read-only data and
 * initialised data; the .bss and the stack are not in it, crt0 clears .bss). It sits in the flash
 * at SOC_BOOT_FLASH_IMAGE_OFFSET (contract/soc_map.toml, docs/boot.md).
 */
#ifndef BOOT_IMAGE_H
#define BOOT_IMAGE_H

#include <stdint.h>

enum {
    BOOT_IMAGE_WORD_MAGIC,        /* SOC_BOOT_IMAGE_MAGIC */
    BOOT_IMAGE_WORD_HEADER_BYTES, /* SOC_BOOT_IMAGE_HEADER_BYTES */
    BOOT_IMAGE_WORD_LOAD,         /* the payload's first byte goes to this address */
    BOOT_IMAGE_WORD_BYTES,        /* the payload's length, a multiple of 4 */
    BOOT_IMAGE_WORD_ENTRY,        /* where the boot program jumps, inside the payload */
    BOOT_IMAGE_WORD_PAYLOAD_CRC,  /* CRC-32 (IEEE, zlib's) of the payload */
    BOOT_IMAGE_WORD_RESERVED,     /* 0 */
    BOOT_IMAGE_WORD_HEADER_CRC,   /* CRC-32 of the seven words above, as bytes */
    BOOT_IMAGE_HEADER_WORDS
};

enum boot_image_status {
    BOOT_IMAGE_OK,
    BOOT_IMAGE_NO_MAGIC,          /* no image at all (an erased or foreign flash) */
    BOOT_IMAGE_BAD_HEADER_CRC,    /* a header, but corrupt */
    BOOT_IMAGE_BAD_LAYOUT,        /* header size, alignment or the reserved word wrong */
    BOOT_IMAGE_OUTSIDE_MEMORY,    /* the payload does not lie within the memory it is loaded to */
    BOOT_IMAGE_ENTRY_OUTSIDE,     /* the entry is not a word inside the payload */
    BOOT_IMAGE_BAD_PAYLOAD_CRC    /* the payload as copied is not the payload the header describes */
};

/* Checks a header read from the flash for a memory [mem_base, mem_base + mem_bytes): all but the
 * payload's CRC, which boot_image_check_payload() checks once the payload is copied. */
enum boot_image_status boot_image_check_header(const uint32_t header[BOOT_IMAGE_HEADER_WORDS],
                                               uint32_t mem_base, uint32_t mem_bytes);

/* The payload's CRC against the header's (header already checked). */
enum boot_image_status boot_image_check_payload(const uint32_t header[BOOT_IMAGE_HEADER_WORDS],
                                                const uint8_t *payload);

/* One line of text for each status ("no firmware image (magic ...)": the caller adds numbers). */
const char *boot_image_status_text(enum boot_image_status status);

#endif /* BOOT_IMAGE_H */
