/*
 * meshconv_core.c — see meshconv_core.h.
 */
#include "meshconv_core.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <meshoptimizer.h>

#include "model/crc32.h"
#include "model/meshfile.h"
#include "render/palette.h"

/* ---- materials ------------------------------------------------------------------------------ */

static const char *const material_names[MESHFILE_MAT_MAX + 1u] = {
    [MAT_RED] = "red",       [MAT_GREEN] = "green", [MAT_BLUE] = "blue",   [MAT_YELLOW] = "yellow",
    [MAT_CYAN] = "cyan",     [MAT_MAGENTA] = "magenta", [MAT_ORANGE] = "orange",
    [MAT_WHITE] = "white",   [MAT_GRASS] = "grass", [MAT_DIRT] = "dirt",   [MAT_STONE] = "stone",
    [MAT_SAND] = "sand",     [MAT_WATER] = "water",
};

uint8_t meshconv_material_from_name(const char *name)
{
    for (uint8_t m = MESHFILE_MAT_MIN; m <= MESHFILE_MAT_MAX; m++) {
        if (strcmp(name, material_names[m]) == 0) {
            return m;
        }
    }
    return 0;
}

const char *meshconv_material_name(uint8_t material)
{
    return (material >= MESHFILE_MAT_MIN && material <= MESHFILE_MAT_MAX) ? material_names[material]
                                                                           : "?";
}

uint8_t meshconv_nearest_material(float r, float g, float b)
{
    /* The firmware's own palette, so that a colour lands where the screen shows it: the full-light
     * entry of each material, RGB444 with R in bits 11:8 (render/palette.h's PAL_RGB444). */
    static uint16_t pal[PAL_ENTRIES];
    static bool built;
    const double want[3] = {(double)r * 15.0, (double)g * 15.0, (double)b * 15.0};
    uint8_t best = MAT_WHITE;
    double best_d = INFINITY;

    if (!built) {
        palette_build(pal);
        built = true;
    }
    for (uint8_t m = MESHFILE_MAT_MIN; m <= MESHFILE_MAT_MAX; m++) {
        const uint16_t e = pal[PAL_INDEX(m, PAL_SHADES - 1u)];
        const double have[3] = {(double)((e >> 8) & 0xFu), (double)((e >> 4) & 0xFu),
                                (double)(e & 0xFu)};
        double d = 0.0;

        for (int i = 0; i < 3; i++) {
            d += (want[i] - have[i]) * (want[i] - have[i]);
        }
        if (d < best_d) {  /* ties: the lower number, so the choice never depends on order */
            best_d = d;
            best = m;
        }
    }
    return best;
}

/* ---- helpers -------------------------------------------------------------------------------- */

void meshconv_default_options(struct meshconv_options *opt)
{
    opt->max_verts = MESHFILE_DEFAULT_MAX_VERTS;
    opt->max_faces = MESHFILE_DEFAULT_MAX_FACES;
    opt->may_simplify = false;
    opt->extent = 4.0;
    opt->default_material = MAT_WHITE;
}

void meshconv_free(struct meshconv_result *out)
{
    free(out->bytes);
    out->bytes = NULL;
    out->len = 0;
}

static int fail(struct meshconv_report *rep, int status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail(struct meshconv_report *rep, int status, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(rep->message, sizeof rep->message, fmt, ap);
    va_end(ap);
    return status;
}

/* A face of the quantised grid is kept when its indices differ and its area is not zero: exact
 * in int64 (coordinates below 2^15, differences below 2^16, products below 2^33). */
static bool face_ok(const int16_t *q, const uint32_t *f)
{
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
        return false;
    }
    const int16_t *a = &q[3u * f[0]], *b = &q[3u * f[1]], *c = &q[3u * f[2]];
    int64_t u[3], v[3];

    for (int i = 0; i < 3; i++) {
        u[i] = (int64_t)b[i] - a[i];
        v[i] = (int64_t)c[i] - a[i];
    }
    return u[1] * v[2] - u[2] * v[1] != 0 || u[2] * v[0] - u[0] * v[2] != 0 ||
           u[0] * v[1] - u[1] * v[0] != 0;
}

/* A working mesh: unique quantised vertices (and one source position each, in double, for
 * re-normalising after simplification), faces over them, a material per face. */
struct work {
    int16_t *q;        /* 3 per vertex */
    double *p;         /* 3 per vertex */
    size_t verts;
    uint32_t *f;       /* 3 per face */
    uint8_t *mat;      /* per face */
    size_t faces;
};

static void work_free(struct work *w)
{
    free(w->q);
    free(w->p);
    free(w->f);
    free(w->mat);
    memset(w, 0, sizeof *w);
}

struct keyed {
    uint64_t key;
    uint32_t index;
};

static int keyed_cmp(const void *a, const void *b)
{
    const struct keyed *x = a, *y = b;

    if (x->key != y->key) {
        return (x->key < y->key) ? -1 : 1;
    }
    return (x->index < y->index) ? -1 : (x->index > y->index);
}

/*
 * Steps 2-4 on faces f[0..faces) over positions p (every index valid): centre, scale, quantise,
 * merge, drop degenerate faces, and keep the used vertices in the order of first use (so that the
 * file does not depend on how the source ordered its vertex array). The counts go to *rep unless
 * it is NULL (the second pass after simplification).
 */
static int normalise(const double *p, size_t verts, const uint32_t *f, const uint8_t *mat,
                     size_t faces, double extent, struct meshconv_report *rep, struct work *out,
                     struct meshconv_report *fail_rep)
{
    int status = MESHCONV_ERR_INPUT;
    uint8_t *used = calloc(verts ? verts : 1u, 1);
    uint32_t *merged = malloc((verts ? verts : 1u) * sizeof *merged);
    int16_t *q = malloc((verts ? verts : 1u) * 3u * sizeof *q);
    struct keyed *keys = NULL;
    uint32_t *nf = malloc((faces ? faces : 1u) * 3u * sizeof *nf);
    uint8_t *nm = malloc(faces ? faces : 1u);
    uint32_t *order = NULL;
    size_t used_count = 0, nonfinite = 0, unique = 0, kept = 0, degenerate = 0;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};

    memset(out, 0, sizeof *out);
    if (!used || !merged || !q || !nf || !nm) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT, "out of memory (%zu vertices, %zu faces)", verts,
                      faces);
        goto done;
    }
    for (size_t i = 0; i < 3u * faces; i++) {
        if (!used[f[i]]) {
            used[f[i]] = 1;
            used_count++;
        }
    }
    for (size_t v = 0; v < verts; v++) {
        if (!used[v]) {
            continue;
        }
        if (!isfinite(p[3 * v]) || !isfinite(p[3 * v + 1]) || !isfinite(p[3 * v + 2])) {
            nonfinite++;
            continue;
        }
        for (int i = 0; i < 3; i++) {
            lo[i] = fmin(lo[i], p[3 * v + i]);
            hi[i] = fmax(hi[i], p[3 * v + i]);
        }
    }
    if (rep) {
        rep->verts_used = used_count;
        rep->nonfinite = nonfinite;
    }
    if (nonfinite) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT,
                      "%zu of %zu used vertices have a non-finite coordinate (NaN or infinity)",
                      nonfinite, used_count);
        goto done;
    }
    if (used_count == 0) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT, "no triangles");
        goto done;
    }
    /* Halves first: hi - lo and hi + lo overflow near the double's limit, their halves do not. */
    double centre[3], half = 0.0;
    for (int i = 0; i < 3; i++) {
        centre[i] = lo[i] / 2.0 + hi[i] / 2.0;
        half = fmax(half, hi[i] / 2.0 - lo[i] / 2.0);
    }
    if (rep) {
        memcpy(rep->centre, centre, sizeof centre);
        rep->half_extent = half;
        rep->scale = (half > 0.0) ? extent / half : 0.0;
    }
    /* (p - c) / half is in [-1, 1] and the same for a model and any power-of-ten copy of it up to
     * rounding of the last bit, which the rounding to 2^-12 units does not see. */
    const double units = extent * (double)(1u << MESHFILE_FRAC_BITS);
    for (size_t v = 0; v < verts; v++) {
        for (int i = 0; i < 3; i++) {
            double t = 0.0;

            if (used[v] && half > 0.0) {
                t = ((p[3 * v + i] - centre[i]) / half) * units;
            }
            /* Halves away from zero: symmetric (a mirrored model gives the mirrored file), and a
             * source already on the half-unit grid (Spider_binary.stl) lands where its decimal
             * print (Spider_ascii.stl, rounded away from the half) does. */
            t = fmax(-32767.0, fmin(32767.0, round(t)));
            q[3 * v + i] = (int16_t)t;
        }
    }
    /* Merge: sort the used vertices by their quantised coordinates. */
    keys = malloc((used_count ? used_count : 1u) * sizeof *keys);
    if (!keys) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT, "out of memory (%zu vertices)", verts);
        goto done;
    }
    size_t k = 0;
    for (size_t v = 0; v < verts; v++) {
        if (used[v]) {
            keys[k].key = ((uint64_t)(uint16_t)(q[3 * v] + 32768) << 32) |
                          ((uint64_t)(uint16_t)(q[3 * v + 1] + 32768) << 16) |
                          (uint64_t)(uint16_t)(q[3 * v + 2] + 32768);
            keys[k].index = (uint32_t)v;
            k++;
        }
    }
    qsort(keys, used_count, sizeof *keys, keyed_cmp);
    for (size_t i = 0; i < used_count; i++) {
        if (i > 0 && keys[i].key != keys[i - 1].key) {
            unique++;
        }
        /* Every copy maps to the first of its run (the lowest source index): a representative. */
        merged[keys[i].index] = (i == 0 || keys[i].key != keys[i - 1].key) ? keys[i].index
                                                                            : merged[keys[i - 1].index];
    }
    unique++;
    for (size_t i = 0; i < faces; i++) {
        const uint32_t g[3] = {merged[f[3 * i]], merged[f[3 * i + 1]], merged[f[3 * i + 2]]};

        if (!face_ok(q, g)) {
            degenerate++;
            continue;
        }
        memcpy(&nf[3 * kept], g, sizeof g);
        nm[kept] = mat[i];
        kept++;
    }
    if (rep) {
        rep->verts_merged = used_count - unique;
        rep->degenerate = degenerate;
    }
    if (kept == 0) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT,
                      "no triangles left: all %zu faces are degenerate once quantised", faces);
        goto done;
    }
    /* Renumber by first use. */
    order = malloc(verts * sizeof *order);
    out->q = malloc(unique * 3u * sizeof *out->q);
    out->p = malloc(unique * 3u * sizeof *out->p);
    if (!order || !out->q || !out->p) {
        status = fail(fail_rep, MESHCONV_ERR_INPUT, "out of memory (%zu vertices)", verts);
        goto done;
    }
    for (size_t v = 0; v < verts; v++) {
        order[v] = UINT32_MAX;
    }
    size_t n = 0;
    for (size_t i = 0; i < 3u * kept; i++) {
        const uint32_t v = nf[i];

        if (order[v] == UINT32_MAX) {
            order[v] = (uint32_t)n;
            memcpy(&out->q[3 * n], &q[3 * v], 3u * sizeof *q);
            memcpy(&out->p[3 * n], &p[3 * v], 3u * sizeof *p);
            n++;
        }
        nf[i] = order[v];
    }
    out->verts = n;
    out->f = nf;
    out->mat = nm;
    out->faces = kept;
    nf = NULL;
    nm = NULL;
    status = MESHCONV_OK;
done:
    if (status != MESHCONV_OK) {
        work_free(out);
    }
    free(used);
    free(merged);
    free(q);
    free(keys);
    free(nf);
    free(nm);
    free(order);
    return status;
}

/* Vertices the faces of a simplified index list use, and those faces with degenerate ones left
 * out (written to keep[], position indices). */
static size_t evaluate(const struct work *w, const uint32_t *corner_vertex, const uint32_t *dst,
                       size_t dst_faces, uint32_t *keep, uint8_t *keep_mat, const uint8_t *corner_mat,
                       uint8_t *seen, size_t *verts_used)
{
    size_t kept = 0, used = 0;

    memset(seen, 0, w->verts);
    for (size_t i = 0; i < dst_faces; i++) {
        const uint32_t g[3] = {corner_vertex[dst[3 * i]], corner_vertex[dst[3 * i + 1]],
                               corner_vertex[dst[3 * i + 2]]};

        if (!face_ok(w->q, g)) {
            continue;
        }
        for (int j = 0; j < 3; j++) {
            if (!seen[g[j]]) {
                seen[g[j]] = 1;
                used++;
            }
        }
        memcpy(&keep[3 * kept], g, sizeof g);
        keep_mat[kept] = corner_mat[dst[3 * i]];
        kept++;
    }
    *verts_used = used;
    return kept;
}

/*
 * Step 5: fewer faces with meshoptimizer, to max_faces faces and max_verts vertices. The
 * simplifier sees one vertex per (position, material) pair, so a colour boundary is a seam it
 * keeps; each output face takes its material from its first corner. A growing error target
 * first (meshopt_simplify stops at the target error, and at topology it must not break), then
 * meshopt_simplifySloppy, which reaches any count; and a smaller face target when the faces fit
 * but the vertices do not. The result is in *w (faces over w's vertices).
 */
static int simplify(struct work *w, const struct meshconv_options *opt, struct meshconv_report *rep)
{
    int status = MESHCONV_ERR_CAPACITY;
    const size_t corners = 3u * w->faces;
    struct keyed *keys = malloc(corners * sizeof *keys);
    uint32_t *sidx = malloc(corners * sizeof *sidx);
    uint32_t *svert = malloc(corners * sizeof *svert);  /* simplifier vertex -> position vertex */
    uint8_t *smat = malloc(corners);                     /* simplifier vertex -> material */
    float *spos = malloc(corners * 3u * sizeof *spos);
    uint32_t *dst = malloc(corners * sizeof *dst);
    uint32_t *keep = malloc(corners * sizeof *keep);
    uint8_t *keep_mat = malloc(w->faces);
    uint8_t *seen = malloc(w->verts);
    size_t sv = 0;

    if (!keys || !sidx || !svert || !smat || !spos || !dst || !keep || !keep_mat || !seen) {
        status = fail(rep, MESHCONV_ERR_INPUT, "out of memory (simplifying %zu faces)", w->faces);
        goto done;
    }
    for (size_t i = 0; i < corners; i++) {
        keys[i].key = ((uint64_t)w->f[i] << 4) | w->mat[i / 3u];
        keys[i].index = (uint32_t)i;
    }
    qsort(keys, corners, sizeof *keys, keyed_cmp);
    for (size_t i = 0; i < corners; i++) {
        if (i == 0 || keys[i].key != keys[i - 1].key) {
            const uint32_t v = (uint32_t)(keys[i].key >> 4);

            svert[sv] = v;
            smat[sv] = (uint8_t)(keys[i].key & 0xFu);
            for (int j = 0; j < 3; j++) {
                spos[3 * sv + j] = (float)w->q[3 * v + j];  /* int16: exact in float */
            }
            sv++;
        }
        sidx[keys[i].index] = (uint32_t)(sv - 1u);
    }
    /* meshoptimizer asserts a target no larger than its input (over capacity by vertices only). */
    size_t target = (opt->max_faces < w->faces) ? opt->max_faces : w->faces;
    for (int attempt = 0; attempt < 64 && target > 0; attempt++) {
        size_t got = 0;
        float err = 1e-3f, res = 0.0f;

        rep->simplifier = "meshopt_simplify";
        for (; err <= 1.0f; err *= 2.0f) {
            got = meshopt_simplify(dst, sidx, corners, spos, sv, 3u * sizeof(float), 3u * target,
                                   err, 0, &res) / 3u;
            if (got <= target) {
                break;
            }
        }
        if (got > target) {
            rep->simplifier = "meshopt_simplifySloppy";
            err = 1.0f;
            got = meshopt_simplifySloppy(dst, sidx, corners, spos, sv, 3u * sizeof(float),
                                         3u * target, err, &res) / 3u;
        }
        size_t verts = 0;
        const size_t kept = evaluate(w, svert, dst, got, keep, keep_mat, smat, seen, &verts);

        if (kept == 0) {
            break;
        }
        if (kept <= opt->max_faces && verts <= opt->max_verts) {
            memcpy(w->f, keep, 3u * kept * sizeof *keep);
            memcpy(w->mat, keep_mat, kept);
            w->faces = kept;
            rep->simplified = true;
            rep->simplify_error = err;
            status = MESHCONV_OK;
            goto done;
        }
        /* Short of the goal: aim lower, in proportion to the excess (and at least one face). */
        double ratio = fmin((double)opt->max_faces / (double)kept,
                            (double)opt->max_verts / (double)verts);
        size_t next = (size_t)((double)target * fmin(ratio, 1.0) * 0.95);
        target = (next < target) ? next : target - 1u;
    }
    status = fail(rep, MESHCONV_ERR_CAPACITY,
                  "simplification cannot reach %u faces and %u vertices (from %zu faces, %zu "
                  "vertices)", opt->max_faces, opt->max_verts, w->faces, w->verts);
done:
    free(keys);
    free(sidx);
    free(svert);
    free(smat);
    free(spos);
    free(dst);
    free(keep);
    free(keep_mat);
    free(seen);
    return status;
}

/* ---- the file ------------------------------------------------------------------------------- */

static uint8_t *put16(uint8_t *b, uint32_t v)
{
    b[0] = (uint8_t)v;
    b[1] = (uint8_t)(v >> 8);
    return b + 2;
}

static uint8_t *put32(uint8_t *b, uint32_t v)
{
    return put16(put16(b, v & 0xFFFFu), v >> 16);
}

static int write_file(const struct work *w, struct meshconv_result *out, struct meshconv_report *rep)
{
    const size_t len = meshfile_bytes((uint32_t)w->verts, (uint32_t)w->faces);
    uint8_t *buf = malloc(len), *b = buf;
    int16_t lo[3] = {INT16_MAX, INT16_MAX, INT16_MAX}, hi[3] = {INT16_MIN, INT16_MIN, INT16_MIN};

    if (!buf) {
        return fail(rep, MESHCONV_ERR_INPUT, "out of memory (%zu bytes)", len);
    }
    for (size_t v = 0; v < w->verts; v++) {
        for (int i = 0; i < 3; i++) {
            lo[i] = (w->q[3 * v + i] < lo[i]) ? w->q[3 * v + i] : lo[i];
            hi[i] = (w->q[3 * v + i] > hi[i]) ? w->q[3 * v + i] : hi[i];
        }
    }
    *b++ = MESHFILE_MAGIC0;
    *b++ = MESHFILE_MAGIC1;
    *b++ = MESHFILE_MAGIC2;
    *b++ = MESHFILE_MAGIC3;
    b = put16(b, MESHFILE_VERSION);
    b = put16(b, MESHFILE_FRAC_BITS);
    b = put32(b, (uint32_t)w->verts);
    b = put32(b, (uint32_t)w->faces);
    for (int i = 0; i < 3; i++) {
        b = put16(b, (uint16_t)lo[i]);
    }
    for (int i = 0; i < 3; i++) {
        b = put16(b, (uint16_t)hi[i]);
    }
    b = put32(b, 0u);
    for (size_t i = 0; i < 3u * w->verts; i++) {
        b = put16(b, (uint16_t)w->q[i]);
    }
    memset(rep->material_faces, 0, sizeof rep->material_faces);
    for (size_t i = 0; i < w->faces; i++) {
        const uint32_t *f = &w->f[3 * i];
        const int16_t *a = &w->q[3u * f[0]], *c1 = &w->q[3u * f[1]], *c2 = &w->q[3u * f[2]];
        double u[3], v[3], n[3];

        for (int j = 0; j < 3; j++) {
            u[j] = (double)c1[j] - a[j];
            v[j] = (double)c2[j] - a[j];
        }
        /* mesh.h's winding: n = (v1 - v0) x (v2 - v0); not zero, face_ok said so. */
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        const double len_n = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int j = 0; j < 3; j++) {
            b = put16(b, f[j]);
        }
        for (int j = 0; j < 3; j++) {
            b = put16(b, (uint16_t)(int16_t)lrint(n[j] / len_n * MESHFILE_NORMAL_ONE));
        }
        *b++ = w->mat[i];
        *b++ = 0;  /* flags: no quad pairing */
        rep->material_faces[w->mat[i]]++;
    }
    b = put32(b, crc32_update(0, buf, len - MESHFILE_CRC_BYTES));
    out->bytes = buf;
    out->len = len;
    rep->faces_out = w->faces;
    rep->verts_out = w->verts;
    return MESHCONV_OK;
}

/* ---- the whole conversion ------------------------------------------------------------------- */

int meshconv_convert(const struct meshconv_mesh *mesh, const struct meshconv_options *opt,
                     struct meshconv_report *rep, struct meshconv_result *out)
{
    int status;
    uint32_t *f = NULL;
    uint8_t *mat = NULL;
    struct work w = {0}, w2 = {0};
    size_t kept = 0;

    memset(rep, 0, sizeof *rep);
    out->bytes = NULL;
    out->len = 0;
    rep->faces_in = mesh->face_count;
    rep->verts_in = mesh->vert_count;
    if (opt->max_verts < 3u || opt->max_verts > 65536u || opt->max_faces < 1u ||
        opt->max_faces > MESHCONV_FACES_LIMIT || !(opt->extent > 0.0) ||
        !(opt->extent <= MESHCONV_EXTENT_MAX) || opt->default_material < MESHFILE_MAT_MIN ||
        opt->default_material > MESHFILE_MAT_MAX) {
        return fail(rep, MESHCONV_ERR_USAGE, "options out of range");
    }
    if (mesh->face_count > UINT32_MAX / 3u || mesh->vert_count > UINT32_MAX) {
        return fail(rep, MESHCONV_ERR_INPUT, "too large: %zu faces, %zu vertices", mesh->face_count,
                    mesh->vert_count);
    }
    f = malloc((mesh->face_count ? mesh->face_count : 1u) * 3u * sizeof *f);
    mat = malloc(mesh->face_count ? mesh->face_count : 1u);
    if (!f || !mat) {
        status = fail(rep, MESHCONV_ERR_INPUT, "out of memory (%zu faces)", mesh->face_count);
        goto done;
    }
    /* Step 1, and each face's material from its colour. */
    for (size_t i = 0; i < mesh->face_count; i++) {
        const uint32_t *g = &mesh->idx[3 * i];
        float rgb[3] = {-1.0f, 0.0f, 0.0f};

        if (g[0] >= mesh->vert_count || g[1] >= mesh->vert_count || g[2] >= mesh->vert_count) {
            rep->bad_index++;
            continue;
        }
        if (mesh->vert_rgb) {
            for (int j = 0; j < 3; j++) {
                rgb[j] = (mesh->vert_rgb[3u * g[0] + j] + mesh->vert_rgb[3u * g[1] + j] +
                          mesh->vert_rgb[3u * g[2] + j]) / 3.0f;
            }
        } else if (mesh->face_rgb && mesh->face_rgb[3 * i] >= 0.0f) {
            memcpy(rgb, &mesh->face_rgb[3 * i], sizeof rgb);
        }
        if (rgb[0] >= 0.0f && isfinite(rgb[0]) && isfinite(rgb[1]) && isfinite(rgb[2])) {
            mat[kept] = meshconv_nearest_material(rgb[0], rgb[1], rgb[2]);
            rep->colour_faces++;
        } else {
            mat[kept] = opt->default_material;
        }
        memcpy(&f[3 * kept], g, 3u * sizeof *g);
        kept++;
    }
    if (kept == 0) {
        status = (mesh->face_count == 0)
                     ? fail(rep, MESHCONV_ERR_INPUT, "no triangles")
                     : fail(rep, MESHCONV_ERR_INPUT,
                            "no triangles left: all %zu faces have an index past the %zu vertices",
                            mesh->face_count, mesh->vert_count);
        goto done;
    }
    /* Steps 2-4. */
    status = normalise(mesh->pos, mesh->vert_count, f, mat, kept, opt->extent, rep, &w, rep);
    if (status != MESHCONV_OK) {
        goto done;
    }
    rep->faces_merged = w.faces;
    rep->verts_unique = w.verts;
    /* Step 5. */
    if (w.faces > opt->max_faces || w.verts > opt->max_verts) {
        if (!opt->may_simplify) {
            status = fail(rep, MESHCONV_ERR_CAPACITY,
                          "%zu faces and %zu vertices after merging; the firmware holds %u and %u: "
                          "pass --max-faces N to simplify",
                          w.faces, w.verts, opt->max_faces, opt->max_verts);
            goto done;
        }
        status = simplify(&w, opt, rep);
        if (status != MESHCONV_OK) {
            goto done;
        }
        /* What is left may span a smaller box: centre and scale it again from the source
         * positions, so the file keeps the format's box rule. Merging only lowers the counts. */
        status = normalise(w.p, w.verts, w.f, w.mat, w.faces, opt->extent, NULL, &w2, rep);
        if (status != MESHCONV_OK) {
            goto done;
        }
        work_free(&w);
        w = w2;
        memset(&w2, 0, sizeof w2);
        /* The scale that holds for the output. */
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        double half = 0.0;
        for (size_t v = 0; v < w.verts; v++) {
            for (int j = 0; j < 3; j++) {
                lo[j] = fmin(lo[j], w.p[3 * v + j]);
                hi[j] = fmax(hi[j], w.p[3 * v + j]);
            }
        }
        for (int j = 0; j < 3; j++) {
            rep->centre[j] = lo[j] / 2.0 + hi[j] / 2.0;
            half = fmax(half, hi[j] / 2.0 - lo[j] / 2.0);
        }
        rep->half_extent = half;
        rep->scale = (half > 0.0) ? opt->extent / half : 0.0;
    }
    /* Step 6. */
    status = write_file(&w, out, rep);
done:
    free(f);
    free(mat);
    work_free(&w);
    work_free(&w2);
    return status;
}
