/*
 * stress.c — `make stress` (issue #13): named stiff and extreme cases of the firmware's pure core
 * rendered through the golden model, one Markdown row each: | case | result | figure |.
 *
 *   stress [--short] [--frame WxH] [--lists DIR] [--soak-frames=N] [--spin-frames=N]
 *     --short        the make-test form: every case, fewer frames (soak 60, look key 10^4)
 *     --frame WxH    the GPU's frame and the projection's: 320x240 (the contract's, the default)
 *                    or 640x480 (its largest; the guard band is then a narrower angle and the
 *                    frame's centre 160 px further from the Q12.4 range's end)
 *     --lists DIR    some cases also write their frame as a primitive list and the frame the
 *                    golden model drew (tests/stress/run.sh co-simulates them)
 *
 * Every case starts with the fixed-point overflow counter cleared (fixed.h) and says what it
 * expects of it: 0, or a nonzero count it reports (a saturation that is counted, never silent).
 * The float backend's build checks the camera basis and view-space values for NaN and infinity
 * instead. Exit status: 0 when every case passed, 1 otherwise.
 */
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/pipeline.h"
#include "bsp.h"
#include "camera/camera.h"
#include "gpu/batch.h"
#include "gpu/gpu.h"
#include "input/input.h"
#include "math/fixed.h"
#include "math/real.h"
#include "render/clip.h"
#include "render/palette.h"
#include "render/proj.h"
#include "render/render.h"
#include "scenes/scene.h"
/* The stress program has every scene (no FW_BUILT_SCENES): their table and storage. */
#include "scenes/scene_set.h"
#include "scenes/voxel/voxel_scene.h"
#include "stress_bsp.h"
#include "test_util.h"  /* the backend's numbers as double (tests/firmware) */

/* ---- settings: the full run and the short (make test) one ---------------------------------- */
static uint32_t stress_soak_frames = 10000u;     /* per scene and run */
static uint32_t stress_spin_frames = 1000000u;   /* the held rotation key */
/* The frame (--frame), stress_bsp's: the model's and the projection's. */
#define stress_fb_w stress_bsp_frame_width()
#define stress_fb_h stress_bsp_frame_height()

static uint32_t stress_pixels(void)
{
    return stress_fb_w * stress_fb_h;
}

#define Q30_MIN_ ((q2_30)INT32_MIN)  /* -2.0 */

/* Non-finite values seen (float backend; the fixed one has none by construction). */
static uint32_t stress_nonfinite;

static void check_finite(double d)
{
    if (!isfinite(d)) {
        stress_nonfinite++;
    }
}

static void check_mat(const mat3 *m)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            check_finite(ud(m->m[i][j]));
        }
    }
}

/* ---- the GPU: driver + golden model --------------------------------------------------------- */
static struct gpu_dev stress_dev;
static uint32_t stress_vtx_words[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t stress_prim_words[GPU_TRI_CAP * GPU_PRIM_WORDS];

static bool gpu_start(void)
{
    uint16_t pal[PAL_ENTRIES];

    bsp_init();
    palette_build(pal);
    return gpu_init(&stress_dev, pal, PAL_ENTRIES) == GPU_OK;
}

/* What a frame's batches reported. */
struct frame_result {
    uint32_t batches;
    uint32_t errors;      /* OR of ERRORS */
    uint32_t drawn;
    uint32_t rejected;
    uint32_t pixels;
    int submit_rc;        /* first failure of submit or wait, GPU_OK if none */
};

/* Stream a frame as app.c does: CLEAR on the first batch, SWAP on the last. */
static void gpu_frame(struct render_frame *f, struct frame_result *r)
{
    struct batch_cursor cur;
    struct batch_words words = BATCH_WORDS_ON(stress_vtx_words, stress_prim_words);
    bool first = true;

    memset(r, 0, sizeof *r);
    batch_begin(&cur);
    do {
        struct gpu_batch b;
        struct gpu_stats st;
        uint32_t tag;
        int rc;

        batch_fill(&cur, f, stress_dev.info.vtx_cap, stress_dev.info.tri_cap, &words);
        b = batch_descriptor(&words,
                             (first ? GPU_CTRL_CLEAR_MASK : 0u) |
                                 (batch_done(&cur, f) ? GPU_CTRL_SWAP_MASK : 0u),
                             PAL_SKY);
        rc = gpu_submit_batch(&stress_dev, &b, &tag);
        if (rc == GPU_OK) {
            rc = gpu_wait(&stress_dev, tag, 1000u);
        }
        if (rc != GPU_OK) {
            r->submit_rc = rc;
            return;
        }
        gpu_read_stats(&stress_dev, &st);
        r->batches++;
        r->errors |= st.errors;
        r->drawn += st.tris_drawn;
        r->rejected += st.tris_rejected;
        r->pixels += st.pixels;
        first = false;
    } while (!batch_done(&cur, f));
}

/* FNV-1a of the shown framebuffer. */
static uint64_t fb_hash(void)
{
    const uint8_t *fb = gpu_model_front(stress_bsp_gpu());
    uint64_t h = 0xcbf29ce484222325ull;

    for (uint32_t i = 0; i < stress_pixels(); i++) {
        h = (h ^ fb[i]) * 0x100000001b3ull;
    }
    return h;
}

/* ---- the co-simulated sample: frames as primitive lists (cosim/prim_list.h) ----------------- */
/* With --lists DIR, some cases also write DIR/<name>.txt, the primitives of their frame as
 * `gpusim raster` reads them, and DIR/<name>.raw, the frame the golden model drew from them here:
 * tests/stress/cosim_sample.sh renders the lists through the RTL and compares. */
static const char *stress_lists_dir;

static FILE *list_open(const char *name, const char *ext)
{
    char path[512];

    snprintf(path, sizeof path, "%s/%s.%s", stress_lists_dir, name, ext);
    return fopen(path, "wb");
}

static void list_prim(FILE *f, uint32_t kind, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                      int32_t x2, int32_t y2, uint32_t color)
{
    if (kind == GPU_PRIM_KIND_LINE) {
        fprintf(f, "line %d %d %d %d %u\n", (int)x0, (int)y0, (int)x1, (int)y1, (unsigned)color);
    } else {
        fprintf(f, "tri %d %d %d %d %d %d %u\n", (int)x0, (int)y0, (int)x1, (int)y1, (int)x2,
                (int)y2, (unsigned)color);
    }
}

static void list_raw(const char *name)
{
    FILE *f = list_open(name, "raw");

    if (f != NULL) {
        fwrite(gpu_model_front(stress_bsp_gpu()), 1, stress_pixels(), f);
        fclose(f);
    }
}

/* A firmware frame (filled: triangles and lines), in draw order, after gpu_frame drew it. */
static void list_frame(const char *name, const struct render_frame *fr)
{
    FILE *f;

    if (stress_lists_dir == NULL || (f = list_open(name, "txt")) == NULL) {
        return;
    }
    fprintf(f, "# stress case %s: the firmware's frame\nclear %u\n", name, (unsigned)PAL_SKY);
    for (uint32_t i = 0; i < fr->prim_count; i++) {
        const struct render_prim *p = &fr->prim[render_draw_index(fr, i)];
        const struct proj_vertex *a = &fr->vert[p->v[0]];
        const struct proj_vertex *b = &fr->vert[p->v[1]];
        const struct proj_vertex *c = &fr->vert[p->v[2]];

        list_prim(f, p->kind, a->sx, a->sy, b->sx, b->sy, c->sx, c->sy, p->color);
    }
    fclose(f);
    list_raw(name);
}

/* A raw batch of this file's vertex and primitive words (indices in range, known kinds). */
static void list_words(const char *name, uint32_t prims)
{
    FILE *f;

    if (stress_lists_dir == NULL || (f = list_open(name, "txt")) == NULL) {
        return;
    }
    fprintf(f, "# stress case %s: a batch written straight to the GPU\nclear %u\n", name,
            (unsigned)PAL_SKY);
    for (uint32_t i = 0; i < prims; i++) {
        const uint32_t *w = &stress_prim_words[2u * i];
        const uint32_t idx[3] = {w[0] & 0xFFFFu, w[0] >> 16, w[1] & 0xFFFFu};
        int32_t xy[6];

        for (int k = 0; k < 3; k++) {
            xy[2 * k] = (int16_t)(stress_vtx_words[2u * idx[k]] & 0xFFFFu);
            xy[2 * k + 1] = (int16_t)(stress_vtx_words[2u * idx[k]] >> 16);
        }
        list_prim(f, (w[1] >> GPU_PRIM_KIND_LSB) & 0xFFu, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5],
                  (w[1] >> GPU_PRIM_COLOR_LSB) & 0xFFu);
    }
    fclose(f);
    list_raw(name);
}

/* ---- hand-made geometry: independent triangles seen from the origin along +z --------------- */
#define TRI_MAX 32u
struct tri_mesh {
    struct mesh m;
    vec3 v[3u * TRI_MAX];
    struct mesh_face f[TRI_MAX];
    uvec3 n[TRI_MAX];
};

static void tri_begin(struct tri_mesh *t)
{
    mesh_init(&t->m, t->v, 3u * TRI_MAX, t->f, TRI_MAX, t->n, TRI_MAX);
}

/* Counter-clockwise as seen from the eye (front-facing): a, b, c. */
static void tri_add(struct tri_mesh *t, vec3 a, vec3 b, vec3 c)
{
    const uint16_t i = mesh_add_vertex(&t->m, a);

    mesh_add_vertex(&t->m, b);
    mesh_add_vertex(&t->m, c);
    mesh_add_face(&t->m, i, (uint16_t)(i + 1u), (uint16_t)(i + 2u), MAT_RED);
}

RENDER_FRAME_STORAGE(stress_frame, 4096u, 4096u);
static struct render_frame tri_frame;
/* A scene with this program's storage (scene_set.h): the camera cases, the soak. */
static struct scene stress_scene;
static struct render_frame stress_scene_frame;

static void setup_pass(struct render_pass *pass, vec3 eye, fx_angle yaw, int32_t pitch)
{
    struct proj_setup ps;
    struct cam_view view;
    const mat3 id = mat3_identity();

    proj_setup_init(&ps, 200, to_real(160.0), stress_fb_w, stress_fb_h);
    view.rot = cam_basis(yaw, pitch);
    view.eye = eye;
    render_pass_init(pass, &ps, &view, &id, v3(0, 0, 0), mat3_row(&view.rot, 2), 4);
}

/* Render the mesh from the origin looking along +z (both windings tried: one is front-facing). */
static void tri_render(struct tri_mesh *t, struct render_frame *f)
{
    struct render_pass pass;
    struct render_object o = {0};

    mesh_finish(&t->m);
    setup_pass(&pass, v3(0, 0, 0), 0, 0);
    o.mesh = &t->m;
    o.faces = render_general_faces_loop;
    o.rot = mat3_identity();
    o.pos = v3(0, 0, 0);
    o.material = 0;
    o.levels = 0;
    render_stats_clear(&f->stats);
    render_frame_begin(f);
    render_object(f, &pass, &o);
    render_sort(f);
}

/* Extremes of the frame's vertices (Q12.4) and whether all lie in the guard band. */
static bool frame_in_band(const struct render_frame *f, int32_t *worst)
{
    const int32_t cx = 16 * (int32_t)(stress_fb_w / 2u);
    const int32_t cy = 16 * (int32_t)(stress_fb_h / 2u);
    bool ok = true;

    *worst = 0;
    for (uint32_t i = 0; i < f->prim_count; i++) {
        for (int k = 0; k < 3; k++) {
            const struct proj_vertex *v = &f->vert[f->prim[i].v[k]];
            const int32_t dx = abs(v->sx - cx);
            const int32_t dy = abs(v->sy - cy);

            *worst = (dx > *worst) ? dx : *worst;
            *worst = (dy > *worst) ? dy : *worst;
            if (dx > PROJ_GUARD_Q4 + 16 || dy > PROJ_GUARD_Q4 + 16 ||
                (v->code & PROJ_OUT_NEAR) != 0u) {
                ok = false;
            }
        }
    }
    return ok;
}

/* ---- the table ------------------------------------------------------------------------------ */
#define FIG_BYTES 400
typedef bool (*stress_fn)(char *fig);

static int fig(char *out, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fig(char *out, const char *fmt, ...)
{
    va_list ap;
    int n;

    va_start(ap, fmt);
    n = vsnprintf(out, FIG_BYTES, fmt, ap);
    va_end(ap);
    return n;
}

/* The overflow counter's part of a figure, and whether it is what the case expects (0). */
static bool no_overflow(void)
{
    return fx_overflow_count() == 0u && stress_nonfinite == 0u;
}

/* ---- near plane ----------------------------------------------------------------------------- */
/* A triangle with one vertex at z = near + dz (the others at z = 2), rendered and drawn. */
static bool near_case(const char *name, char *out, real_t z0, uint32_t want_clipped,
                      uint32_t want_prims)
{
    static struct tri_mesh t;
    struct frame_result r;
    int32_t worst;
    bool band;

    /* In the plane y = -0.5, below the eye whatever z0 is: one winding faces the eye, the other
     * is culled as back-facing. The vertex on the near plane projects 400 px below the centre at
     * 240 lines (800 at 480), and the vertices the near plane cuts from a triangle reaching
     * behind the eye less than 800 px beside it: inside the guard band at either frame. */
    tri_begin(&t);
    tri_add(&t, vec3_make(0, REAL_C(-0.5), z0), v3(0.5, -0.5, 2), v3(-0.5, -0.5, 2));
    tri_add(&t, vec3_make(0, REAL_C(-0.5), z0), v3(-0.5, -0.5, 2), v3(0.5, -0.5, 2));
    tri_render(&t, &tri_frame);
    band = frame_in_band(&tri_frame, &worst);
    gpu_frame(&tri_frame, &r);
    list_frame(name, &tri_frame);
    fig(out, "z0 = %.9g: clipped %u, %u triangle(s), %u pixels, ERRORS 0x%x, %u overflows",
        rd(z0), (unsigned)tri_frame.stats.faces_clipped, (unsigned)tri_frame.prim_count,
        (unsigned)r.pixels, (unsigned)r.errors, (unsigned)fx_overflow_count());
    return band && tri_frame.stats.faces_clipped == want_clipped &&
           tri_frame.stats.faces_back == 1u &&
           tri_frame.prim_count == want_prims && r.submit_rc == GPU_OK && r.errors == 0u &&
           r.pixels > 0u && no_overflow();
}

#if REAL_IS_FIXED
#define REAL_ULP_AT_NEAR ((real_t)1)
#define REAL_ULP_AT_FAR  ((real_t)1)
#else
#define REAL_ULP_AT_NEAR (nextafterf(PROJ_NEAR, 1.0f) - PROJ_NEAR)
#define REAL_ULP_AT_FAR  (nextafterf(160.0f, 1000.0f) - 160.0f)
#endif

static bool case_near_on(char *out)
{
    return near_case("near-on", out, PROJ_NEAR, 0u, 1u);
}

static bool case_near_front(char *out)
{
    return near_case("near-front", out, real_add(PROJ_NEAR, REAL_ULP_AT_NEAR), 0u, 1u);
}

static bool case_near_behind(char *out)
{
    /* One vertex out: the triangle becomes a quad, two triangles (both windings are clipped
     * before the back-face test drops one). */
    return near_case("near-behind", out, real_sub(PROJ_NEAR, REAL_ULP_AT_NEAR), 2u, 2u);
}

static bool case_behind_eye(char *out)
{
    /* A vertex far behind the eye: clipped, nothing mirrored in front. */
    return near_case("behind-eye", out, to_real(-50.0), 2u, 2u);
}

/* GPU primitives at the ends of Q12.4 (+-2048 px), written straight to the GPU. */
static void raw_vertex(uint32_t *w, int32_t sx, int32_t sy)
{
    w[0] = ((uint32_t)sx & 0xFFFFu) | ((uint32_t)(sy & 0xFFFF) << 16);
    w[1] = 0;
}

static void raw_prim(uint32_t *w, uint32_t i0, uint32_t i1, uint32_t i2, uint32_t kind)
{
    w[0] = (i0 & 0xFFFFu) | (i1 << 16);
    w[1] = (i2 & 0xFFFFu) | (0x17u << GPU_PRIM_COLOR_LSB) | (kind << GPU_PRIM_KIND_LSB);
}

/* One batch straight to the driver: vtx_count vertices, prims primitives. */
static int raw_batch(uint32_t vtx_count, uint32_t prims, struct gpu_stats *st)
{
    struct gpu_batch b;
    uint32_t tag;
    int rc;

    b.vtx_words = stress_vtx_words;
    b.vtx_base = 0;
    b.vtx_count = vtx_count;
    b.prim_words = stress_prim_words;
    b.tri_base = 0;
    b.prim_count = prims;
    b.clear_color = PAL_SKY;
    b.ctrl = GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK;
    b.strip = GPU_STRIP_WHOLE;
    rc = gpu_submit_batch(&stress_dev, &b, &tag);
    if (rc == GPU_OK) {
        rc = gpu_wait(&stress_dev, tag, 1000u);
    }
    gpu_read_stats(&stress_dev, st);
    return rc;
}

/* The far plane (160 units here): a triangle exactly on it is drawn, one 1 ulp beyond is culled;
 * its sort depth stays under the cap that keeps a triangle's key in 16 bits. */
static bool case_far_plane(char *out)
{
    static struct tri_mesh t;
    struct frame_result r;
    const real_t far = to_real(160.0);
    uint32_t on_prims;
    uint32_t on_pixels;
    uint32_t depth;
    uint32_t beyond_prims;
    uint32_t beyond_frustum;

    tri_begin(&t);
    tri_add(&t, vec3_make(REAL_C(-10), REAL_C(-10), far), vec3_make(REAL_C(10), REAL_C(-10), far),
            vec3_make(0, REAL_C(10), far));
    tri_add(&t, vec3_make(REAL_C(-10), REAL_C(-10), far), vec3_make(0, REAL_C(10), far),
            vec3_make(REAL_C(10), REAL_C(-10), far));
    tri_render(&t, &tri_frame);
    gpu_frame(&tri_frame, &r);
    on_prims = tri_frame.prim_count;
    on_pixels = r.pixels;
    depth = (on_prims > 0u) ? tri_frame.vert[tri_frame.prim[0].v[0]].depth : 0u;
    for (uint32_t i = 0; i < t.m.vert_count; i++) {
        t.v[i].z = real_add(far, REAL_ULP_AT_FAR);
    }
    tri_render(&t, &tri_frame);
    beyond_prims = tri_frame.prim_count;
    beyond_frustum = tri_frame.stats.faces_frustum;
    fig(out, "z = far: %u triangle, %u pixels, sort depth %u (cap %u); z = far + 1 ulp: %u "
             "triangles, %u frustum-culled; %u overflows", (unsigned)on_prims,
        (unsigned)on_pixels, (unsigned)depth, (unsigned)PROJ_DEPTH_MAX, (unsigned)beyond_prims,
        (unsigned)beyond_frustum, (unsigned)fx_overflow_count());
    return on_prims == 1u && on_pixels > 0u && r.errors == 0u && depth <= PROJ_DEPTH_MAX &&
           beyond_prims == 0u && beyond_frustum >= 1u && no_overflow();
}

/* ---- slivers and grazing angles ------------------------------------------------------------- */
static bool case_sliver(char *out)
{
    static struct tri_mesh t;
    struct frame_result r;
    struct gpu_stats st;
    uint32_t covered;
    int rc;
    /* At z = 4 with f = 200, one world unit is 50 px: 1/16 px is 1/800 unit. Long (200 px),
     * one sub-pixel unit wide at its base, and half a sub-pixel. */
    const double w = 1.0 / 800.0;

    tri_begin(&t);
    for (int wind = 0; wind < 2; wind++) {
        const double s = wind ? -1.0 : 1.0;  /* mirrored in z about 4: the other winding */

        tri_add(&t, v3(-2, 0.001, 4), v3(2, 0.001 + s * w, 4), v3(2, 0.001, 4));
        tri_add(&t, v3(-2, -0.5, 4), v3(2, -0.5 + s * w / 2, 4), v3(2, -0.5, 4));
        tri_add(&t, v3(0.3, -1.5, 4), v3(0.3 + s * w, 1.5, 4), v3(0.3, 1.5, 4));
    }
    tri_render(&t, &tri_frame);
    gpu_frame(&tri_frame, &r);
    list_frame("slivers", &tri_frame);
    /* At the GPU: two slivers 1/16 px tall, 200 px long, on either side of one row of pixel
     * centres (their shared edge on it): the top-left rule gives the row to exactly one. */
    raw_vertex(&stress_vtx_words[0], 16 * 50 + 8, 16 * 100 + 8);
    raw_vertex(&stress_vtx_words[2], 16 * 250 + 8, 16 * 100 + 8);
    raw_vertex(&stress_vtx_words[4], 16 * 250 + 8, 16 * 100 + 9);
    raw_vertex(&stress_vtx_words[6], 16 * 250 + 8, 16 * 100 + 7);
    raw_prim(&stress_prim_words[0], 0, 1, 2, GPU_PRIM_KIND_TRI);
    raw_prim(&stress_prim_words[2], 0, 3, 1, GPU_PRIM_KIND_TRI);
    rc = raw_batch(4, 2, &st);
    list_words("sliver-row", 2);
    covered = 0;
    for (uint32_t i = 0; i < stress_pixels(); i++) {
        covered += gpu_model_front(stress_bsp_gpu())[i] != PAL_SKY;
    }
    fig(out, "3 slivers (1/16, 1/32 px), both windings: %u emitted, %u back, %u drawn, %u px; "
             "2 sharing a pixel-centre row: %u px written, %u covered (once each)",
        (unsigned)tri_frame.prim_count, (unsigned)tri_frame.stats.faces_back, (unsigned)r.drawn,
        (unsigned)r.pixels, (unsigned)st.pixels, (unsigned)covered);
    /* Whatever the rounding keeps, each covers at most a pixel row / column: < 3 H px (the
     * frame's lines); the row of the pair is written once per pixel, nearly all of its 200. */
    return r.submit_rc == GPU_OK && r.errors == 0u && r.pixels <= 3u * stress_fb_h &&
           rc == GPU_OK &&
           st.errors == 0u && st.pixels == covered && covered >= 199u && covered <= 201u &&
           no_overflow();
}

static bool case_grazing(char *out)
{
    static struct tri_mesh t;
    struct frame_result r;
    uint32_t back = 0;
    uint32_t pixels = 0;
    uint32_t in_plane_back = 0;

    /* A floor at y = -h seen ever more edge-on, h = 1 .. 1e-7 and exactly 0 (the eye in its
     * plane: zero area, culled), and a wall turned towards the view ray by 1e-4 rad. */
    for (int k = 0; k <= 8; k++) {
        const double h = (k < 8) ? pow(10.0, -(double)k) : 0.0;

        tri_begin(&t);
        tri_add(&t, v3(-3, -h, 1), v3(3, -h, 40), v3(3, -h, 1));
        tri_add(&t, v3(-3, -h, 1), v3(-3, -h, 40), v3(3, -h, 40));
        tri_add(&t, v3(0.5, -1, 2), v3(0.5 + 1e-4 * 30, 1, 32), v3(0.5, 1, 2));
        tri_render(&t, &tri_frame);
        gpu_frame(&tri_frame, &r);
        back += tri_frame.stats.faces_back;
        pixels += r.pixels;
        if (k == 8) {
            in_plane_back = tri_frame.stats.faces_back;
        }
        if (r.submit_rc != GPU_OK || r.errors != 0u) {
            fig(out, "eye %.0e above the plane: rc %d ERRORS 0x%x", h, r.submit_rc,
                (unsigned)r.errors);
            return false;
        }
    }
    fig(out, "floor 1 .. 1e-7 and 0 below the eye, a wall 1e-4 rad off the view ray: %u faces "
             "culled as back or zero-area (%u of 2 with the eye in the plane), %u pixels, "
             "ERRORS 0, %u overflows", (unsigned)back, (unsigned)in_plane_back,
        (unsigned)pixels, (unsigned)fx_overflow_count());
    return in_plane_back >= 2u && no_overflow();
}

/* ---- fixed-point ranges --------------------------------------------------------------------- */
/* The +-1024 world rule: eye at one corner of the box, triangles at the opposite one. */
static bool case_world_1024(char *out)
{
    static struct tri_mesh t;
    struct render_pass pass;
    struct render_object o = {0};
    uint32_t prims = 0;
    uint32_t errors = 0;

    for (int c = 0; c < 8; c++) {
        const double sx = (c & 1) ? 1024.0 : -1024.0;
        const double sy = (c & 2) ? 1024.0 : -1024.0;
        const double sz = (c & 4) ? 1024.0 : -1024.0;
        const vec3 eye = v3(-sx, -sy, -sz);
        /* Look from the eye at the far corner: yaw and pitch of the diagonal. */
        const double yaw = atan2(2 * sx, 2 * sz) / (2 * TEST_PI) * 65536.0;
        const double pitch = atan2(2 * sy, sqrt(8.0) * 1024.0) / (2 * TEST_PI) * 65536.0;
        struct frame_result r;

        tri_begin(&t);
        for (int k = 0; k < 4; k++) {
            const double d = 20.0 * k;

            tri_add(&t, v3(sx - d * (sx > 0 ? 1 : -1), sy, sz), v3(sx, sy - d * (sy > 0 ? 1 : -1), sz),
                    v3(sx, sy, sz - d * (sz > 0 ? 1 : -1) - 1));
            tri_add(&t, v3(sx, sy, sz - d * (sz > 0 ? 1 : -1) - 1), v3(sx, sy - d * (sy > 0 ? 1 : -1), sz),
                    v3(sx - d * (sx > 0 ? 1 : -1), sy, sz));
        }
        mesh_finish(&t.m);
        {
            struct proj_setup ps;
            struct cam_view view;
            const mat3 id = mat3_identity();

            proj_setup_init(&ps, 200, to_real(160.0), stress_fb_w, stress_fb_h);
            view.rot = cam_basis((fx_angle)lround(yaw), (int32_t)lround(pitch));
            view.eye = eye;
            check_mat(&view.rot);
            render_pass_init(&pass, &ps, &view, &id, v3(0, 0, 0), mat3_row(&view.rot, 2), 4);
            pass.proj.far = to_real(4000.0);
        }
        o.mesh = &t.m;
        o.faces = render_general_faces_loop;
        o.rot = mat3_identity();
        o.pos = v3(0, 0, 0);
        o.material = 0;
        o.levels = 0;
        render_stats_clear(&tri_frame.stats);
        render_frame_begin(&tri_frame);
        render_object(&tri_frame, &pass, &o);
        render_sort(&tri_frame);
        gpu_frame(&tri_frame, &r);
        prims += tri_frame.prim_count;
        errors |= r.errors | (r.submit_rc != GPU_OK ? 0x80000000u : 0u);
    }
    fig(out, "8 corners, eye 3547 units from the meshes: %u primitives, ERRORS 0x%x, %u overflows",
        (unsigned)prims, (unsigned)errors, (unsigned)fx_overflow_count());
    return errors == 0u && no_overflow();
}

/* Beyond the rules, both counted, never silent: a mesh with a vertex at 9000 model units (past
 * the transform's +-8192: mesh_finish counts it, and the frame loop would stop before drawing
 * it), and an object placed at 30000 world units (past the +-1024 box: scene_add_object clamps
 * each coordinate and counts it), then drawn where it was clamped to. */
static bool case_world_beyond(char *out)
{
    static struct tri_mesh t;
    const struct pipeline_opts opts = {.wireframe = false, .depth_test = false, .gpu_lines = true};
    const mat3 id = mat3_identity();
    struct frame_result r;
    uint32_t mesh_count;
    uint32_t pos_count;
    uint32_t draw_count;

    tri_begin(&t);
    tri_add(&t, v3(0, 0, 3), v3(9000, 0, 3), v3(0, 1, 3));
    mesh_finish(&t.m);
    mesh_count = fx_overflow_count();
    fx_overflow_clear();

    tri_begin(&t);
    tri_add(&t, v3(-1, -1, 0), v3(1, -1, 0), v3(0, 1, 0));
    mesh_finish(&t.m);
    scene_set_attach(&stress_scene, &stress_scene_frame);
    scene_set_frame(&stress_scene, stress_fb_w, stress_fb_h);
    if (!scene_start(&stress_scene, scene_find("tetra"))) {
        fig(out, "tetra did not start");
        return false;
    }
    fx_overflow_clear();
    scene_add_object(&stress_scene, &t.m, &id, v3(30000, -30000, 30000), 0);
    pos_count = fx_overflow_count();
    fx_overflow_clear();
    pipeline_pass(&stress_scene_frame, &stress_scene, &opts, 0, NULL, NULL);
    gpu_frame(&stress_scene_frame, &r);
    draw_count = fx_overflow_count();
    fig(out, "vertex at 9000 model units: %u overflow counted (mesh_finish); object at 30000 "
             "world units: %u counted and clamped (scene_add_object), then drawn: %u primitives, "
             "%u overflows, ERRORS 0x%x", (unsigned)mesh_count, (unsigned)pos_count,
        (unsigned)stress_scene_frame.prim_count, (unsigned)draw_count, (unsigned)r.errors);
    return mesh_count == 1u && pos_count == 3u && draw_count == 0u && r.submit_rc == GPU_OK &&
           r.errors == 0u && stress_nonfinite == 0u;
}

/* The q16_16 / q2_30 operations at the ends of int32: every result that does not fit is clamped
 * and counted once; those that fit (the ends themselves) count nothing. */
static bool case_fixed_ends(char *out)
{
#if REAL_IS_FIXED
    uint32_t n = 0;
    uint32_t want_total = 0;
    uint32_t wrong = 0;

    /* expr must give w and add c saturations to the counter. */
#define FX_END(expr, w, c) do { const uint32_t before_ = fx_overflow_count(); \
        const int32_t got_ = (expr); \
        wrong += (fx_overflow_count() - before_ != (c)) || got_ != (w); \
        want_total += (c); n++; } while (0)
    FX_END(fx_add(FX_MAX, 1), FX_MAX, 1u);
    FX_END(fx_sub(FX_MIN, 1), FX_MIN, 1u);
    FX_END(fx_sub(0, FX_MIN), FX_MAX, 1u);
    FX_END(fx_add(FX_MAX, FX_MIN), -1, 0u);
    FX_END(fx_mul(FX_MAX, FX_MAX), FX_MAX, 1u);
    FX_END(fx_mul(FX_MIN, FX_MAX), FX_MIN, 1u);
    FX_END(fx_mul(FX_MAX, FX_ONE), FX_MAX, 0u);
    FX_END(fx_mul(FX_MIN, FX_ONE), FX_MIN, 0u);
    FX_END(fx_div(FX_ONE, 0), FX_MAX, 1u);
    FX_END(fx_div(FX_MAX, 1), FX_MAX, 1u);
    FX_END(fx_div(FX_MIN, -FX_ONE), FX_MAX, 1u);
    FX_END(q30_mul(Q30_MIN_, Q30_MIN_), FX_MAX, 1u);
    FX_END(q30_mul(Q30_ONE, Q30_ONE), Q30_ONE, 0u);
    FX_END(q30_from_q16(FX_FROM_INT(2)), FX_MAX, 1u);
    FX_END(q30_from_q16(-FX_FROM_INT(2)), FX_MIN, 0u);
    FX_END(q30_scale(FX_MAX, Q30_ONE), FX_MAX, 0u);
#undef FX_END
    fig(out, "%u operations at the int32 ends: %u saturations counted (%u expected), %u wrong",
        (unsigned)n, (unsigned)fx_overflow_count(), (unsigned)want_total, (unsigned)wrong);
    return wrong == 0u && fx_overflow_count() == want_total;
#else
    fig(out, "float backend: no fixed-point ranges; 0 NaN");
    return stress_nonfinite == 0u;
#endif
}

/* The guard band: triangles reaching far beyond it are clipped to it; a vertex exactly on its
 * edge is kept. */
static bool case_guard_band(char *out)
{
    static struct tri_mesh t;
    struct frame_result r;
    int32_t worst;
    bool band;
    /* g = 1536 / 200: the band's edge at z = 2 is x = 15.36. */

    tri_begin(&t);
    tri_add(&t, v3(-4000, -1, 2), v3(4000, 3000, 2), v3(4000, -1, 2));
    tri_add(&t, v3(-15.36, 0, 2), v3(0, 1, 2), v3(0, -1, 2));
    tri_add(&t, v3(-1, -3000, 3), v3(1, -3000, 3), v3(0, 3000, 3));
    tri_render(&t, &tri_frame);
    band = frame_in_band(&tri_frame, &worst);
    gpu_frame(&tri_frame, &r);
    list_frame("guard-band", &tri_frame);
    fig(out, "3 triangles -> %u, %u clipped; largest offset %.1f px of the 1536 px band, "
             "ERRORS 0x%x, %u overflows", (unsigned)tri_frame.prim_count,
        (unsigned)tri_frame.stats.faces_clipped, worst / 16.0, (unsigned)r.errors,
        (unsigned)fx_overflow_count());
    return band && tri_frame.stats.faces_clipped >= 2u && r.submit_rc == GPU_OK &&
           r.errors == 0u && r.pixels > 0u && no_overflow();
}

static bool case_q12_4_ends(char *out)
{
    struct gpu_stats st;
    int rc;

    /* A triangle covering the screen from the corners of the Q12.4 range, a line across it,
     * and a triangle wholly outside at the far corner. */
    raw_vertex(&stress_vtx_words[0], -32768, -32768);
    raw_vertex(&stress_vtx_words[2], 32767, -32768);
    raw_vertex(&stress_vtx_words[4], -32768, 32767);
    raw_vertex(&stress_vtx_words[6], 32767, 32767);
    raw_prim(&stress_prim_words[0], 0, 2, 1, GPU_PRIM_KIND_TRI);
    raw_prim(&stress_prim_words[2], 0, 1, 2, GPU_PRIM_KIND_TRI);
    raw_prim(&stress_prim_words[4], 0, 3, 3, GPU_PRIM_KIND_LINE);
    raw_prim(&stress_prim_words[6], 3, 1, 2, GPU_PRIM_KIND_TRI);
    rc = raw_batch(4, 4, &st);
    list_words("q12-4-ends", 4);
    fig(out, "corners +-2048 px: %u of 4 drawn, %u pixels (screen: %u + line), ERRORS 0x%x",
        (unsigned)st.tris_drawn, (unsigned)st.pixels, (unsigned)stress_pixels(),
        (unsigned)st.errors);
    return rc == GPU_OK && st.errors == 0u && st.pixels >= stress_pixels() &&
           st.pixels <= 3u * stress_pixels();
}

/* ---- GPU contract errors: indices out of range, capacities overflowed ----------------------- */
static bool case_gpu_bad_index(char *out)
{
    struct gpu_stats st;
    int rc;

    raw_vertex(&stress_vtx_words[0], 16 * 10, 16 * 10);
    raw_vertex(&stress_vtx_words[2], 16 * 100, 16 * 10);
    raw_vertex(&stress_vtx_words[4], 16 * 10, 16 * 100);
    raw_prim(&stress_prim_words[0], 0, 2, 1, GPU_PRIM_KIND_TRI);      /* good */
    raw_prim(&stress_prim_words[2], 0, 2, 3, GPU_PRIM_KIND_TRI);      /* 3 >= VTX_COUNT */
    raw_prim(&stress_prim_words[4], 0xFFFF, 0, 1, GPU_PRIM_KIND_TRI); /* 65535 */
    raw_prim(&stress_prim_words[6], 1, 1024, 1024, GPU_PRIM_KIND_LINE);
    raw_prim(&stress_prim_words[8], 0, 1, 2, 7u);                     /* unknown kind */
    rc = raw_batch(3, 5, &st);
    fig(out, "5 primitives, 3 with indices >= VTX_COUNT, 1 bad kind: %u drawn, %u rejected, "
             "ERRORS 0x%x (VTX_INDEX + KIND)", (unsigned)st.tris_drawn, (unsigned)st.tris_rejected,
        (unsigned)st.errors);
    return rc == GPU_OK && st.tris_drawn == 1u && st.tris_rejected == 4u &&
           st.errors == (GPU_ERR_VTX_INDEX_MASK | GPU_ERR_KIND_MASK);
}

static bool case_gpu_capacity(char *out)
{
    struct gpu_stats st;
    struct gpu_batch b;
    uint32_t tag;
    uint32_t done;
    uint32_t errors;
    uint32_t polls = 0;
    int rc_vtx;
    int rc_tri;

    /* The driver refuses batches beyond the capacities the GPU reported... */
    b.vtx_words = stress_vtx_words;
    b.vtx_base = 0;
    b.vtx_count = stress_dev.info.vtx_cap + 1u;
    b.prim_words = stress_prim_words;
    b.tri_base = 0;
    b.prim_count = 1;
    b.clear_color = PAL_SKY;
    b.ctrl = GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK;
    b.strip = GPU_STRIP_WHOLE;
    rc_vtx = gpu_submit_batch(&stress_dev, &b, &tag);
    b.vtx_count = 3;
    b.prim_count = stress_dev.info.tri_cap + 1u;
    rc_tri = gpu_submit_batch(&stress_dev, &b, &tag);
    /* ... and the GPU itself, programmed past the driver, skips such a batch with ERR_COUNT. */
    bsp_gpu_write(GPU_REG_CTRL, GPU_CTRL_CLEAR_MASK);
    bsp_gpu_write(GPU_REG_VTX_BASE, stress_dev.info.vtx_cap - 2u);
    bsp_gpu_write(GPU_REG_VTX_COUNT, 3);
    bsp_gpu_write(GPU_REG_TRI_BASE, stress_dev.info.tri_cap);
    bsp_gpu_write(GPU_REG_TRI_COUNT, 1);
    bsp_gpu_write(GPU_REG_DOORBELL, 0x5eed);
    do {
        done = bsp_gpu_read(GPU_REG_DONE_SEQ);
    } while (done != 0x5eedu && ++polls < 1000u);
    errors = bsp_gpu_read(GPU_REG_ERRORS);
    st.tris_drawn = bsp_gpu_read(GPU_REG_PERF_TRIS_DRAWN);
    fig(out, "driver: VTX_CAP+1 -> %s, TRI_CAP+1 -> %s; GPU: base+count > cap -> ERRORS 0x%x, "
             "%u drawn", gpu_strerror(rc_vtx), gpu_strerror(rc_tri), (unsigned)errors,
        (unsigned)st.tris_drawn);
    /* The driver's view is now out of step with the raw tag: reset it. */
    gpu_reset(&stress_dev);
    return rc_vtx == GPU_E_CAPACITY && rc_tri == GPU_E_CAPACITY && done == 0x5eedu &&
           errors == GPU_ERR_COUNT_MASK && st.tris_drawn == 0u;
}

/* The firmware's frame overflowed: what does not fit is dropped and counted. */
RENDER_FRAME_STORAGE(small_frame, 24u, 8u);
static bool case_frame_capacity(char *out)
{
    static struct scene s;
    static struct render_frame big;
    struct render_frame small;
    const struct pipeline_opts opts = {.wireframe = false, .depth_test = false, .gpu_lines = true};
    struct frame_result r;

    scene_set_attach(&s, &big);
    scene_set_frame(&s, stress_fb_w, stress_fb_h);
    RENDER_FRAME_ATTACH(&small, small_frame);
    if (!scene_start(&s, scene_find("cubes"))) {
        fig(out, "cubes did not start");
        return false;
    }
    pipeline_pass(&small, &s, &opts, 0, NULL, NULL);
    gpu_frame(&small, &r);
    fig(out, "cubes into a 24-vertex, 8-primitive frame: %u primitives, %u dropped and counted, "
             "ERRORS 0x%x", (unsigned)small.prim_count, (unsigned)small.stats.dropped,
        (unsigned)r.errors);
    return small.stats.dropped > 0u && small.prim_count <= 8u && r.submit_rc == GPU_OK &&
           r.errors == 0u && no_overflow();
}

/* ---- cameras in awkward places -------------------------------------------------------------- */

/* Turn a full circle (and up and down) from where the camera is; every frame drawn. */
static bool sweep_from(const char *what, char *out)
{
    const struct pipeline_opts opts = {.wireframe = false, .depth_test = false, .gpu_lines = true};
    uint32_t clipped = 0;
    uint32_t dropped = 0;
    uint32_t errors = 0;
    uint32_t pixels = 0;

    for (int k = 0; k < 96; k++) {
        struct frame_result r;

        stress_scene.cam.yaw = (fx_angle)(k * 65536 / 32);
        stress_scene.cam.pitch = (k / 32 - 1) * (CAM_PITCH_LIMIT * 9 / 10);
        pipeline_pass(&stress_scene_frame, &stress_scene, &opts, 0, NULL, NULL);
        gpu_frame(&stress_scene_frame, &r);
        clipped += stress_scene_frame.stats.faces_clipped;
        dropped += stress_scene_frame.stats.dropped;
        pixels += r.pixels;
        errors |= r.errors | (r.submit_rc != GPU_OK ? 0x80000000u : 0u);
    }
    fig(out, "%s, 96 directions: %u faces clipped, %u dropped, %u pixels, ERRORS 0x%x, "
             "%u overflows", what, (unsigned)clipped, (unsigned)dropped, (unsigned)pixels,
        (unsigned)errors, (unsigned)fx_overflow_count());
    return clipped > 0u && dropped == 0u && errors == 0u && no_overflow();
}

static bool case_inside_mesh(char *out)
{
    scene_set_attach(&stress_scene, &stress_scene_frame);
    scene_set_frame(&stress_scene, stress_fb_w, stress_fb_h);
    if (!scene_start(&stress_scene, scene_find("cubes")) || stress_scene.object_count == 0u) {
        fig(out, "cubes did not start");
        return false;
    }
    cam_set_mode(&stress_scene.cam, CAM_FLY);
    stress_scene.cam.eye = stress_scene.object[0].pos;
    return sweep_from("eye at the centre of cube 0", out);
}

static bool case_inside_voxel(char *out)
{
    struct voxel_scene_state *v;

    scene_set_attach(&stress_scene, &stress_scene_frame);
    scene_set_frame(&stress_scene, stress_fb_w, stress_fb_h);
    if (!scene_start(&stress_scene, scene_find("voxel"))) {
        fig(out, "voxel did not start");
        return false;
    }
    v = voxel_scene_state(&stress_scene);
    cam_set_mode(&stress_scene.cam, CAM_FLY);
    for (int32_t y = 1; y < 16; y++) {
        for (int32_t x = 4; x < 12; x++) {
            if (voxel_get(&v->world, x, y, 8) != 0u && voxel_get(&v->world, x, y + 1, 8) != 0u) {
                char what[64];

                stress_scene.cam.eye = v3(x + 0.5, y + 0.5, 8.5);
                snprintf(what, sizeof what, "eye inside block (%d, %d, 8)", (int)x, (int)y);
                return sweep_from(what, out);
            }
        }
    }
    fig(out, "no solid block found");
    return false;
}

/* ---- orientation: pitch at the poles, a key held for a million frames ----------------------- */
static bool case_pitch_pole(char *out)
{
    static const struct cam_config cfg = {
        .box_min = {-REAL_C(1000), -REAL_C(1000), -REAL_C(1000)},
        .box_max = {REAL_C(1000), REAL_C(1000), REAL_C(1000)},
        .dist_min = REAL_C(1), .dist_max = REAL_C(100), .move_step = REAL_C(0.5),
        .zoom_step = REAL_C(0.5), .look_step = 512, .focus = {0, 0, 0},
    };
    struct camera cam;
    const int32_t req = (int32_t)lround(89.99 * 65536.0 / 360.0);
    double worst = 0.0;
    int32_t seen_max = 0;
    bool ok = true;

    for (int sgn = -1; sgn <= 1; sgn += 2) {
        for (int mode = CAM_FLY; mode <= CAM_ORBIT; mode++) {
            cam_init(&cam, &cfg, (enum cam_mode)mode, v3(0, 0, 10), REAL_C(10), 0, sgn * req);
            for (int k = 0; k < 2000; k++) {
                struct cam_view view;

                cam_move(&cam, (k % 3) - 1, 0, 0, 1, sgn, 0, 0);
                cam_get_view(&cam, 0, &view);
                check_mat(&view.rot);
                check_finite(rd(view.eye.x) + rd(view.eye.y) + rd(view.eye.z));
                worst = fmax(worst, mat_ortho_err(&view.rot));
                seen_max = (abs(cam.pitch) > seen_max) ? abs(cam.pitch) : seen_max;
                /* Forward never exactly vertical: yaw keeps its meaning. */
                if (fabs(ud(view.rot.m[2][1])) >= 1.0) {
                    ok = false;
                }
            }
        }
    }
    /* 3e-4: the sine table's bound on the rebuilt basis (camera.c, tests/firmware). */
    fig(out, "asked +-89.99 deg, held at %.4f deg (limit 89), fly and orbit, 2000 frames each; "
             "basis max abs(RR^T-I) <= %.1e (table bound 3e-4), %u non-finite",
        seen_max * 360.0 / 65536.0, worst, (unsigned)stress_nonfinite);
    return ok && seen_max <= CAM_PITCH_LIMIT && worst < 3e-4 && no_overflow();
}

static bool case_spin_drift(char *out)
{
    static const struct cam_config cfg = {
        .box_min = {-REAL_C(1000), -REAL_C(1000), -REAL_C(1000)},
        .box_max = {REAL_C(1000), REAL_C(1000), REAL_C(1000)},
        .dist_min = REAL_C(1), .dist_max = REAL_C(100), .move_step = REAL_C(0.5),
        .zoom_step = REAL_C(0.5), .look_step = 331, .focus = {0, 0, 0},
    };
    struct camera fly;
    struct camera obj;
    double fly_worst = 0.0;
    double obj_worst = 0.0;
    bool yaw_exact;

    cam_init(&fly, &cfg, CAM_FLY, v3(0, 0, 10), REAL_C(10), 0, 1000);
    cam_init(&obj, &cfg, CAM_OBJECT, v3(0, 0, 10), REAL_C(10), 0, 1000);
    for (uint32_t k = 0; k < stress_spin_frames; k++) {
        /* The look-right key held (fly: yaw; object mode: the scene turns), roll now and then. */
        cam_move(&fly, 0, 0, 0, 1, 0, 0, 0);
        cam_move(&obj, 0, 0, 0, 1, ((k & 1023u) == 0u) ? 1 : 0, ((k & 4095u) == 7u) ? 1 : 0, 0);
        if ((k & 1023u) == 0u || k + 1u == stress_spin_frames) {
            struct cam_view view;

            cam_get_view(&fly, 0, &view);
            check_mat(&view.rot);
            check_mat(&obj.scene_rot);
            fly_worst = fmax(fly_worst, mat_ortho_err(&view.rot));
            obj_worst = fmax(obj_worst, mat_ortho_err(&obj.scene_rot));
        }
    }
    /* Fly: the basis is rebuilt from the angles, so the yaw must be exactly N steps and the
     * basis within the sine table's 3e-4; object mode accumulates and re-orthonormalises: within
     * test_camera's 1e-6. */
    yaw_exact = fly.yaw == (fx_angle)(stress_spin_frames * (uint32_t)cfg.look_step);
    fig(out, "%u frames: fly yaw %s N steps, basis max abs(RR^T-I) <= %.1e (no growth: "
             "rebuilt); object-mode rotation <= %.1e; %u non-finite",
        (unsigned)stress_spin_frames, yaw_exact ? "exactly" : "NOT", fly_worst, obj_worst,
        (unsigned)stress_nonfinite);
    return yaw_exact && fly_worst < 3e-4 && obj_worst < 1e-6 && no_overflow();
}

/* ---- soak: every scene, fixed keys, twice, frame hashes identical --------------------------- */
/* The key script: frame k types keys[k % n] (no scene switches, no quit), and R (reset view)
 * every 1000th frame: the camera wanders to the scene box's walls in between. */
static const char *const soak_keys[] = {
    "", "wwwwjjjii", "", "m", "ddd  kkk", "lllll", "mllluo", "sssss", "", "ccaa", "t", "iiii",
    "b", "p", "n", "jjjjjjj", "m", "uuoo", "wwwww", "", "t",
};
#define SOAK_KEY_COUNT (sizeof soak_keys / sizeof soak_keys[0])

struct soak_run {
    uint64_t hash_sum;     /* order-sensitive combination of every frame's hash */
    uint64_t first_diff;   /* frame where the second run first differed (set by the compare) */
    uint32_t dropped;
    uint32_t errors;
    uint32_t overflows;
    uint32_t mesh_full;    /* SCENE_EVENT_MESH_FULL: a rebuilt voxel mesh found no room */
    uint32_t prims;        /* primitives drawn over the run */
    uint32_t changed;      /* frames whose hash differs from the frame before */
};

/* Each frame's hash, per run, for the first 16384 frames (the order-sensitive hash_sum covers
 * every frame of a longer run). */
static uint64_t soak_hashes[2][16384];

static void soak_one(const struct scene_desc *d, uint32_t frames, int run, struct soak_run *sr)
{
    struct input_decoder dec;
    bool wire = false;
    uint64_t prev = 0;

    memset(sr, 0, sizeof *sr);
    fx_overflow_clear();
    gpu_start();
    scene_set_attach(&stress_scene, &stress_scene_frame);
    scene_set_frame(&stress_scene, stress_fb_w, stress_fb_h);
    scene_start(&stress_scene, d);
    input_decoder_init(&dec);
    for (uint32_t k = 0; k < frames; k++) {
        const char *text = (k % 1000u == 999u) ? "r" : soak_keys[k % SOAK_KEY_COUNT];
        struct pipeline_opts opts = {.wireframe = false, .depth_test = false, .gpu_lines = true};
        struct input_counts c;
        struct scene_event ev;
        struct frame_result r;
        uint64_t h;

        input_counts_clear(&c);
        input_feed(&dec, &c, (const uint8_t *)text, (uint32_t)strlen(text));
        if (k % 97u == 96u) {
            wire = !wire;  /* the F key's effect, which is the frame loop's */
        }
        opts.wireframe = wire;
        scene_update(&stress_scene, &c, &ev);
        pipeline_pass(&stress_scene_frame, &stress_scene, &opts, 0, NULL, NULL);
        check_mat(&stress_scene.cam.scene_rot);
        gpu_frame(&stress_scene_frame, &r);
        sr->dropped += stress_scene_frame.stats.dropped;
        sr->mesh_full += ev.kind == SCENE_EVENT_MESH_FULL;
        sr->prims += stress_scene_frame.prim_count;
        sr->errors |= r.errors | (r.submit_rc != GPU_OK ? 0x80000000u : 0u);
        h = fb_hash();
        sr->changed += k > 0u && h != prev;
        prev = h;
        sr->hash_sum = (sr->hash_sum ^ h) * 0x100000001b3ull;
        if (k < 16384u) {
            soak_hashes[run][k] = h;
        }
    }
    sr->overflows = fx_overflow_count();
}

static bool case_soak(char *out)
{
    char *p = out;
    bool ok = true;

    p += fig(p, "%u frames x 2 runs, each scene: 0 dropped, ERRORS 0, 0 overflows, equal hashes; "
             "hash (frames that changed):",
             (unsigned)stress_soak_frames);
    for (uint32_t i = 0; i < scene_count(); i++) {
        const struct scene_desc *d = scene_at(i);
        struct soak_run a;
        struct soak_run b;
        uint32_t diff = stress_soak_frames;

        soak_one(d, stress_soak_frames, 0, &a);
        soak_one(d, stress_soak_frames, 1, &b);
        for (uint32_t k = 0; k < stress_soak_frames && k < 16384u; k++) {
            if (soak_hashes[0][k] != soak_hashes[1][k]) {
                diff = k;
                break;
            }
        }
        if (a.hash_sum != b.hash_sum || diff != stress_soak_frames || a.dropped != 0u ||
            a.errors != 0u || a.overflows != 0u || b.overflows != 0u || a.mesh_full != 0u ||
            a.changed == 0u) {
            ok = false;
            p += snprintf(p, (size_t)(FIG_BYTES - (p - out)), " %s FAILED (diff@%u drop %u err 0x%x "
                          "ovf %u full %u changed %u)", d->name, (unsigned)diff,
                          (unsigned)a.dropped, (unsigned)a.errors, (unsigned)a.overflows,
                          (unsigned)a.mesh_full, (unsigned)a.changed);
        } else {
            p += snprintf(p, (size_t)(FIG_BYTES - (p - out)), " %s %04x (%u)", d->name,
                          (unsigned)(a.hash_sum & 0xFFFFu), (unsigned)a.changed);
        }
        if (p - out >= FIG_BYTES - 1) {
            break;
        }
    }
    return ok && stress_nonfinite == 0u;
}

/* ---- main ----------------------------------------------------------------------------------- */
struct stress_case {
    const char *name;
    stress_fn fn;
};

static const struct stress_case stress_cases[] = {
    {"vertex exactly on the near plane", case_near_on},
    {"vertex 1 ulp in front of the near plane", case_near_front},
    {"vertex 1 ulp behind the near plane", case_near_behind},
    {"vertex far behind the eye", case_behind_eye},
    {"far plane: on it kept, 1 ulp beyond culled", case_far_plane},
    {"camera inside a mesh (cubes)", case_inside_mesh},
    {"camera inside a voxel block", case_inside_voxel},
    {"triangles at grazing angles", case_grazing},
    {"slivers one sub-pixel wide", case_sliver},
    {"+-1024 world rule: opposite corners", case_world_1024},
    {"beyond the model and world ranges: counted", case_world_beyond},
    {"q16.16 / q2.30 operations at the int32 ends", case_fixed_ends},
    {"guard band: clipped to it, edge kept", case_guard_band},
    {"Q12.4 screen range ends at the GPU", case_q12_4_ends},
    {"pitch at +-89.99 deg", case_pitch_pole},
    {"look key held (basis drift)", case_spin_drift},
    {"GPU: indices out of range, bad kind", case_gpu_bad_index},
    {"GPU: capacities overflowed", case_gpu_capacity},
    {"frame capacity overflowed (dropped counted)", case_frame_capacity},
    {"soak: every scene, fixed keys, hashes equal", case_soak},
};

int main(int argc, char **argv)
{
    uint32_t passed = 0;
    uint32_t failed = 0;
    const uint32_t n = (uint32_t)(sizeof stress_cases / sizeof stress_cases[0]);

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--short") == 0) {
            stress_soak_frames = 60u;
            stress_spin_frames = 10000u;
        } else if (strcmp(argv[i], "--frame") == 0 && i + 1 < argc) {
            uint32_t w;
            uint32_t h;

            if (!gpu_model_parse_frame(argv[++i], &w, &h)) {
                fprintf(stderr, "stress: --frame %s: %ux%u or %ux%u\n", argv[i],
                        (unsigned)GPU_FB_WIDTH, (unsigned)GPU_FB_HEIGHT,
                        (unsigned)GPU_FB_MAX_WIDTH, (unsigned)GPU_FB_MAX_HEIGHT);
                return 2;
            }
            stress_bsp_set_frame(w, h);
        } else if (strcmp(argv[i], "--lists") == 0 && i + 1 < argc) {
            stress_lists_dir = argv[++i];
        } else if (strncmp(argv[i], "--soak-frames=", 14) == 0) {
            stress_soak_frames = (uint32_t)strtoul(argv[i] + 14, NULL, 10);
        } else if (strncmp(argv[i], "--spin-frames=", 14) == 0) {
            stress_spin_frames = (uint32_t)strtoul(argv[i] + 14, NULL, 10);
        } else {
            fprintf(stderr, "usage: stress [--short] [--frame WxH] [--lists DIR] [--soak-frames=N] "
                            "[--spin-frames=N]\n");
            return 2;
        }
    }
    printf("stress (%s backend, %ux%u frame): soak %u frames per scene and run, look key %u "
           "frames\n\n", REAL_BACKEND_NAME, (unsigned)stress_fb_w, (unsigned)stress_fb_h,
           (unsigned)stress_soak_frames, (unsigned)stress_spin_frames);
    printf("| case | result | figure |\n|---|---|---|\n");
    for (uint32_t i = 0; i < n; i++) {
        char out[FIG_BYTES] = "";
        bool ok;

        fx_overflow_clear();
        stress_nonfinite = 0;
        if (!gpu_start()) {
            printf("| %s | FAIL | GPU init failed |\n", stress_cases[i].name);
            failed++;
            continue;
        }
        RENDER_FRAME_ATTACH(&tri_frame, stress_frame);
        ok = stress_cases[i].fn(out);
        printf("| %s | %s | %s |\n", stress_cases[i].name, ok ? "pass" : "FAIL", out);
        fflush(stdout);
        if (ok) {
            passed++;
        } else {
            failed++;
        }
    }
    printf("\n%u passed, %u failed\n", (unsigned)passed, (unsigned)failed);
    return failed != 0u;
}
