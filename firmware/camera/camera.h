/*
 * camera.h — the three camera modes and their moves. Pure code; the keys that drive them are bound
 * by the caller (scene_camera_keys in scenes/scene.c), so the camera knows nothing of input.
 *
 *   fly     the eye moves (W/A/S/D along the ground heading, space/C up and down) and looks
 *           (J/L yaw, I/K pitch): the Minecraft project's map.
 *   orbit   the eye circles a target at a distance: J/L and I/K swing it around, W/S zoom,
 *           A/D and space/C move the target (FPGA 360's gimbal mode).
 *   object  the view stays; I/K, J/L and U/O turn the scene about its focus point around the
 *           view's right, up and forward axes (the tetrahedron and ECE 385 projects). W/S zoom.
 *
 * M cycles fly -> orbit -> object -> fly without a jump: entering orbit from fly puts the target
 * `distance` ahead of the eye, leaving orbit puts the fly eye where the orbiting eye was.
 *
 * Orientation: fly and orbit keep yaw (wrapping turn fraction) and pitch (clamped to
 * +-CAM_PITCH_LIMIT = 89 degrees) and rebuild the basis from them every frame with sines and
 * cosines only — no division, no normalisation, so no singularity even at the limit, and nothing
 * to drift. The object-mode rotation is different: it accumulates arbitrary small rotations, so it
 * is re-orthonormalised (mat3_renormalize) after every change.
 *
 * Ranges (fixed backend): the eye and the target are clamped to the scene's box, which scenes keep
 * within +-1024 per axis (real.h); the distance to [dist_min, dist_max].
 */
#ifndef CAMERA_H
#define CAMERA_H

#include <stdint.h>

#include "math/vec.h"

enum cam_mode {
    CAM_FLY = 0,
    CAM_ORBIT = 1,
    CAM_OBJECT = 2,
    CAM_MODE_COUNT = 3
};

/* 89 degrees as a signed turn fraction (65536 = one turn). */
#define CAM_PITCH_LIMIT ((int32_t)(89 * 65536 / 360))

struct cam_config {
    vec3 box_min;         /* the eye and the target stay inside this box (within +-1024) */
    vec3 box_max;
    real_t dist_min;      /* orbit distance limits, > 0 */
    real_t dist_max;
    real_t move_step;     /* units per key press */
    real_t zoom_step;
    fx_angle look_step;   /* turn per key press */
    vec3 focus;           /* object mode turns the scene about this point */
};

struct camera {
    enum cam_mode mode;
    vec3 eye;             /* fly: the eye; orbit/object: derived, target - forward * distance */
    vec3 target;          /* orbit/object: the point looked at */
    real_t distance;
    fx_angle yaw;         /* heading: 0 looks along +z, a quarter turn along +x */
    int32_t pitch;        /* signed turn fraction, positive looks up, |pitch| <= CAM_PITCH_LIMIT */
    mat3 scene_rot;       /* object mode: the scene's rotation about cfg.focus, orthonormal */
    struct cam_config cfg;
};

/* The view of one frame (or one eye): v_view = rot * (w - eye). Rows of rot are the camera's
 * right, up and forward axes in world coordinates. */
struct cam_view {
    mat3 rot;
    vec3 eye;
};

/* Start in `mode` looking at `target` from `distance` with the given yaw and pitch (pitch is
 * clamped); scene_rot starts as the identity. */
void cam_init(struct camera *cam, const struct cam_config *cfg, enum cam_mode mode, vec3 target,
              real_t distance, fx_angle yaw, int32_t pitch);

/* Switch mode, keeping the view (see the top of this file). */
void cam_set_mode(struct camera *cam, enum cam_mode mode);

/* Apply one frame's moves, each a signed count of steps (a key press is one; the key bindings
 * are the caller's, scene_camera_keys): fwd forward (fly) or zoom in (orbit, object), side to the
 * right, rise up, look_x to the right and look_y up (object mode: turn the scene), roll (object
 * mode). The mode_steps steps along fly -> orbit -> object -> fly are taken first, so the moves
 * act in the new mode. Counts stay small
 * (a frame reads at most 32 keys), so count * step cannot overflow. */
void cam_move(struct camera *cam, int32_t fwd, int32_t side, int32_t rise, int32_t look_x,
              int32_t look_y, int32_t roll, uint32_t mode_steps);

/* Turn the scene by `angle` about view axis `axis` (0 right, 1 up, 2 forward) and
 * re-orthonormalise. Object-mode keys use it; tests call it a million times. */
void cam_turn_scene(struct camera *cam, int axis, fx_angle angle);

/* Basis rows (right, up, forward) for a yaw and a pitch. */
mat3 cam_basis(fx_angle yaw, int32_t pitch);

/* The view for this frame; eye_offset shifts the eye along the right axis (anaglyph stereo). */
void cam_get_view(const struct camera *cam, real_t eye_offset, struct cam_view *view);

/* The forward axis (where the crosshair points). */
uvec3 cam_forward(const struct camera *cam);

const char *cam_mode_name(enum cam_mode mode);

#endif /* CAMERA_H */
