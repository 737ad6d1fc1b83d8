/*
 * scene_dump.c — the host build's --dump-scene: every frame's scene, after its update, as the exact
 * reference (tools/exact_ref/exact_ref.c) reads it. Only the scene's data goes out — meshes,
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
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "app/fw_config.h"
#include "bsp.h"
#include "bsp_host.h"
#include "gpu_regs.h"
#include "render/mesh.h"
#include "render/palette.h"
#include "scenes/scene.h"

static double dump_real(real_t r)
{
#if FW_BACKEND_FLOAT
    return (double)r;
#else
    return (double)r / 65536.0;  /* q16_16 */
#endif
}

static double dump_unit(unit_t u)
{
#if FW_BACKEND_FLOAT
    return (double)u;
#else
    return (double)u / 1073741824.0;  /* q2_30 */
#endif
}

static void dump_mat(const mat3 *m, double out[3][3])
{
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            out[r][c] = dump_unit(m->m[r][c]);
        }
    }
}

static void dump_apply(const double m[3][3], const double v[3], double out[3])
{
    for (int r = 0; r < 3; r++) {
        out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
    }
}

void bsp_host_scene_dump(const struct scene *s, const uint16_t *palette, unsigned frame)
{
    const char *dir = bsp_host_dump_dir();
    char path[1024];
    double o[3][3];
    double focus[3];
    uint32_t tris = 0;
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
    dump_mat(&s->cam.scene_rot, o);
    focus[0] = dump_real(s->cam.cfg.focus.x);
    focus[1] = dump_real(s->cam.cfg.focus.y);
    focus[2] = dump_real(s->cam.cfg.focus.z);
    fprintf(f, "exactref-scene 1\n");
    fprintf(f, "screen %u %u %a %a %a %a %a\n", (unsigned)GPU_FB_WIDTH, (unsigned)GPU_FB_HEIGHT,
            s->proj.cx_q4 / 16.0, s->proj.cy_q4 / 16.0, s->proj.focal_q4 / 16.0,
            dump_real(s->proj.near), dump_real(s->proj.far));
    fprintf(f, "camera %a %a %a %u %ld\n", dump_real(s->cam.eye.x), dump_real(s->cam.eye.y),
            dump_real(s->cam.eye.z), (unsigned)s->cam.yaw, (long)s->cam.pitch);
    fprintf(f, "light %a %a %a %u %d\n", dump_unit(s->light.x), dump_unit(s->light.y),
            dump_unit(s->light.z), (unsigned)s->ambient, FW_WITH_LIGHTING ? 1 : 0);
    fprintf(f, "clear %u\npalette", (unsigned)PAL_SKY);
    for (uint32_t i = 0; i < PAL_ENTRIES; i++) {
        fprintf(f, " %03x", (unsigned)palette[i]);
    }
    for (uint32_t i = 0; i < s->object_count; i++) {
        tris += s->object[i].mesh->face_count;
    }
    fprintf(f, "\ntris %lu\n", (unsigned long)tris);
    for (uint32_t i = 0; i < s->object_count; i++) {
        const struct render_object *obj = &s->object[i];
        const struct mesh *m = obj->mesh;
        double r[3][3];
        double pos[3] = {dump_real(obj->pos.x), dump_real(obj->pos.y), dump_real(obj->pos.z)};

        dump_mat(&obj->rot, r);
        for (uint32_t fi = 0; fi < m->face_count; fi++) {
            struct mesh_face tmp;
            const struct mesh_face *face = mesh_face_at(m, fi, &tmp);
            const uvec3 nu = mesh_normal(m, face->normal);
            const double nm[3] = {dump_unit(nu.x), dump_unit(nu.y), dump_unit(nu.z)};
            double nr[3];
            double nw[3];

            fputc('t', f);
            for (int k = 0; k < 3; k++) {
                const vec3 p = m->verts[face->v[k]];
                const double pm[3] = {dump_real(p.x), dump_real(p.y), dump_real(p.z)};
                double ps[3];
                double w[3];

                dump_apply(r, pm, ps);
                for (int c = 0; c < 3; c++) {
                    ps[c] += pos[c] - focus[c];
                }
                dump_apply(o, ps, w);
                fprintf(f, " %a %a %a", w[0] + focus[0], w[1] + focus[1], w[2] + focus[2]);
            }
            dump_apply(r, nm, nr);
            dump_apply(o, nr, nw);
            fprintf(f, " %a %a %a %u\n", nw[0], nw[1], nw[2],
                    (unsigned)((obj->material != 0u) ? obj->material : face->material));
        }
    }
    fclose(f);
}
