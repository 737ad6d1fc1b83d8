/*
 * upload.c — see upload.h and docs/upload-protocol.md.
 */
#include "model/upload.h"

#include <stdio.h>
#include <string.h>

#include "model/crc32.h"
#include "model/le.h"

enum upload_state { RX_HUNT, RX_SOF1, RX_HEAD, RX_PAYLOAD, RX_CRC };


void upload_init(struct upload_rx *rx, uint8_t *buf, uint32_t cap, uint8_t *map,
                 uint32_t map_bytes, uint32_t max_verts, uint32_t max_faces)
{
    memset(rx, 0, sizeof *rx);
    rx->buf = buf;
    /* The bitmap bounds the file: one bit per UPLOAD_CHUNK_MIN bytes. */
    rx->cap = (cap < map_bytes * 8u * UPLOAD_CHUNK_MIN) ? cap : map_bytes * 8u * UPLOAD_CHUNK_MIN;
    rx->map = map;
    rx->map_bytes = map_bytes;
    rx->max_verts = max_verts;
    rx->max_faces = max_faces;
    rx->state = RX_HUNT;
}

static void upload_respond(struct upload_rx *rx, uint8_t kind, uint8_t reason, uint8_t session,
                           uint16_t seq, uint32_t a, uint32_t b)
{
    struct upload_response *r;

    if (rx->resp_count >= UPLOAD_MAX_RESPONSES) {
        rx->resp_lost++;
        return;
    }
    r = &rx->resp[rx->resp_count++];
    r->kind = kind;
    r->reason = reason;
    r->session = session;
    r->seq = seq;
    r->a = a;
    r->b = b;
}

static void upload_close(struct upload_rx *rx)
{
    rx->session = 0;
}

static bool upload_has_chunk(const struct upload_rx *rx, uint32_t k)
{
    return (rx->map[k >> 3] & (1u << (k & 7u))) != 0u;
}

static void upload_begin(struct upload_rx *rx, uint8_t session, uint16_t seq, const uint8_t *p,
                         uint32_t len)
{
    uint32_t total;
    uint32_t total_crc;
    uint32_t chunk;

    if (len != UPLOAD_BEGIN_BYTES) {
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_LENGTH, session, seq, 0, 0);
        return;
    }
    total = le32_at(p);
    total_crc = le32_at(p + 4);
    chunk = le16_at(p + 8);
    if (session == 0u) {
        /* Sessions are 1..255: 0 is "no transfer" here and could never be continued. */
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_SESSION, session, seq, 0, 0);
        return;
    }
    if (session == rx->session && total == rx->total && total_crc == rx->total_crc &&
        chunk == rx->chunk) {
        upload_respond(rx, UPLOAD_R_ACK, 0, session, seq, 0, 0);  /* a resent BEGIN */
        return;
    }
    /* Refusals first: a BEGIN that is refused leaves an open transfer and the staging buffer as
     * they were. */
    if (chunk < UPLOAD_CHUNK_MIN || chunk > UPLOAD_CHUNK_MAX) {
        upload_respond(rx, UPLOAD_R_REJECT, UPLOAD_REASON_CHUNK, session, seq, chunk, 0);
        return;
    }
    if (total < MESHFILE_BYTES(3u, 1u) || total > rx->cap) {
        upload_respond(rx, UPLOAD_R_REJECT, UPLOAD_REASON_CAPACITY, session, seq, total, rx->cap);
        return;
    }
    /* Another sender's transfer is replaced; the same sender starting over is not "abandoned". */
    if (rx->session != 0u && rx->session != session) {
        upload_respond(rx, UPLOAD_R_ABANDONED, 0, rx->session, 0, rx->stray, 0);
    }
    upload_close(rx);
    /* The staging buffer is about to be overwritten: it no longer holds the committed file. */
    rx->staging_valid = false;
    rx->ready = false;
    rx->committed_session = 0;   /* no repeated COMMIT may be answered with the old file's ok */
    rx->session = session;
    rx->total = total;
    rx->total_crc = total_crc;
    rx->chunk = chunk;
    rx->chunks = (total + chunk - 1u) / chunk;  /* <= cap / 64 <= map bits */
    rx->received = 0;
    rx->stray = 0;
    memset(rx->map, 0, (rx->chunks + 7u) / 8u);
    upload_respond(rx, UPLOAD_R_ACK, 0, session, seq, 0, 0);
}

static void upload_data(struct upload_rx *rx, uint8_t session, uint16_t seq, const uint8_t *p,
                        uint32_t len)
{
    uint32_t offset;
    uint32_t k;
    uint32_t want;

    if (len < 4u) {
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_LENGTH, session, seq, 0, 0);
        return;
    }
    offset = le32_at(p);
    if (offset % rx->chunk != 0u || offset >= rx->total) {
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_OFFSET, session, seq, offset, 0);
        return;
    }
    want = rx->total - offset;
    if (want > rx->chunk) {
        want = rx->chunk;
    }
    if (len - 4u != want) {
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_LENGTH, session, seq, len - 4u, want);
        return;
    }
    k = offset / rx->chunk;
    memcpy(rx->buf + offset, p + 4, want);
    if (!upload_has_chunk(rx, k)) {
        rx->map[k >> 3] = (uint8_t)(rx->map[k >> 3] | (1u << (k & 7u)));
        rx->received++;
    }
    upload_respond(rx, UPLOAD_R_ACK, 0, session, seq, 0, 0);
}

static void upload_commit(struct upload_rx *rx, uint8_t session, uint16_t seq)
{
    uint32_t body_crc;
    int rc;

    if (rx->received != rx->chunks) {
        upload_respond(rx, UPLOAD_R_REJECT, UPLOAD_REASON_INCOMPLETE, session, seq,
                       rx->chunks - rx->received, rx->chunks);
        upload_close(rx);
        return;
    }
    /* One pass over the file for both CRCs: the file's own covers all but its last four bytes,
     * BEGIN's the whole file, which is the same CRC carried on over those four. */
    body_crc = crc32_update(0, rx->buf, rx->total - MESHFILE_CRC_BYTES);
    if (crc32_update(body_crc, rx->buf + rx->total - MESHFILE_CRC_BYTES, MESHFILE_CRC_BYTES) !=
        rx->total_crc) {
        upload_respond(rx, UPLOAD_R_REJECT, UPLOAD_REASON_CRC, session, seq, 0, 0);
        upload_close(rx);
        return;
    }
    rc = meshfile_check_known_crc(rx->buf, rx->total, rx->max_verts, rx->max_faces, body_crc,
                                  &rx->info);
    if (rc != MESHFILE_OK) {
        meshfile_message(rc, &rx->info, rx->message, sizeof rx->message);
        upload_respond(rx, UPLOAD_R_REJECT, UPLOAD_REASON_MESH, session, seq, (uint32_t)rc, 0);
        upload_close(rx);
        return;
    }
    rx->ready = true;
    rx->staging_valid = true;
    rx->committed_session = session;
    upload_respond(rx, UPLOAD_R_OK, 0, session, seq, rx->info.faces, rx->info.verts);
    upload_close(rx);
}

/* A frame whose CRC held. */
static void upload_frame(struct upload_rx *rx)
{
    const uint8_t type = rx->head[0];
    const uint8_t session = rx->head[1];
    const uint16_t seq = (uint16_t)le16_at(&rx->head[2]);

    rx->frames_ok++;
    rx->quiet = UPLOAD_QUIET_FRAMES;
    if (type == UPLOAD_BEGIN) {
        rx->idle = 0;
        upload_begin(rx, session, seq, rx->payload, rx->len);
        return;
    }
    if (type != UPLOAD_DATA && type != UPLOAD_COMMIT && type != UPLOAD_ABORT) {
        upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_TYPE, session, seq, type, 0);
        return;
    }
    if (rx->session == 0u || session != rx->session) {
        if (type == UPLOAD_COMMIT && session != 0u && session == rx->committed_session &&
            rx->session == 0u && rx->staging_valid) {
            /* The sender missed our ok: say it again. */
            upload_respond(rx, UPLOAD_R_OK, 0, session, seq, rx->info.faces, rx->info.verts);
        } else {
            upload_respond(rx, UPLOAD_R_NAK,
                           (rx->session == 0u) ? UPLOAD_REASON_STATE : UPLOAD_REASON_SESSION,
                           session, seq, 0, 0);
        }
        return;
    }
    rx->idle = 0;
    if (type == UPLOAD_DATA) {
        upload_data(rx, session, seq, rx->payload, rx->len);
    } else if (type == UPLOAD_COMMIT) {
        if (rx->len != 0u) {
            upload_respond(rx, UPLOAD_R_NAK, UPLOAD_REASON_LENGTH, session, seq, 0, 0);
            return;
        }
        upload_commit(rx, session, seq);
    } else {
        upload_close(rx);
        upload_respond(rx, UPLOAD_R_ACK, 0, session, seq, 0, 0);
    }
}

/* A byte outside any frame: a key, unless a transfer is open or was recently seen. */
static bool upload_stray(struct upload_rx *rx, uint8_t byte)
{
    if (byte >= 0x80u) {
        /* Not a key (keys are ASCII): a frame's remains. Keep the next bytes from the keys too. */
        rx->quiet = UPLOAD_QUIET_FRAMES;
    }
    if (rx->session != 0u || rx->quiet != 0u) {
        rx->stray++;
        return true;
    }
    return false;
}

bool upload_feed(struct upload_rx *rx, uint8_t byte)
{
    rx->byte_this_frame = true;
    switch (rx->state) {
    case RX_HUNT:
        if (byte == UPLOAD_SOF0) {
            rx->state = RX_SOF1;
            rx->quiet = UPLOAD_QUIET_FRAMES;
            return true;
        }
        return upload_stray(rx, byte);
    case RX_SOF1:
        if (byte == UPLOAD_SOF1) {
            rx->state = RX_HEAD;
            rx->pos = 0;
            return true;
        }
        /* The SOF0 was noise; this byte may itself start a frame. */
        rx->stray++;
        rx->state = RX_HUNT;
        return upload_feed(rx, byte);
    case RX_HEAD:
        rx->head[rx->pos++] = byte;
        if (rx->pos == sizeof rx->head) {
            rx->len = (uint16_t)le16_at(&rx->head[4]);
            rx->pos = 0;
            if (rx->len > UPLOAD_MAX_PAYLOAD) {
                rx->frames_bad++;
                upload_respond(rx, UPLOAD_R_NAK_BIG, 0, 0, 0, rx->len, 0);
                rx->state = RX_HUNT;
            } else {
                rx->state = (rx->len == 0u) ? RX_CRC : RX_PAYLOAD;
            }
        }
        return true;
    case RX_PAYLOAD:
        rx->payload[rx->pos++] = byte;
        if (rx->pos == rx->len) {
            rx->pos = 0;
            rx->state = RX_CRC;
        }
        return true;
    default: /* RX_CRC */
        rx->crc[rx->pos++] = byte;
        if (rx->pos == UPLOAD_CRC_BYTES) {
            const uint32_t crc = crc32_update(crc32_update(0, rx->head, sizeof rx->head),
                                              rx->payload, rx->len);

            rx->state = RX_HUNT;
            if (crc == le32_at(rx->crc)) {
                upload_frame(rx);
            } else {
                rx->frames_bad++;
                upload_respond(rx, UPLOAD_R_NAK_CRC, 0, 0, 0, 0, 0);
            }
        }
        return true;
    }
}

void upload_frame_end(struct upload_rx *rx)
{
    if (rx->state != RX_HUNT) {
        rx->partial_idle = rx->byte_this_frame ? 0u : rx->partial_idle + 1u;
        if (rx->partial_idle >= UPLOAD_PARTIAL_TIMEOUT_FRAMES) {
            rx->state = RX_HUNT;  /* the sender stopped mid-frame */
            rx->frames_bad++;
            rx->partial_idle = 0;
        }
    }
    rx->byte_this_frame = false;
    if (rx->session != 0u && ++rx->idle >= UPLOAD_TIMEOUT_FRAMES) {
        upload_respond(rx, UPLOAD_R_ABANDONED, 0, rx->session, 0, rx->stray, 0);
        upload_close(rx);
    }
    if (rx->quiet != 0u) {
        rx->quiet--;
    }
}

static const char *upload_reason_word(uint8_t reason)
{
    static const char *const words[] = {
        "none", "session", "offset", "length", "state", "type",
        "capacity", "chunk", "incomplete", "crc", "mesh",
    };

    return (reason < sizeof words / sizeof words[0]) ? words[reason] : "?";
}

void upload_response_line(const struct upload_rx *rx, uint32_t i, char *out, size_t cap)
{
    const struct upload_response *r = &rx->resp[i];
    const unsigned s = r->session;
    const unsigned q = r->seq;
    const unsigned long a = (unsigned long)r->a;
    const unsigned long b = (unsigned long)r->b;

    switch (r->kind) {
    case UPLOAD_R_ACK:
        snprintf(out, cap, "@up ack %u %u", s, q);
        break;
    case UPLOAD_R_NAK:
        snprintf(out, cap, "@up nak %u %u %s", s, q, upload_reason_word(r->reason));
        break;
    case UPLOAD_R_NAK_CRC:
        snprintf(out, cap, "@up nak crc");
        break;
    case UPLOAD_R_NAK_BIG:
        snprintf(out, cap, "@up nak big %lu", a);
        break;
    case UPLOAD_R_OK:
        snprintf(out, cap, "@up ok %u faces %lu verts %lu", s, a, b);
        break;
    case UPLOAD_R_ABANDONED:
        snprintf(out, cap, "@up abandoned %u (%lu stray bytes ignored)", s, a);
        break;
    default: /* UPLOAD_R_REJECT */
        switch (r->reason) {
        case UPLOAD_REASON_CAPACITY:
            snprintf(out, cap, "@up reject %u capacity: %lu bytes, this build holds %lu", s, a, b);
            break;
        case UPLOAD_REASON_CHUNK:
            snprintf(out, cap, "@up reject %u chunk: %lu bytes (64 to 512)", s, a);
            break;
        case UPLOAD_REASON_INCOMPLETE:
            snprintf(out, cap, "@up reject %u incomplete: %lu of %lu chunks missing", s, a, b);
            break;
        case UPLOAD_REASON_CRC:
            snprintf(out, cap, "@up reject %u crc: the file's CRC does not match BEGIN's", s);
            break;
        default:
            snprintf(out, cap, "@up reject %u mesh: %s", s, rx->message);
            break;
        }
        break;
    }
}
