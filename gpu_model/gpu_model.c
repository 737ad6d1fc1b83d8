/*
 * gpu_model.c - bit-exact golden C model of the GPU (see gpu_model.h).
 *
 * Every rule here is a transcription of contract/gpu-contract.md (version 1.1);
 * the comments quote the step they implement.  The rasterizer is deliberately
 * the plainest possible reading of the "Triangle rule (exact)": for every
 * pixel centre of the clamped bounding box it evaluates the three edge
 * functions, and for a covered pixel the depth plane, from scratch in 64-bit
 * arithmetic.  A hardware rasterizer steps edge and depth values
 * incrementally, W pixels at a time; keeping the model direct means the two
 * do not share the stepping logic, so a stepping bug shows up as a mismatch.
 */
#include "gpu_model.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* Q12.4: one pixel is 16 units, a pixel centre is at 16*n + 8. */
#define SUBPIXEL_ONE  ((int64_t)1 << GPU_SUBPIXEL_BITS)
#define SUBPIXEL_HALF ((int64_t)1 << (GPU_SUBPIXEL_BITS - 1))

/* Extract field NAME (GPU_<NAME>_WORD/_LSB/_MASK) from a buffer entry. */
#define GPU_MODEL_FIELD(words, NAME) \
    (((words)[GPU_##NAME##_WORD] >> GPU_##NAME##_LSB) & GPU_##NAME##_MASK)

/* Words backing each buffer window: the configured capacity's.  The windows
 * are larger than the buffers (e.g. VTX is 0x8000 bytes, a 1024-vertex buffer
 * 1024 * 2 words = 0x2000 bytes); the rest of a window is treated as
 * unmapped.  cfg caps are at most the GPU_MODEL_MAX_* the arrays hold
 * (gpu_model_reset_config), so the products stay below 2^11. */
#define VTX_WORDS_TOTAL(m) ((m)->cfg.vtx_cap * GPU_VTX_WORDS)
#define IDX_WORDS_TOTAL(m) ((m)->cfg.tri_cap * GPU_PRIM_WORDS)

/* A vertex: position in Q12.4, depth (VTX_Z, unsigned 16-bit) and intensity
 * (VTX_I, unsigned Q4.12), widened so every later product is exact. */
typedef struct {
    int64_t x;
    int64_t y;
    int64_t z;
    int64_t i;
} gpu_model_pt;

/* Q16 fixed point of the depth plane. */
#define DEPTH_ONE ((int64_t)1 << 16)

/* Outcome of one primitive, for the PERF_* counters. */
typedef enum {
    PRIM_REJECTED,
    PRIM_DRAWN,
} prim_result;

/* ---------------------------------------------------------------- helpers */

/* Sign-extend a field whose mask is a run of ones from bit 0 (e.g. 0xFFFF).
 * Done arithmetically so it does not rely on implementation-defined
 * conversions to a narrower signed type. */
static int64_t sign_extend(uint32_t raw, uint32_t mask)
{
    int64_t sign = ((int64_t)mask + 1) / 2;
    return (int64_t)(raw & mask) - (((int64_t)raw & sign) ? 2 * sign : 0);
}

/* floor(a / b) and ceil(a / b) for b > 0; C division truncates toward zero,
 * which is wrong for negative a (guard-band vertices). */
static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

static int64_t ceil_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && a > 0) ? q + 1 : q;
}

static int64_t min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int64_t max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

/* trunc(a / b) for b > 0: C division already rounds toward zero. */
static int64_t trunc_div(int64_t a, int64_t b)
{
    return a / b;
}

/* Saturate to a signed 32-bit value, -2^31 ... 2^31 - 1. */
static int64_t sat32(int64_t v)
{
    if (v > INT32_MAX) {
        return INT32_MAX;
    }
    if (v < INT32_MIN) {
        return INT32_MIN;
    }
    return v;
}

static uint8_t *back_buffer(gpu_model *m)
{
    return m->fb[(m->front & 1u) ^ 1u];
}

/* The bits of a pixel a batch writes (contract FB_WRITE_MASK): WMASK_LO the
 * low nibble, WMASK_HI the high one; the others keep their value. */
static uint8_t written_bits(const gpu_model *m)
{
    uint8_t bits = 0;
    if (m->regs.fb_write_mask & GPU_WMASK_LO_MASK) {
        bits |= 0x0Fu;
    }
    if (m->regs.fb_write_mask & GPU_WMASK_HI_MASK) {
        bits |= 0xF0u;
    }
    return bits;
}

/* The shade probe's word for pixel i of fb (the attached probe's). */
static uint32_t *probe_word(const gpu_model *m, const uint8_t *fb, size_t i)
{
    return &m->shade_probe->px[fb == m->fb[1] ? 1 : 0][i];
}

/* Store palette index `color` into pixel i of fb through the write mask; a
 * probe records "as its palette index" (draw_triangle overrides that for a
 * Gouraud pixel). */
static void put_pixel(const gpu_model *m, uint8_t *fb, size_t i, uint8_t color)
{
    uint8_t bits = written_bits(m);
    fb[i] = (uint8_t)((fb[i] & (uint8_t)~bits) | (color & bits));
    if (m->shade_probe != NULL) {
        *probe_word(m, fb, i) = 0;
    }
}

/* On the frame and in the batch's strip rows (row1 <= the frame's last). */
static bool on_screen(const gpu_model *m, int64_t px, int64_t py)
{
    return px >= 0 && px < (int64_t)m->cfg.fb_width && py >= m->row0 &&
           py <= m->row1;
}

/* ------------------------------------------------------------- rasterizer */

/* E_ab(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x), exactly as the
 * contract writes it.  Operands are at most 17 bits, the result 34 bits
 * (contract, "Widths"), far inside int64_t. */
static int64_t edge_fn(gpu_model_pt a, gpu_model_pt b, gpu_model_pt p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/* An edge is top-left when dy < 0, or dy = 0 and dx > 0 (y points down and
 * the interior is where E > 0). */
static bool edge_is_top_left(gpu_model_pt a, gpu_model_pt b)
{
    int64_t dx = b.x - a.x;
    int64_t dy = b.y - a.y;
    return dy < 0 || (dy == 0 && dx > 0);
}

/* The fill rule for one edge: strictly inside, or exactly on a top-left edge.
 * This is what makes triangles sharing an edge cover each centre once. */
static bool edge_covers(int64_t e, bool top_left)
{
    return e > 0 || (e == 0 && top_left);
}

/* Depth plane of an oriented triangle (contract "Depth"):
 *   ZA = sat32(trunc(2^16 (dz1 dy2 - dz2 dy1) / area))
 *   ZB = sat32(trunc(2^16 (dz2 dx1 - dz1 dx2) / area))
 * The numerators are below 2^33, times 2^16 below 2^49: exact in int64. */
typedef struct {
    int64_t za;
    int64_t zb;
} depth_plane;

/* The two slopes of the plane through the vertices' values q0, q1, q2 (depth or intensity, both
 * 16-bit unsigned, so the bounds above hold for either). */
static void plane_slopes(gpu_model_pt v0, gpu_model_pt v1, gpu_model_pt v2,
                         int64_t q0, int64_t q1, int64_t q2, int64_t area,
                         int64_t *a, int64_t *b)
{
    int64_t dx1 = v1.x - v0.x, dy1 = v1.y - v0.y, dq1 = q1 - q0;
    int64_t dx2 = v2.x - v0.x, dy2 = v2.y - v0.y, dq2 = q2 - q0;
    *a = sat32(trunc_div(DEPTH_ONE * (dq1 * dy2 - dq2 * dy1), area));
    *b = sat32(trunc_div(DEPTH_ONE * (dq2 * dx1 - dq1 * dx2), area));
}

static depth_plane depth_setup(gpu_model_pt v0, gpu_model_pt v1,
                               gpu_model_pt v2, int64_t area)
{
    depth_plane d;
    plane_slopes(v0, v1, v2, v0.z, v1.z, v2.z, area, &d.za, &d.zb);
    return d;
}

/* q(p) = clamp(floor((2^16 q0 + A (p.x - x0) + B (p.y - y0)) / 2^16),
 *              0, 65535), evaluated directly at p: the depth (q = z, A, B =
 * ZA, ZB) and the intensity plane's value.  |A (p.x - x0)| < 2^48, the sum
 * < 2^50: exact in int64. */
static uint16_t plane_value(int64_t a, int64_t b, int64_t q0, gpu_model_pt v0,
                            gpu_model_pt p)
{
    int64_t sum = DEPTH_ONE * q0 + a * (p.x - v0.x) + b * (p.y - v0.y);
    int64_t q = floor_div(sum, DEPTH_ONE);
    if (q < 0) {
        q = 0;
    }
    if (q > 0xFFFF) {
        q = 0xFFFF;
    }
    return (uint16_t)q;
}

static uint16_t depth_at(const depth_plane *d, gpu_model_pt v0,
                         gpu_model_pt p)
{
    return plane_value(d->za, d->zb, v0.z, v0, p);
}

/* Intensity plane of an oriented Gouraud triangle (contract "Gouraud
 * intensity"): the depth plane's formula with VTX_I in place of VTX_Z,
 *   IA = sat32(trunc(2^16 (di1 dy2 - di2 dy1) / area))
 *   IB = sat32(trunc(2^16 (di2 dx1 - di1 dx2) / area))
 * with the same bounds (numerators below 2^33, times 2^16 below 2^49). */
typedef struct {
    int64_t ia;
    int64_t ib;
} intensity_plane;

static intensity_plane intensity_setup(gpu_model_pt v0, gpu_model_pt v1,
                                       gpu_model_pt v2, int64_t area)
{
    intensity_plane d;
    plane_slopes(v0, v1, v2, v0.i, v1.i, v2.i, area, &d.ia, &d.ib);
    return d;
}

/* The 4x4 ordered-dither (Bayer) thresholds, [y & 3][x & 3]. */
static const uint8_t bayer4[4][4] = {
    { 0, 8, 2, 10 },
    { 12, 4, 14, 6 },
    { 3, 11, 1, 9 },
    { 15, 7, 13, 5 },
};

/* The colour of a Gouraud triangle's pixel (px, py) of intensity i = i(p):
 *   i(p)  = clamp(floor((2^16 i0 + IA (p.x - x0) + IB (p.y - y0)) / 2^16),
 *                 0, 65535)                                  (Q4.12)
 *           evaluated directly at p (plane_value; the sum is below 2^50, as
 *           depth_at's)
 *   level = i(p) >> 12, plus 1 when dithering and ((i(p) >> 8) & 15) is
 *           greater than bayer4[py & 3][px & 3], at most 15
 *   colour = (PRIM_COLOR + level) mod 256 */
static uint8_t shade_color(int64_t i, int64_t px, int64_t py, uint8_t color,
                           bool dither)
{
    int64_t level = i >> 12;
    int64_t frac = (i >> 8) & 15;
    if (dither && frac > bayer4[py & 3][px & 3] && level < 15) {
        level++;
    }
    return (uint8_t)((color + level) & 0xFF);
}

/* Draw one triangle into the back buffer following "Triangle rule (exact)"
 * and, with ztest (CTRL_ZTEST on a GPU built with the depth buffer),
 * "Depth"; with shaded (a Gouraud triangle) "Gouraud intensity", dithered
 * with dither.  Adds its samples, spans and pixels to the counters and
 * reports drawn / rejected. */
static prim_result draw_triangle(gpu_model *m, gpu_model_pt v0,
                                 gpu_model_pt v1, gpu_model_pt v2,
                                 uint8_t color, bool ztest, bool shaded,
                                 bool dither)
{
    uint8_t *fb = back_buffer(m);

    /* area = E_v0v1(v2); zero area is rejected, negative area swaps v1/v2
     * (position and depth: the vertices themselves) so both windings
     * rasterize identically; area is then its absolute value. */
    int64_t area = edge_fn(v0, v1, v2);
    if (area == 0) {
        return PRIM_REJECTED;
    }
    if (area < 0) {
        gpu_model_pt t = v1;
        v1 = v2;
        v2 = t;
        area = -area;
    }

    /* Clamped bounding box: exactly the pixels whose centres 16*p + 8 lie in
     * [min, max] of the vertex coordinates, clipped to the screen's columns
     * and the strip's rows. */
    int64_t minx = min3(v0.x, v1.x, v2.x);
    int64_t maxx = max3(v0.x, v1.x, v2.x);
    int64_t miny = min3(v0.y, v1.y, v2.y);
    int64_t maxy = max3(v0.y, v1.y, v2.y);
    int64_t px0 = ceil_div(minx - SUBPIXEL_HALF, SUBPIXEL_ONE);
    int64_t px1 = floor_div(maxx - SUBPIXEL_HALF, SUBPIXEL_ONE);
    int64_t py0 = ceil_div(miny - SUBPIXEL_HALF, SUBPIXEL_ONE);
    int64_t py1 = floor_div(maxy - SUBPIXEL_HALF, SUBPIXEL_ONE);
    if (px0 < 0) {
        px0 = 0;
    }
    if (py0 < m->row0) {
        py0 = m->row0;
    }
    if (px1 > (int64_t)m->cfg.fb_width - 1) {
        px1 = (int64_t)m->cfg.fb_width - 1;
    }
    if (py1 > m->row1) {
        py1 = m->row1;
    }
    if (px0 > px1 || py0 > py1) {
        return PRIM_REJECTED; /* off screen or strip, or too thin for any centre */
    }

    /* Edges v0->v1, v1->v2, v2->v0 and their fill-rule class. */
    bool tl01 = edge_is_top_left(v0, v1);
    bool tl12 = edge_is_top_left(v1, v2);
    bool tl20 = edge_is_top_left(v2, v0);

    depth_plane plane = { 0, 0 };
    if (ztest) {
        plane = depth_setup(v0, v1, v2, area);
    }
    intensity_plane iplane = { 0, 0 };
    if (shaded) {
        iplane = intensity_setup(v0, v1, v2, area);
    }

    m->perf.samples += (uint32_t)((px1 - px0 + 1) * (py1 - py0 + 1));

    /* Spans: pixel (px, py) is in span (floor(px / W), py); px >= 0 here, so
     * C division is the floor. */
    const int64_t span_w = (int64_t)m->cfg.span_w;

    for (int64_t py = py0; py <= py1; py++) {
        int64_t last_span = -1; /* last span of this row already counted */
        for (int64_t px = px0; px <= px1; px++) {
            gpu_model_pt p = { SUBPIXEL_ONE * px + SUBPIXEL_HALF,
                               SUBPIXEL_ONE * py + SUBPIXEL_HALF, 0, 0 };
            if (!(edge_covers(edge_fn(v0, v1, p), tl01) &&
                  edge_covers(edge_fn(v1, v2, p), tl12) &&
                  edge_covers(edge_fn(v2, v0, p), tl20))) {
                continue;
            }
            /* Covered (edge test only, before any depth test). */
            if (px / span_w != last_span) {
                last_span = px / span_w;
                m->perf.spans_written++;
            }
            size_t i = (size_t)py * m->cfg.fb_width + (size_t)px;
            if (ztest) {
                /* Written only if strictly nearer; the depth then replaces
                 * the stored one. */
                uint16_t z = (uint16_t)(depth_at(&plane, v0, p) >>
                                        (16u - m->cfg.zbuf_bits));
                if (!(z < m->zbuf[i])) {
                    continue;
                }
                m->zbuf[i] = z;
            }
            if (shaded) {
                int64_t inten = plane_value(iplane.ia, iplane.ib, v0.i, v0, p);
                put_pixel(m, fb, i, shade_color(inten, px, py, color, dither));
                if (m->shade_probe != NULL && written_bits(m) == 0xFFu) {
                    *probe_word(m, fb, i) = GPU_MODEL_PROBE_SHADED |
                                            (uint32_t)color << 16 | (uint32_t)inten;
                }
            } else {
                put_pixel(m, fb, i, color);
            }
            m->perf.pixels++;
        }
    }
    return PRIM_DRAWN;
}

/* Draw one line following "Line rule (exact)": endpoints are the pixels
 * holding the vertices (floor of Q12.4 / 16), Bresenham over n = max(ax, ay)
 * steps, plotting before each step (first endpoint drawn, last not),
 * off-screen plots skipped.  Lines neither test nor write depth and add
 * nothing to PERF_SPANS_WRITTEN. */
static prim_result draw_line(gpu_model *m, gpu_model_pt a, gpu_model_pt b,
                             uint8_t color)
{
    uint8_t *fb = back_buffer(m);

    /* X = x >> 4 (arithmetic shift = floor), written as a floor division so
     * it does not rely on >> of negative numbers. */
    int64_t x = floor_div(a.x, SUBPIXEL_ONE);
    int64_t y = floor_div(a.y, SUBPIXEL_ONE);
    int64_t dx = floor_div(b.x, SUBPIXEL_ONE) - x;
    int64_t dy = floor_div(b.y, SUBPIXEL_ONE) - y;
    int64_t sx = dx < 0 ? -1 : 1;
    int64_t sy = dy < 0 ? -1 : 1;
    int64_t ax = dx < 0 ? -dx : dx;
    int64_t ay = dy < 0 ? -dy : dy;
    int64_t n = ax > ay ? ax : ay;
    if (n == 0) {
        return PRIM_REJECTED; /* zero length: no error flag */
    }

    m->perf.samples += (uint32_t)n;

    if (ax >= ay) {
        int64_t e = 2 * ay - ax;
        for (int64_t k = 0; k < n; k++) {
            if (on_screen(m, x, y)) {
                put_pixel(m, fb, (size_t)y * m->cfg.fb_width + (size_t)x, color);
                m->perf.pixels++;
            }
            if (e > 0) {
                y += sy;
                e -= 2 * ax;
            }
            e += 2 * ay;
            x += sx;
        }
    } else {
        int64_t e = 2 * ax - ay;
        for (int64_t k = 0; k < n; k++) {
            if (on_screen(m, x, y)) {
                put_pixel(m, fb, (size_t)y * m->cfg.fb_width + (size_t)x, color);
                m->perf.pixels++;
            }
            if (e > 0) {
                x += sx;
                e -= 2 * ay;
            }
            e += 2 * ax;
            y += sy;
        }
    }
    return PRIM_DRAWN;
}

/* Position of vertex `index` of the vertex buffer (absolute index). */
static gpu_model_pt vertex_pos(const gpu_model *m, uint32_t index)
{
    const uint32_t *w = &m->vtx[(size_t)index * GPU_VTX_WORDS];
    gpu_model_pt p = { sign_extend(GPU_MODEL_FIELD(w, VTX_X), GPU_VTX_X_MASK),
                       sign_extend(GPU_MODEL_FIELD(w, VTX_Y), GPU_VTX_Y_MASK),
                       (int64_t)GPU_MODEL_FIELD(w, VTX_Z),
                       (int64_t)GPU_MODEL_FIELD(w, VTX_I) };
    return p;
}

/* One primitive, contract "Primitives" steps 2-4 (step 1, the TRIS_IN count,
 * is done by the caller).  ztest: depth-test triangles; dither: CTRL_DITHER
 * for Gouraud ones. */
static prim_result run_primitive(gpu_model *m, uint32_t prim, bool ztest,
                                 bool dither)
{
    const uint32_t *w = &m->idx[(size_t)prim * GPU_PRIM_WORDS];
    uint32_t kind = GPU_MODEL_FIELD(w, PRIM_KIND);
    uint32_t i0 = GPU_MODEL_FIELD(w, PRIM_I0);
    uint32_t i1 = GPU_MODEL_FIELD(w, PRIM_I1);
    uint32_t i2 = GPU_MODEL_FIELD(w, PRIM_I2);
    uint8_t color = (uint8_t)GPU_MODEL_FIELD(w, PRIM_COLOR);

    bool is_line = kind == GPU_PRIM_KIND_LINE;
    bool shaded = kind == GPU_PRIM_KIND_TRI_GOURAUD;

    /* 2. Kind: triangles always, lines and Gouraud triangles only when built
     *    with them; anything else is skipped with ERR_KIND. */
    if (!(kind == GPU_PRIM_KIND_TRI || (is_line && m->cfg.lines) ||
          (shaded && m->cfg.gouraud))) {
        m->errors |= GPU_ERR_KIND_MASK;
        return PRIM_REJECTED;
    }

    /* 3. The indices the primitive uses (I0, I1, I2 for a triangle; I0, I1
     *    for a line) are relative to VTX_BASE and must be < VTX_COUNT; the
     *    batch check already guaranteed VTX_BASE + VTX_COUNT <= VTX_CAP, so
     *    an accepted index never reads outside the vertex buffer. */
    uint32_t count = m->regs.vtx_count;
    if (i0 >= count || i1 >= count || (!is_line && i2 >= count)) {
        m->errors |= GPU_ERR_VTX_INDEX_MASK;
        return PRIM_REJECTED;
    }

    /* 4. Line rule or triangle rule. */
    uint32_t base = m->regs.vtx_base;
    if (is_line) {
        return draw_line(m, vertex_pos(m, base + i0), vertex_pos(m, base + i1),
                         color);
    }
    return draw_triangle(m, vertex_pos(m, base + i0), vertex_pos(m, base + i1),
                         vertex_pos(m, base + i2), color, ztest, shaded,
                         dither);
}

/* The strip buffer's rules (contract "The strip buffer") for a batch of rows
 * row0 .. row1 on a strip build: true when they hold. *opens says whether the
 * batch opens its strip, *zclear_after whether the strip's depths are cleared
 * once the batch has run. */
static bool strip_rules_hold(const gpu_model *m, uint32_t ctrl, bool ztest,
                             bool zclear, bool *opens, bool *zclear_after)
{
    const int64_t rows = m->cfg.strip_rows;
    *opens = false;
    *zclear_after = m->open_strip_zclear;
    if (rows == 0 || m->row0 > m->row1) {
        return true; /* no strip buffer, or a batch of no rows */
    }
    const int64_t strip = m->row0 / rows;
    if (m->row1 / rows != strip) {
        return false; /* rows in two strips */
    }
    const int64_t first = strip * rows;
    const int64_t end = first + rows;
    const int64_t last = (end < (int64_t)m->cfg.fb_height ? end : (int64_t)m->cfg.fb_height) - 1;
    const bool whole = m->row0 == first && m->row1 == last;
    *opens = strip != m->open_strip;
    if (*opens && !((ctrl & GPU_CTRL_CLEAR_MASK) != 0 && whole && written_bits(m) == 0xFFu)) {
        return false; /* a strip's pixels are undefined until cleared */
    }
    *zclear_after = (*opens ? false : m->open_strip_zclear) || (zclear && whole);
    return !ztest || *zclear_after;
}

/* Steps 2-4 of a batch for rows row0 .. row1 (m->row0, m->row1, the last
 * clamped to the frame). Returns false when the batch broke the count or the
 * strip rules (its error set, nothing cleared or drawn). */
static bool run_rows(gpu_model *m, uint32_t ctrl, bool ztest, bool zclear, bool dither)
{
    /* The strip's pixels: rows row0 .. row1 (none when row0 > row1). */
    const size_t strip_first = (size_t)m->row0 * m->cfg.fb_width;
    const size_t strip_end = (m->row0 > m->row1) ? strip_first
                                                 : (size_t)(m->row1 + 1) * m->cfg.fb_width;

    /* 2. Range check in 64 bits so a huge BASE + COUNT cannot wrap; against
     *    the capacities this GPU was built with. */
    bool count_bad =
        (uint64_t)m->regs.vtx_base + m->regs.vtx_count > m->cfg.vtx_cap ||
        (uint64_t)m->regs.tri_base + m->regs.tri_count > m->cfg.tri_cap;

    bool opens_strip = false;
    bool strip_zclear = false;
    const bool strip_bad = !strip_rules_hold(m, ctrl, ztest, zclear, &opens_strip, &strip_zclear);

    if (count_bad || strip_bad) {
        /* skip clear and draw; the open strip stays as it was */
        m->errors |= (count_bad ? GPU_ERR_COUNT_MASK : 0u) | (strip_bad ? GPU_ERR_STRIP_MASK : 0u);
        return false;
    }
    if (opens_strip) {
        m->open_strip = m->row0 / m->cfg.strip_rows;
    }
    m->open_strip_zclear = strip_zclear;
    /* 3. Clear the back buffer to CLEAR_COLOR[7:0]; and, independently,
     *    the depth buffer to 0xFFFF. */
    if (ctrl & GPU_CTRL_CLEAR_MASK) {
        /* Through the write mask, like every pixel a batch writes. */
        uint8_t *fb = back_buffer(m);
        const uint8_t color = (uint8_t)(m->regs.clear_color & 0xFFu);
        if (written_bits(m) == 0xFFu) {
            /* the usual, unmasked clear: fast */
            memset(fb + strip_first, color, strip_end - strip_first);
            if (m->shade_probe != NULL) {
                memset(probe_word(m, fb, strip_first), 0,
                       (strip_end - strip_first) * sizeof(uint32_t));
            }
        } else {
            for (size_t i = strip_first; i < strip_end; i++) {
                put_pixel(m, fb, i, color);
            }
        }
    }
    if (zclear) {
        const uint16_t far = (uint16_t)((1u << m->cfg.zbuf_bits) - 1u);
        for (size_t i = strip_first; i < strip_end; i++) {
            m->zbuf[i] = far;
        }
    }
    /* 4. Primitives in order; later ones overwrite earlier ones. */
    for (uint32_t i = 0; i < m->regs.tri_count; i++) {
        m->perf.tris_in++;
        if (run_primitive(m, m->regs.tri_base + i, ztest, dither) ==
            PRIM_DRAWN) {
            m->perf.tris_drawn++;
        } else {
            m->perf.tris_rejected++;
        }
    }
    return true;
}

/* A batch, contract "A batch, and the frame handshake" steps 1-6, run to
 * completion (the model has no time, so BUSY is never observable). */
static void run_batch(gpu_model *m, uint32_t tag)
{
    uint32_t ctrl = m->regs.ctrl; /* CTRL is sampled at the doorbell */
    /* CTRL_ZTEST / CTRL_ZCLEAR only do something on a GPU built with the
     * depth buffer; otherwise they are ignored. */
    bool ztest = m->cfg.zbuf && (ctrl & GPU_CTRL_ZTEST_MASK) != 0;
    bool zclear = m->cfg.zbuf && (ctrl & GPU_CTRL_ZCLEAR_MASK) != 0;
    bool dither = m->cfg.gouraud && (ctrl & GPU_CTRL_DITHER_MASK) != 0;
    /* CTRL_WALK acts on a strip build only. */
    const bool walk = m->cfg.strip_rows != 0u && (ctrl & GPU_CTRL_WALK_MASK) != 0;
    const int64_t last_row = (int64_t)m->cfg.fb_height - 1;

    /* 1. Clear ERRORS and the PERF_* counters. STRIP is sampled too: its
     *    rows, the last clamped to the frame. */
    m->errors = 0;
    memset(&m->perf, 0, sizeof m->perf);
    m->row0 = (int64_t)(m->regs.strip & GPU_STRIP_FIRST_MASK) >> GPU_STRIP_FIRST_LSB;
    m->row1 = (int64_t)((m->regs.strip & GPU_STRIP_LAST_MASK) >> GPU_STRIP_LAST_LSB);
    if (m->row1 > last_row) {
        m->row1 = last_row;
    }

    /* 2-4, and with CTRL_WALK again for each strip after the last row's
     * (contract "The strip buffer"), until one breaks the rules. */
    while (run_rows(m, ctrl, ztest, zclear, dither) && walk && m->row0 <= m->row1) {
        const int64_t rows = m->cfg.strip_rows;
        const int64_t next = (m->row1 / rows + 1) * rows; /* the next strip's first row */

        if (next > last_row) {
            break;
        }
        m->row0 = next;
        m->row1 = (next + rows - 1 < last_row) ? next + rows - 1 : last_row;
    }

    /* 5. Swap, also after ERR_COUNT ("a requested swap still happens").
     *    Nothing is copied: the new back buffer keeps the old front's pixels. */
    if (ctrl & GPU_CTRL_SWAP_MASK) {
        m->open_strip = -1; /* closed, and in the back buffer before the swap */
        m->front ^= 1u;
        m->frame_count++;
    }

    /* 6. Done. */
    m->done_seq = tag;
}

/* -------------------------------------------------------------------- bus */

static bool span_w_supported(unsigned w)
{
    return w == 1u || w == 4u || w == 8u || w == 16u;
}

/* A frame the model draws: the contract's or the largest (0 x 0 is "the
 * default", handled by the callers). */
static bool fb_supported(uint32_t w, uint32_t h)
{
    return (w == GPU_FB_WIDTH && h == GPU_FB_HEIGHT) ||
           (w == GPU_FB_MAX_WIDTH && h == GPU_FB_MAX_HEIGHT);
}

bool gpu_model_parse_frame(const char *text, uint32_t *w, uint32_t *h)
{
    unsigned width = 0;
    unsigned height = 0;
    char tail = 0;

    if (sscanf(text, "%ux%u%c", &width, &height, &tail) != 2 ||
        !fb_supported(width, height)) {
        return false;
    }
    *w = width;
    *h = height;
    return true;
}

/* STRIP_ROWS of a strip build: a power of two up to the frame's height (0 x 0
 * is the contract's frame). */
static bool strip_rows_supported(const gpu_model_config *cfg)
{
    const uint32_t height = cfg->fb_height != 0u ? cfg->fb_height : GPU_FB_HEIGHT;
    const uint32_t rows = cfg->strip_rows;
    return rows != 0u && (rows & (rows - 1u)) == 0u && rows <= height;
}

/* A capacity the model can hold: 1 ... max (0 is "the default", handled by
 * the callers). */
static bool cap_supported(uint32_t cap, uint32_t max)
{
    return cap >= 1u && cap <= max;
}

const char *gpu_model_config_error(const gpu_model_config *cfg)
{
    if (cfg == NULL) {
        return NULL;
    }
    if (!span_w_supported(cfg->span_w)) {
        return "span_w is not 1, 4, 8 or 16";
    }
    if (cfg->zbuf_bits > 16u) { /* 0 counts as given: it means 16 */
        return "zbuf_bits is not 1 .. 16";
    }
    if (cfg->vtx_cap != 0u && !cap_supported(cfg->vtx_cap, GPU_MODEL_MAX_VTX_CAP)) {
        return "vtx_cap is above the contract's VTX_CAP_MAX, what the vertex window holds";
    }
    if (cfg->tri_cap != 0u && !cap_supported(cfg->tri_cap, GPU_MODEL_MAX_TRI_CAP)) {
        return "tri_cap is above the contract's TRI_CAP_MAX, what the index window holds";
    }
    if ((cfg->fb_width != 0u || cfg->fb_height != 0u) && !fb_supported(cfg->fb_width, cfg->fb_height)) {
        return "fb_width x fb_height is neither the contract's frame nor its largest";
    }
    if (cfg->strip_rows != 0u && !strip_rows_supported(cfg)) {
        return "strip_rows is not a power of two up to the frame's height";
    }
    return NULL;
}

void gpu_model_reset_config(gpu_model *m, const gpu_model_config *cfg)
{
    gpu_model_config c = { GPU_MODEL_DEFAULT_SPAN_W, GPU_MODEL_DEFAULT_LINES,
                           GPU_MODEL_DEFAULT_ZBUF, GPU_MODEL_DEFAULT_VTX_CAP,
                           GPU_MODEL_DEFAULT_TRI_CAP, GPU_MODEL_DEFAULT_ZBUF_BITS,
                           GPU_MODEL_DEFAULT_WMASK, GPU_MODEL_DEFAULT_GOURAUD,
                           GPU_FB_WIDTH, GPU_FB_HEIGHT, GPU_DEFAULT_STRIP_ROWS };
    if (cfg != NULL) {
        c = *cfg;
        if (!span_w_supported(c.span_w)) {
            c.span_w = GPU_MODEL_DEFAULT_SPAN_W;
        }
        if (c.zbuf_bits < 1u || c.zbuf_bits > 16u) {
            c.zbuf_bits = GPU_MODEL_DEFAULT_ZBUF_BITS;
        }
        if (!cap_supported(c.vtx_cap, GPU_MODEL_MAX_VTX_CAP)) {
            c.vtx_cap = GPU_MODEL_DEFAULT_VTX_CAP; /* 0: the default; else refused */
        }
        if (!cap_supported(c.tri_cap, GPU_MODEL_MAX_TRI_CAP)) {
            c.tri_cap = GPU_MODEL_DEFAULT_TRI_CAP;
        }
        if (!fb_supported(c.fb_width, c.fb_height)) {
            c.fb_width = GPU_FB_WIDTH; /* 0 x 0: the default; else refused */
            c.fb_height = GPU_FB_HEIGHT;
        }
        if (c.strip_rows != 0u && !strip_rows_supported(&c)) {
            c.strip_rows = 0u; /* refused: no strip buffer */
        }
    }
    /* Everything is zero at power-on: registers (RESET included), counters,
     * front = 0, palette black, both framebuffers palette index 0, depth
     * buffer 0 (block RAM initial values). */
    memset(m, 0, sizeof *m); /* the shade probe detached too */
    m->cfg = c;
    m->regs.fb_write_mask = GPU_MODEL_WMASK_BITS; /* both planes */
    m->regs.strip = (c.fb_height - 1u) << GPU_STRIP_LAST_LSB; /* the whole frame */
    m->open_strip = -1;
}

void gpu_model_attach_shade_probe(gpu_model *m, gpu_model_shade_probe *probe)
{
    m->shade_probe = probe;
    if (probe != NULL) {
        memset(probe, 0, sizeof *probe);
    }
}

void gpu_model_reset(gpu_model *m)
{
    gpu_model_reset_config(m, NULL);
}

uint32_t gpu_model_caps(const gpu_model *m)
{
    uint32_t caps = ((uint32_t)m->cfg.span_w << GPU_CAPS_SPAN_W_LSB) &
                    GPU_CAPS_SPAN_W_MASK;
    if (m->cfg.lines) {
        caps |= GPU_CAPS_LINES_MASK;
    }
    if (m->cfg.zbuf) {
        caps |= GPU_CAPS_ZBUF_MASK;
        caps |= ((uint32_t)m->cfg.zbuf_bits << GPU_CAPS_ZBUF_BITS_LSB) &
                GPU_CAPS_ZBUF_BITS_MASK;
    }
    if (m->cfg.wmask) {
        caps |= GPU_CAPS_WMASK_MASK;
    }
    if (m->cfg.gouraud) {
        caps |= GPU_CAPS_GOURAUD_MASK;
    }
    return caps;
}

void gpu_model_write(gpu_model *m, uint32_t offset, uint32_t value)
{
    if (offset & 3u) {
        return; /* only aligned words exist on the bus */
    }

    if (offset >= GPU_WIN_PALETTE &&
        offset - GPU_WIN_PALETTE < GPU_WIN_PALETTE_BYTES) {
        uint32_t i = (offset - GPU_WIN_PALETTE) / 4u;
        if (i < GPU_PALETTE_ENTRIES) {
            m->palette[i] = (uint16_t)(value & 0xFFFu); /* RGB444 in [11:0] */
        }
        return;
    }
    if (offset >= GPU_WIN_VTX && offset - GPU_WIN_VTX < GPU_WIN_VTX_BYTES) {
        uint32_t i = (offset - GPU_WIN_VTX) / 4u;
        if (i < VTX_WORDS_TOTAL(m)) {
            m->vtx[i] = value;
        }
        return;
    }
    if (offset >= GPU_WIN_IDX && offset - GPU_WIN_IDX < GPU_WIN_IDX_BYTES) {
        uint32_t i = (offset - GPU_WIN_IDX) / 4u;
        if (i < IDX_WORDS_TOTAL(m)) {
            m->idx[i] = value;
        }
        return;
    }

    /* Registers: only the rw batch registers take writes; writes to the
     * read-only registers and to holes are ignored. */
    switch (offset) {
    case GPU_REG_CTRL:
        m->regs.ctrl = value & GPU_MODEL_CTRL_BITS; /* the defined bits */
        break;
    case GPU_REG_VTX_BASE:
        m->regs.vtx_base = value;
        break;
    case GPU_REG_VTX_COUNT:
        m->regs.vtx_count = value;
        break;
    case GPU_REG_TRI_BASE:
        m->regs.tri_base = value;
        break;
    case GPU_REG_TRI_COUNT:
        m->regs.tri_count = value;
        break;
    case GPU_REG_CLEAR_COLOR:
        m->regs.clear_color = value;
        break;
    case GPU_REG_FB_WRITE_MASK:
        if (m->cfg.wmask) {
            m->regs.fb_write_mask = value & GPU_MODEL_WMASK_BITS;
        }
        break;
    case GPU_REG_STRIP:
        m->regs.strip = value;
        break;
    case GPU_REG_DOORBELL:
        /* Any write starts a batch, whatever the value (the contract asks the
         * firmware for fresh non-zero tags but the device does not check). */
        m->regs.doorbell = value;
        run_batch(m, value);
        break;
    case GPU_REG_RESET:
        /* Aborts the running batch: there never is one in the model (a
         * batch completes inside the DOORBELL write), so the value is
         * stored, to read back, and the open strip dropped. */
        m->regs.reset = value;
        m->open_strip = -1; /* dropped: the next batch of its rows opens it anew */
        break;
    default:
        break;
    }
}

uint32_t gpu_model_read(const gpu_model *m, uint32_t offset)
{
    if (offset & 3u) {
        return 0;
    }
    /* The palette, vertex and index windows are write-only: they read 0, as
     * does everything outside the register window, via the default case. */
    switch (offset) {
    case GPU_REG_ID:
        return GPU_ID_VALUE;
    case GPU_REG_VERSION:
        return GPU_VERSION_VALUE;
    case GPU_REG_CAPS:
        return gpu_model_caps(m);
    case GPU_REG_VTX_CAP:
        return m->cfg.vtx_cap;
    case GPU_REG_TRI_CAP:
        return m->cfg.tri_cap;
    case GPU_REG_FB_SIZE:
        return m->cfg.fb_width | (m->cfg.fb_height << 16);
    case GPU_REG_STRIP_ROWS:
        return m->cfg.strip_rows;
    case GPU_REG_SCANOUT_UNDERFLOWS:
        return 0; /* the model has no display to fall behind: the co-simulation holds the RTL's to 0 */
    case GPU_REG_CTRL:
        return m->regs.ctrl;
    case GPU_REG_VTX_BASE:
        return m->regs.vtx_base;
    case GPU_REG_VTX_COUNT:
        return m->regs.vtx_count;
    case GPU_REG_TRI_BASE:
        return m->regs.tri_base;
    case GPU_REG_TRI_COUNT:
        return m->regs.tri_count;
    case GPU_REG_CLEAR_COLOR:
        return m->regs.clear_color;
    case GPU_REG_FB_WRITE_MASK:
        return m->regs.fb_write_mask;
    case GPU_REG_STRIP:
        return m->regs.strip;
    case GPU_REG_DOORBELL:
        return m->regs.doorbell;
    case GPU_REG_RESET:
        return m->regs.reset;
    case GPU_REG_STATUS:
        /* BUSY is always 0 between calls: batches complete inside write. */
        return (m->front << GPU_STATUS_FRONT_LSB) & GPU_STATUS_FRONT_MASK;
    case GPU_REG_DONE_SEQ:
        return m->done_seq;
    case GPU_REG_FRAME_COUNT:
        return m->frame_count;
    case GPU_REG_ERRORS:
        return m->errors;
    case GPU_REG_PERF_BUSY_CYCLES:
        return 0; /* cycles are not modelled */
    case GPU_REG_PERF_TRIS_IN:
        return m->perf.tris_in;
    case GPU_REG_PERF_TRIS_DRAWN:
        return m->perf.tris_drawn;
    case GPU_REG_PERF_TRIS_REJECTED:
        return m->perf.tris_rejected;
    case GPU_REG_PERF_PIXELS:
        return m->perf.pixels;
    case GPU_REG_PERF_SAMPLES:
        return m->perf.samples;
    case GPU_REG_PERF_SPANS_WRITTEN:
        return m->perf.spans_written;
    case GPU_REG_PERF_SPANS_VISITED:
        return 0; /* implementation-specific, not modelled */
    default:
        return 0;
    }
}

/* ---------------------------------------------------------------- outputs */

const uint8_t *gpu_model_front(const gpu_model *m)
{
    return m->fb[m->front & 1u];
}

const uint8_t *gpu_model_back(const gpu_model *m)
{
    return m->fb[(m->front & 1u) ^ 1u];
}

void gpu_model_scanout(const gpu_model *m, uint8_t *rgb)
{
    const uint8_t *fb = gpu_model_front(m);
    const uint32_t scale = GPU_MODEL_SCREEN_W / m->cfg.fb_width;
    for (uint32_t y = 0; y < GPU_MODEL_SCREEN_H; y++) {
        for (uint32_t x = 0; x < GPU_MODEL_SCREEN_W; x++) {
            /* Each framebuffer pixel covers a scale x scale block of the screen. */
            uint16_t c = m->palette[fb[(y / scale) * m->cfg.fb_width + x / scale]];
            uint8_t *out = &rgb[((size_t)y * GPU_MODEL_SCREEN_W + x) * 3u];
            /* n * 17 maps a 4-bit channel onto 0..255 exactly (0xF -> 0xFF). */
            out[0] = (uint8_t)(((c >> 8) & 0xFu) * 17u);
            out[1] = (uint8_t)(((c >> 4) & 0xFu) * 17u);
            out[2] = (uint8_t)((c & 0xFu) * 17u);
        }
    }
}

/* One RGB444 channel (4 bits at lsb) of palette entries a and b expanded to
 * 0..255 (n * 17) and mixed by frac / 4096 towards b, rounded. */
static uint8_t mix_channel(uint16_t a, uint16_t b, unsigned lsb, uint32_t frac)
{
    uint32_t ca = ((a >> lsb) & 0xFu) * 17u;
    uint32_t cb = ((b >> lsb) & 0xFu) * 17u;
    return (uint8_t)((ca * (4096u - frac) + cb * frac + 2048u) / 4096u);
}

void gpu_model_scanout_unquantised(const gpu_model *m, uint8_t *rgb)
{
    const uint32_t *probe = m->shade_probe->px[m->front & 1u];
    const uint32_t scale = GPU_MODEL_SCREEN_W / m->cfg.fb_width;
    gpu_model_scanout(m, rgb);
    for (uint32_t y = 0; y < GPU_MODEL_SCREEN_H; y++) {
        for (uint32_t x = 0; x < GPU_MODEL_SCREEN_W; x++) {
            uint32_t word = probe[(y / scale) * m->cfg.fb_width + x / scale];
            if ((word & GPU_MODEL_PROBE_SHADED) == 0) {
                continue;
            }
            uint32_t inten = word & 0xFFFFu;
            if (inten > 15u << 12) {
                inten = 15u << 12; /* the ramp ends at level 15 */
            }
            uint32_t base = (word >> 16) & 0xFFu;
            uint32_t level = inten >> 12;
            uint32_t frac = inten & 0xFFFu;
            uint16_t lo = m->palette[(base + level) & 0xFFu];
            uint16_t hi = m->palette[(base + level + (frac != 0u)) & 0xFFu];
            uint8_t *out = &rgb[((size_t)y * GPU_MODEL_SCREEN_W + x) * 3u];
            out[0] = mix_channel(lo, hi, 8, frac);
            out[1] = mix_channel(lo, hi, 4, frac);
            out[2] = mix_channel(lo, hi, 0, frac);
        }
    }
}
