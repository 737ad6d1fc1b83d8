/*
 * clip.c — see clip.h.
 */
#include "render/clip.h"

#if REAL_IS_FIXED
typedef int64_t clip_value_t;

/* g z in q16_16 units, exact in int64: g < 2^5 (q16_16 < 2^21), z < 2^28. */
static clip_value_t clip_gz(const struct proj_setup *ps, real_t z)
{
    return ((int64_t)ps->guard_slope * z) >> FX_FRAC_BITS;
}
#else
typedef float clip_value_t;

static clip_value_t clip_gz(const struct proj_setup *ps, real_t z)
{
    return ps->guard_slope * z;
}
#endif

static clip_value_t clip_value(const struct proj_setup *ps, vec3 v, enum clip_plane plane)
{
    switch (plane) {
    case CLIP_NEAR:
        return (clip_value_t)v.z - (clip_value_t)ps->near;
    case CLIP_LEFT:
        return (clip_value_t)v.x + clip_gz(ps, v.z);
    case CLIP_RIGHT:
        return clip_gz(ps, v.z) - (clip_value_t)v.x;
    case CLIP_TOP:
        return clip_gz(ps, v.z) - (clip_value_t)v.y;
    case CLIP_BOTTOM:
    default:
        return (clip_value_t)v.y + clip_gz(ps, v.z);
    }
}

int clip_inside(const struct proj_setup *ps, vec3 v, enum clip_plane plane)
{
    return clip_value(ps, v, plane) >= 0;
}

/* a + (b - a) * da / (da - db) for one coordinate; da and db have strictly opposite signs. */
static real_t clip_lerp(real_t a, real_t b, clip_value_t da, clip_value_t db)
{
#if REAL_IS_FIXED
    const int64_t num = ((int64_t)b - a) * da;  /* < 2^29 * 2^31.2 */
    const int64_t den = da - db;                /* > 0 when da > 0 > db, < 0 otherwise */
    const int64_t half = (den > 0) ? den / 2 : -den / 2;
    const int64_t q = ((num >= 0) == (den > 0)) ? (num + half) / den : (num - half) / den;

    return (real_t)(a + q);
#else
    return a + (b - a) * (da / (da - db));
#endif
}

/* An intensity (0 .. 65535) at the same t: fixed, clip_lerp's exact form on the integers ((b - a)
 * da < 2^16 * 2^31.2); float, the same lerp, rounded to nearest and kept in range. */
static int32_t clip_lerp_shade(int32_t a, int32_t b, clip_value_t da, clip_value_t db)
{
#if REAL_IS_FIXED
    return (int32_t)clip_lerp((real_t)a, (real_t)b, da, db);
#else
    const float s = (float)a + (float)(b - a) * (da / (da - db));
    const int32_t r = (int32_t)(s + 0.5f);

    return (r < 0) ? 0 : ((r > 65535) ? 65535 : r);
#endif
}

uint32_t clip_against(const struct proj_setup *ps, struct clip_polygon *poly, enum clip_plane plane)
{
    struct clip_polygon out;
    const uint32_t n = poly->count;

    out.count = 0;
    out.has_shade = poly->has_shade;
    for (uint32_t i = 0; i < n; i++) {
        const vec3 a = poly->v[i];
        const vec3 b = poly->v[(i + 1u) % n];
        const clip_value_t da = clip_value(ps, a, plane);
        const clip_value_t db = clip_value(ps, b, plane);

        if (da >= 0 && out.count < CLIP_MAX_VERTS) {
            if (poly->has_shade) {
                out.shade[out.count] = poly->shade[i];
            }
            out.v[out.count++] = a;
        }
        if (((da > 0 && db < 0) || (da < 0 && db > 0)) && out.count < CLIP_MAX_VERTS) {
            vec3 p;

            p.x = clip_lerp(a.x, b.x, da, db);
            p.y = clip_lerp(a.y, b.y, da, db);
            p.z = (plane == CLIP_NEAR) ? ps->near : clip_lerp(a.z, b.z, da, db);
            if (poly->has_shade) {
                out.shade[out.count] = clip_lerp_shade(poly->shade[i], poly->shade[(i + 1u) % n], da, db);
            }
            out.v[out.count++] = p;
        }
    }
    *poly = out;
    return out.count;
}

static uint32_t clip_run(const struct proj_setup *ps, struct clip_polygon *out);

uint32_t clip_triangle(const struct proj_setup *ps, vec3 a, vec3 b, vec3 c,
                       struct clip_polygon *out)
{
    out->v[0] = a;
    out->v[1] = b;
    out->v[2] = c;
    out->count = 3;
    out->has_shade = false;
    return clip_run(ps, out);
}

uint32_t clip_triangle_shaded(const struct proj_setup *ps, vec3 a, vec3 b, vec3 c,
                              const int32_t shade[3], struct clip_polygon *out)
{
    out->v[0] = a;
    out->v[1] = b;
    out->v[2] = c;
    out->shade[0] = shade[0];
    out->shade[1] = shade[1];
    out->shade[2] = shade[2];
    out->count = 3;
    out->has_shade = true;
    return clip_run(ps, out);
}

static uint32_t clip_run(const struct proj_setup *ps, struct clip_polygon *out)
{
    for (int plane = CLIP_NEAR; plane < CLIP_PLANE_COUNT && out->count >= 3u; plane++) {
        uint32_t outside = 0;

        for (uint32_t i = 0; i < out->count; i++) {
            outside += clip_inside(ps, out->v[i], (enum clip_plane)plane) ? 0u : 1u;
        }
        if (outside != 0u) {
            clip_against(ps, out, (enum clip_plane)plane);
        }
    }
    if (out->count < 3u) {
        out->count = 0;
    }
    return out->count;
}
