/*
 * scene.h — what the frame loop asks of a scene, and what scene files share. Pure code.
 *
 * The scenes are the lines of scenes/scene_list.h, each in its own file or folder:
 *   tetra      the walking skeleton's tetrahedron, spinning (object mode)
 *   cubes      64 coloured cubes, each turning on its own (orbit mode)
 *   landscape  a lit low-poly height field, 2048 triangles in 16 tiles (fly mode)
 *   voxel      a 16 x 16 x 16 block world with place/break under the crosshair (fly mode)
 *   knot       a (2, 3) torus knot of exactly 5000 triangles, the large-model benchmark (object mode)
 *   model      a model from a file: built in (MODEL=, tools/meshconv) or uploaded over the UART
 *              (object mode)
 *
 * A scene owns its meshes (built once by init into its own state, SCENE_STATE below), its
 * camera and its objects. The frame loop calls scene_update once per frame with the keys, then
 * scene_draw once per pass (twice for anaglyph stereo). Object mode turns the whole scene about
 * cam.cfg.focus (render.h composes it into every object's transform).
 */
#ifndef SCENE_H
#define SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "config/build_options.h"
#include "camera/camera.h"
#include "input/input.h"
#include "render/mesh.h"
#include "render/render.h"
#include "math/vec.h"
#include "scenes/model/model.h"  /* the model line's columns (scene_list.h) */

/* ---- the scene table ----------------------------------------------------------------------- */

/* SCENE_INDEX_<name>, in the order of scene_list.h; SCENE_COUNT scenes (the whole table: a program
 * may be built with fewer, scene_count()). */
enum scene_index {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) SCENE_INDEX_##name,
#include "scenes/scene_list.h"
#undef SCENE
    SCENE_COUNT
};

/* What each scene needs (scene_list.h's columns): SCENE_STATE_BYTES_<name>,
 * SCENE_MAX_OBJECTS_<name>, and the frame a pass needs in this build, SCENE_MAX_VERTS_<name> and
 * SCENE_MAX_PRIMS_<name>: the (emulated) wireframe columns where the build has wireframe and line
 * emulation (FW_WITH_WIREFRAME, FW_WITH_LINE_EMULATION), else the filled ones; SCENE_FILLED_VERTS/PRIMS_<name> and SCENE_WIRE_VERTS/PRIMS_<name> are the
 * columns themselves. */
enum scene_needs {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) \
    SCENE_STATE_BYTES_##name = (state), SCENE_MAX_OBJECTS_##name = (objects), \
    SCENE_FILLED_VERTS_##name = (verts), SCENE_FILLED_PRIMS_##name = (prims), \
    SCENE_WIRE_VERTS_##name = (wverts), SCENE_WIRE_PRIMS_##name = (wprims), \
    SCENE_MAX_VERTS_##name = FW_FRAME_WIRE_COLUMNS ? (wverts) : (verts), \
    SCENE_MAX_PRIMS_##name = FW_FRAME_WIRE_COLUMNS ? (wprims) : (prims),
#include "scenes/scene_list.h"
#undef SCENE
    SCENE_NEEDS_END
};

/* Each scene's descriptor, defined in its own file (scenes/<name>.c or scenes/<name>/). */
#define SCENE(name, state, objects, verts, prims, wverts, wprims) extern const struct scene_desc scene_##name##_desc;
struct scene_desc;
#include "scenes/scene_list.h"
#undef SCENE

/* The scenes this program is built with, in table order (keys 1..scene_count()): defined by the
 * one file of the program that includes scenes/scene_set.h. */
extern const struct scene_desc *const scene_built[];
extern const uint32_t scene_built_count;

/* ---- a scene's private state --------------------------------------------------------------- */

/* Each scene declares its state (meshes, animation, ...) as a struct of its own file and keeps it
 * in the storage struct scene points to, which holds one scene at a time (the scenes share the
 * memory, which matters on a chip): SCENE_STATE(s, struct tetra_state) is that scene's view of it.
 * SCENE_STATE_FITS(tetra, struct tetra_state) in the scene's file makes a state larger than its
 * scene_list.h column a compile error; the program's storage is the largest column of the scenes
 * it is built with (scene_set.h), and scene_start refuses a scene whose state or objects do not
 * fit the storage it is given. */
#define SCENE_STATE(s, type) ((type *)(void *)(s)->state)
#define SCENE_STATE_FITS(name, type) \
    _Static_assert(sizeof(type) <= (size_t)SCENE_STATE_BYTES_##name, \
                   #type " does not fit its state column of scenes/scene_list.h: raise it")
/* A descriptor's name and capacities from the scene's scene_list.h line, and its .state_bytes, the
 * sizeof its state struct: SCENE_DESC_NEEDS(tetra, struct tetra_state). */
#define SCENE_DESC_NEEDS(scene, state_type) \
    .name = #scene, .state_bytes = sizeof(state_type), \
    .max_objects = SCENE_MAX_OBJECTS_##scene, .max_verts = SCENE_MAX_VERTS_##scene, \
    .max_prims = SCENE_MAX_PRIMS_##scene, .filled_verts = SCENE_FILLED_VERTS_##scene, \
    .filled_prims = SCENE_FILLED_PRIMS_##scene, .wire_verts = SCENE_WIRE_VERTS_##scene, \
    .wire_prims = SCENE_WIRE_PRIMS_##scene

/* ---- the running scene -------------------------------------------------------------------- */

/* Something the scene did that the frame loop may want to report. */
enum scene_event_kind {
    SCENE_EVENT_NONE = 0,
    SCENE_EVENT_BROKE,    /* a block was removed at x, y, z */
    SCENE_EVENT_PLACED,   /* a block of type `block` was placed at x, y, z */
    SCENE_EVENT_NO_TARGET,/* place/break with nothing under the crosshair */
    SCENE_EVENT_BLOCK_TYPE,
    SCENE_EVENT_MESH_FULL,/* a rebuilt mesh found no room: x chunks not drawn (storage: y faces,
                           * z vertices) — an error line */
};

struct scene_event {
    enum scene_event_kind kind;
    int32_t x, y, z;
    const char *block_name;  /* PLACED, BLOCK_TYPE: the block type's name */
};

struct scene_desc;

/* Objects in the cells of a grid (scene_set_grid): its layout, constant in a scene's code. */
struct scene_grid_layout {
    real_t origin[3];  /* the corner of cell (0, 0, 0) */
    real_t cell[3];    /* each axis's cell size; 0: an axis not divided (count 1) */
    uint8_t count[3];  /* cells per axis, x, y, z */
};

struct scene {
    const struct scene_desc *desc;
    struct camera cam;
    struct cam_config cam_default;   /* for reset */
    enum cam_mode mode_default;
    vec3 target_default;
    real_t distance_default;
    fx_angle yaw_default;
    int32_t pitch_default;
    int32_t focal_px;     /* projection: focal length in pixels of a 240-line frame (proj.h) */
    real_t far;           /* projection: far distance */
    uvec3 light;          /* unit vector towards the light, world space */
    uint8_t ambient;      /* 0 .. 15 */
    real_t eye_separation;  /* anaglyph: distance between the two eyes */
    bool crosshair;
    bool animate;
    uint32_t frame;       /* frames updated since the scene started */
    /* The program's storage (scene_set.h: scene_set_attach), kept by scene_start: */
    struct render_object *object;  /* object_cap entries */
    uint32_t object_cap;
    uint32_t object_count;
    uint32_t objects_refused;      /* scene_add_object calls beyond object_cap */
    unsigned char *state;          /* state_cap bytes, 8-aligned: the scene's own, SCENE_STATE */
    size_t state_cap;
    uint32_t frame_width;          /* the GPU's frame (scene_set_frame; the contract's default */
    uint32_t frame_height;         /* frame until then) */
    struct proj_setup proj;  /* the projection of focal_px and far, set by scene_start */
    /* scene_set_grid's layout (the scene's own constant), or NULL: no grid (scene_start's) */
    const struct scene_grid_layout *grid;
};

struct scene_desc {
    const char *name;
    const char *keys;   /* scene-specific keys for the key map, or NULL */
    /* What it needs (SCENE_DESC_NEEDS: its scene_list.h line): */
    size_t state_bytes;   /* sizeof its state struct (<= its column: SCENE_STATE_FITS) */
    uint32_t max_objects; /* objects its init adds */
    uint32_t max_verts;   /* frame vertices and primitives a pass can need in this build */
    uint32_t max_prims;
    uint32_t filled_verts;  /* ... a filled pass (scene_list.h's columns) */
    uint32_t filled_prims;
    uint32_t wire_verts;    /* ... a wireframe pass */
    uint32_t wire_prims;
    void (*init)(struct scene *s);
    /* Animation and scene keys, once per frame (camera keys are already applied). */
    void (*update)(struct scene *s, const struct input_counts *keys, struct scene_event *ev);
};

/* Among the scenes this program is built with: by name (NULL if unknown or not built in), by number
 * 0 .. scene_count()-1 (NULL beyond), and how many. */
const struct scene_desc *scene_find(const char *name);
const struct scene_desc *scene_at(uint32_t index);
uint32_t scene_count(void);

/* Give a scene its storage (kept across scene_start): objects and state bytes (8-aligned). */
void scene_attach(struct scene *s, struct render_object *objects, uint32_t object_cap,
                  unsigned char *state, size_t state_cap);

/* The frame the scene is drawn into (the GPU's FB_SIZE, within the contract's largest frame), kept
 * across scene_start like the storage; it takes effect at the next scene_start. */
void scene_set_frame(struct scene *s, uint32_t width, uint32_t height);

/* Build the scene's meshes and set its camera; every field of *s but its storage is
 * (re)initialised. Returns false when the scene needs more state or objects than s's storage
 * holds (a program built without room for it: *s is left as it was), or when its init added more
 * objects than its max_objects column or the storage took (s->desc is then NULL). */
bool scene_start(struct scene *s, const struct scene_desc *desc);

/* One frame: camera keys, view reset, animation toggle, then the scene's own update. */
void scene_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev);

/* Emit every object into the frame (the frame loop then sorts, and adds the crosshair when
 * s->crosshair). */
void scene_draw(const struct scene *s, struct render_frame *f, const struct render_pass *pass);

/*
 * The scene's objects fill the cells of a grid, one each, in order: object i in cell (i mod nx,
 * i / nx mod ny, i / (nx ny)), cell (x, y, z) being origin + [x, x+1] cell[0] by [y, y+1]
 * cell[1] by [z, z+1] cell[2] (an axis of size 0, with count 1, is not divided), and no object
 * reaches out of its cell, however it turns, as long as it does not move. Then an object can hide
 * another only if its cell lies between the eye's and the other's: the segment from the eye to a
 * point seen crosses cells each no farther from the eye's cell, on every axis, than the point's. So
 * scene_draw walks the cells far to near, each axis as render.c walks a lattice's rows (cells
 * before the eye's up, then from the last down to the eye's), z, then y, then x, and draws them
 * with no depth sort between objects (render_frame.painter_ordered; the face loops keep it or
 * drop it within each object). Called at the end of a scene's init. That each object stays in its
 * cell, every vertex of it in every frame the scene's update makes, is the scene's promise, which
 * tests/firmware/test_scene.c checks for every scene that makes it (a property of the scene's
 * code, not of its input), as are its sizes (each positive, or 0 with a count of 1). Returns
 * whether the grid is on: not when FW_SCENE_ORDER is 0 or the counts do not multiply to the
 * objects'.
 */
bool scene_set_grid(struct scene *s, const struct scene_grid_layout *layout);

/* Triangles of all objects (what "triangles submitted" counts). */
uint32_t scene_triangle_count(const struct scene *s);

/* The camera's key bindings: movement, look, zoom, roll and mode keys -> cam_move. */
void scene_camera_keys(struct camera *cam, const struct input_counts *keys);

/* Common helpers for the scene files. */
void scene_set_camera(struct scene *s, enum cam_mode mode, vec3 target, real_t distance,
                      fx_angle yaw, int32_t pitch, const struct cam_config *cfg);
struct cam_config scene_default_cam_config(void);
void scene_add_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                      uint8_t material);
/* The same for a grid mesh (mesh_set_grid): the object takes the grid's face loop
 * (render_object.faces), which only a program with such a scene then links. */
void scene_add_grid_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                           uint8_t material);
/* The same for a quad mesh (mesh_set_quads): the quad face loop, which draws any other mesh, and
 * a wireframe pass, face by face. */
void scene_add_quad_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                           uint8_t material);
/* The same for a lattice mesh (mesh_set_lattice) with a level cache: the lattice's face loop, which
 * draws any other mesh through the general one. */
void scene_add_lattice_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                              uint8_t material);
/* The update of a scene that turns its one object: while the scene animates, the first object's
 * rotation becomes spin times it (renormalised); nothing without an object. */
void scene_spin_first(struct scene *s, const mat3 *spin);

#endif /* SCENE_H */
