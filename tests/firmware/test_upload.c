/*
 * test_upload.c — the mesh file's validator and loader (model/meshfile.c), CRC-32, and the UART
 * upload's receiver (model/upload.c) against docs/mesh-format.md and docs/upload-protocol.md:
 * every rule broken once, every fault the line can make.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "math/real.h"
#include "model/crc32.h"
#include "model/meshfile.h"
#include "model/upload.h"
#include "render/mesh.h"
#include "unit.h"

#include "upload/test_files.h"

static void refresh_crc(uint8_t *f, uint32_t size)
{
    put32(f + size - 4u, crc32_update(0, f, size - 4u));
}

void test_crc32_vectors(void)
{
    const uint8_t *s = (const uint8_t *)"123456789";

    CHECK_EQ(crc32_update(0, s, 9), 0xCBF43926u);        /* the CRC-32 check value */
    CHECK_EQ(crc32_update(crc32_update(0, s, 4), s + 4, 5), 0xCBF43926u);
    CHECK_EQ(crc32_update(0, s, 0), 0u);
}

void test_meshfile_valid_and_loaded(void)
{
    static uint8_t f[512];
    static vec3 verts[8];
    static struct mesh_face faces[12];
    static uvec3 normals[12];
    struct meshfile_info info;
    struct mesh m;
    const uint32_t size = cube_file(f);

    CHECK_EQ(size, 36u + 6u * 8u + 14u * 12u);
    CHECK_EQ(meshfile_check(f, size, 8, 12, &info), MESHFILE_OK);
    CHECK_EQ(info.verts, 8);
    CHECK_EQ(info.faces, 12);
    CHECK_EQ(meshfile_check(f, size, 7, 12, &info), MESHFILE_E_VERT_COUNT);
    CHECK_EQ(info.limit, 7);
    CHECK_EQ(meshfile_check(f, size, 8, 11, &info), MESHFILE_E_FACE_COUNT);
    CHECK_EQ(meshfile_check(f, size, 8, 12, &info), MESHFILE_OK);
    mesh_init(&m, verts, 8, faces, 12, normals, 12);
    CHECK(meshfile_load(f, &info, &m));
    CHECK_EQ(m.vert_count, 8);
    CHECK_EQ(m.face_count, 12);
    /* Q3.12 4.0 is exactly 4.0; the unit normals exactly 1 on their axis. */
    CHECK_EQ(real_to_q16(m.verts[7].x), 4 * 65536);
    CHECK_EQ(real_to_q16(m.verts[0].y), -4 * 65536);
    CHECK_EQ(real_to_q16(real_from_unit(m.normals[2].z)), 65536);   /* face 2: the +z quad */
    CHECK_EQ(m.faces[11].material, 6);
    CHECK_EQ(m.faces[11].normal, 11);
    /* Too small a mesh: refused, not overrun. */
    mesh_init(&m, verts, 7, faces, 12, normals, 12);
    CHECK(!meshfile_load(f, &info, &m));
}

/* Each rule broken once gives its own error; every truncation and single bit flip is refused. */
void test_meshfile_rules(void)
{
    static uint8_t good[512];
    static uint8_t f[520];
    struct meshfile_info info;
    const uint32_t size = cube_file(good);
    const uint32_t face5 = 32u + 48u + 5u * 14u;
    char msg[96];
    struct {
        uint32_t off;
        uint8_t value;
        int err;
    } cases[] = {
        {0, 'X', MESHFILE_E_MAGIC},
        {4, 2, MESHFILE_E_VERSION},
        {6, 8, MESHFILE_E_FRAC_BITS},
        {28, 1, MESHFILE_E_FLAGS},
        {8, 2, MESHFILE_E_VERT_COUNT},                  /* 2 vertices: fewer than a triangle */
        {17, 0xD0, MESHFILE_E_VERTEX_OUTSIDE},          /* box_lo.x raised to -12288 */
        {face5 + 2, 9, MESHFILE_E_INDEX},
        {face5 + 2, 0, MESHFILE_E_REPEATED_INDEX},      /* face 5 is (2, ?, 3): v1 = v0 */
        {face5 + 7, 0x20, MESHFILE_E_NORMAL},           /* n.x = 0.5: |n| > 1 */
        {face5 + 12, 14, MESHFILE_E_MATERIAL},
        {face5 + 12, 0, MESHFILE_E_MATERIAL},
        {face5 + 13, 2, MESHFILE_E_FACE_FLAGS},
    };

    for (uint32_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        memcpy(f, good, size);
        if (cases[i].err == MESHFILE_E_REPEATED_INDEX) {
            f[face5 + 2] = f[face5];   /* v[1] = v[0] */
        } else {
            f[cases[i].off] = cases[i].value;
        }
        refresh_crc(f, size);
        CHECK_EQ(meshfile_check(f, size, 8, 12, &info), cases[i].err);
        meshfile_message(cases[i].err, &info, msg, sizeof msg);
        CHECK(strlen(msg) > 5u);
    }
    /* The box's lo above its hi. */
    memcpy(f, good, size);
    put16(f + 16, 16384);
    put16(f + 22, (uint32_t)(uint16_t)-16384);
    refresh_crc(f, size);
    CHECK_EQ(meshfile_check(f, size, 8, 12, &info), MESHFILE_E_BOX);
    /* A box that holds the vertices but is not theirs: lo.x lower than any vertex. */
    memcpy(f, good, size);
    put16(f + 16, (uint32_t)(uint16_t)-20000);
    refresh_crc(f, size);
    CHECK_EQ(meshfile_check(f, size, 8, 12, &info), MESHFILE_E_BOX);
    /* A coordinate of -8.0 (int16 -32768), with the box made to match: outside Q3.12's |c| < 8. */
    memcpy(f, good, size);
    put16(f + 16, 0x8000u);
    put16(f + 32, 0x8000u);
    refresh_crc(f, size);
    CHECK_EQ(meshfile_check(f, size, 8, 12, &info), MESHFILE_E_VERTEX_OUTSIDE);
    /* The CRC the caller computed, as the upload's COMMIT passes it. */
    CHECK_EQ(meshfile_check_known_crc(good, size, 8, 12, crc32_update(0, good, size - 4u), &info),
             MESHFILE_OK);
    CHECK_EQ(meshfile_check_known_crc(good, size, 8, 12, 1234u, &info), MESHFILE_E_CRC);
        /* Size: two bytes more than the counts make it (CRC over all but the last four). */
    memcpy(f, good, size - 4u);
    f[size - 4u] = 0;
    f[size - 3u] = 0;
    refresh_crc(f, size + 2u);
    CHECK_EQ(meshfile_check(f, size + 2u, 8, 12, &info), MESHFILE_E_SIZE);
    /* Every truncation is refused (and reads nothing past len: ASan in the fuzzer checks that). */
    for (uint32_t len = 0; len < size; len++) {
        CHECK(meshfile_check(good, len, 8, 12, &info) != MESHFILE_OK);
    }
    /* Every single bit flip is refused (the CRC catches what the rules do not). */
    for (uint32_t bit = 0; bit < size * 8u; bit++) {
        memcpy(f, good, size);
        f[bit / 8u] ^= (uint8_t)(1u << (bit % 8u));
        CHECK(meshfile_check(f, size, 8, 12, &info) != MESHFILE_OK);
    }
    CHECK_EQ(meshfile_check(good, size, 8, 12, &info), MESHFILE_OK);
}

/* ---- the receiver ------------------------------------------------------------------------ */

#define T_CAP 4096u
static uint8_t t_buf[T_CAP];
static uint8_t t_map[UPLOAD_MAP_BYTES(T_CAP)];
static struct upload_rx t_rx;

static uint32_t frame(uint8_t *out, uint8_t type, uint8_t session, uint16_t seq,
                      const uint8_t *payload, uint32_t len)
{
    return upload_frame_bytes(out, type, session, seq, payload, len);
}

static uint32_t begin_frame(uint8_t *out, uint8_t session, uint32_t total, uint32_t crc,
                            uint32_t chunk)
{
    uint8_t p[10];

    put32(p, total);
    put32(p + 4, crc);
    put16(p + 8, chunk);
    return frame(out, UPLOAD_BEGIN, session, 0, p, 10);
}

static uint32_t data_frame(uint8_t *out, uint8_t session, const uint8_t *file, uint32_t total,
                           uint32_t chunk, uint32_t k)
{
    uint8_t p[4 + UPLOAD_CHUNK_MAX];
    const uint32_t off = k * chunk;
    const uint32_t n = (total - off < chunk) ? total - off : chunk;

    put32(p, off);
    memcpy(p + 4, file + off, n);
    return frame(out, UPLOAD_DATA, session, (uint16_t)(k + 1u), p, 4u + n);
}

/* Feed bytes; returns how many the protocol left for the keys. */
static uint32_t feed(const uint8_t *b, uint32_t n)
{
    uint32_t keys = 0;

    for (uint32_t i = 0; i < n; i++) {
        keys += upload_feed(&t_rx, b[i]) ? 0u : 1u;
    }
    return keys;
}

/* The frame's response lines joined by '|', then cleared. */
static const char *responses(void)
{
    static char all[2048];
    char line[112];

    all[0] = 0;
    for (uint32_t i = 0; i < t_rx.resp_count; i++) {
        upload_response_line(&t_rx, i, line, sizeof line);
        if (i != 0u) {
            strcat(all, "|");
        }
        strcat(all, line);
    }
    upload_responses_clear(&t_rx);
    return all;
}

#define CHECK_STR(a, b)                                                             \
    do {                                                                            \
        const char *unit_s_ = (a);                                                  \
        if (strcmp(unit_s_, (b)) != 0) {                                            \
            unit_fail(__FILE__, __LINE__, "'%s' != '%s'", unit_s_, (b));            \
        }                                                                           \
    } while (0)

/* BEGIN (whole-file CRC crc) and every DATA frame of file in 64-byte chunks, their answers
 * cleared: what most refusal tests start from. */
static void send_file(uint8_t session, const uint8_t *file, uint32_t size, uint32_t crc)
{
    uint8_t fr[600];

    feed(fr, begin_frame(fr, session, size, crc, 64));
    for (uint32_t k = 0; k < (size + 63u) / 64u; k++) {
        feed(fr, data_frame(fr, session, file, size, 64, k));
    }
    (void)responses();
}

static void rx_reset(void)
{
    upload_init(&t_rx, t_buf, T_CAP, t_map, sizeof t_map, 8, 12);
}

/* The file the transfer tests send: the cube, its size and CRC (rx_reset_with_cube fills it). */
static struct {
    uint8_t file[512];
    uint32_t size;
    uint32_t crc;
} t_cube;

static void rx_reset_with_cube(void)
{
    rx_reset();
    t_cube.size = cube_file(t_cube.file);
    t_cube.crc = crc32_update(0, t_cube.file, t_cube.size);
}

/* A whole transfer of the cube in 64-byte chunks: acks, ok, the file in the buffer. */
void test_upload_transfer(void)
{
    uint8_t fr[600];

    rx_reset_with_cube();
    const uint32_t chunks = (t_cube.size + 63u) / 64u;

    CHECK_EQ(feed((const uint8_t *)"wasd", 4), 4);   /* keys pass through outside a transfer */
    CHECK_EQ(feed(fr, begin_frame(fr, 7, t_cube.size, t_cube.crc, 64)), 0);
    CHECK_STR(responses(), "@up ack 7 0");
    for (uint32_t k = 0; k < chunks; k++) {
        CHECK_EQ(feed(fr, data_frame(fr, 7, t_cube.file, t_cube.size, 64, k)), 0);
    }
    CHECK_EQ(t_rx.resp_count, chunks);
    (void)responses();
    CHECK(!upload_ready(&t_rx));
    feed(fr, frame(fr, UPLOAD_COMMIT, 7, (uint16_t)(chunks + 1u), 0, 0));
    CHECK_STR(responses(), "@up ok 7 faces 12 verts 8");
    CHECK(upload_ready(&t_rx));
    CHECK(t_rx.staging_valid);
    CHECK_EQ(memcmp(t_buf, t_cube.file, t_cube.size), 0);
    CHECK_EQ(t_rx.total, t_cube.size);
    /* The ok was lost: a resent COMMIT is answered again. */
    feed(fr, frame(fr, UPLOAD_COMMIT, 7, (uint16_t)(chunks + 1u), 0, 0));
    CHECK_STR(responses(), "@up ok 7 faces 12 verts 8");
    upload_taken(&t_rx);
    CHECK(!upload_ready(&t_rx));
    /* Keys are ignored for the quiet time after a transfer, then pass again. */
    CHECK_EQ(feed((const uint8_t *)"w", 1), 0);
    for (uint32_t i = 0; i + 1u < UPLOAD_QUIET_FRAMES; i++) {
        upload_frame_end(&t_rx);
    }
    CHECK_EQ(feed((const uint8_t *)"w", 1), 0);
    upload_frame_end(&t_rx);
    upload_frame_end(&t_rx);
    CHECK_EQ(feed((const uint8_t *)"w", 1), 1);
    /* A new BEGIN: the buffer no longer holds the committed file. */
    feed(fr, begin_frame(fr, 8, t_cube.size, t_cube.crc, 64));
    CHECK_STR(responses(), "@up ack 8 0");
    CHECK(!t_rx.staging_valid);
}

/* Duplicated, reordered, corrupted, oversized and truncated frames, and garbage between them. */
void test_upload_line_faults(void)
{
    uint8_t fr[600];
    uint8_t fr2[600];
    uint32_t n;

    rx_reset_with_cube();
    const uint32_t chunks = (t_cube.size + 63u) / 64u;

    /* An oversized frame: nak big, and the next frame is still understood. */
    n = frame(fr, UPLOAD_DATA, 3, 1, t_cube.file, 8);
    put16(fr + 6, 600);
    CHECK_EQ(feed(fr, 8), 0);
    CHECK_STR(responses(), "@up nak big 600");
    CHECK_EQ(feed(fr + 8, n - 8u), 0);   /* its remains: stray, not keys (quiet after SOF0) */
    feed(fr, begin_frame(fr, 3, t_cube.size, t_cube.crc, 64));
    CHECK_STR(responses(), "@up ack 3 0");
    /* Chunks in reverse order, each twice, one corrupted first, garbage between. */
    for (uint32_t k = chunks; k-- > 0;) {
        static const uint8_t garbage[] = {0x80, 'q', 0xA5, 'w', 0xFF, '1'};

        n = data_frame(fr, 3, t_cube.file, t_cube.size, 64, k);
        memcpy(fr2, fr, n);
        fr2[20] ^= 0x10;
        CHECK_EQ(feed(fr2, n), 0);
        CHECK_STR(responses(), "@up nak crc");
        CHECK_EQ(feed(garbage, sizeof garbage), 0);   /* never keys during a transfer */
        CHECK_EQ(feed(fr, n), 0);
        CHECK_EQ(feed(fr, n), 0);
        CHECK_EQ(t_rx.resp_count, 2);
        (void)responses();
    }
    CHECK_EQ(t_rx.received, chunks);
    /* A truncated frame: the receiver waits, then drops it once no byte came for its timeout (the
     * frame in which its bytes came does not count) and resyncs. */
    n = frame(fr, UPLOAD_COMMIT, 3, (uint16_t)(chunks + 1u), 0, 0);
    feed(fr, 5);
    for (uint32_t i = 0; i < UPLOAD_PARTIAL_TIMEOUT_FRAMES; i++) {
        upload_frame_end(&t_rx);
    }
    CHECK_EQ(t_rx.state != 0u, 1);   /* still waiting for the rest */
    upload_frame_end(&t_rx);
    CHECK_EQ(t_rx.state, 0);
    CHECK_STR(responses(), "");
    feed(fr, n);
    CHECK_STR(responses(), "@up ok 3 faces 12 verts 8");
    CHECK(upload_ready(&t_rx));
    CHECK_EQ(memcmp(t_buf, t_cube.file, t_cube.size), 0);
}

/* Refusals: capacity, chunk size, frames of no transfer or another, an incomplete file, a file
 * whose CRC or rules fail; an abandoned transfer times out; keys outside stay keys. */
void test_upload_refusals(void)
{
    uint8_t fr[600];

    rx_reset_with_cube();
    feed(fr, begin_frame(fr, 1, T_CAP + 1u, t_cube.crc, 64));
    CHECK_STR(responses(), "@up reject 1 capacity: 4097 bytes, this build holds 4096");
    feed(fr, begin_frame(fr, 1, t_cube.size, t_cube.crc, 32));
    CHECK_STR(responses(), "@up reject 1 chunk: 32 bytes (64 to 512)");
    feed(fr, data_frame(fr, 1, t_cube.file, t_cube.size, 64, 0));
    CHECK_STR(responses(), "@up nak 1 1 state");
    feed(fr, begin_frame(fr, 2, t_cube.size, t_cube.crc, 64));
    CHECK_STR(responses(), "@up ack 2 0");
    feed(fr, data_frame(fr, 5, t_cube.file, t_cube.size, 64, 0));
    CHECK_STR(responses(), "@up nak 5 1 session");
    /* Offsets and lengths. */
    {
        uint8_t p[8] = {0};

        put32(p, 65);
        feed(fr, frame(fr, UPLOAD_DATA, 2, 1, p, 8));
        CHECK_STR(responses(), "@up nak 2 1 offset");
        put32(p, 0);
        feed(fr, frame(fr, UPLOAD_DATA, 2, 1, p, 8));
        CHECK_STR(responses(), "@up nak 2 1 length");
        feed(fr, frame(fr, 9, 2, 1, p, 8));
        CHECK_STR(responses(), "@up nak 2 1 type");
    }
    feed(fr, data_frame(fr, 2, t_cube.file, t_cube.size, 64, 0));
    (void)responses();
    feed(fr, frame(fr, UPLOAD_COMMIT, 2, 9, 0, 0));
    CHECK(strstr(responses(), "@up reject 2 incomplete:") != 0);
    CHECK(!upload_ready(&t_rx));
    /* The whole file's CRC. */
    send_file(3, t_cube.file, t_cube.size, t_cube.crc ^ 1u);
    feed(fr, frame(fr, UPLOAD_COMMIT, 3, 0, 0, 0));
    CHECK_STR(responses(), "@up reject 3 crc: the file's CRC does not match BEGIN's");
    /* A file that breaks a rule: the validator's message. */
    t_cube.file[32 + 48 + 2] = 9;
    refresh_crc(t_cube.file, t_cube.size);
    send_file(4, t_cube.file, t_cube.size, crc32_update(0, t_cube.file, t_cube.size));
    feed(fr, frame(fr, UPLOAD_COMMIT, 4, 0, 0, 0));
    CHECK_STR(responses(), "@up reject 4 mesh: face 0: index 9 out of range (8 vertices)");
    CHECK(!upload_ready(&t_rx));
    /* Abandoned half way: the timeout closes it, and counts what it ignored. */
    feed(fr, begin_frame(fr, 6, t_cube.size, t_cube.crc, 64));
    feed((const uint8_t *)"xyz", 3);
    (void)responses();
    for (uint32_t i = 0; i + 1u < UPLOAD_TIMEOUT_FRAMES; i++) {
        upload_frame_end(&t_rx);
    }
    CHECK_STR(responses(), "");
    upload_frame_end(&t_rx);
    CHECK_STR(responses(), "@up abandoned 6 (3 stray bytes ignored)");
    CHECK_EQ(t_rx.session, 0);
    /* A new session replaces an open one. */
    feed(fr, begin_frame(fr, 10, t_cube.size, t_cube.crc, 64));
    feed(fr, begin_frame(fr, 11, t_cube.size, t_cube.crc, 64));
    CHECK_STR(responses(), "@up ack 10 0|@up abandoned 10 (0 stray bytes ignored)|@up ack 11 0");
}

/* Sessions: 0 is refused; a refused BEGIN leaves an open transfer alone; a sender starting its own
 * session over is not told it was abandoned; a repeated COMMIT is answered with ok only while the
 * committed file is still in the buffer. */
void test_upload_sessions(void)
{
    uint8_t fr[600];

    rx_reset_with_cube();
    feed(fr, begin_frame(fr, 0, t_cube.size, t_cube.crc, 64));
    CHECK_STR(responses(), "@up nak 0 0 session");
    CHECK_EQ(t_rx.session, 0);
    /* Commit session 7. */
    send_file(7, t_cube.file, t_cube.size, t_cube.crc);
    feed(fr, frame(fr, UPLOAD_COMMIT, 7, 0, 0, 0));
    (void)responses();
    CHECK(t_rx.staging_valid);
    /* Session 7 again, with another file that fails: its repeated COMMIT must not get the old ok. */
    feed(fr, begin_frame(fr, 7, t_cube.size, t_cube.crc ^ 1u, 64));
    CHECK_STR(responses(), "@up ack 7 0");
    /* a resent BEGIN (acked again), then the chunks */
    send_file(7, t_cube.file, t_cube.size, t_cube.crc ^ 1u);
    feed(fr, frame(fr, UPLOAD_COMMIT, 7, 0, 0, 0));
    CHECK_STR(responses(), "@up reject 7 crc: the file's CRC does not match BEGIN's");
    feed(fr, frame(fr, UPLOAD_COMMIT, 7, 0, 0, 0));
    CHECK_STR(responses(), "@up nak 7 0 state");
    /* An open transfer survives a refused BEGIN of another sender. */
    feed(fr, begin_frame(fr, 8, t_cube.size, t_cube.crc, 64));
    feed(fr, data_frame(fr, 8, t_cube.file, t_cube.size, 64, 0));
    (void)responses();
    feed(fr, begin_frame(fr, 9, t_cube.size, t_cube.crc, 32));
    CHECK_STR(responses(), "@up reject 9 chunk: 32 bytes (64 to 512)");
    feed(fr, begin_frame(fr, 9, T_CAP + 1u, t_cube.crc, 64));
    CHECK(strncmp(responses(), "@up reject 9 capacity", 21) == 0);
    CHECK_EQ(t_rx.session, 8);
    CHECK_EQ(t_rx.received, 1);
    /* Session 8 starting over with other parameters: a fresh transfer, not "abandoned". */
    feed(fr, begin_frame(fr, 8, t_cube.size, t_cube.crc, 128));
    CHECK_STR(responses(), "@up ack 8 0");
    CHECK_EQ(t_rx.received, 0);
}

/* Responses beyond a frame's queue are counted as lost, not written past it. */
void test_upload_response_queue(void)
{
    uint8_t fr[64];
    const uint32_t n = frame(fr, UPLOAD_DATA, 1, 1, (const uint8_t *)"abcd", 4);

    rx_reset();
    for (uint32_t i = 0; i < UPLOAD_MAX_RESPONSES + 5u; i++) {
        feed(fr, n);
    }
    CHECK_EQ(t_rx.resp_count, UPLOAD_MAX_RESPONSES);
    CHECK_EQ(t_rx.resp_lost, 5);
}
