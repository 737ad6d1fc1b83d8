/*
 * voxel_scene.h — the voxel scene's state, for the tests and the fuzzer that look inside it (the
 * frame loop does not: it sees the scene through struct scene_desc). Pure code.
 */
#ifndef VOXEL_SCENE_H
#define VOXEL_SCENE_H

#include <stdint.h>

#include "scenes/scene.h"
#include "scenes/voxel/voxel_world.h"

_Static_assert(VOXEL_CHUNK_COUNT <= 8, "left_out_mask holds a bit per chunk");

/* The chunks' shared storage: every chunk's vertices and faces packed in chunk order. Sized for
 * the world's realistic need, not every chunk's worst case (8 x 3,072 faces, 317 KiB): the
 * generated world needs VOXEL_POOL_GEN_FACES faces and VOXEL_POOL_GEN_VERTS vertices
 * (test_voxel_pool measures it), and the pool leaves room for edits on top (firmware/README.md,
 * "Memory per scene"). A rebuild that does not fit leaves the chunks that found no room out of
 * the frame (empty meshes) and says so (SCENE_EVENT_MESH_FULL: the frame loop prints an error
 * line); the next rebuild that fits draws them again. */
#define VOXEL_POOL_FACES 3328u
#define VOXEL_POOL_VERTS 2048u
#define VOXEL_POOL_GEN_FACES 2300u
#define VOXEL_POOL_GEN_VERTS 1296u

struct voxel_scene_state {
    struct voxel_world world;
    struct voxel_chunk chunk[VOXEL_CHUNK_COUNT];
    vec3 pool_verts[VOXEL_POOL_VERTS];
    struct mesh_face pool_faces[VOXEL_POOL_FACES];
    uint16_t grid_index[VOXEL_CHUNK_MAX_VERTS];  /* meshing scratch */
    uint8_t place_block;                         /* block type P places */
    uint8_t left_out_mask;                       /* bit i: chunk i found no room in the pool */
};

/* The voxel scene's state inside a scene started as voxel. */
static inline struct voxel_scene_state *voxel_scene_state(struct scene *s)
{
    return SCENE_STATE(s, struct voxel_scene_state);
}

#endif /* VOXEL_SCENE_H */
