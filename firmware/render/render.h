/*
 * render.h — one frame's geometry: objects in, sorted screen-space primitives out. Pure code.
 *
 * Per object (render_object):
 *   1. model -> view in one affine transform, composed once per object: the object's rotation and
 *      position in the scene, the scene's rotation about its focus (object mode), the camera.
 *   2. frustum culling of the whole object by its bounding sphere (near, far, four screen edges);
 *      an object entirely inside skips every per-vertex and per-face frustum test below.
 *   3. every vertex: xf_apply, proj_point -> Q12.4 position, depths, outcode.
 *   4. every face: culled when its three outcodes share a bit (frustum, per triangle); sent to
 *      clip.c when a vertex is in front of the near plane or beyond the guard band; else culled
 *      when its signed area is <= 0 (back face or degenerate); else lit, keyed and emitted.
 * Then render_sort orders the primitives far to near (sort.h), and overlay primitives (the
 * crosshair) are appended unsorted, drawn last.
 *
 * Emission: a triangle, or in wireframe its outline. With GPU lines (CAPS_LINES) the outline is
 * one frame primitive per triangle, kind RENDER_PRIM_OUTLINE with a mask of the edges to draw
 * (a clipped polygon's fan leaves its inner diagonals out), which batch.c expands into one GPU
 * LINE primitive per edge: a wireframe pass needs exactly the frame a filled pass needs. Without
 * GPU lines, in a build with FW_WITH_LINE_EMULATION, each edge becomes a one-pixel-wide quad of
 * two triangles on four new vertices, so the toggle degrades instead of failing (a build without
 * it refuses the wireframe on such a GPU: app.c).
 *
 * Colour: flat lighting per face (palette.h), the light taken into model space once per object.
 * In anaglyph mode the face's material is replaced by the eye's red or cyan ramp.
 * Gouraud (FW_WITH_GOURAUD, pass.gouraud, a mesh with vertex normals, filled faces): every vertex
 * gets its light as a Q4.12 intensity (palette_light_intensity of its averaged normal) and each
 * face becomes a GPU_PRIM_KIND_TRI_GOURAUD primitive coloured with its material's ramp base
 * (shade 0): the GPU interpolates the intensity and adds the level. The intensity travels in the
 * frame vertex's `depth` half-word, written once the object's faces have their sort keys (the
 * only reader of `depth`), so a frame vertex stays 12 bytes; a clipped face's new vertices get
 * theirs through clip.c, interpolated like their positions.
 *
 * All state lives in the caller's render_frame; nothing is global.
 */
#ifndef RENDER_H
#define RENDER_H

#include <stdbool.h>
#include <stdint.h>

#include "camera/camera.h"
#include "config/build_options.h"
#include "config/hot_path.h"
#include "render/mesh.h"
#include "render/proj.h"
#include "render/sort.h"
#include "math/vec.h"

/* A frame's capacities are the program's (render_frame_init): each scene states what it needs in
 * scenes/scene_list.h and the program sizes its frame for the largest of the scenes it is built
 * with (scenes/scene_set.h). The index formats bound them: vertex numbers are render_index values
 * (render_prim), primitive numbers the payload of a sort item (sort.h) — 16 bits (65,535 of each:
 * the largest value is RENDER_NO_POSITION), or 32 in a build with wide frame indices
 * (config/build_options.h: FW_RENDER_WIDE_INDEX, where the model scene's capacities need more
 * than 65,535), whose limit 2^24 keeps every count and sum of them far from
 * overflowing 32 bits. Anything beyond a capacity is not drawn and is counted in stats.dropped,
 * which the frame loop reports. */
#if FW_RENDER_WIDE_INDEX
typedef uint32_t render_index;
#define RENDER_INDEX_LIMIT 16777216u
#else
typedef uint16_t render_index;
#define RENDER_INDEX_LIMIT 65535u
#endif
/* No draw position: a list of positions linked through sort_tmp ends with it (render/strips.h,
 * gpu/batch.h). A frame's positions are below RENDER_INDEX_LIMIT <= it. */
#define RENDER_NO_POSITION SORT_PAYLOAD_MASK

struct render_prim {
#if FW_RENDER_WIDE_INDEX
    /* Wide: the fields alone (16 bytes); batch.c packs the GPU's words from them. */
    render_index v[3];
    uint8_t color;
    uint8_t kind;
#else
    union {
        struct {
            render_index v[3];  /* indices into render_frame.vert; v[2] repeats v[1] for a line */
            uint8_t color;      /* palette index */
            uint8_t kind;       /* GPU_PRIM_KIND_TRI, GPU_PRIM_KIND_LINE, or RENDER_PRIM_OUTLINE | edges */
        };
        /* The same 8 bytes as two words: on a little-endian CPU they are the contract's primitive
         * words with frame vertex numbers in place of batch ones (batch.c uses that). */
        uint32_t w[2];
    };
#endif
};

/* A frame primitive that is not a GPU one: the outline of triangle v[0] v[1] v[2], edge k (from
 * v[k] to v[(k + 1) % 3]) drawn when bit k of the kind is set, as a GPU LINE primitive (v[k],
 * v[k+1], v[k+1]) — batch.c expands it, edges in the order 0, 1, 2. The GPU's kinds are 0 and 1, so
 * bit 7 cannot be mistaken for one. */
#define RENDER_PRIM_OUTLINE 0x80u
#define RENDER_PRIM_OUTLINE_EDGES 0x07u

struct render_stats {
    uint32_t faces_in;            /* faces of every object offered: "triangles submitted" */
    uint32_t objects_in;
    uint32_t objects_culled;      /* bounding sphere outside the frustum */
    uint32_t faces_culled_object; /* faces of those objects */
    uint32_t faces_frustum;       /* one outcode bit shared by all three vertices */
    uint32_t faces_back;          /* back-facing or zero area */
    uint32_t faces_clipped;       /* went through clip.c */
    uint32_t faces_clipped_away;  /* ... and nothing was left */
    uint32_t faces_emitted;       /* faces that produced primitives */
    uint32_t dropped;             /* primitives or vertices that found no room (capacity) */
};

struct render_frame {
    struct proj_vertex *vert;  /* vert_cap entries */
    struct render_prim *prim;  /* prim_cap entries */
    /* (draw key << SORT_KEY_SHIFT) | primitive index, one per primitive, in emission order; after
     * render_sort, the first sorted_count in draw order. Primitives emitted after the sort (the
     * overlay) keep items naming themselves, so sort_item[i]'s index is the i-th primitive to
     * draw for every i. The draw key is 65535 minus the depth key: ascending = far to near. */
    sort_item_t *sort_item;    /* prim_cap entries */
    sort_item_t *sort_tmp;     /* prim_cap entries */
    struct sort_scratch *sort; /* NULL when prim_cap < SORT_SMALL_N (the sort never needs it) */
    uint32_t vert_cap;
    uint32_t prim_cap;
    uint32_t vert_count;
    uint32_t prim_count;
    uint32_t sorted_count;  /* primitives covered by render_sort; later ones are overlay */
    uint32_t outline_count; /* RENDER_PRIM_OUTLINE primitives among them (batch.c expands them) */
    /* The primitives so far are already far to near, so render_sort leaves them in emission order:
     * set by a scene that draws its objects in a painter's order (scene_set_grid), kept by the
     * face loops that keep one within an object (a convex mesh's, a regular lattice's walk) and
     * cleared by every other; false from render_frame_begin. */
    bool painter_ordered;
    uint8_t batch_stamp;    /* batch.c: stamp of the last batch filled from these vertices */
    /* A wireframe pass draws an edge two front faces share once (render.c): the edges drawn so
     * far, as (lower vertex << SORT_KEY_SHIFT | higher vertex) keys (0 = empty slot), open
     * addressing in edge_cap items (a power of two; 0: no such set, every edge drawn). The storage
     * is sort_tmp, which nothing uses before render_sort. */
    sort_item_t *edge_set;
    uint32_t edge_cap;
    uint32_t edge_used;     /* keys in the set; edge_cap + 1: not cleared since render_frame_begin */
    struct render_stats stats;
};

/* What stays the same for every object of one pass (a frame, or one eye of a stereo frame). */
struct render_pass {
    struct proj_setup proj;
    /* Scene -> view for points given relative to the focus: r = V O (the camera's rotation times
     * the scene's rotation about its focus), t = V (focus - eye). */
    xf_affine focus_to_view;
    vec3 focus;           /* the scene's focus (world) */
    uvec3 light_scene;    /* unit vector towards the light, in the rotated scene's frame: O^T l */
    uint8_t ambient;      /* light level of unlit faces, 0 .. 15 */
    uint8_t eye_material; /* 0, or MAT_ANAGLYPH_LEFT / _RIGHT: every face uses that ramp */
    bool wireframe;
    bool gpu_lines;       /* the GPU draws line primitives (CAPS_LINES) */
    bool gouraud;         /* meshes with vertex normals are Gouraud shaded (CAPS_GOURAUD) */
};

/*
 * Light levels of a static mesh's normals, kept across frames (owned by the scene, next to the
 * mesh). A face's level depends only on its normal, the light in model space and the ambient level
 * (palette.h), so while those are unchanged the level computed in an earlier frame is exactly the
 * one this frame would compute. Filled lazily (only front faces ever need a level); emptied when
 * the model-space light or the ambient level changes. The mesh's normals must not change while a
 * cache is attached (the landscape's never do; meshes rebuilt at run time do not use one).
 */
#define RENDER_LEVEL_UNKNOWN 0xFFu  /* an entry not computed yet (levels are 0 .. 15) */

struct render_level_cache {
    uint8_t *level;       /* cap entries, one per normal: a level, or RENDER_LEVEL_UNKNOWN */
    uint32_t cap;         /* used only if >= the mesh's normal_count */
    bool valid;           /* light and ambient below are what the entries were computed for */
    uvec3 light;          /* unit vector towards the light, model space */
    uint32_t ambient;
};

/* Attach storage (cap entries) to an empty cache. */
void render_level_cache_init(struct render_level_cache *c, uint8_t *storage, uint32_t cap);

struct render_object;

/* Fill an object's cache for every normal, as render_object would for this light (world space),
 * scene rotation and ambient level: static lighting computed when a scene is built rather than
 * in its first frame. Exact: the same levels the lazy fill computes. No-op without a cache. */
void render_level_cache_fill(const struct render_object *obj, const mat3 *scene_rot, uvec3 light,
                             uint32_t ambient);

/* One instance of a mesh in the scene: p_scene = rot p_model + pos. */
/* What an object's face loop is given (render.c's), and such a loop: inside says the object's
 * bounding sphere is inside the frustum (no face to cull by outcodes or to clip). */
struct render_faces_job;
typedef void (*render_faces_fn)(struct render_frame *f, const struct render_faces_job *job,
                                bool inside);
/* A projection of an object's vertices into the frame's (render_object.project). */
typedef void (*render_project_fn)(const struct proj_setup *ps, const xf_affine *mv,
                                  const struct mesh *mesh, struct proj_vertex *out, bool inside);

struct render_object {
    const struct mesh *mesh;
    mat3 rot;
    vec3 pos;
    uint8_t material;     /* 0: each face's own material; else this one for every face */
    struct render_level_cache *levels;  /* 0, or the cache of a static mesh's light levels */
    /* 0, or the mesh's per-vertex unit normals (3 Q1.14 values a vertex, mesh_q14_normal): the
     * object asks to be Gouraud shaded (where pass.gouraud; flat otherwise, and in wireframe). */
    const int16_t *vnormal14;
    /* The loop its mesh's faces need: render_general_faces_loop, or a grid mesh's (mesh_set_grid)
     * render_grid_faces_loop. The scene names it (scene_add_object, scene_add_grid_object), so
     * that a program links only the loops its scenes use (3 KiB each: a one-scene build must fit
     * the SoC's RAM). An object without one (0) is not drawn, and counts in stats.dropped. */
    render_faces_fn faces;
    /* 0: every vertex through the model-view transform; render_project_boxed (scene_add_object's)
     * takes a box mesh's eight corners the cheaper way (xf_apply_box: the same view points), so
     * that only a program whose scenes may hold boxes links that code. */
    render_project_fn project;
};

/* For render_object.project: a box mesh (mesh.box) by its corners, any other by its vertices. */
void render_project_boxed(const struct proj_setup *ps, const xf_affine *mv, const struct mesh *mesh,
                          struct proj_vertex *out, bool inside);

/* For render_object.project: a lattice mesh (mesh_set_lattice) inside the frustum whose vertices
 * lie on its rows' and columns' axes (mesh.lattice_axes) with three products a vertex, any other
 * vertex by vertex: the same projected vertices either way. */
void render_project_lattice(const struct proj_setup *ps, const xf_affine *mv,
                            const struct mesh *mesh, struct proj_vertex *out, bool inside);

/* The face loops, for render_object.faces: a mesh with a faces array (mesh.h), and a grid mesh
 * (implicit faces). */
void render_general_faces_loop(struct render_frame *f, const struct render_faces_job *job,
                               bool inside);
void render_grid_faces_loop(struct render_frame *f, const struct render_faces_job *job,
                            bool inside);
/* A quad mesh's (mesh_set_quads): the general loop's primitives, each quad's corners, key and
 * colour read once for both halves, filled and flat; anything else (wireframe, Gouraud, a mesh not
 * marked) goes face by face through one copy of the general loop's code. */
void render_quad_faces_loop(struct render_frame *f, const struct render_faces_job *job,
                            bool inside);
/* A lattice mesh's (mesh_set_lattice; with a level cache, render_object.levels): the general loop's
 * primitives, its faces' corners walked instead of read, flat or Gouraud. Anything else (another
 * mesh, wireframe, an eye material) goes face by face through one copy of the general loop's code. */
void render_lattice_faces_loop(struct render_frame *f, const struct render_faces_job *job,
                               bool inside);

/* Compose a pass. light: unit vector towards the light in world space. */
void render_pass_init(struct render_pass *pass, const struct proj_setup *ps,
                      const struct cam_view *view, const mat3 *scene_rot, vec3 focus,
                      uvec3 light, uint32_t ambient);

/* Attach storage to a frame and empty it: vert_cap vertices, prim_cap primitives (each at most
 * RENDER_INDEX_LIMIT; larger capacities are cut to it), sort_item and sort_tmp prim_cap items each,
 * scratch the sort's (may be NULL only when prim_cap < SORT_SMALL_N). RENDER_FRAME_STORAGE defines
 * such storage statically and RENDER_FRAME_ATTACH attaches it. */
void render_frame_init(struct render_frame *f, struct proj_vertex *vert, uint32_t vert_cap,
                       struct render_prim *prim, sort_item_t *sort_item, sort_item_t *sort_tmp,
                       uint32_t prim_cap, struct sort_scratch *scratch);

#define RENDER_FRAME_STORAGE(id, nv, np) \
    _Static_assert((nv) >= 1u && (nv) <= RENDER_INDEX_LIMIT && (np) >= 1u && \
                       (np) <= RENDER_INDEX_LIMIT, \
                   "frame capacities must be 1 .. RENDER_INDEX_LIMIT"); \
    static struct proj_vertex id##_vert[nv]; \
    static struct render_prim id##_prim[np]; \
    static sort_item_t id##_sort_item[np]; \
    static sort_item_t id##_sort_tmp[np]; \
    static FW_FAST_DATA struct sort_scratch id##_sort_scratch[((np) >= SORT_SMALL_N) ? 1 : 0]
#define RENDER_FRAME_ATTACH(f, id) \
    render_frame_init((f), id##_vert, (uint32_t)(sizeof id##_vert / sizeof id##_vert[0]), \
                      id##_prim, id##_sort_item, id##_sort_tmp, \
                      (uint32_t)(sizeof id##_prim / sizeof id##_prim[0]), \
                      (sizeof id##_sort_scratch != 0u) ? id##_sort_scratch : (void *)0)

/* Empty the frame's vertices and primitives (statistics are kept: render_stats_clear). */
void render_frame_begin(struct render_frame *f);
void render_stats_clear(struct render_stats *s);

/* Transform, cull, clip, light and emit one object. */
void render_object(struct render_frame *f, const struct render_pass *pass,
                   const struct render_object *obj);

/* Where a sphere (view-space centre, radius) lies against near, far and the four planes through
 * the eye and the screen edges. */
enum render_sphere_class {
    RENDER_SPHERE_OUTSIDE = 0,   /* entirely beyond one plane: cull the object */
    RENDER_SPHERE_CROSSING = 1,  /* partly inside: test every vertex and face */
    RENDER_SPHERE_INSIDE = 2,    /* entirely inside: no vertex needs an outcode or clipping */
};
enum render_sphere_class render_sphere_classify(const struct proj_setup *ps, vec3 center_view,
                                                real_t radius);

/* At least partly inside? */
static inline bool render_sphere_visible(const struct proj_setup *ps, vec3 center_view,
                                         real_t radius)
{
    return render_sphere_classify(ps, center_view, radius) != RENDER_SPHERE_OUTSIDE;
}

/* Order the primitives emitted so far from far to near. */
/* The painter's walks far to near (render.c's over a regular lattice's rows and quads, scene.c's
 * over a grid's cells, each axis on its own): over 0 .. n-1 from `split`, the cells wholly before
 * the eye (render_walk_split), place k holds cell k for k < split, then n-1 down to split. */
static inline uint32_t render_walk_at(uint32_t k, uint32_t n, uint32_t split)
{
    return (k < split) ? k : n - 1u + split - k;
}

/* The cells of size step (> 0) from origin wholly before an eye at `eye`: floor((eye - origin) /
 * step), clamped to 0 .. n (an eye outside the cells orders them as one just outside would). */
static inline uint32_t render_walk_split(real_t eye, real_t origin, real_t step, uint32_t n)
{
    const real_t d = real_sub(eye, origin);
#if REAL_IS_FIXED
    /* The raw quotient of two q16_16 values, truncated, then floored (step > 0). */
    int32_t q = d / step;

    q = (q * step > d) ? q - 1 : q;
#else
    const int32_t q = real_floor_int(d / step);
#endif
    return (q < 0) ? 0u : (((uint32_t)q > n) ? n : (uint32_t)q);
}

void render_sort(struct render_frame *f);

/* Append a crosshair at the screen centre (arms of half_px pixels), drawn after everything. */
void render_overlay_crosshair(struct render_frame *f, const struct render_pass *pass,
                              int32_t half_px, uint8_t color);

/* Index of the i-th primitive to draw (sorted ones, then the overlay; see sort_item). */
static inline uint32_t render_draw_index(const struct render_frame *f, uint32_t i)
{
    return sort_item_payload(f->sort_item[i]);
}

/* The depth key of primitive i (larger = farther), as emitted. Before render_sort only. */
static inline uint16_t render_depth_key(const struct render_frame *f, uint32_t i)
{
    return (uint16_t)(0xFFFFu - sort_item_key(f->sort_item[i]));
}

#endif /* RENDER_H */
