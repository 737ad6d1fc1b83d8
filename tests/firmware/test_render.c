/*
 * test_render.c — rotation, projection against a double-precision reference, back-face culling,
 * the depth sort and the packed output of a whole frame.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "fixed.h"
#include "gpu.h"
#include "render.h"
#include "scene.h"
#include "unit.h"
#include "xform.h"

#define PI 3.14159265358979323846

static double d(q16_16 v)
{
    return (double)v / 65536.0;
}

static q16_16 rand_q(double lo, double hi)
{
    const double u = (double)unit_rand() / 4294967296.0;

    return (q16_16)llround((lo + u * (hi - lo)) * 65536.0);
}

/* Double-precision R = Rx(pitch) * Ry(yaw), the reference for xf_rot_yx. */
static void ref_rot(double r[3][3], fx_angle yaw, fx_angle pitch)
{
    const double a = 2.0 * PI * yaw / 65536.0;
    const double b = 2.0 * PI * pitch / 65536.0;
    const double sy = sin(a), cy = cos(a), sp = sin(b), cp = cos(b);

    r[0][0] = cy;       r[0][1] = 0.0; r[0][2] = sy;
    r[1][0] = sp * sy;  r[1][1] = cp;  r[1][2] = -sp * cy;
    r[2][0] = -cp * sy; r[2][1] = sp;  r[2][2] = cp * cy;
}

void test_xf_rotation(void)
{
    xf_mat3 r;
    xf_vec3 v;
    const xf_vec3 zero = {0, 0, 0};
    double ref[3][3];

    xf_rot_yx(&r, 0, 0);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            CHECK_EQ(r.m[i][j], (i == j) ? FX_ONE : 0);
        }
    }
    /* Quarter turns are exact: yaw +90 turns +z to +x, pitch +90 turns +y to +z. */
    xf_rot_yx(&r, FX_ANGLE_DEG(90), 0);
    v = xf_transform(&r, (xf_vec3){0, 0, FX_ONE}, zero);
    CHECK_EQ(v.x, FX_ONE);
    CHECK_EQ(v.y, 0);
    CHECK_EQ(v.z, 0);
    xf_rot_yx(&r, 0, FX_ANGLE_DEG(90));
    v = xf_transform(&r, (xf_vec3){0, FX_ONE, 0}, (xf_vec3){FX_CONST(1.0), 0, FX_CONST(5.0)});
    CHECK_EQ(v.x, FX_CONST(1.0));
    CHECK_EQ(v.y, 0);
    CHECK_EQ(v.z, FX_CONST(6.0));

    /* Any angles: entries within 2.5e-4 of the double matrix (sin/cos error < 1e-4, products
     * of two such add up to twice that plus a rounding). */
    for (int i = 0; i < 2000; i++) {
        const fx_angle yaw = (fx_angle)unit_rand();
        const fx_angle pitch = (fx_angle)unit_rand();

        xf_rot_yx(&r, yaw, pitch);
        ref_rot(ref, yaw, pitch);
        for (int a = 0; a < 3; a++) {
            for (int b = 0; b < 3; b++) {
                CHECK(fabs(d(r.m[a][b]) - ref[a][b]) < 2.5e-4);
            }
        }
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/*
 * Projection against double arithmetic. Bound (render.h): the error is one rounding of the
 * offset (<= 0.5 sixteenth of a pixel) plus |x| * 2^-17 from the rounding of p = f/z, so below
 * 0.5 + 64/131072 < 0.501 sixteenths for |x|, |y| <= 64.
 */
void test_render_project_vs_double(void)
{
    const struct render_camera *cam = &scene_camera;
    double max_err = 0.0;
    int projected = 0;

    for (int i = 0; i < 200000; i++) {
        const xf_vec3 v = {rand_q(-64.0, 64.0), rand_q(-64.0, 64.0),
                           rand_q(d(cam->near_z), (i & 1) ? 8.0 : 200.0)};
        const double ex = cam->cx_q4 + cam->focal_q4 * d(v.x) / d(v.z);
        const double ey = cam->cy_q4 - cam->focal_q4 * d(v.y) / d(v.z);
        struct render_vertex pv;
        const enum render_vstate st = render_project(cam, v, &pv);
        const int in_range = ex > -32768.5 && ex < 32767.5 && ey > -32768.5 && ey < 32767.5;
        const int clearly_in = ex > -32767.0 && ex < 32766.0 && ey > -32767.0 && ey < 32766.0;

        if (st == RENDER_V_OK) {
            projected++;
            CHECK(in_range);
            max_err = fmax(max_err, fmax(fabs(pv.sx_q4 - ex), fabs(pv.sy_q4 - ey)));
            CHECK_EQ(pv.depth, ((v.z - cam->near_z) >> 8) > 0xFFFF ? 0xFFFF
                                                                    : (v.z - cam->near_z) >> 8);
        } else {
            CHECK_EQ(st, RENDER_V_RANGE);
            CHECK(!clearly_in);
        }
    }
    if (!(max_err < 0.501)) {
        unit_fail(__FILE__, __LINE__, "max projection error %.4f >= 0.501 (1/16 px)", max_err);
    }
    CHECK(projected > 50000);

    /* Known points: the optical axis lands on the screen centre; one unit right at depth 5 is
     * f/5 = 40 px right of it; one unit up is 40 px higher (y grows downwards). */
    {
        struct render_vertex pv;

        CHECK_EQ(render_project(cam, (xf_vec3){0, 0, FX_CONST(5.0)}, &pv), RENDER_V_OK);
        CHECK_EQ(pv.sx_q4, 160 * 16);
        CHECK_EQ(pv.sy_q4, 120 * 16);
        CHECK_EQ(render_project(cam, (xf_vec3){FX_ONE, FX_ONE, FX_CONST(5.0)}, &pv), RENDER_V_OK);
        CHECK_EQ(pv.sx_q4, 200 * 16);
        CHECK_EQ(pv.sy_q4, 80 * 16);
        CHECK_EQ(pv.depth, (FX_CONST(5.0) - FX_CONST(0.25)) >> 8);
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

void test_render_project_near(void)
{
    const struct render_camera *cam = &scene_camera;
    struct render_vertex pv;

    CHECK_EQ(render_project(cam, (xf_vec3){0, 0, cam->near_z - 1}, &pv), RENDER_V_NEAR);
    CHECK_EQ(pv.state, RENDER_V_NEAR);
    CHECK_EQ(render_project(cam, (xf_vec3){0, 0, -FX_ONE}, &pv), RENDER_V_NEAR);
    CHECK_EQ(render_project(cam, (xf_vec3){0, 0, 0}, &pv), RENDER_V_NEAR);
    CHECK_EQ(render_project(cam, (xf_vec3){FX_ONE, 0, cam->near_z}, &pv), RENDER_V_OK);
    CHECK_EQ(pv.sx_q4, 160 * 16 + 4 * 3200);  /* f / near = 800 px per unit */
    CHECK_EQ(pv.depth, 0);
    CHECK_EQ(fx_overflow_count(), 0);
}

void test_render_project_range(void)
{
    const struct render_camera *cam = &scene_camera;
    struct render_vertex pv;

    /* 64 units right at the near plane: 51200 px, far beyond Q12.4. */
    CHECK_EQ(render_project(cam, (xf_vec3){FX_FROM_INT(64), 0, cam->near_z}, &pv),
             RENDER_V_RANGE);
    CHECK_EQ(render_project(cam, (xf_vec3){0, FX_FROM_INT(-64), cam->near_z}, &pv),
             RENDER_V_RANGE);
    /* Largest x that still fits: sx = 2560 + 3200 * x / 1 <= 32767 -> x <= 9.4396. */
    CHECK_EQ(render_project(cam, (xf_vec3){FX_CONST(9.4396), 0, FX_ONE}, &pv), RENDER_V_OK);
    CHECK_EQ(render_project(cam, (xf_vec3){FX_CONST(9.4400), 0, FX_ONE}, &pv), RENDER_V_RANGE);
    /* Very far: depth clamps. */
    CHECK_EQ(render_project(cam, (xf_vec3){0, 0, FX_FROM_INT(30000)}, &pv), RENDER_V_OK);
    CHECK_EQ(pv.depth, 0xFFFF);
    CHECK_EQ(fx_overflow_count(), 0);
}

void test_render_signed_area(void)
{
    /* Clockwise on screen (y down): right, then down-left. Positive = front. */
    CHECK(render_signed_area(0, 0, 16, 0, 0, 16) > 0);
    CHECK(render_is_front(render_signed_area(0, 0, 16, 0, 0, 16)));
    CHECK_EQ(render_signed_area(0, 0, 16, 0, 0, 16), 256);
    /* Same triangle the other way round: back. */
    CHECK(render_signed_area(0, 0, 0, 16, 16, 0) < 0);
    CHECK(!render_is_front(render_signed_area(0, 0, 0, 16, 16, 0)));
    /* Collinear: zero, culled. */
    CHECK_EQ(render_signed_area(0, 0, 16, 16, 32, 32), 0);
    CHECK(!render_is_front(0));
    /* Rotating the vertex order keeps the sign. */
    CHECK_EQ(render_signed_area(16, 0, 0, 16, 0, 0), 256);
    /* Extremes of Q12.4: the 34-bit result is exact. */
    CHECK_EQ(render_signed_area(-32768, -32768, 32767, -32768, -32768, 32767),
             (int64_t)65535 * 65535);
    CHECK_EQ(render_signed_area(-32768, -32768, -32768, 32767, 32767, -32768),
             -(int64_t)65535 * 65535);
}

void test_render_sort(void)
{
    const int32_t key[5] = {5, 9, 1, 9, 3};
    uint16_t order[5] = {0, 1, 2, 3, 4};
    uint16_t one[1] = {0};

    render_sort_back_to_front(key, order, 5);
    /* Largest (farthest) first; equal keys keep their order (stable). */
    CHECK_EQ(order[0], 1);
    CHECK_EQ(order[1], 3);
    CHECK_EQ(order[2], 0);
    CHECK_EQ(order[3], 4);
    CHECK_EQ(order[4], 2);
    render_sort_back_to_front(key, one, 1);
    CHECK_EQ(one[0], 0);
    render_sort_back_to_front(key, order, 0);  /* nothing to do, must not touch memory */
}

void test_render_sort_random(void)
{
    int32_t key[RENDER_MAX_FACES];
    uint16_t order[RENDER_MAX_FACES];

    for (int round = 0; round < 500; round++) {
        const uint32_t n = 1u + unit_rand() % RENDER_MAX_FACES;
        uint32_t seen[RENDER_MAX_FACES] = {0};

        for (uint32_t i = 0; i < n; i++) {
            key[i] = (int32_t)(unit_rand() % 16u) - 8;  /* many ties */
            order[i] = (uint16_t)i;
        }
        render_sort_back_to_front(key, order, n);
        for (uint32_t i = 0; i < n; i++) {
            seen[order[i]]++;
            if (i > 0) {
                CHECK(key[order[i - 1]] >= key[order[i]]);
                if (key[order[i - 1]] == key[order[i]]) {
                    CHECK(order[i - 1] < order[i]);  /* stable */
                }
            }
        }
        for (uint32_t i = 0; i < n; i++) {
            CHECK_EQ(seen[i], 1);  /* a permutation */
        }
    }
}

/* The scene's mesh: indices in range, one distinct colour per face, faces clockwise seen from
 * outside in the left-handed view frame (equivalently: (b-a) x (c-a) points outwards). */
void test_scene_mesh_valid(void)
{
    const struct render_mesh *m = &scene_tetra;
    double cx = 0.0, cy = 0.0, cz = 0.0;

    CHECK_EQ(m->vert_count, 4);
    CHECK_EQ(m->face_count, 4);
    for (uint32_t i = 0; i < m->vert_count; i++) {
        cx += d(m->verts[i].x) / m->vert_count;
        cy += d(m->verts[i].y) / m->vert_count;
        cz += d(m->verts[i].z) / m->vert_count;
    }
    for (uint32_t f = 0; f < m->face_count; f++) {
        const struct render_face *face = &m->faces[f];
        double p[3][3];
        double e1[3], e2[3], n[3], out[3];

        for (uint32_t g = 0; g < f; g++) {
            CHECK(m->faces[g].color != face->color);
        }
        CHECK(face->color != SCENE_PAL_BG && face->color < SCENE_PAL_COUNT);
        for (int k = 0; k < 3; k++) {
            CHECK(face->v[k] < m->vert_count);
            p[k][0] = d(m->verts[face->v[k]].x);
            p[k][1] = d(m->verts[face->v[k]].y);
            p[k][2] = d(m->verts[face->v[k]].z);
        }
        for (int k = 0; k < 3; k++) {
            e1[k] = p[1][k] - p[0][k];
            e2[k] = p[2][k] - p[0][k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        out[0] = (p[0][0] + p[1][0] + p[2][0]) / 3.0 - cx;
        out[1] = (p[0][1] + p[1][1] + p[2][1]) / 3.0 - cy;
        out[2] = (p[0][2] + p[1][2] + p[2][2]) / 3.0 - cz;
        CHECK(n[0] * out[0] + n[1] * out[1] + n[2] * out[2] > 0.0);
    }
}

static int frame_has_face(const struct render_frame *fr, const struct render_face *face)
{
    for (uint32_t i = 0; i < fr->prim_count; i++) {
        const uint32_t *w = &fr->prim_words[i * GPU_PRIM_WORDS];

        if (((w[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK) == face->v[0] &&
            ((w[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK) == face->v[1] &&
            ((w[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK) == face->v[2]) {
            return 1;
        }
    }
    return 0;
}

/*
 * Culling against geometry, independent of winding: a face of a convex body is visible from
 * the eye (the origin) exactly when the eye is on the outer side of the face's plane. Computed
 * in double from the exact rotation; orientations within 1e-3 of edge-on are skipped.
 */
void test_render_cull_vs_geometry(void)
{
    static struct render_frame fr;
    const struct render_mesh *m = &scene_tetra;
    int compared = 0;

    for (uint32_t yi = 0; yi < 97; yi++) {
        for (uint32_t pi = 0; pi < 61; pi++) {
            const fx_angle yaw = (fx_angle)(yi * 677u);
            const fx_angle pitch = (fx_angle)(pi * 1087u);
            double r[3][3];
            double vv[4][3];
            xf_mat3 rot;

            xf_rot_yx(&rot, yaw, pitch);
            render_mesh_frame(m, &rot, scene_model_pos, &scene_camera, &fr);
            CHECK_EQ(fr.prim_count + fr.culled + fr.dropped_near + fr.dropped_range,
                     m->face_count);
            CHECK_EQ(fr.dropped_near + fr.dropped_range, 0);
            CHECK(fr.prim_count >= 1 && fr.prim_count <= 3);

            ref_rot(r, yaw, pitch);
            for (uint32_t i = 0; i < m->vert_count; i++) {
                const double x = d(m->verts[i].x), y = d(m->verts[i].y), z = d(m->verts[i].z);

                for (int k = 0; k < 3; k++) {
                    vv[i][k] = r[k][0] * x + r[k][1] * y + r[k][2] * z;
                }
                vv[i][2] += d(scene_model_pos.z);
            }
            for (uint32_t f = 0; f < m->face_count; f++) {
                const double *a = vv[m->faces[f].v[0]];
                const double *b = vv[m->faces[f].v[1]];
                const double *c = vv[m->faces[f].v[2]];
                const double *o = vv[f];  /* face f is opposite vertex f: inside the body */
                double e1[3], e2[3], n[3], side, eye, len_n, len_a;

                for (int k = 0; k < 3; k++) {
                    e1[k] = b[k] - a[k];
                    e2[k] = c[k] - a[k];
                }
                n[0] = e1[1] * e2[2] - e1[2] * e2[1];
                n[1] = e1[2] * e2[0] - e1[0] * e2[2];
                n[2] = e1[0] * e2[1] - e1[1] * e2[0];
                side = n[0] * (o[0] - a[0]) + n[1] * (o[1] - a[1]) + n[2] * (o[2] - a[2]);
                if (side > 0.0) {  /* make n point outwards */
                    n[0] = -n[0];
                    n[1] = -n[1];
                    n[2] = -n[2];
                }
                eye = -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]);  /* n . (eye - a) */
                len_n = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                len_a = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
                if (fabs(eye) < 1e-3 * len_n * len_a) {
                    continue;
                }
                compared++;
                CHECK_EQ(frame_has_face(&fr, &m->faces[f]), eye > 0.0);
            }
        }
    }
    CHECK(compared > 97 * 61 * 4 * 9 / 10);
    CHECK_EQ(fx_overflow_count(), 0);
}

/* One frame's packed output, decoded with the contract's field macros. */
void test_render_frame_output(void)
{
    static struct render_frame fr;
    const struct render_mesh *m = &scene_tetra;
    xf_mat3 rot;
    int32_t prev_key = INT32_MAX;

    xf_rot_yx(&rot, SCENE_YAW0, SCENE_PITCH0);
    CHECK_EQ(render_mesh_frame(m, &rot, scene_model_pos, &scene_camera, &fr), fr.prim_count);
    CHECK_EQ(fr.vtx_count, m->vert_count);
    for (uint32_t i = 0; i < fr.vtx_count; i++) {
        const uint32_t *w = &fr.vtx_words[i * GPU_VTX_WORDS];

        CHECK_EQ((int16_t)((w[GPU_VTX_X_WORD] >> GPU_VTX_X_LSB) & GPU_VTX_X_MASK), fr.pv[i].sx_q4);
        CHECK_EQ((int16_t)((w[GPU_VTX_Y_WORD] >> GPU_VTX_Y_LSB) & GPU_VTX_Y_MASK), fr.pv[i].sy_q4);
        CHECK_EQ((w[GPU_VTX_Z_WORD] >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK, fr.pv[i].depth);
        /* The tetrahedron stays well inside the screen. */
        CHECK(fr.pv[i].sx_q4 > 0 && fr.pv[i].sx_q4 < 320 * 16);
        CHECK(fr.pv[i].sy_q4 > 0 && fr.pv[i].sy_q4 < 240 * 16);
    }
    CHECK(fr.prim_count >= 1);
    for (uint32_t i = 0; i < fr.prim_count; i++) {
        const uint32_t *w = &fr.prim_words[i * GPU_PRIM_WORDS];
        const uint32_t i0 = (w[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK;
        const uint32_t i1 = (w[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK;
        const uint32_t i2 = (w[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK;
        const uint32_t color = (w[GPU_PRIM_COLOR_WORD] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK;
        const uint32_t kind = (w[GPU_PRIM_KIND_WORD] >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK;
        const struct render_face *face = NULL;
        int32_t key;

        for (uint32_t f = 0; f < m->face_count; f++) {
            if (m->faces[f].v[0] == i0 && m->faces[f].v[1] == i1 && m->faces[f].v[2] == i2) {
                face = &m->faces[f];
            }
        }
        CHECK(face != NULL);
        if (face == NULL) {
            break;
        }
        CHECK_EQ(color, face->color);
        CHECK_EQ(kind, GPU_PRIM_KIND_TRI);
        CHECK(render_signed_area(fr.pv[i0].sx_q4, fr.pv[i0].sy_q4, fr.pv[i1].sx_q4,
                                 fr.pv[i1].sy_q4, fr.pv[i2].sx_q4, fr.pv[i2].sy_q4) > 0);
        key = (fr.pv[i0].z >> 2) + (fr.pv[i1].z >> 2) + (fr.pv[i2].z >> 2);
        CHECK(key <= prev_key);  /* back to front */
        prev_key = key;
    }

    /* Pushed into the near plane: faces touching a vertex in front of it are dropped and
     * counted, and no primitive refers to such a vertex. */
    {
        const xf_vec3 close = {0, 0, FX_CONST(1.0)};

        xf_rot_yx(&rot, 0, 0);
        render_mesh_frame(m, &rot, close, &scene_camera, &fr);
        CHECK(fr.dropped_near > 0);
        CHECK_EQ(fr.prim_count + fr.culled + fr.dropped_near + fr.dropped_range, m->face_count);
        for (uint32_t i = 0; i < fr.prim_count; i++) {
            const uint32_t *w = &fr.prim_words[i * GPU_PRIM_WORDS];

            CHECK_EQ(fr.pv[(w[0] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK].state, RENDER_V_OK);
            CHECK_EQ(fr.pv[(w[0] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK].state, RENDER_V_OK);
            CHECK_EQ(fr.pv[(w[1] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK].state, RENDER_V_OK);
        }
    }
    CHECK_EQ(fx_overflow_count(), 0);
}
