/*
 * strips.c — see strips.h.
 */
#include "render/strips.h"

/* floor(y / 16) of a Q12.4 coordinate (-2048 .. 2047 px), without a shift of a negative number. */
static inline int32_t strips_pixel_row(int32_t y)
{
    return (int32_t)((uint32_t)(y + 32768) >> 4) - 2048;
}

static inline uint32_t strips_log2(uint32_t rows)
{
    uint32_t k = 0;

    while ((1u << (k + 1u)) <= rows) {
        k++;
    }
    return k;
}

void strips_bin(struct strip_bins *b, struct render_frame *f, uint32_t rows, uint32_t height)
{
    /* Strip heights are powers of two (strip = row >> shift); anything else is taken as the
     * power of two below it. */
    const uint32_t shift = strips_log2(rows);
    const int32_t last_row = (int32_t)height - 1;
    const struct proj_vertex *vert = f->vert;
    const struct render_prim *prim = f->prim;
    sort_item_t *link = f->sort_tmp;

    b->rows = 1u << shift;
    b->height = height;
    b->count = (height + b->rows - 1u) >> shift;
    b->active = RENDER_NO_POSITION;
    b->reached = 0;
    for (uint32_t s = 0; s < b->count; s++) {
        b->head[s] = (render_index)RENDER_NO_POSITION;
    }
    /* Backwards, each primitive pushed onto the list of its first strip: every list in draw
     * order. */
    for (uint32_t i = f->prim_count; i-- > 0u;) {
        const struct render_prim *p = &prim[render_draw_index(f, i)];
        const int32_t y0 = vert[p->v[0]].sy;
        const int32_t y1 = vert[p->v[1]].sy;
        const int32_t y2 = vert[p->v[2]].sy;
        int32_t lo = (y0 < y1) ? y0 : y1;
        int32_t hi = (y0 < y1) ? y1 : y0;

        lo = (y2 < lo) ? y2 : lo;
        hi = (y2 > hi) ? y2 : hi;
        lo = strips_pixel_row(lo);
        hi = strips_pixel_row(hi);
        if (hi < 0 || lo > last_row) {
            continue;  /* above or below the frame: in no strip */
        }
        lo = (lo < 0) ? 0 : lo;
        hi = (hi > last_row) ? last_row : hi;
        {
            const uint32_t first = (uint32_t)lo >> shift;

            link[i] = sort_item_make((uint32_t)hi >> shift, b->head[first]);
            b->head[first] = (render_index)i;
        }
    }
}

uint32_t strips_take(struct strip_bins *b, struct render_frame *f, uint32_t s)
{
    sort_item_t *link = f->sort_tmp;
    uint32_t a = b->active;  /* the last strip's list: whatever of it reaches this strip stays */
    uint32_t c = b->head[s]; /* the primitives that start here */
    uint32_t first = RENDER_NO_POSITION;
    uint32_t tail = RENDER_NO_POSITION;
    uint32_t n = 0;

    /* Merge the two (both in draw order) into this strip's list, relinking in place. */
    while (a != RENDER_NO_POSITION || c != RENDER_NO_POSITION) {
        uint32_t take;

        if (a != RENDER_NO_POSITION && sort_item_key(link[a]) < s) {
            a = sort_item_payload(link[a]);  /* it ended above this strip */
            continue;
        }
        if (c == RENDER_NO_POSITION || (a != RENDER_NO_POSITION && a < c)) {
            take = a;
            a = sort_item_payload(link[a]);
        } else {
            take = c;
            c = sort_item_payload(link[c]);
        }
        if (tail == RENDER_NO_POSITION) {
            first = take;
        } else {
            link[tail] = sort_item_make(sort_item_key(link[tail]), take);
        }
        tail = take;
        n++;
    }
    if (tail != RENDER_NO_POSITION) {
        link[tail] = sort_item_make(sort_item_key(link[tail]), RENDER_NO_POSITION);
    }
    b->active = first;
    b->reached += n;
    return first;
}
