/*
 * knot.c — a (2, 3) torus knot swept by a tube: 100 rings of 25 vertices, 5000 triangles,
 * the procedural stand-in for an imported model. The tube crosses over itself, so the painter's
 * sort decides what is in front. Object mode, spinning.
 */
#include "render/palette.h"
#include "scenes/scene.h"

#define KNOT_SEGMENTS 100  /* along the curve */
#define KNOT_SIDES 25      /* around the tube: 100 * 25 * 2 = 5000 triangles */

struct knot_state {
    struct mesh mesh;
    vec3 verts[KNOT_SEGMENTS * KNOT_SIDES];
    struct mesh_face faces[KNOT_SEGMENTS * KNOT_SIDES * 2];
    uvec3 normals[KNOT_SEGMENTS * KNOT_SIDES * 2];
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

    mesh_init(m, k->verts, KNOT_SEGMENTS * KNOT_SIDES, k->faces, KNOT_SEGMENTS * KNOT_SIDES * 2,
              k->normals, KNOT_SEGMENTS * KNOT_SIDES * 2);
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
    for (int32_t i = 0; i < KNOT_SEGMENTS; i++) {
        const int32_t i1 = (i + 1) % KNOT_SEGMENTS;

        for (int32_t j = 0; j < KNOT_SIDES; j++) {
            const int32_t j1 = (j + 1) % KNOT_SIDES;
            const uint16_t a = (uint16_t)(i * KNOT_SIDES + j);
            const uint16_t b = (uint16_t)(i1 * KNOT_SIDES + j);
            const uint16_t c = (uint16_t)(i1 * KNOT_SIDES + j1);
            const uint16_t d = (uint16_t)(i * KNOT_SIDES + j1);
            /* Alternate bands of colour along the curve, so its crossings read clearly. */
            const uint8_t mat = ((i / 10) & 1) ? MAT_ORANGE : MAT_CYAN;

            if (flip) {
                mesh_add_face(m, a, d, c, mat);
                mesh_add_face(m, a, c, b, mat);
            } else {
                mesh_add_face(m, a, b, c, mat);
                mesh_add_face(m, a, c, d, mat);
            }
        }
    }
    mesh_finish(m);

    k->spin = mat3_mul(&spin_y, &spin_x);
    scene_add_object(s, m, &start, vec3_make(0, 0, 0), 0);
    cfg.dist_min = REAL_C(3.0);
    cfg.dist_max = REAL_C(30.0);
    scene_set_camera(s, CAM_OBJECT, vec3_make(0, 0, 0), REAL_C(8.5), 0, 0, &cfg);
}

static void knot_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    struct render_object *o = &s->object[0];

    (void)keys;
    (void)ev;
    if (s->animate) {
        o->rot = mat3_mul(&SCENE_STATE(s, struct knot_state)->spin, &o->rot);
        mat3_renormalize(&o->rot);
    }
}

const struct scene_desc scene_knot_desc = {
    .name = "knot",
    .keys = 0,
    .state_bytes = sizeof(struct knot_state),
    SCENE_DESC_NEEDS(knot),
    .init = knot_init,
    .update = knot_update,
};
