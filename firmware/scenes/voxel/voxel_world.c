/*
 * voxel_world.c — see voxel_world.h.
 */
#include "scenes/voxel/voxel_world.h"

#include "render/palette.h"

uint8_t voxel_get(const struct voxel_world *w, int32_t x, int32_t y, int32_t z)
{
    return voxel_inside(x, y, z) ? w->block[y][z][x] : (uint8_t)BLOCK_AIR;
}

static void voxel_mark(struct voxel_world *w, int32_t x, int32_t y, int32_t z)
{
    if (voxel_inside(x, y, z)) {
        w->chunk_dirty[voxel_chunk_index(x / VOXEL_CHUNK, y / VOXEL_CHUNK, z / VOXEL_CHUNK)] = true;
    }
}

bool voxel_set(struct voxel_world *w, int32_t x, int32_t y, int32_t z, uint8_t block)
{
    if (!voxel_inside(x, y, z) || w->block[y][z][x] == block) {
        return false;
    }
    w->block[y][z][x] = block;
    /* The block's own chunk, and the chunks of its six neighbours: their faces against this
     * block appear or disappear. */
    voxel_mark(w, x, y, z);
    voxel_mark(w, x - 1, y, z);
    voxel_mark(w, x + 1, y, z);
    voxel_mark(w, x, y - 1, z);
    voxel_mark(w, x, y + 1, z);
    voxel_mark(w, x, y, z - 1);
    voxel_mark(w, x, y, z + 1);
    return true;
}

/* Terrain height of column (x, z), 2 .. 9, from two table sines (integers only, so both
 * backends build the same world). */
static int32_t voxel_height(int32_t x, int32_t z)
{
    const q16_16 a = fx_sin((fx_angle)(x * 3000 + z * 1100));
    const q16_16 b = fx_cos((fx_angle)(z * 3700 - x * 900));
    /* 3a + 2b is within +-5 (q16_16 < 2^19 raw): no overflow. */
    int32_t h = 5 + fx_round_to_int(3 * a + 2 * b);

    return (h < 2) ? 2 : ((h > 9) ? 9 : h);
}

static void voxel_tree(struct voxel_world *w, int32_t x, int32_t z)
{
    const int32_t ground = voxel_height(x, z);

    for (int32_t y = ground; y < ground + 3; y++) {
        w->block[y][z][x] = BLOCK_WOOD;
    }
    for (int32_t y = ground + 2; y < ground + 5; y++) {
        for (int32_t dz = -1; dz <= 1; dz++) {
            for (int32_t dx = -1; dx <= 1; dx++) {
                if (voxel_inside(x + dx, y, z + dz) && w->block[y][z + dz][x + dx] == BLOCK_AIR) {
                    w->block[y][z + dz][x + dx] = BLOCK_LEAVES;
                }
            }
        }
    }
}

void voxel_generate(struct voxel_world *w)
{
    for (int32_t y = 0; y < VOXEL_NY; y++) {
        for (int32_t z = 0; z < VOXEL_NZ; z++) {
            for (int32_t x = 0; x < VOXEL_NX; x++) {
                const int32_t h = voxel_height(x, z);
                uint8_t b = BLOCK_AIR;

                if (y < h - 3) {
                    b = BLOCK_STONE;
                } else if (y < h - 1) {
                    b = BLOCK_DIRT;
                } else if (y == h - 1) {
                    b = (h <= 3) ? BLOCK_SAND : BLOCK_GRASS;
                }
                w->block[y][z][x] = b;
            }
        }
    }
    voxel_tree(w, 4, 11);
    voxel_tree(w, 11, 5);
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        w->chunk_dirty[i] = true;
    }
}

uint8_t voxel_face_material(uint8_t block, uint32_t face)
{
    switch (block) {
    case BLOCK_GRASS:
        return (face == 2u) ? MAT_GRASS : MAT_DIRT;
    case BLOCK_DIRT:
        return MAT_DIRT;
    case BLOCK_STONE:
        return MAT_STONE;
    case BLOCK_SAND:
        return MAT_SAND;
    case BLOCK_WOOD:
        return MAT_ORANGE;
    case BLOCK_LEAVES:
        return MAT_GREEN;
    default:
        return MAT_MAGENTA;  /* unknown: loud */
    }
}

void voxel_chunk_init(struct voxel_chunk *c, int32_t cx, int32_t cy, int32_t cz)
{
    voxel_chunk_attach(c, 0, 0, 0, 0);
    c->origin = vec3_make(real_from_int(cx * VOXEL_CHUNK), real_from_int(cy * VOXEL_CHUNK),
                          real_from_int(cz * VOXEL_CHUNK));
}

void voxel_chunk_attach(struct voxel_chunk *c, vec3 *verts, uint32_t vert_cap,
                        struct mesh_face *faces, uint32_t face_cap)
{
    mesh_init(&c->mesh, verts, vert_cap, faces, face_cap, c->normals, 6);
}

/* Grid corner (chunk-local, 0 .. 8 per axis) -> mesh vertex, created on first use. */
static uint16_t voxel_corner(struct mesh *m, uint16_t *grid_index, int32_t x, int32_t y, int32_t z)
{
    const uint32_t g = (uint32_t)((y * VOXEL_CHUNK_GRID + z) * VOXEL_CHUNK_GRID + x);

    if (grid_index[g] == 0xFFFFu) {
        grid_index[g] = mesh_add_vertex(m, vec3_make(real_from_int(x), real_from_int(y),
                                                     real_from_int(z)));
    }
    return grid_index[g];
}

void voxel_build_chunk(const struct voxel_world *w, int32_t cx, int32_t cy, int32_t cz,
                       struct voxel_chunk *c, uint16_t *grid_index)
{
    struct mesh *m = &c->mesh;
    const int32_t x0 = cx * VOXEL_CHUNK;
    const int32_t y0 = cy * VOXEL_CHUNK;
    const int32_t z0 = cz * VOXEL_CHUNK;

    mesh_clear(m);
    for (uint32_t i = 0; i < (uint32_t)VOXEL_CHUNK_MAX_VERTS; i++) {
        grid_index[i] = 0xFFFFu;
    }
    for (uint32_t d = 0; d < 6u; d++) {
        mesh_add_normal(m, mesh_cube_face_normal(d));
    }
    for (int32_t ly = 0; ly < VOXEL_CHUNK; ly++) {
        for (int32_t lz = 0; lz < VOXEL_CHUNK; lz++) {
            for (int32_t lx = 0; lx < VOXEL_CHUNK; lx++) {
                const uint8_t b = voxel_get(w, x0 + lx, y0 + ly, z0 + lz);

                if (b == BLOCK_AIR) {
                    continue;
                }
                for (uint32_t d = 0; d < 6u; d++) {
                    const int8_t *n = mesh_cube_faces[d].n;
                    int32_t corner[4][3];
                    uint16_t q[4];

                    if (voxel_get(w, x0 + lx + n[0], y0 + ly + n[1], z0 + lz + n[2]) !=
                        BLOCK_AIR) {
                        continue;  /* hidden between two solid blocks */
                    }
                    mesh_cube_face_corners(d, corner);
                    for (int k = 0; k < 4; k++) {
                        q[k] = voxel_corner(m, grid_index, lx + corner[k][0], ly + corner[k][1],
                                            lz + corner[k][2]);
                    }
                    mesh_add_quad(m, q[0], q[1], q[2], q[3], (uint16_t)d,
                                  voxel_face_material(b, d));
                }
            }
        }
    }
    mesh_finish(m);
    (void)mesh_set_quads(m);  /* every face a quad's half (mesh_add_quad): the quad face loop's */
}

bool voxel_raycast(const struct voxel_world *w, vec3 origin, uvec3 dir, real_t max_dist,
                   struct voxel_hit *hit)
{
    const real_t o[3] = {origin.x, origin.y, origin.z};
    const unit_t d[3] = {dir.x, dir.y, dir.z};
    const unit_t tiny = UNIT_C(1.0 / 1024.0);
    int32_t cell[3];
    int32_t step[3];
    real_t t_max[3];
    real_t t_delta[3];
    int32_t prev[3];

    for (int a = 0; a < 3; a++) {
        cell[a] = real_floor_int(o[a]);
        prev[a] = cell[a];
        if (d[a] > tiny || d[a] < -tiny) {
            /* 1/|d| <= 1024 and the distance to the next boundary is <= 1: both fit q16_16. */
            const real_t inv = real_div(REAL_ONE, real_from_unit((d[a] > 0) ? d[a] : -d[a]));
            const real_t boundary = (d[a] > 0) ? real_sub(real_from_int(cell[a] + 1), o[a])
                                               : real_sub(o[a], real_from_int(cell[a]));

            step[a] = (d[a] > 0) ? 1 : -1;
            t_delta[a] = inv;
            t_max[a] = real_mul(boundary, inv);
        } else {
            step[a] = 0;
            t_delta[a] = REAL_HUGE;
            t_max[a] = REAL_HUGE;
        }
    }
    hit->prev_valid = false;
    /* Each step crosses one cell boundary; within max_dist at most 3 * (max_dist + 1) of them. */
    for (int32_t n = 0; n < 3 * 66; n++) {
        int a = 0;

        if (voxel_get(w, cell[0], cell[1], cell[2]) != BLOCK_AIR) {
            hit->x = cell[0];
            hit->y = cell[1];
            hit->z = cell[2];
            hit->px = prev[0];
            hit->py = prev[1];
            hit->pz = prev[2];
            hit->prev_valid = (n > 0);
            return true;
        }
        if (t_max[1] < t_max[a]) {
            a = 1;
        }
        if (t_max[2] < t_max[a]) {
            a = 2;
        }
        if (t_max[a] > max_dist) {
            return false;
        }
        prev[0] = cell[0];
        prev[1] = cell[1];
        prev[2] = cell[2];
        cell[a] += step[a];
        /* t_max <= max_dist (<= 64) here and t_delta <= 1024: the sum fits q16_16. */
        t_max[a] = real_add(t_max[a], t_delta[a]);
    }
    return false;
}
