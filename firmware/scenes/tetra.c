/*
 * tetra.c — the walking skeleton's tetrahedron, now spinning by accumulated small rotations
 * (re-orthonormalised every frame) in object mode: I/J/K/L and U/O turn it further.
 */
#include "render/palette.h"
#include "scenes/scene.h"

struct tetra_state {
    struct mesh mesh;
    vec3 verts[4];
    struct mesh_face faces[4];
    uvec3 normals[4];
    mat3 spin;      /* rotation applied every animated frame */
};
SCENE_STATE_FITS(tetra, struct tetra_state);

static void tetra_init(struct scene *s)
{
    struct tetra_state *t = SCENE_STATE(s, struct tetra_state);
    struct cam_config cfg = scene_default_cam_config();
    const mat3 yaw = mat3_rotation(1, FX_ANGLE_DEG(6.0));
    const mat3 pitch = mat3_rotation(0, FX_ANGLE_DEG(2.5));
    const mat3 start = mat3_from_yaw_pitch(FX_ANGLE_DEG(30), FX_ANGLE_DEG(20));

    /* Regular tetrahedron: alternate corners of the cube [-1, 1]^3 (circumradius sqrt 3). */
    mesh_init(&t->mesh, t->verts, 4, t->faces, 4, t->normals, 4);
    mesh_add_vertex(&t->mesh, vec3_make(REAL_C(1), REAL_C(1), REAL_C(1)));
    mesh_add_vertex(&t->mesh, vec3_make(REAL_C(1), REAL_C(-1), REAL_C(-1)));
    mesh_add_vertex(&t->mesh, vec3_make(REAL_C(-1), REAL_C(1), REAL_C(-1)));
    mesh_add_vertex(&t->mesh, vec3_make(REAL_C(-1), REAL_C(-1), REAL_C(1)));
    /* Face k is opposite vertex k, wound outwards. */
    mesh_add_face(&t->mesh, 1, 3, 2, MAT_RED);
    mesh_add_face(&t->mesh, 0, 2, 3, MAT_GREEN);
    mesh_add_face(&t->mesh, 0, 3, 1, MAT_BLUE);
    mesh_add_face(&t->mesh, 0, 1, 2, MAT_YELLOW);
    mesh_finish(&t->mesh);

    t->spin = mat3_mul(&yaw, &pitch);
    scene_add_object(s, &t->mesh, &start, vec3_make(0, 0, 0), 0);
    cfg.dist_min = REAL_C(1.5);
    cfg.dist_max = REAL_C(20.0);
    scene_set_camera(s, CAM_OBJECT, vec3_make(0, 0, 0), REAL_C(4.5), 0, 0, &cfg);
}

static void tetra_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    (void)keys;
    (void)ev;
    scene_spin_first(s, &SCENE_STATE(s, struct tetra_state)->spin);
}

const struct scene_desc scene_tetra_desc = {
    SCENE_DESC_NEEDS(tetra, struct tetra_state),
    .init = tetra_init,
    .update = tetra_update,
};
