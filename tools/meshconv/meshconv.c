/*
 * meshconv — any model assimp reads -> a .gmsh file (docs/mesh-format.md). The edge: options,
 * assimp, the scene's nodes, the firmware's validator on the result, the atomic write. The
 * conversion itself is meshconv_core.c.
 *
 *   meshconv IN OUT.gmsh [--max-faces N] [--max-verts N] [--extent X] [--material NAME] [--quiet]
 *   meshconv --check FILE.gmsh [--max-faces N] [--max-verts N]
 *
 * Exit status: 0 written (or valid), 1 the input cannot be converted (or the file is invalid),
 * 2 usage, 3 over capacity. Every failure is one "meshconv: error: ..." line on stderr, and leaves
 * no OUT behind (the file is written under a temporary name and renamed).
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <signal.h>
#include <sys/resource.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <assimp/cimport.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "meshconv_core.h"
#include "model/meshfile.h"

/* Beyond this a scene is refused before copying: it could not be simplified in reasonable memory
 * and time (a 100k-face model takes well under a second). */
#define MESHCONV_MAX_SOURCE_FACES 20000000u
/* Deeper node trees than this are refused: the walk is recursive. */
#define MESHCONV_MAX_NODE_DEPTH 256
/* --check reads at most this much: more than any capacity a uint16 index allows. */
#define MESHCONV_MAX_FILE_BYTES (64u << 20)

/* Limits that turn a hostile file's huge claims into an error rather than a hang: assimp reserves
 * what a header claims (invalid/OutOfMemory.off: 353535235358 vertices), which a limit on the
 * address space makes fail as std::bad_alloc, reported by assimp; and a wall-clock limit for
 * importers that loop. */
#define MESHCONV_MEMORY_LIMIT (8ull << 30)
#define MESHCONV_TIME_LIMIT_S 120u

static bool quiet;

static void on_alarm(int sig)
{
    static const char msg[] = "meshconv: error: gave up after the time limit (120 s)\n";

    (void)sig;
    if (write(STDERR_FILENO, msg, sizeof msg - 1u) < 0) {
        _exit(1);
    }
    _exit(1);
}

static void set_limits(void)
{
    struct rlimit r;

    if (getrlimit(RLIMIT_AS, &r) == 0 && (r.rlim_cur == RLIM_INFINITY || r.rlim_cur > MESHCONV_MEMORY_LIMIT)) {
        r.rlim_cur = MESHCONV_MEMORY_LIMIT;
        setrlimit(RLIMIT_AS, &r);
    }
    signal(SIGALRM, on_alarm);
    alarm(MESHCONV_TIME_LIMIT_S);
}

static int error(int status, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int error(int status, const char *fmt, ...)
{
    va_list ap;

    fputs("meshconv: error: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return status;
}

static void say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void say(const char *fmt, ...)
{
    va_list ap;

    if (quiet) {
        return;
    }
    fputs("meshconv: ", stdout);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
}

static double now_ms(void)
{
    struct timespec t;

    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static bool parse_u32(const char *s, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long v;

    errno = 0;
    v = strtoul(s, &end, 10);
    if (errno || end == s || *end || s[0] == '-' || v < lo || v > hi) {
        return false;
    }
    *out = (uint32_t)v;
    return true;
}

static int usage(const char *why)
{
    error(2, "%s", why);
    fputs("usage: meshconv IN OUT.gmsh [--max-faces N] [--max-verts N] [--extent X] "
          "[--material NAME] [--quiet]\n"
          "       meshconv --check FILE.gmsh [--max-faces N] [--max-verts N]\n",
          stderr);
    return 2;
}

/* ---- the scene -> one mesh ------------------------------------------------------------------ */

struct soup {
    double *pos;
    size_t verts, vert_cap;
    uint32_t *idx;
    size_t faces, face_cap;
    float *vert_rgb;      /* allocated only once some mesh has vertex colours */
    float *face_rgb;
    size_t ignored;       /* points and lines */
    size_t meshes;
};

static bool grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) {
        return true;
    }
    size_t n = *cap ? *cap : 1024u;
    while (n < need) {
        n *= 2u;
    }
    void *q = realloc(*p, n * elem);
    if (!q) {
        return false;
    }
    *p = q;
    *cap = n;
    return true;
}

/* The colour a material gives its faces, or r = -1 when it has none: assimp's stand-in for
 * formats without materials (AI_DEFAULT_MATERIAL_NAME) means "no colour", the default. */
static void material_rgb(const struct aiScene *sc, unsigned m, float rgb[3])
{
    struct aiColor4D c;
    struct aiString name;

    rgb[0] = -1.0f;
    if (m >= sc->mNumMaterials || !sc->mMaterials[m]) {
        return;
    }
    if (aiGetMaterialString(sc->mMaterials[m], AI_MATKEY_NAME, &name) == aiReturn_SUCCESS &&
        strcmp(name.data, AI_DEFAULT_MATERIAL_NAME) == 0) {
        return;
    }
    if (aiGetMaterialColor(sc->mMaterials[m], AI_MATKEY_BASE_COLOR, &c) == aiReturn_SUCCESS ||
        aiGetMaterialColor(sc->mMaterials[m], AI_MATKEY_COLOR_DIFFUSE, &c) == aiReturn_SUCCESS) {
        rgb[0] = fminf(fmaxf(c.r, 0.0f), 1.0f);
        rgb[1] = fminf(fmaxf(c.g, 0.0f), 1.0f);
        rgb[2] = fminf(fmaxf(c.b, 0.0f), 1.0f);
    }
}

/* Appends one mesh's triangles with the node's transform t (row-major 4x4, in double). */
static int add_mesh(struct soup *s, const struct aiScene *sc, const struct aiMesh *m, const double t[16])
{
    size_t tris = 0;
    float rgb[3];

    for (unsigned i = 0; i < m->mNumFaces; i++) {
        if (m->mFaces[i].mNumIndices == 3u) {
            tris++;
        } else {
            s->ignored++;
        }
    }
    if (tris == 0 || !m->mVertices) {
        return 0;
    }
    if (s->faces + tris > MESHCONV_MAX_SOURCE_FACES) {
        return error(1, "more than %u faces in the scene", MESHCONV_MAX_SOURCE_FACES);
    }
    const size_t base = s->verts;
    const size_t old_vcap = s->vert_cap;
    if (!grow((void **)&s->pos, &s->vert_cap, base + m->mNumVertices, 3u * sizeof(double)) ||
        !grow((void **)&s->idx, &s->face_cap, s->faces + tris, 3u * sizeof(uint32_t))) {
        return error(1, "out of memory (%zu faces)", s->faces + tris);
    }
    /* Colour arrays follow the position and index arrays' capacities. */
    if (s->vert_rgb && s->vert_cap != old_vcap) {
        float *q = realloc(s->vert_rgb, s->vert_cap * 3u * sizeof(float));
        if (!q) {
            return error(1, "out of memory");
        }
        s->vert_rgb = q;
    }
    float *frgb = realloc(s->face_rgb, s->face_cap * 3u * sizeof(float));
    if (!frgb) {
        return error(1, "out of memory");
    }
    s->face_rgb = frgb;
    if (m->mColors[0] && !s->vert_rgb) {
        /* The first mesh with vertex colours: the core then colours every face from its
         * vertices, so the vertices so far carry their faces' material colour. */
        s->vert_rgb = malloc(s->vert_cap * 3u * sizeof(float));
        if (!s->vert_rgb) {
            return error(1, "out of memory");
        }
        for (size_t f = 0; f < s->faces; f++) {
            for (int k = 0; k < 3; k++) {
                memcpy(&s->vert_rgb[3u * s->idx[3 * f + k]], &s->face_rgb[3 * f], 3u * sizeof(float));
            }
        }
    }
    material_rgb(sc, m->mMaterialIndex, rgb);
    for (unsigned v = 0; v < m->mNumVertices; v++) {
        const double p[3] = {m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z};
        double *o = &s->pos[3 * (base + v)];

        for (int r = 0; r < 3; r++) {
            o[r] = t[4 * r] * p[0] + t[4 * r + 1] * p[1] + t[4 * r + 2] * p[2] + t[4 * r + 3];
        }
        if (s->vert_rgb) {
            float *c = &s->vert_rgb[3 * (base + v)];
            if (m->mColors[0]) {
                c[0] = fminf(fmaxf(m->mColors[0][v].r, 0.0f), 1.0f);
                c[1] = fminf(fmaxf(m->mColors[0][v].g, 0.0f), 1.0f);
                c[2] = fminf(fmaxf(m->mColors[0][v].b, 0.0f), 1.0f);
            } else {
                memcpy(c, rgb, sizeof rgb);
            }
        }
    }
    for (unsigned i = 0; i < m->mNumFaces; i++) {
        const struct aiFace *f = &m->mFaces[i];

        if (f->mNumIndices != 3u) {
            continue;
        }
        for (int k = 0; k < 3; k++) {
            /* An index past this mesh's vertices stays past the soup's: the core drops it. */
            s->idx[3 * s->faces + k] = (f->mIndices[k] < m->mNumVertices)
                                           ? (uint32_t)(base + f->mIndices[k])
                                           : UINT32_MAX;
        }
        memcpy(&s->face_rgb[3 * s->faces], rgb, sizeof rgb);
        s->faces++;
    }
    s->verts += m->mNumVertices;
    s->meshes++;
    return 0;
}

static void mat_mul(const double a[16], const struct aiMatrix4x4 *b, double out[16])
{
    const double bb[16] = {b->a1, b->a2, b->a3, b->a4, b->b1, b->b2, b->b3, b->b4,
                           b->c1, b->c2, b->c3, b->c4, b->d1, b->d2, b->d3, b->d4};

    for (int r = 0; r < 4; r++) {
        for (int c = 0; c < 4; c++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++) {
                sum += a[4 * r + k] * bb[4 * k + c];
            }
            out[4 * r + c] = sum;
        }
    }
}

static int walk(struct soup *s, const struct aiScene *sc, const struct aiNode *n, const double parent[16],
                int depth)
{
    double t[16];

    if (depth > MESHCONV_MAX_NODE_DEPTH) {
        return error(1, "the node tree is deeper than %d", MESHCONV_MAX_NODE_DEPTH);
    }
    mat_mul(parent, &n->mTransformation, t);
    for (unsigned i = 0; i < n->mNumMeshes; i++) {
        if (n->mMeshes[i] < sc->mNumMeshes && sc->mMeshes[n->mMeshes[i]]) {
            const int rc = add_mesh(s, sc, sc->mMeshes[n->mMeshes[i]], t);
            if (rc) {
                return rc;
            }
        }
    }
    for (unsigned i = 0; i < n->mNumChildren; i++) {
        if (n->mChildren[i]) {
            const int rc = walk(s, sc, n->mChildren[i], t, depth + 1);
            if (rc) {
                return rc;
            }
        }
    }
    return 0;
}

static void soup_free(struct soup *s)
{
    free(s->pos);
    free(s->idx);
    free(s->vert_rgb);
    free(s->face_rgb);
    memset(s, 0, sizeof *s);
}

/* ---- output --------------------------------------------------------------------------------- */

static int write_atomic(const char *path, const uint8_t *buf, size_t len)
{
    const size_t n = strlen(path) + 32u;
    char *tmp = malloc(n);
    FILE *f;

    if (!tmp) {
        return error(1, "out of memory");
    }
    snprintf(tmp, n, "%s.tmp%ld", path, (long)getpid());
    f = fopen(tmp, "wb");
    if (!f) {
        int e = errno;
        free(tmp);
        return error(1, "%s: %s", path, strerror(e));
    }
    const bool ok = fwrite(buf, 1, len, f) == len;
    if (fclose(f) != 0 || !ok || rename(tmp, path) != 0) {
        int e = errno;
        unlink(tmp);
        free(tmp);
        return error(1, "%s: cannot write: %s", path, strerror(e));
    }
    free(tmp);
    return 0;
}

static int self_check(const uint8_t *buf, size_t len, uint32_t max_verts, uint32_t max_faces,
                      struct meshfile_info *info)
{
    const int err = meshfile_check(buf, len, max_verts, max_faces, info);

    if (err != 0) {
        char why[256];
        meshfile_message(err, info, why, sizeof why);
        return error(1, "the firmware's validator refuses the result (a converter bug): %s", why);
    }
    return 0;
}

/* ---- the commands --------------------------------------------------------------------------- */

static int check_file(const char *path, uint32_t max_verts, uint32_t max_faces)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t len = 0;
    struct meshfile_info info;

    if (!f) {
        return error(1, "%s: %s", path, strerror(errno));
    }
    buf = malloc(MESHCONV_MAX_FILE_BYTES + 1u);
    if (!buf) {
        fclose(f);
        return error(1, "out of memory");
    }
    len = fread(buf, 1, MESHCONV_MAX_FILE_BYTES + 1u, f);
    fclose(f);
    if (len > MESHCONV_MAX_FILE_BYTES) {
        free(buf);
        return error(1, "%s: larger than %u bytes", path, MESHCONV_MAX_FILE_BYTES);
    }
    const int err = meshfile_check(buf, len, max_verts, max_faces, &info);
    free(buf);
    if (err != 0) {
        char why[256];
        meshfile_message(err, &info, why, sizeof why);
        return error(1, "%s: invalid: %s", path, why);
    }
    printf("%s: valid: %u vertices, %u faces, box (%d %d %d) .. (%d %d %d), %zu bytes\n", path,
           info.verts, info.faces, info.box_lo[0], info.box_lo[1], info.box_lo[2], info.box_hi[0],
           info.box_hi[1], info.box_hi[2], len);
    return 0;
}

static int convert(const char *in, const char *outp, const struct meshconv_options *opt)
{
    const double t0 = now_ms();
    const struct aiScene *sc;
    struct soup s = {0};
    struct meshconv_report rep;
    struct meshconv_result res;
    struct meshfile_info info;
    size_t polygons = 0, faces_raw = 0;
    int rc;

    /* Validation first (assimp's own checks: indices in range, counts consistent), then the
     * polygons counted before triangulation splits them. */
    sc = aiImportFile(in, aiProcess_ValidateDataStructure);
    if (!sc) {
        const char *why = aiGetErrorString();
        return error(1, "%s: %s", in, (why && *why) ? why : "assimp cannot read it");
    }
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *m = sc->mMeshes[i];
        for (unsigned j = 0; m && j < m->mNumFaces; j++) {
            faces_raw++;
            polygons += m->mFaces[j].mNumIndices > 3u;
        }
    }
    sc = aiApplyPostProcessing(sc, aiProcess_Triangulate | aiProcess_SortByPType);
    if (!sc) {
        const char *why = aiGetErrorString();
        return error(1, "%s: %s", in, (why && *why) ? why : "assimp cannot triangulate it");
    }
    static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    if (sc->mRootNode) {
        rc = walk(&s, sc, sc->mRootNode, identity, 0);
    } else {
        rc = 0;
        for (unsigned i = 0; i < sc->mNumMeshes && rc == 0; i++) {
            if (sc->mMeshes[i]) {
                rc = add_mesh(&s, sc, sc->mMeshes[i], identity);
            }
        }
    }
    aiReleaseImport(sc);
    if (rc) {
        soup_free(&s);
        return rc;
    }
    if (s.faces == 0) {
        const size_t ignored = s.ignored;
        soup_free(&s);
        return error(1, "%s: no triangles (%zu points or lines ignored)", in, ignored);
    }
    say("read %s: %zu faces in %zu meshes (%zu polygons triangulated, %zu points/lines ignored)",
        in, faces_raw, s.meshes, polygons, s.ignored);
    const struct meshconv_mesh mesh = {
        .pos = s.pos, .vert_count = s.verts, .idx = s.idx, .face_count = s.faces,
        .vert_rgb = s.vert_rgb, .face_rgb = s.face_rgb,
    };
    rc = meshconv_convert(&mesh, opt, &rep, &res);
    soup_free(&s);
    if (rc != MESHCONV_OK) {
        return error(rc, "%s: %s", in, rep.message);
    }
    say("faces: %zu triangles in, %zu with a bad index dropped, %zu degenerate dropped, %zu left",
        rep.faces_in, rep.bad_index, rep.degenerate, rep.faces_merged);
    say("vertices: %zu in, %zu used, %zu merged, %zu left", rep.verts_in, rep.verts_used,
        rep.verts_merged, rep.verts_unique);
    if (rep.simplified) {
        say("simplification: %zu faces -> %zu (%s, error target %g), %zu vertices -> %zu",
            rep.faces_merged, rep.faces_out, rep.simplifier, rep.simplify_error, rep.verts_unique,
            rep.verts_out);
    } else {
        say("simplification: none needed (capacity %u faces, %u vertices)", opt->max_faces,
            opt->max_verts);
    }
    say("scale: centre (%g %g %g), half-extent %g, factor %g (to %g units)", rep.centre[0],
        rep.centre[1], rep.centre[2], rep.half_extent, rep.scale, opt->extent);
    char mats[512];
    size_t used = 0;
    mats[0] = '\0';
    for (uint8_t m = MESHFILE_MAT_MIN; m <= MESHFILE_MAT_MAX; m++) {
        if (rep.material_faces[m] && used < sizeof mats) {
            used += (size_t)snprintf(mats + used, sizeof mats - used, " %s %u",
                                     meshconv_material_name(m), rep.material_faces[m]);
        }
    }
    say("materials: %zu faces coloured, the rest %s; faces per material:%s", rep.colour_faces,
        meshconv_material_name(opt->default_material), mats);
    rc = self_check(res.bytes, res.len, opt->max_verts, opt->max_faces, &info);
    if (rc == 0) {
        rc = write_atomic(outp, res.bytes, res.len);
    }
    if (rc == 0) {
        say("wrote %s: %zu bytes, %zu faces, %zu vertices, in %.0f ms", outp, res.len, rep.faces_out,
            rep.verts_out, now_ms() - t0);
    }
    meshconv_free(&res);
    return rc;
}

int main(int argc, char **argv)
{
    struct meshconv_options opt;
    const char *pos[2] = {NULL, NULL};
    int npos = 0;
    bool check = false;

    meshconv_default_options(&opt);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const bool has_value = i + 1 < argc;

        if (strcmp(a, "--check") == 0) {
            check = true;
        } else if (strcmp(a, "--quiet") == 0) {
            quiet = true;
        } else if (strcmp(a, "--max-faces") == 0) {
            if (!has_value || !parse_u32(argv[++i], 1u, MESHCONV_FACES_LIMIT, &opt.max_faces)) {
                return usage("--max-faces needs a number of faces, 1 or more");
            }
            opt.may_simplify = true;
        } else if (strcmp(a, "--max-verts") == 0) {
            if (!has_value || !parse_u32(argv[++i], 3u, 65535u, &opt.max_verts)) {
                return usage("--max-verts needs a number of vertices, 3 .. 65535 (uint16 indices)");
            }
        } else if (strcmp(a, "--extent") == 0) {
            char *end;
            if (!has_value) {
                return usage("--extent needs a number");
            }
            opt.extent = strtod(argv[++i], &end);
            if (*end || !(opt.extent > 0.0) || !(opt.extent <= MESHCONV_EXTENT_MAX)) {
                return usage("--extent needs a number of world units above 0 and at most 7.99 "
                             "(Q3.12)");
            }
        } else if (strcmp(a, "--material") == 0) {
            if (!has_value || !(opt.default_material = meshconv_material_from_name(argv[++i]))) {
                return usage("--material needs one of red green blue yellow cyan magenta orange "
                             "white grass dirt stone sand water");
            }
        } else if (a[0] == '-' && a[1] != '\0') {
            char why[300];
            snprintf(why, sizeof why, "unknown option %.200s", a);
            return usage(why);
        } else if (npos < 2) {
            pos[npos++] = a;
        } else {
            return usage("too many arguments");
        }
    }
    if (check) {
        if (npos != 1) {
            return usage("--check takes one file");
        }
        return check_file(pos[0], opt.max_verts, opt.max_faces);
    }
    if (npos != 2) {
        return usage("expected an input model and an output .gmsh file");
    }
    set_limits();
    return convert(pos[0], pos[1], &opt);
}
