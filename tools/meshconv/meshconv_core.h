/*
 * meshconv_core.h — the converter's pure core: an indexed triangle mesh in (double positions,
 * optional colours) -> the bytes of a .gmsh file (docs/mesh-format.md). No files, no assimp: the
 * CLI (meshconv.c) and the fuzz harness feed it, the host tests check what it returns.
 *
 * The steps, in order:
 *   1. faces with an index past the vertex array are dropped (counted: bad_index);
 *   2. any non-finite coordinate of a used vertex refuses the mesh (counted: nonfinite);
 *   3. the used vertices' bounding box is centred and its largest half-extent scaled to `extent`,
 *      in double ((p - centre) / half_extent first, so 1e30 and 1e-30 models give the bytes of the
 *      unit one), and quantised to Q3.12;
 *   4. equal quantised vertices are merged (counted), faces with a repeated index or zero area on
 *      the quantised grid dropped (counted: degenerate), unused vertices left out;
 *   5. over capacity: refused, or simplified with meshoptimizer when allowed (never truncated);
 *   6. each face gets its normal (from the quantised vertices, in double, rounded to Q1.14) and
 *      the palette material nearest to its colour.
 */
#ifndef MESHCONV_CORE_H
#define MESHCONV_CORE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Results: the CLI's exit statuses. */
enum meshconv_status {
    MESHCONV_OK = 0,
    MESHCONV_ERR_INPUT = 1,     /* the model cannot be converted (non-finite, nothing left, ...) */
    MESHCONV_ERR_USAGE = 2,     /* options out of range */
    MESHCONV_ERR_CAPACITY = 3,  /* over --max-faces / --max-verts, or simplification fell short */
};

struct meshconv_mesh {
    const double *pos;        /* 3 per vertex: x, y, z */
    size_t vert_count;
    const uint32_t *idx;      /* 3 per face, counter-clockwise seen from outside */
    size_t face_count;
    const float *vert_rgb;    /* optional: 3 per vertex, 0..1; a face takes its vertices' mean */
    const float *face_rgb;    /* optional: 3 per face, 0..1, r < 0 = none (the default material) */
};

struct meshconv_options {
    uint32_t max_verts;       /* 3 .. 65536 (uint16 indices 0 .. 65535) */
    uint32_t max_faces;       /* 1 .. MESHCONV_FACES_LIMIT */
    bool may_simplify;        /* the user gave --max-faces: simplify instead of refusing */
    double extent;            /* largest half-extent in world units, (0, MESHCONV_EXTENT_MAX] */
    uint8_t default_material; /* MESHFILE_MAT_MIN .. MESHFILE_MAT_MAX */
};

/* Faces a file may hold: meshfile_bytes stays exact below 2^24. */
#define MESHCONV_FACES_LIMIT (1u << 20)
/* Q3.12: the scaled extent times 4096 must stay an int16. */
#define MESHCONV_EXTENT_MAX 7.99

struct meshconv_report {
    size_t faces_in, verts_in;
    size_t bad_index;         /* faces dropped: an index past the vertex array */
    size_t nonfinite;         /* used vertices with a NaN or infinite coordinate */
    size_t verts_used;        /* vertices some face uses */
    size_t verts_merged;      /* used vertices equal to another after quantisation */
    size_t degenerate;        /* faces dropped: repeated index or zero area once quantised */
    size_t faces_merged;      /* faces after steps 1-4 */
    size_t verts_unique;      /* their vertices */
    bool simplified;
    const char *simplifier;   /* "meshopt_simplify" or "meshopt_simplifySloppy" when simplified */
    double simplify_error;    /* the relative error target that met the capacity */
    size_t faces_out, verts_out;
    double centre[3], half_extent, scale;  /* world = (p - centre) * scale */
    size_t colour_faces;      /* faces that had a colour (the rest: the default material) */
    uint32_t material_faces[16];  /* faces per material, by palette material number */
    char message[256];        /* why, when not MESHCONV_OK */
};

struct meshconv_result {
    uint8_t *bytes;           /* malloc'ed .gmsh image, NULL on failure; free with meshconv_free */
    size_t len;
};

void meshconv_default_options(struct meshconv_options *opt);
int meshconv_convert(const struct meshconv_mesh *mesh, const struct meshconv_options *opt,
                     struct meshconv_report *rep, struct meshconv_result *out);
void meshconv_free(struct meshconv_result *out);

/* The lit materials by name (palette.h's MAT_* in lower case): 0 when unknown. */
uint8_t meshconv_material_from_name(const char *name);
const char *meshconv_material_name(uint8_t material);
/* The palette material (1..13) nearest to an RGB colour, 0..1 per channel. */
uint8_t meshconv_nearest_material(float r, float g, float b);

#endif /* MESHCONV_CORE_H */
