/*
 * batch.c — see batch.h.
 */
#include "gpu/batch.h"

#include "config/hot_path.h"

void batch_begin(struct batch_cursor *cur)
{
    cur->next = 0;
}

void batch_begin_list(struct batch_cursor *cur, uint32_t first)
{
    cur->next = first;
}

/* The contract's vertex and primitive words are, on a little-endian CPU, the very bytes of
 * proj_vertex.sxy / zbuf and render_prim.w (with frame vertex numbers): batches copy words
 * instead of packing fields. Every platform of this firmware is little-endian; a contract or a
 * CPU for which that no longer holds stops the build here (test_gpu_native_words checks the
 * same layout at run time). */
#if !(defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && \
      GPU_VTX_WORDS == 2 && GPU_PRIM_WORDS == 2 && \
      GPU_VTX_X_WORD == 0 && GPU_VTX_X_LSB == 0 && GPU_VTX_Y_WORD == 0 && GPU_VTX_Y_LSB == 16 && \
      GPU_VTX_Z_WORD == 1 && GPU_VTX_Z_LSB == 0 && GPU_VTX_I_WORD == 1 && GPU_VTX_I_LSB == 16 && \
      GPU_PRIM_I0_WORD == 0 && GPU_PRIM_I0_LSB == 0 && GPU_PRIM_I1_WORD == 0 && \
      GPU_PRIM_I1_LSB == 16 && GPU_PRIM_I2_WORD == 1 && GPU_PRIM_I2_LSB == 0 && \
      GPU_PRIM_COLOR_WORD == 1 && GPU_PRIM_COLOR_LSB == 16 && GPU_PRIM_KIND_WORD == 1 && \
      GPU_PRIM_KIND_LSB == 24)
#error "batch.c copies proj_vertex and render_prim words as the GPU's: this CPU or contract differs"
#endif

/* A frame primitive's three vertex numbers and its GPU word 1 without the third (the colour and
 * the kind in their places: the contract's word 1 above VTX_I2). A narrow frame's primitive is
 * those words already (two loads); a wide one's (render.h) is packed here. */
struct batch_prim_fields {
    uint32_t v0, v1, v2;
    uint32_t hi;
};

static inline struct batch_prim_fields batch_prim_read(const struct render_prim *p)
{
    struct batch_prim_fields r;
#if FW_RENDER_WIDE_INDEX
    r.v0 = p->v[0];
    r.v1 = p->v[1];
    r.v2 = p->v[2];
    r.hi = ((uint32_t)p->color << GPU_PRIM_COLOR_LSB) | ((uint32_t)p->kind << GPU_PRIM_KIND_LSB);
#else
    /* Both words in locals first: the vertex stamps batch_fill writes are uint16_t like the
     * indices, so the compiler would otherwise reload the primitive after every store. */
    const uint32_t w0 = p->w[0];
    const uint32_t w1 = p->w[1];

    r.v0 = w0 & 0xFFFFu;
    r.v1 = w0 >> 16;
    r.v2 = w1 & 0xFFFFu;
    r.hi = w1 & 0xFFFF0000u;
#endif
    return r;
}

/* Word 1: VTX_Z and, with Gouraud built in, VTX_I from the depth half-word, which holds a shaded
 * object's vertex intensity by now (render.h); a flat object's sort depth there is never read,
 * since only Gouraud triangles read VTX_I. */
static inline void batch_put_vertex(uint32_t *w, const struct proj_vertex *v)
{
    w[0] = v->sxy;
    w[1] = FW_WITH_GOURAUD ? v->zd : v->zbuf;
}

/* The vertex's slot in the current batch, writing it there first if the batch lacks it.
 * *nv counts the batch's vertices so far. */
static inline uint32_t batch_vertex(struct proj_vertex *v, uint8_t stamp, uint32_t *vtx,
                                    uint32_t *nv)
{
    /* Mostly in the batch already (a sorted frame's neighbours share vertices: 70-85 % of the
     * look-ups on the knot), so that is the straight path. */
    if (FW_UNLIKELY(v->batch_stamp != stamp)) {
        v->batch_stamp = stamp;
        v->batch_slot = (uint16_t)*nv;
        batch_put_vertex(&vtx[*nv * GPU_VTX_WORDS], v);
        (*nv)++;
    }
    return v->batch_slot;
}

/*
 * The whole frame in one batch with the frame's own vertex numbers: every vertex is copied once,
 * in order (also those only back faces used: the GPU reads only what primitives name), and the
 * primitives need no renumbering. Cheaper than batch_fill's general path by the vertex look-ups.
 */
static void batch_fill_whole(struct render_frame *f, struct batch_words *out)
{
    const uint32_t nv = f->vert_count;
    const uint32_t np = f->prim_count;
    const struct proj_vertex *vert = f->vert;
    const struct render_prim *prim = f->prim;
    uint32_t *vtx = out->vtx;
    uint32_t *prim_words = out->prim;

    for (uint32_t v = 0; v < nv; v++) {
        batch_put_vertex(&vtx[v * GPU_VTX_WORDS], &vert[v]);
    }
    for (uint32_t i = 0; i < np; i++) {
        const struct render_prim *p = &prim[render_draw_index(f, i)];

        /* nv <= vtx_cap <= GPU_VTX_CAP_MAX: every vertex number fits its 16-bit field (a narrow
         * primitive's words come back as they were: the compiler folds the unpacking away). */
        const struct batch_prim_fields r = batch_prim_read(p);

        prim_words[i * GPU_PRIM_WORDS] = r.v0 | (r.v1 << 16);
        prim_words[i * GPU_PRIM_WORDS + 1u] = r.v2 | r.hi;
    }
    out->vtx_count = nv;
    out->prim_count = np;
}

/* An outline primitive's edges as GPU LINE primitives at pw (render.h, RENDER_PRIM_OUTLINE): edge
 * k from slot s[k] to s[(k + 1) % 3], in the order 0, 1, 2; w1_hi its colour and kind
 * (batch_prim_read). Returns how many it wrote (1 .. 3). */
static inline uint32_t batch_put_outline(uint32_t *pw, const uint32_t s[3], uint32_t w1_hi)
{
    const uint32_t edges = (w1_hi >> GPU_PRIM_KIND_LSB) & RENDER_PRIM_OUTLINE_EDGES;
    const uint32_t hi = (w1_hi & 0x00FF0000u) | ((uint32_t)GPU_PRIM_KIND_LINE << GPU_PRIM_KIND_LSB);
    uint32_t n = 0;

    for (uint32_t k = 0; k < 3u; k++) {
        if ((edges & (1u << k)) != 0u) {
            const uint32_t b = s[(k + 1u) % 3u];

            pw[n * GPU_PRIM_WORDS] = s[k] | (b << 16);
            pw[n * GPU_PRIM_WORDS + 1u] = b | hi;
            n++;
        }
    }
    return n;
}

/* The capacities a batch takes: the GPU's, clamped to out's room and to a minimum of 3 vertices
 * and 1 primitive (3 with outlines: an outline's three lines always fit an empty batch). */
static inline void batch_clamp_caps(const struct render_frame *f, const struct batch_words *out,
                                    uint32_t *vtx_cap, uint32_t *tri_cap)
{
    uint32_t v = *vtx_cap;
    uint32_t t = *tri_cap;

    v = (v > out->vtx_room) ? out->vtx_room : v;
    t = (t > out->prim_room) ? out->prim_room : t;
    v = (v < 3u) ? 3u : v;
    t = (t < 1u) ? 1u : t;
    t = (t < 3u && f->outline_count != 0u) ? 3u : t;
    *vtx_cap = v;
    *tri_cap = t;
}

static inline bool batch_whole_fits_clamped(const struct render_frame *f, uint32_t vtx_cap,
                                            uint32_t tri_cap)
{
    return f->outline_count == 0u && f->vert_count <= vtx_cap && f->prim_count <= tri_cap;
}

bool batch_whole_fits(const struct render_frame *f, uint32_t vtx_cap, uint32_t tri_cap,
                      const struct batch_words *out)
{
    batch_clamp_caps(f, out, &vtx_cap, &tri_cap);
    return batch_whole_fits_clamped(f, vtx_cap, tri_cap);
}

/* batch_fill and batch_fill_list: the next primitives from the draw order, or from a list linked
 * through sort_tmp (render/strips.h), a constant at each call. */
static inline __attribute__((always_inline)) void batch_fill_from(struct batch_cursor *cur,
                                                                  struct render_frame *f,
                                                                  uint32_t vtx_cap,
                                                                  uint32_t tri_cap,
                                                                  struct batch_words *out,
                                                                  bool list)
{
    uint8_t stamp;
    const uint32_t first = cur->next;
    uint32_t i = first;
    uint32_t nv = 0;  /* locals, not out->..., so the stores to the word arrays cannot alias them */
    uint32_t np = 0;  /* GPU primitives written (an outline writes up to 3) */
    uint32_t end;
    uint32_t vtx_room;
    const uint32_t total = f->prim_count;
    const struct render_prim *prim = f->prim;
    const sort_item_t *order = f->sort_item;  /* render_draw_index's, kept in a register */
    struct proj_vertex *vert = f->vert;
    uint32_t *vtx = out->vtx;
    uint32_t *prim_words = out->prim;
    uint32_t vsize = sizeof(struct proj_vertex);

    FW_AS_MULTIPLIER(vsize);
    batch_clamp_caps(f, out, &vtx_cap, &tri_cap);

    if (!list && first == 0u && batch_whole_fits_clamped(f, vtx_cap, tri_cap)) {
        batch_fill_whole(f, out);
        cur->next = total;
        return;
    }

    /* A fresh stamp: 0 marks "in no batch" (every new vertex's), so on wrapping past 255 the
     * old stamps are cleared first — after 255 batches of one frame (a frame of the largest
     * scene needs about 6; the clearing costs one store per vertex then). */
    stamp = (uint8_t)(f->batch_stamp + 1u);
    if (stamp == 0u) {
        for (uint32_t v = 0; v < f->vert_count; v++) {
            f->vert[v].batch_stamp = 0;
        }
        stamp = 1;
    }
    f->batch_stamp = stamp;

    /* Primitives [first, end) in draw order (render_draw_index) at most; the batch closes early
     * when fewer than three vertex slots are left (nv > vtx_room), or, before an outline, fewer
     * than three primitive slots. */
    end = list ? RENDER_NO_POSITION : ((total - first > tri_cap) ? first + tri_cap : total);
    vtx_room = vtx_cap - 3u;
    if (!list && f->outline_count == 0u) {
        /* No outline in the frame: every primitive is one GPU primitive, so the n-th written is
         * draw position first + n, and end (at most first + tri_cap) bounds both; the loop below
         * without its outline tests and primitive count. */
        const sort_item_t *o = &order[first];
        const sort_item_t *const o_end = &order[end];
        uint32_t *pw = prim_words;

        while (o != o_end && nv <= vtx_room) {
            const struct batch_prim_fields r = batch_prim_read(&prim[sort_item_payload(*o)]);
            const uint32_t s0 = batch_vertex(proj_vertex_at_mut(vert, r.v0, vsize), stamp, vtx, &nv);
            const uint32_t s1 = batch_vertex(proj_vertex_at_mut(vert, r.v1, vsize), stamp, vtx, &nv);
            const uint32_t s2 = batch_vertex(proj_vertex_at_mut(vert, r.v2, vsize), stamp, vtx, &nv);

            pw[0] = s0 | (s1 << 16);
            pw[1] = s2 | r.hi;
            pw += GPU_PRIM_WORDS;
            o++;
        }
        np = (uint32_t)(o - &order[first]);
        out->vtx_count = nv;
        out->prim_count = np;
        cur->next = first + np;
        return;
    }
    while (i != end && nv <= vtx_room) {
        const struct batch_prim_fields r = batch_prim_read(&prim[sort_item_payload(order[i])]);
        const bool outline = ((r.hi >> GPU_PRIM_KIND_LSB) & RENDER_PRIM_OUTLINE) != 0u;
        uint32_t *pw = &prim_words[np * GPU_PRIM_WORDS];

        if (outline && np + 3u > tri_cap) {
            break;
        }
        {
            const uint32_t s0 = batch_vertex(proj_vertex_at_mut(vert, r.v0, vsize), stamp, vtx, &nv);
            const uint32_t s1 = batch_vertex(proj_vertex_at_mut(vert, r.v1, vsize), stamp, vtx, &nv);
            const uint32_t s2 = batch_vertex(proj_vertex_at_mut(vert, r.v2, vsize), stamp, vtx, &nv);

            if (outline) {
                const uint32_t s[3] = {s0, s1, s2};

                np += batch_put_outline(pw, s, r.hi);
            } else {
                pw[0] = s0 | (s1 << 16);
                pw[1] = s2 | r.hi;
                np++;
            }
        }
        i = list ? sort_item_payload(f->sort_tmp[i]) : i + 1u;
        if (np >= tri_cap) {
            break;
        }
    }
    out->vtx_count = nv;
    out->prim_count = np;
    cur->next = i;
}

void batch_fill(struct batch_cursor *cur, struct render_frame *f, uint32_t vtx_cap,
                uint32_t tri_cap, struct batch_words *out)
{
    batch_fill_from(cur, f, vtx_cap, tri_cap, out, false);
}

void batch_fill_list(struct batch_cursor *cur, struct render_frame *f, uint32_t vtx_cap,
                     uint32_t tri_cap, struct batch_words *out)
{
    batch_fill_from(cur, f, vtx_cap, tri_cap, out, true);
}
