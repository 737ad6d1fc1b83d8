/*
 * xform.h — 3-vectors and 3x3 matrices in q16_16 for the camera/model transforms. Pure code.
 *
 * Coordinate frame (model and view alike): x right, y up, z forward, away from the camera
 * (left-handed). A rotation matrix has entries in [-1, 1].
 */
#ifndef XFORM_H
#define XFORM_H

#include "fixed.h"

typedef struct {
    q16_16 x;
    q16_16 y;
    q16_16 z;
} xf_vec3;

typedef struct {
    q16_16 m[3][3];  /* row-major: out.x = m[0][0]*x + m[0][1]*y + m[0][2]*z */
} xf_mat3;

/* R = Rx(pitch) * Ry(yaw): turn by yaw about the y axis, then by pitch about the x axis.
 * With the z axis forward, a positive yaw turns +z towards +x, a positive pitch turns +y towards +z.
 * Entries are products of two sines/cosines (each within [-1, 1]): no overflow. */
void xf_rot_yx(xf_mat3 *r, fx_angle yaw, fx_angle pitch);

/*
 * r * v + t.
 * Range: each |r_ij| <= 1.0 = 2^16 raw and |v_j| < 2^31 raw, so each product is below 2^47 and the
 * sum of three plus t * 2^16 (< 2^47) is below 2^49: exact in the int64 accumulator, rounded once.
 * The result saturates (and counts, see fixed.h) only if it leaves q16_16; for model coordinates
 * within +-64 and |t| <= 1024 per axis it cannot (|r v| <= |v| <= 111 for a rotation).
 */
xf_vec3 xf_transform(const xf_mat3 *r, xf_vec3 v, xf_vec3 t);

#endif /* XFORM_H */
