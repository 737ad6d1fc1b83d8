/*
 * fuzz_gpu_driver — libFuzzer target for the firmware's GPU driver (firmware/gpu/gpu.c) and
 * batching (firmware/gpu/batch.c), on a bus that checks every access and forwards it to the
 * golden model. The device may lie about itself (ID, VERSION, capacities, FB_SIZE) and may hang
 * (DONE_SEQ never reaches the tag) until the driver resets it.
 *
 * The input: the device's identity registers, then commands: raw batches with arbitrary bases,
 * counts and buffer words; waits with few polls; resets; hangs; and whole frames — arbitrary
 * well-formed draw lists (render_frame as render.c leaves it: indices below vert_count, the first
 * sorted_count items in a shuffled draw order, the rest naming themselves; batch_fill does not
 * check this precondition) cut by
 * batch_fill and submitted as app.c does.
 *
 * Properties (a violation aborts; ASan + UBSan are on):
 *   - gpu_init accepts only a device the contract describes — right ID, compatible VERSION,
 *     320 x 240, capacities that fit their bus windows — and writes nothing before it has
 *     checked; a palette beyond 256 entries is refused;
 *   - every bus write is aligned, inside the aperture, to a writable register or to the buffer
 *     slots of the batch being submitted (inside the capacities the device reported and inside
 *     their windows), with DOORBELL last; a refused batch (pending, or beyond capacity, however
 *     large the numbers) writes nothing and changes nothing; refusals are exactly the cases the
 *     header documents;
 *   - a hung GPU gives GPU_E_TIMEOUT after max_polls reads, submits are refused until
 *     gpu_reset, and after the reset the next batch goes through; tags are never 0 and never
 *     repeat the previous one;
 *   - batch_fill never exceeds the capacities (the device's, clamped to the header's), always
 *     makes progress, names only vertices its batch carries, and the GPU receives every primitive
 *     of the frame once, in draw order, with its own vertices, kind and colour: the model
 *     reports no error flag for such batches.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/batch.h"
#include "bsp.h"
#include "gpu/gpu.h"
#include "gpu_model.h"
#include "render/render.h"
#include "fuzz_common.h"

/* The most vertices and primitives the bus windows can hold: a capacity beyond is a lie. */
#define WIN_VTX_MAX (GPU_WIN_VTX_BYTES / (4u * GPU_VTX_WORDS))
#define WIN_IDX_MAX (GPU_WIN_IDX_BYTES / (4u * GPU_PRIM_WORDS))

/* ---- the bus ------------------------------------------------------------------------------- */

static gpu_model *gpu;
static struct {
    uint32_t id, version, caps, vtx_cap, tri_cap, fb_size, strip_rows;  /* what the device reports */
    bool hung;                /* DONE_SEQ reads stay at stale_done */
    uint32_t stale_done;
} device;

/* What the harness allows right now: writes to [vtx_lo, vtx_hi) vertex slots, [idx_lo, idx_hi)
 * primitive slots, the palette, the batch registers; DOORBELL ends the batch. */
static struct {
    bool palette;
    uint32_t vtx_lo, vtx_hi, idx_lo, idx_hi;
    bool regs;
    bool reset;
    bool doorbell_done;
    uint32_t writes;
    uint32_t fences;
} bus;

static void bus_allow_nothing(void)
{
    memset(&bus, 0, sizeof bus);
}

void fuzz_bus_fence(void)
{
    bus.fences++;
}

void fuzz_bus_write(uint32_t offset, uint32_t value)
{
    bus.writes++;
    REQUIRE((offset & 3u) == 0u && offset < GPU_APERTURE_BYTES, "write at 0x%x", offset);
    REQUIRE(!bus.doorbell_done, "write at 0x%x after DOORBELL", offset);
    if (offset >= GPU_WIN_PALETTE && offset - GPU_WIN_PALETTE < GPU_WIN_PALETTE_BYTES) {
        REQUIRE(bus.palette && (offset - GPU_WIN_PALETTE) / 4u < GPU_PALETTE_ENTRIES,
                "palette write at 0x%x", offset);
    } else if (offset >= GPU_WIN_VTX && offset - GPU_WIN_VTX < GPU_WIN_VTX_BYTES) {
        const uint32_t slot = (offset - GPU_WIN_VTX) / (4u * GPU_VTX_WORDS);
        REQUIRE(slot >= bus.vtx_lo && slot < bus.vtx_hi, "vertex slot %u outside [%u, %u)", slot,
                bus.vtx_lo, bus.vtx_hi);
    } else if (offset >= GPU_WIN_IDX && offset - GPU_WIN_IDX < GPU_WIN_IDX_BYTES) {
        const uint32_t slot = (offset - GPU_WIN_IDX) / (4u * GPU_PRIM_WORDS);
        REQUIRE(slot >= bus.idx_lo && slot < bus.idx_hi, "primitive slot %u outside [%u, %u)",
                slot, bus.idx_lo, bus.idx_hi);
    } else if (offset == GPU_REG_RESET) {
        REQUIRE(bus.reset, "RESET written");
        REQUIRE(value != gpu_model_read(gpu, GPU_REG_RESET), "RESET written with its old value");
    } else {
        REQUIRE(bus.regs && ((offset >= GPU_REG_CTRL && offset <= GPU_REG_DOORBELL) ||
                             offset == GPU_REG_STRIP),
                "register 0x%x written", offset);
        if (offset == GPU_REG_DOORBELL) {
            REQUIRE(value != 0u, "tag 0");
            REQUIRE(value != gpu_model_read(gpu, GPU_REG_DOORBELL), "tag repeats DOORBELL");
            REQUIRE(bus.fences > 0u, "no fence before DOORBELL");
            bus.doorbell_done = true;
            device.stale_done = gpu_model_read(gpu, GPU_REG_DONE_SEQ);
        }
    }
    gpu_model_write(gpu, offset, value);
}

uint32_t fuzz_bus_read(uint32_t offset)
{
    switch (offset) {
    case GPU_REG_ID:
        return device.id;
    case GPU_REG_VERSION:
        return device.version;
    case GPU_REG_CAPS:
        return device.caps;
    case GPU_REG_VTX_CAP:
        return device.vtx_cap;
    case GPU_REG_TRI_CAP:
        return device.tri_cap;
    case GPU_REG_FB_SIZE:
        return device.fb_size;
    case GPU_REG_DONE_SEQ:
        return device.hung ? device.stale_done : gpu_model_read(gpu, offset);
    default:
        return gpu_model_read(gpu, offset);
    }
}

/* ---- the input ----------------------------------------------------------------------------- */

/* A count or base: the edges that matter, small values, or raw. */
static uint32_t take_value(struct reader *r)
{
    static const uint32_t edge[] = {
        0u, 1u, 2u, 3u, GPU_VTX_CAP - 1u, GPU_VTX_CAP, GPU_VTX_CAP + 1u, GPU_TRI_CAP - 1u,
        GPU_TRI_CAP, GPU_TRI_CAP + 1u, WIN_VTX_MAX, WIN_VTX_MAX + 1u, 0x7FFFFFFFu, 0x80000000u,
        0xFFFFFFFFu, 0x20000000u, 0x10000u,
    };
    const uint32_t sel = take8(r);
    if (sel < 128u) {
        return edge[sel % (sizeof edge / sizeof edge[0])];
    }
    if (sel < 224u) {
        return sel & 0x1Fu;
    }
    return take32(r);
}

/* ---- checks -------------------------------------------------------------------------------- */

static uint32_t vtx_words[WIN_VTX_MAX * GPU_VTX_WORDS];
static uint32_t prim_words[WIN_IDX_MAX * GPU_PRIM_WORDS];
/* A frame of 3000 vertices and primitives (make_frame's largest); this program links batch.c
 * without render.c, so the storage is attached by hand (as render_frame_init would). */
static struct proj_vertex frame_vert[3000];
static struct render_prim frame_prim[3000];
static sort_item_t frame_sort_item[3000];
static struct render_frame frame = {
    .vert = frame_vert, .prim = frame_prim, .sort_item = frame_sort_item, .sort_tmp = NULL,
    .sort = NULL, .vert_cap = 3000u, .prim_cap = 3000u,
};
static uint32_t batch_vtx[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t batch_prim[GPU_TRI_CAP * GPU_PRIM_WORDS];
static struct batch_words words = BATCH_WORDS_ON(batch_vtx, batch_prim);

/* Submit through the driver with the bus open exactly for this batch; check the outcome. */
static int submit(struct gpu_dev *dev, const struct gpu_batch *b, uint32_t *tag)
{
    const struct gpu_dev dev_before = *dev;
    const uint32_t doorbell_before = gpu_model_read(gpu, GPU_REG_DOORBELL);
    const bool fits = (uint64_t)b->vtx_base + b->vtx_count <= dev->info.vtx_cap &&
                      (uint64_t)b->tri_base + b->prim_count <= dev->info.tri_cap;
    int rc;

    bus_allow_nothing();
    bus.vtx_lo = b->vtx_base;
    bus.vtx_hi = b->vtx_base + b->vtx_count;  /* only used when it fits, so no wrap */
    bus.idx_lo = b->tri_base;
    bus.idx_hi = b->tri_base + b->prim_count;
    bus.regs = true;
    rc = gpu_submit_batch(dev, b, tag);
    if (dev_before.pending || !fits) {
        REQUIRE(rc == (dev_before.pending ? GPU_E_PENDING : GPU_E_CAPACITY), "rc %d", rc);
        REQUIRE(bus.writes == 0u && bus.fences == 0u, "a refused batch wrote %u words",
                bus.writes);
        REQUIRE(memcmp(dev, &dev_before, sizeof *dev) == 0, "a refused batch changed the driver");
        return rc;
    }
    REQUIRE(rc == GPU_OK, "rc %d for a batch that fits", rc);
    REQUIRE(bus.doorbell_done, "no doorbell");
    /* The buffers' words, then CTRL, VTX_BASE/COUNT, TRI_BASE/COUNT, CLEAR_COLOR, STRIP, DOORBELL. */
    REQUIRE(bus.writes == GPU_VTX_WORDS * b->vtx_count + GPU_PRIM_WORDS * b->prim_count + 8u,
            "%u writes", bus.writes);
    REQUIRE(*tag != 0u && *tag != doorbell_before && dev->pending, "tag %u", *tag);
    /* The model has run the batch: ERR_COUNT exactly when it exceeds the model's own buffers
     * (a device that over-reported its capacities). */
    const bool over = (uint64_t)b->vtx_base + b->vtx_count > GPU_VTX_CAP ||
                      (uint64_t)b->tri_base + b->prim_count > GPU_TRI_CAP;
    REQUIRE(((gpu_model_read(gpu, GPU_REG_ERRORS) & GPU_ERR_COUNT_MASK) != 0u) == over,
            "ERR_COUNT");
    bus_allow_nothing();
    return rc;
}

static int wait(struct gpu_dev *dev, uint32_t tag, uint32_t polls)
{
    const bool done = fuzz_bus_read(GPU_REG_DONE_SEQ) == tag;  /* what the driver will read */
    int rc;

    bus_allow_nothing();
    rc = gpu_wait(dev, tag, polls);
    REQUIRE(bus.writes == 0u, "gpu_wait wrote");
    if (!done || polls == 0u) {
        REQUIRE(rc == GPU_E_TIMEOUT, "rc %d: should time out", rc);
    } else {
        REQUIRE(rc == GPU_OK && !dev->pending, "rc %d", rc);
    }
    return rc;
}

static void reset(struct gpu_dev *dev)
{
    const uint32_t resets = dev->resets;

    bus_allow_nothing();
    bus.reset = true;
    gpu_reset(dev);
    REQUIRE(bus.writes == 1u && !dev->pending && dev->resets == resets + 1u, "gpu_reset");
    device.hung = false;  /* the contract: RESET returns the GPU to idle */
    bus_allow_nothing();
}

/* An arbitrary well-formed draw list (the precondition batch_fill has: render.c builds it). */
static void make_frame(struct reader *r)
{
    const uint32_t nv = take16(r) % 3000u + 1u;
    const uint32_t np = take16(r) % 3000u;

    /* As render_frame_begin and the projection leave it (every new vertex has stamp 0), except
     * that the frame's stamp counter starts anywhere, so its wrap past 255 is exercised. */
    frame.batch_stamp = (uint8_t)(0xFFu - (take8(r) & 0x0Fu));
    frame.vert_count = nv;
    for (uint32_t i = 0; i < nv; i++) {
        /* Signed, but within a pixel or two of the origin: the model then rejects or draws
         * each triangle at once (what is checked here is what reaches it, not the pixels). */
        const uint32_t xy = take32(r) ^ (i * 0x9E3779B9u);
        frame.vert[i].sxy = (uint32_t)(uint16_t)((int32_t)(xy & 0x1Fu) - 16) |
                            (uint32_t)(uint16_t)((int32_t)((xy >> 16) & 0x1Fu) - 16) << 16;
        frame.vert[i].zbuf = (uint16_t)(i * 7u);
        frame.vert[i].batch_stamp = 0;
    }
    /* Primitives: mostly sharing nearby vertices (so batches share), sometimes far ones. */
    for (uint32_t i = 0; i < np; i++) {
        const uint32_t sel = take8(r);
        const uint32_t base = (sel & 0x80u) ? take16(r) % nv : (i * 2u) % nv;
        struct render_prim *p = &frame.prim[i];
        p->v[0] = (render_index)base;
        p->v[1] = (render_index)((base + 1u + (sel & 3u)) % nv);
        p->v[2] = (render_index)((base + 2u + ((sel >> 2) & 3u)) % nv);
        p->kind = (sel & 0x40u) ? GPU_PRIM_KIND_LINE : GPU_PRIM_KIND_TRI;
        p->color = (uint8_t)i;
    }
    frame.prim_count = np;
    frame.sorted_count = np ? take16(r) % (np + 1u) : 0u;
    for (uint32_t i = 0; i < frame.sorted_count; i++) {
        frame.sort_item[i] = i;
    }
    for (uint32_t i = frame.sorted_count; i > 1u; i--) {  /* a shuffled draw order */
        const uint32_t j = take16(r) % i;
        const sort_item_t t = frame.sort_item[i - 1u];
        frame.sort_item[i - 1u] = frame.sort_item[j];
        frame.sort_item[j] = t;
    }
    for (uint32_t i = 0; i < frame.sorted_count; i++) {
        frame.sort_item[i] |= sort_item_make(take8(r), 0u);  /* a draw key above the index */
    }
    for (uint32_t i = frame.sorted_count; i < np; i++) {
        frame.sort_item[i] = sort_item_make(0xFFFFu, i);  /* the overlay's items name themselves */
    }
}

/* app_submit: batch after batch, each waited for; check what the GPU received. */
static void submit_frame(struct gpu_dev *dev)
{
    const uint32_t vcap = dev->info.vtx_cap < GPU_VTX_CAP ? dev->info.vtx_cap : GPU_VTX_CAP;
    const uint32_t tcap = dev->info.tri_cap < GPU_TRI_CAP ? dev->info.tri_cap : GPU_TRI_CAP;
    struct batch_cursor cur;
    uint32_t drawn = 0;

    if (dev->pending) {
        reset(dev);  /* the watchdog's way out */
    }
    device.hung = false;
    batch_begin(&cur);
    do {
        struct gpu_batch b;
        uint32_t tag;
        const uint32_t next = cur.next;

        batch_fill(&cur, &frame, dev->info.vtx_cap, dev->info.tri_cap, &words);
        REQUIRE(words.vtx_count <= vcap && words.prim_count <= tcap, "batch %u/%u over %u/%u",
                words.vtx_count, words.prim_count, vcap, tcap);
        REQUIRE(words.prim_count > 0u || frame.prim_count == 0u, "no progress");
        REQUIRE(cur.next == next + words.prim_count, "cursor");
        b = batch_descriptor(&words, GPU_CTRL_CLEAR_MASK, 0);
        REQUIRE(submit(dev, &b, &tag) == GPU_OK, "a batch_fill batch was refused");
        REQUIRE(wait(dev, tag, 1u) == GPU_OK, "wait");
        REQUIRE(gpu_model_read(gpu, GPU_REG_ERRORS) == 0u, "the GPU flagged 0x%x",
                gpu_model_read(gpu, GPU_REG_ERRORS));
        REQUIRE(gpu_model_read(gpu, GPU_REG_PERF_TRIS_IN) == words.prim_count, "TRIS_IN");
        /* What the GPU holds: each primitive of the draw order, with its own vertices. */
        for (uint32_t k = 0; k < words.prim_count; k++) {
            const struct render_prim *p = &frame.prim[render_draw_index(&frame, next + k)];
            const uint32_t *w = &gpu->idx[k * GPU_PRIM_WORDS];
            const uint32_t at[3] = {
                (w[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK,
                (w[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK,
                (w[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK,
            };
            REQUIRE(((w[GPU_PRIM_KIND_WORD] >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK) == p->kind &&
                        ((w[GPU_PRIM_COLOR_WORD] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK) ==
                            p->color,
                    "primitive %u: kind or colour", k);
            for (int j = 0; j < 3; j++) {
                REQUIRE(at[j] < words.vtx_count, "index %u of %u", at[j], words.vtx_count);
                const uint32_t *v = &gpu->vtx[at[j] * GPU_VTX_WORDS];
                REQUIRE(v[0] == frame.vert[p->v[j]].sxy &&
                            ((v[GPU_VTX_Z_WORD] >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK) ==
                                frame.vert[p->v[j]].zbuf,
                        "primitive %u vertex %d is not its own", k, j);
            }
        }
        drawn += words.prim_count;
    } while (!batch_done(&cur, &frame));
    REQUIRE(drawn == frame.prim_count, "%u of %u primitives sent", drawn, frame.prim_count);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint16_t palette[GPU_PALETTE_ENTRIES + 8u];
    struct reader r = {data, size};
    struct gpu_dev dev;
    uint32_t tag = 0;
    uint32_t frames = 0;

    if (gpu == NULL) {
        gpu = malloc(sizeof *gpu);
        REQUIRE(gpu != NULL, "out of memory");
    }
    gpu_model_reset(gpu);
    memset(&device, 0, sizeof device);

    /* The device's identity: usually right, each field sometimes wrong. */
    const uint32_t lie = take16(&r);
    device.id = (lie & 0x1u) ? take32(&r) : GPU_ID_VALUE;
    device.version = (lie & 0x2u) ? take32(&r) : GPU_VERSION_VALUE;
    device.caps = gpu_model_caps(gpu) ^ ((lie & 0x4u) ? take32(&r) : 0u);
    device.vtx_cap = (lie & 0x8u) ? take_value(&r) : GPU_VTX_CAP;
    device.tri_cap = (lie & 0x10u) ? take_value(&r) : GPU_TRI_CAP;
    device.fb_size = (lie & 0x20u) ? take32(&r) : ((GPU_FB_HEIGHT << 16) | GPU_FB_WIDTH);
    const uint32_t n_palette = (lie & 0x40u) ? take16(&r) % (GPU_PALETTE_ENTRIES + 8u) : 16u;
    /* Stale DOORBELL / DONE_SEQ values from before, which the first tag must avoid. */
    gpu_model_write(gpu, GPU_REG_DOORBELL, take32(&r));
    if (lie & 0x80u) {
        gpu_model_write(gpu, GPU_REG_DOORBELL, take32(&r));  /* DONE_SEQ != DOORBELL */
    }

    bus_allow_nothing();
    bus.palette = true;
    const int rc = gpu_init(&dev, palette, n_palette);
    const bool good = device.id == GPU_ID_VALUE &&
                      (device.version >> 16) == (GPU_VERSION_VALUE >> 16) &&
                      device.version >= GPU_VERSION_VALUE &&
                      (device.fb_size & 0xFFFFu) >= 1u &&
                      (device.fb_size & 0xFFFFu) <= GPU_FB_MAX_WIDTH &&
                      (device.fb_size >> 16) >= 1u && (device.fb_size >> 16) <= GPU_FB_MAX_HEIGHT &&
                      device.vtx_cap >= 3u && device.vtx_cap <= WIN_VTX_MAX &&
                      device.tri_cap >= 1u && device.tri_cap <= WIN_IDX_MAX;
    REQUIRE(dev.info.id == device.id && dev.info.vtx_cap == device.vtx_cap, "info not read");
    if (!good) {
        REQUIRE(rc != GPU_OK, "gpu_init accepted a device the contract does not describe "
                "(id 0x%x version 0x%x fb 0x%x vtx_cap %u tri_cap %u)", device.id,
                device.version, device.fb_size, device.vtx_cap, device.tri_cap);
        REQUIRE(bus.writes == 0u, "gpu_init wrote to a device it refused");
        return 0;
    }
    if (n_palette > GPU_PALETTE_ENTRIES) {
        REQUIRE(rc == GPU_E_ARG && bus.writes == 0u, "palette of %u entries", n_palette);
        return 0;
    }
    REQUIRE(rc == GPU_OK && bus.writes == n_palette, "rc %d, %u writes", rc, bus.writes);
    REQUIRE(dev.next_tag != 0u && dev.next_tag != gpu_model_read(gpu, GPU_REG_DOORBELL) &&
                dev.next_tag != gpu_model_read(gpu, GPU_REG_DONE_SEQ),
            "first tag %u", dev.next_tag);

    while (r.n > 0u && frames < 3u) {
        switch (take8(&r) % 6u) {
        case 0: {  /* a raw batch */
            struct gpu_batch b;
            const uint32_t fill = take8(&r);
            b.vtx_base = take_value(&r);
            b.vtx_count = take_value(&r);
            b.tri_base = take_value(&r);
            b.prim_count = take_value(&r);
            b.ctrl = take8(&r);
            b.clear_color = (uint8_t)take8(&r);
            b.strip = (fill & 4u) ? take32(&r) : GPU_STRIP_WHOLE;
            b.vtx_words = vtx_words;
            b.prim_words = prim_words;
            /* Arbitrary buffer words (bad indices and kinds included) in the first slots. */
            for (uint32_t i = 0; i < 16u; i++) {
                vtx_words[i] = (fill & 2u) ? take32(&r) : take32(&r) & 0x000F000Fu;
                prim_words[i] = (fill & 1u) ? take32(&r) : (i % 5u) | (i % 7u) << 16;
            }
            if (submit(&dev, &b, &tag) == GPU_OK && (uint64_t)b.vtx_base + b.vtx_count <=
                                                        GPU_VTX_CAP &&
                (uint64_t)b.tri_base + b.prim_count <= GPU_TRI_CAP) {
                /* A bad index or kind is the GPU's to flag, and it does: nothing is drawn from
                 * outside the batch (fuzz_gpu_model checks the flags themselves). */
                const uint32_t errors = gpu_model_read(gpu, GPU_REG_ERRORS);
                REQUIRE((errors & ~(GPU_ERR_VTX_INDEX_MASK | GPU_ERR_KIND_MASK)) == 0u,
                        "errors 0x%x", errors);
            }
            break;
        }
        case 1:
            wait(&dev, tag, take8(&r) % 4u);
            break;
        case 2:
            reset(&dev);
            break;
        case 3:
            device.hung = true;
            break;
        default:
            make_frame(&r);
            submit_frame(&dev);
            if (take8(&r) & 1u) {
                submit_frame(&dev);  /* the same frame cut again (stamps from the first cut) */
            }
            frames++;
            break;
        }
    }
    return 0;
}
