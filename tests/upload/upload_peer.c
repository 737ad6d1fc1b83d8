/*
 * upload_peer — the firmware's upload receiver (firmware/model/upload.c, the same source) on a
 * pseudo-terminal, at the speed of the host: what tools/mesh_upload.py talks to in tests that do
 * not need a whole co-simulation. It behaves as the frame loop does: a "frame" takes at most
 * FW_UART_BYTES_PER_FRAME bytes or lasts --frame-ms milliseconds, then runs the receiver's
 * timeouts and writes the frame's response lines to the pty.
 *
 *   upload_peer --pty LINK [--out FILE] [--frame-ms N] [--frames N] [--cap BYTES]
 *
 * Ends with status 0 after the first committed file (written to --out), 1 after --frames frames
 * without one; prints a summary (frames, stray bytes, keys) on stderr.
 */
#define _DEFAULT_SOURCE
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include "app/fw_config.h"
#include "model/upload.h"
#include "scenes/model/model.h"

static uint8_t peer_buf[MESHFILE_BYTES(FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES)];
static uint8_t peer_map[UPLOAD_MAP_BYTES(sizeof peer_buf)];
static struct upload_rx peer_rx;

static int open_pty(const char *link)
{
    struct termios t;
    int fd = posix_openpt(O_RDWR | O_NOCTTY);
    const char *name;
    int slave;

    if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0 || (name = ptsname(fd)) == 0) {
        return -1;
    }
    /* Raw on the slave side (8-bit clean), and keep it open so a client's close is not EIO. */
    slave = open(name, O_RDWR | O_NOCTTY);
    if (slave < 0 || tcgetattr(slave, &t) != 0) {
        return -1;
    }
    cfmakeraw(&t);
    tcsetattr(slave, TCSANOW, &t);
    unlink(link);
    if (symlink(name, link) != 0) {
        return -1;
    }
    fprintf(stderr, "upload_peer: listening on %s (%s)\n", link, name);
    return fd;
}

int main(int argc, char **argv)
{
    const char *link = 0;
    const char *out = 0;
    long frame_ms = 16;
    long max_frames = 20000;
    uint32_t cap = sizeof peer_buf;
    uint32_t keys = 0;
    int fd;

    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--pty") && i + 1 < argc) {
            link = argv[++i];
        } else if (!strcmp(argv[i], "--out") && i + 1 < argc) {
            out = argv[++i];
        } else if (!strcmp(argv[i], "--frame-ms") && i + 1 < argc) {
            frame_ms = atol(argv[++i]);
        } else if (!strcmp(argv[i], "--frames") && i + 1 < argc) {
            max_frames = atol(argv[++i]);
        } else if (!strcmp(argv[i], "--cap") && i + 1 < argc) {
            cap = (uint32_t)atol(argv[++i]);
            if (cap > sizeof peer_buf) {
                cap = sizeof peer_buf;
            }
        } else {
            fprintf(stderr, "usage: upload_peer --pty LINK [--out FILE] [--frame-ms N] "
                            "[--frames N] [--cap BYTES]\n");
            return 2;
        }
    }
    if (link == 0 || (fd = open_pty(link)) < 0) {
        fprintf(stderr, "upload_peer: cannot open a pty at %s: %s\n", link ? link : "(none)",
                strerror(errno));
        return 2;
    }
    upload_init(&peer_rx, peer_buf, cap, peer_map, sizeof peer_map, FW_MODEL_MAX_VERTS,
                FW_MODEL_MAX_FACES);
    for (long frame = 0; frame < max_frames; frame++) {
        uint32_t taken = 0;
        struct pollfd p = {fd, POLLIN, 0};
        char line[112];

        /* One frame: up to the firmware's byte budget, or its duration. */
        while (taken < FW_UART_BYTES_PER_FRAME && poll(&p, 1, (int)frame_ms) > 0) {
            uint8_t b[256];
            const size_t want = FW_UART_BYTES_PER_FRAME - taken < sizeof b
                                    ? FW_UART_BYTES_PER_FRAME - taken : sizeof b;
            const ssize_t n = read(fd, b, want);

            if (n <= 0) {
                break;
            }
            for (ssize_t k = 0; k < n; k++) {
                keys += upload_feed(&peer_rx, b[k]) ? 0u : 1u;
            }
            taken += (uint32_t)n;
        }
        upload_frame_end(&peer_rx);
        for (uint32_t i = 0; i < peer_rx.resp_count; i++) {
            upload_response_line(&peer_rx, i, line, sizeof line);
            strcat(line, "\n");
            if (write(fd, line, strlen(line)) < 0) {
                break;
            }
        }
        upload_responses_clear(&peer_rx);
        if (upload_ready(&peer_rx)) {
            FILE *f = out ? fopen(out, "wb") : 0;

            if (f != 0) {
                fwrite(peer_buf, 1, peer_rx.total, f);
                fclose(f);
            }
            fprintf(stderr, "upload_peer: committed after %ld frames: %lu bytes, %lu faces, %lu "
                            "vertices; %lu frames ok, %lu bad, %lu keys, %lu responses lost\n",
                    frame + 1, (unsigned long)peer_rx.total, (unsigned long)peer_rx.info.faces,
                    (unsigned long)peer_rx.info.verts, (unsigned long)peer_rx.frames_ok,
                    (unsigned long)peer_rx.frames_bad, (unsigned long)keys,
                    (unsigned long)peer_rx.resp_lost);
            usleep(200000);  /* let the client read the ok */
            unlink(link);
            return 0;
        }
    }
    fprintf(stderr, "upload_peer: no file committed in %ld frames (%lu frames ok, %lu bad)\n",
            max_frames, (unsigned long)peer_rx.frames_ok, (unsigned long)peer_rx.frames_bad);
    unlink(link);
    return 1;
}
