/*
 * fuzz_gpu_model — libFuzzer target for the golden model's public API (gpu_model.h): arbitrary
 * bus writes and reads — registers, palette, vertex and index words, unaligned and unmapped
 * offsets — and doorbells, on a model built with fuzzed options.
 *
 * The input: byte 0 picks the build options (span width, lines, depth buffer); then commands of
 * an opcode byte and its operands (see the switch below). Values are raw fuzz bytes or, often,
 * picked from edge values (capacities and one past them, int16 extremes, kinds 0..2 and 255).
 *
 * Properties checked at every doorbell (a violation aborts; ASan + UBSan are on, the model is
 * malloc'ed on its own so a write past its end is caught; the rasterizer's own out-of-range
 * writes inside the struct are caught by the buffer comparisons):
 *   - no crash; a batch changes only the back buffer, the depth buffer (only on a depth-buffer
 *     build, only with CTRL_ZCLEAR or CTRL_ZTEST), the status and counter registers — never the
 *     front buffer, the palette, the vertex or index buffers, the batch registers or the options;
 *   - ERRORS is exactly what the contract says, computed here independently: ERR_COUNT when
 *     VTX_BASE + VTX_COUNT > VTX_CAP or TRI_BASE + TRI_COUNT > TRI_CAP (64-bit sums; then nothing
 *     is drawn, the back buffer is unchanged and every counter is 0); otherwise ERR_KIND for a
 *     kind the build lacks, ERR_VTX_INDEX for an index >= VTX_COUNT; never ERR_WRITE_BUSY;
 *   - the counters add up: TRIS_IN = TRI_COUNT = TRIS_DRAWN + TRIS_REJECTED, rejected >= the
 *     primitives with a flagged error, PIXELS <= SAMPLES, back-buffer pixels that changed <=
 *     PIXELS (+ the clear), DONE_SEQ = the tag, FRAME_COUNT and STATUS.FRONT follow CTRL_SWAP;
 *   - reads of write-only windows, unmapped and unaligned offsets return 0.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu_model.h"
#include "fuzz_common.h"

/* A register value: mostly the edges that matter, sometimes raw. */
static uint32_t take_value(struct reader *r)
{
    static const uint32_t edge[] = {
        0u, 1u, 2u, 3u, GPU_VTX_CAP - 1u, GPU_VTX_CAP, GPU_VTX_CAP + 1u, GPU_TRI_CAP - 1u,
        GPU_TRI_CAP, GPU_TRI_CAP + 1u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, 0xFFFFFFFEu,
        0xFFFFu, 0x10000u,
    };
    const uint32_t sel = take8(r);
    if (sel < 128u) {
        return edge[sel % (sizeof edge / sizeof edge[0])];
    }
    if (sel < 192u) {
        return sel & 0x3Fu;  /* small counts: batches the fuzzer can fill */
    }
    return take32(r);
}

/* A vertex coordinate: int16 extremes, around the screen, or raw. */
static uint32_t take_coord(struct reader *r)
{
    static const int32_t edge[] = {-32768, 32767, 0, 8, 7, 9, 5112, 3832, -1, 16, 5120, 3840};
    const uint32_t sel = take8(r);
    if (sel < 64u) {
        return (uint16_t)edge[sel % (sizeof edge / sizeof edge[0])];
    }
    return take16(r);
}

static const uint32_t batch_regs[] = {
    GPU_REG_CTRL, GPU_REG_VTX_BASE, GPU_REG_VTX_COUNT, GPU_REG_TRI_BASE, GPU_REG_TRI_COUNT,
    GPU_REG_CLEAR_COLOR, GPU_REG_RESET,
    /* read-only registers and holes: writes ignored */
    GPU_REG_ID, GPU_REG_VTX_CAP, GPU_REG_STATUS, GPU_REG_DONE_SEQ, GPU_REG_FRAME_COUNT,
    GPU_REG_ERRORS, GPU_REG_PERF_PIXELS, 0x018u, 0x0FCu, 0x100u,
};

static gpu_model *before;  /* the state just before a doorbell */
static gpu_model *model;   /* malloc'ed on its own: ASan sees any write past its end */

/* The contract's ERRORS for the batch the registers describe now. */
static uint32_t expected_errors(const gpu_model *m, uint32_t *flagged)
{
    uint32_t errors = 0;

    *flagged = 0;
    if ((uint64_t)m->regs.vtx_base + m->regs.vtx_count > GPU_VTX_CAP ||
        (uint64_t)m->regs.tri_base + m->regs.tri_count > GPU_TRI_CAP) {
        return GPU_ERR_COUNT_MASK;
    }
    for (uint32_t i = 0; i < m->regs.tri_count; i++) {
        const uint32_t *w = &m->idx[(m->regs.tri_base + i) * GPU_PRIM_WORDS];
        const uint32_t kind = (w[GPU_PRIM_KIND_WORD] >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK;
        const uint32_t i0 = (w[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK;
        const uint32_t i1 = (w[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK;
        const uint32_t i2 = (w[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK;
        const bool line = kind == GPU_PRIM_KIND_LINE;

        if (!(kind == GPU_PRIM_KIND_TRI || (line && m->cfg.lines) ||
              (kind == GPU_PRIM_KIND_TRI_GOURAUD && m->cfg.gouraud))) {
            errors |= GPU_ERR_KIND_MASK;
            (*flagged)++;
        } else if (i0 >= m->regs.vtx_count || i1 >= m->regs.vtx_count ||
                   (!line && i2 >= m->regs.vtx_count)) {
            errors |= GPU_ERR_VTX_INDEX_MASK;
            (*flagged)++;
        }
    }
    return errors;
}

static void doorbell(gpu_model *m, uint32_t tag)
{
    uint32_t flagged;
    const uint32_t want = expected_errors(m, &flagged);
    const uint32_t old_front = m->front & 1u;
    const bool swap = (m->regs.ctrl & GPU_CTRL_SWAP_MASK) != 0u;
    const bool clear = (m->regs.ctrl & GPU_CTRL_CLEAR_MASK) != 0u;
    const bool zbuf_may_change =
        m->cfg.zbuf && (m->regs.ctrl & (GPU_CTRL_ZCLEAR_MASK | GPU_CTRL_ZTEST_MASK)) != 0u;

    memcpy(before, m, sizeof *m);
    gpu_model_write(m, GPU_REG_DOORBELL, tag);

    REQUIRE(m->errors == want, "ERRORS 0x%x, contract says 0x%x", m->errors, want);
    REQUIRE(gpu_model_read(m, GPU_REG_ERRORS) == want, "ERRORS read");
    REQUIRE(gpu_model_read(m, GPU_REG_DONE_SEQ) == tag, "DONE_SEQ");
    REQUIRE(gpu_model_read(m, GPU_REG_DOORBELL) == tag, "DOORBELL read back");
    REQUIRE((gpu_model_read(m, GPU_REG_STATUS) & GPU_STATUS_BUSY_MASK) == 0u, "BUSY");
    REQUIRE(m->frame_count == before->frame_count + (swap ? 1u : 0u), "FRAME_COUNT");
    REQUIRE((m->front & 1u) == (old_front ^ (swap ? 1u : 0u)), "front");

    /* What a batch must never touch. */
    REQUIRE(memcmp(&m->cfg, &before->cfg, sizeof m->cfg) == 0, "build options changed");
    REQUIRE(m->regs.ctrl == before->regs.ctrl && m->regs.vtx_base == before->regs.vtx_base &&
                m->regs.vtx_count == before->regs.vtx_count &&
                m->regs.tri_base == before->regs.tri_base &&
                m->regs.tri_count == before->regs.tri_count &&
                m->regs.clear_color == before->regs.clear_color &&
                m->regs.reset == before->regs.reset,
            "batch registers changed");
    REQUIRE(memcmp(m->palette, before->palette, sizeof m->palette) == 0, "palette written");
    REQUIRE(memcmp(m->vtx, before->vtx, sizeof m->vtx) == 0, "vertex buffer written");
    REQUIRE(memcmp(m->idx, before->idx, sizeof m->idx) == 0, "index buffer written");
    REQUIRE(memcmp(m->fb[old_front], before->fb[old_front], GPU_MODEL_FB_PIXELS) == 0,
            "the scanned-out buffer was drawn into");
    if (!zbuf_may_change || (want & GPU_ERR_COUNT_MASK) != 0u) {
        REQUIRE(memcmp(m->zbuf, before->zbuf, sizeof m->zbuf) == 0, "depth buffer written");
    }

    /* The back buffer and the counters. */
    const uint8_t *back_now = m->fb[old_front ^ 1u];
    const uint8_t *back_was = before->fb[old_front ^ 1u];
    uint32_t changed = 0;
    for (uint32_t i = 0; i < GPU_MODEL_FB_PIXELS; i++) {
        changed += (back_now[i] != back_was[i]) ? 1u : 0u;
    }
    if ((want & GPU_ERR_COUNT_MASK) != 0u) {
        REQUIRE(changed == 0u, "ERR_COUNT batch drew %u pixels", changed);
        REQUIRE(m->perf.tris_in == 0u && m->perf.tris_drawn == 0u &&
                    m->perf.tris_rejected == 0u && m->perf.pixels == 0u &&
                    m->perf.samples == 0u && m->perf.spans_written == 0u,
                "counters after ERR_COUNT");
        return;
    }
    REQUIRE(m->perf.tris_in == m->regs.tri_count, "TRIS_IN %u of %u", m->perf.tris_in,
            m->regs.tri_count);
    REQUIRE(m->perf.tris_drawn + m->perf.tris_rejected == m->perf.tris_in, "drawn + rejected");
    REQUIRE(m->perf.tris_rejected >= flagged, "rejected %u < %u flagged", m->perf.tris_rejected,
            flagged);
    REQUIRE(m->perf.pixels <= m->perf.samples, "PIXELS %u > SAMPLES %u", m->perf.pixels,
            m->perf.samples);
    REQUIRE(m->perf.samples <= m->perf.tris_drawn * (uint32_t)GPU_MODEL_FB_PIXELS ||
                m->cfg.lines,
            "SAMPLES beyond the drawn triangles' screen area");
    if (!clear) {
        REQUIRE(changed <= m->perf.pixels, "%u pixels changed, PIXELS %u", changed,
                m->perf.pixels);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const unsigned spans[] = {1u, 4u, 8u, 16u, 3u, 0u};
    struct reader r = {data, size};
    gpu_model_config cfg = {0}; /* capacities 0: the contract's, which the checks below assume */
    uint32_t doorbells = 0;
    gpu_model *m;

    if (before == NULL) {
        before = malloc(sizeof *before);
        model = malloc(sizeof *model);
        REQUIRE(before != NULL && model != NULL, "out of memory");
    }
    m = model;

    const uint32_t opt = take8(&r);
    cfg.span_w = spans[opt % 6u];
    cfg.lines = (opt & 0x08u) != 0u;
    cfg.zbuf = (opt & 0x10u) != 0u;
    cfg.wmask = (opt & 0x40u) != 0u;
    cfg.zbuf_bits = (const unsigned[]){16u, 8u, 12u, 0u}[opt >> 6];  /* 0: replaced by 16 */
    cfg.gouraud = (opt & 0x04u) != 0u;
    gpu_model_reset_config(m, (opt & 0x20u) ? &cfg : NULL);
    if ((opt & 0x20u) == 0u) {
        REQUIRE(m->cfg.span_w == 8u && m->cfg.lines && !m->cfg.zbuf, "default options");
    } else {
        REQUIRE(m->cfg.span_w == ((cfg.span_w == 3u || cfg.span_w == 0u) ? 8u : cfg.span_w),
                "span width %u", m->cfg.span_w);
        REQUIRE(m->cfg.zbuf_bits == (cfg.zbuf_bits == 0u ? 16u : cfg.zbuf_bits), "zbuf bits %u",
                m->cfg.zbuf_bits);
    }
    REQUIRE(((gpu_model_caps(m) & GPU_CAPS_SPAN_W_MASK) >> GPU_CAPS_SPAN_W_LSB) == m->cfg.span_w,
            "CAPS_SPAN_W");

    /* Bounded work per input: the largest batch (512 screen-sized triangles) is ~40 M pixel
     * tests, so a few doorbells at most. */
    while (r.n > 0u && doorbells < 4u) {
        const uint32_t op = take8(&r) % 8u;

        switch (op) {
        case 0: {  /* a batch or other register */
            const uint32_t reg = batch_regs[take8(&r) % (sizeof batch_regs / sizeof batch_regs[0])];
            const uint32_t ro_before = gpu_model_read(m, reg);
            const uint32_t value = take_value(&r);
            gpu_model_write(m, reg, value);
            if (reg >= GPU_REG_STATUS || reg < GPU_REG_CTRL) {
                REQUIRE(gpu_model_read(m, reg) == ro_before, "read-only 0x%x written", reg);
            }
            break;
        }
        case 1: {  /* a vertex, both words */
            const uint32_t i = take16(&r) % (GPU_VTX_CAP + 8u);  /* past the buffer, too */
            const uint32_t xy = take_coord(&r) | take_coord(&r) << 16;
            const uint32_t z = take8(&r) < 128u ? take16(&r) : take32(&r);
            gpu_model_write(m, GPU_WIN_VTX + 4u * GPU_VTX_WORDS * i, xy);
            gpu_model_write(m, GPU_WIN_VTX + 4u * GPU_VTX_WORDS * i + 4u, z);
            break;
        }
        case 2: {  /* a primitive, both words */
            const uint32_t i = take16(&r) % (GPU_TRI_CAP + 8u);
            const uint32_t sel = take8(&r);
            const uint32_t kind = (sel & 0x80u) ? take8(&r) : (sel & 1u);
            const uint32_t limit = (sel & 0x40u) ? 0x10000u : 16u;  /* mostly small indices */
            const uint32_t i0 = take16(&r) % limit;
            const uint32_t i1 = take16(&r) % limit;
            const uint32_t i2 = take16(&r) % limit;
            gpu_model_write(m, GPU_WIN_IDX + 4u * GPU_PRIM_WORDS * i, i0 | i1 << 16);
            gpu_model_write(m, GPU_WIN_IDX + 4u * GPU_PRIM_WORDS * i + 4u,
                            i2 | take8(&r) << GPU_PRIM_COLOR_LSB | kind << GPU_PRIM_KIND_LSB);
            break;
        }
        case 3: {  /* many primitives at once: a run of triangles over the first vertices */
            const uint32_t first = take16(&r) % GPU_TRI_CAP;
            const uint32_t n = take8(&r) + 1u;
            const uint32_t stride = take8(&r) % 4u + 1u;
            for (uint32_t k = 0; k < n && first + k < GPU_TRI_CAP; k++) {
                const uint32_t v = k * stride;
                gpu_model_write(m, GPU_WIN_IDX + 8u * (first + k), v | (v + 1u) << 16);
                gpu_model_write(m, GPU_WIN_IDX + 8u * (first + k) + 4u,
                                (v + 2u) | (k & 0xFFu) << GPU_PRIM_COLOR_LSB);
            }
            break;
        }
        case 4: {  /* a raw bus write anywhere, aligned or not, in or past the aperture */
            const uint32_t offset = take8(&r) < 200u ? take32(&r) % (GPU_APERTURE_BYTES + 64u)
                                                     : take32(&r);
            gpu_model_write(m, offset, take32(&r));
            break;
        }
        case 5: {  /* a raw read: write-only windows, holes and unaligned offsets read 0 */
            const uint32_t offset = take32(&r);
            const uint32_t v = gpu_model_read(m, offset);
            if ((offset & 3u) != 0u || offset >= GPU_WIN_REGS_BYTES) {
                REQUIRE(v == 0u, "read 0x%x at 0x%x", v, offset);
            }
            break;
        }
        case 6: {  /* the whole batch in one go: CTRL, bases, counts, colour */
            gpu_model_write(m, GPU_REG_CTRL, take8(&r));
            gpu_model_write(m, GPU_REG_VTX_BASE, take8(&r) < 200u ? 0u : take_value(&r));
            gpu_model_write(m, GPU_REG_VTX_COUNT, take_value(&r));
            gpu_model_write(m, GPU_REG_TRI_BASE, take8(&r) < 200u ? 0u : take_value(&r));
            gpu_model_write(m, GPU_REG_TRI_COUNT, take_value(&r));
            gpu_model_write(m, GPU_REG_CLEAR_COLOR, take32(&r));
            break;
        }
        default:  /* 7 */
            doorbell(m, take32(&r));
            doorbells++;
            break;
        }
    }
    if (doorbells == 0u) {
        doorbell(m, 1u);
    }
    /* The scan-out (the only other public entry; 300k pixels, so only sometimes). */
    if ((opt & 0xC0u) == 0xC0u) {
        static uint8_t rgb[GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3];
        gpu_model_scanout(m, rgb);
    }
    return 0;
}
