/*
 * knot.c — a (2, 3) torus knot swept by a tube: 100 rings of 25 vertices, 5000 triangles,
 * the procedural stand-in for an imported model. The tube crosses over itself, so the painter's
 * sort decides what is in front. Object mode, spinning.
 *
 * Stored compactly (issue #9: its one-scene image in 192 KiB): the tube is a grid mesh (mesh.h),
 * its faces implicit in (ring, side) rather than 5000 stored faces (50 KB), and the two
 * triangles of a quad share the quad's normal, kept in Q1.14 (2500 normals of 6 bytes, not 5000
 * of 12: 45 KB less). The quad's normal is that of its diagonals' cross product, the usual flat
 * normal of a slightly non-planar quad; each triangle's own normal differed from it by a few
 * degrees, so the knot's shading changed with this (deliberately: both halves of a quad now show
 * one level). 140160 bytes of state became 45 KB.
 */
#include "render/palette.h"
#include "scenes/scene.h"

#define KNOT_SEGMENTS 100  /* along the curve */
#define KNOT_SIDES 25      /* around the tube: 100 * 25 * 2 = 5000 triangles */

struct knot_state {
    struct mesh mesh;
    vec3 verts[KNOT_SEGMENTS * KNOT_SIDES];
    int16_t normal14[KNOT_SEGMENTS * KNOT_SIDES * 3];  /* one per quad, Q1.14 (mesh.h) */
    uint8_t row_material[KNOT_SEGMENTS];
    mat3 spin;
};
SCENE_STATE_FITS(knot, struct knot_state);

#define KNOT_R      REAL_C(2.0)    /* torus radius the knot winds around */
#define KNOT_r      REAL_C(0.85)   /* torus tube radius the knot lies on */
#define KNOT_TUBE   REAL_C(0.32)   /* radius of the knot's own tube */

/* Point of the knot at curve parameter t (a turn fraction): it goes twice around the z axis and
 * three times around the torus tube: u = 2t, v = 3t, C = ((R + r cos v) cos u,
 * (R + r cos v) sin u, r sin v). Also returns the torus's surface normal there. */
static vec3 knot_point(fx_angle t, uvec3 *torus_normal)
{
    const fx_angle u = (fx_angle)(2u * t);
    const fx_angle v = (fx_angle)(3u * t);
    const unit_t cu = unit_from_q16(fx_cos(u));
    const unit_t su = unit_from_q16(fx_sin(u));
    const unit_t cv = unit_from_q16(fx_cos(v));
    const unit_t sv = unit_from_q16(fx_sin(v));
    const real_t ring = real_add(KNOT_R, real_scale(KNOT_r, cv));

    torus_normal->x = unit_mul(cv, cu);
    torus_normal->y = unit_mul(cv, su);
    torus_normal->z = sv;
    return vec3_make(real_scale(ring, cu), real_scale(ring, su), real_scale(KNOT_r, sv));
}

static void knot_init(struct scene *s)
{
    struct knot_state *k = SCENE_STATE(s, struct knot_state);
    struct mesh *m = &k->mesh;
    struct cam_config cfg = scene_default_cam_config();
    const mat3 spin_y = mat3_rotation(1, FX_ANGLE_DEG(1.5));
    const mat3 spin_x = mat3_rotation(0, FX_ANGLE_DEG(0.7));
    const mat3 start = mat3_rotation(0, FX_ANGLE_DEG(-35));
    bool flip = false;

    mesh_init(m, k->verts, KNOT_SEGMENTS * KNOT_SIDES, 0, 0, 0, 0);
    for (int32_t i = 0; i < KNOT_SEGMENTS; i++) {
        const fx_angle t = (fx_angle)((uint32_t)i * FX_TURN / KNOT_SEGMENTS);
        const fx_angle dt = (fx_angle)(FX_TURN / (KNOT_SEGMENTS * 4u));
        uvec3 n0;
        uvec3 unused;
        const vec3 c = knot_point(t, &n0);
        /* Tangent by central difference; the tube's frame: b = t x n0, n = b x t, both unit. */
        const uvec3 tan = vec3_direction(vec3_sub(knot_point((fx_angle)(t + dt), &unused),
                                                  knot_point((fx_angle)(t - dt), &unused)));
        const uvec3 bn = uvec3_normalize(uvec3_cross(tan, n0));
        const uvec3 nn = uvec3_cross(bn, tan);

        for (int32_t j = 0; j < KNOT_SIDES; j++) {
            const fx_angle w = (fx_angle)((uint32_t)j * FX_TURN / KNOT_SIDES);
            const unit_t cw = unit_from_q16(fx_cos(w));
            const unit_t sw = unit_from_q16(fx_sin(w));
            const uvec3 radial = {unit_add(unit_mul(cw, nn.x), unit_mul(sw, bn.x)),
                                  unit_add(unit_mul(cw, nn.y), unit_mul(sw, bn.y)),
                                  unit_add(unit_mul(cw, nn.z), unit_mul(sw, bn.z))};

            mesh_add_vertex(m, vec3_add(c, vec3_along(radial, KNOT_TUBE)));
        }
    }
    /* Winding: pick the order that makes the first quad face away from the curve (outwards). */
    {
        uvec3 n0;
        const vec3 c = knot_point(0, &n0);
        const uvec3 fn = vec3_triangle_normal(m->verts[0], m->verts[KNOT_SIDES], m->verts[1]);
        const uvec3 out = vec3_direction(vec3_sub(m->verts[0], c));

        flip = uvec3_dot(fn, out) < 0;
    }
    /* Quad (i, j)'s normal, index i * KNOT_SIDES + j as mesh_set_grid wants: the unit cross
     * product of its diagonals, (c - a) x (d - b), in the winding's sense (flip: the other one),
     * kept in Q1.14. The vertices are within 3.2 units of the origin, so the differences and
     * their sums are well inside vec3_triangle_normal's range. */
    for (int32_t i = 0; i < KNOT_SEGMENTS; i++) {
        const int32_t i1 = (i + 1) % KNOT_SEGMENTS;

        for (int32_t j = 0; j < KNOT_SIDES; j++) {
            const int32_t j1 = (j + 1) % KNOT_SIDES;
            const vec3 a = m->verts[i * KNOT_SIDES + j];
            const vec3 b = m->verts[i1 * KNOT_SIDES + j];
            const vec3 c = m->verts[i1 * KNOT_SIDES + j1];
            const vec3 d = m->verts[i * KNOT_SIDES + j1];
            const vec3 diag = flip ? vec3_sub(b, d) : vec3_sub(d, b);
            const uvec3 n = vec3_triangle_normal(a, c, vec3_add(a, diag));
            int16_t *q = &k->normal14[3 * (i * KNOT_SIDES + j)];

            q[0] = mesh_q14_from_unit(n.x);
            q[1] = mesh_q14_from_unit(n.y);
            q[2] = mesh_q14_from_unit(n.z);
        }
        /* Alternate bands of colour along the curve, so its crossings read clearly. */
        k->row_material[i] = ((i / 10) & 1) ? MAT_ORANGE : MAT_CYAN;
    }
    mesh_set_grid(m, KNOT_SEGMENTS, KNOT_SIDES, flip, k->row_material, k->normal14);
    mesh_finish(m);

    k->spin = mat3_mul(&spin_y, &spin_x);
    scene_add_grid_object(s, m, &start, vec3_make(0, 0, 0), 0);
    cfg.dist_min = REAL_C(3.0);
    cfg.dist_max = REAL_C(30.0);
    scene_set_camera(s, CAM_OBJECT, vec3_make(0, 0, 0), REAL_C(8.5), 0, 0, &cfg);
}

static void knot_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    (void)keys;
    (void)ev;
    scene_spin_first(s, &SCENE_STATE(s, struct knot_state)->spin);
}

const struct scene_desc scene_knot_desc = {
    SCENE_DESC_NEEDS(knot, struct knot_state),
    .init = knot_init,
    .update = knot_update,
};
