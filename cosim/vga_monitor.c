/* vga_monitor: see vga_monitor.h. */
#include "vga_monitor.h"

#include <stdio.h>
#include <string.h>

enum {
    H_TOTAL = 800, H_SYNC = 96, H_BACK = 48,
    V_TOTAL = 525, V_SYNC = 2, V_BACK = 33,
};

static void fail(vga_monitor *m, const char *what, long long value)
{
    if (m->error[0] == '\0') {
        snprintf(m->error, sizeof m->error, "VGA timing: %s (%lld)", what, value);
    }
}

void vga_monitor_reset(vga_monitor *m)
{
    memset(m, 0, sizeof *m);
    m->px_since_hs_end = -1;
    m->px_since_hs_start = -1;
    m->lines_since_vs_end = -1;
    m->lines_since_vs_start = -1;
}

void vga_monitor_arm(vga_monitor *m)
{
    m->armed = true;
    m->capturing = false;
    m->frame_ready = false;
}

static void on_hsync_start(vga_monitor *m)
{
    if (m->px_since_hs_start >= 0 && m->px_since_hs_start != H_TOTAL) {
        fail(m, "line length is not 800 pixels", m->px_since_hs_start);
    }
    m->px_since_hs_start = 0;
    if (m->lines_since_vs_start >= 0) {
        m->lines_since_vs_start++;
    }
    if (m->lines_since_vs_end >= 0) {
        m->lines_since_vs_end++;
    }
}

static void on_vsync_start(vga_monitor *m)
{
    if (m->lines_since_vs_start >= 0 && m->lines_since_vs_start != V_TOTAL) {
        fail(m, "frame length is not 525 lines", m->lines_since_vs_start);
    }
    m->lines_since_vs_start = 0;
    if (m->capturing) {
        fail(m, "vsync arrived before the frame's last visible line", m->lines_since_vs_end);
        m->capturing = false;
    }
}

static void on_vsync_end(vga_monitor *m)
{
    if (m->lines_since_vs_start != V_SYNC && m->lines_since_vs_start >= 0 && m->frames_seen > 0) {
        fail(m, "vsync pulse is not 2 lines", m->lines_since_vs_start);
    }
    m->lines_since_vs_end = 0;
    m->frames_seen++;
    if (m->armed) {
        m->armed = false;
        m->capturing = true;
    }
}

void vga_monitor_sample(vga_monitor *m, int hsync_n, int vsync_n, int r, int g, int b)
{
    bool hs = !hsync_n;
    bool vs = !vsync_n;

    if (hs && !m->hs_prev) {
        on_hsync_start(m);
    }
    if (!hs && m->hs_prev) {
        if (m->px_since_hs_start != H_SYNC && m->frames_seen > 0) {
            fail(m, "hsync pulse is not 96 pixels", m->px_since_hs_start);
        }
        m->px_since_hs_end = 0;
    }
    if (vs && !m->vs_prev) {
        on_vsync_start(m);
    }
    if (!vs && m->vs_prev) {
        on_vsync_end(m);
    }
    m->hs_prev = hs;
    m->vs_prev = vs;

    long long x = m->px_since_hs_end >= 0 ? m->px_since_hs_end - H_BACK : -1;
    long long y = m->lines_since_vs_end >= 0 ? m->lines_since_vs_end - V_BACK : -1;
    bool visible = x >= 0 && x < VGA_W && y >= 0 && y < VGA_H && !hs && !vs;
    if (!visible && (r | g | b) != 0 && m->frames_seen > 0) {
        fail(m, "colour is not black during blanking", (long long)(r << 8 | g << 4 | b));
    }
    if (visible && m->capturing) {
        uint8_t *p = &m->rgb[(y * VGA_W + x) * 3];
        p[0] = (uint8_t)(r * 17);
        p[1] = (uint8_t)(g * 17);
        p[2] = (uint8_t)(b * 17);
        if (x == VGA_W - 1 && y == VGA_H - 1) {
            m->capturing = false;
            m->frame_ready = true;
        }
    }

    if (m->px_since_hs_end >= 0) {
        m->px_since_hs_end++;
    }
    if (m->px_since_hs_start >= 0) {
        m->px_since_hs_start++;
    }
}
