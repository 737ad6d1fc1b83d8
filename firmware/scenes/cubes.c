/*
 * cubes.c — 64 coloured unit cubes on a 4 x 4 x 4 grid, each turning at its own rate; the
 * painter's sort has to interleave the faces of many objects. Orbit mode.
 */
#include "render/palette.h"
#include "scenes/scene.h"

struct cubes_state {
    struct mesh mesh;
    vec3 verts[8];
    struct mesh_face faces[12];
    uvec3 normals[6];
};
SCENE_STATE_FITS(cubes, struct cubes_state);

#define CUBES_PER_SIDE 4
#define CUBES_SPACING REAL_C(2.5)

/* The cubes, x fastest, fill a grid's cells, each turning inside its own (its sphere, radius 0.87,
 * within the 2.5 cell): drawn far to near, unsorted. */
#define CUBES_CORNER (-CUBES_SPACING * CUBES_PER_SIDE / 2)
static const struct scene_grid_layout cubes_grid = {
    {CUBES_CORNER, CUBES_CORNER, CUBES_CORNER},
    {CUBES_SPACING, CUBES_SPACING, CUBES_SPACING},
    {CUBES_PER_SIDE, CUBES_PER_SIDE, CUBES_PER_SIDE},
};

static void cubes_init(struct scene *s)
{
    struct cubes_state *c = SCENE_STATE(s, struct cubes_state);
    struct mesh *m = &c->mesh;
    struct cam_config cfg = scene_default_cam_config();
    const mat3 id = mat3_identity();
    uint32_t n = 0;

    /* The cube [-0.5, 0.5]^3: vertex index = x + 2 y + 4 z over the corner bits. */
    mesh_init(m, c->verts, 8, c->faces, 12, c->normals, 6);
    for (int32_t i = 0; i < 8; i++) {
        mesh_add_vertex(m, vec3_make((i & 1) ? REAL_C(0.5) : REAL_C(-0.5),
                                     (i & 2) ? REAL_C(0.5) : REAL_C(-0.5),
                                     (i & 4) ? REAL_C(0.5) : REAL_C(-0.5)));
    }
    for (uint32_t d = 0; d < 6u; d++) {
        int32_t k[4][3];
        uint16_t q[4];

        mesh_cube_face_corners(d, k);
        for (int j = 0; j < 4; j++) {
            q[j] = (uint16_t)(k[j][0] + 2 * k[j][1] + 4 * k[j][2]);
        }
        mesh_add_quad(m, q[0], q[1], q[2], q[3], mesh_add_normal(m, mesh_cube_face_normal(d)), 0);
    }
    mesh_finish(m);
    (void)mesh_set_quads(m);

    for (int32_t z = 0; z < CUBES_PER_SIDE; z++) {
        for (int32_t y = 0; y < CUBES_PER_SIDE; y++) {
            for (int32_t x = 0; x < CUBES_PER_SIDE; x++) {
                /* centred on the origin: (i - 1.5) * spacing */
                const vec3 pos = vec3_make(CUBES_SPACING * (2 * x - 3) / 2,
                                           CUBES_SPACING * (2 * y - 3) / 2,
                                           CUBES_SPACING * (2 * z - 3) / 2);

                scene_add_quad_object(s, m, &id, pos, (uint8_t)(MAT_RED + n % 8u));
                n++;
            }
        }
    }
    (void)scene_set_grid(s, &cubes_grid);
    cfg.dist_max = REAL_C(50.0);
    scene_set_camera(s, CAM_ORBIT, vec3_make(0, 0, 0), REAL_C(16.0), FX_ANGLE_DEG(30),
                     -(int32_t)(25 * 65536 / 360), &cfg);
}

static void cubes_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    (void)keys;
    (void)ev;
    if (!s->animate) {
        return;
    }
    for (uint32_t i = 0; i < s->object_count; i++) {
        /* Angles from the frame number: exact, nothing accumulates. Rates 1.6 .. 4.6 deg/frame. */
        const fx_angle yaw = (fx_angle)(s->frame * (300u + 37u * i));
        const fx_angle pitch = (fx_angle)(s->frame * (200u + 23u * i));

        s->object[i].rot = mat3_from_yaw_pitch(yaw, pitch);
    }
}

const struct scene_desc scene_cubes_desc = {
    SCENE_DESC_NEEDS(cubes, struct cubes_state),
    .init = cubes_init,
    .update = cubes_update,
};
