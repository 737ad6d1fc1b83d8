/*
 * voxel_world.h — a 16 x 16 x 16 block world: terrain, meshing without hidden faces, and the ray cast
 * that finds the block under the crosshair. Pure code.
 *
 * Blocks are unit cubes; block (x, y, z) spans [x, x+1] x [y, y+1] x [z, z+1] in world units, y up.
 * Outside the world is air.
 *
 * Meshing: the world is cut into 8 x 8 x 8 chunks, each one mesh (one render_object, so it is
 * frustum-culled by its bounding sphere, and rebuilt alone when an edit touches it). A face is
 * emitted only where a solid block meets air — faces between two solid blocks are left out — as
 * a quad of two triangles wound outwards (mesh.h). Vertices are shared through a per-build grid
 * index, so a chunk carries each corner once.
 *
 * Ray cast: Amanatides and Woo's grid walk from the eye along the view direction, cell by cell in
 * order of distance, up to a maximum distance; it reports the first solid block and the empty cell
 * before it (where a placed block goes).
 */
#ifndef VOXEL_H
#define VOXEL_H

#include <stdbool.h>
#include <stdint.h>

#include "render/mesh.h"
#include "render/render.h"
#include "math/vec.h"

#define VOXEL_NX 16
#define VOXEL_NY 16
#define VOXEL_NZ 16
#define VOXEL_CHUNK 8
#define VOXEL_CHUNKS_X (VOXEL_NX / VOXEL_CHUNK)
#define VOXEL_CHUNKS_Y (VOXEL_NY / VOXEL_CHUNK)
#define VOXEL_CHUNKS_Z (VOXEL_NZ / VOXEL_CHUNK)
#define VOXEL_CHUNK_COUNT (VOXEL_CHUNKS_X * VOXEL_CHUNKS_Y * VOXEL_CHUNKS_Z)

/* Worst case of one chunk: a 3-D checkerboard, 256 solid blocks with all 6 faces exposed. */
#define VOXEL_CHUNK_MAX_FACES (VOXEL_CHUNK * VOXEL_CHUNK * VOXEL_CHUNK / 2 * 6 * 2)
#define VOXEL_CHUNK_GRID (VOXEL_CHUNK + 1)
#define VOXEL_CHUNK_MAX_VERTS (VOXEL_CHUNK_GRID * VOXEL_CHUNK_GRID * VOXEL_CHUNK_GRID)

enum voxel_block {
    BLOCK_AIR = 0,
    BLOCK_GRASS,
    BLOCK_DIRT,
    BLOCK_STONE,
    BLOCK_SAND,
    BLOCK_WOOD,
    BLOCK_LEAVES,
    BLOCK_TYPES
};

struct voxel_world {
    uint8_t block[VOXEL_NY][VOXEL_NZ][VOXEL_NX];
    bool chunk_dirty[VOXEL_CHUNK_COUNT];
};

/* A chunk's mesh. Its vertices and faces live in storage the caller attaches
 * (voxel_chunk_attach): the scene packs every chunk into one pool sized for the world's realistic
 * need (voxel_scene.h), not each for its worst case (VOXEL_CHUNK_MAX_*: 39 KiB a chunk). */
struct voxel_chunk {
    struct mesh mesh;
    uvec3 normals[6];
    vec3 origin;  /* world position of the chunk's corner */
    /* The six normals' light levels, carried from frame to frame while the light stays (render.h):
     * a face's level is then a look-up, not three multiplies. */
    uint8_t level[6];
    struct render_level_cache levels;
};

struct voxel_hit {
    int32_t x, y, z;         /* the solid block hit */
    int32_t px, py, pz;      /* the cell the ray was in just before (adjacent to a face of it) */
    bool prev_valid;         /* false when the ray started inside the hit block */
};

/* Block at (x, y, z); air outside the world. */
uint8_t voxel_get(const struct voxel_world *w, int32_t x, int32_t y, int32_t z);
/* Set a block inside the world (else nothing) and mark the chunks whose mesh it touches dirty.
 * Returns true if the block changed. */
bool voxel_set(struct voxel_world *w, int32_t x, int32_t y, int32_t z, uint8_t block);
static inline bool voxel_inside(int32_t x, int32_t y, int32_t z)
{
    return x >= 0 && x < VOXEL_NX && y >= 0 && y < VOXEL_NY && z >= 0 && z < VOXEL_NZ;
}

/* Rolling terrain (stone, dirt, grass, sand) with two trees; all chunks dirty. Deterministic. */
void voxel_generate(struct voxel_world *w);

/* Set chunk cx, cy, cz's origin and give it no storage yet. Call once before building. */
void voxel_chunk_init(struct voxel_chunk *c, int32_t cx, int32_t cy, int32_t cz);
/* Give the chunk's mesh vert_cap vertices and face_cap faces of storage, and empty it. */
void voxel_chunk_attach(struct voxel_chunk *c, vec3 *verts, uint32_t vert_cap,
                        struct mesh_face *faces, uint32_t face_cap);
/* Rebuild chunk (cx, cy, cz) from the world into its attached storage (mesh.full when it did not
 * fit: the mesh is then incomplete). grid_index is scratch of VOXEL_CHUNK_MAX_VERTS. */
void voxel_build_chunk(const struct voxel_world *w, int32_t cx, int32_t cy, int32_t cz,
                       struct voxel_chunk *c, uint16_t *grid_index);
/* Chunk number of chunk coordinates (x fastest). */
static inline uint32_t voxel_chunk_index(int32_t cx, int32_t cy, int32_t cz)
{
    return (uint32_t)((cy * VOXEL_CHUNKS_Z + cz) * VOXEL_CHUNKS_X + cx);
}

/* A block's faces are the unit cube's: mesh_cube_faces, mesh_cube_face_corners (render/mesh.h). */

/* The palette material of a block's face (0 = +x, 1 = -x, 2 = +y, 3 = -y, 4 = +z, 5 = -z). */
uint8_t voxel_face_material(uint8_t block, uint32_t face);

/* First solid block along origin + t dir, 0 <= t <= max_dist (max_dist <= 64). dir need not be
 * exactly unit length; components below 2^-10 in magnitude count as 0 (such a ray would need
 * more than 1024 units to cross one cell on that axis). */
bool voxel_raycast(const struct voxel_world *w, vec3 origin, uvec3 dir, real_t max_dist,
                   struct voxel_hit *hit);

#endif /* VOXEL_H */
