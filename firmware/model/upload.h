/*
 * upload.h — the UART upload's receiver (docs/upload-protocol.md). Pure code: bytes in, responses
 * and a validated mesh file out; the frame loop (app.c) owns the UART and the swap.
 *
 * Every UART byte goes through upload_feed first. It returns false for a byte that is the key
 * decoder's (outside a transfer, not a frame's start) and true for one the protocol took. Once
 * per frame upload_frame_end runs the timeouts; the frame loop then prints the queued responses
 * (upload_response_line) and, when upload_ready says so, swaps the model in and calls
 * upload_taken.
 *
 * Memory is the caller's: the staging buffer (the file, docs/mesh-format.md) and a bitmap of its
 * chunks, one bit per UPLOAD_CHUNK_MIN bytes of the buffer (UPLOAD_MAP_BYTES).
 */
#ifndef UPLOAD_H
#define UPLOAD_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "model/meshfile.h"

#define UPLOAD_SOF0 0xA5u
#define UPLOAD_SOF1 0xC3u
#define UPLOAD_HEADER_BYTES 8u      /* SOF0 SOF1 type session seq16 len16 */
#define UPLOAD_CRC_BYTES 4u
#define UPLOAD_CHUNK_MIN 64u
#define UPLOAD_CHUNK_MAX 512u
#define UPLOAD_MAX_PAYLOAD (UPLOAD_CHUNK_MAX + 4u)  /* DATA: offset + a chunk */
#define UPLOAD_BEGIN_BYTES 10u

enum upload_type { UPLOAD_BEGIN = 1, UPLOAD_DATA = 2, UPLOAD_COMMIT = 3, UPLOAD_ABORT = 4 };

/* Frames without a valid frame before an open transfer is abandoned: 15 s at 60 frames/s, longer
 * than the host tool's resend timeout (10 s by default) so that a frame lost at the very end of a
 * window, which nothing after it can reveal, is resent before the receiver gives up; and frames
 * without a byte before a partly received frame is dropped (a sender that stopped mid-frame). */
#ifndef UPLOAD_TIMEOUT_FRAMES
#define UPLOAD_TIMEOUT_FRAMES 900u
#endif
#define UPLOAD_PARTIAL_TIMEOUT_FRAMES 30u
/* Frames after the last protocol byte (a frame, a SOF or a byte >= 0x80) in which stray bytes are
 * discarded rather than taken for keys: a frame's remains arrive within milliseconds of it, and
 * keys typed after an upload work again half a second later (at 60 frames/s). */
#define UPLOAD_QUIET_FRAMES 30u
/* Responses held per frame; more in one frame are lost (counted: the sender's timeout resends). */
#define UPLOAD_MAX_RESPONSES 32u

/* Bitmap bytes for a staging buffer of cap bytes. */
#define UPLOAD_MAP_BYTES(cap) (((cap) + UPLOAD_CHUNK_MIN * 8u - 1u) / (UPLOAD_CHUNK_MIN * 8u))

enum upload_response_kind {
    UPLOAD_R_ACK,        /* session, seq */
    UPLOAD_R_NAK,        /* session, seq, reason */
    UPLOAD_R_NAK_CRC,
    UPLOAD_R_NAK_BIG,    /* a: the len field */
    UPLOAD_R_REJECT,     /* session, reason (+ the receiver's message for UPLOAD_REASON_MESH) */
    UPLOAD_R_OK,         /* session, a: faces, b: vertices */
    UPLOAD_R_ABANDONED,  /* session, a: stray bytes ignored during it */
};

enum upload_reason {
    UPLOAD_REASON_NONE = 0,
    UPLOAD_REASON_SESSION,     /* nak: not the open transfer */
    UPLOAD_REASON_OFFSET,      /* nak: DATA offset not a chunk of the file */
    UPLOAD_REASON_LENGTH,      /* nak: payload length wrong for its type or offset */
    UPLOAD_REASON_STATE,       /* nak: DATA or COMMIT with no open transfer */
    UPLOAD_REASON_TYPE,        /* nak: unknown frame type */
    UPLOAD_REASON_CAPACITY,    /* reject BEGIN: the file is larger than the staging buffer */
    UPLOAD_REASON_CHUNK,       /* reject BEGIN: chunk_bytes outside 64..512 */
    UPLOAD_REASON_INCOMPLETE,  /* reject COMMIT: a: chunks missing */
    UPLOAD_REASON_CRC,         /* reject COMMIT: the whole file's CRC */
    UPLOAD_REASON_MESH,        /* reject COMMIT: the validator's message */
};

struct upload_response {
    uint8_t kind;
    uint8_t reason;
    uint8_t session;
    uint16_t seq;
    uint32_t a;
    uint32_t b;
};

struct upload_rx {
    /* The caller's memory and the build's capacities (upload_init). */
    uint8_t *buf;
    uint32_t cap;
    uint8_t *map;
    uint32_t map_bytes;
    uint32_t max_verts;
    uint32_t max_faces;
    /* The frame being received. */
    uint8_t state;
    uint16_t pos;
    uint8_t head[UPLOAD_HEADER_BYTES - 2u];    /* type session seq16 len16 */
    uint16_t len;
    uint8_t payload[UPLOAD_MAX_PAYLOAD];
    uint8_t crc[UPLOAD_CRC_BYTES];
    uint32_t partial_idle;   /* frames without a byte while a frame is partly received */
    bool byte_this_frame;
    /* The open transfer (session 0: none). */
    uint8_t session;
    uint8_t committed_session;  /* the last transfer committed (a repeated COMMIT is acked) */
    uint32_t total;
    uint32_t total_crc;
    uint32_t chunk;
    uint32_t chunks;
    uint32_t received;       /* distinct chunks */
    uint32_t idle;           /* frames since the last valid frame */
    uint32_t quiet;          /* frames left in which stray bytes are discarded, not keys
                              * (UPLOAD_QUIET_FRAMES after the last protocol byte) */
    uint32_t stray;          /* bytes discarded outside frames since the transfer opened */
    /* The result: a validated file in buf (upload_ready). */
    bool ready;
    bool staging_valid;      /* buf holds the last committed file (a BEGIN clears it) */
    struct meshfile_info info;
    char message[80];        /* the last REJECT's reason (UPLOAD_REASON_MESH) */
    /* This frame's responses. */
    struct upload_response resp[UPLOAD_MAX_RESPONSES];
    uint32_t resp_count;
    uint32_t resp_lost;
    /* Totals since upload_init. */
    uint32_t frames_ok;
    uint32_t frames_bad;
};

void upload_init(struct upload_rx *rx, uint8_t *buf, uint32_t cap, uint8_t *map,
                 uint32_t map_bytes, uint32_t max_verts, uint32_t max_faces);

/* One UART byte: true when the protocol took it, false when it is a key. */
bool upload_feed(struct upload_rx *rx, uint8_t byte);

/* Once per frame, after its bytes: timeouts. */
void upload_frame_end(struct upload_rx *rx);

/* A committed, validated file waits in rx->buf (rx->info has its counts). */
static inline bool upload_ready(const struct upload_rx *rx) { return rx->ready; }
/* The frame loop has swapped it in (the buffer stays the committed file until the next BEGIN). */
static inline void upload_taken(struct upload_rx *rx) { rx->ready = false; }

/* Response i of this frame as one line without '\n' ("@up ack 7 12"); clear them with
 * upload_responses_clear after printing. */
void upload_response_line(const struct upload_rx *rx, uint32_t i, char *out, size_t cap);
static inline void upload_responses_clear(struct upload_rx *rx) { rx->resp_count = 0; }

#endif /* UPLOAD_H */
