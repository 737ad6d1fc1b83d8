/*
 * render.c — see render.h.
 */
#include "render/render.h"

#include "config/build_options.h"
#include "config/hot_path.h"
#include "gpu_regs.h"  /* the contract's primitive kinds (GPU_PRIM_KIND_*): no driver needed */
#include "render/clip.h"
#include "render/palette.h"
#include "render/proj_unit.h"

/* The light in the rotated scene's frame, O^T l, and in an object's model space, R^T (O^T l):
 * one place for both, so a cache filled ahead (render_level_cache_fill) matches render_object. */
static uvec3 render_light_scene(const mat3 *scene_rot, uvec3 light)
{
    return mat3_apply_transposed_unit(scene_rot, light);
}

static uvec3 render_light_model(const mat3 *obj_rot, uvec3 light_scene)
{
    return mat3_apply_transposed_unit_fast(obj_rot, light_scene);
}

static uint8_t render_ambient(uint32_t ambient)
{
    return (uint8_t)((ambient > 15u) ? 15u : ambient);
}

void render_pass_init(struct render_pass *pass, const struct proj_setup *ps,
                      const struct cam_view *view, const mat3 *scene_rot, vec3 focus,
                      uvec3 light, uint32_t ambient)
{
    pass->proj = *ps;
    pass->focus_to_view.r = mat3_compose(&view->rot, scene_rot);
    pass->focus_to_view.t = mat3_apply(&view->rot, vec3_sub(focus, view->eye));
    pass->focus = focus;
    pass->light_scene = render_light_scene(scene_rot, light);
    pass->ambient = render_ambient(ambient);
    pass->eye_material = 0;
    pass->wireframe = false;
    pass->gpu_lines = true;
    pass->gouraud = false;
}

FW_BUILD_ONCE void render_level_cache_init(struct render_level_cache *c, uint8_t *storage,
                                           uint32_t cap)
{
    c->level = storage;
    c->cap = cap;
    c->valid = false;
    c->light.x = 0;
    c->light.y = 0;
    c->light.z = 0;
    c->ambient = 0;
}

/* The cache's entries for this object's model-space light, or 0 when it has no usable cache.
 * Exact: an entry is what palette_light_level returns for the same light and normal. */
static uint8_t *render_level_cache_for(struct render_level_cache *c, const struct mesh *mesh,
                                       uvec3 light_model, uint32_t ambient)
{
    if (c == 0 || c->cap < mesh->normal_count || mesh->grid.rows != 0u) {
        return 0;
    }
    if (!c->valid || c->light.x != light_model.x || c->light.y != light_model.y ||
        c->light.z != light_model.z || c->ambient != ambient) {
        for (uint32_t i = 0; i < mesh->normal_count; i++) {
            c->level[i] = (uint8_t)RENDER_LEVEL_UNKNOWN;
        }
        c->light = light_model;
        c->ambient = ambient;
        c->valid = true;
    }
    return c->level;
}

FW_BUILD_ONCE void render_level_cache_fill(const struct render_object *obj, const mat3 *scene_rot,
                                           uvec3 light, uint32_t ambient)
{
    const struct mesh *mesh = obj->mesh;
    const uvec3 light_model = render_light_model(&obj->rot, render_light_scene(scene_rot, light));
    const uint32_t amb = render_ambient(ambient);
    struct palette_light pl;
    uint8_t *level = render_level_cache_for(obj->levels, mesh, light_model, amb);

    if (level == 0) {
        return;
    }
    palette_light_init(&pl, light_model, amb);
    for (uint32_t i = 0; i < mesh->normal_count; i++) {
        level[i] = (uint8_t)palette_light_level(&pl, mesh->normals[i]);
    }
}

void render_stats_clear(struct render_stats *s)
{
    *s = (struct render_stats){0};  /* every counter, a new one included */
}

FW_BUILD_ONCE void render_frame_init(struct render_frame *f, struct proj_vertex *vert,
                                     uint32_t vert_cap, struct render_prim *prim,
                                     sort_item_t *sort_item, sort_item_t *sort_tmp,
                                     uint32_t prim_cap, struct sort_scratch *scratch)
{
    f->vert = vert;
    f->prim = prim;
    f->sort_item = sort_item;
    f->sort_tmp = sort_tmp;
    f->vert_cap = (vert_cap > RENDER_INDEX_LIMIT) ? RENDER_INDEX_LIMIT : vert_cap;
    f->prim_cap = (prim_cap > RENDER_INDEX_LIMIT) ? RENDER_INDEX_LIMIT : prim_cap;
    /* Without scratch the sort takes the insertion path, which it may only for small lists. */
    if (scratch == 0 && f->prim_cap >= SORT_SMALL_N) {
        f->prim_cap = SORT_SMALL_N - 1u;
    }
    f->sort = scratch;
    /* The edge set borrows sort_tmp: the largest power of two of words within prim_cap. */
    f->edge_set = sort_tmp;
    f->edge_cap = 0;
    if (sort_tmp != 0) {
        for (f->edge_cap = 1u; 2u * f->edge_cap <= f->prim_cap; f->edge_cap *= 2u) {
        }
    }
    render_stats_clear(&f->stats);
    render_frame_begin(f);
}

void render_frame_begin(struct render_frame *f)
{
    f->vert_count = 0;
    f->prim_count = 0;
    f->sorted_count = 0;
    f->outline_count = 0;
    f->painter_ordered = false;
    f->batch_stamp = 0;  /* every vertex made from now on starts with stamp 0 */
    f->edge_used = f->edge_cap + 1u;  /* the set is cleared when a wireframe first needs it */
}

enum render_sphere_class render_sphere_classify(const struct proj_setup *ps, vec3 c,
                                                real_t radius)
{
    /* The dot products below may be low by 3 units of 2^-16 (vec3_dot_unit_fast); a margin of
     * 2^-8 on the radius keeps both answers conservative: never cull what touches the frustum,
     * never call inside what reaches out of it. Plain sums: view coordinates are within +-4096
     * and a mesh's radius below 14190 (model coordinates within +-8192, real.h), so every sum
     * below stays under 2^15 units, inside q16_16. */
    const real_t r = radius + REAL_C(1.0 / 256.0);
    enum render_sphere_class cls = RENDER_SPHERE_INSIDE;

    if (c.z + r < ps->near || c.z - r > ps->far) {
        return RENDER_SPHERE_OUTSIDE;
    }
    if (c.z - r < ps->near || c.z + r > ps->far) {
        cls = RENDER_SPHERE_CROSSING;
    }
    for (int i = 0; i < 4; i++) {
        /* Signed distance to a plane through the eye: c . n, n the inward unit normal. */
        const real_t d = vec3_dot_unit_fast(c, ps->edge_plane[i]);

        if (d < -r) {
            return RENDER_SPHERE_OUTSIDE;
        }
        if (d < r) {
            cls = RENDER_SPHERE_CROSSING;
        }
    }
    return cls;
}

/* ---- emission ----------------------------------------------------------------------------- */

/* The sort item of primitive `index` with depth key `key` (larger = farther): draw key
 * 65535 - key above the index (sort.h), so ascending items run far to near. key < 2^16, index <
 * prim_cap <= RENDER_INDEX_LIMIT = 2^SORT_KEY_SHIFT or less. */
static inline sort_item_t render_sort_item(uint32_t key, uint32_t index)
{
    return sort_item_make(key ^ 0xFFFFu, index);  /* key ^ 0xFFFF = 65535 - key */
}

static void render_emit_prim(struct render_frame *f, uint32_t i0, uint32_t i1, uint32_t i2,
                             uint8_t color, uint8_t kind, uint16_t key)
{
    struct render_prim *p;
    const uint32_t n = f->prim_count;

    if (n >= f->prim_cap) {
        f->stats.dropped++;
        return;
    }
    p = &f->prim[n];
    p->v[0] = (render_index)i0;
    p->v[1] = (render_index)i1;
    p->v[2] = (render_index)i2;
    p->color = color;
    p->kind = kind;
    f->sort_item[n] = render_sort_item(key, n);
    f->prim_count = n + 1u;
}

/* A vertex that is not the projection of a point: the corners of an emulated line, the
 * crosshair. Returns its index, or -1 when the frame is full. */
static int32_t render_add_screen_vertex(struct render_frame *f, int32_t sx, int32_t sy,
                                        uint16_t zbuf)
{
    struct proj_vertex *v;

    if (f->vert_count >= f->vert_cap) {
        f->stats.dropped++;
        return -1;
    }
    v = &f->vert[f->vert_count];
    v->sx = (int16_t)sx;  /* callers stay within the guard band plus a pixel */
    v->sy = (int16_t)sy;
    v->zbuf = zbuf;
    v->depth = 0;
    v->code = 0;
    v->batch_stamp = 0;
    v->batch_slot = 0;
    return (int32_t)f->vert_count++;
}

/*
 * A line a -> b. With GPU lines: one LINE primitive. Without: a quad one pixel wide across the
 * line's minor axis, centred on it (+-8 sixteenths), as two triangles. For an x-major line the quad
 * spans exactly one pixel centre per column under the fill rule (its vertical extent is 16
 * sixteenths, half-open by the top-left rule), which is what a Bresenham line plots.
 */
static void render_emit_line(struct render_frame *f, const struct render_pass *pass, uint32_t a,
                             uint32_t b, uint8_t color, uint16_t key)
{
    int32_t ax;
    int32_t ay;
    int32_t bx;
    int32_t by;
    int32_t hx = 0;
    int32_t hy = 0;
    int32_t q[4];

    if (pass->gpu_lines) {
        render_emit_prim(f, a, b, b, color, (uint8_t)GPU_PRIM_KIND_LINE, key);
        return;
    }
    ax = f->vert[a].sx;
    ay = f->vert[a].sy;
    bx = f->vert[b].sx;
    by = f->vert[b].sy;
    if (((bx > ax) ? bx - ax : ax - bx) >= ((by > ay) ? by - ay : ay - by)) {
        hy = 8;
    } else {
        hx = 8;
    }
    q[0] = render_add_screen_vertex(f, ax - hx, ay - hy, f->vert[a].zbuf);
    q[1] = render_add_screen_vertex(f, bx - hx, by - hy, f->vert[b].zbuf);
    q[2] = render_add_screen_vertex(f, bx + hx, by + hy, f->vert[b].zbuf);
    q[3] = render_add_screen_vertex(f, ax + hx, ay + hy, f->vert[a].zbuf);
    if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[3] < 0) {
        return;
    }
    /* The GPU draws either winding, so no orientation care is needed here. */
    render_emit_prim(f, (uint32_t)q[0], (uint32_t)q[1], (uint32_t)q[2], color,
                     (uint8_t)GPU_PRIM_KIND_TRI, key);
    render_emit_prim(f, (uint32_t)q[0], (uint32_t)q[2], (uint32_t)q[3], color,
                     (uint8_t)GPU_PRIM_KIND_TRI, key);
}

/* Empty the edge set. */
static void render_edge_set_clear(struct render_frame *f)
{
    for (uint32_t i = 0; i < f->edge_cap; i++) {
        f->edge_set[i] = 0;
    }
    f->edge_used = 0;
}

/*
 * Whether a wireframe draws edge a-b now: false when an earlier face of the pass drew it (the two
 * front faces of a closed mesh that share an edge list it once each, in opposite directions), true
 * the first time, which enters it in the set. Frame vertex numbers name the edge: a mesh's faces
 * share their vertices (render_object projects each once), so a shared edge has one key whatever
 * the direction; a clipped face's new vertices are its own, and its edges are always drawn. When
 * the set is three quarters full every further edge is drawn (a duplicate costs a line, never a
 * missing one); render_object empties a set half full at the start of an object, since no edge is
 * shared between objects.
 */
static bool render_edge_first(struct render_frame *f, uint32_t a, uint32_t b)
{
    const uint32_t lo = (a < b) ? a : b;
    const uint32_t hi = (a < b) ? b : a;
    const sort_item_t key = sort_item_make(lo, hi);  /* a != b: never 0 */
    const uint32_t mask = f->edge_cap - 1u;
    uint32_t i;

    if (f->edge_cap == 0u || a == b) {
        return true;
    }
    if (f->edge_used > f->edge_cap) {
        render_edge_set_clear(f);
    }
    if (f->edge_used >= f->edge_cap - f->edge_cap / 4u) {
        return true;
    }
    /* Fibonacci hashing: key * 2^32 / phi spreads neighbouring vertex numbers (the key itself in
     * a narrow build; a wide one's folded to 32 bits, lo * 2^16 + hi, a probe's start only). */
    for (i = ((lo * 65536u + hi) * 2654435769u) & mask; f->edge_set[i] != 0u; i = (i + 1u) & mask) {
        if (f->edge_set[i] == key) {
            return false;
        }
    }
    f->edge_set[i] = key;
    f->edge_used++;
    return true;
}

/* A convex polygon (front-facing, already projected): a fan of triangles, or its outline. The
 * outline is the polygon's edges k (idx[k] -> idx[(k + 1) % n]) but those `hidden` names (bit k:
 * an edge inside a larger polygon of the mesh, mesh.h) and those an earlier face of the pass drew
 * (render_edge_first). With GPU lines it is the same fan as RENDER_PRIM_OUTLINE primitives, each
 * with the edges that are the polygon's and drawn: triangle (0, k, k+1) has edge 0 (0 -> k) only
 * when k = 1 and edge 2 (k+1 -> 0) only when k + 1 = n - 1, edge 1 always; a triangle left with no
 * edge is not emitted. Expanded in order, they are the polygon's edges 0 -> 1, 1 -> 2, ...,
 * n-1 -> 0, in that order, all with the polygon's key. n <= 9 (clip.h), so a bit mask holds them. */
static void render_emit_polygon(struct render_frame *f, const struct render_pass *pass,
                                const uint32_t *idx, uint32_t n, uint32_t hidden, uint8_t color,
                                uint16_t key, uint8_t tri_kind)
{
    const bool wire = FW_WITH_WIREFRAME && pass->wireframe;
    uint32_t draw = 0;  /* bit k: edge k is drawn */

    if (wire) {
        for (uint32_t k = 0; k < n; k++) {
            if (((hidden >> k) & 1u) == 0u && render_edge_first(f, idx[k], idx[(k + 1u) % n])) {
                draw |= 1u << k;
            }
        }
    }
    if (wire && !pass->gpu_lines) {
        if (FW_WITH_LINE_EMULATION) {
            for (uint32_t k = 0; k < n; k++) {
                if (((draw >> k) & 1u) != 0u) {
                    render_emit_line(f, pass, idx[k], idx[(k + 1u) % n], color, key);
                }
            }
        }
        return;  /* without emulation app.c keeps the wireframe off on such a GPU */
    }
    for (uint32_t k = 1; k + 1u < n; k++) {
        uint8_t kind = tri_kind;  /* GPU_PRIM_KIND_TRI, or _TRI_GOURAUD (never in wireframe) */

        if (wire) {
            const uint32_t edges = (((draw >> k) & 1u) << 1) | ((k == 1u) ? (draw & 1u) : 0u) |
                                   ((k + 2u == n) ? ((draw >> (n - 1u)) & 1u) << 2 : 0u);

            if (edges == 0u) {
                continue;
            }
            kind = (uint8_t)(RENDER_PRIM_OUTLINE | edges);
            f->outline_count += (f->prim_count < f->prim_cap) ? 1u : 0u;  /* else dropped */
        }
        render_emit_prim(f, idx[0], idx[k], idx[k + 1u], color, kind, key);
    }
}

/* ---- lighting ----------------------------------------------------------------------------- */

/* Palette index of a face: its material (or the object's, or the eye's ramp) at its light level. */
static inline uint8_t render_face_color(const struct palette_light *light,
                                        const struct mesh *mesh, const struct mesh_face *face,
                                        uint32_t material_override)
{
    const uint32_t mat = (material_override != 0u) ? material_override : face->material;

    return PAL_INDEX(mat, palette_light_level(light, mesh_normal(mesh, face->normal)));
}

/* Depth key of a face: the sum of its three sort depths (3x the mean), or for half a quad 3/2 of
 * its diagonal's two (3x the quad's centre). Each depth <= 21845: both stay <= 65535. */
static inline uint32_t render_face_key(const struct mesh_face *face, const struct proj_vertex *a,
                                       const struct proj_vertex *b, const struct proj_vertex *c)
{
    if ((face->flags & MESH_FACE_QUAD) != 0u) {
        return (((uint32_t)a->depth + c->depth) * 3u) >> 1;
    }
    return (uint32_t)a->depth + b->depth + c->depth;
}

/* The material every face of an object uses, or 0 for each face's own. */
static uint32_t render_material_override(const struct render_pass *pass,
                                         const struct render_object *obj)
{
    return (pass->eye_material != 0u) ? pass->eye_material : obj->material;
}

/* ---- the slow path: near plane or guard band crossed -------------------------------------- */

static void render_clipped_face(struct render_frame *f, const struct render_pass *pass,
                                const xf_affine *mv, const struct mesh *mesh,
                                const struct mesh_face *face, const struct palette_light *light,
                                uint32_t material_override, const int16_t *vnormal14)
{
    const bool shaded = FW_WITH_GOURAUD && vnormal14 != 0;  /* Gouraud: its vertex normals
                                                             * (render_object) */
    struct clip_polygon poly;
    uint32_t idx[CLIP_MAX_VERTS];
    const uint32_t first = f->vert_count;
    uint32_t n;
    uint32_t all_codes = PROJ_CULL_BITS;
    uint32_t depth_sum = 0;
    int64_t area = 0;

    f->stats.faces_clipped++;
    /* The same transform as the fast path, so shared vertices land on the same pixels. */
#if FW_WITH_GOURAUD
    if (shaded) {
        int32_t shade[3];

        for (uint32_t k = 0; k < 3u; k++) {
            shade[k] = (int32_t)palette_light_intensity(light, mesh_q14_normal(vnormal14, face->v[k]));
        }
        n = clip_triangle_shaded(&pass->proj, xf_apply(mv, mesh->verts[face->v[0]]),
                                 xf_apply(mv, mesh->verts[face->v[1]]),
                                 xf_apply(mv, mesh->verts[face->v[2]]), shade, &poly);
    } else
#endif
    {
        n = clip_triangle(&pass->proj, xf_apply(mv, mesh->verts[face->v[0]]),
                          xf_apply(mv, mesh->verts[face->v[1]]),
                          xf_apply(mv, mesh->verts[face->v[2]]), &poly);
    }
    if (n == 0u) {
        f->stats.faces_clipped_away++;
        return;
    }
    if (f->vert_count + n > f->vert_cap) {
        f->stats.dropped++;
        return;
    }
    for (uint32_t k = 0; k < n; k++) {
        struct proj_vertex *v = &f->vert[f->vert_count];

        proj_point(&pass->proj, poly.v[k], v);
        /* Clipped to the band up to rounding, which its margin absorbs: not a GUARD vertex. */
        v->code &= (uint8_t)~PROJ_OUT_GUARD;
        all_codes &= v->code;
        depth_sum += v->depth;
        idx[k] = f->vert_count++;
    }
    /* Whole polygon's signed area (coplanar fan: every part has the same sign). */
    for (uint32_t k = 1; k + 1u < n; k++) {
        area += proj_signed_area(&f->vert[idx[0]], &f->vert[idx[k]], &f->vert[idx[k + 1u]]);
    }
    if ((all_codes & PROJ_CULL_BITS) != 0u || area <= 0) {
        if ((all_codes & PROJ_CULL_BITS) != 0u) {
            f->stats.faces_frustum++;
        } else {
            f->stats.faces_back++;
        }
        f->vert_count = first;  /* give the vertices back */
        return;
    }
    /* Key: the polygon's mean depth, times three like the fast path's sum. n <= 9. */
    depth_sum = depth_sum * 3u / n;
#if FW_WITH_GOURAUD
    if (shaded) {
        const uint32_t mat = (material_override != 0u) ? material_override : face->material;

        /* A clipped polygon's edges are not the face's (hidden edges are not tracked through
         * clip.c): every one is drawn. */
        render_emit_polygon(f, pass, idx, n, 0u, PAL_INDEX(mat, 0u),
                            (uint16_t)((depth_sum > 65535u) ? 65535u : depth_sum),
                            (uint8_t)GPU_PRIM_KIND_TRI_GOURAUD);
        /* The key is formed: the new vertices' depth half-words now carry their intensity. */
        for (uint32_t k = 0; k < n; k++) {
            f->vert[idx[k]].depth = (uint16_t)poly.shade[k];
        }
        f->stats.faces_emitted++;
        return;
    }
#endif
    /* A clipped polygon's edges are not the face's (hidden edges are not tracked through
     * clip.c): every one is drawn. */
    render_emit_polygon(f, pass, idx, n, 0u, render_face_color(light, mesh, face, material_override),
                        (uint16_t)((depth_sum > 65535u) ? 65535u : depth_sum),
                        (uint8_t)GPU_PRIM_KIND_TRI);
    f->stats.faces_emitted++;
}

/* ---- per object --------------------------------------------------------------------------- */

/* Every vertex of a mesh through the model-view transform and the projection. Kept out of line
 * so the compiler gives the loop all the registers; one loop per case, so the inside one has no
 * outcode work at all. */
static void __attribute__((noinline))
render_project_vertices(const struct proj_setup *ps, const xf_affine *mv, const vec3 *verts,
                        uint32_t n, struct proj_vertex *out, bool inside)
{
#if PROJ_UNIT_USED
    /* The SoC's projection unit (render/proj_unit.h): the same vertices. */
    if (n == 0u) {
        return;
    }
    proj_unit_load(ps, mv);
    if (inside) {
        proj_unit_points(verts, n, out, true);
    } else {
        proj_unit_points(verts, n, out, false);
    }
#else
    const xf_affine m = *mv;  /* a local copy: the stores to out cannot alias it */

    if (inside) {
        for (uint32_t i = 0; i < n; i++) {
            proj_point_inside(ps, xf_apply(&m, verts[i]), &out[i]);
        }
    } else {
        for (uint32_t i = 0; i < n; i++) {
            proj_point(ps, xf_apply(&m, verts[i]), &out[i]);
        }
    }
#endif
}

#if !PROJ_UNIT_USED
/* The same for a box mesh (mesh.box): its eight corners through xf_apply_box, which gives the
 * same view points as xf_apply (cubes: 184 instructions for the eight instead of about 256). */
static void __attribute__((noinline))
render_project_box(const struct proj_setup *ps, const xf_affine *mv, const struct mesh *mesh,
                   struct proj_vertex *out, bool inside)
{
    vec3 p[8];

    xf_apply_box(mv, mesh->box_lo, mesh->box_hi, p);
    if (inside) {
        for (uint32_t i = 0; i < 8u; i++) {
            proj_point_inside(ps, p[i], &out[i]);
        }
    } else {
        for (uint32_t i = 0; i < 8u; i++) {
            proj_point(ps, p[i], &out[i]);
        }
    }
}

#endif

/* With the projection unit every mesh takes it, vertex by vertex: 14-16 instructions a vertex,
 * against the box's 85 a corner (the cubes' profile: xf_apply_box and the projection) and the
 * lattice's 77 (the landscape's inside tiles); leaving those out leaves room in the SoC's image. */
void render_project_boxed(const struct proj_setup *ps, const xf_affine *mv, const struct mesh *mesh,
                          struct proj_vertex *out, bool inside)
{
#if !PROJ_UNIT_USED
    if (mesh->box) {
        render_project_box(ps, mv, mesh, out, inside);
        return;
    }
#endif
    render_project_vertices(ps, mv, mesh->verts, mesh->vert_count, out, inside);
}

/* Columns a lattice mesh may have for render_project_lattice_inside: its column products live on
 * the stack (12 bytes a column; the landscape's tiles have 9). A wider lattice takes the general
 * loop. */
#define RENDER_LATTICE_AXES_MAX_COLS 33u

#if REAL_IS_FIXED && !PROJ_UNIT_USED
/*
 * A lattice mesh with lattice_axes (mesh.h) inside the frustum: vertex (r, c) is (x_c, y, z_r).
 * xf_apply's x row is mulh(m00, 4 x) + mulh(m01, 4 y) + mulh(m02, 4 z) + t.x, each product
 * floored on its own: the x term is column c's and the z term (with t) row r's, formed once here,
 * so a vertex takes three products instead of nine. The sum is the same integer in any order (no
 * partial sum overflows: each is within xf_apply's |p| + |t| < 2^30.2 bound), so the view points,
 * and everything after, are exactly xf_apply's. Only the inside case: a second copy of the
 * projection, for the tiles that cross the frustum, would not fit the landscape's 192 KiB image.
 * Float keeps xf_apply (its sums round in order).
 */
static void __attribute__((noinline))
render_project_lattice_inside(const struct proj_setup *ps, const xf_affine *mv,
                              const struct mesh *mesh, struct proj_vertex *out)
{
    const uint32_t w = mesh->lattice_cols;
    const uint32_t rows = mesh->vert_count / w;
    const vec3 *verts = mesh->verts;
    const unit_t(*m)[3] = mv->r.m;
    const int32_t m01 = m[0][1];
    const int32_t m11 = m[1][1];
    const int32_t m21 = m[2][1];
    vec3 col[RENDER_LATTICE_AXES_MAX_COLS];  /* column c's x products */

    for (uint32_t c = 0; c < w; c++) {
        const int32_t x4 = verts[c].x * 4;

        col[c] = vec3_make(fx_mulh(m[0][0], x4), fx_mulh(m[1][0], x4), fx_mulh(m[2][0], x4));
    }
    for (uint32_t r = 0; r < rows; r++, verts += w, out += w) {
        const int32_t z4 = verts[0].z * 4;
        const vec3 row = vec3_make(fx_mulh(m[0][2], z4) + mv->t.x, fx_mulh(m[1][2], z4) + mv->t.y,
                                   fx_mulh(m[2][2], z4) + mv->t.z);

        for (uint32_t c = 0; c < w; c++) {
            const int32_t y4 = verts[c].y * 4;

            proj_point_inside(ps,
                              vec3_make(col[c].x + fx_mulh(m01, y4) + row.x,
                                        col[c].y + fx_mulh(m11, y4) + row.y,
                                        col[c].z + fx_mulh(m21, y4) + row.z),
                              &out[c]);
        }
    }
}
#endif

void render_project_lattice(const struct proj_setup *ps, const xf_affine *mv,
                            const struct mesh *mesh, struct proj_vertex *out, bool inside)
{
#if REAL_IS_FIXED && !PROJ_UNIT_USED
    if (inside && mesh->lattice_axes && mesh->lattice_cols <= RENDER_LATTICE_AXES_MAX_COLS) {
        render_project_lattice_inside(ps, mv, mesh, out);
        return;
    }
#endif
    render_project_vertices(ps, mv, mesh->verts, mesh->vert_count, out, inside);
}

/* The face loop's rare cases, out of line: a face that crosses the near plane or the guard band
 * (clip.c), and every face in wireframe mode. Emits through f->prim_count. */
static void __attribute__((noinline))
render_face_general(struct render_frame *f, const struct render_pass *pass, const xf_affine *mv,
                    const struct mesh *mesh, const struct mesh_face *face, uint32_t base,
                    const struct palette_light *light, uint32_t material_override,
                    const int16_t *vnormal14)
{
    const bool shaded = FW_WITH_GOURAUD && vnormal14 != 0;
    const struct proj_vertex *a = &f->vert[base + face->v[0]];
    const struct proj_vertex *b = &f->vert[base + face->v[1]];
    const struct proj_vertex *c = &f->vert[base + face->v[2]];

    if (((a->code | b->code | c->code) & PROJ_CLIP_BITS) != 0u) {
        render_clipped_face(f, pass, mv, mesh, face, light, material_override, vnormal14);
    } else if (proj_signed_area(a, b, c) <= 0) {
        f->stats.faces_back++;
    } else {
        const uint32_t idx[3] = {base + face->v[0], base + face->v[1], base + face->v[2]};

        const uint32_t mat = (material_override != 0u) ? material_override : face->material;

        render_emit_polygon(f, pass, idx, 3u, (uint32_t)(face->flags & MESH_FACE_EDGES_HIDDEN) >> 1,
                            shaded ? PAL_INDEX(mat, 0u)
                                   : render_face_color(light, mesh, face, material_override),
                            (uint16_t)render_face_key(face, a, b, c),
                            shaded ? (uint8_t)GPU_PRIM_KIND_TRI_GOURAUD : (uint8_t)GPU_PRIM_KIND_TRI);
        f->stats.faces_emitted++;
    }
}

/* A frame primitive's fields, written as its two words where render_prim has them (a narrow
 * frame on a little-endian CPU, render.h): i0, i1, i2 are frame vertex numbers, below
 * RENDER_INDEX_LIMIT = 2^16 there, so no field needs masking; color and kind are bytes. */
static inline void render_prim_put(struct render_prim *p, uint32_t i0, uint32_t i1, uint32_t i2,
                                   uint32_t color, uint32_t kind)
{
#if !FW_RENDER_WIDE_INDEX && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    p->w[0] = i0 | (i1 << 16);
    p->w[1] = i2 | (color << 16) | (kind << 24);
#else
    p->v[0] = (render_index)i0;
    p->v[1] = (render_index)i1;
    p->v[2] = (render_index)i2;
    p->color = (uint8_t)color;
    p->kind = (uint8_t)kind;
#endif
}

/*
 * A face loop's counts into the frame's statistics: of `faces` faces, n_frustum were culled by the
 * frustum, n_aside went through the general path or found no room, `fast` were emitted one
 * primitive each, and the rest were back faces (the loops do not count those as they cull them:
 * a counter kept in memory cost the knot's grid loop 5 instructions a back face).
 */
static inline void render_face_stats(struct render_frame *f, uint32_t faces, uint32_t n_frustum,
                                     uint32_t n_aside, uint32_t fast)
{
    f->stats.faces_frustum += n_frustum;
    f->stats.faces_emitted += fast;
    f->stats.faces_back += faces - n_frustum - n_aside - fast;
}

/* What the face loop needs about one object. */
struct render_faces_job {
    const struct render_pass *pass;
    const xf_affine *mv;
    const struct mesh *mesh;
    const struct palette_light *light;
    uint8_t *levels;             /* 0, or the object's cached level per normal (filled lazily) */
    uint32_t base;               /* index of the object's first vertex in the frame */
    uint32_t material_override;
    const int16_t *vnormal14;    /* Gouraud: the object's vertex normals; 0: flat */
};

/* Where render_grid_faces is in a grid mesh, and what its halves share. */
struct render_grid_walk {
    const struct render_faces_job *job;  /* the loop's job as given (the out-of-line path's) */
    uint32_t i, j;       /* the quad's row and column */
    uint32_t quad;       /* its number, i * cols + j: its normal's */
    uint32_t mat;        /* its row's material (or the override) */
    uint32_t level;      /* its light level, RENDER_LEVEL_UNKNOWN until a half is drawn */
    bool general;        /* wireframe: every face through render_face_general */
    bool shaded;         /* Gouraud */
    uint32_t np_general; /* primitives the general path added */
    uint32_t n_frustum;
    uint32_t n_aside;    /* faces through the general path, or dropped (no room) */
    uint32_t n_dropped;  /* dropped (no room): the frame's stats.dropped gets them at the end */
    /* The frame's arrays, read once: the face's stores into them could otherwise (for all the
     * compiler knows) change the frame's pointers, which it would then read again a face. */
    const struct proj_vertex *vert;  /* the object's first vertex */
    struct render_prim *prim;
    sort_item_t *sort_item;
    uint32_t prim_cap;
};

/*
 * The face loop. `check` (a constant at every call, folded away) is false for an object whose
 * bounding sphere is inside the frustum: no face can be culled by outcodes or need clipping, so
 * the loop skips those tests. `cached` (likewise a constant) is true when job->levels holds the
 * object's level cache: a face's light level is then looked up, computed only on a miss. Hot state stays in locals and is written back once; the fast path
 * emits one triangle per front face, everything else goes through render_face_general.
 */
static inline __attribute__((always_inline)) void render_faces(struct render_frame *f,
                                                               const struct render_faces_job *job,
                                                               bool check, bool cached)
{
    const struct mesh *mesh = job->mesh;
    const uint32_t nf = mesh->face_count;
    const struct mesh_face *faces = mesh->faces;
    const uvec3 *normals = mesh->normals;
    uint8_t *const levels = job->levels;
    const struct proj_vertex *vert = &f->vert[job->base];
    const uint32_t base = job->base;
    const uint32_t material_override = job->material_override;
    const bool general = FW_WITH_WIREFRAME && job->pass->wireframe;
    const bool shaded = FW_WITH_GOURAUD && job->vnormal14 != 0;  /* 0 in wireframe (render_object) */
    struct render_prim *const prim = f->prim;
    struct render_prim *const p_end = prim + f->prim_cap;
    const uint32_t np_start = f->prim_count;
    /* The next primitive and sort item as pointers, and the next item's payload with the largest
     * draw key above it (a face's item is then one subtraction, below). */
    struct render_prim *p = prim + np_start;
    sort_item_t *item = f->sort_item + np_start;
    sort_item_t key_np = sort_item_make(0xFFFFu, np_start);
    uint32_t np;
    uint32_t np_general = 0;  /* primitives the general path added (not one per face) */
    uint32_t n_frustum = 0;
    uint32_t n_aside = 0;     /* faces through the general path, or dropped (no room) */
    /* Without a cache: the last light level worked out, and its normal's number (none yet). A
     * quad's halves (mesh_add_quad) follow each other with one normal: the second reuses it. */
    uint32_t last_normal = UINT32_MAX;
    uint32_t last_level = 0;
    uint32_t vsize = sizeof(struct proj_vertex);

    FW_ONE_REGISTER(vert);  /* one add less per vertex of every face */
    FW_AS_MULTIPLIER(vsize);
    for (uint32_t fi = 0; fi < nf; fi++) {
        const struct mesh_face *face = &faces[fi];
        const struct proj_vertex *a = proj_vertex_at(vert, face->v[0], vsize);
        const struct proj_vertex *b = proj_vertex_at(vert, face->v[1], vsize);
        const struct proj_vertex *c = proj_vertex_at(vert, face->v[2], vsize);
        uint32_t mat;
        uint32_t level;

        if (check && (a->code & b->code & c->code & PROJ_CULL_BITS) != 0u) {
            n_frustum++;
            continue;
        }
        if ((check && ((a->code | b->code | c->code) & PROJ_CLIP_BITS) != 0u) || general) {
            np = (uint32_t)(p - prim);
            f->prim_count = np;
            render_face_general(f, job->pass, job->mv, mesh, face, base, job->light,
                                material_override, job->vnormal14);
            np_general += f->prim_count - np;
            np = f->prim_count;
            p = prim + np;
            item = f->sort_item + np;
            key_np = sort_item_make(0xFFFFu, np);
            n_aside++;
            continue;
        }
        /* A back face (not counted here: render_face_stats works the count out). */
        if (check ? (proj_signed_area(a, b, c) <= 0) : (proj_signed_area_inside(a, b, c) <= 0)) {
            continue;
        }
        if (p >= p_end) {
            f->stats.dropped++;
            n_aside++;
            continue;
        }
        p->v[0] = (render_index)(base + face->v[0]);
        p->v[1] = (render_index)(base + face->v[1]);
        p->v[2] = (render_index)(base + face->v[2]);
        mat = (material_override != 0u) ? material_override : face->material;
        if (shaded) {
            p->color = PAL_INDEX(mat, 0u);
            p->kind = (uint8_t)GPU_PRIM_KIND_TRI_GOURAUD;
            *item = key_np - ((sort_item_t)render_face_key(face, a, b, c) << SORT_KEY_SHIFT);
            p++;
            item++;
            key_np++;
            continue;
        }
        if (cached) {
            level = levels[face->normal];
            if (level == RENDER_LEVEL_UNKNOWN) {
                level = palette_light_level(job->light, normals[face->normal]);
                levels[face->normal] = (uint8_t)level;
            }
        } else {
            if (face->normal != last_normal) {
                last_normal = face->normal;
                last_level = palette_light_level(job->light, normals[last_normal]);
            }
            level = last_level;
        }
        p->color = PAL_INDEX(mat, level);
        p->kind = (uint8_t)GPU_PRIM_KIND_TRI;
        /* render_sort_item(key, np): key <= 65535 (render_face_key), so
         * (65535 - key) << shift | np = ((65535 << shift) | np) - (key << shift), no borrow. */
        *item = key_np - ((sort_item_t)render_face_key(face, a, b, c) << SORT_KEY_SHIFT);
        p++;
        item++;
        key_np++;
    }
    np = (uint32_t)(p - prim);
    f->prim_count = np;
    render_face_stats(f, nf, n_frustum, n_aside, (np - np_start) - np_general);
}

/* A grid face through the general path, out of line (render_grid_half_aside is inlined three
 * times): face `half` of quad (i, j) through render_face_general, after np primitives; returns
 * the primitive count. */
static uint32_t __attribute__((noinline))
render_grid_face_general(struct render_frame *f, const struct render_faces_job *job, uint32_t i,
                         uint32_t j, uint32_t half, uint32_t np)
{
    struct mesh_face face;

    mesh_grid_face(&job->mesh->grid, i, j, half, &face);
    f->prim_count = np;
    render_face_general(f, job->pass, job->mv, job->mesh, &face, job->base, job->light,
                        job->material_override, job->vnormal14);
    return f->prim_count;
}

/* One corner of a grid or lattice quad, read once for both of the quad's faces (the stores of the
 * first face's primitive could otherwise, for all the compiler knows, change the vertices), and in
 * a grid row once for both quads that share it. */
struct render_lattice_corner {
    int32_t x, y;    /* Q12.4 */
    uint32_t depth;  /* sort depth */
};

static inline __attribute__((always_inline)) struct render_lattice_corner
render_lattice_corner(const struct proj_vertex *v)
{
    struct render_lattice_corner k;

    k.x = v->sx;
    k.y = v->sy;
    k.depth = v->depth;
    return k;
}

/* The signed area of the corners' triangle in 32 bits: exact when every corner is on the frame
 * (proj_signed_area_inside's argument), as in an object inside the frustum. */
static inline int32_t render_corner_area(struct render_lattice_corner a, struct render_lattice_corner b,
                                         struct render_lattice_corner c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/*
 * A front half (ia, i1, i2) of grid quad w->quad: dropped for want of room, or its primitive and
 * sort item (a grid face is not MESH_FACE_QUAD, mesh_grid_face: its key is its three depths' sum,
 * depth_sum). w->level is the quad's light level once a half
 * has worked it out: both halves share the quad's normal, so the second half drawn reuses it. np
 * primitives so far, returned with this face's.
 */
static inline __attribute__((always_inline)) uint32_t
render_grid_emit(const struct render_faces_job *job, struct render_grid_walk *w, uint32_t ia,
                 uint32_t i1, uint32_t i2, uint32_t depth_sum, uint32_t np)
{
    uint32_t color;
    uint32_t kind;

    if (np >= w->prim_cap) {
        w->n_dropped++;
        w->n_aside++;
        return np;
    }
    if (w->shaded) {
        color = PAL_INDEX(w->mat, 0u);
        kind = GPU_PRIM_KIND_TRI_GOURAUD;
    } else {
        if (w->level == RENDER_LEVEL_UNKNOWN) {
            w->level = palette_light_level(job->light, mesh_normal(job->mesh, w->quad));
        }
        color = PAL_INDEX(w->mat, w->level);
        kind = GPU_PRIM_KIND_TRI;
    }
    render_prim_put(&w->prim[np], job->base + ia, job->base + i1, job->base + i2, color, kind);
    w->sort_item[np] = render_sort_item(depth_sum, np);
    return np + 1u;
}

/* One half of a grid quad of an object inside the frustum, from its corners as
 * render_grid_row_inside reads them: no outcode can cull or clip it, and its area is the 32-bit
 * one (every corner on the frame). */
static inline __attribute__((always_inline)) uint32_t
render_grid_half_inside(const struct render_faces_job *job, struct render_grid_walk *w,
                        struct render_lattice_corner a, struct render_lattice_corner b,
                        struct render_lattice_corner c, uint32_t ia, uint32_t i1, uint32_t i2,
                        uint32_t np)
{
    if (render_corner_area(a, b, c) <= 0) {
        return np;  /* a back face (render_face_stats works the count out) */
    }
    return render_grid_emit(job, w, ia, i1, i2, a.depth + b.depth + c.depth, np);
}

/*
 * Row w->i of a grid mesh inside the frustum (no wireframe): quads (i, 0 .. cols-1), each corner
 * read once — quad j's right corners are quad j+1's left ones, carried over —, the halves as
 * render_grid_faces orders them. row and row1: the first vertex numbers of rows i and i + 1 (0 for
 * the last row: the grid wraps). Returns the primitive count with this row's.
 */
static inline __attribute__((always_inline)) uint32_t
render_grid_row_inside(const struct render_faces_job *job, struct render_grid_walk *w,
                       uint32_t row, uint32_t row1, uint32_t cols, bool flip, uint32_t np,
                       uint32_t vsize)
{
    struct render_lattice_corner ka = render_lattice_corner(proj_vertex_at(w->vert, row, vsize));
    struct render_lattice_corner kb = render_lattice_corner(proj_vertex_at(w->vert, row1, vsize));

    for (uint32_t j = 0; j < cols; j++) {
        const uint32_t j1 = (j + 1u == cols) ? 0u : j + 1u;
        const uint32_t ia = row + j;    /* (i, j) */
        const uint32_t ib = row1 + j;   /* (i + 1, j) */
        const uint32_t ic = row1 + j1;  /* (i + 1, j + 1) */
        const uint32_t id = row + j1;   /* (i, j + 1) */
        const struct render_lattice_corner kc = render_lattice_corner(proj_vertex_at(w->vert, ic, vsize));
        const struct render_lattice_corner kd = render_lattice_corner(proj_vertex_at(w->vert, id, vsize));

        w->quad = ia;
        w->level = RENDER_LEVEL_UNKNOWN;
        if (flip) {  /* (a, d, c), (a, c, b) */
            np = render_grid_half_inside(job, w, ka, kd, kc, ia, id, ic, np);
            np = render_grid_half_inside(job, w, ka, kc, kb, ia, ic, ib, np);
        } else {     /* (a, b, c), (a, c, d) */
            np = render_grid_half_inside(job, w, ka, kb, kc, ia, ib, ic, np);
            np = render_grid_half_inside(job, w, ka, kc, kd, ia, ic, id, np);
        }
        ka = kd;
        kb = kc;
    }
    return np;
}

/* Half `half` of grid quad (w->i, w->j) through the general path (render_face_general:
 * clipping, wireframe), its primitives counted aside; np so far, returned with its own. */
static inline __attribute__((always_inline)) uint32_t
render_grid_half_aside(struct render_frame *f, struct render_grid_walk *w, uint32_t half,
                       uint32_t np)
{
    const uint32_t after = render_grid_face_general(f, w->job, w->i, w->j, half, np);

    w->np_general += after - np;
    w->n_aside++;
    return after;
}

/*
 * One half of a grid quad of a mesh crossing the frustum's planes, with every test: the face
 * (ia, i1, i2), half `half` of quad (w->i, w->j) (mesh_grid_face gives it whole when the general
 * path needs it); np primitives so far, returned with this face's (render_grid_emit). Out of line:
 * the rare case, and one copy keeps a one-scene program of the knot within the SoC's 192 KiB.
 */
static uint32_t __attribute__((noinline))
render_grid_half_checked(struct render_frame *f, const struct render_faces_job *job,
                         struct render_grid_walk *w, uint32_t ia, uint32_t i1, uint32_t i2,
                         uint32_t half, uint32_t np)
{
    const struct proj_vertex *a = &w->vert[ia];
    const struct proj_vertex *b = &w->vert[i1];
    const struct proj_vertex *c = &w->vert[i2];

    if ((a->code & b->code & c->code & PROJ_CULL_BITS) != 0u) {
        w->n_frustum++;
        return np;
    }
    if (((a->code | b->code | c->code) & PROJ_CLIP_BITS) != 0u || w->general) {
        return render_grid_half_aside(f, w, half, np);
    }
    /* A back face (not counted here: render_face_stats works the count out). */
    if (proj_signed_area(a, b, c) <= 0) {
        return np;
    }
    return render_grid_emit(job, w, ia, i1, i2, (uint32_t)a->depth + b->depth + c->depth, np);
}

/*
 * The face loop of a grid mesh (mesh.h), quad by quad: faces 2q and 2q + 1 of quad q share its
 * corners, its row's material and its normal, worked out once for both (the light level only when
 * a half is drawn). The same primitives, in the same order and with the same counts, as
 * render_faces over mesh_grid_face's faces. `check` as there: false for a mesh inside the frustum.
 */
static inline __attribute__((always_inline)) void render_grid_faces(struct render_frame *f,
                                                                    const struct render_faces_job *job_in,
                                                                    bool check)
{
    /* A copy in locals: stores to the frame cannot change it, so the loop keeps it in registers. */
    const struct render_faces_job job_copy = *job_in;
    const struct render_faces_job *const job = &job_copy;
    const struct mesh_grid *g = &job->mesh->grid;
    const uint32_t rows = g->rows;
    const uint32_t cols = g->cols;
    const uint32_t np_start = f->prim_count;
    uint32_t np = np_start;
    struct render_grid_walk w;
    uint32_t vsize = sizeof(struct proj_vertex);

    FW_AS_MULTIPLIER(vsize);
    w.job = job_in;
    w.general = FW_WITH_WIREFRAME && job->pass->wireframe;
    w.shaded = FW_WITH_GOURAUD && job->vnormal14 != 0;
    w.np_general = 0;
    w.n_frustum = 0;
    w.n_aside = 0;
    w.n_dropped = 0;
    w.vert = &f->vert[job->base];
    w.prim = f->prim;
    w.sort_item = f->sort_item;
    w.prim_cap = f->prim_cap;
    for (w.i = 0; w.i < rows; w.i++) {
        const uint32_t row = w.i * cols;
        const uint32_t row1 = (w.i + 1u == rows) ? 0u : row + cols;

        w.mat = (job->material_override != 0u) ? job->material_override : g->material[w.i];
        if (!check && !w.general) {
            np = render_grid_row_inside(job, &w, row, row1, cols, g->flip, np, vsize);
            continue;
        }
        for (w.j = 0; w.j < cols; w.j++) {
            const uint32_t j1 = (w.j + 1u == cols) ? 0u : w.j + 1u;
            const uint32_t ia = row + w.j;   /* (i, j) */
            const uint32_t ib = row1 + w.j;  /* (i + 1, j) */
            const uint32_t ic = row1 + j1;   /* (i + 1, j + 1) */
            const uint32_t id = row + j1;    /* (i, j + 1) */
            const uint32_t second0 = g->flip ? id : ib;  /* half 0's second corner */
            const uint32_t third1 = g->flip ? ib : id;   /* half 1's third */

            w.quad = ia;
            w.level = RENDER_LEVEL_UNKNOWN;
            if (check) {
                np = render_grid_half_checked(f, job, &w, ia, second0, ic, 0u, np);
                np = render_grid_half_checked(f, job, &w, ia, ic, third1, 1u, np);
            } else {  /* wireframe inside the frustum: every face to the general path */
                np = render_grid_half_aside(f, &w, 0u, np);
                np = render_grid_half_aside(f, &w, 1u, np);
            }
        }
    }
    f->prim_count = np;
    f->stats.dropped += w.n_dropped;
    render_face_stats(f, 2u * rows * cols, w.n_frustum, w.n_aside, (np - np_start) - w.np_general);
}

/* What the faces of render_lattice_faces and render_quad_faces share, and what they count: the
 * next primitive and sort item as pointers, and the next item's payload with the largest draw key
 * above it, from which a face's item is one subtraction (render_lattice_face, render_quad_half). */
struct render_emit_walk {
    struct render_prim *prim;       /* the frame's primitives */
    struct render_prim *p;          /* the next one: prim + np */
    struct render_prim *p_end;      /* prim + prim_cap */
    sort_item_t *item;              /* sort_item + np */
    sort_item_t key_np;             /* sort_item_make(0xFFFF, np) */
    uint8_t *levels;     /* the object's level cache, or 0 (render_lattice_faces_loop needs one) */
    uint32_t n_back;
};

/* The walk's pointers and key for np primitives. */
static inline void render_emit_at(struct render_emit_walk *w, sort_item_t *sort_item, uint32_t np)
{
    w->p = w->prim + np;
    w->item = sort_item + np;
    w->key_np = sort_item_make(0xFFFFu, np);
}

/* The primitive just written at w->p done: its sort item from its depth key (<= 65535, shifted
 * into place: (65535 - key) << shift | np = ((65535 << shift) | np) - (key << shift), no borrow),
 * and the walk on to the next. */
static inline void render_emit_next(struct render_emit_walk *w, sort_item_t key_shifted)
{
    *w->item = w->key_np - key_shifted;
    w->p++;
    w->item++;
    w->key_np++;
}

/* A level cache's miss, out of line (once per normal while the light stays): the level of normal
 * `normal`, entered in the cache. */
static uint32_t __attribute__((noinline))
render_level_fill(uint8_t *levels, const struct palette_light *light, const struct mesh *mesh,
                  uint32_t normal)
{
    const uint32_t level = palette_light_level(light, mesh->normals[normal]);

    levels[normal] = (uint8_t)level;
    return level;
}

/* What render_face_any counts besides the primitives. */
struct render_face_counts {
    uint32_t np_general; /* primitives the general path added */
    uint32_t n_frustum;
    uint32_t n_back;
};

/*
 * One face of any mesh with a faces array, exactly as render_faces treats it (its tests in its
 * order, the same primitive, key and counts), every option a run-time one: one copy for the
 * lattice loop's other cases (a quad with a corner off the screen; wireframe, Gouraud, an eye
 * material, a mesh that is not a lattice), so a program with only lattice meshes does not link
 * render_faces' four loops (the landscape's one-scene image must fit the SoC's 192 KiB). np
 * primitives so far; returns the count with this face's.
 */
static uint32_t __attribute__((noinline))
render_face_any(struct render_frame *f, const struct render_faces_job *job, bool check,
                const struct mesh_face *face, uint32_t np, struct render_face_counts *n)
{
    const struct mesh *mesh = job->mesh;
    const struct proj_vertex *vert = &f->vert[job->base];
    const struct proj_vertex *a = &vert[face->v[0]];
    const struct proj_vertex *b = &vert[face->v[1]];
    const struct proj_vertex *c = &vert[face->v[2]];
    const uint32_t base = job->base;
    uint32_t mat;
    uint32_t level;

    if (check && (a->code & b->code & c->code & PROJ_CULL_BITS) != 0u) {
        n->n_frustum++;
        return np;
    }
    if ((check && ((a->code | b->code | c->code) & PROJ_CLIP_BITS) != 0u) ||
        (FW_WITH_WIREFRAME && job->pass->wireframe)) {
        f->prim_count = np;
        render_face_general(f, job->pass, job->mv, mesh, face, base, job->light,
                            job->material_override, job->vnormal14);
        n->np_general += f->prim_count - np;
        return f->prim_count;
    }
    if (check ? (proj_signed_area(a, b, c) <= 0) : (proj_signed_area_inside(a, b, c) <= 0)) {
        n->n_back++;
        return np;
    }
    if (np >= f->prim_cap) {
        f->stats.dropped++;
        return np;
    }
    mat = (job->material_override != 0u) ? job->material_override : face->material;
    if (FW_WITH_GOURAUD && job->vnormal14 != 0) {
        render_prim_put(&f->prim[np], base + face->v[0], base + face->v[1], base + face->v[2],
                        PAL_INDEX(mat, 0u), GPU_PRIM_KIND_TRI_GOURAUD);
    } else {
        if (job->levels != 0) {
            level = job->levels[face->normal];
            if (level == RENDER_LEVEL_UNKNOWN) {
                level = render_level_fill(job->levels, job->light, mesh, face->normal);
            }
        } else {
            level = palette_light_level(job->light, mesh->normals[face->normal]);
        }
        render_prim_put(&f->prim[np], base + face->v[0], base + face->v[1], base + face->v[2],
                        PAL_INDEX(mat, level), GPU_PRIM_KIND_TRI);
    }
    f->sort_item[np] = render_sort_item(render_face_key(face, a, b, c), np);
    return np + 1u;
}

/* A half of render_quad_faces' quad, with frame vertices i0, i1, i2, the quad's colour and its key
 * (shifted into place): a back face counted, a front one dropped for want of room or emitted. */
static inline __attribute__((always_inline)) void
render_quad_half(struct render_frame *f, struct render_emit_walk *w, bool front, uint32_t i0,
                 uint32_t i1, uint32_t i2, uint32_t color, sort_item_t key)
{
    if (!front) {
        w->n_back++;
    } else if (w->p >= w->p_end) {
        f->stats.dropped++;
    } else {
        render_prim_put(w->p, i0, i1, i2, color, GPU_PRIM_KIND_TRI);
        render_emit_next(w, key);
    }
}

/*
 * The face loop of a quad mesh (mesh.quads), filled and flat: quad q's halves (a, b, c) and
 * (c, d, a) have their four corners read once and, being halves of one quad (one normal, one
 * material, MESH_FACE_QUAD: both keys are the diagonal a-c's), one colour and one key formed for
 * both, when a half is drawn. A quad with a corner off the screen (only where `check`, as in
 * render_faces: the object crosses the frustum) has both halves done by render_face_any; else
 * every corner is on the frame and the 32-bit area is exact (proj_signed_area_inside). The same
 * primitives, in the same order and with the same counts, as render_faces over the same faces.
 * One copy for every case (`check` and a level cache are run-time tests, a predicted branch a
 * quad): the voxel's one-scene image has no room for four.
 */
static void render_quad_faces(struct render_frame *f, const struct render_faces_job *job_in,
                              bool check)
{
    /* A copy in locals: stores to the frame cannot change it, so the loop keeps it in registers. */
    const struct render_faces_job job_copy = *job_in;
    const struct render_faces_job *const job = &job_copy;
    const struct mesh *mesh = job->mesh;
    const struct mesh_face *face = mesh->faces;
    const struct mesh_face *const face_end = face + mesh->face_count;
    const uint32_t base = job->base;
    const struct proj_vertex *vert = &f->vert[base];
    sort_item_t *const sort_item = f->sort_item;
    const uint32_t np_start = f->prim_count;
    struct render_emit_walk w;
    struct render_face_counts slow = {0, 0, 0};  /* render_face_any's */
    uint32_t np;
    uint32_t vsize = sizeof(struct proj_vertex);

    w.prim = f->prim;
    w.p_end = f->prim + f->prim_cap;
    w.levels = job->levels;
    w.n_back = 0;
    render_emit_at(&w, sort_item, np_start);
    FW_ONE_REGISTER(vert);
    FW_AS_MULTIPLIER(vsize);
    for (; face != face_end; face += 2) {
        const uint32_t ia = face[0].v[0];
        const uint32_t ib = face[0].v[1];
        const uint32_t ic = face[0].v[2];
        const uint32_t id = face[1].v[1];
        const struct proj_vertex *a = proj_vertex_at(vert, ia, vsize);
        const struct proj_vertex *b = proj_vertex_at(vert, ib, vsize);
        const struct proj_vertex *c = proj_vertex_at(vert, ic, vsize);
        const struct proj_vertex *d = proj_vertex_at(vert, id, vsize);
        bool front0;
        bool front1;
        uint32_t level;
        uint32_t color;
        sort_item_t key;

        if (check && (a->code | b->code | c->code | d->code) != 0u) {
            /* All four corners beyond one plane: both halves frustum-culled, as render_faces
             * would find each. */
            if ((a->code & b->code & c->code & d->code & PROJ_CULL_BITS) != 0u) {
                slow.n_frustum += 2u;
                continue;
            }
            np = (uint32_t)(w.p - w.prim);
            np = render_face_any(f, job, true, &face[0], np, &slow);
            np = render_face_any(f, job, true, &face[1], np, &slow);
            render_emit_at(&w, sort_item, np);
            continue;
        }
        front0 = proj_signed_area_inside(a, b, c) > 0;
        front1 = proj_signed_area_inside(c, d, a) > 0;
        if (!front0 && !front1) {
            w.n_back += 2u;
            continue;
        }
        if (w.p >= w.p_end) {  /* no room: no light level looked up either, as in render_faces */
            w.n_back += (front0 ? 0u : 1u) + (front1 ? 0u : 1u);
            f->stats.dropped += (front0 ? 1u : 0u) + (front1 ? 1u : 0u);
            continue;
        }
        if (w.levels != 0) {
            level = w.levels[face->normal];
            if (FW_UNLIKELY(level == RENDER_LEVEL_UNKNOWN)) {
                level = render_level_fill(w.levels, job->light, mesh, face->normal);
            }
        } else {
            level = palette_light_level(job->light, mesh->normals[face->normal]);
        }
        color = PAL_INDEX((job->material_override != 0u) ? job->material_override : face->material,
                          level);
        /* render_face_key of a MESH_FACE_QUAD half; <= 65535, so no borrow (render_faces). */
        key = (sort_item_t)((((uint32_t)a->depth + c->depth) * 3u) >> 1) << SORT_KEY_SHIFT;
        render_quad_half(f, &w, front0, base + ia, base + ib, base + ic, color, key);
        render_quad_half(f, &w, front1, base + ic, base + id, base + ia, color, key);
    }
    np = (uint32_t)(w.p - w.prim);
    f->prim_count = np;
    f->stats.faces_frustum += slow.n_frustum;
    f->stats.faces_back += w.n_back + slow.n_back;
    f->stats.faces_emitted += (np - np_start) - slow.np_general;  /* all but the general path's */
}

/*
 * One face of a lattice mesh in render_lattice_faces whose quad has all four corners on the screen
 * (outcode 0, or an object inside the frustum): `face` with corners a, b, c, frame vertices ia, ib,
 * ic (its v[0..2] plus the object's base: mesh_set_lattice checked that they are). What
 * render_faces does with such a face, filled, with its own material, flat with cached levels or
 * Gouraud (the cases render_lattice_faces_loop brings here): no outcode can cull or clip it, and its area
 * is the 32-bit one (proj_signed_area_inside: corners on the frame keep every difference below
 * 2^14, so it equals proj_signed_area); a lattice face is never MESH_FACE_QUAD, so its key is its
 * three depths' sum.
 */
static inline __attribute__((always_inline)) void
render_lattice_face(struct render_frame *f, const struct render_faces_job *job,
                    struct render_emit_walk *w, struct render_lattice_corner a,
                    struct render_lattice_corner b, struct render_lattice_corner c, uint32_t ia,
                    uint32_t ib, uint32_t ic, const struct mesh_face *face, bool shaded,
                    bool keyed)
{
    uint32_t level;
    uint32_t normal;

    if (render_corner_area(a, b, c) <= 0) {
        w->n_back++;
        return;
    }
    if (w->p >= w->p_end) {
        f->stats.dropped++;
        return;
    }
    if (FW_WITH_GOURAUD && shaded) {  /* the material's base colour: the GPU shades it */
        render_prim_put(w->p, ia, ib, ic, PAL_INDEX(face->material, 0u), GPU_PRIM_KIND_TRI_GOURAUD);
    } else {
        normal = face->normal;
        level = w->levels[normal];
        if (FW_UNLIKELY(level == RENDER_LEVEL_UNKNOWN)) {
            level = render_level_fill(w->levels, job->light, job->mesh, normal);
        }
        render_prim_put(w->p, ia, ib, ic, PAL_INDEX(face->material, level), GPU_PRIM_KIND_TRI);
    }
    /* The key: the depths' sum, <= 3 PROJ_DEPTH_MAX = 65535. */
    render_emit_next(w, keyed ? (sort_item_t)(a.depth + b.depth + c.depth) << SORT_KEY_SHIFT : 0u);
}

/*
 * The painter's order of a height field. Over a regular lattice (mesh.lattice_regular) a quad can
 * hide another from the eye only if it lies between them: the segment from the eye to a point
 * seen, projected onto the x-z plane, crosses the quads between the eye's column and row and the
 * point's, and no others, each no farther from the eye's quad in columns and in rows than the
 * next. So drawing the quads in order of their row's distance from the eye's row falling, and
 * within a row of their column's distance, draws whatever hides a quad after that quad: rows
 * before the eye's ascending, rows after it descending, the eye's row last, and the same for the
 * columns of each row. A quad's two halves need no order: front faces sharing an edge lie on
 * either side of it on the screen, and the GPU's fill rule gives each pixel of the edge to one of
 * them (contract: top-left). The walk is exact for any eye, inside the lattice or out, and needs
 * no depth key; render_sort then leaves the frame as it is (render_frame.painter_ordered).
 */

/* Draw order of the items [first, end) reversed. */
static void render_reverse_items(sort_item_t *first, sort_item_t *end)
{
    while (end - first > 1) {
        const sort_item_t x = *first;

        end--;
        *first = *end;
        *end = x;
        first++;
    }
}

/*
 * The face loop of a lattice mesh (mesh_set_lattice), quad by quad: a quad's corners come from its
 * place in the lattice (the next quad's are the next vertices) and are read once for both its
 * faces, so no face's vertex numbers are read or turned into addresses; material and normal still
 * come from the stored face. A quad with a corner off the screen (only where `check`, as in
 * render_faces: the object crosses the frustum) has both faces done by render_face_any. The same
 * primitives, with the same counts, as render_faces over the same faces: in the painter's walk
 * above where the frame keeps a painter's order and the lattice is regular, else in the faces'
 * order (and the frame is sorted).
 */
static void render_lattice_faces(struct render_frame *f, const struct render_faces_job *job_in,
                                 bool check)
{
    /* A copy in locals: stores to the frame cannot change it, so the loop keeps it in registers. */
    const struct render_faces_job job_copy = *job_in;
    const struct render_faces_job *const job = &job_copy;
    const struct mesh *mesh = job->mesh;
    const uint32_t w_verts = mesh->lattice_cols;  /* vertices per row */
    const uint32_t cols = w_verts - 1u;           /* quads per row */
    const uint32_t rows = mesh->face_count / (2u * cols);
    const uint32_t np_start = f->prim_count;
    uint32_t np;
    struct render_emit_walk w;
    struct render_face_counts slow = {0, 0, 0};  /* render_face_any's */
    /* Rows 0 .. split_r - 1 up, then rows - 1 down to split_r; in a row, quads 0 .. split_c - 1
     * up, then cols - 1 down to split_c (emitted up, then reversed): the walk far to near from
     * the eye's row and column, clamped to 0 .. rows and 0 .. cols. */
    uint32_t split_r = rows;
    uint32_t split_c = cols;
    /* Gouraud: each face its material's base colour (one test a face; a copy of the loop for
     * each case would not fit the landscape's program in the SoC's 192 KiB). */
    const bool shaded = FW_WITH_GOURAUD && job->vnormal14 != 0;
    bool keyed;  /* depth keys for the sort: not in the painter's walk */

    f->painter_ordered = f->painter_ordered && mesh->lattice_regular;
    keyed = !f->painter_ordered;
    if (f->painter_ordered) {
        const vec3 eye = xf_eye(job->mv);  /* model space */
        const vec3 *p = mesh->verts;
        split_r = render_walk_split(eye.z, p[0].z, real_sub(p[w_verts].z, p[0].z), rows);
        split_c = render_walk_split(eye.x, p[0].x, real_sub(p[1].x, p[0].x), cols);
    }
    w.prim = f->prim;
    w.p_end = f->prim + f->prim_cap;
    w.levels = job->levels;
    w.n_back = 0;
    render_emit_at(&w, f->sort_item, np_start);
    for (uint32_t k = 0; k < rows; k++) {
        const uint32_t r = render_walk_at(k, rows, split_r);

        /* Row r: corner a of its quad c at vertex (r, c), faces 2 (r cols + c) and the next. */
        const struct proj_vertex *v = &f->vert[job->base + r * w_verts];
        uint32_t ia = job->base + r * w_verts;
        const struct mesh_face *face = &mesh->faces[2u * r * cols];
        const struct mesh_face *const row_end = face + 2u * cols;
        const struct mesh_face *const split = face + 2u * split_c;  /* the first quad walked down */
        uint32_t bd = (r + mesh->lattice_diag) & 1u;  /* 1: this quad splits along b-d */
        sort_item_t *down_from = 0;  /* where the quads walked down start, once reached */

        for (; face != row_end; face += 2, v++, ia++, bd ^= 1u) {
            struct render_lattice_corner ka;
            struct render_lattice_corner kb;
            struct render_lattice_corner kc;
            struct render_lattice_corner kd;
            uint32_t ib;

            if (face == split) {
                down_from = w.item;
            }
            if (check && (v->code | v[w_verts].code | v[w_verts + 1u].code | v[1].code) != 0u) {
                /* All four corners beyond one plane: both faces frustum-culled, as
                 * render_faces would find each (most of a crossing tile's off-screen
                 * quads). */
                if ((v->code & v[w_verts].code & v[w_verts + 1u].code & v[1].code &
                     PROJ_CULL_BITS) != 0u) {
                    slow.n_frustum += 2u;
                    continue;
                }
                np = (uint32_t)(w.p - w.prim);
                np = render_face_any(f, job, true, &face[0], np, &slow);
                np = render_face_any(f, job, true, &face[1], np, &slow);
                render_emit_at(&w, f->sort_item, np);
                continue;
            }
            ka = render_lattice_corner(v);
            kb = render_lattice_corner(v + w_verts);
            kc = render_lattice_corner(v + w_verts + 1);
            kd = render_lattice_corner(v + 1);
            ib = ia + w_verts;
            if (bd != 0u) {  /* (a, b, d), (b, c', d) */
                render_lattice_face(f, job, &w, ka, kb, kd, ia, ib, ia + 1u, &face[0], shaded,
                                    keyed);
                render_lattice_face(f, job, &w, kb, kc, kd, ib, ib + 1u, ia + 1u, &face[1], shaded,
                                    keyed);
            } else {         /* (a, b, c'), (a, c', d) */
                render_lattice_face(f, job, &w, ka, kb, kc, ia, ib, ib + 1u, &face[0], shaded,
                                    keyed);
                render_lattice_face(f, job, &w, ka, kc, kd, ia, ib + 1u, ia + 1u, &face[1], shaded,
                                    keyed);
            }
        }
        if (down_from != 0) {
            render_reverse_items(down_from, w.item);  /* a quad's halves need no order */
        }
    }
    np = (uint32_t)(w.p - w.prim);
    f->prim_count = np;
    f->stats.faces_frustum += slow.n_frustum;
    f->stats.faces_back += w.n_back + slow.n_back;
    f->stats.faces_emitted += (np - np_start) - slow.np_general;  /* all but the general path's */
}

/* Every face of the mesh one by one, as render_faces treats it: the lattice and quad loops' other
 * cases (inlined in each: a program links one of the two, and a shared copy would cost the
 * landscape's image the call's bytes). A wireframe pass sends each face the frustum leaves to the
 * general path; anything else goes through render_face_any. */
static inline __attribute__((always_inline)) void
render_faces_one_by_one(struct render_frame *f, const struct render_faces_job *job, bool check)
{
    const uint32_t nf = job->mesh->face_count;
    const uint32_t np_start = f->prim_count;
    uint32_t np = np_start;
    struct render_face_counts n = {0, 0, 0};

    if (FW_WITH_WIREFRAME && job->pass->wireframe) {
        /* Every face the frustum leaves takes the general path, as in render_faces, which counts
         * the rest; straight there, not through render_face_any's tests (67 instructions a face
         * on the cubes). */
        const struct mesh_face *faces = job->mesh->faces;
        const struct proj_vertex *vert = &f->vert[job->base];

        for (uint32_t fi = 0; fi < nf; fi++) {
            const struct mesh_face *face = &faces[fi];

            if (check && (vert[face->v[0]].code & vert[face->v[1]].code & vert[face->v[2]].code &
                          PROJ_CULL_BITS) != 0u) {
                n.n_frustum++;
                continue;
            }
            render_face_general(f, job->pass, job->mv, job->mesh, face, job->base, job->light,
                                job->material_override, job->vnormal14);
        }
        f->stats.faces_frustum += n.n_frustum;
        return;
    }
    for (uint32_t fi = 0; fi < nf; fi++) {
        np = render_face_any(f, job, check, &job->mesh->faces[fi], np, &n);
    }
    f->prim_count = np;
    f->stats.faces_frustum += n.n_frustum;
    f->stats.faces_back += n.n_back;
    f->stats.faces_emitted += (np - np_start) - n.np_general;
}

void render_lattice_faces_loop(struct render_frame *f, const struct render_faces_job *job,
                               bool inside)
{
    /* The lattice loop is the filled pass of a lattice mesh with its own materials and a level
     * cache, flat or Gouraud; anything else (wireframe, anaglyph's eye material, another mesh)
     * goes face by face (render_faces_one_by_one). */
    if (job->mesh->lattice_cols == 0u || job->levels == 0 || job->material_override != 0u ||
        (FW_WITH_WIREFRAME && job->pass->wireframe)) {
        f->painter_ordered = false;  /* faces in their stored order */
        render_faces_one_by_one(f, job, !inside);
    } else {
        render_lattice_faces(f, job, !inside);
    }
}

/* The front faces of a convex mesh (a box: mesh.box) never cover one another, so filled, in any
 * order, they keep the frame's painter's order (render_frame.painter_ordered); any other mesh's
 * faces, in the order stored, need the sort. */
static inline void render_order_by_convexity(struct render_frame *f,
                                             const struct render_faces_job *job)
{
    f->painter_ordered = f->painter_ordered && job->mesh->box &&
                         !(FW_WITH_WIREFRAME && job->pass->wireframe);
}

void render_general_faces_loop(struct render_frame *f, const struct render_faces_job *job_in,
                               bool inside)
{
    /* A copy in locals: stores to the frame cannot change it, so the loops keep it in registers.
     * Four specialisations of the loop, so that neither test costs a face anything. */
    const struct render_faces_job job = *job_in;

    render_order_by_convexity(f, &job);
    if (inside) {
        if (job.levels != 0) {
            render_faces(f, &job, false, true);
        } else {
            render_faces(f, &job, false, false);
        }
    } else {
        if (job.levels != 0) {
            render_faces(f, &job, true, true);
        } else {
            render_faces(f, &job, true, false);
        }
    }
}

void render_quad_faces_loop(struct render_frame *f, const struct render_faces_job *job, bool inside)
{
    /* The quad loop is the filled, flat pass of a quad mesh; anything else (wireframe, Gouraud, a
     * mesh that is not marked) goes face by face (render_faces_one_by_one). */
    render_order_by_convexity(f, job);
    if (!job->mesh->quads || (FW_WITH_WIREFRAME && job->pass->wireframe) ||
        (FW_WITH_GOURAUD && job->vnormal14 != 0)) {
        render_faces_one_by_one(f, job, !inside);
    } else {
        render_quad_faces(f, job, !inside);
    }
}

void render_grid_faces_loop(struct render_frame *f, const struct render_faces_job *job, bool inside)
{
    f->painter_ordered = false;  /* a grid mesh's faces in their stored order */
    if (inside) {
        render_grid_faces(f, job, false);
    } else {
        render_grid_faces(f, job, true);
    }
}

void render_object(struct render_frame *f, const struct render_pass *pass,
                   const struct render_object *obj)
{
    const struct mesh *mesh = obj->mesh;
    const uint32_t nv = mesh->vert_count;
    const uint32_t nf = mesh->face_count;
    struct palette_light light;
    struct render_faces_job job;
    enum render_sphere_class where;
    uvec3 light_model;
    xf_affine mv;

    f->stats.faces_in += nf;
    f->stats.objects_in++;
    if (FW_WITH_WIREFRAME && pass->wireframe && f->edge_used > f->edge_cap / 2u &&
        f->edge_used <= f->edge_cap) {
        render_edge_set_clear(f);  /* no edge is shared between objects (render_edge_first) */
    }

    /* Model -> view: r = (V O) R, t = (V O)(pos - focus) + V (focus - eye). pos and focus are
     * world points (within +-1024 per axis, real.h; scene_add_object enforces it for pos, and the
     * focus is a scene's constant, the origin or the voxel world's centre), so pos - focus is
     * exact and within xf_apply's |p| < 8192, and
     * V (focus - eye) within its |t| < 4096: the object's offset gets the vertices' arithmetic. */
    mv.r = mat3_compose(&pass->focus_to_view.r, &obj->rot);
    mv.t = xf_apply(&pass->focus_to_view, vec3_make(obj->pos.x - pass->focus.x,
                                                    obj->pos.y - pass->focus.y,
                                                    obj->pos.z - pass->focus.z));
    /* The sphere's centre in view space; a mesh centred on its own origin (the cubes') has it at
     * mv.t, which is what xf_apply gives for the origin (every product of a zero coordinate is 0). */
    where = render_sphere_classify(&pass->proj,
                                   (mesh->center.x == 0 && mesh->center.y == 0 &&
                                    mesh->center.z == 0) ? mv.t : xf_apply(&mv, mesh->center),
                                   mesh->radius);
    if (where == RENDER_SPHERE_OUTSIDE) {
        f->stats.objects_culled++;
        f->stats.faces_culled_object += nf;
        return;
    }
    if (f->vert_count + nv > f->vert_cap || obj->faces == 0) {
        f->stats.dropped++;  /* (an object without a face loop: render_object.faces) */
        return;
    }
    job.base = f->vert_count;
    if (obj->project != 0) {
        obj->project(&pass->proj, &mv, mesh, &f->vert[job.base], where == RENDER_SPHERE_INSIDE);
    } else {
        render_project_vertices(&pass->proj, &mv, mesh->verts, nv, &f->vert[job.base],
                                where == RENDER_SPHERE_INSIDE);
    }
    f->vert_count += nv;

    /* The light in model space: (O R)^T l = R^T (O^T l). */
    light_model = render_light_model(&obj->rot, pass->light_scene);
    palette_light_init(&light, light_model, pass->ambient);
    job.levels = render_level_cache_for(obj->levels, mesh, light_model, pass->ambient);
    job.pass = pass;
    job.mv = &mv;
    job.mesh = mesh;
    job.light = &light;
    job.material_override = render_material_override(pass, obj);
    job.vnormal14 = (FW_WITH_GOURAUD && pass->gouraud && !(FW_WITH_WIREFRAME && pass->wireframe))
                        ? obj->vnormal14 : 0;
    /* The face loop its mesh needs: render_general_faces_loop or render_grid_faces_loop. */
    obj->faces(f, &job, where == RENDER_SPHERE_INSIDE);
#if FW_WITH_GOURAUD
    /* Every face has its sort key: the object's vertices' depth half-words become their
     * intensities (VTX_I), which only its Gouraud triangles read. */
    if (job.vnormal14 != 0) {
        struct proj_vertex *v = &f->vert[job.base];

        for (uint32_t i = 0; i < nv; i++) {
            v[i].depth = (uint16_t)palette_light_intensity(&light, mesh_q14_normal(obj->vnormal14, i));
        }
    }
#endif
}

void render_sort(struct render_frame *f)
{
    if (!f->painter_ordered) {
        sort_items(f->sort_item, f->sort_tmp, f->prim_count, f->sort);
    }
    f->sorted_count = f->prim_count;
}

void render_overlay_crosshair(struct render_frame *f, const struct render_pass *pass,
                              int32_t half_px, uint8_t color)
{
    const int32_t cx = pass->proj.cx_q4;
    const int32_t cy = pass->proj.cy_q4;
    const int32_t h = half_px * 16;
    /* Line endpoints are the pixels holding the vertices, the last one not drawn: one pixel past
     * the arm's end so the cross is symmetric about the centre pixel. */
    const int32_t l = render_add_screen_vertex(f, cx - h, cy + 8, 0);
    const int32_t r = render_add_screen_vertex(f, cx + h + 16, cy + 8, 0);
    const int32_t t = render_add_screen_vertex(f, cx + 8, cy - h, 0);
    const int32_t b = render_add_screen_vertex(f, cx + 8, cy + h + 16, 0);

    if (l < 0 || r < 0 || t < 0 || b < 0) {
        return;
    }
    render_emit_line(f, pass, (uint32_t)l, (uint32_t)r, color, 0);
    render_emit_line(f, pass, (uint32_t)t, (uint32_t)b, color, 0);
}
