/*
 * test_strips.c — binning a frame into strips (render/strips.h) against a brute-force filter:
 * each strip's list holds exactly the primitives whose vertices' rows reach it, in draw order,
 * for strips of 1 to 512 lines and both frame heights; a strip's batches (batch_fill_list) carry
 * exactly its list.
 */
#include <stdbool.h>
#include <stdint.h>

#include "gpu/batch.h"
#include "render/strips.h"
#include "test_frame.h"
#include "unit.h"

static uint32_t vtx_words[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t prim_words[GPU_TRI_CAP * GPU_PRIM_WORDS];
static struct batch_words words = BATCH_WORDS_ON(vtx_words, prim_words);
static struct strip_bins bins;

/* A frame of n primitives over nv vertices, their rows anywhere from far above the frame to far
 * below it (some primitives tall, most short), triangles, lines and outlines, in a random draw
 * order. */
static void random_frame(struct render_frame *f, uint32_t n, uint32_t nv, int32_t height)
{
    render_frame_begin(f);
    for (uint32_t v = 0; v < nv; v++) {
        struct proj_vertex *pv = &f->vert[v];
        const int32_t y = (int32_t)(unit_rand() % (uint32_t)(3 * height)) - height;

        pv->sx = (int16_t)(unit_rand() % (16u * GPU_FB_MAX_WIDTH));
        pv->sy = (int16_t)(16 * y + (int32_t)(unit_rand() % 16u));
        pv->zbuf = (uint16_t)unit_rand();
        pv->depth = 0;
        pv->batch_stamp = 0;
        pv->code = 0;
    }
    f->vert_count = nv;
    for (uint32_t i = 0; i < n; i++) {
        struct render_prim *p = &f->prim[i];
        const uint32_t kind = unit_rand() % 5u;
        /* Mostly neighbours (short primitives), now and then any vertex (a tall one). */
        const uint32_t a = unit_rand() % nv;
        const uint32_t spread = (unit_rand() % 8u == 0u) ? nv : 4u;

        p->v[0] = (render_index)a;
        p->v[1] = (render_index)((a + unit_rand() % spread) % nv);
        p->v[2] = (render_index)((a + unit_rand() % spread) % nv);
        p->color = (uint8_t)(1u + unit_rand() % 200u);
        p->kind = (kind == 0u) ? GPU_PRIM_KIND_LINE
                : ((kind == 1u) ? (RENDER_PRIM_OUTLINE | 0x5u) : GPU_PRIM_KIND_TRI);
        if (kind == 0u) {
            p->v[2] = p->v[1];
        }
        f->outline_count += (kind == 1u) ? 1u : 0u;
    }
    /* A random draw order: a shuffled permutation of the primitives. */
    for (uint32_t i = 0; i < n; i++) {
        f->sort_item[i] = sort_item_make(0, i);
    }
    for (uint32_t i = n; i > 1u; i--) {
        const uint32_t j = unit_rand() % i;
        const sort_item_t t = f->sort_item[i - 1u];

        f->sort_item[i - 1u] = f->sort_item[j];
        f->sort_item[j] = t;
    }
    f->prim_count = n;
    f->sorted_count = n;
}

/* floor(y / 16) */
static int32_t pixel_row(int32_t y)
{
    return (y >= 0) ? y / 16 : -((15 - y) / 16);
}

/* Does draw position i reach rows first .. last (its vertices' rows, as strips.h states)? */
static bool reaches(const struct render_frame *f, uint32_t i, int32_t first, int32_t last)
{
    const struct render_prim *p = &f->prim[render_draw_index(f, i)];
    int32_t lo = 1 << 20;
    int32_t hi = -(1 << 20);

    for (int k = 0; k < 3; k++) {
        const int32_t r = pixel_row(f->vert[p->v[k]].sy);

        lo = (r < lo) ? r : lo;
        hi = (r > hi) ? r : hi;
    }
    return hi >= first && lo <= last;
}

void test_strips_match_brute_force(void)
{
    static const uint32_t heights[] = {GPU_FB_HEIGHT, GPU_FB_MAX_HEIGHT};
    static const uint32_t rows[] = {1, 2, 8, 16, 32, 64, 512};
    struct render_frame *f = &test_frame;

    for (unsigned h = 0; h < 2u; h++) {
        random_frame(f, 1500u, 400u, (int32_t)heights[h]);
        for (unsigned r = 0; r < sizeof rows / sizeof rows[0]; r++) {
            uint32_t want_reached = 0;
            uint32_t binned = 0;  /* primitives in at least one strip */

            strips_bin(&bins, f, rows[r], heights[h]);
            CHECK_EQ(bins.rows, rows[r]);
            CHECK_EQ(bins.count, (heights[h] + rows[r] - 1u) / rows[r]);
            for (uint32_t s = 0; s < bins.count; s++) {
                const int32_t first = (int32_t)strips_first_row(&bins, s);
                const int32_t last = (int32_t)strips_last_row(&bins, s);
                uint32_t pos = strips_take(&bins, f, s);

                CHECK(last < (int32_t)heights[h] && last - first + 1 <= (int32_t)rows[r]);
                /* The list is the brute-force filter, element by element. */
                for (uint32_t i = 0; i < f->prim_count; i++) {
                    if (!reaches(f, i, first, last)) {
                        continue;
                    }
                    want_reached++;
                    if (pos != i) {
                        unit_fail(__FILE__, __LINE__, "rows %u strip %u: position %u where %u "
                                  "belongs", (unsigned)rows[r], (unsigned)s, (unsigned)pos,
                                  (unsigned)i);
                        return;
                    }
                    pos = strips_next_pos(f, pos);
                }
                CHECK_EQ(pos, RENDER_NO_POSITION);
            }
            CHECK_EQ(bins.reached, want_reached);
            for (uint32_t i = 0; i < f->prim_count; i++) {
                binned += reaches(f, i, 0, (int32_t)heights[h] - 1) ? 1u : 0u;
            }
            CHECK(binned > f->prim_count / 3u && binned < f->prim_count);  /* some off the frame */
            CHECK(want_reached >= binned);
        }
    }
}

/* A strip's batches carry exactly its list, in order, every capacity respected; an empty strip
 * gives one empty batch. */
void test_strips_batches(void)
{
    struct render_frame *f = &test_frame;
    uint32_t strips_with_many_batches = 0;

    random_frame(f, 4000u, 3000u, GPU_FB_MAX_HEIGHT);
    strips_bin(&bins, f, 32u, GPU_FB_MAX_HEIGHT);
    for (uint32_t s = 0; s < bins.count; s++) {
        const uint32_t first = strips_take(&bins, f, s);
        uint32_t pos = first;
        uint32_t batches = 0;
        struct batch_cursor cur;

        batch_begin_list(&cur, first);
        do {
            batch_fill_list(&cur, f, 64u, 40u, &words);
            batches++;
            CHECK(words.prim_count <= 40u && words.vtx_count <= 64u);
            for (uint32_t k = 0; k < words.prim_count;) {
                const struct render_prim *p = &f->prim[render_draw_index(f, pos)];
                const uint32_t *pw = &words.prim[k * GPU_PRIM_WORDS];
                const uint32_t i0 = (pw[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK;
                const uint32_t *vw = &words.vtx[i0 * GPU_VTX_WORDS];
                /* An outline becomes one line per edge it names (0x5: edges 0 and 2). */
                const uint32_t gpu_prims = ((p->kind & RENDER_PRIM_OUTLINE) != 0u) ? 2u : 1u;

                CHECK(pos != RENDER_NO_POSITION);
                CHECK_EQ((pw[GPU_PRIM_COLOR_WORD] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK,
                         p->color);
                CHECK(i0 < words.vtx_count);
                if ((p->kind & RENDER_PRIM_OUTLINE) == 0u) {
                    CHECK_EQ((int16_t)((vw[GPU_VTX_Y_WORD] >> GPU_VTX_Y_LSB) & GPU_VTX_Y_MASK),
                             f->vert[p->v[0]].sy);
                }
                k += gpu_prims;
                pos = strips_next_pos(f, pos);
            }
        } while (!batch_list_done(&cur));
        CHECK_EQ(pos, RENDER_NO_POSITION);  /* the whole list went out */
        strips_with_many_batches += (batches > 2u) ? 1u : 0u;
        CHECK(first != RENDER_NO_POSITION || batches == 1u);
    }
    CHECK(strips_with_many_batches > 0u);
}
