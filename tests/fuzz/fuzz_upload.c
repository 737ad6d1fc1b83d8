/*
 * fuzz_upload — libFuzzer target for the UART upload's receiver (firmware/model/upload.c) and,
 * through its COMMIT, the mesh file's validator and loader (model/meshfile.c).
 *
 * The input is a script of operations, so that well-formed frames (correct CRCs) reach the deep
 * states that random bytes never would, and the line's faults are all in reach:
 *   0 end of a frame (the receiver's timeouts)   1 BEGIN   2 DATA of chunk k   3 COMMIT   4 ABORT
 *   5 raw bytes (a length, then the bytes)      6 patch a byte of the file being sent
 *   7 a frame with a broken CRC or length       8 refresh the file's own CRC after patches
 * The file sent starts as the test cube (tests/upload/test_files.h).
 *
 * Properties (a violation aborts; ASan + UBSan are on):
 *   - a frame's responses never exceed the queue, and every response line starts "@up " and fits;
 *   - a byte the receiver hands to the keys is ASCII and came while no transfer was open;
 *   - upload_ready implies the staged file passes meshfile_check at the build's capacity again,
 *     and loads into a mesh of that capacity with every vertex inside the header's box;
 *   - after the script, UPLOAD_TIMEOUT_FRAMES frames without bytes close any transfer and drop any
 *     partial frame (no state in which the receiver waits forever).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "math/real.h"
#include "model/meshfile.h"
#include "model/upload.h"
#include "render/mesh.h"
#include "upload/test_files.h"
#include "fuzz_common.h"

/* One of the properties listed above. */
#define PROPERTY(cond) REQUIRE(cond, "%s", "a property of this harness (its header) failed")

#define CAP_BYTES 1024u
#define CAP_VERTS 16u
#define CAP_FACES 24u

static uint8_t buf[CAP_BYTES];
static uint8_t map[UPLOAD_MAP_BYTES(CAP_BYTES)];
static struct upload_rx rx;
static uint8_t file[CAP_BYTES];
static uint32_t file_size;

static void check_responses(void)
{
    char line[112];

    PROPERTY(rx.resp_count <= UPLOAD_MAX_RESPONSES);
    for (uint32_t i = 0; i < rx.resp_count; i++) {
        upload_response_line(&rx, i, line, sizeof line);
        PROPERTY(strncmp(line, "@up ", 4) == 0);
        PROPERTY(strlen(line) < sizeof line - 1u);
    }
    upload_responses_clear(&rx);
}

static void check_ready(void)
{
    static vec3 verts[CAP_VERTS];
    static struct mesh_face faces[CAP_FACES];
    static uvec3 normals[CAP_FACES];
    struct meshfile_info info;
    struct mesh m;

    if (!upload_ready(&rx)) {
        return;
    }
    PROPERTY(meshfile_check(buf, rx.total, CAP_VERTS, CAP_FACES, &info) == MESHFILE_OK);
    mesh_init(&m, verts, CAP_VERTS, faces, CAP_FACES, normals, CAP_FACES);
    PROPERTY(meshfile_load(buf, &info, &m));
    for (uint32_t v = 0; v < m.vert_count; v++) {
        PROPERTY(real_to_q16(m.verts[v].x) >= info.box_lo[0] * 16 &&
                   real_to_q16(m.verts[v].x) <= info.box_hi[0] * 16);
    }
    upload_taken(&rx);
}

static void feed(const uint8_t *b, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        const bool open = rx.session != 0u;

        if (!upload_feed(&rx, b[i])) {
            PROPERTY(b[i] < 0x80u && !open);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t fr[12u + UPLOAD_MAX_PAYLOAD + 8u];
    uint8_t session = 1;
    uint32_t chunk = 64;
    size_t i = 0;

    upload_init(&rx, buf, sizeof buf, map, sizeof map, CAP_VERTS, CAP_FACES);
    file_size = cube_file(file);
#define NEXT() ((i < size) ? data[i++] : 0u)
    while (i < size) {
        const uint8_t op = NEXT() % 9u;

        switch (op) {
        case 0:
            upload_frame_end(&rx);
            break;
        case 1: {
            uint8_t p[10];
            const uint8_t how = NEXT();

            session = NEXT();
            chunk = 32u + (uint32_t)NEXT() * 2u;   /* 32 .. 542: some outside 64..512 */
            put32(p, (how & 1u) ? file_size : file_size + NEXT());
            put32(p + 4, (how & 2u) ? crc32_update(0, file, file_size) : (uint32_t)NEXT());
            put16(p + 8, chunk);
            feed(fr, upload_frame_bytes(fr, UPLOAD_BEGIN, session, 0, p, 10));
            break;
        }
        case 2: {
            uint8_t p[4 + UPLOAD_CHUNK_MAX + 2];
            const uint32_t k = NEXT();
            const uint32_t c = (chunk >= 1u && chunk <= UPLOAD_CHUNK_MAX) ? chunk : 64u;
            const uint32_t off = k * c;
            uint32_t n = (off < file_size) ? file_size - off : 0u;

            if (n > c) {
                n = c;
            }
            put32(p, off);
            memcpy(p + 4, file + (off < file_size ? off : 0u), n);
            feed(fr, upload_frame_bytes(fr, UPLOAD_DATA, session, (uint16_t)(k + 1u), p, 4u + n));
            break;
        }
        case 3:
            feed(fr, upload_frame_bytes(fr, UPLOAD_COMMIT, session, 0, 0, 0));
            break;
        case 4:
            feed(fr, upload_frame_bytes(fr, UPLOAD_ABORT, session, 0, 0, 0));
            break;
        case 5: {
            uint32_t n = NEXT();

            if (n > size - i) {
                n = (uint32_t)(size - i);
            }
            feed(data + i, n);
            i += n;
            break;
        }
        case 6: {
            const uint32_t hi = NEXT();
            const uint32_t off = ((hi << 8) | NEXT()) % file_size;

            file[off] = NEXT();
            break;
        }
        case 7: {
            const uint8_t type = (uint8_t)(1u + NEXT() % 4u);
            const uint32_t n = upload_frame_bytes(fr, type, session, 0, file, NEXT() % 64u);
            const uint8_t where = NEXT();

            fr[where % n] ^= (uint8_t)(1u << (NEXT() % 8u));
            feed(fr, n);
            break;
        }
        default:
            put32(file + file_size - 4u, crc32_update(0, file, file_size - 4u));
            break;
        }
        check_responses();
        check_ready();
    }
#undef NEXT
    /* Silence: every transfer and partial frame ends. */
    for (uint32_t f = 0; f <= UPLOAD_TIMEOUT_FRAMES; f++) {
        upload_frame_end(&rx);
        check_responses();
    }
    PROPERTY(rx.session == 0u);
    PROPERTY(rx.state == 0u);
    return 0;
}
