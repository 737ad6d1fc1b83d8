/*
 * test_voxel.c — the block world: faces between solid blocks left out, faces wound outwards,
 * chunk borders, the worst case fitting its arrays, edits marking chunks dirty, and the ray cast
 * that picks the block under the crosshair.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "unit.h"
#include "scenes/voxel/voxel_world.h"

static struct voxel_world world;
static struct voxel_chunk chunk;
static uint16_t grid[VOXEL_CHUNK_MAX_VERTS];
static vec3 chunk_verts[VOXEL_CHUNK_MAX_VERTS];            /* one chunk's worst case */
static struct mesh_face chunk_faces[VOXEL_CHUNK_MAX_FACES];

static void clear_world(void)
{
    memset(&world, 0, sizeof world);
}

static void build(int cx, int cy, int cz)
{
    voxel_chunk_init(&chunk, cx, cy, cz);
    voxel_chunk_attach(&chunk, chunk_verts, VOXEL_CHUNK_MAX_VERTS, chunk_faces,
                       VOXEL_CHUNK_MAX_FACES);
    voxel_build_chunk(&world, cx, cy, cz, &chunk, grid);
}

/* Every face's stored normal agrees with its winding. */
static void check_windings(void)
{
    const struct mesh *m = &chunk.mesh;

    for (uint32_t i = 0; i < m->face_count; i++) {
        const struct mesh_face *f = &m->faces[i];
        const uvec3 n = vec3_triangle_normal(m->verts[f->v[0]], m->verts[f->v[1]], m->verts[f->v[2]]);
        const uvec3 s = m->normals[f->normal];

        CHECK(fabs(ud(n.x) - ud(s.x)) < 1e-6 && fabs(ud(n.y) - ud(s.y)) < 1e-6 &&
              fabs(ud(n.z) - ud(s.z)) < 1e-6);
    }
}

void test_voxel_hidden_faces(void)
{
    clear_world();
    world.block[1][1][1] = BLOCK_STONE;
    build(0, 0, 0);
    CHECK_EQ(chunk.mesh.face_count, 12);  /* 6 quads */
    CHECK_EQ(chunk.mesh.vert_count, 8);
    check_windings();
    world.block[1][1][2] = BLOCK_STONE;  /* a neighbour along x */
    build(0, 0, 0);
    CHECK_EQ(chunk.mesh.face_count, 20);  /* 10 quads: the shared one twice left out */
    CHECK_EQ(chunk.mesh.vert_count, 12);
    /* A solid 3 x 3 x 3 cube: only its outside, 6 * 9 quads, 64 corners. */
    clear_world();
    for (int y = 2; y < 5; y++) {
        for (int z = 2; z < 5; z++) {
            for (int x = 2; x < 5; x++) {
                world.block[y][z][x] = BLOCK_DIRT;
            }
        }
    }
    build(0, 0, 0);
    CHECK_EQ(chunk.mesh.face_count, 6 * 9 * 2);
    CHECK_EQ(chunk.mesh.vert_count, 4 * 4 * 4 - 8);  /* the 8 inner corners touch no face */
    check_windings();
    /* Materials: grass is green on top, dirt on the sides. */
    CHECK(voxel_face_material(BLOCK_GRASS, 2) != voxel_face_material(BLOCK_GRASS, 0));
}

/* Across a chunk border the neighbour still hides the face; the world's edge shows it. */
void test_voxel_chunk_border(void)
{
    clear_world();
    world.block[0][0][7] = BLOCK_STONE;  /* last column of chunk 0 */
    world.block[0][0][8] = BLOCK_STONE;  /* first column of chunk 1 */
    build(0, 0, 0);
    CHECK_EQ(chunk.mesh.face_count, 10);  /* the +x face is hidden by the block in chunk 1 */
    build(1, 0, 0);
    CHECK_EQ(chunk.mesh.face_count, 10);
    CHECK(rd(chunk.origin.x) == 8.0);
    check_windings();
}

/* A 3-D checkerboard, every face exposed: the worst case fits the chunk's arrays. */
void test_voxel_worst_case(void)
{
    clear_world();
    for (int y = 0; y < VOXEL_CHUNK; y++) {
        for (int z = 0; z < VOXEL_CHUNK; z++) {
            for (int x = 0; x < VOXEL_CHUNK; x++) {
                world.block[y][z][x] = ((x + y + z) & 1) ? BLOCK_STONE : BLOCK_AIR;
            }
        }
    }
    build(0, 0, 0);
    CHECK(!chunk.mesh.full);
    CHECK_EQ(chunk.mesh.face_count, VOXEL_CHUNK_MAX_FACES);
    check_windings();
}

void test_voxel_edit_marks_chunks(void)
{
    clear_world();
    CHECK(voxel_set(&world, 8, 3, 3, BLOCK_SAND));  /* on a border: chunks (1,0,0) and (0,0,0) */
    CHECK(world.chunk_dirty[voxel_chunk_index(1, 0, 0)]);
    CHECK(world.chunk_dirty[voxel_chunk_index(0, 0, 0)]);
    CHECK(!world.chunk_dirty[voxel_chunk_index(0, 1, 0)]);
    CHECK(!voxel_set(&world, 8, 3, 3, BLOCK_SAND));  /* no change */
    CHECK(!voxel_set(&world, -1, 3, 3, BLOCK_SAND));  /* outside: nothing */
    CHECK_EQ(voxel_get(&world, 8, 3, 3), BLOCK_SAND);
    CHECK_EQ(voxel_get(&world, 99, 3, 3), BLOCK_AIR);
    voxel_generate(&world);
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        CHECK(world.chunk_dirty[i]);
    }
    CHECK(VOXEL_NX >= 16 && VOXEL_NY >= 16 && VOXEL_NZ >= 16);
}

void test_voxel_raycast(void)
{
    struct voxel_hit hit;

    clear_world();
    world.block[5][0][3] = BLOCK_STONE;  /* (x 3, y 5, z 0) */
    CHECK(voxel_raycast(&world, v3(0.5, 5.5, 0.5), u3(1, 0, 0), to_real(10.0), &hit));
    CHECK(hit.x == 3 && hit.y == 5 && hit.z == 0);
    CHECK(hit.prev_valid && hit.px == 2 && hit.py == 5 && hit.pz == 0);
    /* Out of reach. */
    CHECK(!voxel_raycast(&world, v3(0.5, 5.5, 0.5), u3(1, 0, 0), to_real(2.0), &hit));
    /* Looking away. */
    CHECK(!voxel_raycast(&world, v3(0.5, 5.5, 0.5), u3(-1, 0, 0), to_real(10.0), &hit));
    /* From above, diagonally down: the face entered is the top, the previous cell is above. */
    CHECK(voxel_raycast(&world, v3(3.5, 8.2, 0.5), u3(0, -1, 0), to_real(10.0), &hit));
    CHECK(hit.x == 3 && hit.y == 5 && hit.py == 6 && hit.px == 3);
    {
        const double s = 1.0 / sqrt(3.0);

        world.block[2][2][2] = BLOCK_DIRT;
        CHECK(voxel_raycast(&world, v3(0.5, 0.5, 0.5), u3(s, s, s), to_real(10.0), &hit));
        CHECK(hit.x == 2 && hit.y == 2 && hit.z == 2);
        CHECK(abs(hit.px - 2) + abs(hit.py - 2) + abs(hit.pz - 2) == 1);  /* a face neighbour */
    }
    /* From outside the world, looking in. */
    CHECK(voxel_raycast(&world, v3(-3.5, 5.5, 0.5), u3(1, 0, 0), to_real(10.0), &hit));
    CHECK(hit.x == 3 && hit.px == 2);
    /* Starting inside a block: a hit with no cell before it. */
    CHECK(voxel_raycast(&world, v3(3.5, 5.5, 0.5), u3(0, 1, 0), to_real(10.0), &hit));
    CHECK(!hit.prev_valid);
    CHECK_EQ(fx_overflow_count(), 0);
}
