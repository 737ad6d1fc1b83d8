/*
 * scene_set.h — a program's part of the scene table: the scenes it is built with, and the memory
 * they run in, sized for the largest of them. Include it in exactly one file of each program
 * (app/app.c, which is compiled per ELF; the unit tests' test_scene.c; the input fuzzer).
 *
 * Which scenes: FW_BUILT_SCENES, a list of SCENE(name) (firmware.mk passes
 * -DFW_BUILT_SCENES='SCENE(tetra)' to a one-scene build); by default every scene of scene_list.h.
 * Only the listed descriptors are referenced, so --gc-sections drops every other scene's code and
 * data, and keys 1..N choose among the listed scenes, in the table's order.
 *
 * Defines:
 *   scene_built[], scene_built_count   the table scene_at/scene_find/scene_count read (scene.h)
 *   SCENE_SET_STATE_BYTES, SCENE_SET_OBJECTS, SCENE_SET_VERTS, SCENE_SET_PRIMS
 *                                      the largest column of the listed scenes (scene_list.h)
 *   scene_set_attach(scene, frame)     gives a scene and a frame this program's storage
 * The storage is static: SCENE_SET_STATE_BYTES of scene state, SCENE_SET_OBJECTS objects, a
 * frame of SCENE_SET_VERTS vertices and SCENE_SET_PRIMS primitives (a pass's needs: the emulated
 * wireframe's columns in a build with FW_WITH_WIREFRAME and FW_WITH_LINE_EMULATION, else the filled
 * ones, which a wireframe with GPU lines needs exactly: render.h).
 */
#ifndef SCENE_SET_H
#define SCENE_SET_H

#include "render/render.h"
#include "scenes/scene.h"

/* The largest need: sizeof a union of one char array per listed scene. Without FW_BUILT_SCENES,
 * the table's own lines (scene_list.h cannot be expanded inside a macro, so it is included once
 * per use, with SCENE defined for that use). */
#ifndef FW_BUILT_SCENES
union scene_set_state_max {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) unsigned char name[state];
#include "scenes/scene_list.h"
#undef SCENE
};
union scene_set_objects_max {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) unsigned char name[objects];
#include "scenes/scene_list.h"
#undef SCENE
};
union scene_set_verts_max {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) \
    unsigned char name[FW_FRAME_WIRE_COLUMNS ? (wverts) : (verts)];
#include "scenes/scene_list.h"
#undef SCENE
};
union scene_set_prims_max {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) \
    unsigned char name[FW_FRAME_WIRE_COLUMNS ? (wprims) : (prims)];
#include "scenes/scene_list.h"
#undef SCENE
};
const struct scene_desc *const scene_built[] = {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) &scene_##name##_desc,
#include "scenes/scene_list.h"
#undef SCENE
};
#else
union scene_set_state_max {
#define SCENE(name) unsigned char name[SCENE_STATE_BYTES_##name];
    FW_BUILT_SCENES
#undef SCENE
};
union scene_set_objects_max {
#define SCENE(name) unsigned char name[SCENE_MAX_OBJECTS_##name];
    FW_BUILT_SCENES
#undef SCENE
};
union scene_set_verts_max {
#define SCENE(name) unsigned char name[SCENE_MAX_VERTS_##name];
    FW_BUILT_SCENES
#undef SCENE
};
union scene_set_prims_max {
#define SCENE(name) unsigned char name[SCENE_MAX_PRIMS_##name];
    FW_BUILT_SCENES
#undef SCENE
};
const struct scene_desc *const scene_built[] = {
#define SCENE(name) &scene_##name##_desc,
    FW_BUILT_SCENES
#undef SCENE
};
#endif

#define SCENE_SET_STATE_BYTES (sizeof(union scene_set_state_max))
#define SCENE_SET_OBJECTS (sizeof(union scene_set_objects_max))
#define SCENE_SET_VERTS (sizeof(union scene_set_verts_max))
#define SCENE_SET_PRIMS (sizeof(union scene_set_prims_max))

const uint32_t scene_built_count = (uint32_t)(sizeof scene_built / sizeof scene_built[0]);

_Static_assert(sizeof scene_built / sizeof scene_built[0] >= 1u &&
                   sizeof scene_built / sizeof scene_built[0] <= SCENE_COUNT,
               "FW_BUILT_SCENES: 1 to SCENE_COUNT scenes of scene_list.h");

static _Alignas(8) unsigned char scene_set_state[SCENE_SET_STATE_BYTES];
static struct render_object scene_set_objects[SCENE_SET_OBJECTS];
RENDER_FRAME_STORAGE(scene_set_frame, SCENE_SET_VERTS, SCENE_SET_PRIMS);

/* Give the scene and the frame this program's storage (once, before the first scene_start). */
static inline void scene_set_attach(struct scene *s, struct render_frame *f)
{
    scene_attach(s, scene_set_objects, (uint32_t)SCENE_SET_OBJECTS, scene_set_state,
                 sizeof scene_set_state);
    RENDER_FRAME_ATTACH(f, scene_set_frame);
}

#endif /* SCENE_SET_H */
