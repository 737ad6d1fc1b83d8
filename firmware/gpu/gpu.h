/*
 * gpu.h — driver for the memory-mapped GPU of contract/gpu-contract.md.
 *
 * Two layers:
 *   - a pure core (below): the batch descriptor and the vertex and primitive word formats, which
 *     are the contract's (gpu_regs.h); render code builds the words in that layout and batch.c
 *     copies them whole (a build check there keeps the layouts equal). No hardware access.
 *   - a thin edge (gpu.c): every access to the device goes through the platform's accessors
 *     bsp_gpu_write(offset, value) / bsp_gpu_read(offset) / bsp_gpu_write_words() (bsp.h).
 *
 * The driver keeps its state in a gpu_dev the caller owns; there are no globals.
 */
#ifndef GPU_H
#define GPU_H

#include <stdbool.h>
#include <stdint.h>

#include "gpu_regs.h"

/* ---- pure core: buffer word formats -------------------------------------------------------- */

/* Vertex: x, y signed Q12.4 screen coordinates (1/16 px), z unsigned depth (0 = near);
 * primitive: three vertex indices relative to VTX_BASE, a palette colour, a GPU_PRIM_KIND_*.
 * batch.c writes both as the words of proj_vertex and render_prim (their layout is the
 * contract's on every platform of this firmware; batch.c stops the build where it is not). */

/* Palette words (RGB444) are built by render/palette.h (PAL_RGB444) and loaded as they are. */

/* ---- edge: the device ---------------------------------------------------------------------- */

/* Driver results. 0 is success; every failure is negative. */
enum gpu_result {
    GPU_OK = 0,
    GPU_E_NOT_FOUND = -1,  /* ID register is not GPU_ID_VALUE */
    GPU_E_VERSION = -2,    /* contract major version differs, or minor is older than ours */
    GPU_E_GEOMETRY = -3,   /* FB_SIZE is empty or beyond GPU_FB_MAX_WIDTH x GPU_FB_MAX_HEIGHT, or
                            * STRIP_ROWS neither 0 nor a power of two up to the frame's height
                            * (not 0 in a build without FW_WITH_STRIPS) */
    GPU_E_CAPACITY = -4,   /* the batch does not fit VTX_CAP / TRI_CAP */
    GPU_E_PENDING = -5,    /* a batch was submitted and not yet waited for */
    GPU_E_TIMEOUT = -6,    /* DONE_SEQ did not reach the tag within max_polls reads */
    GPU_E_ARG = -7,        /* bad argument (e.g. palette larger than the palette window) */
    GPU_E_BUFFERS = -8,    /* VTX_CAP / TRI_CAP beyond their bus windows, or below one triangle */
};

/* Capability fields of CAPS. */
static inline bool gpu_caps_lines(uint32_t caps)
{
    return (caps & GPU_CAPS_LINES_MASK) != 0u;
}

static inline bool gpu_caps_zbuf(uint32_t caps)
{
    return (caps & GPU_CAPS_ZBUF_MASK) != 0u;
}

static inline bool gpu_caps_wmask(uint32_t caps)
{
    return (caps & GPU_CAPS_WMASK_MASK) != 0u;
}

/* The depth bits the GPU's depth buffer keeps (contract "Depth": 1 .. 16; 0 without one). */
static inline uint32_t gpu_caps_zbuf_bits(uint32_t caps)
{
    return (caps & GPU_CAPS_ZBUF_BITS_MASK) >> GPU_CAPS_ZBUF_BITS_LSB;
}

static inline bool gpu_caps_gouraud(uint32_t caps)
{
    return (caps & GPU_CAPS_GOURAUD_MASK) != 0u;
}

/* What the device reports about itself (read by gpu_init). */
struct gpu_info {
    uint32_t id;
    uint32_t version;
    uint32_t caps;
    uint32_t vtx_cap;
    uint32_t tri_cap;
    uint32_t fb_size;   /* FB_SIZE: the frame, height << 16 | width */
    uint32_t strip_rows; /* STRIP_ROWS: 0, or the rows of the strips the GPU draws on chip */
};

/* The frame the device draws, from FB_SIZE. */
static inline uint32_t gpu_fb_width(const struct gpu_info *info)
{
    return info->fb_size & 0xFFFFu;
}

static inline uint32_t gpu_fb_height(const struct gpu_info *info)
{
    return info->fb_size >> 16;
}

struct gpu_dev {
    struct gpu_info info;
    uint32_t next_tag;  /* tag of the next doorbell: never 0, +1 per batch (skipping 0) */
    bool pending;       /* a batch is in flight: submitted, not yet seen done */
    uint32_t pending_tag;  /* its tag, while pending */
    uint32_t last_done_seq;  /* DONE_SEQ at the last gpu_wait return (for error messages) */
    uint32_t resets;    /* gpu_reset calls since gpu_init */
};

/* One batch (contract/gpu-contract.md, "A batch, and the frame handshake"). The driver copies
 * vtx_count vertices to the vertex buffer starting at vtx_base and prim_count primitives to the
 * index buffer starting at tri_base, then programs the batch registers with the same values. */
struct gpu_batch {
    const uint32_t *vtx_words;   /* vtx_count * GPU_VTX_WORDS words */
    uint32_t vtx_base;
    uint32_t vtx_count;
    const uint32_t *prim_words;  /* prim_count * GPU_PRIM_WORDS words */
    uint32_t tri_base;
    uint32_t prim_count;
    uint32_t ctrl;               /* GPU_CTRL_*_MASK bits */
    uint8_t clear_color;         /* palette index used when ctrl has GPU_CTRL_CLEAR_MASK */
    uint32_t strip;              /* STRIP: the rows it draws and clears (gpu_strip, GPU_STRIP_WHOLE) */
};

/* STRIP of a batch drawing rows first .. last (contract "Strips"), and of one drawing them all
 * (rows 0 .. 65535: the frame's last is its last). */
static inline uint32_t gpu_strip(uint32_t first, uint32_t last)
{
    return ((first << GPU_STRIP_FIRST_LSB) & GPU_STRIP_FIRST_MASK) |
           ((last << GPU_STRIP_LAST_LSB) & GPU_STRIP_LAST_MASK);
}
#define GPU_STRIP_WHOLE GPU_STRIP_LAST_MASK

/* Counters and flags of the last finished batch. */
struct gpu_stats {
    uint32_t errors;        /* GPU_ERR_*_MASK bits */
    uint32_t busy_cycles;
    uint32_t tris_in;
    uint32_t tris_drawn;
    uint32_t tris_rejected;
    uint32_t pixels;
    uint32_t samples;
    uint32_t spans_written;
};

/* Read ID/VERSION/CAPS/capacities into dev->info (always, so a caller can report them), then
 * check them: GPU_E_NOT_FOUND, GPU_E_VERSION or GPU_E_GEOMETRY on a mismatch, GPU_E_BUFFERS when
 * VTX_CAP is not in 3 .. GPU_VTX_CAP_MAX or TRI_CAP not in 1 .. GPU_TRI_CAP_MAX (gpu_regs.h: what
 * the bus windows hold; a device reporting more is not the contract's, and trusting it would send
 * buffer words past their window). On success load
 * palette[0 .. n-1] (RGB444 words) into the palette window and pick a first tag that differs from
 * the current DOORBELL and DONE_SEQ values. */
int gpu_init(struct gpu_dev *dev, const uint16_t *palette, uint32_t n);

/* Copy the batch's buffers, program the batch registers, fence, ring DOORBELL with a fresh
 * non-zero tag. The tag is returned in *tag for gpu_wait. Fails without touching the device when
 * a batch is still pending or the batch does not fit the capacities the device reported.
 * Words already in place (vtx_words / prim_words pointing where gpu_buffer_words says the buffer
 * at that base is) are not copied. */
int gpu_submit_batch(struct gpu_dev *dev, const struct gpu_batch *batch, uint32_t *tag);

/* The GPU's vertex buffer (GPU_WIN_VTX) or index buffer (GPU_WIN_IDX) as CPU memory to build
 * batches in place, when the platform maps the window (bsp_gpu_buffer); NULL otherwise. Write it
 * only while no batch is pending. */
uint32_t *gpu_buffer_words(uint32_t window_offset);

/* Poll DONE_SEQ until it equals tag, at most max_polls reads. GPU_OK or GPU_E_TIMEOUT (the last
 * value read is left in dev->last_done_seq). */
int gpu_wait(struct gpu_dev *dev, uint32_t tag, uint32_t max_polls);

/* gpu_wait with work of the caller's between polls: idle(ctx) after every GPU_WAIT_IDLE_POLLS
 * polls while the GPU is still busy (the frame loop drains the UART there, so bytes that arrive
 * during a frame wait in memory rather than in a 16-byte FIFO). max_polls bounds the polls
 * exactly as gpu_wait's does; the time each takes grows by idle's share. */
#define GPU_WAIT_IDLE_POLLS 32u
int gpu_wait_idle(struct gpu_dev *dev, uint32_t tag, uint32_t max_polls, void (*idle)(void *ctx),
                  void *ctx);

/* FB_WRITE_MASK: the framebuffer planes (GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK bits) the
 * following batches write, clear included, until changed. GPU_E_PENDING while a batch is in
 * flight, GPU_E_ARG for other bits. A GPU without CAPS_WMASK ignores it (writes every bit). */
int gpu_set_write_mask(struct gpu_dev *dev, uint32_t planes);

/* Load palette[0 .. n-1] (RGB444 words) into the palette window, as gpu_init does: GPU_E_PENDING
 * while a batch is in flight (the GPU would drop the writes), GPU_E_ARG for n beyond the palette. */
int gpu_load_palette(struct gpu_dev *dev, const uint16_t *palette, uint32_t n);

/* Read ERRORS and the PERF_* counters of the last finished batch. */
void gpu_read_stats(const struct gpu_dev *dev, struct gpu_stats *stats);

/* The watchdog's way out (contract: "A batch, and the frame handshake"): write a new value to
 * RESET, which abandons the running batch and returns the GPU to idle, and forget the pending
 * batch so the next submit proceeds. DONE_SEQ keeps its old value; tags continue. */
void gpu_reset(struct gpu_dev *dev);

/* Short English text for a gpu_result. */
const char *gpu_strerror(int result);

#endif /* GPU_H */
