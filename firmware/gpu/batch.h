/*
 * batch.h — cutting a frame's draw list into GPU batches. Pure code.
 *
 * The GPU holds VTX_CAP vertices and TRI_CAP primitives per batch (1024 and 512 today); a frame
 * can have many more. batch_fill takes primitives in draw order until either buffer would
 * overflow and writes them, packed in the contract's word formats, where the caller's batch_words
 * points: staging arrays the driver then copies into the GPU, or, on a platform that maps the
 * GPU's buffers, those buffers themselves (no copy). The next call continues where this one
 * stopped.
 *
 * Vertices are renumbered per batch: each primitive's vertices are looked up by a per-vertex stamp
 * (the batch that last wrote it; a counter kept in the render_frame, so stamps stay unique however
 * many times the same frame is cut into batches) and written once per batch, so shared vertices
 * stay shared inside a batch and a batch never names a vertex it does not carry. A batch is closed
 * while it still has room for three more vertices, so every primitive fits whole.
 *
 * An outline primitive (render.h, RENDER_PRIM_OUTLINE: a wireframe triangle with GPU lines) becomes
 * one GPU LINE primitive per edge it names, up to three, in the batch that takes it; a batch is
 * closed before an outline that would not fit it whole.
 *
 * A frame without outlines whose vertices and primitives all fit one batch skips the renumbering: its vertices are
 * copied in order and the primitives keep the frame's vertex numbers.
 */
#ifndef BATCH_H
#define BATCH_H

#include <stdbool.h>
#include <stdint.h>

#include "gpu/gpu.h"
#include "render/render.h"

/* Where batch_fill writes: staging arrays the driver copies from or the GPU's own buffers
 * (gpu_buffer_words), with room for vtx_room vertices and prim_room primitives (a batch never
 * takes more, whatever the GPU's capacities say). */
struct batch_words {
    uint32_t *vtx;
    uint32_t *prim;
    uint32_t vtx_room;
    uint32_t prim_room;
    uint32_t vtx_count;
    uint32_t prim_count;
};

/* A batch_words on two word arrays (not pointers: their sizes give the room). */
#define BATCH_WORDS_ON(vtx_array, prim_array)                                                  \
    {                                                                                          \
        .vtx = (vtx_array), .prim = (prim_array),                                              \
        .vtx_room = (uint32_t)(sizeof(vtx_array) / (sizeof((vtx_array)[0]) * GPU_VTX_WORDS)),  \
        .prim_room = (uint32_t)(sizeof(prim_array) / (sizeof((prim_array)[0]) * GPU_PRIM_WORDS)), \
    }

struct batch_cursor {
    uint32_t next;    /* position in the frame's draw order */
};

void batch_begin(struct batch_cursor *cur);

/* Fill one batch from the frame's draw list (render_draw_index order). vtx_cap/tri_cap are the
 * GPU's reported capacities, clamped to out's room and to a minimum of
 * 3 vertices and 1 primitive (3 in a frame with outlines: an outline's lines). Writes the frame's per-vertex stamps. */
void batch_fill(struct batch_cursor *cur, struct render_frame *f, uint32_t vtx_cap,
                uint32_t tri_cap, struct batch_words *out);

/* True when batch_fill, called first, puts the whole frame in one batch (no outlines, its
 * vertices and primitives within the capacities as batch_fill clamps them): the frame's vertex
 * numbers unchanged, every primitive in draw order from buffer offset 0. */
bool batch_whole_fits(const struct render_frame *f, uint32_t vtx_cap, uint32_t tri_cap,
                      const struct batch_words *out);

/* True when every primitive of the frame has been put in a batch. */
static inline bool batch_done(const struct batch_cursor *cur, const struct render_frame *f)
{
    return cur->next >= f->prim_count;
}

/* The same from a list of draw positions linked through the frame's sort_tmp (a strip's,
 * render/strips.h: its first position, RENDER_NO_POSITION after the last), in its order. */
void batch_begin_list(struct batch_cursor *cur, uint32_t first);
void batch_fill_list(struct batch_cursor *cur, struct render_frame *f, uint32_t vtx_cap,
                     uint32_t tri_cap, struct batch_words *out);

static inline bool batch_list_done(const struct batch_cursor *cur)
{
    return cur->next == RENDER_NO_POSITION;
}

/* The driver's descriptor of the batch batch_fill just wrote: its words from buffer offset 0,
 * with these CTRL bits and clear colour, drawing every row (a strip's: set .strip). */
static inline struct gpu_batch batch_descriptor(const struct batch_words *w, uint32_t ctrl,
                                                uint8_t clear_color)
{
    const struct gpu_batch b = {
        .vtx_words = w->vtx, .vtx_base = 0, .vtx_count = w->vtx_count,
        .prim_words = w->prim, .tri_base = 0, .prim_count = w->prim_count,
        .ctrl = ctrl, .clear_color = clear_color, .strip = GPU_STRIP_WHOLE,
    };

    return b;
}

#endif /* BATCH_H */
