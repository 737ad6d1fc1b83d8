/*
 * clip.h — Sutherland-Hodgman clipping of a view-space triangle against the near plane and, where
 * needed, the guard-band planes of proj.h. Pure code.
 *
 * Only triangles with a vertex in front of the near plane (z < near) or beyond the guard band get
 * here (render.c); everything else goes to the GPU unclipped. The result is a convex polygon of up
 * to CLIP_MAX_VERTS vertices, all with z >= near and |x|, |y| <= g z (up to rounding, which the
 * guard band's margin absorbs), fanned back into triangles by the caller.
 *
 * Plane values (>= 0 inside): near z - near; left x + g z; right g z - x; top g z - y;
 * bottom y + g z. A vertex with value exactly 0 is inside and is kept as it is; a new vertex is made
 * only for an edge whose ends are strictly on opposite sides, at t = da / (da - db) — so a vertex
 * on the plane never produces a duplicate. On the near plane the new vertex gets z = near exactly.
 *
 * Fixed point: plane values are int64 in q16_16 units (|x| < 2^28, g z < 2^31: < 2^31.2); the
 * new coordinate a + (b - a) da / (da - db) is formed exactly, (b - a) da < 2^29 * 2^31.2, and
 * rounded once by the division. Cost does not matter here: few triangles cross a plane.
 */
#ifndef CLIP_H
#define CLIP_H

#include <stdbool.h>
#include <stdint.h>

#include "render/proj.h"
#include "math/vec.h"

#define CLIP_MAX_VERTS 9u  /* 3, plus at most one per plane for a convex polygon (5 planes), +1 */

enum clip_plane {
    CLIP_NEAR = 0,
    CLIP_LEFT,
    CLIP_RIGHT,
    CLIP_TOP,
    CLIP_BOTTOM,
    CLIP_PLANE_COUNT
};

/* shade: a Gouraud vertex intensity (Q4.12, 0 .. 65535) per vertex, carried through the clip when
 * has_shade: a new vertex gets a + (b - a) t, rounded like its coordinates (t the same), so it lies
 * on the intensity plane of the triangle up to that rounding. */
struct clip_polygon {
    vec3 v[CLIP_MAX_VERTS];
    int32_t shade[CLIP_MAX_VERTS];
    uint32_t count;
    bool has_shade;
};

/* Clip the polygon in place against one plane; returns the new vertex count (0: all outside). */
uint32_t clip_against(const struct proj_setup *ps, struct clip_polygon *poly, enum clip_plane plane);

/* Clip triangle (a, b, c) against the near plane and every guard plane one of its vertices is
 * outside of. Returns the vertex count of *out (0, or 3 .. CLIP_MAX_VERTS), winding preserved. */
uint32_t clip_triangle(const struct proj_setup *ps, vec3 a, vec3 b, vec3 c,
                       struct clip_polygon *out);
/* The same, carrying the three vertices' intensities shade[0..2] (0 .. 65535) into out->shade. */
uint32_t clip_triangle_shaded(const struct proj_setup *ps, vec3 a, vec3 b, vec3 c,
                              const int32_t shade[3], struct clip_polygon *out);

/* True when v is inside (value >= 0) the plane. */
int clip_inside(const struct proj_setup *ps, vec3 v, enum clip_plane plane);

#endif /* CLIP_H */
