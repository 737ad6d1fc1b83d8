/*
 * meshconv_scene.c — see meshconv_scene.h.
 */
#include "meshconv_scene.h"

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <assimp/material.h>


static int soup_error(struct meshconv_soup *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int soup_error(struct meshconv_soup *s, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(s->message, sizeof s->message, fmt, ap);
    va_end(ap);
    return 1;
}

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
static int add_mesh(struct meshconv_soup *s, const struct aiScene *sc, const struct aiMesh *m, const double t[16])
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
        return soup_error(s, "more than %u faces in the scene", MESHCONV_MAX_SOURCE_FACES);
    }
    /* Indices are uint32 and UINT32_MAX marks a bad one: the vertices stay well below. */
    if (s->verts + m->mNumVertices > 3u * MESHCONV_MAX_SOURCE_FACES) {
        return soup_error(s, "more than %u vertices in the scene", 3u * MESHCONV_MAX_SOURCE_FACES);
    }
    const size_t base = s->verts;
    const size_t old_vcap = s->vert_cap;
    if (!grow((void **)&s->pos, &s->vert_cap, base + m->mNumVertices, 3u * sizeof(double)) ||
        !grow((void **)&s->idx, &s->face_cap, s->faces + tris, 3u * sizeof(uint32_t))) {
        return soup_error(s, "out of memory (%zu faces)", s->faces + tris);
    }
    /* Colour arrays follow the position and index arrays' capacities. */
    if (s->vert_rgb && s->vert_cap != old_vcap) {
        float *q = realloc(s->vert_rgb, s->vert_cap * 3u * sizeof(float));
        if (!q) {
            return soup_error(s, "out of memory");
        }
        s->vert_rgb = q;
    }
    float *frgb = realloc(s->face_rgb, s->face_cap * 3u * sizeof(float));
    if (!frgb) {
        return soup_error(s, "out of memory");
    }
    s->face_rgb = frgb;
    if (m->mColors[0] && !s->vert_rgb) {
        /* The first mesh with vertex colours: the core then colours every face from its
         * vertices, so the vertices so far carry their faces' material colour. */
        s->vert_rgb = malloc(s->vert_cap * 3u * sizeof(float));
        if (!s->vert_rgb) {
            return soup_error(s, "out of memory");
        }
        for (size_t f = 0; f < s->faces; f++) {
            for (int k = 0; k < 3; k++) {
                if (s->idx[3 * f + k] < s->verts) {  /* a bad index stays for the core to drop */
                    memcpy(&s->vert_rgb[3u * s->idx[3 * f + k]], &s->face_rgb[3 * f],
                           3u * sizeof(float));
                }
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

static int walk(struct meshconv_soup *s, const struct aiScene *sc, const struct aiNode *n, const double parent[16],
                int depth)
{
    double t[16];

    if (depth > MESHCONV_MAX_NODE_DEPTH) {
        return soup_error(s, "the node tree is deeper than %d", MESHCONV_MAX_NODE_DEPTH);
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

void meshconv_soup_free(struct meshconv_soup *s)
{
    free(s->pos);
    free(s->idx);
    free(s->vert_rgb);
    free(s->face_rgb);
    memset(s, 0, sizeof *s);
}

void meshconv_scene_count(const struct aiScene *sc, size_t *faces, size_t *polygons)
{
    *faces = 0;
    *polygons = 0;
    for (unsigned i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *m = sc->mMeshes[i];
        for (unsigned j = 0; m && j < m->mNumFaces; j++) {
            (*faces)++;
            *polygons += m->mFaces[j].mNumIndices > 3u;
        }
    }
}

int meshconv_scene_soup(const struct aiScene *sc, struct meshconv_soup *s)
{
    static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    int rc = 0;

    memset(s, 0, sizeof *s);
    if (sc->mRootNode) {
        return walk(s, sc, sc->mRootNode, identity, 0);
    }
    /* No node tree (some importers): every mesh once, untransformed. */
    for (unsigned i = 0; i < sc->mNumMeshes && rc == 0; i++) {
        if (sc->mMeshes[i]) {
            rc = add_mesh(s, sc, sc->mMeshes[i], identity);
        }
    }
    return rc;
}

struct meshconv_mesh meshconv_soup_mesh(const struct meshconv_soup *s)
{
    const struct meshconv_mesh mesh = {
        .pos = s->pos, .vert_count = s->verts, .idx = s->idx, .face_count = s->faces,
        .vert_rgb = s->vert_rgb, .face_rgb = s->face_rgb,
    };
    return mesh;
}
