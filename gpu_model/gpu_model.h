/*
 * gpu_model.h - bit-exact golden C model of the GPU.
 *
 * Written only from docs/gpu-contract.md and the generated register map
 * (firmware/include/gpu_regs.h), never from the RTL, so that the two readers of
 * the contract cannot share a bug by sharing code.  It must agree with the RTL
 * on every framebuffer pixel and every register except PERF_BUSY_CYCLES.
 *
 * The model has no time: a DOORBELL write runs the whole batch (clear, draw,
 * swap) to completion inside gpu_model_write(), so STATUS.BUSY is never seen
 * set and ERR_WRITE_BUSY can never happen.
 *
 * Host code, C11, no dependencies beyond the C library.  The state is one plain
 * struct (~160 KiB because of the two framebuffers): allocate it statically or
 * with malloc, then call gpu_model_reset() before use.
 */
#ifndef GPU_MODEL_H
#define GPU_MODEL_H

#include <stdint.h>

#include "gpu_regs.h"

/* The VGA picture: each framebuffer pixel is shown as a 2 x 2 block. */
#define GPU_MODEL_SCREEN_W 640
#define GPU_MODEL_SCREEN_H 480

/* Pixels in one framebuffer (320 x 240). */
#define GPU_MODEL_FB_PIXELS (GPU_FB_WIDTH * GPU_FB_HEIGHT)

/* Capabilities this model implements: triangles only, no lines, no depth
 * buffer, and one pixel per "clock" (the model has no clock; SPAN_W is what
 * CAPS reports so the firmware sees a consistent value). */
#define GPU_MODEL_CAPS ((1u << GPU_CAPS_SPAN_W_LSB) & GPU_CAPS_SPAN_W_MASK)

/*
 * The whole device state.  Public so tests and the co-simulation harness can
 * inspect it directly; change it only through gpu_model_write() (or reset)
 * if you want contract behaviour.
 */
typedef struct gpu_model {
    /* Batch registers (rw), holding the last 32-bit value the bus wrote.
     * Only the meaningful bits are used when a batch runs: CTRL_CLEAR and
     * CTRL_SWAP of ctrl, [7:0] of clear_color. */
    struct {
        uint32_t ctrl;
        uint32_t vtx_base;
        uint32_t vtx_count;
        uint32_t tri_base;
        uint32_t tri_count;
        uint32_t clear_color;
        uint32_t doorbell;    /* reads back the last tag written */
    } regs;

    /* Read-only status registers. */
    uint32_t done_seq;        /* DONE_SEQ: tag of the last finished batch */
    uint32_t frame_count;     /* FRAME_COUNT: swaps since reset (wraps at 2^32) */
    uint32_t errors;          /* ERRORS: GPU_ERR_* flags of the last batch */
    uint32_t front;           /* STATUS.FRONT: index (0/1) of the scanned-out fb */

    /* PERF_* counters of the last batch (PERF_BUSY_CYCLES is not modelled
     * and reads 0).  None can overflow 32 bits: at most TRI_CAP primitives
     * of at most 320*240 samples each, 1024 * 76800 < 2^27. */
    struct {
        uint32_t tris_in;
        uint32_t tris_drawn;
        uint32_t tris_rejected;
        uint32_t pixels;
        uint32_t samples;
    } perf;

    /* Palette: RGB444, R in [11:8], G in [7:4], B in [3:0]. */
    uint16_t palette[GPU_PALETTE_ENTRIES];

    /* Vertex buffer: GPU_VTX_WORDS words per vertex, format GPU_VTX_*. */
    uint32_t vtx[GPU_VTX_CAP * GPU_VTX_WORDS];

    /* Index buffer: GPU_PRIM_WORDS words per primitive, format GPU_PRIM_*. */
    uint32_t idx[GPU_TRI_CAP * GPU_PRIM_WORDS];

    /* The two framebuffers, palette indices, row-major, top row first.
     * fb[front] is scanned out, fb[front ^ 1] is drawn. */
    uint8_t fb[2][GPU_MODEL_FB_PIXELS];
} gpu_model;

/* Power-on state: all registers, counters and flags 0 (the identity registers
 * are constants), palette black, both framebuffers 0, front = 0. */
void gpu_model_reset(gpu_model *m);

/* A 32-bit bus write at byte `offset` from the GPU base.  Unaligned offsets,
 * unmapped offsets and read-only registers are ignored.  A DOORBELL write runs
 * the batch to completion (including the swap if CTRL_SWAP) and sets
 * DONE_SEQ to `value`. */
void gpu_model_write(gpu_model *m, uint32_t offset, uint32_t value);

/* A 32-bit bus read at byte `offset`.  Write-only windows (palette, vertex,
 * index), unmapped and unaligned offsets read 0; so does PERF_BUSY_CYCLES. */
uint32_t gpu_model_read(const gpu_model *m, uint32_t offset);

/* The scanned-out framebuffer (320*240 palette indices). */
const uint8_t *gpu_model_front(const gpu_model *m);

/* The framebuffer batches draw into (320*240 palette indices). */
const uint8_t *gpu_model_back(const gpu_model *m);

/* What the VGA monitor shows: GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3
 * bytes of RGB888, row-major, each front-buffer pixel as a 2 x 2 block, each
 * RGB444 channel n expanded to n * 17 (0x0 -> 0x00, 0xF -> 0xFF). */
void gpu_model_scanout(const gpu_model *m, uint8_t *rgb);

#endif /* GPU_MODEL_H */
