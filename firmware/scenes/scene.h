/*
 * scene.h — what the frame loop asks of a scene, and what scene files share. Pure code.
 *
 * The scenes are the lines of scenes/scene_list.h, each in its own file or folder:
 *   tetra      the walking skeleton's tetrahedron, spinning (object mode)
 *   cubes      64 coloured cubes, each turning on its own (orbit mode)
 *   landscape  a lit low-poly height field, 2048 triangles in 16 tiles (fly mode)
 *   voxel      a 16 x 16 x 16 block world with place/break under the crosshair (fly mode)
 *   knot       a (2, 3) torus knot of exactly 5000 triangles, the large-model benchmark (object mode)
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

#include "camera/camera.h"
#include "input/input.h"
#include "render/mesh.h"
#include "render/render.h"
#include "math/vec.h"

#define SCENE_MAX_OBJECTS 64u

/* ---- the scene table ----------------------------------------------------------------------- */

/* SCENE_INDEX_<name>, in the order of scene_list.h; SCENE_COUNT scenes. */
enum scene_index {
#define SCENE(name) SCENE_INDEX_##name,
#include "scenes/scene_list.h"
#undef SCENE
    SCENE_COUNT
};

/* Each scene's descriptor, defined in its own file (scenes/<name>.c or scenes/<name>/). */
#define SCENE(name) extern const struct scene_desc scene_##name##_desc;
struct scene_desc;
#include "scenes/scene_list.h"
#undef SCENE

/* ---- a scene's private state --------------------------------------------------------------- */

/* Each scene declares its state (meshes, animation, ...) as a struct of its own file and keeps it
 * inside struct scene, which holds one scene at a time (the scenes share the memory, which matters
 * on a chip): SCENE_STATE(s, struct tetra_state) is that scene's view of the storage.
 * SCENE_STATE_FITS(type) in the scene's file makes a state too big for the storage a compile error;
 * the scene's descriptor gives its size (state_bytes), and test_scene_state_storage checks that the
 * largest one fills the storage but for its rounding up to 64 bytes, so the number below stays the
 * largest scene's state (today the voxel scene's, sized on a 64-bit host, a little larger than on
 * rv32). */
#define SCENE_STATE_BYTES 322752u
#define SCENE_STATE(s, type) ((type *)(void *)(s)->state)
#define SCENE_STATE_FITS(type) \
    _Static_assert(sizeof(type) <= SCENE_STATE_BYTES, \
                   #type " does not fit SCENE_STATE_BYTES: raise it in scenes/scene.h")

/* ---- the running scene -------------------------------------------------------------------- */

/* Something the scene did that the frame loop may want to report. */
enum scene_event_kind {
    SCENE_EVENT_NONE = 0,
    SCENE_EVENT_BROKE,    /* a block was removed at x, y, z */
    SCENE_EVENT_PLACED,   /* a block of type `block` was placed at x, y, z */
    SCENE_EVENT_NO_TARGET,/* place/break with nothing under the crosshair */
    SCENE_EVENT_BLOCK_TYPE,
};

struct scene_event {
    enum scene_event_kind kind;
    int32_t x, y, z;
    const char *block_name;  /* PLACED, BLOCK_TYPE: the block type's name */
};

struct scene_desc;

struct scene {
    const struct scene_desc *desc;
    struct camera cam;
    struct cam_config cam_default;   /* for reset */
    enum cam_mode mode_default;
    vec3 target_default;
    real_t distance_default;
    fx_angle yaw_default;
    int32_t pitch_default;
    int32_t focal_px;     /* projection: focal length in pixels */
    real_t far;           /* projection: far distance */
    uvec3 light;          /* unit vector towards the light, world space */
    uint8_t ambient;      /* 0 .. 15 */
    real_t eye_separation;  /* anaglyph: distance between the two eyes */
    bool crosshair;
    bool animate;
    uint32_t frame;       /* frames updated since the scene started */
    struct render_object object[SCENE_MAX_OBJECTS];
    uint32_t object_count;
    _Alignas(8) unsigned char state[SCENE_STATE_BYTES];  /* the scene's own: SCENE_STATE */
    struct proj_setup proj;  /* the projection of focal_px and far, set by scene_start */
};

struct scene_desc {
    const char *name;
    const char *keys;   /* scene-specific keys for the key map, or NULL */
    size_t state_bytes; /* sizeof its state struct (SCENE_STATE_FITS) */
    void (*init)(struct scene *s);
    /* Animation and scene keys, once per frame (camera keys are already applied). */
    void (*update)(struct scene *s, const struct input_counts *keys, struct scene_event *ev);
};

/* Scene by name (NULL if unknown) or by number 0 .. SCENE_COUNT-1. */
const struct scene_desc *scene_find(const char *name);
const struct scene_desc *scene_at(uint32_t index);

/* Build the scene's meshes and set its camera; every field of *s is (re)initialised. */
void scene_start(struct scene *s, const struct scene_desc *desc);

/* One frame: camera keys, view reset, animation toggle, then the scene's own update. */
void scene_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev);

/* Emit every object into the frame (the frame loop then sorts, and adds the crosshair when
 * s->crosshair). */
void scene_draw(const struct scene *s, struct render_frame *f, const struct render_pass *pass);

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

#endif /* SCENE_H */
