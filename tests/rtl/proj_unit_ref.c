/*
 * proj_unit_ref.c — the firmware's fixed-point projection, as the reference for soc_proj_unit
 * (tests/rtl/proj_unit_tb.cpp): proj_setup_init, proj_unit_regs, xf_apply and proj_point_impl,
 * compiled from the firmware's own sources (the RTL shares none of them).
 */
#include "render/proj.h"
#include "render/proj_unit.h"

#include "proj_unit_ref.h"

/* The model-view transform of rotation m (q2_30, row-major) and translation t (q16_16). */
static xf_affine ref_transform(const int32_t m[9], const int32_t t[3])
{
    xf_affine mv;

    for (int i = 0; i < 9; i++) {
        mv.r.m[i / 3][i % 3] = m[i];
    }
    mv.t = vec3_make(t[0], t[1], t[2]);
    return mv;
}

/* The projection set-up of the firmware's proj_setup_init, with or without the depth buffer. */
static struct proj_setup ref_setup(int32_t focal_px, int32_t far_q16, uint32_t width,
                                   uint32_t height, int zbuf)
{
    struct proj_setup ps;

    proj_setup_init(&ps, focal_px, far_q16, width, height);
    ps.zbuf = zbuf != 0;
    return ps;
}

void proj_ref_regs(int32_t focal_px, int32_t far_q16, uint32_t width, uint32_t height, int zbuf,
                   const int32_t m[9], const int32_t t[3], uint32_t regs[PROJ_REF_REGS])
{
    const struct proj_setup ps = ref_setup(focal_px, far_q16, width, height, zbuf);
    const xf_affine mv = ref_transform(m, t);

    proj_unit_regs(&ps, &mv, regs);
}

void proj_ref_point(int32_t focal_px, int32_t far_q16, uint32_t width, uint32_t height, int zbuf,
                    const int32_t m[9], const int32_t t[3], const int32_t v[3], int inside,
                    uint32_t words[3])
{
    const struct proj_setup ps = ref_setup(focal_px, far_q16, width, height, zbuf);
    const xf_affine mv = ref_transform(m, t);
    const vec3 view = xf_apply(&mv, vec3_make(v[0], v[1], v[2]));
    struct proj_vertex out;

    if (inside) {
        proj_point_inside(&ps, view, &out);
    } else {
        proj_point(&ps, view, &out);
    }
    words[0] = out.sxy;
    words[1] = out.zd;
    words[2] = out.code;
}

uint32_t proj_ref_view_z(const int32_t m[9], const int32_t t[3], const int32_t v[3])
{
    const xf_affine mv = ref_transform(m, t);

    return (uint32_t)xf_apply(&mv, vec3_make(v[0], v[1], v[2])).z;
}
