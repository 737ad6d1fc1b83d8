/*
 * scene_dump.c — the host build's --dump-scene: every frame's scene, after its update, as the exact
 * reference (bench/exact_ref/exact_ref.c) reads it. Only the scene's data goes out — meshes,
 * object and scene transforms applied, the camera's eye and angles, the light, the palette — none
 * of the pipeline's results (no view transform, projection, culling, clipping, lighting level or
 * order): the reference computes all of those itself, in double.
 *
 * DIR/NNNN.scene, text, one record a line, numbers as C99 hex floats (%a: exact) or integers:
 *   exactref-scene 1
 *   screen W H CX CY F NEAR FAR     framebuffer, centre and focal length in pixels (sx = CX + F x/z,
 *                                   sy = CY - F y/z, y down), near and far distances (view units)
 *   camera EX EY EZ YAW PITCH       eye (world); yaw and pitch as turn fractions (65536 = a turn):
 *                                   rows right (cos y, 0, -sin y), up (-sin p sin y, cos p,
 *                                   -sin p cos y), forward (sin y cos p, sin p, cos y cos p)
 *   light LX LY LZ AMBIENT LIT      unit vector towards the light (world), ambient level 0..15,
 *                                   LIT 0: built without lighting (every face at level 15)
 *   clear INDEX                     palette index of the cleared frame
 *   palette C0 .. C255              RGB444 entries (hex)
 *   tris N                          then N lines:
 *   t X0 Y0 Z0 X1 Y1 Z1 X2 Y2 Z2 NX NY NZ MATERIAL
 *                                   world-space corners in the mesh's winding (front: (v1 - v0) x
 *                                   (v2 - v0) towards the eye), the face's lighting normal (world)
 *                                   and its material (the object's override applied)
 * World = the scene's frame after object mode's rotation O about the focus:
 * w = O (R p + pos - focus) + focus, n = O R n_model (render.h's composition, in double).
 * The numbers come through the scene's export interface (scenes/scene_export.h); this file only
 * formats them.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bsp.h"
#include "bsp_host.h"
#include "scenes/scene_export.h"

static void dump_tri(void *ctx, const struct scene_export_tri *t)
{
    FILE *f = ctx;

    fputc('t', f);
    for (int k = 0; k < 3; k++) {
        fprintf(f, " %a %a %a", t->v[k][0], t->v[k][1], t->v[k][2]);
    }
    fprintf(f, " %a %a %a %u\n", t->n[0], t->n[1], t->n[2], (unsigned)t->material);
}

void bsp_host_scene_dump(const struct scene *s, const uint16_t *palette, unsigned frame)
{
    const char *dir = bsp_host_dump_dir();
    char path[1024];
    struct scene_export_view v;
    FILE *f;

    if (dir == NULL) {
        return;
    }
    snprintf(path, sizeof path, "%s/%04u.scene", dir, frame);
    f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "fw-host: cannot write %s\n", path);
        exit(2);
    }
    scene_export_view(s, &v);
    fprintf(f, "exactref-scene 1\n");
    fprintf(f, "screen %u %u %a %a %a %a %a\n", (unsigned)v.width, (unsigned)v.height,
            v.cx, v.cy, v.focal, v.near, v.far);
    fprintf(f, "camera %a %a %a %u %ld\n", v.eye[0], v.eye[1], v.eye[2], (unsigned)v.yaw,
            (long)v.pitch);
    fprintf(f, "light %a %a %a %u %d\n", v.light[0], v.light[1], v.light[2],
            (unsigned)v.ambient, v.lit);
    fprintf(f, "clear %u\npalette", (unsigned)v.clear_index);
    for (uint32_t i = 0; i < v.palette_entries; i++) {
        fprintf(f, " %03x", (unsigned)palette[i]);
    }
    fprintf(f, "\ntris %lu\n", (unsigned long)v.tris);
    scene_export_tris(s, dump_tri, f);
    fclose(f);
}
