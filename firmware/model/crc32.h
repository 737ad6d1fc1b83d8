/*
 * crc32.h — CRC-32 as IEEE 802.3 and zlib define it (reflected polynomial 0xEDB88320, initial and
 * final XOR 0xFFFFFFFF), over the mesh file and the upload's frames. Pure code.
 */
#ifndef CRC32_H
#define CRC32_H

#include <stddef.h>
#include <stdint.h>

/* The CRC of p[0..n) continuing from crc (0 to start): crc32_update(crc32_update(0, a), b) is
 * the CRC of a followed by b, as zlib's crc32(). */
uint32_t crc32_update(uint32_t crc, const uint8_t *p, size_t n);

#endif /* CRC32_H */
