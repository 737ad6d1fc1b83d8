/*
 * fuzz_meshfile — libFuzzer target for the mesh file's validator and loader
 * (firmware/model/meshfile.c) on arbitrary bytes: what a built-in model or an upload could carry.
 *
 * So that mutations get past the CRC, the harness re-seals the input first when its last byte
 * is odd (the CRC of every byte but the last four written over them); the even half keeps the
 * input as it is, so the CRC check itself is fuzzed too.
 *
 * Properties (a violation aborts; ASan + UBSan are on):
 *   - meshfile_check reads only within the input, and its message fits and is never empty;
 *   - a file it accepts has exactly the size its counts make, loads into a mesh of the capacity
 *     it was checked against, every face's indices are below the vertex count and distinct, and
 *     every vertex lies inside the header's box (so within Q3.12, the +-8 units the format
 *     promises, and inside the firmware's world rule);
 *   - the mesh's bounding sphere is finite and at most the box's half-diagonal.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "math/real.h"
#include "model/crc32.h"
#include "model/meshfile.h"
#include "render/mesh.h"
#include "fuzz_common.h"

/* One of the properties listed above. */
#define PROPERTY(cond) REQUIRE(cond, "%s", "a property of this harness (its header) failed")

#define CAP 512u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t copy[65536];
    static vec3 verts[CAP];
    static struct mesh_face faces[CAP];
    static uvec3 normals[CAP];
    struct meshfile_info info;
    struct mesh m;
    char msg[96];
    uint8_t *f;
    int rc;

    if (size > sizeof copy) {
        return 0;
    }
    f = malloc(size ? size : 1u);   /* exactly size bytes: ASan sees any read past them */
    memcpy(f, data, size);
    if (size >= 8u && (data[size - 1u] & 1u)) {
        const uint32_t crc = crc32_update(0, f, size - 4u);

        f[size - 4u] = (uint8_t)crc;
        f[size - 3u] = (uint8_t)(crc >> 8);
        f[size - 2u] = (uint8_t)(crc >> 16);
        f[size - 1u] = (uint8_t)(crc >> 24);
    }
    rc = meshfile_check(f, size, CAP, CAP, &info);
    meshfile_message(rc, &info, msg, sizeof msg);
    PROPERTY(msg[0] != 0 && strlen(msg) < sizeof msg - 1u);
    if (rc == MESHFILE_OK) {
        PROPERTY(size == meshfile_bytes(info.verts, info.faces));
        mesh_init(&m, verts, CAP, faces, CAP, normals, CAP);
        PROPERTY(meshfile_load(f, &info, &m));
        PROPERTY(m.vert_count == info.verts && m.face_count == info.faces);
        for (uint32_t i = 0; i < m.face_count; i++) {
            const struct mesh_face *fc = &m.faces[i];

            PROPERTY(fc->v[0] < m.vert_count && fc->v[1] < m.vert_count && fc->v[2] < m.vert_count);
            PROPERTY(fc->v[0] != fc->v[1] && fc->v[1] != fc->v[2] && fc->v[0] != fc->v[2]);
        }
        for (uint32_t v = 0; v < m.vert_count; v++) {
            const int32_t c[3] = {real_to_q16(m.verts[v].x), real_to_q16(m.verts[v].y),
                                  real_to_q16(m.verts[v].z)};

            for (int k = 0; k < 3; k++) {
                PROPERTY(c[k] >= info.box_lo[k] * 16 && c[k] <= info.box_hi[k] * 16);
            }
        }
        PROPERTY(real_to_q16(m.radius) >= 0 && real_to_q16(m.radius) <= 14 * 65536);
    }
    free(f);
    return 0;
}
