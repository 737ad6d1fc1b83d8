/*
 * scene.c — data of the walking-skeleton scene (see scene.h).
 */
#include "scene.h"

#include "gpu.h"

const uint16_t scene_palette[SCENE_PAL_COUNT] = {
    GPU_RGB444(0x0, 0x0, 0x0),  /* 0: black (unused, as at reset) */
    GPU_RGB444(0x1, 0x1, 0x3),  /* 1: background, dark blue */
    GPU_RGB444(0xF, 0x3, 0x2),  /* 2: red */
    GPU_RGB444(0x3, 0xD, 0x3),  /* 3: green */
    GPU_RGB444(0x3, 0x6, 0xF),  /* 4: blue */
    GPU_RGB444(0xF, 0xD, 0x2),  /* 5: yellow */
};

/* Regular tetrahedron: alternate corners of the cube [-1, 1]^3 (edge 2*sqrt(2), circumradius
 * sqrt(3) = 1.73). */
static const xf_vec3 tetra_verts[4] = {
    {FX_CONST(1.0), FX_CONST(1.0), FX_CONST(1.0)},
    {FX_CONST(1.0), FX_CONST(-1.0), FX_CONST(-1.0)},
    {FX_CONST(-1.0), FX_CONST(1.0), FX_CONST(-1.0)},
    {FX_CONST(-1.0), FX_CONST(-1.0), FX_CONST(1.0)},
};

/* Face k is opposite vertex k, listed clockwise seen from outside (render.h). */
static const struct render_face tetra_faces[4] = {
    {{1, 3, 2}, SCENE_PAL_FACE0 + 0u},
    {{0, 2, 3}, SCENE_PAL_FACE0 + 1u},
    {{0, 3, 1}, SCENE_PAL_FACE0 + 2u},
    {{0, 1, 2}, SCENE_PAL_FACE0 + 3u},
};

const struct render_mesh scene_tetra = {
    .verts = tetra_verts,
    .vert_count = 4,
    .faces = tetra_faces,
    .face_count = 4,
};

/* 320 x 240 screen, centre (160, 120) px; focal length 200 px (vertical field of view
 * 2 * atan(120 / 200) = 62 degrees); near plane at 0.25. focal_q4 / near_z = 12800 < 32768. */
const struct render_camera scene_camera = {
    .near_z = FX_CONST(0.25),
    .focal_q4 = 200 * 16,
    .cx_q4 = (int32_t)(GPU_FB_WIDTH / 2u) * 16,
    .cy_q4 = (int32_t)(GPU_FB_HEIGHT / 2u) * 16,
};

/* 4.5 units ahead: the model (radius 1.73, so z >= 2.77, far from the near plane) stays within
 * about +-100 px of the screen centre. */
const xf_vec3 scene_model_pos = {0, 0, FX_CONST(4.5)};
