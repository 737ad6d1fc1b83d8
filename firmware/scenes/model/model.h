/*
 * model.h — the `model` scene: one mesh from a mesh file (docs/mesh-format.md), the one built in
 * (`make run SCENE=model MODEL=path`, converted by tools/meshconv at build time) or the last one
 * uploaded over the UART (docs/upload-protocol.md). Pure code.
 *
 * Its capacities are build switches, FW_MODEL_MAX_VERTS and FW_MODEL_MAX_FACES (default
 * MESHFILE_DEFAULT_MAX_*: 1024 each, which the SoC's 192 KiB hold with the upload's staging
 * buffer, make fw-size); scene_list.h's model line takes its columns from here, so they follow
 * the switches (the formulas are config/build_options.h's, where the frame's index width follows
 * from them: beyond 65,536 vertices or primitives the frame is a wide one, render.h):
 *   state   the mesh: 12 bytes a vertex, 10 a face and 12 its normal (the unit normal, read from
 *           the file); 35 KiB at the defaults
 *   verts   the mesh's vertices, two new ones per face the near plane clips for up to a quarter
 *           of the faces (a plane crosses a closed mesh along one curve: a strip of faces, far
 *           fewer than that), and the crosshair's 4
 *   prims   every face front-facing (a sheet seen face-on), one more per clipped face (a
 *           quarter, as above), the crosshair's 2 lines
 *   wverts, wprims  four vertices and two triangles per edge, three edges per face (the
 *           emulated wireframe: each face's outline)
 * A frame that needs more drops the rest and says so (app.c); test_scene_capacities drives the
 * built-in model through its sweeps against these columns.
 */
#ifndef SCENES_MODEL_H
#define SCENES_MODEL_H

#include <stdbool.h>
#include <stdint.h>

#include "config/build_options.h"  /* the frame columns' formulas (FW_MODEL_FRAME_*) */
#include "model/meshfile.h"
#include "render/mesh.h"

#ifndef FW_MODEL_MAX_VERTS
#define FW_MODEL_MAX_VERTS MESHFILE_DEFAULT_MAX_VERTS
#endif
#ifndef FW_MODEL_MAX_FACES
#define FW_MODEL_MAX_FACES MESHFILE_DEFAULT_MAX_FACES
#endif

struct model_state {
    struct mesh mesh;
    vec3 verts[FW_MODEL_MAX_VERTS];
    struct mesh_face faces[FW_MODEL_MAX_FACES];
    uvec3 normals[FW_MODEL_MAX_FACES];
    mat3 spin;
    int load_error;  /* MESHFILE_OK, or why the source was refused (the scene is then empty) */
    struct meshfile_info info;  /* the validator's findings */
    bool uploaded;   /* drawn from the last upload rather than the built-in model */
};

/* scene_list.h's columns for the model line. */
#define MODEL_STATE_COLUMN ((sizeof(struct model_state) + 63u) / 64u * 64u)
#define MODEL_FRAME_VERTS FW_MODEL_FRAME_VERTS(FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES)
#define MODEL_FRAME_PRIMS FW_MODEL_FRAME_PRIMS(FW_MODEL_MAX_FACES)
#define MODEL_WIRE_VERTS FW_MODEL_WIRE_VERTS(FW_MODEL_MAX_FACES)
#define MODEL_WIRE_PRIMS FW_MODEL_WIRE_PRIMS(FW_MODEL_MAX_FACES)

/* The file the scene's init loads: a checked upload (file, len), or NULL for the built-in model.
 * The file must stay as it is while the scene may be started from it (scene_start). */
void model_scene_source(const uint8_t *file, uint32_t len);

struct scene;

/* The running model scene's mesh: MESHFILE_OK and its counts in *info, or why its file was
 * refused (the scene is then empty; *info says what the validator found). */
int model_scene_status(const struct scene *s, struct meshfile_info *info);
/* Whether it was drawn from an upload rather than the built-in model. */
bool model_scene_uploaded(const struct scene *s);

/* The built-in model, from the build (firmware.mk links it where the model scene is built in):
 * NULL when the program has none. */
const uint8_t *model_builtin_file(uint32_t *len);

#endif /* SCENES_MODEL_H */
