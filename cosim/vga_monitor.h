/* vga_monitor: a model of a VGA monitor that turns sampled sync and colour signals into frames.
 *
 * It knows nothing of the GPU: it locks onto the sync pulses, checks them against the standard
 * 640x480@60 timing (800 pixels per line, 96-pixel hsync; 525 lines per frame, 2-line vsync; 48-pixel
 * and 33-line back porches), checks that colour is black during blanking, and captures the visible
 * 640x480 area as RGB888 (each RGB444 channel times 17). Feed it one sample per pixel clock. */
#ifndef VGA_MONITOR_H
#define VGA_MONITOR_H

#include <stdbool.h>
#include <stdint.h>

#define VGA_W 640
#define VGA_H 480

typedef struct vga_monitor {
    /* horizontal state */
    bool hs_prev;           /* previous hsync level (true = asserted) */
    int64_t px_since_hs_end; /* pixels since the end of the last hsync pulse, -1 before the first */
    int64_t px_since_hs_start;
    int64_t hs_width;
    /* vertical state */
    bool vs_prev;
    int64_t lines_since_vs_end; /* hsync pulses since the end of vsync, -1 before the first */
    int64_t lines_since_vs_start;
    /* capture */
    bool armed;              /* capture the next frame that starts */
    bool capturing;
    bool frame_ready;        /* a complete frame is in rgb */
    uint64_t frames_seen;
    uint8_t rgb[VGA_H * VGA_W * 3];
    /* first timing error, "" if none */
    char error[160];
} vga_monitor;

void vga_monitor_reset(vga_monitor *m);
/* Capture the next complete frame whose vertical sync ends after this call. */
void vga_monitor_arm(vga_monitor *m);
/* One pixel-clock sample. hsync_n/vsync_n are the active-low pins; r, g, b are 4-bit. */
void vga_monitor_sample(vga_monitor *m, int hsync_n, int vsync_n, int r, int g, int b);

#endif
