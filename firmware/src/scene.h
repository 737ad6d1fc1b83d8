/*
 * scene.h — the built-in scenes and what the frame loop asks of them. Pure code.
 *
 *   tetra      the walking skeleton's tetrahedron, spinning (object mode)
 *   cubes      64 coloured cubes, each turning on its own (orbit mode)
 *   landscape  a lit low-poly height field, 2048 triangles in 16 tiles (fly mode)
 *   voxel      a 16 x 16 x 16 block world with place/break under the crosshair (fly mode)
 *   knot       a (2, 3) torus knot of exactly 5000 triangles, the large-model benchmark (object mode)
 *
 * A scene owns its meshes (built once by init into its own storage, inside struct scene), its
 * camera and its objects. The frame loop calls scene_update once per frame with the keys, then
 * scene_draw once per pass (twice for anaglyph stereo). Object mode turns the whole scene about
 * cam.cfg.focus (render.h composes it into every object's transform).
 */
#ifndef SCENE_H
#define SCENE_H

#include <stdbool.h>
#include <stdint.h>

#include "camera.h"
#include "input.h"
#include "mesh.h"
#include "render.h"
#include "vec.h"
#include "voxel.h"

#define SCENE_MAX_OBJECTS 64u

/* ---- per-scene storage ------------------------------------------------------------------- */

struct scene_tetra_state {
    struct mesh mesh;
    vec3 verts[4];
    struct mesh_face faces[4];
    uvec3 normals[4];
    mat3 spin;      /* rotation applied every animated frame */
};

struct scene_cubes_state {
    struct mesh mesh;
    vec3 verts[8];
    struct mesh_face faces[12];
    uvec3 normals[6];
};

#define LANDSCAPE_TILES 4         /* tiles per side */
#define LANDSCAPE_TILE_CELLS 8    /* cells per tile side */
#define LANDSCAPE_TILE_VERTS ((LANDSCAPE_TILE_CELLS + 1) * (LANDSCAPE_TILE_CELLS + 1))
#define LANDSCAPE_TILE_FACES (LANDSCAPE_TILE_CELLS * LANDSCAPE_TILE_CELLS * 2)

struct scene_landscape_tile {
    struct mesh mesh;
    vec3 verts[LANDSCAPE_TILE_VERTS];
    struct mesh_face faces[LANDSCAPE_TILE_FACES];
    uvec3 normals[LANDSCAPE_TILE_FACES];
    /* The terrain never changes: its light levels carry over from frame to frame (render.h). */
    uint8_t level[LANDSCAPE_TILE_FACES];
    struct render_level_cache levels;
};

struct scene_landscape_state {
    struct scene_landscape_tile tile[LANDSCAPE_TILES * LANDSCAPE_TILES];
};

struct scene_voxel_state {
    struct voxel_world world;
    struct voxel_chunk chunk[VOXEL_CHUNK_COUNT];
    uint16_t grid_index[VOXEL_CHUNK_MAX_VERTS];  /* meshing scratch */
    uint8_t place_block;                         /* block type P places */
};

#define KNOT_SEGMENTS 100  /* along the curve */
#define KNOT_SIDES 25      /* around the tube: 100 * 25 * 2 = 5000 triangles */

struct scene_knot_state {
    struct mesh mesh;
    vec3 verts[KNOT_SEGMENTS * KNOT_SIDES];
    struct mesh_face faces[KNOT_SEGMENTS * KNOT_SIDES * 2];
    uvec3 normals[KNOT_SEGMENTS * KNOT_SIDES * 2];
    mat3 spin;
};

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
    uint8_t block;
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
    union {
        struct scene_tetra_state tetra;
        struct scene_cubes_state cubes;
        struct scene_landscape_state landscape;
        struct scene_voxel_state voxel;
        struct scene_knot_state knot;
    } u;
};

struct scene_desc {
    const char *name;
    const char *keys;   /* scene-specific keys for the key map, or NULL */
    void (*init)(struct scene *s);
    /* Animation and scene keys, once per frame (camera keys are already applied). */
    void (*update)(struct scene *s, const struct input_counts *keys, struct scene_event *ev);
};

#define SCENE_COUNT 5u

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

/* Common helpers for the scene files. */
void scene_set_camera(struct scene *s, enum cam_mode mode, vec3 target, real_t distance,
                      fx_angle yaw, int32_t pitch, const struct cam_config *cfg);
struct cam_config scene_default_cam_config(void);
void scene_add_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                      uint8_t material);

/* The scenes (scene_*.c). */
extern const struct scene_desc scene_tetra_desc;
extern const struct scene_desc scene_cubes_desc;
extern const struct scene_desc scene_landscape_desc;
extern const struct scene_desc scene_voxel_desc;
extern const struct scene_desc scene_knot_desc;

#endif /* SCENE_H */
