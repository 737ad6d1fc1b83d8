/*
 * scene_export.h — a frame's scene as plain numbers, for tools outside the firmware: the host
 * build's --dump-scene (bsp/host/scene_dump.c), which writes it for the exact reference
 * (bench/exact_ref). The reader sees doubles and indices only, never the scene's, the meshes' or
 * the pipeline's types: the scene stays opaque (struct scene), so the host BSP depends on this
 * interface and not on scenes/, render/ or app/.
 *
 * Only the scene's data goes out — meshes with the object and scene transforms applied, the
 * camera's eye and angles, the light — none of the pipeline's results (no view transform,
 * projection, culling, clipping, lighting level or order): the reference computes those itself.
 * Values are exact conversions of the backend's numbers; the composition is done in double:
 * world = O (R p + pos - focus) + focus, n = O R n_model (O: object mode's rotation about the focus).
 *
 * Host only (firmware.mk builds scene_export.c into the host programs): the target has no use for
 * doubles.
 */
#ifndef SCENE_EXPORT_H
#define SCENE_EXPORT_H

#include <stdint.h>

struct scene;

struct scene_export_view {
    uint32_t width, height;   /* the frame, pixels */
    double cx, cy, focal;     /* screen centre and focal length, pixels (sx = cx + focal x/z) */
    double near, far;         /* view units */
    double eye[3];            /* world */
    uint32_t yaw;             /* turn fraction, 65536 = a turn */
    int32_t pitch;            /* signed turn fraction */
    double light[3];          /* unit vector towards the light, world */
    uint32_t ambient;         /* 0 .. 15 */
    int lit;                  /* 0: built without lighting (every face at level 15) */
    uint32_t clear_index;     /* palette index of the cleared frame */
    uint32_t palette_entries; /* entries of the palette the frame loop passes along */
    uint32_t tris;            /* triangles scene_export_tris reports */
};

struct scene_export_tri {
    double v[3][3];     /* world-space corners in the mesh's winding */
    double n[3];        /* the face's lighting normal, world */
    uint32_t material;  /* the object's override applied */
};

void scene_export_view(const struct scene *s, struct scene_export_view *out);

/* Every triangle of every object, object by object in mesh order. */
typedef void (*scene_export_tri_fn)(void *ctx, const struct scene_export_tri *t);
void scene_export_tris(const struct scene *s, scene_export_tri_fn fn, void *ctx);

#endif /* SCENE_EXPORT_H */
