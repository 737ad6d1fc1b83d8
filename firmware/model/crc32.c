/*
 * crc32.c — see crc32.h. A 16-entry table, one nibble at a time: 64 bytes of table instead of
 * 1 KiB (RAM is the SoC's scarce resource), at about twice the instructions of a byte table —
 * a 34 KB upload costs some 1.5 M instructions in all, spread over its frames.
 */
#include "model/crc32.h"

static const uint32_t crc32_nibble[16] = {
    0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u,
    0x4DB26158u, 0x5005713Cu, 0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu,
    0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu,
};

#if CRC32_BYTE_TABLE
/* -DCRC32_BYTE_TABLE=1 (the boot program, bsp/soc/boot, which checks a whole firmware image and has
 * the on-chip RAM to itself): a byte at a time from a 1 KiB table made from the nibble table at the
 * first call — a third of the cycles. */
static uint32_t crc32_byte[256];

static void crc32_make_byte_table(void)
{
    for (uint32_t b = 0; b < 256u; b++) {
        uint32_t c = b;
        c = (c >> 4) ^ crc32_nibble[c & 0xFu];
        crc32_byte[b] = (c >> 4) ^ crc32_nibble[c & 0xFu];
    }
}
#endif

uint32_t crc32_update(uint32_t crc, const uint8_t *p, size_t n)
{
    crc = ~crc;
#if CRC32_BYTE_TABLE
    if (crc32_byte[1] == 0u) {  /* entry 1 is never 0 once made */
        crc32_make_byte_table();
    }
    for (size_t i = 0; i < n; i++) {
        crc = (crc >> 8) ^ crc32_byte[(crc ^ p[i]) & 0xFFu];
    }
#else
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        crc = (crc >> 4) ^ crc32_nibble[crc & 0xFu];
        crc = (crc >> 4) ^ crc32_nibble[crc & 0xFu];
    }
#endif
    return ~crc;
}
