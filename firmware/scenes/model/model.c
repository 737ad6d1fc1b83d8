/*
 * model.c — see model.h.
 */
#include "scenes/model/model.h"

#include "math/real.h"
#include "render/palette.h"
#include "scenes/scene.h"

SCENE_STATE_FITS(model, struct model_state);

/* The built-in file, linked by firmware.mk as its own object (a weak reference: a program built
 * without one, such as the unit tests' fake platform, finds NULL and says so). */
extern const uint8_t model_builtin[] __attribute__((weak));
extern const uint8_t model_builtin_end[] __attribute__((weak));

static const uint8_t *model_source_file;
static uint32_t model_source_len;

void model_scene_source(const uint8_t *file, uint32_t len)
{
    model_source_file = file;
    model_source_len = len;
}

const uint8_t *model_builtin_file(uint32_t *len)
{
    if (model_builtin == 0 || model_builtin_end == 0) {
        *len = 0;
        return 0;
    }
    *len = (uint32_t)(model_builtin_end - model_builtin);
    return model_builtin;
}

static void model_init(struct scene *s)
{
    struct model_state *st = SCENE_STATE(s, struct model_state);
    struct mesh *m = &st->mesh;
    struct cam_config cfg = scene_default_cam_config();
    const mat3 spin_y = mat3_rotation(1, FX_ANGLE_DEG(1.0));
    const mat3 start = mat3_from_yaw_pitch(FX_ANGLE_DEG(30), FX_ANGLE_DEG(15));
    struct meshfile_info *info = &st->info;
    const uint8_t *file = model_source_file;
    uint32_t len = model_source_len;
    real_t r;

    st->uploaded = file != 0;
    if (file == 0) {
        file = model_builtin_file(&len);
    }
    mesh_init(m, st->verts, FW_MODEL_MAX_VERTS, st->faces, FW_MODEL_MAX_FACES, st->normals,
              FW_MODEL_MAX_FACES);
    info->verts = 0;
    info->faces = 0;
    info->value = 0;
    info->limit = 0;
    st->load_error = (file == 0) ? MESHFILE_E_MISSING
                                 : meshfile_check(file, len, FW_MODEL_MAX_VERTS,
                                                  FW_MODEL_MAX_FACES, info);
    if (st->load_error == MESHFILE_OK && !meshfile_load(file, info, m)) {
        st->load_error = MESHFILE_E_FACE_COUNT;
    }
    if (st->load_error != MESHFILE_OK) {
        mesh_clear(m);
        mesh_finish(m);
    }
    st->spin = spin_y;
    if (m->face_count != 0u) {
        scene_add_object(s, m, &start, vec3_make(0, 0, 0), 0);
    }
    /* The converter centres the model and scales its largest half-extent to 4 units, so the
     * radius is at most 4 sqrt 3 < 7: the camera starts 2.2 radii away, where the bounding
     * sphere fills most of the screen's height. */
    r = (m->radius > REAL_C(0.5)) ? m->radius : REAL_C(0.5);
    cfg.dist_min = real_mul(r, REAL_C(1.1));
    cfg.dist_max = real_mul(r, REAL_C(8.0));
    scene_set_camera(s, CAM_OBJECT, vec3_make(0, 0, 0), real_mul(r, REAL_C(2.2)), 0, 0, &cfg);
}

int model_scene_status(const struct scene *s, struct meshfile_info *info)
{
    const struct model_state *st = SCENE_STATE(s, struct model_state);

    *info = st->info;
    return st->load_error;
}

bool model_scene_uploaded(const struct scene *s)
{
    return SCENE_STATE(s, struct model_state)->uploaded;
}

static void model_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    (void)keys;
    (void)ev;
    scene_spin_first(s, &SCENE_STATE(s, struct model_state)->spin);
}

const struct scene_desc scene_model_desc = {
    SCENE_DESC_NEEDS(model, struct model_state),
    .init = model_init,
    .update = model_update,
};
