/*
 * test_camera.c — the three camera modes: pitch at its limits (no singularity, basis still
 * orthonormal), movement and box clamping, mode switches without a jump, object-mode turns.
 */
#include <math.h>
#include <stdint.h>

#include "camera/camera.h"
#include "input/input.h"
#include "scenes/scene.h"  /* scene_camera_keys: the key bindings */
#include "test_util.h"
#include "unit.h"

static struct cam_config test_cfg(void)
{
    struct cam_config c;

    c.box_min = v3(-50, -50, -50);
    c.box_max = v3(50, 50, 50);
    c.dist_min = to_real(1.0);
    c.dist_max = to_real(30.0);
    c.move_step = to_real(0.25);
    c.zoom_step = to_real(0.25);
    c.look_step = (fx_angle)(FX_TURN / 128u);
    c.focus = v3(0, 0, 0);
    return c;
}

static void press(struct camera *cam, enum input_key k, int times)
{
    struct input_counts keys;

    while (times > 0) {
        const int n = (times > 32) ? 32 : times;  /* at most a frame's worth per call */

        input_counts_clear(&keys);
        for (int i = 0; i < n; i++) {
            input_counts_add(&keys, k);
        }
        scene_camera_keys(cam, &keys);
        times -= n;
    }
}

/* Holding look-up (or down) forever stops at +-89 degrees; the basis is still a rotation there,
 * and straight up is never reached, in fly and orbit mode alike. */
void test_cam_pitch_limits(void)
{
    const struct cam_config cfg = test_cfg();
    struct camera cam;

    for (int mode = CAM_FLY; mode <= CAM_ORBIT; mode++) {
        cam_init(&cam, &cfg, (enum cam_mode)mode, v3(0, 0, 0), to_real(10.0), 0, 0);
        press(&cam, KEY_LOOK_UP, 1000);
        CHECK_EQ(cam.pitch, CAM_PITCH_LIMIT);
        {
            const mat3 b = cam_basis(cam.yaw, cam.pitch);
            const uvec3 f = cam_forward(&cam);

            CHECK(mat_ortho_err(&b) < 3e-4);
            CHECK(ud(f.y) > 0.9997 && ud(f.y) < 0.99999);  /* sin 89 = 0.99985, table +-1e-4 */
        }
        press(&cam, KEY_LOOK_DOWN, 5000);
        CHECK_EQ(cam.pitch, -CAM_PITCH_LIMIT);
        {
            const mat3 b = cam_basis(cam.yaw, cam.pitch);

            CHECK(mat_ortho_err(&b) < 3e-4);
        }
        /* Yaw keeps turning at the limit: no gimbal lock. */
        press(&cam, KEY_LOOK_RIGHT, 7);
        CHECK_EQ(cam.yaw, 7u * cfg.look_step);
        if (mode == CAM_ORBIT) {
            /* The orbiting eye stays at the distance, straight below the target here. */
            const vec3 d = vec3_sub(cam.target, cam.eye);

            CHECK(fabs(rd(vec3_length(d)) - 10.0) < 2e-3);
            CHECK(rd(cam.eye.y) > 9.9);  /* looking down from above */
        }
    }
    /* Out-of-range pitches given to the basis are clamped too. */
    {
        const mat3 b = cam_basis(0, 90 * 65536 / 360);
        const mat3 c = cam_basis(0, CAM_PITCH_LIMIT);

        CHECK_EQ(b.m[2][1], c.m[2][1]);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

void test_cam_fly_moves_and_clamps(void)
{
    const struct cam_config cfg = test_cfg();
    struct camera cam;

    cam_init(&cam, &cfg, CAM_FLY, v3(0, 0, 10), to_real(10.0), 0, 0);
    CHECK(fabs(rd(cam.eye.z)) < 1e-3);  /* eye = target - forward * distance */
    press(&cam, KEY_FORWARD, 8);        /* 8 * 0.25 along +z */
    CHECK(fabs(rd(cam.eye.z) - 2.0) < 1e-3 && fabs(rd(cam.eye.x)) < 1e-3);
    press(&cam, KEY_RIGHT, 4);          /* strafe +x */
    CHECK(fabs(rd(cam.eye.x) - 1.0) < 1e-3);
    press(&cam, KEY_UP, 2);
    CHECK(fabs(rd(cam.eye.y) - 0.5) < 1e-3);
    /* Looking up does not make W climb: movement stays on the ground heading. */
    press(&cam, KEY_LOOK_UP, 10);
    press(&cam, KEY_FORWARD, 4);
    CHECK(fabs(rd(cam.eye.y) - 0.5) < 1e-3);
    /* A quarter turn right: W now moves along +x. */
    cam.pitch = 0;
    press(&cam, KEY_LOOK_RIGHT, 32);
    press(&cam, KEY_FORWARD, 4);
    CHECK(fabs(rd(cam.eye.x) - 2.0) < 2e-3);
    /* The box holds however long a key is held. */
    press(&cam, KEY_FORWARD, 100000);
    press(&cam, KEY_DOWN, 100000);
    CHECK(rd(cam.eye.x) <= 50.0 && rd(cam.eye.y) >= -50.0);
    CHECK_EQ(fx_overflow_count(), 0);
}

/* M cycles fly -> orbit -> object -> fly and the view does not jump at any switch. */
void test_cam_mode_cycle(void)
{
    const struct cam_config cfg = test_cfg();
    struct camera cam;
    struct input_counts keys;
    vec3 eye;
    fx_angle yaw;

    cam_init(&cam, &cfg, CAM_FLY, v3(3, 1, 7), to_real(6.0), FX_ANGLE_DEG(40), -5000);
    press(&cam, KEY_FORWARD, 5);
    eye = cam.eye;
    yaw = cam.yaw;
    input_counts_clear(&keys);
    input_counts_add(&keys, KEY_MODE);
    scene_camera_keys(&cam, &keys);
    CHECK_EQ(cam.mode, CAM_ORBIT);
    CHECK(fabs(rd(cam.eye.x) - rd(eye.x)) < 2e-3 && fabs(rd(cam.eye.z) - rd(eye.z)) < 2e-3);
    CHECK_EQ(cam.yaw, yaw);
    press(&cam, KEY_LOOK_LEFT, 5);  /* orbit a little */
    eye = cam.eye;
    scene_camera_keys(&cam, &keys);
    CHECK_EQ(cam.mode, CAM_OBJECT);
    CHECK(fabs(rd(cam.eye.y) - rd(eye.y)) < 2e-3);
    scene_camera_keys(&cam, &keys);
    CHECK_EQ(cam.mode, CAM_FLY);
    CHECK(fabs(rd(cam.eye.x) - rd(eye.x)) < 2e-3 && fabs(rd(cam.eye.z) - rd(eye.z)) < 2e-3);
    /* Two presses in one frame: two steps. */
    input_counts_add(&keys, KEY_MODE);
    scene_camera_keys(&cam, &keys);
    CHECK_EQ(cam.mode, CAM_OBJECT);
    CHECK(cam_mode_name(CAM_OBJECT)[0] == 'o');
}

/* Object mode: 32 presses of J turn the scene a quarter turn about the view's up axis; the
 * rotation stays orthonormal; the eye does not move. */
void test_cam_object_turns(void)
{
    const struct cam_config cfg = test_cfg();
    struct camera cam;
    vec3 eye;
    vec3 p;

    cam_init(&cam, &cfg, CAM_OBJECT, v3(0, 0, 0), to_real(5.0), 0, 0);
    eye = cam.eye;
    press(&cam, KEY_LOOK_RIGHT, 32);
    CHECK(mat_ortho_err(&cam.scene_rot) < 1e-6);
    CHECK(rd(cam.eye.z) == rd(eye.z));
    /* A quarter turn about +y (the view's up): +z goes to +x. */
    p = mat3_apply(&cam.scene_rot, v3(0, 0, 1));
    CHECK(fabs(rd(p.x) - 1.0) < 1e-3 && fabs(rd(p.z)) < 1e-3);
    press(&cam, KEY_LOOK_LEFT, 32);
    press(&cam, KEY_ROLL_RIGHT, 64);
    press(&cam, KEY_ROLL_LEFT, 64);
    press(&cam, KEY_LOOK_UP, 16);
    press(&cam, KEY_LOOK_DOWN, 16);
    p = mat3_apply(&cam.scene_rot, v3(0, 0, 1));
    CHECK(fabs(rd(p.z) - 1.0) < 1e-3);  /* back where it started */
    press(&cam, KEY_BACK, 1000);        /* zoom out to the limit */
    CHECK(fabs(rd(cam.distance) - 30.0) < 1e-3);
    CHECK_EQ(fx_overflow_count(), 0);
}
