/*
 * render.h — the geometry pipeline for one mesh: model rotation, view translation, perspective
 * projection to Q12.4 screen coordinates, near-plane rejection, back-face culling and a
 * back-to-front depth sort, producing packed GPU vertex and primitive words.
 *
 * Pure code: takes plain data, fills a caller-owned render_frame, touches no hardware and no
 * globals (apart from fixed.h's sticky overflow counter). Host unit tests run it as is.
 *
 * Conventions:
 *   - view space: x right, y up, z forward (away from the camera), q16_16 units.
 *   - screen: Q12.4 (1/16 px), x right, y down; sx = cx + f*x/z, sy = cy - f*y/z.
 *   - a face is front-facing when its projected vertices v0, v1, v2 give a positive signed area
 *     E_v0v1(v2) in the contract's sense (docs/gpu-contract.md, "Triangle rule"), i.e. they run
 *     clockwise on the screen. Seen from outside the mesh, faces are listed clockwise.
 */
#ifndef RENDER_H
#define RENDER_H

#include <stdbool.h>
#include <stdint.h>

#include "fixed.h"
#include "gpu.h"
#include "xform.h"

#define RENDER_MAX_VERTS 64u
#define RENDER_MAX_FACES 64u

struct render_camera {
    q16_16 near_z;     /* near plane, view-space z; > 0. Vertices with z < near_z are not projected */
    int32_t focal_q4;  /* focal length in 1/16 px, 1 .. 32767 (so focal_q4 * 2^16 fits q16_16) */
    int32_t cx_q4;     /* screen centre, Q12.4 */
    int32_t cy_q4;
};

struct render_face {
    uint16_t v[3];  /* vertex indices, clockwise seen from outside */
    uint8_t color;  /* palette index */
};

struct render_mesh {
    const xf_vec3 *verts;  /* model space; each coordinate within +-64.0 (see xform.h) */
    uint16_t vert_count;   /* <= RENDER_MAX_VERTS */
    const struct render_face *faces;
    uint16_t face_count;   /* <= RENDER_MAX_FACES */
};

/* Projection result of one vertex. */
enum render_vstate {
    RENDER_V_OK = 0,    /* projected; sx, sy, depth valid */
    RENDER_V_NEAR = 1,  /* z < near plane: not projected (needs clipping, a later issue) */
    RENDER_V_RANGE = 2, /* projects outside the Q12.4 range (beyond the guard band) */
};

struct render_vertex {
    int16_t sx_q4;   /* screen x, Q12.4 */
    int16_t sy_q4;   /* screen y, Q12.4 */
    uint16_t depth;  /* (z - near) in 1/256 units, clamped to 0xFFFF; 0 = near */
    uint8_t state;   /* enum render_vstate */
    q16_16 z;        /* view-space z */
};

/* Output of render_mesh_frame: ready for a gpu_batch, plus statistics and scratch. */
struct render_frame {
    uint32_t vtx_words[RENDER_MAX_VERTS * GPU_VTX_WORDS];
    uint32_t prim_words[RENDER_MAX_FACES * GPU_PRIM_WORDS];
    uint32_t vtx_count;      /* vertices packed (all of the mesh's) */
    uint32_t prim_count;     /* primitives packed, back to front */
    uint32_t culled;         /* faces dropped as back-facing or zero-area */
    uint32_t dropped_near;   /* faces dropped because a vertex is in front of the near plane */
    uint32_t dropped_range;  /* faces dropped because a vertex is beyond the Q12.4 range */
    /* scratch, kept here so the pipeline needs no globals and little stack */
    struct render_vertex pv[RENDER_MAX_VERTS];
    int32_t key[RENDER_MAX_FACES];
    uint16_t order[RENDER_MAX_FACES];
};

/*
 * Project a view-space point.
 * Range: p = focal_q4 / z is formed once per vertex with fx_div; z >= near_z keeps it within
 * q16_16 when focal_q4 / near_z < 32768 (e.g. 3200 / 0.25 = 12800). The offsets x * p and y * p
 * are exact int64 products (|x|, |p| < 2^31, so < 2^62) scaled by 2^-32 with one rounding; a
 * result outside int16 gives RENDER_V_RANGE. Error against exact arithmetic: < 1/16 px + tiny
 * (one rounding of the offset, plus p's rounding of < 2^-17 relative).
 */
enum render_vstate render_project(const struct render_camera *cam, xf_vec3 v,
                                  struct render_vertex *out);

/* The contract's edge function E_v0v1(v2) = (x1-x0)(y2-y0) - (y1-y0)(x2-x0) on Q12.4 coordinates.
 * Operands are 17-bit differences, products 33 bits, result 34 bits: exact in int64. */
int64_t render_signed_area(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2,
                           int32_t y2);

/* Front-facing: positive signed area (clockwise on screen). Zero area counts as back-facing. */
static inline bool render_is_front(int64_t area)
{
    return area > 0;
}

/* Sort order[0 .. n-1] so that key[order[i]] is non-increasing: largest key (farthest) first, so
 * nearer faces are drawn later and overwrite. Stable insertion sort: n is tiny. */
void render_sort_back_to_front(const int32_t *key, uint16_t *order, uint32_t n);

/* Run the pipeline: every vertex through view = rot * v + pos, projected and packed; every face
 * with all vertices projected and a positive area is packed, back to front. Returns prim_count. */
uint32_t render_mesh_frame(const struct render_mesh *mesh, const xf_mat3 *rot, xf_vec3 pos,
                           const struct render_camera *cam, struct render_frame *out);

#endif /* RENDER_H */
