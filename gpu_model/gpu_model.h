/*
 * gpu_model.h - bit-exact golden C model of the GPU (contract 1.1).
 *
 * Written only from contract/gpu-contract.md and the generated register map
 * (contract/gpu_regs.h), never from the RTL, so that the two readers of
 * the contract cannot share a bug by sharing code.  It must agree with the RTL
 * on every framebuffer pixel and every register except PERF_BUSY_CYCLES and
 * PERF_SPANS_VISITED (implementation-specific; both read 0 here).
 *
 * The model has no time: a DOORBELL write runs the whole batch (clear, draw,
 * swap) to completion inside gpu_model_write(), so STATUS.BUSY is never seen
 * set, ERR_WRITE_BUSY can never happen and a RESET write has nothing to abort.
 *
 * Like the RTL, the model is built with four options (contract "Build
 * options, reported in CAPS"): the span width, lines, the depth buffer and
 * Gouraud triangles; and with the RTL's two capacities (VTX_CAP, TRI_CAP),
 * at most the contract's limits.
 *
 * Host C11 (and includable from C++), no dependencies beyond the C library.
 * The state is one plain struct (~1.2 MiB because of the two framebuffers and
 * the depth buffer): allocate it statically or with malloc, then call
 * gpu_model_reset() or gpu_model_reset_config() before use.
 */
#ifndef GPU_MODEL_H
#define GPU_MODEL_H

#include <stdbool.h>
#include <stdint.h>

#include "gpu_regs.h"

/* The VGA picture: each framebuffer pixel is shown as a 2 x 2 block (a
 * 640 x 480 frame 1:1). */
#define GPU_MODEL_SCREEN_W 640
#define GPU_MODEL_SCREEN_H 480

/* Pixels in one framebuffer of the contract's frame (320 x 240), also in the
 * depth buffer. */
#define GPU_MODEL_FB_PIXELS (GPU_FB_WIDTH * GPU_FB_HEIGHT)

/* The largest frame the model draws (the contract's FB_MAX_*: the screen
 * 1:1), what its buffers hold. */
#define GPU_MODEL_MAX_FB_PIXELS (GPU_FB_MAX_WIDTH * GPU_FB_MAX_HEIGHT)

/* Build-option defaults, the same as the RTL's parameter defaults: both come
 * from the contract's [build] table (contract/gpu_contract.toml). */
#define GPU_MODEL_DEFAULT_SPAN_W GPU_DEFAULT_SPAN_W
#define GPU_MODEL_DEFAULT_LINES  (GPU_DEFAULT_ENABLE_LINES != 0u)
#define GPU_MODEL_DEFAULT_ZBUF   (GPU_DEFAULT_ENABLE_ZBUF != 0u)
#define GPU_MODEL_DEFAULT_WMASK  (GPU_DEFAULT_ENABLE_WMASK != 0u)
/* The bits of FB_WRITE_MASK the contract defines (the planes). */
#define GPU_MODEL_WMASK_BITS (GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK)
#define GPU_MODEL_DEFAULT_ZBUF_BITS GPU_DEFAULT_ZBUF_BITS
#define GPU_MODEL_DEFAULT_GOURAUD (GPU_DEFAULT_ENABLE_GOURAUD != 0u)

/* The largest capacities the model holds: what the buffers' windows hold
 * (the contract's VTX_CAP_MAX, TRI_CAP_MAX); by default it has the contract's
 * limits, the RTL's parameter defaults.  A GPU may be built with either
 * smaller or larger buffers. */
#define GPU_MODEL_MAX_VTX_CAP GPU_VTX_CAP_MAX
#define GPU_MODEL_MAX_TRI_CAP GPU_TRI_CAP_MAX
#define GPU_MODEL_DEFAULT_VTX_CAP GPU_VTX_CAP
#define GPU_MODEL_DEFAULT_TRI_CAP GPU_TRI_CAP

/* The bits of CTRL the contract defines; CTRL keeps (and reads back) only
 * these, whatever the build options. */
#define GPU_MODEL_CTRL_BITS \
    (GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK | GPU_CTRL_ZTEST_MASK | \
     GPU_CTRL_ZCLEAR_MASK | GPU_CTRL_DITHER_MASK | GPU_CTRL_WALK_MASK)

/*
 * The build options the modelled GPU was "built" with; CAPS reports them.
 *   span_w: SPAN_W, 1, 4, 8 or 16 (any other value is replaced by the
 *           default 8, so CAPS then disagrees with the RTL and co-simulation
 *           reports it); the span size of PERF_SPANS_WRITTEN.
 *   lines:  ENABLE_LINES; without it a line primitive sets ERR_KIND.
 *   zbuf:   ENABLE_ZBUF; without it CTRL_ZTEST / CTRL_ZCLEAR have no effect
 *           (they are still stored and read back) and zbuf[] is never touched.
 *   wmask:  ENABLE_WMASK; without it FB_WRITE_MASK ignores writes and reads 3
 *           (every batch writes all 8 bits of a pixel).  A config written
 *           before the option existed ({span_w, lines, zbuf}) leaves it false.
 *   vtx_cap, tri_cap: VTX_CAP and TRI_CAP, the buffers' capacities in
 *           vertices and primitives, 1 ... GPU_MODEL_MAX_*_CAP; 0 means the
 *           contract's limits (so a config written before these fields, or zeroed,
 *           is the default GPU); any other value is replaced by the
 *           contract's, like span_w (gpu_model_config_error says why).  They
 *           decide the VTX_CAP / TRI_CAP registers, the ERR_COUNT check
 *           (BASE + COUNT > CAP) and which window words exist: a write past
 *           the capacity is to an unmapped offset and is ignored (never
 *           wrapped into the buffer).
 *   zbuf_bits: ZBUF_BITS, the depth bits the buffer keeps, 1 .. 16 (contract
 *           "Depth"; any other value, 0 included, is replaced by the default
 *           16, as span_w's is); CAPS_ZBUF_BITS reports it with zbuf, 0
 *           without.
 *   gouraud: ENABLE_GOURAUD; without it a PRIM_KIND_TRI_GOURAUD primitive
 *           sets ERR_KIND and CTRL_DITHER has no effect (it is still stored).
 *           An initializer naming only the fields before it leaves it false,
 *           the RTL's default.
 *   fb_width, fb_height: the frame, GPU_FB_WIDTH x GPU_FB_HEIGHT (320 x 240,
 *           shown 2 x 2) or GPU_FB_MAX_WIDTH x GPU_FB_MAX_HEIGHT (640 x 480,
 *           shown 1:1); 0 x 0 means the contract's, any other pair is
 *           replaced by it. FB_SIZE reports it; the framebuffers and the
 *           depth buffer hold fb_width * fb_height pixels, rows fb_width apart.
 *           So that an initializer naming only the fields before them
 *           leaves the contract's frame.
 *   strip_rows: STRIP_ROWS, the rows of the strip buffer (contract "The strip
 *           buffer"): 0 (the default: an initializer naming only the fields
 *           before it), or a power of two up to fb_height; any other value is
 *           replaced by 0. The model draws the frame either way: with strips
 *           it checks the batches against the strip rules (ERR_STRIP), which
 *           is all that makes a strip build differ from the frame drawn whole.
 */
typedef struct gpu_model_config {
    unsigned span_w;
    bool lines;
    bool zbuf;
    uint32_t vtx_cap;
    uint32_t tri_cap;
    unsigned zbuf_bits;  /* configs written before it get 0 = 16 */
    bool wmask;          /* configs written before it get false (no mask) */
    bool gouraud;        /* configs written before it get false (flat only) */
    uint32_t fb_width;   /* configs written before them get 0 x 0, */
    uint32_t fb_height;  /* the contract's 320 x 240 */
    uint32_t strip_rows; /* configs written before it get 0: no strip buffer */
} gpu_model_config;

/*
 * The whole device state.  Public so tests and the co-simulation harness can
 * inspect it directly; change it only through gpu_model_write() (or reset)
 * if you want contract behaviour.
 */
typedef struct gpu_model {
    /* The build options (set by gpu_model_reset_config(); read-only after). */
    gpu_model_config cfg;

    /* Batch registers (rw).  ctrl keeps the five defined CTRL bits
     * (GPU_MODEL_CTRL_BITS), the others the whole 32-bit value written.  A
     * batch uses CTRL_CLEAR, CTRL_SWAP, CTRL_ZTEST and CTRL_ZCLEAR (the last
     * two only with cfg.zbuf) and CLEAR_COLOR[7:0]. */
    struct {
        uint32_t ctrl;
        uint32_t vtx_base;
        uint32_t vtx_count;
        uint32_t tri_base;
        uint32_t tri_count;
        uint32_t clear_color;
        uint32_t doorbell;    /* reads back the last tag written */
        uint32_t reset;       /* RESET: reads back the last value written; it
                               * drops the open strip, and has no other
                               * effect, as no batch is ever running */
        uint32_t fb_write_mask; /* FB_WRITE_MASK, its two plane bits; 3 after
                                 * reset and always 3 without cfg.wmask */
        uint32_t strip;       /* STRIP, all 32 bits; the whole frame after
                               * reset: first row 0, last fb_height - 1 */
    } regs;

    /* The running batch's rows (contract "Strips"): STRIP's first row and
     * its last clamped to the frame, set by the doorbell; row0 > row1 draws
     * nothing. */
    int64_t row0, row1;

    /* The strip buffer's state (cfg.strip_rows > 0): the open strip's index,
     * -1 when none is open (after reset, a swap or RESET), and whether its
     * depths have been cleared since it was opened. */
    int64_t open_strip;
    bool open_strip_zclear;

    /* Read-only status registers. */
    uint32_t done_seq;        /* DONE_SEQ: tag of the last finished batch */
    uint32_t frame_count;     /* FRAME_COUNT: swaps since reset (wraps at 2^32) */
    uint32_t errors;          /* ERRORS: GPU_ERR_* flags of the last batch */
    uint32_t front;           /* STATUS.FRONT: index (0/1) of the scanned-out fb */

    /* PERF_* counters of the last batch (PERF_BUSY_CYCLES and
     * PERF_SPANS_VISITED are not modelled and read 0).  None can overflow 32
     * bits: at most GPU_MODEL_MAX_TRI_CAP = 512 primitives, each adding at most 640*480
     * samples, pixels or spans (a line at most 4095 samples), 512 * 307200
     * < 2^28. */
    struct {
        uint32_t tris_in;
        uint32_t tris_drawn;
        uint32_t tris_rejected;
        uint32_t pixels;        /* pixels written (after the depth test) */
        uint32_t samples;       /* triangle box areas + line step counts */
        uint32_t spans_written; /* per triangle: W-aligned spans with >= 1
                                 * covered pixel (before the depth test) */
    } perf;

    /* Palette: RGB444, R in [11:8], G in [7:4], B in [3:0]. */
    uint16_t palette[GPU_PALETTE_ENTRIES];

    /* Vertex buffer: GPU_VTX_WORDS words per vertex, format GPU_VTX_*; the
     * first cfg.vtx_cap vertices exist, the rest stay 0. */
    uint32_t vtx[GPU_MODEL_MAX_VTX_CAP * GPU_VTX_WORDS];

    /* Index buffer: GPU_PRIM_WORDS words per primitive, format GPU_PRIM_*;
     * the first cfg.tri_cap primitives exist. */
    uint32_t idx[GPU_MODEL_MAX_TRI_CAP * GPU_PRIM_WORDS];

    /* The two framebuffers, palette indices, row-major, top row first: the
     * first cfg.fb_width * cfg.fb_height bytes of each, rows cfg.fb_width
     * apart. fb[front] is scanned out, fb[front ^ 1] is drawn. */
    uint8_t fb[2][GPU_MODEL_MAX_FB_PIXELS];

    /* The depth buffer (contract "Depth"), row-major like fb, one buffer, not
     * swapped: the kept depths zb = z >> (16 - cfg.zbuf_bits), 0 ..
     * 2^zbuf_bits - 1.  0 at power-on (block RAM initial value, like the
     * framebuffers), 2^zbuf_bits - 1 (0xFFFF at 16 bits) after a CTRL_ZCLEAR.
     * Only used with cfg.zbuf; without it, it stays 0. */
    uint16_t zbuf[GPU_MODEL_MAX_FB_PIXELS];

    /* A measurement aid, not GPU state: NULL unless attached
     * (gpu_model_attach_shade_probe) after the last reset. */
    struct gpu_model_shade_probe *shade_probe;
} gpu_model;

/* The unquantised Gouraud colours (bench-error's undithered reference; not
 * in the contract, nothing the RTL has): with a probe attached, every write
 * to a framebuffer pixel also records in the probe's word for that pixel of
 * that framebuffer what the pixel would show before its level is rounded -
 * for a Gouraud triangle's pixel written through the full write mask,
 * GPU_MODEL_PROBE_SHADED | PRIM_COLOR << 16 | i(p) (contract "Gouraud
 * intensity", Q4.12); for any other write (clear, flat triangle, line, a
 * masked write) 0, "as its palette index". */
#define GPU_MODEL_PROBE_SHADED (1u << 24)
typedef struct gpu_model_shade_probe {
    uint32_t px[2][GPU_MODEL_MAX_FB_PIXELS];
} gpu_model_shade_probe;

/* Attach (or, with NULL, detach) a probe; its words start at 0. A reset
 * detaches it. */
void gpu_model_attach_shade_probe(gpu_model *m, gpu_model_shade_probe *probe);

/* Power-on state with the default build options (SPAN_W = 8, lines, no
 * depth buffer): all registers, counters and flags 0 (the identity registers
 * are constants), palette black, both framebuffers and the depth buffer 0,
 * front = 0. */
void gpu_model_reset(gpu_model *m);

/* Power-on state with the given build options (NULL: the defaults).  An
 * unsupported span_w (not 1, 4, 8 or 16) is replaced by 8, a capacity of 0 or
 * above the contract's limit by that limit, a zbuf_bits outside 1 .. 16 by
 * 16; m->cfg holds what was taken. */
void gpu_model_reset_config(gpu_model *m, const gpu_model_config *cfg);

/* NULL when gpu_model_reset_config would take cfg as it is (0 capacities
 * count as given: they mean the contract's), else a sentence naming the first
 * field it would replace and why.  For harnesses that must refuse a GPU the
 * model cannot stand beside, rather than compare it with another one. */
const char *gpu_model_config_error(const gpu_model_config *cfg);

/* A frame given as "WxH" on a harness's command line (--frame): true, with
 * *w and *h, when it is one the model draws (the contract's or its largest),
 * false for anything else. */
bool gpu_model_parse_frame(const char *text, uint32_t *w, uint32_t *h);

/* The CAPS register for m's build options. */
uint32_t gpu_model_caps(const gpu_model *m);

/* A 32-bit bus write at byte `offset` from the GPU base.  Unaligned offsets,
 * unmapped offsets and read-only registers are ignored.  A DOORBELL write runs
 * the batch to completion (including the swap if CTRL_SWAP) and sets
 * DONE_SEQ to `value`. */
void gpu_model_write(gpu_model *m, uint32_t offset, uint32_t value);

/* A 32-bit bus read at byte `offset`.  Write-only windows (palette, vertex,
 * index), unmapped and unaligned offsets read 0; so do PERF_BUSY_CYCLES and
 * PERF_SPANS_VISITED (not modelled). */
uint32_t gpu_model_read(const gpu_model *m, uint32_t offset);

/* The scanned-out framebuffer (cfg.fb_width * cfg.fb_height palette indices). */
const uint8_t *gpu_model_front(const gpu_model *m);

/* The framebuffer batches draw into (likewise). */
const uint8_t *gpu_model_back(const gpu_model *m);

/* What the VGA monitor shows: GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3
 * bytes of RGB888, row-major, each front-buffer pixel as a block of
 * GPU_MODEL_SCREEN_W / cfg.fb_width pixels square (2 x 2 for 320 x 240), each
 * RGB444 channel n expanded to n * 17 (0x0 -> 0x00, 0xF -> 0xFF). */
void gpu_model_scanout(const gpu_model *m, uint8_t *rgb);

/* gpu_model_scanout with the probe's unquantised colours (m needs a probe):
 * a recorded Gouraud pixel shows its intensity I = min(i(p), 15 * 4096) /
 * 4096 on its ramp, each channel of palette[PRIM_COLOR + floor(I)] and
 * palette[PRIM_COLOR + ceil(I)] (mod 256) expanded to 0..255 and mixed
 * linearly by I's fraction, rounded; every other pixel as gpu_model_scanout. */
void gpu_model_scanout_unquantised(const gpu_model *m, uint8_t *rgb);

#endif /* GPU_MODEL_H */
