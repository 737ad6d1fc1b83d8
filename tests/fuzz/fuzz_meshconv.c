/*
 * fuzz_meshconv — libFuzzer target for the model converter's path: bytes -> assimp (from memory)
 * -> meshconv_scene (the scene walk) -> meshconv_core -> the firmware's validator, as
 * tools/meshconv/meshconv.c runs it.
 *
 * The input: byte 0 picks the format hint (low 4 bits: obj stl off gltf glb 3ds ac ase nff smd
 * raw x dae, assimp's readers of the formats a user would hand the converter) and the
 * capacity (high 4 bits: small capacities reach the simplifier; odd values allow simplifying,
 * as --max-faces does); the rest is the file.
 *
 * Properties (a violation aborts; ASan + UBSan are on, assimp itself is not instrumented):
 *   - an accepted mesh is a file the firmware's meshfile_check accepts at the capacity asked
 *     for, exactly meshfile_bytes long, with the counts the report gives;
 *   - over capacity without leave to simplify is always refused with MESHCONV_ERR_CAPACITY;
 *   - every refusal is MESHCONV_ERR_INPUT or MESHCONV_ERR_CAPACITY with a one-line message;
 *   - the conversion is deterministic: the same mesh converts to the same bytes twice.
 *
 * Left out: PLY. assimp 5.2.5's PLY reader crashes (SIGSEGV inside libassimp) on a binary file
 * cut short and loops without end, allocating, on an ASCII header cut short — both found by this
 * harness from our own seeds. Those are assimp's bugs, not ours: the CLI converts in a child
 * process (a crash becomes one error line) under a time limit, and tests/meshconv/run.sh keeps
 * the crashing file as a regression test of that. No hint below selects PLY, so the run reaches
 * the converter instead of stopping at the first such input.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <assimp/cimport.h>

#include "fuzz_common.h"
#include "meshconv_core.h"
#include "meshconv_scene.h"
#include "model/meshfile.h"

/* assimp 5.2.5 leaks on some malformed files (its STL reader, when it throws mid-file: the
 * allocation's stack is operator new called from libassimp). Allocations through operator new
 * are assimp's and meshoptimizer's, never this project's C code (malloc, with our frames on the
 * stack), so only they are exempt from the leak check. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:libstdc++.so\n";
}

static const char *const hints[16] = {
    "obj", "stl", "obj", "off", "gltf", "glb", "3ds", "ac",  /* 2: was PLY (see above) */
    "ase", "nff", "smd", "raw", "x", "dae", "obj", "stl",
};

/* Capacities: (faces, vertices); small ones put most inputs over them. */
static const uint32_t caps[8][2] = {
    {1, 3}, {2, 4}, {8, 8}, {12, 10}, {64, 40}, {500, 300}, {2048, 2048}, {65536, 65535},
};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2u) {
        return 0;
    }
    const char *hint = hints[data[0] & 0xFu];
    struct meshconv_options opt;
    meshconv_default_options(&opt);
    opt.max_faces = caps[(data[0] >> 5) & 7u][0];
    opt.max_verts = caps[(data[0] >> 5) & 7u][1];
    opt.may_simplify = (data[0] >> 4) & 1u;

    const struct aiScene *sc = aiImportFileFromMemory((const char *)data + 1, (unsigned)(size - 1u),
                                                      MESHCONV_IMPORT_FLAGS, hint);
    if (!sc) {
        return 0;
    }
    size_t faces_raw, polygons;
    meshconv_scene_count(sc, &faces_raw, &polygons);
    sc = aiApplyPostProcessing(sc, MESHCONV_POSTPROCESS);
    if (!sc) {
        return 0;
    }
    struct meshconv_soup soup;
    const int rc_scene = meshconv_scene_soup(sc, &soup);
    aiReleaseImport(sc);
    if (rc_scene != 0) {
        REQUIRE(soup.message[0] != '\0', "a scene refusal without a message");
        meshconv_soup_free(&soup);
        return 0;
    }
    const struct meshconv_mesh mesh = meshconv_soup_mesh(&soup);
    struct meshconv_report rep;
    struct meshconv_result res;
    const int rc = meshconv_convert(&mesh, &opt, &rep, &res);

    if (rc != MESHCONV_OK) {
        REQUIRE(rc == MESHCONV_ERR_INPUT || rc == MESHCONV_ERR_CAPACITY, "status %d", rc);
        REQUIRE(rep.message[0] != '\0' && strchr(rep.message, '\n') == NULL,
                "refusal message '%s'", rep.message);
        REQUIRE(res.bytes == NULL, "a refusal returned bytes");
        meshconv_soup_free(&soup);
        return 0;
    }
    REQUIRE(opt.may_simplify || (rep.faces_merged <= opt.max_faces && rep.verts_unique <= opt.max_verts),
            "over capacity (%zu faces, %zu vertices) accepted without leave to simplify",
            rep.faces_merged, rep.verts_unique);
    REQUIRE(res.len == meshfile_bytes((uint32_t)rep.verts_out, (uint32_t)rep.faces_out),
            "%zu bytes for %zu vertices and %zu faces", res.len, rep.verts_out, rep.faces_out);

    struct meshfile_info info;
    const int err = meshfile_check(res.bytes, res.len, opt.max_verts, opt.max_faces, &info);
    if (err != MESHFILE_OK) {
        char why[200];
        meshfile_message(err, &info, why, sizeof why);
        REQUIRE(err == MESHFILE_OK, "meshfile_check refuses the converter's file: %s", why);
    }
    REQUIRE(info.verts == rep.verts_out && info.faces == rep.faces_out,
            "counts %u/%u against the report's %zu/%zu", info.verts, info.faces, rep.verts_out,
            rep.faces_out);

    struct meshconv_report rep2;
    struct meshconv_result res2;
    REQUIRE(meshconv_convert(&mesh, &opt, &rep2, &res2) == MESHCONV_OK, "second conversion failed");
    REQUIRE(res2.len == res.len && memcmp(res2.bytes, res.bytes, res.len) == 0,
            "two conversions of one mesh differ");
    meshconv_free(&res2);
    meshconv_free(&res);
    meshconv_soup_free(&soup);
    return 0;
}
