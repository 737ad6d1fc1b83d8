/*
 * mesh.c — see mesh.h.
 */
#include "render/mesh.h"

#include "config/hot_path.h"

void mesh_init(struct mesh *m, vec3 *verts, uint32_t vert_cap, struct mesh_face *faces,
               uint32_t face_cap, uvec3 *normals, uint32_t normal_cap)
{
    m->verts = verts;
    m->faces = faces;
    m->normals = normals;
    /* Face vertex and normal indices are uint16. */
    m->vert_cap = (vert_cap > 65536u) ? 65536u : vert_cap;
    m->face_cap = face_cap;
    m->normal_cap = (normal_cap > 65536u) ? 65536u : normal_cap;
    mesh_clear(m);
}

void mesh_clear(struct mesh *m)
{
    m->grid.rows = 0;
    m->grid.cols = 0;
    m->grid.flip = false;
    m->grid.material = 0;
    m->grid.normal14 = 0;
    m->vert_count = 0;
    m->face_count = 0;
    m->normal_count = 0;
    m->center = vec3_make(0, 0, 0);
    m->radius = 0;
    m->full = false;
    m->box = false;
    m->lattice_diag = 0;
    m->lattice_axes = 0;
    m->lattice_regular = 0;
    m->quads = 0;
    m->lattice_cols = 0;
}

uint16_t mesh_add_vertex(struct mesh *m, vec3 p)
{
    if (m->vert_count >= m->vert_cap) {
        m->full = true;
        return 0;
    }
    m->verts[m->vert_count] = p;
    return (uint16_t)m->vert_count++;
}

uint16_t mesh_add_normal(struct mesh *m, uvec3 n)
{
    if (m->normal_count >= m->normal_cap) {
        m->full = true;
        return 0;
    }
    m->normals[m->normal_count] = n;
    return (uint16_t)m->normal_count++;
}

FW_BUILD_ONCE void mesh_add_face_normal(struct mesh *m, uint16_t a, uint16_t b, uint16_t c,
                                        uint16_t normal, uint8_t material)
{
    struct mesh_face *f;

    if (m->face_count >= m->face_cap) {
        m->full = true;
        return;
    }
    f = &m->faces[m->face_count++];
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    f->normal = normal;
    f->material = material;
    f->flags = 0;
}

FW_BUILD_ONCE void mesh_add_face(struct mesh *m, uint16_t a, uint16_t b, uint16_t c,
                                 uint8_t material)
{
    const uvec3 n = vec3_triangle_normal(m->verts[a], m->verts[b], m->verts[c]);

    mesh_add_face_normal(m, a, b, c, mesh_add_normal(m, n), material);
}

void mesh_add_quad(struct mesh *m, uint16_t a, uint16_t b, uint16_t c, uint16_t d,
                   uint16_t normal, uint8_t material)
{
    mesh_add_face_normal(m, a, b, c, normal, material);
    mesh_add_face_normal(m, c, d, a, normal, material);
    if (!m->full) {
        m->faces[m->face_count - 2u].flags = MESH_FACE_QUAD | MESH_FACE_EDGE_HIDDEN(2u);
        m->faces[m->face_count - 1u].flags = MESH_FACE_QUAD | MESH_FACE_EDGE_HIDDEN(2u);
    }
}

/* Every coordinate strictly within +-MESH_MODEL_LIMIT (mesh.h). */
static bool mesh_in_model_range(vec3 p)
{
    return p.x > -MESH_MODEL_LIMIT && p.x < MESH_MODEL_LIMIT && p.y > -MESH_MODEL_LIMIT &&
           p.y < MESH_MODEL_LIMIT && p.z > -MESH_MODEL_LIMIT && p.z < MESH_MODEL_LIMIT;
}

FW_BUILD_ONCE void mesh_finish(struct mesh *m)
{
    vec3 lo;
    vec3 hi;
    real_t r = 0;

    m->box = false;
    if (m->vert_count == 0u) {
        m->center = vec3_make(0, 0, 0);
        m->radius = 0;
        return;
    }
    lo = m->verts[0];
    hi = m->verts[0];
    for (uint32_t i = 1; i < m->vert_count; i++) {
        const vec3 p = m->verts[i];

        lo.x = (p.x < lo.x) ? p.x : lo.x;
        lo.y = (p.y < lo.y) ? p.y : lo.y;
        lo.z = (p.z < lo.z) ? p.z : lo.z;
        hi.x = (p.x > hi.x) ? p.x : hi.x;
        hi.y = (p.y > hi.y) ? p.y : hi.y;
        hi.z = (p.z > hi.z) ? p.z : hi.z;
    }
    /* The transform's range argument (vec.h, xf_apply: 4 p_i must fit int32): a vertex outside
     * +-8192 would wrap, silently, in every frame's vertex loop, which checks nothing. Counted
     * once here instead, where the whole mesh is looked at anyway. */
    if (!mesh_in_model_range(lo) || !mesh_in_model_range(hi)) {
        fx_overflow_note();
    }
    m->center = vec3_make(real_half(real_add(lo.x, hi.x)), real_half(real_add(lo.y, hi.y)),
                          real_half(real_add(lo.z, hi.z)));
    for (uint32_t i = 0; i < m->vert_count; i++) {
        const real_t d = vec3_length(vec3_sub(m->verts[i], m->center));

        r = (d > r) ? d : r;
    }
    /* One unit of the last place up: rounding of the length must not shrink the sphere. */
    m->radius = real_add(r, REAL_C(1.0 / 256.0));

    m->box = (m->vert_count == 8u);
    for (uint32_t i = 0; i < m->vert_count && m->box; i++) {
        const vec3 p = m->verts[i];

        m->box = p.x == ((i & 1u) ? hi.x : lo.x) && p.y == ((i & 2u) ? hi.y : lo.y) &&
                 p.z == ((i & 4u) ? hi.z : lo.z);
    }
    m->box_lo = lo;
    m->box_hi = hi;
}

/*
 * The six face directions: the outward normal's axis and sign, and the two tangent axes u, v with
 * u x v = normal, so the quad o, o+u, o+u+v, o+v is wound outwards (mesh.h). o is the face's
 * corner with the smallest coordinates.
 */
const struct mesh_cube_face mesh_cube_faces[6] = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},    /* +x: y x z = x */
    {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   /* -x: z x y = -x */
    {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},    /* +y: z x x = y */
    {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},   /* -y: x x z = -y */
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    /* +z: x x y = z */
    {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},   /* -z: y x x = -z */
};

void mesh_cube_face_corners(uint32_t dir, int32_t corner[4][3])
{
    const int8_t *n = mesh_cube_faces[dir].n;
    const int8_t *u = mesh_cube_faces[dir].u;
    const int8_t *v = mesh_cube_faces[dir].v;

    for (int a = 0; a < 3; a++) {
        const int32_t o = (n[a] > 0) ? 1 : 0;

        corner[0][a] = o;
        corner[1][a] = o + u[a];
        corner[2][a] = o + u[a] + v[a];
        corner[3][a] = o + v[a];
    }
}

uvec3 mesh_cube_face_normal(uint32_t dir)
{
    const int8_t *n = mesh_cube_faces[dir].n;
    uvec3 r = {UNIT_ONE * n[0], UNIT_ONE * n[1], UNIT_ONE * n[2]};

    return r;
}

void mesh_set_grid(struct mesh *m, uint32_t rows, uint32_t cols, bool flip,
                   const uint8_t *row_material, const int16_t *normal14)
{
    /* Every vertex must exist: rows * cols (indices are uint16); normal14 holds as many. */
    if (rows * cols != m->vert_count || rows * cols > 65536u ||
        rows < 2u || cols < 2u) {
        m->full = true;
        return;
    }
    m->grid.rows = (uint16_t)rows;
    m->grid.cols = (uint16_t)cols;
    m->grid.flip = flip;
    m->grid.material = row_material;
    m->grid.normal14 = normal14;
    m->normal_count = rows * cols;
    m->face_count = 2u * rows * cols;
}

FW_BUILD_ONCE bool mesh_set_lattice(struct mesh *m, uint32_t rows, uint32_t cols, uint32_t diag0)
{
    const uint32_t w = cols + 1u;  /* vertices per row */
    const struct mesh_face *face = m->faces;

    if (m->grid.rows != 0u || m->full || rows == 0u || cols == 0u || rows > 65535u ||
        cols > 65534u || m->vert_count != (rows + 1u) * w || m->face_count != 2u * rows * cols) {
        return false;
    }
    for (uint32_t r = 0; r < rows; r++) {
        for (uint32_t c = 0; c < cols; c++, face += 2) {
            const uint32_t a = r * w + c;
            const uint32_t b = a + w;
            const uint32_t cc = b + 1u;
            const uint32_t d = a + 1u;
            const bool bd = ((r + c + diag0) & 1u) != 0u;
            const uint32_t want[2][3] = {{a, b, bd ? d : cc}, {bd ? b : a, cc, d}};

            for (uint32_t h = 0; h < 2u; h++) {
                if (face[h].v[0] != want[h][0] || face[h].v[1] != want[h][1] ||
                    face[h].v[2] != want[h][2] || (face[h].flags & MESH_FACE_QUAD) != 0u) {
                    return false;
                }
            }
        }
    }
    m->lattice_diag = (uint8_t)(diag0 & 1u);
    m->lattice_axes = 1;
    /* Regular as well while column c's x is x_0 + c dx and row r's z is z_0 + r dz, dx, dz > 0. */
    m->lattice_regular = m->verts[1].x > m->verts[0].x && m->verts[w].z > m->verts[0].z;
    for (uint32_t r = 0; r <= rows; r++) {
        for (uint32_t c = 0; c < w; c++) {
            const vec3 p = m->verts[r * w + c];

            if (p.x != m->verts[c].x || p.z != m->verts[r * w].z) {
                m->lattice_axes = 0;  /* not on its column's x and its row's z */
            }
            /* Each step from the vertex before (coordinates within +-8192: no overflow). */
            if ((c > 0u && p.x - m->verts[r * w + c - 1u].x != m->verts[1].x - m->verts[0].x) ||
                (r > 0u && p.z - m->verts[(r - 1u) * w + c].z != m->verts[w].z - m->verts[0].z)) {
                m->lattice_regular = 0;
            }
        }
    }
    m->lattice_cols = (uint16_t)w;
    return true;
}

FW_BUILD_ONCE bool mesh_set_quads(struct mesh *m)
{
    m->quads = 0;
    if (m->face_count == 0u || (m->face_count & 1u) != 0u || m->grid.rows != 0u || m->full) {
        return false;
    }
    for (uint32_t q = 0; q < m->face_count; q += 2u) {
        const struct mesh_face *h0 = &m->faces[q];
        const struct mesh_face *h1 = &m->faces[q + 1u];

        if ((h0->flags & MESH_FACE_QUAD) == 0u || (h1->flags & MESH_FACE_QUAD) == 0u ||
            h1->v[0] != h0->v[2] || h1->v[2] != h0->v[0] || h1->normal != h0->normal ||
            h1->material != h0->material) {
            return false;
        }
    }
    m->quads = 1;
    return true;
}

const struct mesh_face *mesh_face_at(const struct mesh *m, uint32_t fi, struct mesh_face *tmp)
{
    if (m->grid.rows == 0u) {
        return &m->faces[fi];
    }
    mesh_grid_face(&m->grid, (fi / 2u) / m->grid.cols, (fi / 2u) % m->grid.cols, fi & 1u, tmp);
    return tmp;
}
