/*
 * xform.c — see xform.h.
 */
#include "xform.h"

void xf_rot_yx(xf_mat3 *r, fx_angle yaw, fx_angle pitch)
{
    const q16_16 sy = fx_sin(yaw);
    const q16_16 cy = fx_cos(yaw);
    const q16_16 sp = fx_sin(pitch);
    const q16_16 cp = fx_cos(pitch);

    /*      | 1  0    0  |        |  cy  0  sy |
     * Rx = | 0  cp  -sp |   Ry = |  0   1  0  |   R = Rx * Ry
     *      | 0  sp   cp |        | -sy  0  cy |
     */
    r->m[0][0] = cy;
    r->m[0][1] = 0;
    r->m[0][2] = sy;
    r->m[1][0] = fx_mul(sp, sy);
    r->m[1][1] = cp;
    r->m[1][2] = -fx_mul(sp, cy);
    r->m[2][0] = -fx_mul(cp, sy);
    r->m[2][1] = sp;
    r->m[2][2] = fx_mul(cp, cy);
}

static q16_16 xf_row(const q16_16 row[3], xf_vec3 v, q16_16 t)
{
    int64_t acc = (int64_t)row[0] * v.x + (int64_t)row[1] * v.y + (int64_t)row[2] * v.z;

    acc += (int64_t)t * FX_ONE + FX_HALF;
    return fx_sat64(acc >> FX_FRAC_BITS);
}

xf_vec3 xf_transform(const xf_mat3 *r, xf_vec3 v, xf_vec3 t)
{
    xf_vec3 out;

    out.x = xf_row(r->m[0], v, t.x);
    out.y = xf_row(r->m[1], v, t.y);
    out.z = xf_row(r->m[2], v, t.z);
    return out;
}
