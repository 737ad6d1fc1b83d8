/*
 * test_files.h — a mesh file and upload frames written from the tables of docs/mesh-format.md
 * and docs/upload-protocol.md, not by the firmware's code: the unit tests (tests/firmware) and the
 * fuzzers (tests/fuzz) build their inputs with these.
 */
#ifndef TEST_FILES_H
#define TEST_FILES_H

#include <stdint.h>
#include <string.h>

#include "model/crc32.h"
#include "model/meshfile.h"
#include "model/upload.h"

/* ---- a mesh file, written here from the format's table (not by the firmware's code) ---------- */

static inline void put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static inline void put32(uint8_t *p, uint32_t v)
{
    put16(p, v & 0xFFFFu);
    put16(p + 2, v >> 16);
}

/* The cube [-4, 4]^3 as 8 vertices and 12 faces, outward normals exact in Q1.14. */
static inline uint32_t cube_file(uint8_t *out)
{
    static const int8_t corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {-1, 1, 1},  {1, 1, 1}};
    static const uint8_t quad[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    static const int8_t normal[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0},
                                        {0, 1, 0},  {-1, 0, 0}, {1, 0, 0}};
    uint8_t *p = out;
    const uint32_t size = meshfile_bytes(8, 12);

    memset(out, 0, size);
    memcpy(p, "GMSH", 4);
    put16(p + 4, 1);
    put16(p + 6, 12);
    put32(p + 8, 8);
    put32(p + 12, 12);
    for (int k = 0; k < 3; k++) {
        put16(p + 16 + 2 * k, (uint32_t)(uint16_t)-16384);
        put16(p + 22 + 2 * k, 16384);
    }
    p += 32;
    for (int v = 0; v < 8; v++, p += 6) {
        for (int k = 0; k < 3; k++) {
            put16(p + 2 * k, (uint32_t)(uint16_t)(int16_t)(corner[v][k] * 16384));
        }
    }
    for (int q = 0; q < 6; q++) {
        for (int h = 0; h < 2; h++, p += 14) {
            const uint8_t a = quad[q][0];
            const uint8_t b = quad[q][h == 0 ? 1 : 2];
            const uint8_t c = quad[q][h == 0 ? 2 : 3];

            put16(p, a);
            put16(p + 2, b);
            put16(p + 4, c);
            for (int k = 0; k < 3; k++) {
                put16(p + 6 + 2 * k, (uint32_t)(uint16_t)(int16_t)(normal[q][k] * 16384));
            }
            p[12] = (uint8_t)(1 + q);
            p[13] = 0;
        }
    }
    put32(p, crc32_update(0, out, size - 4u));
    return size;
}

/* One upload frame's bytes (docs/upload-protocol.md's table); out holds 12 + len bytes. */
static inline uint32_t upload_frame_bytes(uint8_t *out, uint8_t type, uint8_t session, uint16_t seq,
                                          const uint8_t *payload, uint32_t len)
{
    out[0] = UPLOAD_SOF0;
    out[1] = UPLOAD_SOF1;
    out[2] = type;
    out[3] = session;
    put16(out + 4, seq);
    put16(out + 6, len);
    if (len != 0u) {
        memcpy(out + 8, payload, len);
    }
    put32(out + 8 + len, crc32_update(0, out + 2, 6u + len));
    return 12u + len;
}

#endif /* TEST_FILES_H */
