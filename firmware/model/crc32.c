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

#if CRC32_SLICE_TABLES
/* -DCRC32_SLICE_TABLES=1 (the boot program, bsp/soc/boot, which checks a whole firmware image and
 * has the on-chip RAM to itself): four 1 KiB tables made from the nibble table at the first call,
 * slice[0] the byte table, slice[k][b] the CRC of byte b followed by k zero bytes; an aligned word
 * at a time then takes four look-ups (slicing-by-4). On the SoC, an image in the SDRAM: 10.8 cycles
 * a byte, against 20 a byte at a time (one table; docs/boot.md). */
static uint32_t crc32_slice[4][256];
typedef uint32_t __attribute__((may_alias)) crc32_word;  /* the bytes read as words */

static void crc32_make_slice_tables(void)
{
    for (uint32_t b = 0; b < 256u; b++) {
        uint32_t c = b;
        c = (c >> 4) ^ crc32_nibble[c & 0xFu];
        crc32_slice[0][b] = (c >> 4) ^ crc32_nibble[c & 0xFu];
    }
    for (uint32_t k = 1; k < 4u; k++) {
        for (uint32_t b = 0; b < 256u; b++) {
            const uint32_t c = crc32_slice[k - 1u][b];
            crc32_slice[k][b] = (c >> 8) ^ crc32_slice[0][c & 0xFFu];
        }
    }
}
#endif

uint32_t crc32_update(uint32_t crc, const uint8_t *p, size_t n)
{
    crc = ~crc;
#if CRC32_SLICE_TABLES
    if (crc32_slice[0][1] == 0u) {  /* entry 1 is never 0 once made */
        crc32_make_slice_tables();
    }
    for (; n > 0u && ((uintptr_t)p & 3u) != 0u; n--) {  /* bytes up to a word boundary */
        crc = (crc >> 8) ^ crc32_slice[0][(crc ^ *p++) & 0xFFu];
    }
    /* A word holds the next four bytes little-endian, as the CRC's bit order takes them (the SoC
     * and the hosts this builds for are little-endian). */
    for (; n >= 4u; n -= 4u, p += 4) {
        crc ^= *(const crc32_word *)(const void *)p;
        crc = crc32_slice[3][crc & 0xFFu] ^ crc32_slice[2][(crc >> 8) & 0xFFu] ^
              crc32_slice[1][(crc >> 16) & 0xFFu] ^ crc32_slice[0][crc >> 24];
    }
    for (; n > 0u; n--) {
        crc = (crc >> 8) ^ crc32_slice[0][(crc ^ *p++) & 0xFFu];
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
