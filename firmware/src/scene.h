/*
 * scene.h — the walking-skeleton scene: one flat-coloured tetrahedron turning in front of the
 * camera. Constant data only.
 */
#ifndef SCENE_H
#define SCENE_H

#include <stdint.h>

#include "fixed.h"
#include "render.h"
#include "xform.h"

/* Palette indices. */
#define SCENE_PAL_BG     1u  /* dark background, the clear colour */
#define SCENE_PAL_FACE0  2u  /* four face colours: 2..5 */
#define SCENE_PAL_COUNT  6u  /* entries in scene_palette */

extern const uint16_t scene_palette[SCENE_PAL_COUNT];  /* RGB444 */
extern const struct render_mesh scene_tetra;
extern const struct render_camera scene_camera;

/* Where the model sits in view space: straight ahead of the camera. */
extern const xf_vec3 scene_model_pos;

/* Model orientation at frame 0, and its change per frame (turn fractions). */
#define SCENE_YAW0        FX_ANGLE_DEG(30)
#define SCENE_PITCH0      FX_ANGLE_DEG(20)
#define SCENE_YAW_STEP    ((fx_angle)(FX_TURN / 48u))   /* 7.5 degrees per frame */
#define SCENE_PITCH_STEP  ((fx_angle)(FX_TURN / 120u))  /* 3 degrees per frame */

#endif /* SCENE_H */
