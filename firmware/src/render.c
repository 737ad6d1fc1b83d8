/*
 * render.c — see render.h.
 */
#include "render.h"

/* Round x * 2^-32 to nearest (ties up). |x| < 2^62, so adding 2^31 cannot overflow. */
static inline int64_t render_round_shift32(int64_t x)
{
    return (x + ((int64_t)1 << 31)) >> 32;
}

enum render_vstate render_project(const struct render_camera *cam, xf_vec3 v,
                                  struct render_vertex *out)
{
    q16_16 p;
    int64_t sx;
    int64_t sy;
    int32_t dz;

    out->z = v.z;
    out->sx_q4 = 0;
    out->sy_q4 = 0;
    out->depth = 0;
    if (v.z < cam->near_z) {
        out->state = RENDER_V_NEAR;
        return RENDER_V_NEAR;
    }

    /* p = focal_q4 / z as q16_16: scale from view units to 1/16 px at this depth. */
    p = fx_div(FX_FROM_INT(cam->focal_q4), v.z);
    sx = cam->cx_q4 + render_round_shift32((int64_t)v.x * p);
    sy = cam->cy_q4 - render_round_shift32((int64_t)v.y * p);
    if (sx < INT16_MIN || sx > INT16_MAX || sy < INT16_MIN || sy > INT16_MAX) {
        out->state = RENDER_V_RANGE;
        return RENDER_V_RANGE;
    }

    /* Depth: distance behind the near plane in 1/256 view units, clamped to 16 bits. */
    dz = (v.z - cam->near_z) >> 8;  /* v.z >= near_z > 0: no overflow, dz >= 0 */
    out->depth = (dz > 0xFFFF) ? 0xFFFFu : (uint16_t)dz;
    out->sx_q4 = (int16_t)sx;
    out->sy_q4 = (int16_t)sy;
    out->state = RENDER_V_OK;
    return RENDER_V_OK;
}

int64_t render_signed_area(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2,
                           int32_t y2)
{
    return (int64_t)(x1 - x0) * (y2 - y0) - (int64_t)(y1 - y0) * (x2 - x0);
}

void render_sort_back_to_front(const int32_t *key, uint16_t *order, uint32_t n)
{
    for (uint32_t i = 1; i < n; i++) {
        const uint16_t item = order[i];
        const int32_t k = key[item];
        uint32_t j = i;

        while (j > 0u && key[order[j - 1u]] < k) {
            order[j] = order[j - 1u];
            j--;
        }
        order[j] = item;
    }
}

uint32_t render_mesh_frame(const struct render_mesh *mesh, const xf_mat3 *rot, xf_vec3 pos,
                           const struct render_camera *cam, struct render_frame *out)
{
    const uint32_t nv = (mesh->vert_count <= RENDER_MAX_VERTS) ? mesh->vert_count
                                                                 : RENDER_MAX_VERTS;
    const uint32_t nf = (mesh->face_count <= RENDER_MAX_FACES) ? mesh->face_count
                                                                 : RENDER_MAX_FACES;
    uint32_t n = 0;

    out->culled = 0;
    out->dropped_near = 0;
    out->dropped_range = 0;

    /* Vertices: transform, project, pack. A vertex that did not project is packed at (0, 0);
     * no primitive below refers to it. */
    for (uint32_t i = 0; i < nv; i++) {
        struct render_vertex *pv = &out->pv[i];

        render_project(cam, xf_transform(rot, mesh->verts[i], pos), pv);
        gpu_pack_vertex(&out->vtx_words[i * GPU_VTX_WORDS], pv->sx_q4, pv->sy_q4, pv->depth);
    }
    out->vtx_count = nv;

    /* Faces: drop those not fully projected, cull back faces, key the rest by depth. */
    for (uint32_t f = 0; f < nf; f++) {
        const struct render_face *face = &mesh->faces[f];
        const struct render_vertex *a = &out->pv[face->v[0]];
        const struct render_vertex *b = &out->pv[face->v[1]];
        const struct render_vertex *c = &out->pv[face->v[2]];
        const uint8_t worst = a->state | b->state | c->state;

        if ((worst & RENDER_V_NEAR) != 0u) {
            out->dropped_near++;
            continue;
        }
        if (worst != RENDER_V_OK) {
            out->dropped_range++;
            continue;
        }
        if (!render_is_front(render_signed_area(a->sx_q4, a->sy_q4, b->sx_q4, b->sy_q4,
                                                c->sx_q4, c->sy_q4))) {
            out->culled++;
            continue;
        }
        /* Sum of the three view depths, each >> 2 so the sum fits int32 (z < 2^31, z > 0). */
        out->key[f] = (a->z >> 2) + (b->z >> 2) + (c->z >> 2);
        out->order[n] = (uint16_t)f;
        n++;
    }

    render_sort_back_to_front(out->key, out->order, n);

    for (uint32_t i = 0; i < n; i++) {
        const struct render_face *face = &mesh->faces[out->order[i]];

        gpu_pack_prim(&out->prim_words[i * GPU_PRIM_WORDS], face->v[0], face->v[1], face->v[2],
                      face->color, (uint8_t)GPU_PRIM_KIND_TRI);
    }
    out->prim_count = n;
    return n;
}
