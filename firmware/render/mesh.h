/*
 * mesh.h — indexed triangle meshes and a builder for the scenes. Pure code.
 *
 * Winding: a face (a, b, c) faces the direction of (b - a) x (c - a) (vec.h), which must point out
 * of the solid. Projected, a front face then has a positive signed area E_v0v1(v2) in the GPU
 * contract's sense (y down), which is what the back-face test keeps.
 *
 * Each face names a normal in the mesh's normal table (unit vectors, model space), so meshes with
 * few distinct normals (voxel chunks: six) share them. The builder computes a face's normal from
 * its winding unless given one.
 *
 * Ranges: model coordinates within +-8192 (MESH_MODEL_LIMIT, vec.h's transform; mesh_finish counts
 * a mesh beyond it as one fixed-point overflow, fx_overflow_note), and the bounding sphere plus the
 * object's position within the +-1024 world box (real.h).
 *
 * Storage is the caller's: a mesh points into arrays it was given, so the render path allocates
 * nothing.
 */
#ifndef MESH_H
#define MESH_H

#include <stdbool.h>
#include <stdint.h>

#include "math/vec.h"

struct mesh_face {
    uint16_t v[3];     /* vertex indices */
    uint16_t normal;   /* index into the normal table */
    uint8_t material;  /* palette material (palette.h) */
    uint8_t flags;     /* MESH_FACE_* */
};

/* The face is half of a planar quad whose diagonal is v[0]-v[2] (mesh_add_quad): both halves take
 * the quad's centre (the diagonal's midpoint) as their depth, so the painter keeps them together
 * instead of letting a neighbouring face slip between them (saw-tooth seams on voxel terrain). */
#define MESH_FACE_QUAD 0x01u
/* Edge k of the face (v[k] -> v[(k + 1) % 3]) lies inside one of the mesh's polygons (a quad's
 * diagonal, an inner edge of a triangulated polygon): a wireframe draws the polygons' edges only,
 * so it skips this one (render.c). mesh_add_quad sets it on both halves' diagonal, mesh_grid_face
 * on a grid quad's, meshfile_load on the edges two coplanar faces of one material share. */
#define MESH_FACE_EDGE_HIDDEN(k) (0x02u << (k))
#define MESH_FACE_EDGES_HIDDEN 0x0Eu

struct mesh {
    vec3 *verts;
    struct mesh_face *faces;
    uvec3 *normals;
    uint32_t vert_count;
    uint32_t face_count;
    uint32_t normal_count;
    uint32_t vert_cap;
    uint32_t face_cap;
    uint32_t normal_cap;
    vec3 center;    /* bounding sphere, model space (mesh_finish) */
    real_t radius;
    /* mesh_finish: the vertices are exactly the corners of the box [box_lo, box_hi], vertex i at
     * hi on axis k when bit k of i is set (x: 1, y: 2, z: 4): render.c then transforms them with
     * xf_apply_box. */
    bool box;
    vec3 box_lo;
    vec3 box_hi;
    bool full;      /* an add did not fit its array: the mesh is incomplete */
    /* A lattice mesh (mesh_set_lattice; in the padding after `full`, so a mesh stays its size):
     * faces stored, each with the corners a lattice of quads gives it, which a face loop can then
     * walk instead of reading them. */
    uint8_t lattice_diag : 1;  /* quad (0, 0)'s diagonal: 0 = a-c, 1 = b-d (it alternates) */
    /* Every vertex's x is its column's and its z its row's (a height field over a regular
     * x-z lattice: the landscape's tiles), so render.c projects it with a column's and a row's
     * products formed once (render_project_lattice). */
    uint8_t lattice_axes : 1;
    /* ... and regular: column c's x is x_0 + c dx, row r's z is z_0 + r dz, dx and dz > 0, so
     * render.c's lattice loop can walk its quads far to near from any eye (the painter's order of a
     * height field, render_lattice_faces). */
    uint8_t lattice_regular : 1;
    uint8_t quads : 1;      /* mesh_set_quads: the faces are quads' halves in pairs */
    uint16_t lattice_cols;  /* vertices per lattice row; 0: not a lattice mesh */
    /* A grid mesh (mesh_set_grid): faces implicit, not stored; faces is then unused. */
    struct mesh_grid {
        uint16_t rows;           /* 0: not a grid mesh */
        uint16_t cols;
        bool flip;
        const uint8_t *material; /* rows entries: the material of row i's faces */
        const int16_t *normal14; /* 3 per quad: its unit normal in Q1.14 (mesh_normal_q14) */
    } grid;
};

/* A unit vector component in Q1.14: |c| <= 1, so |c| * 2^14 <= 16384 fits int16 with room;
 * rounded to nearest, within 2^-15 of the component (a light level, 1/16 of the range, moves
 * only where the exact dot product lies within about 2^-14 of a level's edge). */
static inline int16_t mesh_q14_from_unit(unit_t c)
{
    const int32_t q16 = real_to_q16(real_from_unit(c));  /* |q16| <= 65536 */

    return (int16_t)((q16 >= 0) ? (q16 + 2) / 4 : -((2 - q16) / 4));
}

/* Normal i of a mesh: the stored uvec3, or a grid mesh's Q1.14 one widened (exact: q14 * 4 is
 * a Q16.16 value within +-65536). */
static inline uvec3 mesh_normal(const struct mesh *m, uint32_t i)
{
    if (m->grid.normal14 != 0) {
        const int16_t *n = &m->grid.normal14[3u * i];
        uvec3 u;

        u.x = unit_from_q16((q16_16)n[0] * 4);
        u.y = unit_from_q16((q16_16)n[1] * 4);
        u.z = unit_from_q16((q16_16)n[2] * 4);
        return u;
    }
    return m->normals[i];
}

/*
 * A grid mesh: a closed tube (the knot) whose vertices are rows x cols, vertex (i, j) at
 * i * cols + j, each row a ring. Quad q = i * cols + j has corners a = (i, j), b = (i+1, j),
 * c = (i+1, j+1), d = (i, j+1), indices modulo rows and cols; its faces are 2q and 2q + 1:
 * (a, b, c) and (a, c, d), or with flip (a, d, c) and (a, c, b) — the other winding. Both take
 * normal q (one per quad: rows * cols normals, given as normal14, 3 int16 each in Q1.14, not in
 * the normals table: 6 bytes a normal instead of 12) and material[i]. Nothing per face is stored:
 * 10 bytes a face less (the knot: 50 KB). mesh_face_at gives any face, mesh_normal any normal;
 * render.c walks the faces in order with mesh_grid_face. A grid mesh takes no level cache.
 */
void mesh_set_grid(struct mesh *m, uint32_t rows, uint32_t cols, bool flip,
                   const uint8_t *row_material, const int16_t *normal14);

/* Face (i, j, half) of a grid mesh, as mesh_set_grid defines it, into *out. */
static inline void mesh_grid_face(const struct mesh_grid *g, uint32_t i, uint32_t j, uint32_t half,
                                  struct mesh_face *out)
{
    const uint32_t i1 = (i + 1u == g->rows) ? 0u : i + 1u;
    const uint32_t j1 = (j + 1u == g->cols) ? 0u : j + 1u;
    const uint32_t a = i * g->cols + j;
    const uint32_t b = i1 * g->cols + j;
    const uint32_t c = i1 * g->cols + j1;
    const uint32_t d = i * g->cols + j1;
    const uint32_t second = (half == 0u) ? (g->flip ? d : b) : c;
    const uint32_t third = (half == 0u) ? c : (g->flip ? b : d);

    out->v[0] = (uint16_t)a;
    out->v[1] = (uint16_t)second;
    out->v[2] = (uint16_t)third;
    out->normal = (uint16_t)a;
    out->material = g->material[i];
    /* The quad's diagonal a-c: half 0's edge 2 (c -> a), half 1's edge 0 (a -> c). */
    out->flags = (uint8_t)MESH_FACE_EDGE_HIDDEN((half == 0u) ? 2u : 0u);
}

/*
 * A lattice mesh: (rows + 1) x (cols + 1) vertices, vertex (r, c) at r * (cols + 1) + c, and faces
 * 2q, 2q + 1 the halves of quad q = r * cols + c, whose corners are a = (r, c), b = (r + 1, c),
 * c' = (r + 1, c + 1), d = (r, c + 1): split along a-c' as (a, b, c') and (a, c', d), or along b-d
 * as (a, b, d) and (b, c', d); quad (0, 0) along diag0's diagonal (0: a-c', 1: b-d), and the
 * diagonal alternating from quad to quad along rows and columns (a height field's checkerboard:
 * the landscape's tiles). Unlike a grid mesh the faces are stored, with their own materials,
 * normals and flags; mesh_set_lattice only checks that the built faces are exactly that, none
 * flagged MESH_FACE_QUAD, and then marks the mesh, so that render.c's lattice face loop may form
 * a face's corners from its place instead of reading them. Returns whether it did (else the mesh
 * is left unmarked, and any face loop draws it). It also notes whether vertex (r, c) has column
 * c's x (row 0's) and row r's z (column 0's) for every r and c (lattice_axes), and whether those
 * are evenly spaced and increasing (lattice_regular). Neither the faces
 * nor the vertices may change while it is marked (mesh_clear unmarks).
 */
bool mesh_set_lattice(struct mesh *m, uint32_t rows, uint32_t cols, uint32_t diag0);

/*
 * A quad mesh: faces 2q and 2q + 1 are quad q's halves as mesh_add_quad adds them, (a, b, c) and
 * (c, d, a), both MESH_FACE_QUAD, with one normal and one material (the cubes, the voxel chunks).
 * mesh_set_quads checks that every face is, and then marks the mesh (quads), so that render.c's
 * quad face loop may read a quad's corners, key and colour once for both halves. Returns whether
 * it did (else the mesh is left unmarked, and the quad loop draws it face by face). The faces must
 * not change while it is marked (mesh_clear unmarks).
 */
bool mesh_set_quads(struct mesh *m);

/* Per-vertex normals (a render_object's vnormal14, render.h): 3 Q1.14 values a vertex, as a grid
 * mesh's normal14 holds per quad. Normal i widened as mesh_normal widens a grid's. */
static inline uvec3 mesh_q14_normal(const int16_t *normal14, uint32_t i)
{
    const int16_t *n = &normal14[3u * i];
    uvec3 u;

    u.x = unit_from_q16((q16_16)n[0] * 4);
    u.y = unit_from_q16((q16_16)n[1] * 4);
    u.z = unit_from_q16((q16_16)n[2] * 4);
    return u;
}

/* A unit normal as such a Q1.14 triple (mesh_q14_from_unit per component). */
static inline void mesh_normal_to_q14(uvec3 n, int16_t out[3])
{
    out[0] = mesh_q14_from_unit(n.x);
    out[1] = mesh_q14_from_unit(n.y);
    out[2] = mesh_q14_from_unit(n.z);
}

/* Face fi of any mesh: a pointer into faces[], or for a grid mesh *tmp filled. */
const struct mesh_face *mesh_face_at(const struct mesh *m, uint32_t fi, struct mesh_face *tmp);

/* Point the mesh at caller-owned arrays and empty it. */
void mesh_init(struct mesh *m, vec3 *verts, uint32_t vert_cap, struct mesh_face *faces,
               uint32_t face_cap, uvec3 *normals, uint32_t normal_cap);
void mesh_clear(struct mesh *m);

/* Append; each returns the new index (or 0 and sets m->full when the array is full). */
uint16_t mesh_add_vertex(struct mesh *m, vec3 p);
uint16_t mesh_add_normal(struct mesh *m, uvec3 n);
/* A face with its normal computed from the winding. */
void mesh_add_face(struct mesh *m, uint16_t a, uint16_t b, uint16_t c, uint8_t material);
/* A face with a given normal index. */
void mesh_add_face_normal(struct mesh *m, uint16_t a, uint16_t b, uint16_t c, uint16_t normal,
                          uint8_t material);
/* Quad a-b-c-d (in winding order, planar) as the faces (a, b, c) and (c, d, a), one normal, both
 * flagged MESH_FACE_QUAD with the diagonal a-c as their v[0]-v[2], and that edge (edge 2 of both)
 * MESH_FACE_EDGE_HIDDEN. */
void mesh_add_quad(struct mesh *m, uint16_t a, uint16_t b, uint16_t c, uint16_t d,
                   uint16_t normal, uint8_t material);

/* Model coordinates stay strictly inside +-8192 (4 p_i fits int32 in xf_apply). */
#define MESH_MODEL_LIMIT REAL_C(8192)

/* Bounding sphere: centre of the vertices' box, radius to the farthest vertex; and whether the
 * vertices are that box's eight corners in the order mesh.box names. A vertex outside
 * +-MESH_MODEL_LIMIT is counted (fx_overflow_note): the frame loop then reports it and stops. */
void mesh_finish(struct mesh *m);

/* The six faces of the unit cube [0, 1]^3, dir 0 = +x, 1 = -x, 2 = +y, 3 = -y, 4 = +z, 5 = -z:
 * the outward normal n and tangent axes u, v with u x v = n (the voxel world's block faces, the
 * cubes scene's cube). */
struct mesh_cube_face {
    int8_t n[3];
    int8_t u[3];
    int8_t v[3];
};
extern const struct mesh_cube_face mesh_cube_faces[6];

/* Corners of face `dir` in outward winding order: the quad corner[0..3] (mesh_add_quad). */
void mesh_cube_face_corners(uint32_t dir, int32_t corner[4][3]);
/* Outward unit normal of face `dir`. */
uvec3 mesh_cube_face_normal(uint32_t dir);

#endif /* MESH_H */
