/*
 * proj.c — see proj.h.
 */
#include "render/proj.h"

void proj_setup_init(struct proj_setup *ps, int32_t focal_px, real_t far)
{
    const int32_t cx_px = (int32_t)(GPU_FB_WIDTH / 2u);
    const int32_t cy_px = (int32_t)(GPU_FB_HEIGHT / 2u);
    const int32_t w_px = (int32_t)GPU_FB_WIDTH;
    const int32_t h_px = (int32_t)GPU_FB_HEIGHT;

    focal_px = (focal_px < 64) ? 64 : ((focal_px > 255) ? 255 : focal_px);
    ps->focal_q4 = focal_px * 16;
    ps->cx_q4 = cx_px * 16;
    ps->cy_q4 = cy_px * 16;
    ps->near = PROJ_NEAR;
    ps->far = far;
    /* 24576 / focal_q4 with focal_q4 >= 1024: at most 24, inside q16_16. */
    ps->guard_slope = real_div(real_from_int(PROJ_GUARD_Q4), real_from_int(ps->focal_q4));
    ps->focal_hi = (uint32_t)ps->focal_q4 << 19;
    ps->zbuf = false;
    /* A plane through the eye and a screen edge: the inside is where sx (or sy) is on the
     * screen's side. Left edge sx = 0: f x + cx z >= 0, normal (f, 0, cx); right edge sx = W:
     * -f x + (W - cx) z >= 0; top edge sy = 0 (view y up): -f y + cy z >= 0; bottom edge sy = H:
     * f y + (H - cy) z >= 0. */
    ps->edge_plane[0] = vec3_direction(vec3_make(real_from_int(focal_px), 0, real_from_int(cx_px)));
    ps->edge_plane[1] = vec3_direction(vec3_make(real_from_int(-focal_px), 0,
                                                 real_from_int(w_px - cx_px)));
    ps->edge_plane[2] = vec3_direction(vec3_make(0, real_from_int(-focal_px), real_from_int(cy_px)));
    ps->edge_plane[3] = vec3_direction(vec3_make(0, real_from_int(focal_px),
                                                 real_from_int(h_px - cy_px)));
}
