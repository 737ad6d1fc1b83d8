/*
 * batch.c — see batch.h.
 */
#include "batch.h"

void batch_begin(struct batch_cursor *cur)
{
    cur->next = 0;
}

/* The vertex's slot in the current batch, writing it there first if the batch lacks it.
 * *nv counts the batch's vertices so far. */
static inline uint32_t batch_vertex(struct proj_vertex *v, uint16_t stamp, uint32_t *vtx,
                                    uint32_t *nv)
{
    if (v->batch_stamp != stamp) {
        uint32_t *w = &vtx[*nv * GPU_VTX_WORDS];

        v->batch_stamp = stamp;
        v->batch_slot = (uint16_t)*nv;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && \
    GPU_VTX_X_WORD == 0 && GPU_VTX_X_LSB == 0 && GPU_VTX_Y_WORD == 0 && GPU_VTX_Y_LSB == 16 && \
    GPU_VTX_Z_WORD == 1 && GPU_VTX_Z_LSB == 0
        /* sx, sy in memory (little-endian) are exactly the contract's first vertex word. */
        w[0] = v->sxy;
        w[1] = v->zbuf;
#else
        gpu_pack_vertex(w, v->sx, v->sy, v->zbuf);
#endif
        (*nv)++;
    }
    return v->batch_slot;
}

void batch_fill(struct batch_cursor *cur, struct render_frame *f, uint32_t vtx_cap,
                uint32_t tri_cap, struct batch_words *out)
{
    uint16_t stamp;
    uint32_t i = cur->next;
    uint32_t nv = 0;  /* locals, not out->..., so the stores to the word arrays cannot alias them */
    uint32_t np = 0;
    const uint32_t total = f->prim_count;
    const uint32_t sorted = f->sorted_count;
    const uint32_t *sort_item = f->sort_item;
    const struct render_prim *prim = f->prim;
    struct proj_vertex *vert = f->vert;
    uint32_t *vtx = out->vtx;
    uint32_t *prim_words = out->prim;

    vtx_cap = (vtx_cap > GPU_VTX_CAP) ? GPU_VTX_CAP : vtx_cap;
    tri_cap = (tri_cap > GPU_TRI_CAP) ? GPU_TRI_CAP : tri_cap;
    vtx_cap = (vtx_cap < 3u) ? 3u : vtx_cap;
    tri_cap = (tri_cap < 1u) ? 1u : tri_cap;

    /* A fresh stamp: 0 marks "in no batch" (every new vertex's), so on wrapping past 65535 the
     * old stamps are cleared first — after 65535 batches of one frame, i.e. never in practice. */
    stamp = (uint16_t)(f->batch_stamp + 1u);
    if (stamp == 0u) {
        for (uint32_t v = 0; v < f->vert_count; v++) {
            f->vert[v].batch_stamp = 0;
        }
        stamp = 1;
    }
    f->batch_stamp = stamp;

    while (i < total && np < tri_cap && nv + 3u <= vtx_cap) {
        const uint32_t index = (i < sorted) ? (sort_item[i] & 0xFFFFu) : i;  /* draw order */
        /* The primitive in locals first: the vertex stamps written below are uint16_t like
         * p->v[], so the compiler would otherwise reload the primitive after every store. */
        const struct render_prim p = prim[index];
        const uint32_t s0 = batch_vertex(&vert[p.v[0]], stamp, vtx, &nv);
        const uint32_t s1 = batch_vertex(&vert[p.v[1]], stamp, vtx, &nv);
        const uint32_t s2 = batch_vertex(&vert[p.v[2]], stamp, vtx, &nv);

        gpu_pack_prim(&prim_words[np * GPU_PRIM_WORDS], (uint16_t)s0, (uint16_t)s1, (uint16_t)s2,
                      p.color, p.kind);
        np++;
        i++;
    }
    out->vtx_count = nv;
    out->prim_count = np;
    cur->next = i;
}
