/*
 * proj.c — see proj.h.
 */
#include "render/proj.h"

#include "config/hot_path.h"

FW_BUILD_ONCE void proj_setup_init(struct proj_setup *ps, int32_t focal_px, real_t far,
                                   uint32_t width, uint32_t height)
{
    const int32_t w_px = (int32_t)width;
    const int32_t h_px = (int32_t)height;
    const int32_t cx_px = w_px / 2;
    const int32_t cy_px = h_px / 2;
    int32_t focal_q4;
    real_t focal;

    focal_px = (focal_px < PROJ_FOCAL_MIN_PX) ? PROJ_FOCAL_MIN_PX
                                              : ((focal_px > PROJ_FOCAL_MAX_PX) ? PROJ_FOCAL_MAX_PX
                                                                                : focal_px);
    /* Scaled to the frame's height, rounded; at the reference height exactly 16 focal_px. Kept
     * within 1024 .. 8160 (proj.h's range argument: a frame of fewer lines than the reference
     * keeps the reference's smallest focal length). */
    focal_q4 = (16 * focal_px * h_px + PROJ_FOCAL_REF_LINES / 2) / PROJ_FOCAL_REF_LINES;
    focal_q4 = (focal_q4 < 16 * PROJ_FOCAL_MIN_PX) ? 16 * PROJ_FOCAL_MIN_PX : focal_q4;
    ps->focal_q4 = focal_q4;
    ps->cx_q4 = cx_px * 16;
    ps->cy_q4 = cy_px * 16;
    ps->x_last = 16 * (w_px - 1) + 8;
    ps->y_last = 16 * (h_px - 1) + 8;
    ps->width = w_px;
    ps->height = h_px;
    ps->near = PROJ_NEAR;
    ps->far = far;
    /* 24576 / focal_q4 with focal_q4 >= 1024: at most 24, inside q16_16. */
    ps->guard_slope = real_div(real_from_int(PROJ_GUARD_Q4), real_from_int(focal_q4));
    /* Q's multiplier: the larger shift where it fits 31 bits (proj.h). */
    ps->off_shift = (focal_q4 < 4096) ? 21 : 20;
    ps->focal_hi = (uint32_t)focal_q4 << (ps->off_shift - 2);
    ps->zbuf = false;
    /* A plane through the eye and a screen edge: the inside is where sx (or sy) is on the
     * screen's side. Left edge sx = 0: f x + cx z >= 0, normal (f, 0, cx); right edge sx = W:
     * -f x + (W - cx) z >= 0; top edge sy = 0 (view y up): -f y + cy z >= 0; bottom edge sy = H:
     * f y + (H - cy) z >= 0. */
    focal = real_div(real_from_int(focal_q4), real_from_int(16));  /* exact: q4 in q16_16 */
    ps->edge_plane[0] = vec3_direction(vec3_make(focal, 0, real_from_int(cx_px)));
    ps->edge_plane[1] = vec3_direction(vec3_make(-focal, 0, real_from_int(w_px - cx_px)));
    ps->edge_plane[2] = vec3_direction(vec3_make(0, -focal, real_from_int(cy_px)));
    ps->edge_plane[3] = vec3_direction(vec3_make(0, focal, real_from_int(h_px - cy_px)));
}
