/*
 * test_render.c — the frame pipeline per object: back-face culling, frustum culling per triangle
 * and per object (bounding sphere), near-plane clipping that neither drops nor mirrors, the
 * painter's order (far first, stable), wireframe with and without GPU lines, flat lighting,
 * anaglyph colours, the overlay, and running out of room; the lattice face loop against the
 * general one.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/batch.h"
#include "render/palette.h"
#include "render/render.h"
#include "test_frame.h"
#include "test_util.h"
#include "unit.h"


/* Camera at the origin looking along +z, no scene rotation, light from behind the camera. */
static void setup_pass(struct render_pass *pass)
{
    struct proj_setup ps;
    struct cam_view view;
    const mat3 id = mat3_identity();

    proj_setup_init(&ps, 200, to_real(160.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    view.rot = mat3_identity();
    view.eye = v3(0, 0, 0);
    render_pass_init(pass, &ps, &view, &id, v3(0, 0, 0), u3(0, 0, -1), 4);
}

/* A mesh of independent triangles given as 3 points each (storage static per call site). */
struct tri_mesh {
    struct mesh m;
    vec3 v[96];
    struct mesh_face f[32];
    uvec3 n[32];
};

static void tri_mesh_init(struct tri_mesh *t)
{
    mesh_init(&t->m, t->v, 96, t->f, 32, t->n, 32);
}

static void tri_mesh_add(struct tri_mesh *t, vec3 a, vec3 b, vec3 c, uint8_t mat)
{
    const uint16_t i = mesh_add_vertex(&t->m, a);

    mesh_add_vertex(&t->m, b);
    mesh_add_vertex(&t->m, c);
    mesh_add_face(&t->m, i, (uint16_t)(i + 1u), (uint16_t)(i + 2u), mat);
}

/* A mesh of one unit triangle at depth z, (0,0) (0,1) (1,0): facing an eye at the origin that
 * looks along +z. */
static void tri_mesh_unit(struct tri_mesh *t, double z, uint8_t mat)
{
    tri_mesh_init(t);
    tri_mesh_add(t, v3(0, 0, z), v3(0, 1, z), v3(1, 0, z), mat);
    mesh_finish(&t->m);
}

static void draw(const struct render_pass *pass, const struct mesh *m, vec3 pos, uint8_t mat)
{
    struct render_object o = {0};

    o.mesh = m;

    o.faces = render_general_faces_loop;
    o.rot = mat3_identity();
    o.pos = pos;
    o.material = mat;
    o.levels = 0;
    render_object(&test_frame, pass, &o);
}

static void begin(void)
{
    render_frame_begin(&test_frame);
    render_stats_clear(&test_frame.stats);
}

/* A frame of one object: m at the origin, its own materials. */
static void draw_alone(const struct render_pass *pass, const struct mesh *m)
{
    begin();
    draw(pass, m, v3(0, 0, 0), 0);
}

/* Edge-function test of a pixel centre against an emitted triangle (either winding). */
static int covers(const struct render_prim *p, int px, int py)
{
    const int64_t x = 16 * px + 8;
    const int64_t y = 16 * py + 8;
    int64_t e[3];

    for (int k = 0; k < 3; k++) {
        const struct proj_vertex *a = &test_frame.vert[p->v[k]];
        const struct proj_vertex *b = &test_frame.vert[p->v[(k + 1) % 3]];

        e[k] = (int64_t)(b->sx - a->sx) * (y - a->sy) - (int64_t)(b->sy - a->sy) * (x - a->sx);
    }
    return (e[0] >= 0 && e[1] >= 0 && e[2] >= 0) || (e[0] <= 0 && e[1] <= 0 && e[2] <= 0);
}

void test_render_backface(void)
{
    static struct tri_mesh t;
    struct render_pass pass;

    setup_pass(&pass);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 1, 3), v3(1, 0, 3), MAT_RED);  /* faces the eye (-z) */
    tri_mesh_add(&t, v3(0, 0, 4), v3(1, 0, 4), v3(0, 1, 4), MAT_RED);  /* faces away */
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim_count, 1);
    CHECK_EQ(test_frame.stats.faces_back, 1);
    CHECK_EQ(test_frame.stats.faces_emitted, 1);
    CHECK_EQ(test_frame.prim[0].kind, GPU_PRIM_KIND_TRI);
    /* The kept face has a positive signed area in the contract's sense. */
    CHECK(proj_signed_area(&test_frame.vert[test_frame.prim[0].v[0]], &test_frame.vert[test_frame.prim[0].v[1]],
                           &test_frame.vert[test_frame.prim[0].v[2]]) > 0);
    /* Edge-on: zero area counts as back-facing. */
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 0, 4), v3(0, 1, 3), MAT_RED);  /* in the plane x = 0 */
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim_count, 0);
    CHECK_EQ(test_frame.stats.faces_back, 1);
}

/* The level cache of a static mesh: the same colours as without it, in the first frame (filled
 * lazily) and in the next (looked up); a new light empties it. */
void test_render_level_cache(void)
{
    static struct tri_mesh t;
    static uint8_t level[32];
    struct render_level_cache cache;
    struct render_prim plain[8];
    struct render_pass pass;
    struct render_object o = {0};
    uint32_t n;

    setup_pass(&pass);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 1, 3), v3(1, 0, 3), MAT_RED);        /* faces the light */
    tri_mesh_add(&t, v3(-2, 0, 3), v3(-2, 1, 4), v3(-1, 0, 3), MAT_GRASS);   /* tilted */
    tri_mesh_add(&t, v3(0, -2, 4), v3(0, -1, 3), v3(1, -2, 4), MAT_STONE);   /* tilted */
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    n = test_frame.prim_count;
    CHECK_EQ(n, 3);
    memcpy(plain, test_frame.prim, n * sizeof plain[0]);

    render_level_cache_init(&cache, level, 32);
    o.mesh = &t.m;
    o.faces = render_general_faces_loop;
    o.rot = mat3_identity();
    o.pos = v3(0, 0, 0);
    o.material = 0;
    o.levels = &cache;
    for (int rep = 0; rep < 2; rep++) {
        begin();
        render_object(&test_frame, &pass, &o);
        CHECK_EQ(test_frame.prim_count, n);
        CHECK(memcmp(test_frame.prim, plain, n * sizeof plain[0]) == 0);
        CHECK(cache.valid);
        CHECK(level[t.m.faces[0].normal] <= 15u);
    }
    /* Another light: the cache is emptied and refilled, and agrees with the uncached path. */
    pass.light_scene = u3(0.6, 0.0, -0.8);
    draw_alone(&pass, &t.m);
    memcpy(plain, test_frame.prim, n * sizeof plain[0]);
    begin();
    render_object(&test_frame, &pass, &o);
    CHECK(memcmp(test_frame.prim, plain, n * sizeof plain[0]) == 0);
    {
        /* the cache holds the light in model space, as render_object forms it */
        const uvec3 l = mat3_apply_transposed_unit_fast(&o.rot, pass.light_scene);

        CHECK(cache.light.x == l.x && cache.light.y == l.y && cache.light.z == l.z);
    }
    /* Filled ahead for the pass's light (setup_pass: identity scene, light u3(0, 0, -1),
     * ambient 4): every entry set, and the frame is the one the lazy path drew. */
    {
        const mat3 id = mat3_identity();

        render_level_cache_init(&cache, level, 32);
        setup_pass(&pass);
        render_level_cache_fill(&o, &id, u3(0, 0, -1), 4);
        CHECK(cache.valid);
        for (uint32_t i = 0; i < t.m.normal_count; i++) {
            CHECK(level[i] <= 15u);
        }
        begin();
        draw(&pass, &t.m, v3(0, 0, 0), 0);
        memcpy(plain, test_frame.prim, n * sizeof plain[0]);
        begin();
        render_object(&test_frame, &pass, &o);
        CHECK(memcmp(test_frame.prim, plain, n * sizeof plain[0]) == 0);
        CHECK(cache.valid);
    }
}

/* Per triangle: three vertices beyond one screen edge (or all beyond far, or all behind) are
 * culled, while another triangle of the same object is drawn. Per object: a bounding sphere
 * outside the frustum skips the whole object before any vertex is transformed. */
void test_render_frustum_culling(void)
{
    static struct tri_mesh t;
    struct render_pass pass;

    setup_pass(&pass);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 1, 3), v3(1, 0, 3), MAT_RED);        /* visible */
    tri_mesh_add(&t, v3(10, 0, 3), v3(10, 1, 3), v3(11, 0, 3), MAT_RED);     /* right of it */
    tri_mesh_add(&t, v3(0, -9, 3), v3(0, -8, 3), v3(1, -9, 3), MAT_RED);     /* below */
    tri_mesh_add(&t, v3(0, 0, 170), v3(0, 1, 170), v3(1, 0, 170), MAT_RED);  /* beyond far */
    tri_mesh_add(&t, v3(0, 0, -3), v3(1, 0, -3), v3(0, 1, -3), MAT_RED);     /* behind */
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim_count, 1);
    CHECK_EQ(test_frame.stats.faces_frustum, 4);
    CHECK_EQ(test_frame.stats.objects_culled, 0);

    tri_mesh_unit(&t, 0, MAT_RED);
    begin();
    draw(&pass, &t.m, v3(0, 0, -5), 0);    /* behind the eye */
    draw(&pass, &t.m, v3(0, 0, 200), 0);   /* beyond far */
    draw(&pass, &t.m, v3(-50, 0, 5), 0);   /* left */
    draw(&pass, &t.m, v3(50, 0, 5), 0);    /* right */
    draw(&pass, &t.m, v3(0, 50, 5), 0);    /* above */
    draw(&pass, &t.m, v3(0, -50, 5), 0);   /* below */
    CHECK_EQ(test_frame.stats.objects_culled, 6);
    CHECK_EQ(test_frame.stats.faces_culled_object, 6);
    CHECK_EQ(test_frame.vert_count, 0);  /* nothing was even transformed */
    draw(&pass, &t.m, v3(-0.5, 0, 5), 0);
    CHECK_EQ(test_frame.stats.objects_culled, 6);
    CHECK_EQ(test_frame.prim_count, 1);
    /* A sphere straddling an edge plane is kept; inside, crossing and outside are told apart
     * (the left edge plane at z = 5 is at x = -4; the near plane at z = 0.25). */
    CHECK(render_sphere_visible(&pass.proj, v3(-4.1, 0, 5), to_real(0.5)));
    CHECK(!render_sphere_visible(&pass.proj, v3(-5.0, 0, 5), to_real(0.5)));
    CHECK_EQ(render_sphere_classify(&pass.proj, v3(-4.1, 0, 5), to_real(0.5)), RENDER_SPHERE_CROSSING);
    CHECK_EQ(render_sphere_classify(&pass.proj, v3(-3.0, 0, 5), to_real(0.5)), RENDER_SPHERE_INSIDE);
    CHECK_EQ(render_sphere_classify(&pass.proj, v3(0, 0, 0.6), to_real(0.5)), RENDER_SPHERE_CROSSING);
    CHECK_EQ(render_sphere_classify(&pass.proj, v3(0, 0, 159.8), to_real(0.5)), RENDER_SPHERE_CROSSING);
    CHECK_EQ(render_sphere_classify(&pass.proj, v3(0, 0, 161), to_real(0.5)), RENDER_SPHERE_OUTSIDE);
}

/* An object inside the frustum takes the shortcut (no outcodes) and an object crossing an edge
 * the full path; both give the same primitives for the faces they share. */
void test_render_inside_shortcut(void)
{
    static struct tri_mesh t;
    struct render_pass pass;
    struct render_prim inside[2];
    struct proj_vertex inside_v[6];

    setup_pass(&pass);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 0), v3(0, 0.5, 0), v3(0.5, 0, 0), MAT_RED);
    tri_mesh_add(&t, v3(0, 0, 0), v3(0.5, 0, 0), v3(0, 0.5, 0), MAT_RED);  /* back */
    mesh_finish(&t.m);
    begin();
    draw(&pass, &t.m, v3(0, 0, 5), 0);  /* well inside */
    CHECK_EQ(test_frame.prim_count, 1);
    CHECK_EQ(test_frame.vert[0].code, 0);
    memcpy(inside, test_frame.prim, sizeof inside);
    memcpy(inside_v, test_frame.vert, sizeof inside_v);
    /* Same object, same view position, but a far plane that cuts its sphere: full path. */
    pass.proj.far = to_real(5.1);
    begin();
    draw(&pass, &t.m, v3(0, 0, 5), 0);
    CHECK_EQ(test_frame.prim_count, 1);
    CHECK_EQ(test_frame.stats.faces_back, 1);
    CHECK(memcmp(&test_frame.prim[0], &inside[0], sizeof inside[0]) == 0);
    for (int k = 0; k < 3; k++) {
        CHECK_EQ(test_frame.vert[k].sxy, inside_v[k].sxy);
        CHECK_EQ(test_frame.vert[k].depth, inside_v[k].depth);
    }
}

/* A floor running from behind the eye to far ahead: its triangles cross the near plane. They are
 * cut, not dropped (the pixels just in front are covered), and not mirrored (a floor triangle
 * to the left stays on the left). */
void test_render_near_clipping(void)
{
    static struct tri_mesh t;
    struct render_pass pass;
    int covered = 0;

    setup_pass(&pass);
    tri_mesh_init(&t);
    /* Floor y = -1, facing up: wound so (b - a) x (c - a) = +y. */
    tri_mesh_add(&t, v3(-2, -1, -3), v3(-2, -1, 10), v3(2, -1, 10), MAT_GREEN);
    tri_mesh_add(&t, v3(-2, -1, -3), v3(2, -1, 10), v3(2, -1, -3), MAT_GREEN);
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.stats.faces_clipped, 2);
    CHECK(test_frame.prim_count >= 2);
    for (uint32_t i = 0; i < test_frame.prim_count; i++) {
        for (int k = 0; k < 3; k++) {
            CHECK((test_frame.vert[test_frame.prim[i].v[k]].code & PROJ_CLIP_BITS) == 0);
        }
        covered |= covers(&test_frame.prim[i], 160, 239);  /* bottom centre: floor right in front */
        CHECK(proj_signed_area(&test_frame.vert[test_frame.prim[i].v[0]], &test_frame.vert[test_frame.prim[i].v[1]],
                               &test_frame.vert[test_frame.prim[i].v[2]]) >= 0);
    }
    CHECK(covered);

    /* Left of the eye, partly behind it: everything drawn stays in the left half. */
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(-3, -1, 2), v3(-1, -1, 2), v3(-2, -1, -5), MAT_GREEN);  /* faces up */
    mesh_finish(&t.m);
    draw_alone(&pass, &t.m);
    CHECK(test_frame.prim_count >= 1);
    for (uint32_t i = 0; i < test_frame.prim_count; i++) {
        for (int k = 0; k < 3; k++) {
            CHECK(test_frame.vert[test_frame.prim[i].v[k]].sx <= 2560);
        }
    }
    CHECK_EQ(fx_overflow_count(), 0);
}

/* After render_sort the farther primitive comes first; equal depths keep emission order. */
void test_render_painter_order(void)
{
    static struct tri_mesh near_t;
    static struct tri_mesh far_t;
    struct render_pass pass;

    setup_pass(&pass);
    tri_mesh_unit(&near_t, 2, MAT_RED);
    tri_mesh_unit(&far_t, 4, MAT_BLUE);
    begin();
    draw(&pass, &near_t.m, v3(0, 0, 0), 0);
    draw(&pass, &far_t.m, v3(0, 0, 0), 0);
    draw(&pass, &near_t.m, v3(0, 0, 0), MAT_YELLOW);  /* same depth as the first, later */
    CHECK(render_depth_key(&test_frame, 1) > render_depth_key(&test_frame, 0));
    render_sort(&test_frame);
    CHECK_EQ(render_draw_index(&test_frame, 0), 1);  /* far first */
    CHECK_EQ(render_draw_index(&test_frame, 1), 0);  /* then the two near ones, in emission order */
    CHECK_EQ(render_draw_index(&test_frame, 2), 2);
    /* Many primitives: the draw order is non-increasing in depth. */
    begin();
    for (int i = 0; i < 300; i++) {
        draw(&pass, &near_t.m, v3(((int)(unit_rand() % 200u) - 100) / 100.0, 0,
                                  (double)(unit_rand() % 1000u) / 10.0),
             0);
    }
    {
        uint16_t keys[TEST_FRAME_PRIMS];

        for (uint32_t i = 0; i < test_frame.prim_count; i++) {
            keys[i] = render_depth_key(&test_frame, i);
        }
        render_sort(&test_frame);
        for (uint32_t i = 1; i < test_frame.prim_count; i++) {
            CHECK(keys[render_draw_index(&test_frame, i - 1u)] >= keys[render_draw_index(&test_frame, i)]);
        }
    }
}

/* The GPU LINE primitives batch.c makes of the frame (in draw order), as (from, to) pairs of
 * frame vertices: a batch's slots mapped back through the vertices' positions. */
static uint32_t wire_lines(uint32_t lines[][2], uint32_t max)
{
    static uint32_t vtx[GPU_VTX_CAP * GPU_VTX_WORDS];
    static uint32_t prim[GPU_TRI_CAP * GPU_PRIM_WORDS];
    struct batch_words w = BATCH_WORDS_ON(vtx, prim);
    struct batch_cursor cur;
    uint32_t n = 0;

    batch_begin(&cur);
    while (!batch_done(&cur, &test_frame)) {
        batch_fill(&cur, &test_frame, GPU_VTX_CAP, GPU_TRI_CAP, &w);
        for (uint32_t i = 0; i < w.prim_count && n < max; i++) {
            const uint32_t *pw = &prim[i * GPU_PRIM_WORDS];
            const uint32_t slot[2] = {pw[0] & 0xFFFFu, pw[0] >> 16};

            CHECK_EQ(pw[1] >> GPU_PRIM_KIND_LSB, GPU_PRIM_KIND_LINE);
            CHECK_EQ(pw[1] & 0xFFFFu, slot[1]);  /* I2 repeats I1 */
            for (int k = 0; k < 2; k++) {
                uint32_t v = 0;

                while (v < test_frame.vert_count && test_frame.vert[v].sxy != vtx[slot[k] * GPU_VTX_WORDS]) {
                    v++;
                }
                lines[n][k] = v;
            }
            n++;
        }
    }
    return n;
}

/* Wireframe: with GPU lines, one outline primitive per front triangle (the frame a filled pass
 * needs), which the batch expands into its three lines, a closed loop; a clipped polygon's fan
 * outlines the polygon only (n lines for n vertices, no inner diagonal). Without GPU lines, each
 * edge becomes two thin triangles on four new vertices; back faces draw nothing either way. */
void test_render_wireframe(void)
{
    static struct tri_mesh t;
    static struct tri_mesh floor;
    struct render_pass pass;
    uint32_t lines[64][2];
    uint32_t n;

    setup_pass(&pass);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 1, 3), v3(1, 0, 3), MAT_RED);
    tri_mesh_add(&t, v3(0, 0, 4), v3(1, 0, 4), v3(0, 1, 4), MAT_RED);  /* back */
    mesh_finish(&t.m);
    pass.wireframe = true;
    pass.gpu_lines = true;
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim_count, 1);
    CHECK_EQ(test_frame.outline_count, 1);
    CHECK_EQ(test_frame.prim[0].kind, RENDER_PRIM_OUTLINE | 0x07u);
    CHECK_EQ(test_frame.stats.faces_back, 1);
    render_sort(&test_frame);
    n = wire_lines(lines, 64);
    CHECK_EQ(n, 3);
    for (uint32_t i = 0; i < 3; i++) {
        CHECK_EQ(lines[i][0], test_frame.prim[0].v[i]);
        CHECK_EQ(lines[i][1], lines[(i + 1u) % 3u][0]);  /* a closed outline */
    }

    /* A floor crossing the near plane: each face clipped to a polygon, outlined edge by edge. */
    tri_mesh_init(&floor);
    tri_mesh_add(&floor, v3(-2, -1, -3), v3(-2, -1, 10), v3(2, -1, 10), MAT_GREEN);
    mesh_finish(&floor.m);
    begin();
    draw(&pass, &floor.m, v3(0, 0, 0), 0);
    CHECK_EQ(test_frame.stats.faces_clipped, 1);
    CHECK(test_frame.prim_count >= 2u);  /* a fan: the polygon has 4 or more vertices */
    render_sort(&test_frame);
    n = wire_lines(lines, 64);
    CHECK_EQ(n, test_frame.prim_count + 2u);  /* n - 2 triangles outline n edges */
    for (uint32_t i = 0; i < n; i++) {
        CHECK_EQ(lines[i][1], lines[(i + 1u) % n][0]);  /* one closed loop, in order */
        CHECK(lines[i][0] != lines[i][1]);
    }

    pass.gpu_lines = false;
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim_count, 6);
    CHECK_EQ(test_frame.vert_count, 6u + 12u);
    CHECK_EQ(test_frame.outline_count, 0);
    for (uint32_t i = 0; i < 6; i++) {
        const struct render_prim *p = &test_frame.prim[i];

        CHECK_EQ(p->kind, GPU_PRIM_KIND_TRI);
        /* one pixel wide: the quad's two long sides are 16 sixteenths apart */
        CHECK(proj_signed_area(&test_frame.vert[p->v[0]], &test_frame.vert[p->v[1]], &test_frame.vert[p->v[2]]) != 0);
    }
}

/* Flat light: a face turned to the light gets the full level, the object's material overrides
 * the face's, the anaglyph eye's ramp overrides both. */
void test_render_lighting_and_colour(void)
{
    static struct tri_mesh t;
    struct render_pass pass;

    setup_pass(&pass);  /* light towards -z: straight at the faces that face the eye */
    tri_mesh_unit(&t, 3, MAT_RED);
    draw_alone(&pass, &t.m);
    CHECK_EQ(test_frame.prim[0].color, PAL_INDEX(MAT_RED, 15u));
    draw(&pass, &t.m, v3(0, 0, 0), MAT_BLUE);
    CHECK_EQ(test_frame.prim[1].color, PAL_INDEX(MAT_BLUE, 15u));
    pass.eye_material = MAT_ANAGLYPH_LEFT;
    draw(&pass, &t.m, v3(0, 0, 0), MAT_BLUE);
    CHECK_EQ(test_frame.prim[2].color, PAL_INDEX(MAT_ANAGLYPH_LEFT, 15u));
    /* Light from the side (towards +x), perpendicular to the face's normal: ambient only. */
    {
        struct cam_view view;
        const mat3 id = mat3_identity();
        struct proj_setup ps;

        proj_setup_init(&ps, 200, to_real(160.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
        view.rot = mat3_identity();
        view.eye = v3(0, 0, 0);
        render_pass_init(&pass, &ps, &view, &id, v3(0, 0, 0), u3(1, 0, 0), 4);
        begin();
        draw(&pass, &t.m, v3(0, 0, 0), 0);
        CHECK_EQ(test_frame.prim[0].color, PAL_INDEX(MAT_RED, 4u));
    }
}

/* The crosshair comes after the sorted primitives and stays last. */
void test_render_overlay(void)
{
    static struct tri_mesh t;
    struct render_pass pass;

    setup_pass(&pass);
    tri_mesh_unit(&t, 3, MAT_RED);
    draw_alone(&pass, &t.m);
    draw(&pass, &t.m, v3(0, 0, 1), 0);
    render_sort(&test_frame);
    render_overlay_crosshair(&test_frame, &pass, 5, PAL_WHITE);
    CHECK_EQ(test_frame.sorted_count, 2);
    CHECK_EQ(test_frame.prim_count, 4);
    CHECK_EQ(render_draw_index(&test_frame, 2), 2);
    CHECK_EQ(render_draw_index(&test_frame, 3), 3);
    CHECK_EQ(test_frame.prim[3].kind, GPU_PRIM_KIND_LINE);
    CHECK_EQ(test_frame.prim[3].color, PAL_WHITE);
    pass.gpu_lines = false;
    render_overlay_crosshair(&test_frame, &pass, 5, PAL_WHITE);
    CHECK_EQ(test_frame.prim_count, 8);
    CHECK_EQ(test_frame.prim[7].kind, GPU_PRIM_KIND_TRI);
}

/* More primitives than the frame holds: the excess is counted, nothing is written past the
 * arrays, and what fits is intact. (3000 faces on the same three vertices per object.) */
void test_render_capacity(void)
{
    static struct mesh m;
    static vec3 v[3];
    static struct mesh_face f[3000];
    static uvec3 n[1];
    struct render_pass pass;

    setup_pass(&pass);
    mesh_init(&m, v, 3, f, 3000, n, 1);
    mesh_add_normal(&m, u3(0, 0, -1));
    mesh_add_vertex(&m, v3(0, 0, 3));
    mesh_add_vertex(&m, v3(0, 1, 3));
    mesh_add_vertex(&m, v3(1, 0, 3));
    for (uint32_t i = 0; i < 3000u; i++) {
        mesh_add_face_normal(&m, 0, 1, 2, 0, MAT_RED);
    }
    mesh_finish(&m);
    CHECK(!m.full);
    begin();
    for (int k = 0; k < 6; k++) {
        draw(&pass, &m, v3(0, 0, 0), 0);
    }
    CHECK_EQ(test_frame.prim_count, TEST_FRAME_PRIMS);
    CHECK_EQ(test_frame.stats.dropped, 6u * 3000u - TEST_FRAME_PRIMS);
    CHECK_EQ(test_frame.vert_count, 18);
    render_sort(&test_frame);
    CHECK_EQ(test_frame.sorted_count, TEST_FRAME_PRIMS);
}

/* Model coordinates beyond +-8192 would wrap in xf_apply's unchecked vertex loop: mesh_finish
 * counts such a mesh once (fx_overflow_note), so the breach is never silent (`make stress`'s
 * "beyond the world rule" case found it silent); a mesh just inside the limit counts nothing. */
void test_render_mesh_model_range(void)
{
    static struct tri_mesh t;

    fx_overflow_clear();
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(-8191.5, 0, 3), v3(0, 8191.5, 3), v3(8191.5, 0, -8191.5), MAT_RED);
    mesh_finish(&t.m);
    CHECK_EQ(fx_overflow_count(), 0);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, 1, 3), v3(8192, 0, 3), MAT_RED);
    mesh_finish(&t.m);
    CHECK_EQ(fx_overflow_count(), 1);
    tri_mesh_init(&t);
    tri_mesh_add(&t, v3(0, 0, 3), v3(0, -20000, 3), v3(1, 0, 3), MAT_RED);
    mesh_finish(&t.m);
    CHECK_EQ(fx_overflow_count(), 2);
    fx_overflow_clear();
}

/* ---- the lattice face loop -------------------------------------------------------------- */

/* A lattice mesh (mesh.h) of LAT_R x LAT_C quads over random heights, built face by face as the
 * landscape builds its tiles: quad (r, c) split along a-c' when (r + c + diag0) is even. */
#define LAT_R 5
#define LAT_C 6
#define LAT_VERTS ((LAT_R + 1) * (LAT_C + 1))
#define LAT_FACES (2 * LAT_R * LAT_C)

struct lat_mesh {
    struct mesh m;
    vec3 v[LAT_VERTS];
    struct mesh_face f[LAT_FACES];
    uvec3 n[LAT_FACES];
    int16_t vnormal[3 * LAT_VERTS];
};

/* The mesh's (LAT_R + 1) x (LAT_C + 1) vertices: a regular x-z lattice at random heights, each
 * with an upward vertex normal. */
static void lat_mesh_vertices(struct lat_mesh *t)
{
    const uint16_t w = LAT_C + 1;

    mesh_init(&t->m, t->v, LAT_VERTS, t->f, LAT_FACES, t->n, LAT_FACES);
    for (int r = 0; r <= LAT_R; r++) {
        for (int c = 0; c <= LAT_C; c++) {
            mesh_add_vertex(&t->m, v3(2.0 * c - LAT_C, (double)(unit_rand() % 2001u) / 1000.0 - 1.0,
                                      2.0 * r - LAT_R));
            mesh_normal_to_q14(u3(0, 1, 0), &t->vnormal[3 * (r * w + c)]);
        }
    }
}

static void lat_mesh_build(struct lat_mesh *t, uint32_t diag0)
{
    const uint16_t w = LAT_C + 1;

    lat_mesh_vertices(t);
    for (uint16_t r = 0; r < LAT_R; r++) {
        for (uint16_t c = 0; c < LAT_C; c++) {
            const uint16_t a = (uint16_t)(r * w + c);
            const uint16_t b = (uint16_t)(a + w);
            const uint16_t cc = (uint16_t)(b + 1u);
            const uint16_t d = (uint16_t)(a + 1u);
            const uint8_t mat = (uint8_t)(MAT_RED + unit_rand() % 4u);

            if (((r + c + diag0) & 1u) == 0u) {
                mesh_add_face(&t->m, a, b, cc, mat);
                mesh_add_face(&t->m, a, cc, d, (uint8_t)(mat + 1u));
            } else {
                mesh_add_face(&t->m, a, b, d, mat);
                mesh_add_face(&t->m, b, cc, d, (uint8_t)(mat + 1u));
            }
        }
    }
    mesh_finish(&t->m);
}

/* What one object left in the test frame. */
struct lat_result {
    uint32_t vert_count, prim_count, outline_count;
    struct render_stats stats;
    uint32_t prim[64 * LAT_FACES][5];
    sort_item_t item[64 * LAT_FACES];
    uint32_t vert[64 * LAT_FACES][3];
};

static void lat_capture(struct lat_result *r)
{
    r->vert_count = test_frame.vert_count;
    r->prim_count = test_frame.prim_count;
    r->outline_count = test_frame.outline_count;
    r->stats = test_frame.stats;
    for (uint32_t i = 0; i < r->prim_count && i < 64u * LAT_FACES; i++) {
        const struct render_prim *p = &test_frame.prim[i];

        r->prim[i][0] = p->v[0];
        r->prim[i][1] = p->v[1];
        r->prim[i][2] = p->v[2];
        r->prim[i][3] = p->color;
        r->prim[i][4] = p->kind;
        r->item[i] = test_frame.sort_item[i];
    }
    for (uint32_t i = 0; i < r->vert_count && i < 64u * LAT_FACES; i++) {
        r->vert[i][0] = test_frame.vert[i].sxy;
        r->vert[i][1] = test_frame.vert[i].zd;
        r->vert[i][2] = test_frame.vert[i].code;
    }
}

static int lat_same(const struct lat_result *a, const struct lat_result *b)
{
    if (a->vert_count != b->vert_count || a->prim_count != b->prim_count ||
        a->outline_count != b->outline_count || memcmp(&a->stats, &b->stats, sizeof a->stats) != 0) {
        return 0;
    }
    for (uint32_t i = 0; i < a->prim_count && i < 64u * LAT_FACES; i++) {
        if (memcmp(a->prim[i], b->prim[i], sizeof a->prim[i]) != 0 || a->item[i] != b->item[i]) {
            return 0;
        }
    }
    for (uint32_t i = 0; i < a->vert_count && i < 64u * LAT_FACES; i++) {
        if (memcmp(a->vert[i], b->vert[i], sizeof a->vert[i]) != 0) {
            return 0;
        }
    }
    return 1;
}

/* A pass for the face loops' comparisons: a random eye (pitch within +-110 degrees) or, when
 * `look_at`, the same rotation looking at the origin from 25 units (view = rot (p - eye) puts it at
 * z = 25: a small mesh there is inside the frustum); `mode` 0..6: filled flat (0, 1), Gouraud (2),
 * an eye material (3), wireframe with GPU lines (4) and without (5), filled (6). */
static void loop_test_pass(struct render_pass *pass, struct proj_setup *ps, uint32_t mode,
                           bool look_at)
{
    struct cam_view cam;
    const mat3 id = mat3_identity();

    proj_setup_init(ps, 200, to_real(40.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    cam.rot = mat3_from_yaw_pitch((fx_angle)unit_rand(),
                                   (fx_angle)(65536u - 20000u + unit_rand() % 40001u));
    cam.eye = v3((double)(unit_rand() % 4001u) / 100.0 - 20.0,
                 (double)(unit_rand() % 1001u) / 100.0 - 2.0,
                 (double)(unit_rand() % 4001u) / 100.0 - 20.0);
    if (look_at) {
        const real_t back = to_real(-25.0);

        cam.eye = vec3_make(real_mul(back, real_from_unit(cam.rot.m[2][0])),
                            real_mul(back, real_from_unit(cam.rot.m[2][1])),
                            real_mul(back, real_from_unit(cam.rot.m[2][2])));
    }
    render_pass_init(pass, ps, &cam, &id, v3(0, 0, 0), u3(0.3, 0.8, -0.5), 3);
    pass->wireframe = (mode == 4u || mode == 5u);
    pass->gpu_lines = (mode != 5u);
    pass->gouraud = (mode == 2u);
    pass->eye_material = (mode == 3u) ? MAT_ANAGLYPH_LEFT : 0u;
}

/* The lattice loop and projection draw exactly what the general loop and projection draw, for
 * random views (inside the frustum, crossing its planes, the near plane and the guard band), in
 * every mode: filled flat with and without a level cache, Gouraud, an eye material, wireframe
 * with and without GPU lines, and with the frame running out of room; with the vertices on the
 * lattice's axes (a row's and a column's products) and one vertex off them (vertex by vertex).
 * mesh_set_lattice accepts only a lattice. */
void test_render_lattice_loop(void)
{
    static struct lat_mesh t;
    static struct lat_result general;
    static struct lat_result lattice;
    static uint8_t cache_storage[2][LAT_FACES];
    struct render_level_cache cache[2];
    const uint32_t prim_cap = test_frame.prim_cap;
    uint32_t cases = 0;
    uint32_t clipped = 0;

    unit_srand(2718u);
    lat_mesh_build(&t, 1u);
    t.f[7].v[2] = t.f[7].v[1];  /* not a lattice any more */
    CHECK(!mesh_set_lattice(&t.m, LAT_R, LAT_C, 1u));
    CHECK_EQ(t.m.lattice_cols, 0);
    for (uint32_t diag0 = 0; diag0 < 2u; diag0++) {
        lat_mesh_build(&t, diag0);
        if (diag0 == 1u) {
            t.v[2 * (LAT_C + 1) + 3].x += 1;  /* off its column: projected vertex by vertex */
        }
        CHECK(!mesh_set_lattice(&t.m, LAT_R, LAT_C, diag0 ^ 1u));
        CHECK(mesh_set_lattice(&t.m, LAT_R, LAT_C, diag0));
        CHECK_EQ(t.m.lattice_cols, LAT_C + 1);
        CHECK_EQ(t.m.lattice_axes, (diag0 == 0u) ? 1 : 0);
        for (uint32_t view = 0; view < 1000u; view++) {
            struct render_pass pass;
            struct proj_setup ps;
            const uint32_t mode = view % 7u;
            const uint32_t cap = (mode == 6u) ? 1u + unit_rand() % 40u : prim_cap;
            struct render_object o = {0};

            loop_test_pass(&pass, &ps, mode, false);
            o.mesh = &t.m;
            o.rot = mat3_identity();
            o.vnormal14 = t.vnormal;
            for (uint32_t k = 0; k < 2u; k++) {
                render_level_cache_init(&cache[k], cache_storage[k], LAT_FACES);
                o.levels = (mode == 1u) ? 0 : &cache[k];
                o.faces = (k == 0u) ? render_general_faces_loop : render_lattice_faces_loop;
                o.project = (k == 0u) ? 0 : render_project_lattice;
                test_frame.prim_cap = cap;
                begin();
                render_object(&test_frame, &pass, &o);
                lat_capture((k == 0u) ? &general : &lattice);
                test_frame.prim_cap = prim_cap;
            }
            CHECK(lat_same(&general, &lattice));
            cases += (general.prim_count != 0u) ? 1u : 0u;
            clipped += (general.stats.faces_clipped != 0u) ? 1u : 0u;
        }
    }
    CHECK(cases > 300u);    /* about a sixth of the 2000 random views see the mesh (355) */
    CHECK(clipped > 100u);  /* many of those across the near plane or the guard band (260) */
}

/* Whether two results hold the same primitives on the mesh's own vertices, in any order (a
 * clipper's primitives name vertices numbered in emission order: only counted). */
static int lat_prim_cmp(const void *a, const void *b)
{
    return memcmp(a, b, 5 * sizeof(uint32_t));
}

static int lat_same_unclipped(const struct lat_result *a, const struct lat_result *b)
{
    static uint32_t pa[64 * LAT_FACES][5];
    static uint32_t pb[64 * LAT_FACES][5];
    uint32_t na = 0;
    uint32_t nb = 0;

    for (uint32_t i = 0; i < a->prim_count; i++) {
        if (a->prim[i][0] < LAT_VERTS && a->prim[i][1] < LAT_VERTS && a->prim[i][2] < LAT_VERTS) {
            memcpy(pa[na++], a->prim[i], sizeof pa[0]);
        }
    }
    for (uint32_t i = 0; i < b->prim_count; i++) {
        if (b->prim[i][0] < LAT_VERTS && b->prim[i][1] < LAT_VERTS && b->prim[i][2] < LAT_VERTS) {
            memcpy(pb[nb++], b->prim[i], sizeof pb[0]);
        }
    }
    qsort(pa, na, sizeof pa[0], lat_prim_cmp);
    qsort(pb, nb, sizeof pb[0], lat_prim_cmp);
    return na == nb && memcmp(pa, pb, na * sizeof pa[0]) == 0;
}

/* The painter's walk of a regular lattice (render.c): from random eyes, inside the lattice's
 * extent and outside it, above and below, in every mode the lattice loop walks (flat with a level
 * cache, Gouraud), the frame keeps its painter's order (render_sort leaves it), it holds exactly
 * the primitives the stored order gives, and no quad is drawn before one it lies between the eye
 * and: the quad of a later primitive is never farther from the eye's quad, in rows and in columns
 * on the same side, than an earlier one's, unless it is the same quad. A lattice off its axes is
 * not walked (the frame is sorted). */
void test_render_lattice_walk(void)
{
    static struct lat_mesh t;
    static struct lat_result stored;
    static struct lat_result walked;
    static uint8_t cache_storage[LAT_FACES];
    struct render_level_cache cache;
    const int32_t w = LAT_C + 1;
    uint32_t checked = 0;
    uint32_t reversed = 0;

    unit_srand(1414u);
    for (uint32_t diag0 = 0; diag0 < 2u; diag0++) {
        lat_mesh_build(&t, diag0);
        CHECK(mesh_set_lattice(&t.m, LAT_R, LAT_C, diag0));
        CHECK(t.m.lattice_regular);
        for (uint32_t view = 0; view < 1500u; view++) {
            struct render_pass pass;
            struct proj_setup ps;
            const uint32_t mode = (view % 3u == 2u) ? 2u : 0u;  /* flat, flat, Gouraud */
            struct render_object o = {0};
            vec3 eye;
            int32_t er;
            int32_t ec;

            loop_test_pass(&pass, &ps, mode, view % 2u == 0u);
            eye = xf_eye(&pass.focus_to_view);
            /* The eye's quad, floored: vertex (r, c) at x = 2c - LAT_C, z = 2r - LAT_R. */
            er = (int32_t)floor((rd(eye.z) + LAT_R) / 2.0);
            ec = (int32_t)floor((rd(eye.x) + LAT_C) / 2.0);
            o.mesh = &t.m;
            o.rot = mat3_identity();
            o.vnormal14 = t.vnormal;
            o.faces = render_lattice_faces_loop;
            o.project = render_project_lattice;
            for (uint32_t k = 0; k < 2u; k++) {
                render_level_cache_init(&cache, cache_storage, LAT_FACES);
                o.levels = &cache;
                begin();
                test_frame.painter_ordered = (k == 1u);
                render_object(&test_frame, &pass, &o);
                CHECK_EQ(test_frame.painter_ordered, k == 1u);
                render_sort(&test_frame);
                lat_capture((k == 0u) ? &stored : &walked);
            }
            CHECK_EQ(walked.prim_count, stored.prim_count);
            CHECK_EQ(walked.vert_count, stored.vert_count);
            CHECK(memcmp(&walked.stats, &stored.stats, sizeof walked.stats) == 0);
            CHECK(lat_same_unclipped(&walked, &stored));
            for (uint32_t i = 0; i < walked.prim_count; i++) {
                const uint32_t *pi = walked.prim[sort_item_payload(walked.item[i])];

                if (sort_item_payload(walked.item[i]) != i) {
                    reversed++;
                }
                for (uint32_t j = i + 1u; j < walked.prim_count; j++) {
                    const uint32_t *pj = walked.prim[sort_item_payload(walked.item[j])];
                    int32_t q[2][2];  /* row, column of the quads of i and j */
                    bool clipped = false;

                    for (uint32_t n = 0; n < 2u; n++) {
                        const uint32_t *p = (n == 0u) ? pi : pj;

                        q[n][0] = LAT_R;
                        q[n][1] = LAT_C;
                        for (uint32_t v = 0; v < 3u; v++) {
                            clipped = clipped || p[v] >= (uint32_t)LAT_VERTS;
                            q[n][0] = ((int32_t)p[v] / w < q[n][0]) ? (int32_t)p[v] / w : q[n][0];
                            q[n][1] = ((int32_t)p[v] % w < q[n][1]) ? (int32_t)p[v] % w : q[n][1];
                        }
                    }
                    if (clipped || (q[0][0] == q[1][0] && q[0][1] == q[1][1])) {
                        continue;  /* a clipper's vertex, or the two halves of one quad */
                    }
                    {
                        const int32_t ri = q[0][0] - er;
                        const int32_t ci = q[0][1] - ec;
                        const int32_t rj = q[1][0] - er;
                        const int32_t cj = q[1][1] - ec;
                        /* i lies between the eye and j: on j's side (or the eye's row, column)
                         * and no farther on either axis. */
                        const bool between = (ri == 0 || (ri < 0) == (rj < 0)) &&
                                             (ci == 0 || (ci < 0) == (cj < 0)) &&
                                             abs(ri) <= abs(rj) && abs(ci) <= abs(cj);

                        CHECK(!between);
                        checked++;
                    }
                }
            }
        }
    }
    CHECK(checked > 100000u);
    CHECK(reversed > 1000u);  /* the walk went down rows and columns, not only up */
    /* Off its axes: not regular, so the frame keeps no painter's order. */
    lat_mesh_build(&t, 0u);
    t.v[LAT_C + 1].z += 1;
    CHECK(mesh_set_lattice(&t.m, LAT_R, LAT_C, 0u));
    CHECK(!t.m.lattice_regular);
    {
        struct render_pass pass;
        struct proj_setup ps;
        struct render_object o = {0};

        loop_test_pass(&pass, &ps, 0u, true);
        render_level_cache_init(&cache, cache_storage, LAT_FACES);
        o.mesh = &t.m;
        o.rot = mat3_identity();
        o.levels = &cache;
        o.faces = render_lattice_faces_loop;
        o.project = render_project_lattice;
        begin();
        test_frame.painter_ordered = true;
        render_object(&test_frame, &pass, &o);
        CHECK(!test_frame.painter_ordered);
    }
}

/* A quad mesh (mesh_set_quads) over the lattice's random heights: each cell one quad (a, b, c', d)
 * through mesh_add_quad, with one of four normals and a random material. */
static void quad_mesh_build(struct lat_mesh *t)
{
    const uint16_t w = LAT_C + 1;

    lat_mesh_vertices(t);
    mesh_add_normal(&t->m, u3(0, 1, 0));
    mesh_add_normal(&t->m, u3(0.6, 0.8, 0));
    mesh_add_normal(&t->m, u3(0, 0.8, -0.6));
    mesh_add_normal(&t->m, u3(-0.48, 0.6, 0.64));
    for (uint16_t r = 0; r < LAT_R; r++) {
        for (uint16_t c = 0; c < LAT_C; c++) {
            const uint16_t a = (uint16_t)(r * w + c);

            mesh_add_quad(&t->m, a, (uint16_t)(a + w), (uint16_t)(a + w + 1u), (uint16_t)(a + 1u),
                          (uint16_t)(unit_rand() % 4u), (uint8_t)(MAT_RED + unit_rand() % 4u));
        }
    }
    mesh_finish(&t->m);
}

/* The quad loop draws exactly what the general loop draws, for random views (inside the frustum,
 * crossing its planes, the near plane and the guard band), in every mode: filled flat with and
 * without a level cache, Gouraud, an eye material, wireframe with and without GPU lines, and with
 * the frame running out of room. mesh_set_quads accepts only quads' halves. */
void test_render_quad_loop(void)
{
    static struct lat_mesh t;
    static struct lat_result general;
    static struct lat_result quads;
    static uint8_t cache_storage[2][LAT_FACES];
    struct render_level_cache cache[2];
    const uint32_t prim_cap = test_frame.prim_cap;
    uint32_t cases = 0;
    uint32_t clipped = 0;
    uint32_t dropped = 0;
    uint32_t inside = 0;

    unit_srand(1618u);
    lat_mesh_build(&t, 0u);  /* triangles, not quads */
    CHECK(!mesh_set_quads(&t.m));
    quad_mesh_build(&t);
    t.f[9].material ^= 1u;  /* halves of one quad with two materials */
    CHECK(!mesh_set_quads(&t.m));
    CHECK_EQ(t.m.quads, 0);
    quad_mesh_build(&t);
    t.f[4].v[0] = t.f[5].v[1];  /* a half that is not the quad's */
    CHECK(!mesh_set_quads(&t.m));
    quad_mesh_build(&t);
    CHECK(mesh_set_quads(&t.m));
    CHECK_EQ(t.m.quads, 1);
    for (uint32_t view = 0; view < 2000u; view++) {
        struct render_pass pass;
        struct proj_setup ps;
        const uint32_t mode = view % 7u;
        const uint32_t cap = (mode == 6u) ? 1u + unit_rand() % 40u : prim_cap;
        struct render_object o = {0};

        loop_test_pass(&pass, &ps, mode, view % 4u == 3u);  /* a quarter inside the frustum */
        o.mesh = &t.m;
        o.rot = mat3_identity();
        o.vnormal14 = (mode == 2u) ? t.vnormal : 0;
        o.material = (view % 5u == 0u) ? (uint8_t)MAT_GREEN : 0u;
        for (uint32_t k = 0; k < 2u; k++) {
            render_level_cache_init(&cache[k], cache_storage[k], LAT_FACES);
            o.levels = (view % 3u == 0u) ? 0 : &cache[k];
            o.faces = (k == 0u) ? render_general_faces_loop : render_quad_faces_loop;
            test_frame.prim_cap = cap;
            begin();
            render_object(&test_frame, &pass, &o);
            lat_capture((k == 0u) ? &general : &quads);
            test_frame.prim_cap = prim_cap;
        }
        CHECK(lat_same(&general, &quads));
        CHECK(memcmp(cache_storage[0], cache_storage[1], sizeof cache_storage[0]) == 0);
        cases += (general.prim_count != 0u) ? 1u : 0u;
        clipped += (general.stats.faces_clipped != 0u) ? 1u : 0u;
        dropped += (general.stats.dropped != 0u) ? 1u : 0u;
        inside += (general.stats.faces_frustum == 0u && general.stats.faces_clipped == 0u &&
                   general.prim_count != 0u && view % 4u == 3u) ? 1u : 0u;
    }
    CHECK(cases > 500u);    /* views that see the mesh (612) */
    CHECK(clipped > 120u);  /* across the near plane or the guard band (183) */
    CHECK(dropped > 40u);   /* out of room part-way (63) */
    CHECK(inside > 250u);   /* the whole mesh on the screen (345) */
}

/* The projection alone (the views above seldom hold the whole mesh inside the frustum, the
 * case render_project_lattice has its own loop for): the same vertices as render_project_boxed's
 * (a lattice is no box: every vertex through xf_apply), inside or not, for random model-view
 * transforms that put the mesh in front of the eye, on the lattice's axes and off them. */
void test_render_lattice_projection(void)
{
    static struct lat_mesh t;
    static struct proj_vertex by_lattice[LAT_VERTS];
    static struct proj_vertex by_vertex[LAT_VERTS];
    struct proj_setup ps;
    uint32_t inside_views = 0;

    unit_srand(3141u);
    proj_setup_init(&ps, 200, to_real(40.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    for (uint32_t view = 0; view < 1000u; view++) {
        xf_affine mv;

        lat_mesh_build(&t, view & 1u);
        if ((view & 2u) != 0u) {
            t.v[unit_rand() % LAT_VERTS].z += 1;  /* off its row */
        }
        CHECK(mesh_set_lattice(&t.m, LAT_R, LAT_C, view & 1u));
        CHECK_EQ(t.m.lattice_axes, ((view & 2u) != 0u) ? 0 : 1);
        mv.r = mat3_from_yaw_pitch((fx_angle)unit_rand(), (fx_angle)unit_rand());
        mv.t = v3((double)(unit_rand() % 4001u) / 1000.0 - 2.0,
                  (double)(unit_rand() % 4001u) / 1000.0 - 2.0,
                  (double)(unit_rand() % 30001u) / 1000.0 + 12.0);
        for (uint32_t inside = 0; inside < 2u; inside++) {
            if (inside != 0u && render_sphere_classify(&ps, xf_apply(&mv, t.m.center),
                                                       t.m.radius) != RENDER_SPHERE_INSIDE) {
                continue;
            }
            memset(by_lattice, 0xA5, sizeof by_lattice);
            memset(by_vertex, 0x5A, sizeof by_vertex);
            render_project_lattice(&ps, &mv, &t.m, by_lattice, inside != 0u);
            render_project_boxed(&ps, &mv, &t.m, by_vertex, inside != 0u);
            CHECK(memcmp(by_lattice, by_vertex, sizeof by_lattice) == 0);
            inside_views += inside;
        }
    }
    CHECK(inside_views > 400u);  /* 501: half of them on the lattice's axes */
}
