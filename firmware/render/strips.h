/*
 * strips.h — binning a sorted frame into strips: bands of rows the GPU draws one after another
 * (contract "Strips", register STRIP; docs/strips.md). Pure code.
 *
 * A strip must receive every primitive that reaches its rows and, for the frames to stay the
 * same, in the frame's draw order (render_draw_index); a primitive reaching no row of the frame
 * reaches no strip and costs no strip work. The rows a primitive may reach are taken from its
 * vertices, floor(y / 16) of the highest and the lowest (Q12.4): a superset of the rows the GPU
 * draws for it (a triangle covers centres 16 r + 8 within its vertices' y range; a line plots the
 * rows of its endpoints and between), so nothing is lost, and the GPU clips the rest.
 *
 * Cost: one pass over the frame's primitives to bin them (each joins the list of the first strip
 * it reaches), then per strip one merge of the strips' lists, which drops what ended above it:
 * O(primitives + primitives reached by strip), no pass over the frame per strip. Storage: the
 * frame's sort_tmp, free after render_sort, holds one word per draw position (the last strip the
 * primitive reaches and the next position in its list, sort.h's item layout), and the bins one
 * list head per strip.
 */
#ifndef STRIPS_H
#define STRIPS_H

#include <stdbool.h>
#include <stdint.h>

#include "gpu_regs.h"
#include "render/render.h"

/* Strips of a frame: at most one per row of the contract's largest frame. */
#define STRIPS_MAX GPU_FB_MAX_HEIGHT

struct strip_bins {
    uint32_t rows;        /* lines per strip (the last strip may have fewer) */
    uint32_t count;       /* strips in the frame: ceil(height / rows) */
    uint32_t height;      /* the frame's lines */
    uint32_t active;      /* draw position heading the current strip's list, or
                           * RENDER_NO_POSITION */
    uint32_t reached;     /* primitives handed to strips so far (a primitive counts per strip) */
    render_index head[STRIPS_MAX];  /* per strip: the list of primitives it is the first of */
};

/* Bin f's primitives (after render_sort and any overlay) into strips of `rows` lines (a power of
 * two, 1 .. ; another is rounded down to one: b->rows says) of a frame `height` lines high
 * (1 .. STRIPS_MAX). Uses f->sort_tmp until the frame's last strip has been taken. */
void strips_bin(struct strip_bins *b, struct render_frame *f, uint32_t rows, uint32_t height);

/* The list of strip s (0 .. count - 1, each once, in order): its first draw position, or
 * RENDER_NO_POSITION when no primitive reaches it; strips_next_pos walks it in draw order. */
uint32_t strips_take(struct strip_bins *b, struct render_frame *f, uint32_t s);

static inline uint32_t strips_next_pos(const struct render_frame *f, uint32_t pos)
{
    return sort_item_payload(f->sort_tmp[pos]);
}

/* Rows first .. last of strip s. */
static inline uint32_t strips_first_row(const struct strip_bins *b, uint32_t s)
{
    return s * b->rows;
}

static inline uint32_t strips_last_row(const struct strip_bins *b, uint32_t s)
{
    const uint32_t last = s * b->rows + b->rows - 1u;

    return (last < b->height) ? last : b->height - 1u;
}

#endif /* STRIPS_H */
