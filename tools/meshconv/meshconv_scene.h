/*
 * meshconv_scene.h — an assimp scene -> one triangle soup for meshconv_core: every mesh of every
 * node with the node's transform applied (in double), points and lines left out, each face's
 * colour from its vertices' colours or its material's. Shared by the CLI and the fuzz harness, so
 * that the fuzzer runs the path the CLI runs.
 */
#ifndef MESHCONV_SCENE_H
#define MESHCONV_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "meshconv_core.h"

/* The import's first step: assimp's own consistency checks (indices in range, counts), before
 * the polygons are counted; then MESHCONV_POSTPROCESS through aiApplyPostProcessing. */
#define MESHCONV_IMPORT_FLAGS aiProcess_ValidateDataStructure
#define MESHCONV_POSTPROCESS (aiProcess_Triangulate | aiProcess_SortByPType)

/* Beyond this a scene is refused before copying: it could not be simplified in reasonable memory
 * and time (a 100k-face model takes well under a second). */
#define MESHCONV_MAX_SOURCE_FACES 20000000u
/* Deeper node trees than this are refused: the walk is recursive. */
#define MESHCONV_MAX_NODE_DEPTH 256

struct meshconv_soup {
    double *pos;
    size_t verts, vert_cap;
    uint32_t *idx;
    size_t faces, face_cap;
    float *vert_rgb;      /* allocated only once some mesh has vertex colours */
    float *face_rgb;
    size_t ignored;       /* points and lines */
    size_t meshes;
    char message[160];    /* why, when meshconv_scene_soup fails */
};

/* Faces, and polygons of more than three corners, of a scene before triangulation. */
void meshconv_scene_count(const struct aiScene *sc, size_t *faces, size_t *polygons);
/* The triangulated scene's triangles into *s (zeroed first): 0, or 1 with s->message. */
int meshconv_scene_soup(const struct aiScene *sc, struct meshconv_soup *s);
/* The soup as the core's input. */
struct meshconv_mesh meshconv_soup_mesh(const struct meshconv_soup *s);
void meshconv_soup_free(struct meshconv_soup *s);

#endif /* MESHCONV_SCENE_H */
