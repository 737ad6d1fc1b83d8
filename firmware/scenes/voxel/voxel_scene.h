/*
 * voxel_scene.h — the voxel scene's state, for the tests and the fuzzer that look inside it (the
 * frame loop does not: it sees the scene through struct scene_desc). Pure code.
 */
#ifndef VOXEL_SCENE_H
#define VOXEL_SCENE_H

#include <stdint.h>

#include "scenes/scene.h"
#include "scenes/voxel/voxel_world.h"

struct voxel_scene_state {
    struct voxel_world world;
    struct voxel_chunk chunk[VOXEL_CHUNK_COUNT];
    uint16_t grid_index[VOXEL_CHUNK_MAX_VERTS];  /* meshing scratch */
    uint8_t place_block;                         /* block type P places */
};

/* The voxel scene's state inside a scene started as voxel. */
static inline struct voxel_scene_state *voxel_scene_state(struct scene *s)
{
    return SCENE_STATE(s, struct voxel_scene_state);
}

#endif /* VOXEL_SCENE_H */
