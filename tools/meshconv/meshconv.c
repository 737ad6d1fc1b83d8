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
#include <sys/types.h>
#include <sys/wait.h>
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
#include "meshconv_scene.h"
#include "model/meshfile.h"

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

/* ---- output --------------------------------------------------------------------------------- */

/* The temporary name of OUT while process pid writes it. */
static void temp_name(char *buf, size_t cap, const char *path, pid_t pid)
{
    snprintf(buf, cap, "%s.tmp%ld", path, (long)pid);
}

static int write_atomic(const char *path, const uint8_t *buf, size_t len)
{
    const size_t n = strlen(path) + 32u;
    char *tmp = malloc(n);
    FILE *f;

    if (!tmp) {
        return error(1, "out of memory");
    }
    temp_name(tmp, n, path, getpid());
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
    struct meshconv_soup s;
    struct meshconv_report rep;
    struct meshconv_result res;
    struct meshfile_info info;
    size_t polygons = 0, faces_raw = 0;
    int rc;

    sc = aiImportFile(in, MESHCONV_IMPORT_FLAGS);
    if (!sc) {
        const char *why = aiGetErrorString();
        return error(1, "%s: %s", in, (why && *why) ? why : "assimp cannot read it");
    }
    meshconv_scene_count(sc, &faces_raw, &polygons);
    sc = aiApplyPostProcessing(sc, MESHCONV_POSTPROCESS);
    if (!sc) {
        const char *why = aiGetErrorString();
        return error(1, "%s: %s", in, (why && *why) ? why : "assimp cannot triangulate it");
    }
    rc = meshconv_scene_soup(sc, &s);
    aiReleaseImport(sc);
    if (rc) {
        rc = error(1, "%s: %s", in, s.message);
        meshconv_soup_free(&s);
        return rc;
    }
    if (s.faces == 0) {
        const size_t ignored = s.ignored;
        meshconv_soup_free(&s);
        return error(1, "%s: no triangles (%zu points or lines ignored)", in, ignored);
    }
    say("read %s: %zu faces in %zu meshes (%zu polygons triangulated, %zu points/lines ignored)",
        in, faces_raw, s.meshes, polygons, s.ignored);
    const struct meshconv_mesh mesh = meshconv_soup_mesh(&s);
    rc = meshconv_convert(&mesh, opt, &rep, &res);
    meshconv_soup_free(&s);
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

/*
 * The conversion in a child process: assimp's readers crash on some malformed files (a binary PLY
 * found by fuzz_meshconv: SIGSEGV inside libassimp), and a crash must still end as one error
 * line, a status and no OUT. The limits apply to the child only.
 */
static int convert_isolated(const char *in, const char *outp, const struct meshconv_options *opt)
{
    int st = 0;
    pid_t pid;

    fflush(NULL);
    pid = fork();
    if (pid < 0) {
        set_limits();  /* no child: convert here, unprotected from a crash */
        return convert(in, outp, opt);
    }
    if (pid == 0) {
        set_limits();
        const int rc = convert(in, outp, opt);
        fflush(NULL);
        _exit(rc);
    }
    while (waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) {
            return error(1, "%s: lost the converting process: %s", in, strerror(errno));
        }
    }
    if (WIFEXITED(st)) {
        return WEXITSTATUS(st);
    }
    /* Killed: whatever it had begun to write goes. */
    const size_t n = strlen(outp) + 32u;
    char *tmp = malloc(n);
    if (tmp) {
        temp_name(tmp, n, outp, pid);
        unlink(tmp);
        free(tmp);
    }
    return error(1, "%s: the importer crashed (signal %d, %s): assimp cannot read this file", in,
                 WTERMSIG(st), strsignal(WTERMSIG(st)));
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
            if (!has_value || !parse_u32(argv[++i], 3u, 65536u, &opt.max_verts)) {
                return usage("--max-verts needs a number of vertices, 3 .. 65536 (uint16 indices 0 .. 65535)");
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
    return convert_isolated(pos[0], pos[1], &opt);
}
