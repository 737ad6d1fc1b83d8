/*
 * landscape.c — a lit low-poly height field: 32 x 32 cells of 2 x 2 units, two triangles
 * each (2048), in 4 x 4 tiles so that frustum culling can drop whole tiles. Heights from a few
 * table sines of the grid indices (integer inputs: both backends build the same terrain), water
 * flattened at sea level, materials by height. Fly mode.
 *
 * Gouraud (FW_WITH_GOURAUD): every vertex carries the mean of the unit normals of the faces around
 * its grid point in the whole terrain (land_vertex_normal), so the tiles' shared border vertices
 * get the same normal on either side and the shading has no seams; the GPU then interpolates the
 * light across each face where it can (CAPS_GOURAUD), and the scene stays flat where it cannot.
 */
#include "config/hot_path.h"
#include "render/palette.h"
#include "scenes/scene.h"

#define LANDSCAPE_TILES 4         /* tiles per side */
#define LANDSCAPE_TILE_CELLS 8    /* cells per tile side */
#define LANDSCAPE_TILE_VERTS ((LANDSCAPE_TILE_CELLS + 1) * (LANDSCAPE_TILE_CELLS + 1))
#define LANDSCAPE_TILE_FACES (LANDSCAPE_TILE_CELLS * LANDSCAPE_TILE_CELLS * 2)

struct landscape_tile {
    struct mesh mesh;
    vec3 verts[LANDSCAPE_TILE_VERTS];
    struct mesh_face faces[LANDSCAPE_TILE_FACES];
    uvec3 normals[LANDSCAPE_TILE_FACES];
    /* The terrain never changes: its light levels carry over from frame to frame (render.h). */
    uint8_t level[LANDSCAPE_TILE_FACES];
    struct render_level_cache levels;
#if FW_WITH_GOURAUD
    int16_t vnormal[LANDSCAPE_TILE_VERTS * 3];  /* per-vertex normals, Q1.14 (mesh.h) */
#endif
};

struct landscape_state {
    struct landscape_tile tile[LANDSCAPE_TILES * LANDSCAPE_TILES];
};
SCENE_STATE_FITS(landscape, struct landscape_state);

#define LAND_CELLS (LANDSCAPE_TILES * LANDSCAPE_TILE_CELLS)  /* 32 */
#define LAND_CELL_SIZE 2                                      /* units */
#define LAND_SEA_Q16 FX_CONST(0.4)

/* Height at grid point (i, j), q16_16, sea level .. ~6.5: a sum of three sines of amplitude
 * 2.2, 1.6 and 1.1 plus 1.6 (each term < 2^18 raw, the sum < 2^19: no overflow). */
static FW_BUILD_ONCE q16_16 land_height(int32_t i, int32_t j)
{
    const q16_16 a = fx_sin((fx_angle)(i * 1500 + j * 700));
    const q16_16 b = fx_cos((fx_angle)(j * 1900 - i * 600));
    const q16_16 c = fx_sin((fx_angle)((i + 2 * j) * 3100));
    q16_16 h = FX_CONST(1.6) + (a * 22) / 10 + (b * 16) / 10 + (c * 11) / 10;

    return (h < LAND_SEA_Q16) ? LAND_SEA_Q16 : h;
}

static FW_BUILD_ONCE uint8_t land_material(q16_16 mean_height)
{
    if (mean_height <= LAND_SEA_Q16 + FX_CONST(0.01)) {
        return MAT_WATER;
    }
    if (mean_height < FX_CONST(1.0)) {
        return MAT_SAND;
    }
    if (mean_height < FX_CONST(3.2)) {
        return MAT_GRASS;
    }
    if (mean_height < FX_CONST(4.6)) {
        return MAT_STONE;
    }
    return MAT_WHITE;
}

/* Grid point (gi, gj) of the terrain, model space: the vertex land_build_tile makes for it. */
static FW_BUILD_ONCE vec3 land_point(int32_t gi, int32_t gj)
{
    return vec3_make(real_from_int((gi - LAND_CELLS / 2) * LAND_CELL_SIZE),
                     real_from_q16(land_height(gi, gj) * 3 / 2),
                     real_from_int((gj - LAND_CELLS / 2) * LAND_CELL_SIZE));
}

#if FW_WITH_GOURAUD
/* The normal of face h (0 or 1) of terrain cell (ci, cj): the one mesh_add_face computed for it in
 * its tile (land_build_tile adds a tile's cells row by row, two faces each). */
static FW_BUILD_ONCE uvec3 land_face_normal(const struct landscape_state *l, int32_t ci,
                                            int32_t cj, uint32_t h)
{
    const int32_t n = LANDSCAPE_TILE_CELLS;
    const struct landscape_tile *t = &l->tile[(cj / n) * LANDSCAPE_TILES + ci / n];

    return t->normals[t->faces[2 * ((cj % n) * n + ci % n) + (int32_t)h].normal];
}

/* The normal of grid point (gi, gj): the direction of the sum of the unit normals of every face
 * of the whole terrain that has it as a corner (the cells (gi-1 .. gi, gj-1 .. gj) that exist,
 * each split along the diagonal land_build_tile chooses; 1 .. 8 faces), read from the tiles once
 * every tile is built: each face's normal is computed once, not once per corner. */
static FW_BUILD_ONCE uvec3 land_vertex_normal(const struct landscape_state *l, int32_t gi,
                                              int32_t gj)
{
    uvec3 n[8];
    uint32_t count = 0;

    for (int32_t cj = gj - 1; cj <= gj; cj++) {
        for (int32_t ci = gi - 1; ci <= gi; ci++) {
            /* Corners as land_build_tile's: a = (i, j), b = (i, j+1), c = (i+1, j+1), d = (i+1, j). */
            const int32_t ci_[4] = {ci, ci, ci + 1, ci + 1};
            const int32_t cj_[4] = {cj, cj + 1, cj + 1, cj};
            /* The two faces of the cell as corner numbers (0 = a .. 3 = d). */
            static const uint8_t even[2][3] = {{0, 1, 2}, {0, 2, 3}};
            static const uint8_t odd[2][3] = {{0, 1, 3}, {1, 2, 3}};

            if (ci < 0 || cj < 0 || ci >= LAND_CELLS || cj >= LAND_CELLS) {
                continue;
            }
            for (uint32_t h = 0; h < 2u; h++) {
                const uint8_t *fc = (((ci + cj) & 1) == 0) ? even[h] : odd[h];
                bool has = false;

                for (uint32_t k = 0; k < 3u; k++) {
                    has = has || (ci_[fc[k]] == gi && cj_[fc[k]] == gj);
                }
                if (has) {
                    n[count++] = land_face_normal(l, ci, cj, h);
                }
            }
        }
    }
    return uvec3_mean_direction(n, count);
}

/* Tile (ti, tj)'s vertex normals, from the faces of every tile (all built). */
static FW_BUILD_ONCE void land_tile_vertex_normals(const struct landscape_state *l,
                                                   struct landscape_tile *t, int32_t ti,
                                                   int32_t tj)
{
    const int32_t n = LANDSCAPE_TILE_CELLS;

    for (int32_t j = 0; j <= n; j++) {
        for (int32_t i = 0; i <= n; i++) {
            mesh_normal_to_q14(land_vertex_normal(l, ti * n + i, tj * n + j),
                               &t->vnormal[3 * (j * (n + 1) + i)]);
        }
    }
}
#endif

static FW_BUILD_ONCE void land_build_tile(struct landscape_tile *t, int32_t ti, int32_t tj)
{
    struct mesh *m = &t->mesh;
    const int32_t n = LANDSCAPE_TILE_CELLS;

    mesh_init(m, t->verts, LANDSCAPE_TILE_VERTS, t->faces, LANDSCAPE_TILE_FACES, t->normals,
              LANDSCAPE_TILE_FACES);
    for (int32_t j = 0; j <= n; j++) {
        for (int32_t i = 0; i <= n; i++) {
            const int32_t gi = ti * n + i;
            const int32_t gj = tj * n + j;

            mesh_add_vertex(m, land_point(gi, gj));
        }
    }
    for (int32_t j = 0; j < n; j++) {
        for (int32_t i = 0; i < n; i++) {
            /* Corners a = (i, j), b = (i, j+1), c = (i+1, j+1), d = (i+1, j): with u = +z, v = +x,
             * u x v = +y, the quad a, b, c, d faces up (mesh.h). The diagonal alternates. */
            const uint16_t a = (uint16_t)(j * (n + 1) + i);
            const uint16_t b = (uint16_t)((j + 1) * (n + 1) + i);
            const uint16_t c = (uint16_t)((j + 1) * (n + 1) + i + 1);
            const uint16_t d = (uint16_t)(j * (n + 1) + i + 1);
            const int32_t gi = ti * n + i;
            const int32_t gj = tj * n + j;
            const q16_16 ha = land_height(gi, gj);
            const q16_16 hb = land_height(gi, gj + 1);
            const q16_16 hc = land_height(gi + 1, gj + 1);
            const q16_16 hd = land_height(gi + 1, gj);

            if (((gi + gj) & 1) == 0) {
                mesh_add_face(m, a, b, c, land_material((ha + hb + hc) / 3));
                mesh_add_face(m, a, c, d, land_material((ha + hc + hd) / 3));
            } else {
                mesh_add_face(m, a, b, d, land_material((ha + hb + hd) / 3));
                mesh_add_face(m, b, c, d, land_material((hb + hc + hd) / 3));
            }
        }
    }
    mesh_finish(m);
    /* Built as a lattice (mesh.h): rows j, columns i, quad (0, 0) split along a-c' where the
     * terrain's cell (ti n, tj n) is ((gi + gj) even above): the face loop walks its corners. */
    (void)mesh_set_lattice(m, (uint32_t)n, (uint32_t)n, (uint32_t)((ti * n + tj * n) & 1));
}

/* The tiles, row by row, fill the cells of an x-z grid: drawn far to near, unsorted. */
#define LAND_CORNER (-(LAND_CELLS / 2) * LAND_CELL_SIZE)
#define LAND_TILE_SIZE (LANDSCAPE_TILE_CELLS * LAND_CELL_SIZE)
static const struct scene_grid_layout land_tile_grid = {
    {REAL_C(LAND_CORNER), 0, REAL_C(LAND_CORNER)},
    {REAL_C(LAND_TILE_SIZE), 0, REAL_C(LAND_TILE_SIZE)},
    {LANDSCAPE_TILES, 1, LANDSCAPE_TILES},
};

static FW_BUILD_ONCE void land_init(struct scene *s)
{
    struct landscape_state *l = SCENE_STATE(s, struct landscape_state);
    struct cam_config cfg = scene_default_cam_config();
    const mat3 id = mat3_identity();

    for (int32_t tj = 0; tj < LANDSCAPE_TILES; tj++) {
        for (int32_t ti = 0; ti < LANDSCAPE_TILES; ti++) {
            struct landscape_tile *t = &l->tile[tj * LANDSCAPE_TILES + ti];

            land_build_tile(t, ti, tj);
            scene_add_lattice_object(s, &t->mesh, &id, vec3_make(0, 0, 0), 0);
            render_level_cache_init(&t->levels, t->level, LANDSCAPE_TILE_FACES);
            s->object[s->object_count - 1u].levels = &t->levels;
#if FW_WITH_GOURAUD
            s->object[s->object_count - 1u].vnormal14 = t->vnormal;  /* filled below */
#endif
        }
    }
#if FW_WITH_GOURAUD
    for (int32_t tj = 0; tj < LANDSCAPE_TILES; tj++) {
        for (int32_t ti = 0; ti < LANDSCAPE_TILES; ti++) {
            land_tile_vertex_normals(l, &l->tile[tj * LANDSCAPE_TILES + ti], ti, tj);
        }
    }
#endif
    (void)scene_set_grid(s, &land_tile_grid);
    cfg.box_min = vec3_make(REAL_C(-96), REAL_C(-8), REAL_C(-96));
    cfg.box_max = vec3_make(REAL_C(96), REAL_C(60), REAL_C(96));
    cfg.move_step = REAL_C(0.5);
    cfg.zoom_step = REAL_C(1.0);
    cfg.dist_max = REAL_C(80.0);
    scene_set_camera(s, CAM_FLY, vec3_make(0, REAL_C(1.0), REAL_C(4.0)), REAL_C(50.0),
                     FX_ANGLE_DEG(200), -(int32_t)(24 * 65536 / 360), &cfg);
}

static void land_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    (void)s;
    (void)keys;
    (void)ev;
}

const struct scene_desc scene_landscape_desc = {
    SCENE_DESC_NEEDS(landscape, struct landscape_state),
    .init = land_init,
    .update = land_update,
};
