/*
 * camera.c — see camera.h.
 */
#include "camera/camera.h"

#include "config/hot_path.h"

static real_t cam_clamp(real_t v, real_t lo, real_t hi)
{
    return (v < lo) ? lo : ((v > hi) ? hi : v);
}

static vec3 cam_clamp_box(const struct cam_config *cfg, vec3 p)
{
    return vec3_make(cam_clamp(p.x, cfg->box_min.x, cfg->box_max.x),
                     cam_clamp(p.y, cfg->box_min.y, cfg->box_max.y),
                     cam_clamp(p.z, cfg->box_min.z, cfg->box_max.z));
}

static int32_t cam_clamp_pitch(int32_t pitch)
{
    if (pitch > CAM_PITCH_LIMIT) {
        return CAM_PITCH_LIMIT;
    }
    if (pitch < -CAM_PITCH_LIMIT) {
        return -CAM_PITCH_LIMIT;
    }
    return pitch;
}

mat3 cam_basis(fx_angle yaw, int32_t pitch)
{
    const fx_angle p = (fx_angle)(uint32_t)cam_clamp_pitch(pitch);  /* two's complement wrap */
    const unit_t sy = unit_from_q16(fx_sin(yaw));
    const unit_t cy = unit_from_q16(fx_cos(yaw));
    const unit_t sp = unit_from_q16(fx_sin(p));
    const unit_t cp = unit_from_q16(fx_cos(p));
    mat3 m;

    /* right = (cos y, 0, -sin y); forward = (sin y cos p, sin p, cos y cos p);
     * up = forward x right = (-sin p sin y, cos p, -sin p cos y). Products of two table values:
     * |entries| <= 1, and the rows are orthonormal up to the table's 1e-4. */
    m.m[0][0] = cy;
    m.m[0][1] = 0;
    m.m[0][2] = unit_sub(0, sy);
    m.m[1][0] = unit_sub(0, unit_mul(sp, sy));
    m.m[1][1] = cp;
    m.m[1][2] = unit_sub(0, unit_mul(sp, cy));
    m.m[2][0] = unit_mul(sy, cp);
    m.m[2][1] = sp;
    m.m[2][2] = unit_mul(cy, cp);
    return m;
}

uvec3 cam_forward(const struct camera *cam)
{
    const mat3 b = cam_basis(cam->yaw, cam->pitch);

    return mat3_row(&b, 2);
}

/* Orbit and object modes: the eye follows from target, distance and the basis. */
static void cam_update_eye(struct camera *cam)
{
    if (cam->mode != CAM_FLY) {
        const uvec3 f = cam_forward(cam);

        cam->eye = vec3_sub(cam->target, vec3_along(f, cam->distance));
        /* Keeps the fixed-point range argument even when the orbit would leave the box; the
         * view then no longer centres the target exactly, which only happens at the box edge. */
        cam->eye = cam_clamp_box(&cam->cfg, cam->eye);
    }
}

FW_BUILD_ONCE void cam_init(struct camera *cam, const struct cam_config *cfg, enum cam_mode mode,
                            vec3 target, real_t distance, fx_angle yaw, int32_t pitch)
{
    cam->cfg = *cfg;
    cam->mode = CAM_ORBIT;
    cam->target = cam_clamp_box(cfg, target);
    cam->distance = cam_clamp(distance, cfg->dist_min, cfg->dist_max);
    cam->yaw = yaw;
    cam->pitch = cam_clamp_pitch(pitch);
    cam->scene_rot = mat3_identity();
    cam_update_eye(cam);
    cam->mode = mode;
}

FW_BUILD_ONCE void cam_set_mode(struct camera *cam, enum cam_mode mode)
{
    if (mode == cam->mode) {
        return;
    }
    if (cam->mode == CAM_FLY) {
        /* Look at whatever is `distance` ahead: the view does not jump. */
        cam->target = cam_clamp_box(&cam->cfg, vec3_add(cam->eye, vec3_along(cam_forward(cam),
                                                                             cam->distance)));
    }
    cam->mode = mode;  /* leaving orbit for fly keeps the eye where it was */
    cam_update_eye(cam);
}

void cam_turn_scene(struct camera *cam, int axis, fx_angle angle)
{
    /* A turn about view axis k is V^T Rk V in world coordinates (V = the view basis). */
    const mat3 v = cam_basis(cam->yaw, cam->pitch);
    const mat3 vt = mat3_transpose(&v);
    const mat3 rk = mat3_rotation(axis, angle);
    const mat3 a = mat3_mul(&rk, &v);
    const mat3 turn = mat3_mul(&vt, &a);

    cam->scene_rot = mat3_mul(&turn, &cam->scene_rot);
    mat3_renormalize(&cam->scene_rot);
}

void cam_move(struct camera *cam, int32_t fwd, int32_t side, int32_t rise, int32_t look_x,
              int32_t look_y, int32_t roll, uint32_t mode_steps)
{
    const struct cam_config *cfg = &cam->cfg;
    /* Heading on the ground: counts are <= 255 per frame, so count * step stays small. */
    const unit_t sy = unit_from_q16(fx_sin(cam->yaw));
    const unit_t cy = unit_from_q16(fx_cos(cam->yaw));
    const uvec3 ahead = {sy, 0, cy};
    const uvec3 right = {cy, 0, unit_sub(0, sy)};
    const real_t move_fwd = cfg->move_step * fwd;
    const real_t move_side = cfg->move_step * side;
    const real_t move_rise = cfg->move_step * rise;

    /* Each mode step (press of M) moves one step along fly -> orbit -> object -> fly. */
    for (uint32_t i = 0; i < mode_steps % CAM_MODE_COUNT; i++) {
        cam_set_mode(cam, (enum cam_mode)((cam->mode + 1) % CAM_MODE_COUNT));
    }

    switch (cam->mode) {
    case CAM_FLY:
        cam->eye = vec3_add(cam->eye, vec3_along(ahead, move_fwd));
        cam->eye = vec3_add(cam->eye, vec3_along(right, move_side));
        cam->eye.y = real_add(cam->eye.y, move_rise);
        cam->eye = cam_clamp_box(cfg, cam->eye);
        cam->yaw = (fx_angle)(cam->yaw + look_x * cfg->look_step);
        cam->pitch = cam_clamp_pitch(cam->pitch + look_y * (int32_t)cfg->look_step);
        break;
    case CAM_ORBIT:
    case CAM_OBJECT:
        cam->distance = cam_clamp(real_sub(cam->distance, cfg->zoom_step * fwd), cfg->dist_min,
                                  cfg->dist_max);
        cam->target = vec3_add(cam->target, vec3_along(right, move_side));
        cam->target.y = real_add(cam->target.y, move_rise);
        cam->target = cam_clamp_box(cfg, cam->target);
        if (cam->mode == CAM_ORBIT) {
            cam->yaw = (fx_angle)(cam->yaw + look_x * cfg->look_step);
            cam->pitch = cam_clamp_pitch(cam->pitch + look_y * (int32_t)cfg->look_step);
        } else {
            if (look_y != 0) {
                cam_turn_scene(cam, 0, (fx_angle)(-look_y * cfg->look_step));
            }
            if (look_x != 0) {
                cam_turn_scene(cam, 1, (fx_angle)(look_x * cfg->look_step));
            }
            if (roll != 0) {
                cam_turn_scene(cam, 2, (fx_angle)(-roll * cfg->look_step));
            }
        }
        break;
    default:
        break;
    }
    cam_update_eye(cam);
}

void cam_get_view(const struct camera *cam, real_t eye_offset, struct cam_view *view)
{
    view->rot = cam_basis(cam->yaw, cam->pitch);
    view->eye = vec3_add(cam->eye, vec3_along(mat3_row(&view->rot, 0), eye_offset));
}

const char *cam_mode_name(enum cam_mode mode)
{
    switch (mode) {
    case CAM_FLY:
        return "fly";
    case CAM_ORBIT:
        return "orbit";
    case CAM_OBJECT:
        return "object";
    default:
        return "?";
    }
}
