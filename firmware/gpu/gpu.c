/*
 * gpu.c — the hardware edge of the GPU driver (see gpu.h). Every device access goes through
 * the BSP's accessors with a byte offset from gpu_regs.h: bsp_gpu_write()/bsp_gpu_read() for
 * registers, bsp_gpu_write_words() for the buffer copies (aligned 32-bit stores at BSP_GPU_BASE on
 * real hardware; calls into the golden model on the host build).
 */
#include <stddef.h>
#include <stdint.h>

#include "bsp.h"
#include "gpu/gpu.h"

#include "config/build_options.h"
#include "config/hot_path.h"

/* The contract's register names, through the platform's one accessor pair (bsp.h). */
static inline void gpu_write(uint32_t offset, uint32_t value)
{
    bsp_gpu_write(offset, value);
}

static inline uint32_t gpu_read(uint32_t offset)
{
    return bsp_gpu_read(offset);
}

static uint32_t gpu_next_tag(uint32_t tag)
{
    tag++;
    return (tag == 0u) ? 1u : tag;  /* 0 never names a batch */
}

FW_BUILD_ONCE int gpu_init(struct gpu_dev *dev, const uint16_t *palette, uint32_t n)
{
    struct gpu_info *info = &dev->info;
    uint32_t doorbell;
    uint32_t done;
    uint32_t tag;

    info->id = gpu_read(GPU_REG_ID);
    info->version = gpu_read(GPU_REG_VERSION);
    info->caps = gpu_read(GPU_REG_CAPS);
    info->vtx_cap = gpu_read(GPU_REG_VTX_CAP);
    info->tri_cap = gpu_read(GPU_REG_TRI_CAP);
    info->fb_size = gpu_read(GPU_REG_FB_SIZE);
    info->strip_rows = gpu_read(GPU_REG_STRIP_ROWS);
    dev->pending = false;
    dev->next_tag = 1u;
    dev->last_done_seq = 0u;
    dev->resets = 0u;

    if (info->id != GPU_ID_VALUE) {
        return GPU_E_NOT_FOUND;
    }
    /* Same major version; a newer minor only adds, an older one may lack what we use. */
    if ((info->version >> 16) != (GPU_VERSION_VALUE >> 16) || info->version < GPU_VERSION_VALUE) {
        return GPU_E_VERSION;
    }
    /* Any frame up to the contract's largest: the projection's ranges are argued for those
     * (render/proj.h). */
    if (gpu_fb_width(info) == 0u || gpu_fb_width(info) > GPU_FB_MAX_WIDTH ||
        gpu_fb_height(info) == 0u || gpu_fb_height(info) > GPU_FB_MAX_HEIGHT) {
        return GPU_E_GEOMETRY;
    }
    /* A strip buffer's strips: a power of two of rows, within the frame (contract "The strip
     * buffer"); the firmware bins its frames into them, where it is built to (FW_WITH_STRIPS). */
    if ((info->strip_rows & (info->strip_rows - 1u)) != 0u ||
        info->strip_rows > (FW_WITH_STRIPS ? gpu_fb_height(info) : 0u)) {
        return GPU_E_GEOMETRY;
    }
    /* gpu_submit_batch trusts the capacities: they must fit the windows (else buffer words would
     * land in the next window, or the offset arithmetic would wrap), and hold one triangle. */
    if (info->vtx_cap < 3u || info->vtx_cap > GPU_VTX_CAP_MAX || info->tri_cap < 1u ||
        info->tri_cap > GPU_TRI_CAP_MAX) {
        return GPU_E_BUFFERS;
    }
    if (n > GPU_PALETTE_ENTRIES || (n > 0u && palette == NULL)) {
        return GPU_E_ARG;
    }

    for (uint32_t i = 0; i < n; i++) {
        gpu_write(GPU_WIN_PALETTE + 4u * i, palette[i]);
    }

    /* The first tag must differ from what DOORBELL holds now (a store of the same value is
     * invisible to the co-simulation harness) and from DONE_SEQ (else gpu_wait would return at
     * once). Stepping twice from the larger is enough for both. */
    doorbell = gpu_read(GPU_REG_DOORBELL);
    done = gpu_read(GPU_REG_DONE_SEQ);
    tag = gpu_next_tag(doorbell);
    if (tag == done) {
        tag = gpu_next_tag(tag);
    }
    dev->next_tag = tag;
    return GPU_OK;
}

/* The doorbell, after the batch's buffers and registers: a fresh tag, returned; the batch is
 * pending until waited for. */
static inline __attribute__((always_inline)) uint32_t gpu_ring(struct gpu_dev *dev)
{
    const uint32_t t = dev->next_tag;

    bsp_fence();  /* buffers and batch registers before the doorbell */
    gpu_write(GPU_REG_DOORBELL, t);
    dev->next_tag = gpu_next_tag(t);
    dev->pending = true;
    dev->pending_tag = t;
    return t;
}

int gpu_submit_batch(struct gpu_dev *dev, const struct gpu_batch *batch, uint32_t *tag)
{
    const uint32_t nv = batch->vtx_count * GPU_VTX_WORDS;
    const uint32_t np = batch->prim_count * GPU_PRIM_WORDS;
    const uint32_t vtx_off = GPU_WIN_VTX + 4u * GPU_VTX_WORDS * batch->vtx_base;
    const uint32_t idx_off = GPU_WIN_IDX + 4u * GPU_PRIM_WORDS * batch->tri_base;

    if (dev->pending) {
        return GPU_E_PENDING;
    }
    /* Written as subtractions so large values cannot wrap around the comparison. */
    if (batch->vtx_base > dev->info.vtx_cap ||
        batch->vtx_count > dev->info.vtx_cap - batch->vtx_base ||
        batch->tri_base > dev->info.tri_cap ||
        batch->prim_count > dev->info.tri_cap - batch->tri_base) {
        return GPU_E_CAPACITY;
    }

    /* A buffer built in place is already there: copying it onto itself is skipped. */
    if (batch->vtx_words != bsp_gpu_buffer(vtx_off)) {
        bsp_gpu_write_words(vtx_off, batch->vtx_words, nv);
    }
    if (batch->prim_words != bsp_gpu_buffer(idx_off)) {
        bsp_gpu_write_words(idx_off, batch->prim_words, np);
    }
    gpu_write(GPU_REG_CTRL, batch->ctrl);
    gpu_write(GPU_REG_VTX_BASE, batch->vtx_base);
    gpu_write(GPU_REG_VTX_COUNT, batch->vtx_count);
    gpu_write(GPU_REG_TRI_BASE, batch->tri_base);
    gpu_write(GPU_REG_TRI_COUNT, batch->prim_count);
    gpu_write(GPU_REG_CLEAR_COLOR, batch->clear_color);
    gpu_write(GPU_REG_STRIP, batch->strip);
    *tag = gpu_ring(dev);
    return GPU_OK;
}

int gpu_set_write_mask(struct gpu_dev *dev, uint32_t planes)
{
    if (dev->pending) {
        return GPU_E_PENDING;
    }
    if ((planes & ~(uint32_t)(GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK)) != 0u) {
        return GPU_E_ARG;
    }
    gpu_write(GPU_REG_FB_WRITE_MASK, planes);
    return GPU_OK;
}

int gpu_load_palette(struct gpu_dev *dev, const uint16_t *palette, uint32_t n)
{
    if (dev->pending) {
        return GPU_E_PENDING;
    }
    if (n > GPU_PALETTE_ENTRIES || (n > 0u && palette == NULL)) {
        return GPU_E_ARG;
    }
    for (uint32_t i = 0; i < n; i++) {
        gpu_write(GPU_WIN_PALETTE + 4u * i, palette[i]);
    }
    return GPU_OK;
}

uint32_t *gpu_buffer_words(uint32_t window_offset)
{
    return bsp_gpu_buffer(window_offset);
}

int gpu_wait(struct gpu_dev *dev, uint32_t tag, uint32_t max_polls)
{
    uint32_t done = 0u;

    for (uint32_t i = 0; i < max_polls; i++) {
        done = gpu_read(GPU_REG_DONE_SEQ);
        if (done == tag) {
            bsp_fence();  /* DONE_SEQ before the results read after it */
            dev->last_done_seq = done;
            dev->pending = false;
            return GPU_OK;
        }
    }
    dev->last_done_seq = done;
    return GPU_E_TIMEOUT;
}

int gpu_wait_idle(struct gpu_dev *dev, uint32_t tag, uint32_t max_polls, void (*idle)(void *ctx),
                  void *ctx)
{
    for (uint32_t polls = 0; polls < max_polls;) {
        const uint32_t left = max_polls - polls;
        const uint32_t n = (left < GPU_WAIT_IDLE_POLLS) ? left : GPU_WAIT_IDLE_POLLS;

        if (gpu_wait(dev, tag, n) == GPU_OK) {
            return GPU_OK;
        }
        polls += n;
        idle(ctx);
    }
    return GPU_E_TIMEOUT;
}

void gpu_read_stats(const struct gpu_dev *dev, struct gpu_stats *stats)
{
    (void)dev;
    stats->errors = gpu_read(GPU_REG_ERRORS);
    stats->busy_cycles = gpu_read(GPU_REG_PERF_BUSY_CYCLES);
    stats->tris_in = gpu_read(GPU_REG_PERF_TRIS_IN);
    stats->tris_drawn = gpu_read(GPU_REG_PERF_TRIS_DRAWN);
    stats->tris_rejected = gpu_read(GPU_REG_PERF_TRIS_REJECTED);
    stats->pixels = gpu_read(GPU_REG_PERF_PIXELS);
    stats->samples = gpu_read(GPU_REG_PERF_SAMPLES);
    stats->spans_written = gpu_read(GPU_REG_PERF_SPANS_WRITTEN);
}

void gpu_reset(struct gpu_dev *dev)
{
    /* RESET acts on a change of value (a store of the same value is invisible in
     * co-simulation), so write one more than what it holds; 0 is as good as any other. */
    gpu_write(GPU_REG_RESET, gpu_read(GPU_REG_RESET) + 1u);
    bsp_fence();
    dev->pending = false;
    dev->resets++;
}

const char *gpu_strerror(int result)
{
    switch (result) {
    case GPU_OK:
        return "ok";
    case GPU_E_NOT_FOUND:
        return "GPU not found";
    case GPU_E_VERSION:
        return "unsupported GPU contract version";
    case GPU_E_GEOMETRY:
        return "unexpected frame or strips";
    case GPU_E_CAPACITY:
        return "batch exceeds the GPU's buffer capacity";
    case GPU_E_PENDING:
        return "previous batch not finished";
    case GPU_E_TIMEOUT:
        return "timeout waiting for DONE_SEQ";
    case GPU_E_ARG:
        return "bad argument";
    case GPU_E_BUFFERS:
        return "GPU buffer capacities out of range";
    default:
        return "unknown error";
    }
}
