/*
 * cam_path.h — a seeded camera path for measurements: with FW_CAMERA_PATH = N (> 0) frame k shows
 * view k mod N of the path instead of the scene's own camera, for `make bench-error`'s camera
 * paths (bench/bench_error.py --path). Off by default (FW_CAMERA_PATH = 0: this file is empty);
 * only app.c includes it, so only app.o differs between a path build and the default one.
 *
 * The path is a function of the view number, the seed FW_CAMERA_PATH_SEED and the scene's default
 * camera (target T, distance D: the scene's own constants), computed in integers only (xorshift32,
 * a sine of its own, app/cam_path_sin.h, Q16.16 products), so that the fixed and the float backend,
 * and every size of the firmware's sine table (FW_SIN_TABLE_BITS, an accuracy knob), on
 * the host and on rv32, set bit-identical cameras: eye coordinates are rounded to 1/256 unit, exact
 * in q16_16 and in a float for |x| < 65536. Views cycle through four kinds (k mod 4):
 *   0 orbit       around T at 0.6 .. 1.2 D, yaw anywhere, pitch -55 .. +35 degrees;
 *   1 fly-through along a line through T (eye from D before T to D past it), looking along it;
 *   2 close-up    at 0.08 .. 0.4 D from T: geometry near and across the near plane;
 *   3 grazing     odd views: pitch -4 .. +2 degrees from T's height (ground planes edge-on);
 *                 even views: steep, |pitch| 78 .. 85 degrees (walls edge-on).
 * The path also stops the animation and leaves out the crosshair (cam_path_start): the views then
 * differ by camera only, and the overlay (which is not scene geometry) is not measured.
 */
#ifndef CAM_PATH_H
#define CAM_PATH_H

#include "app/fw_config.h"

#ifndef FW_CAMERA_PATH
#define FW_CAMERA_PATH 0
#endif
#ifndef FW_CAMERA_PATH_SEED
#define FW_CAMERA_PATH_SEED 1u
#endif

#if FW_CAMERA_PATH

#include <stdint.h>

#include "app/cam_path_sin.h"
#include "camera/camera.h"
#include "math/fixed.h"
#include "math/real.h"
#include "scenes/scene.h"

#define CAM_PATH_DEG(d) ((int32_t)((d) * 65536 / 360))  /* signed turn fraction */

static inline uint32_t cam_path_next(uint32_t *state)
{
    uint32_t x = *state;

    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

/* Uniform in lo .. hi (hi - lo < 2^31). */
static inline int32_t cam_path_range(uint32_t *state, int32_t lo, int32_t hi)
{
    return lo + (int32_t)(cam_path_next(state) % (uint32_t)(hi - lo + 1));
}

/* v * num / 1024 for |v| < 2^26, num <= 2048: int64 keeps it exact. */
static inline int32_t cam_path_scale(int32_t v, int32_t num)
{
    return (int32_t)(((int64_t)v * num) / 1024);
}

/* Before the first frame: no animation, no crosshair. */
static inline void cam_path_start(struct scene *s)
{
    s->animate = false;
    s->crosshair = false;
}

/* The camera of frame `frame`: view frame mod FW_CAMERA_PATH, in fly mode (eye, yaw, pitch). */
static inline void cam_path_apply(struct scene *s, unsigned frame)
{
    const uint32_t k = (uint32_t)frame % (uint32_t)FW_CAMERA_PATH;
    uint32_t st = (FW_CAMERA_PATH_SEED * 2654435761u) ^ ((k + 1u) * 0x9E3779B9u);
    const int32_t t[3] = {real_to_q16(s->target_default.x), real_to_q16(s->target_default.y),
                          real_to_q16(s->target_default.z)};
    const int32_t dist = real_to_q16(s->distance_default);  /* D, Q16.16 */
    int32_t yaw;
    int32_t pitch;
    int32_t d;          /* eye = T - forward * d, Q16.16 */
    int32_t look_yaw;   /* where the eye looks, if not at T */

    for (int i = 0; i < 4; i++) {
        (void)cam_path_next(&st);  /* mix the seed */
    }
    yaw = cam_path_range(&st, 0, 65535);
    switch (k % 4u) {
    case 0u:
        pitch = cam_path_range(&st, CAM_PATH_DEG(-55), CAM_PATH_DEG(35));
        d = cam_path_scale(dist, cam_path_range(&st, 614, 1229));
        look_yaw = yaw;
        break;
    case 1u:
        pitch = cam_path_range(&st, CAM_PATH_DEG(-20), CAM_PATH_DEG(10));
        d = cam_path_scale(dist, cam_path_range(&st, -1024, 1024));
        look_yaw = yaw + cam_path_range(&st, CAM_PATH_DEG(-10), CAM_PATH_DEG(10));
        break;
    case 2u:
        pitch = cam_path_range(&st, CAM_PATH_DEG(-45), CAM_PATH_DEG(30));
        d = cam_path_scale(dist, cam_path_range(&st, 82, 410));
        look_yaw = yaw;
        break;
    default:
        if ((k / 4u) % 2u == 1u) {
            pitch = cam_path_range(&st, CAM_PATH_DEG(-4), CAM_PATH_DEG(2));
            d = cam_path_scale(dist, cam_path_range(&st, 307, 1024));
        } else {
            pitch = cam_path_range(&st, CAM_PATH_DEG(78), CAM_PATH_DEG(85));
            pitch = (cam_path_next(&st) & 1u) ? pitch : -pitch;
            d = cam_path_scale(dist, cam_path_range(&st, 512, 1024));
        }
        look_yaw = yaw;
        break;
    }
    {
        const q16_16 sy = cam_path_sin((uint32_t)yaw);
        const q16_16 cy = cam_path_cos((uint32_t)yaw);
        const q16_16 sp = cam_path_sin((uint32_t)pitch);
        const q16_16 cp = cam_path_cos((uint32_t)pitch);
        const int64_t fwd[3] = {((int64_t)sy * cp) >> 16, sp, ((int64_t)cy * cp) >> 16};
        int32_t eye[3];

        for (int i = 0; i < 3; i++) {
            const int64_t e = (int64_t)t[i] - ((fwd[i] * d) >> 16);

            eye[i] = (int32_t)((e + 128) & ~(int64_t)255);  /* 1/256 unit */
        }
        s->cam.mode = CAM_FLY;
        s->cam.eye = vec3_make(real_from_q16(eye[0]), real_from_q16(eye[1]), real_from_q16(eye[2]));
        s->cam.yaw = (fx_angle)(uint32_t)look_yaw;
        s->cam.pitch = pitch;
    }
}

#endif /* FW_CAMERA_PATH */
#endif /* CAM_PATH_H */
