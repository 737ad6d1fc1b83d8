/*
 * scene_export.c — see scene_export.h.
 */
#include "scenes/scene_export.h"

#include "config/build_options.h"
#include "math/real.h"
#include "render/mesh.h"
#include "render/palette.h"
#include "scenes/scene.h"

static void export_mat(const mat3 *m, double out[3][3])
{
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
            out[r][c] = unit_as_double(m->m[r][c]);
        }
    }
}

static void export_apply(const double m[3][3], const double v[3], double out[3])
{
    for (int r = 0; r < 3; r++) {
        out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
    }
}

void scene_export_view(const struct scene *s, struct scene_export_view *out)
{
    out->width = (uint32_t)s->proj.width;
    out->height = (uint32_t)s->proj.height;
    out->cx = s->proj.cx_q4 / 16.0;
    out->cy = s->proj.cy_q4 / 16.0;
    out->focal = s->proj.focal_q4 / 16.0;
    out->near = real_as_double(s->proj.near);
    out->far = real_as_double(s->proj.far);
    out->eye[0] = real_as_double(s->cam.eye.x);
    out->eye[1] = real_as_double(s->cam.eye.y);
    out->eye[2] = real_as_double(s->cam.eye.z);
    out->yaw = s->cam.yaw;
    out->pitch = s->cam.pitch;
    out->light[0] = unit_as_double(s->light.x);
    out->light[1] = unit_as_double(s->light.y);
    out->light[2] = unit_as_double(s->light.z);
    out->ambient = s->ambient;
    out->lit = FW_WITH_LIGHTING ? 1 : 0;
    out->clear_index = PAL_SKY;
    out->palette_entries = PAL_ENTRIES;
    out->tris = 0;
    for (uint32_t i = 0; i < s->object_count; i++) {
        out->tris += s->object[i].mesh->face_count;
    }
}

void scene_export_tris(const struct scene *s, scene_export_tri_fn fn, void *ctx)
{
    double o[3][3];
    const double focus[3] = {real_as_double(s->cam.cfg.focus.x),
                             real_as_double(s->cam.cfg.focus.y),
                             real_as_double(s->cam.cfg.focus.z)};

    export_mat(&s->cam.scene_rot, o);
    for (uint32_t i = 0; i < s->object_count; i++) {
        const struct render_object *obj = &s->object[i];
        const struct mesh *m = obj->mesh;
        const double pos[3] = {real_as_double(obj->pos.x), real_as_double(obj->pos.y),
                               real_as_double(obj->pos.z)};
        double r[3][3];

        export_mat(&obj->rot, r);
        for (uint32_t fi = 0; fi < m->face_count; fi++) {
            struct mesh_face tmp;
            const struct mesh_face *face = mesh_face_at(m, fi, &tmp);
            const uvec3 nu = mesh_normal(m, face->normal);
            const double nm[3] = {unit_as_double(nu.x), unit_as_double(nu.y),
                                  unit_as_double(nu.z)};
            struct scene_export_tri t;
            double nr[3];

            for (int k = 0; k < 3; k++) {
                const vec3 p = m->verts[face->v[k]];
                const double pm[3] = {real_as_double(p.x), real_as_double(p.y),
                                      real_as_double(p.z)};
                double ps[3];

                export_apply(r, pm, ps);
                for (int c = 0; c < 3; c++) {
                    ps[c] += pos[c] - focus[c];
                }
                export_apply(o, ps, t.v[k]);
                for (int c = 0; c < 3; c++) {
                    t.v[k][c] += focus[c];
                }
            }
            export_apply(r, nm, nr);
            export_apply(o, nr, t.n);
            t.material = (obj->material != 0u) ? obj->material : face->material;
            fn(ctx, &t);
        }
    }
}
