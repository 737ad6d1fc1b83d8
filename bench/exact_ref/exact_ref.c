/*
 * exact_ref.c — the exact reference of `make bench-error`: a scene (bsp/host/scene_dump.c's
 * dump of one frame) rendered in double precision, written independently of the firmware's
 * pipeline: nothing of its view transform, culling, clipping, projection, lighting rule, sort or
 * of the GPU's rasterizer is used, only the definitions they implement:
 *
 *   camera     v = B (w - eye), B's rows right, up, forward from yaw and pitch (camera.h), sines
 *              from libm, pitch clamped to +-89 degrees as the camera defines it;
 *   culling    a face is drawn when its front (mesh.h: (v1 - v0) x (v2 - v0)) faces the eye;
 *   clipping   the polygon is cut to the view volume near <= z <= far (Sutherland-Hodgman in
 *              double): exact, where the firmware culls beyond far per triangle;
 *   projection sx = cx + f x / z, sy = cy - f y / z in pixels (proj.h's screen mapping, without
 *              its Q12.4 rounding);
 *   coverage   pixel centre (px + 0.5, py + 0.5) covered when every edge function is > 0, or = 0
 *              on a top-left edge (contract/gpu-contract.md's triangle rule, on the unrounded
 *              convex polygon: a fan of it covers the same centres);
 *   depth      the view-space z of the face's plane on the pixel centre's ray, a per-pixel depth
 *              test in double (nearer wins; at equal z the earlier face stays);
 *   lighting   level = ambient + floor((15 - ambient) max(0, n . l)), at most 15 (palette.h's
 *              rule, in double), palette index = material * 16 + level;
 *   output     the palette's RGB444 entry, each channel times 17, each pixel a 2 x 2 block:
 *              640 x 480 like the captured frames, so tools/png_diff --block 2 compares them.
 *
 *   exact_ref SCENE PNG            one frame
 *   exact_ref --dir DUMPDIR OUTDIR every DUMPDIR/NNNN.scene as OUTDIR/NNNN.png
 *   exact_ref --self-test          coverage, ties, near plane and depth order on known polygons
 */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_write.h"

#define ER_MAX_W 320
#define ER_MAX_H 240
#define ER_MAX_POLY 8   /* a triangle cut by two planes has at most 5 corners */

struct er_view {
    int w, h;
    double cx, cy, f, near, far;
};

struct er_frame {
    struct er_view view;
    uint8_t index[ER_MAX_W * ER_MAX_H];
    double depth[ER_MAX_W * ER_MAX_H];
    uint16_t writes[ER_MAX_W * ER_MAX_H];  /* covered-and-nearer count, for the self-test */
};

struct er_scene {
    struct er_view view;
    double eye[3];
    unsigned yaw;
    long pitch;
    double light[3];
    unsigned ambient;
    int lit;
    unsigned clear;
    uint16_t palette[256];
    size_t tris;
    double (*tri)[13];  /* 3 corners, normal, material */
};

static void er_clear(struct er_frame *fr, const struct er_view *v, uint8_t clear)
{
    fr->view = *v;
    for (int i = 0; i < v->w * v->h; i++) {
        fr->index[i] = clear;
        fr->depth[i] = INFINITY;
        fr->writes[i] = 0;
    }
}

/* Keep the part of polygon p (n corners, view space) where s * (z - bound) >= 0. */
static int er_clip(double p[][3], int n, double bound, double s, double out[][3])
{
    int m = 0;

    for (int i = 0; i < n; i++) {
        const double *a = p[i];
        const double *b = p[(i + 1) % n];
        const double da = s * (a[2] - bound);
        const double db = s * (b[2] - bound);

        if (da >= 0.0) {
            memcpy(out[m++], a, sizeof out[0]);
        }
        if ((da >= 0.0) != (db >= 0.0)) {
            const double t = da / (da - db);

            for (int c = 0; c < 3; c++) {
                out[m][c] = a[c] + t * (b[c] - a[c]);
            }
            out[m][2] = bound;  /* on the plane exactly */
            m++;
        }
    }
    return m;
}

/* A planar convex polygon in view space (any winding), colour `index`: clipped, projected,
 * covered at pixel centres with the fill rule, depth-tested per pixel. */
static void er_draw_polygon(struct er_frame *fr, double poly[][3], int n, uint8_t index)
{
    const struct er_view *v = &fr->view;
    double a[ER_MAX_POLY][3];
    double b[ER_MAX_POLY][3];
    double sx[ER_MAX_POLY];
    double sy[ER_MAX_POLY];
    double nv[3];
    double dplane;
    double area = 0.0;
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    int px0, px1, py0, py1;

    /* The plane n . p = d through the original corners (before clipping). */
    {
        const double e1[3] = {poly[1][0] - poly[0][0], poly[1][1] - poly[0][1], poly[1][2] - poly[0][2]};
        const double e2[3] = {poly[2][0] - poly[0][0], poly[2][1] - poly[0][1], poly[2][2] - poly[0][2]};

        nv[0] = e1[1] * e2[2] - e1[2] * e2[1];
        nv[1] = e1[2] * e2[0] - e1[0] * e2[2];
        nv[2] = e1[0] * e2[1] - e1[1] * e2[0];
        dplane = nv[0] * poly[0][0] + nv[1] * poly[0][1] + nv[2] * poly[0][2];
    }
    n = er_clip(poly, n, v->near, 1.0, a);
    if (n < 3) {
        return;
    }
    n = er_clip(a, n, v->far, -1.0, b);
    if (n < 3) {
        return;
    }
    for (int i = 0; i < n; i++) {
        sx[i] = v->cx + v->f * b[i][0] / b[i][2];
        sy[i] = v->cy - v->f * b[i][1] / b[i][2];
    }
    for (int i = 0; i < n; i++) {
        const int j = (i + 1) % n;

        area += sx[i] * sy[j] - sx[j] * sy[i];
    }
    if (area == 0.0) {
        return;
    }
    if (area < 0.0) {  /* the contract's swap: from here on the interior has E > 0 */
        for (int i = 0, j = n - 1; i < j; i++, j--) {
            double t = sx[i];

            sx[i] = sx[j];
            sx[j] = t;
            t = sy[i];
            sy[i] = sy[j];
            sy[j] = t;
        }
    }
    for (int i = 0; i < n; i++) {
        minx = fmin(minx, sx[i]);
        maxx = fmax(maxx, sx[i]);
        miny = fmin(miny, sy[i]);
        maxy = fmax(maxy, sy[i]);
    }
    px0 = (int)fmax(0.0, ceil(minx - 0.5));
    px1 = (int)fmin((double)(v->w - 1), floor(maxx - 0.5));
    py0 = (int)fmax(0.0, ceil(miny - 0.5));
    py1 = (int)fmin((double)(v->h - 1), floor(maxy - 0.5));
    for (int py = py0; py <= py1; py++) {
        const double cy = py + 0.5;

        for (int px = px0; px <= px1; px++) {
            const double cx = px + 0.5;
            int inside = 1;

            for (int i = 0; i < n && inside; i++) {
                const int j = (i + 1) % n;
                const double dx = sx[j] - sx[i];
                const double dy = sy[j] - sy[i];
                const double e = dx * (cy - sy[i]) - dy * (cx - sx[i]);

                inside = (e > 0.0) || (e == 0.0 && (dy < 0.0 || (dy == 0.0 && dx > 0.0)));
            }
            if (inside) {
                const double r[3] = {(cx - v->cx) / v->f, -(cy - v->cy) / v->f, 1.0};
                const double z = dplane / (nv[0] * r[0] + nv[1] * r[1] + nv[2] * r[2]);
                const int k = py * v->w + px;

                if (z < fr->depth[k]) {
                    fr->depth[k] = z;
                    fr->index[k] = index;
                    fr->writes[k]++;
                }
            }
        }
    }
}

static void er_render(struct er_frame *fr, const struct er_scene *sc)
{
    const double turn = 2.0 * 3.14159265358979323846 / 65536.0;  /* 2 pi / a turn */
    const long limit = 89L * 65536L / 360L;
    const long pitch = (sc->pitch > limit) ? limit : ((sc->pitch < -limit) ? -limit : sc->pitch);
    const double y = sc->yaw * turn, p = pitch * turn;
    const double sy = sin(y), cy = cos(y), sp = sin(p), cp = cos(p);
    const double basis[3][3] = {{cy, 0.0, -sy}, {-sp * sy, cp, -sp * cy}, {sy * cp, sp, cy * cp}};
    const double amb = (sc->ambient > 15u) ? 15.0 : (double)sc->ambient;

    er_clear(fr, &sc->view, (uint8_t)sc->clear);
    for (size_t t = 0; t < sc->tris; t++) {
        const double *tr = sc->tri[t];
        double poly[3][3];
        double e1[3], e2[3], ng[3];
        double facing;
        double level;
        double nl;

        for (int k = 0; k < 3; k++) {
            const double d[3] = {tr[3 * k] - sc->eye[0], tr[3 * k + 1] - sc->eye[1], tr[3 * k + 2] - sc->eye[2]};

            for (int r = 0; r < 3; r++) {
                poly[k][r] = basis[r][0] * d[0] + basis[r][1] * d[1] + basis[r][2] * d[2];
            }
        }
        /* Front: the winding's normal points towards the eye (the origin of view space). */
        for (int c = 0; c < 3; c++) {
            e1[c] = poly[1][c] - poly[0][c];
            e2[c] = poly[2][c] - poly[0][c];
        }
        ng[0] = e1[1] * e2[2] - e1[2] * e2[1];
        ng[1] = e1[2] * e2[0] - e1[0] * e2[2];
        ng[2] = e1[0] * e2[1] - e1[1] * e2[0];
        facing = -(ng[0] * poly[0][0] + ng[1] * poly[0][1] + ng[2] * poly[0][2]);
        if (!(facing > 0.0)) {
            continue;
        }
        nl = tr[9] * sc->light[0] + tr[10] * sc->light[1] + tr[11] * sc->light[2];
        level = sc->lit ? amb + floor((15.0 - amb) * fmax(0.0, nl)) : 15.0;
        level = fmin(level, 15.0);
        er_draw_polygon(fr, poly, 3, (uint8_t)(((unsigned)tr[12] << 4) | (unsigned)level));
    }
}

static int er_write_png(const struct er_frame *fr, const uint16_t *palette, const char *path)
{
    const int w = fr->view.w, h = fr->view.h;
    uint8_t *rgb = malloc((size_t)w * h * 12);
    int rc;

    if (rgb == NULL) {
        return -1;
    }
    for (int y = 0; y < 2 * h; y++) {
        for (int x = 0; x < 2 * w; x++) {
            const uint16_t c = palette[fr->index[(y / 2) * w + x / 2]];
            uint8_t *o = &rgb[((size_t)y * 2 * w + x) * 3];

            o[0] = (uint8_t)(((c >> 8) & 0xFu) * 17u);
            o[1] = (uint8_t)(((c >> 4) & 0xFu) * 17u);
            o[2] = (uint8_t)((c & 0xFu) * 17u);
        }
    }
    rc = png_write_rgb(path, rgb, 2 * w, 2 * h);
    free(rgb);
    return rc;
}

static int er_read_scene(const char *path, struct er_scene *sc)
{
    FILE *f = fopen(path, "r");
    char tag[32];
    int version = 0;
    unsigned long tris = 0;
    int ok;

    if (f == NULL) {
        fprintf(stderr, "exact_ref: cannot open %s\n", path);
        return -1;
    }
    ok = fscanf(f, "exactref-scene %d", &version) == 1 && version == 1 &&
         fscanf(f, " screen %d %d %lf %lf %lf %lf %lf", &sc->view.w, &sc->view.h, &sc->view.cx,
                &sc->view.cy, &sc->view.f, &sc->view.near, &sc->view.far) == 7 &&
         fscanf(f, " camera %lf %lf %lf %u %ld", &sc->eye[0], &sc->eye[1], &sc->eye[2], &sc->yaw,
                &sc->pitch) == 5 &&
         fscanf(f, " light %lf %lf %lf %u %d", &sc->light[0], &sc->light[1], &sc->light[2],
                &sc->ambient, &sc->lit) == 5 &&
         fscanf(f, " clear %u %31s", &sc->clear, tag) == 2 && strcmp(tag, "palette") == 0;
    for (int i = 0; ok && i < 256; i++) {
        unsigned c;

        ok = fscanf(f, " %x", &c) == 1;
        sc->palette[i] = (uint16_t)c;
    }
    ok = ok && fscanf(f, " tris %lu", &tris) == 1 && sc->view.w <= ER_MAX_W &&
         sc->view.h <= ER_MAX_H && sc->view.w > 0 && sc->view.h > 0 && sc->clear < 256u;
    if (ok) {
        sc->tri = realloc(sc->tri, (tris ? tris : 1) * sizeof sc->tri[0]);
        sc->tris = tris;
        ok = sc->tri != NULL;
    }
    for (unsigned long t = 0; ok && t < tris; t++) {
        ok = fscanf(f, " t") == 0;
        for (int k = 0; ok && k < 13; k++) {
            ok = fscanf(f, " %lf", &sc->tri[t][k]) == 1;
        }
    }
    fclose(f);
    if (!ok) {
        fprintf(stderr, "exact_ref: %s: not a version-1 scene dump\n", path);
        return -1;
    }
    return 0;
}

static int er_one(const char *in, const char *out)
{
    static struct er_frame fr;
    static struct er_scene sc;

    if (er_read_scene(in, &sc) != 0) {
        return 1;
    }
    er_render(&fr, &sc);
    if (er_write_png(&fr, sc.palette, out) != 0) {
        fprintf(stderr, "exact_ref: cannot write %s\n", out);
        return 1;
    }
    return 0;
}

static int er_dir(const char *in, const char *out)
{
    DIR *d = opendir(in);
    struct dirent *e;
    int done = 0;

    if (d == NULL) {
        fprintf(stderr, "exact_ref: cannot open %s\n", in);
        return 1;
    }
    while ((e = readdir(d)) != NULL) {
        const size_t len = strlen(e->d_name);
        char src[4096], dst[4096];

        if (len < 7 || strcmp(e->d_name + len - 6, ".scene") != 0) {
            continue;
        }
        snprintf(src, sizeof src, "%s/%s", in, e->d_name);
        snprintf(dst, sizeof dst, "%s/%.*s.png", out, (int)(len - 6), e->d_name);
        if (er_one(src, dst) != 0) {
            closedir(d);
            return 1;
        }
        done++;
    }
    closedir(d);
    printf("exact_ref: %d frames\n", done);
    return done > 0 ? 0 : 1;
}

/* ---- the self-test: known polygons --------------------------------------------------------- */

static int er_failures;

static void er_expect(int cond, const char *what)
{
    if (!cond) {
        printf("exact_ref self-test: FAILED: %s\n", what);
        er_failures++;
    }
}

/* A screen-space corner at view depth z: f = 256 and the centre (160, 120) keep it exact. */
static void er_at(double p[3], double sx, double sy, double z)
{
    p[0] = (sx - 160.0) / 256.0 * z;
    p[1] = -(sy - 120.0) / 256.0 * z;
    p[2] = z;
}

/* The triangle whose vertices lie on the pixel positions (x0, y0), (x1, y1), (x2, y2) at depth z. */
static void er_tri_at(double t[][3], double x0, double y0, double x1, double y1, double x2, double y2,
                      double z)
{
    er_at(t[0], x0, y0, z);
    er_at(t[1], x1, y1, z);
    er_at(t[2], x2, y2, z);
}

static int er_count(const struct er_frame *fr, uint8_t index, int *max_writes)
{
    int n = 0;

    *max_writes = 0;
    for (int i = 0; i < fr->view.w * fr->view.h; i++) {
        n += fr->index[i] == index;
        *max_writes = (fr->writes[i] > *max_writes) ? fr->writes[i] : *max_writes;
    }
    return n;
}

static int er_self_test(void)
{
    static struct er_frame fr;
    const struct er_view v = {320, 240, 160.0, 120.0, 256.0, 0.25, 160.0};
    double t[4][3];
    int most;

    /* 1. The square (10.5, 10.5) .. (20.5, 20.5) as two triangles sharing a diagonal, every edge
     * through pixel centres: the top-left rule takes the left column and the top row, not the
     * right or the bottom: exactly 10 x 10 centres, each covered once (the diagonal too). */
    er_clear(&fr, &v, 0);
    er_tri_at(t, 10.5, 10.5, 20.5, 10.5, 20.5, 20.5, 1.0);
    er_draw_polygon(&fr, t, 3, 7);
    er_at(t[1], 20.5, 20.5, 1.0);
    er_at(t[2], 10.5, 20.5, 1.0);
    er_draw_polygon(&fr, t, 3, 7);
    er_expect(er_count(&fr, 7, &most) == 100, "square: 100 centres covered");
    er_expect(most == 1, "square: no centre covered twice (shared diagonal)");
    er_expect(fr.index[10 * 320 + 10] == 7, "square: top-left corner centre (10, 10) covered");
    er_expect(fr.index[10 * 320 + 20] == 0, "square: right edge's centre (20, 10) not covered");
    er_expect(fr.index[20 * 320 + 10] == 0, "square: bottom edge's centre (10, 20) not covered");

    /* 2. Winding does not matter (culling is the caller's): the same square reversed. */
    er_clear(&fr, &v, 0);
    er_at(t[0], 10.5, 10.5, 1.0);
    er_at(t[1], 10.5, 20.5, 1.0);
    er_at(t[2], 20.5, 20.5, 1.0);
    er_at(t[3], 20.5, 10.5, 1.0);
    er_draw_polygon(&fr, t, 4, 7);
    er_expect(er_count(&fr, 7, &most) == 100, "reversed quad: 100 centres covered");

    /* 3. A floor triangle (y = -1) from behind the eye to z = 5: cut at the near plane, it covers
     * only centres below the horizon, down to the bottom row; entirely behind, nothing. */
    er_clear(&fr, &v, 0);
    t[0][0] = -1.0; t[0][1] = -1.0; t[0][2] = -2.0;
    t[1][0] = 1.0;  t[1][1] = -1.0; t[1][2] = -2.0;
    t[2][0] = 0.0;  t[2][1] = -1.0; t[2][2] = 5.0;
    er_draw_polygon(&fr, t, 3, 9);
    {
        int above = 0;

        for (int i = 0; i < 320 * 120; i++) {
            above += fr.index[i] == 9;
        }
        er_expect(above == 0, "near plane: nothing above the horizon");
    }
    er_expect(er_count(&fr, 9, &most) > 0, "near plane: the part in front is drawn");
    er_expect(fr.index[239 * 320 + 160] == 9, "near plane: reaches the bottom row");
    er_expect(fr.index[121 * 320 + 160] == 0, "near plane: ends at z = 5, below the horizon");
    er_clear(&fr, &v, 0);
    t[2][2] = -0.5;
    er_draw_polygon(&fr, t, 3, 9);
    er_expect(er_count(&fr, 9, &most) == 0, "behind the eye: nothing drawn");

    /* 4. Depth order: a near and a far triangle over the same centres, either order: the near one
     * is seen; where only the far one lies, the far one. */
    for (int order = 0; order < 2; order++) {
        double nearer[3][3], farther[3][3];

        er_clear(&fr, &v, 0);
        er_tri_at(nearer, 100.0, 100.0, 140.0, 100.0, 100.0, 140.0, 2.0);
        er_tri_at(farther, 90.0, 90.0, 160.0, 90.0, 90.0, 160.0, 4.0);
        if (order == 0) {
            er_draw_polygon(&fr, nearer, 3, 1);
            er_draw_polygon(&fr, farther, 3, 2);
        } else {
            er_draw_polygon(&fr, farther, 3, 2);
            er_draw_polygon(&fr, nearer, 3, 1);
        }
        er_expect(fr.index[110 * 320 + 110] == 1, "depth: the nearer triangle in front");
        er_expect(fr.index[92 * 320 + 92] == 2, "depth: the farther one where alone");
    }

    /* 5. Beyond the far plane: nothing. */
    er_clear(&fr, &v, 0);
    er_tri_at(t, 10.5, 10.5, 20.5, 10.5, 20.5, 20.5, 200.0);
    er_draw_polygon(&fr, t, 3, 7);
    er_expect(er_count(&fr, 7, &most) == 0, "far plane: nothing beyond it");

    if (er_failures == 0) {
        printf("exact_ref self-test: square 100 centres once each, top-left ties, near-plane cut, "
               "depth order both ways, far plane: ok\n");
    }
    return er_failures ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--self-test") == 0) {
        return er_self_test();
    }
    if (argc == 4 && strcmp(argv[1], "--dir") == 0) {
        return er_dir(argv[2], argv[3]);
    }
    if (argc == 3) {
        return er_one(argv[1], argv[2]);
    }
    fprintf(stderr, "usage: exact_ref SCENE PNG | --dir DUMPDIR OUTDIR | --self-test\n");
    return 2;
}
