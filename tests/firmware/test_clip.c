/*
 * test_clip.c — Sutherland-Hodgman against the near plane and the guard band: one, two and three
 * vertices behind the near plane, a vertex (and an edge) exactly on it, guard-band crossings,
 * winding, and that new vertices lie on the original edges.
 */
#include <math.h>
#include <stdint.h>

#include "render/clip.h"
#include "test_util.h"
#include "unit.h"

static struct proj_setup clip_setup(void)
{
    struct proj_setup ps;

    proj_setup_init(&ps, 200, to_real(160.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    return ps;
}

/* Is p on segment a-b (within tolerance)? */
static int on_segment(vec3 p, vec3 a, vec3 b)
{
    const double ab[3] = {rd(b.x) - rd(a.x), rd(b.y) - rd(a.y), rd(b.z) - rd(a.z)};
    const double ap[3] = {rd(p.x) - rd(a.x), rd(p.y) - rd(a.y), rd(p.z) - rd(a.z)};
    const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    const double t = (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2;
    double d2 = 0.0;

    for (int i = 0; i < 3; i++) {
        const double d = ap[i] - t * ab[i];

        d2 += d * d;
    }
    return t >= -1e-6 && t <= 1.0 + 1e-6 && sqrt(d2) < 1e-4;
}

static int same_point(vec3 a, vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

static double signed_area_xz(const struct clip_polygon *p)
{
    double s = 0.0;

    for (uint32_t i = 0; i < p->count; i++) {
        const vec3 a = p->v[i];
        const vec3 b = p->v[(i + 1u) % p->count];

        s += rd(a.x) * rd(b.z) - rd(b.x) * rd(a.z);
    }
    return s / 2.0;
}

void test_clip_one_vertex_behind(void)
{
    const struct proj_setup ps = clip_setup();
    const vec3 a = v3(-1, 0, 2);
    const vec3 b = v3(1, 0, 2);
    const vec3 c = v3(0, 0, -1);  /* behind the eye */
    struct clip_polygon p;

    CHECK_EQ(clip_triangle(&ps, a, b, c, &p), 4);
    CHECK(same_point(p.v[0], a));
    CHECK(same_point(p.v[1], b));
    CHECK_EQ(p.v[2].z, ps.near);  /* new vertices exactly on the plane */
    CHECK_EQ(p.v[3].z, ps.near);
    CHECK(on_segment(p.v[2], b, c));
    CHECK(on_segment(p.v[3], c, a));
    /* The kept part is exactly the part in front: a trapezoid from z = 2 to z = 0.25. */
    CHECK(fabs(fabs(signed_area_xz(&p)) - (2.0 * 1.75 - 1.75 * 1.75 / 3.0)) < 1e-3);
    CHECK(signed_area_xz(&p) < 0);  /* same winding as the triangle (a, b, c): clockwise in xz */
}

void test_clip_two_vertices_behind(void)
{
    const struct proj_setup ps = clip_setup();
    const vec3 a = v3(0, 1, 3);
    const vec3 b = v3(2, 0, -2);
    const vec3 c = v3(-2, 0, -2);
    struct clip_polygon p;

    CHECK_EQ(clip_triangle(&ps, a, b, c, &p), 3);
    CHECK(same_point(p.v[0], a));
    CHECK(on_segment(p.v[1], a, b));
    CHECK(on_segment(p.v[2], c, a));
    CHECK_EQ(p.v[1].z, ps.near);
    CHECK_EQ(p.v[2].z, ps.near);
}

void test_clip_three_vertices_behind(void)
{
    const struct proj_setup ps = clip_setup();
    struct clip_polygon p;

    CHECK_EQ(clip_triangle(&ps, v3(0, 1, 0.2), v3(1, 0, -5), v3(-1, 0, 0), &p), 0);
}

/* A vertex exactly on the near plane is kept as it is and makes no duplicate; an edge on the
 * plane with the third vertex behind leaves nothing with area (count 0). */
void test_clip_vertex_on_plane(void)
{
    const struct proj_setup ps = clip_setup();
    const vec3 on = v3(0.5, 0.5, 0.25);
    struct clip_polygon p;

    /* on + two in front: unchanged. */
    CHECK_EQ(clip_triangle(&ps, on, v3(1, 0, 3), v3(-1, 0, 3), &p), 3);
    CHECK(same_point(p.v[0], on));
    /* on + one in front + one behind: a triangle: on, the front vertex, one new point. */
    CHECK_EQ(clip_triangle(&ps, on, v3(1, 0, 3), v3(-1, 0, -3), &p), 3);
    CHECK(same_point(p.v[0], on));
    CHECK(on_segment(p.v[2], v3(1, 0, 3), v3(-1, 0, -3)));
    for (uint32_t i = 0; i < p.count; i++) {
        for (uint32_t j = i + 1u; j < p.count; j++) {
            CHECK(!same_point(p.v[i], p.v[j]));
        }
    }
    /* Edge on the plane, third vertex behind: only the edge survives, no area. */
    CHECK_EQ(clip_triangle(&ps, on, v3(-0.5, 0.5, 0.25), v3(0, 0, -1), &p), 0);
    /* All three on the plane: kept (in front is z >= near); it projects to a triangle. */
    CHECK_EQ(clip_triangle(&ps, on, v3(-0.5, 0.5, 0.25), v3(0, -0.5, 0.25), &p), 3);
}

/* Guard band: a triangle reaching far outside is cut to the band's planes; every vertex ends up
 * inside (within rounding), and the winding is kept. */
void test_clip_guard_band(void)
{
    const struct proj_setup ps = clip_setup();
    const vec3 a = v3(-200, -1, 2);
    const vec3 b = v3(0, 150, 3);
    const vec3 c = v3(300, -2, 2);
    struct clip_polygon p;
    const double g = rd(ps.guard_slope);

    CHECK(clip_triangle(&ps, a, b, c, &p) >= 3);
    for (uint32_t i = 0; i < p.count; i++) {
        const double x = rd(p.v[i].x);
        const double y = rd(p.v[i].y);
        const double z = rd(p.v[i].z);

        CHECK(fabs(x) <= g * z + 1e-3 && fabs(y) <= g * z + 1e-3 && z >= 0.25);
    }
    /* Near and guard together: a ground plane running from behind the eye to the horizon. */
    CHECK(clip_triangle(&ps, v3(-500, -2, -10), v3(500, -2, -10), v3(0, -2, 150), &p) >= 3);
    for (uint32_t i = 0; i < p.count; i++) {
        CHECK(rd(p.v[i].z) >= 0.25);
        CHECK(fabs(rd(p.v[i].x)) <= g * rd(p.v[i].z) + 1e-3);
    }
    CHECK(p.count <= CLIP_MAX_VERTS);
    CHECK_EQ(fx_overflow_count(), 0);
}

static void sub3(const vec3 a, const vec3 b, double out[3])
{
    out[0] = rd(a.x) - rd(b.x);
    out[1] = rd(a.y) - rd(b.y);
    out[2] = rd(a.z) - rd(b.z);
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Is p inside triangle (a, b, c): within 1e-3 of its plane and on the inner side of each edge line
 * (signed in-plane distance >= -1e-3)? Distances, not barycentrics, so thin triangles behave. */
static int in_triangle(vec3 p, vec3 a, vec3 b, vec3 c)
{
    const vec3 v[3] = {a, b, c};
    double e1[3];
    double e2[3];
    double n[3];
    double q[3];
    double nl;

    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, n);
    nl = sqrt(dot3(n, n));
    if (nl < 1e-6) {
        return 1;  /* degenerate: nothing to check */
    }
    sub3(p, a, q);
    if (fabs(dot3(q, n)) / nl > 1e-3) {
        return 0;
    }
    for (int k = 0; k < 3; k++) {
        double e[3];
        double r[3];
        double s[3];

        sub3(v[(k + 1) % 3], v[k], e);
        sub3(p, v[k], r);
        cross3(e, r, s);
        if (dot3(s, n) / (nl * sqrt(dot3(e, e))) < -1e-3) {
            return 0;
        }
    }
    return 1;
}

/* Random triangles around the eye: the result never has a vertex behind the near plane, every
 * vertex lies in the original triangle, and a triangle entirely inside comes back unchanged. */
void test_clip_random(void)
{
    const struct proj_setup ps = clip_setup();

    for (int i = 0; i < 20000; i++) {
        vec3 t[3];
        struct clip_polygon p;
        int in_front = 1;

        for (int k = 0; k < 3; k++) {
            t[k] = v3(((int32_t)(unit_rand() % 2001u) - 1000) / 100.0,
                      ((int32_t)(unit_rand() % 2001u) - 1000) / 100.0,
                      ((int32_t)(unit_rand() % 2001u) - 700) / 100.0);
            in_front &= rd(t[k].z) >= 0.25 && fabs(rd(t[k].x)) <= rd(ps.guard_slope) * rd(t[k].z) &&
                        fabs(rd(t[k].y)) <= rd(ps.guard_slope) * rd(t[k].z);
        }
        clip_triangle(&ps, t[0], t[1], t[2], &p);
        if (in_front) {
            CHECK_EQ(p.count, 3);
        }
        for (uint32_t j = 0; j < p.count; j++) {
            CHECK(rd(p.v[j].z) >= 0.25);
            CHECK(in_triangle(p.v[j], t[0], t[1], t[2]));
        }
    }
    CHECK_EQ(fx_overflow_count(), 0);
}
