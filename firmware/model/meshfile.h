/*
 * meshfile.h — the mesh file (.gmsh, docs/mesh-format.md): its constants, its validator and its
 * loader. Pure code, shared by the firmware (built-in models, UART uploads) and the host
 * converter (tools/meshconv checks what it writes with the same validator).
 *
 * Every multi-byte field is little-endian and read byte by byte: no alignment, no host order.
 */
#ifndef MESHFILE_H
#define MESHFILE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define MESHFILE_MAGIC0 'G'
#define MESHFILE_MAGIC1 'M'
#define MESHFILE_MAGIC2 'S'
#define MESHFILE_MAGIC3 'H'
#define MESHFILE_VERSION 1u
#define MESHFILE_FRAC_BITS 12u          /* coordinates: int16 in units of 2^-12 (Q3.12) */
#define MESHFILE_NORMAL_ONE 16384       /* normals: Q1.14 */
#define MESHFILE_HEADER_BYTES 32u
#define MESHFILE_VERT_BYTES 6u
#define MESHFILE_FACE_BYTES 14u
#define MESHFILE_CRC_BYTES 4u
#define MESHFILE_MAT_MIN 1u             /* palette.h: MAT_RED */
#define MESHFILE_MAT_MAX 13u            /* palette.h: MAT_WATER */
#define MESHFILE_FACE_FLAG_QUAD 0x01u   /* mesh.h: MESH_FACE_QUAD */
#define MESHFILE_FACE_FLAGS_KNOWN 0x01u
/* |n|^2 of a stored normal within 2^-8 of 16384^2 (rounding moves it by about 2^-13). */
#define MESHFILE_NORMAL_TOLERANCE_SHIFT 8u

/* The firmware's default model capacity (scenes/model/model.h: FW_MODEL_MAX_*), which the SoC's
 * 192 KiB hold with the rest of the model scene's program (make fw-size), and tools/meshconv's
 * default budget. QEMU has room for far more: make FW_MODEL_MAX_FACES=4096 FW_MODEL_MAX_VERTS=4096. */
#define MESHFILE_DEFAULT_MAX_VERTS 1024u
#define MESHFILE_DEFAULT_MAX_FACES 1024u

/* Header field offsets. */
#define MESHFILE_OFF_VERSION 4u
#define MESHFILE_OFF_FRAC_BITS 6u
#define MESHFILE_OFF_VERT_COUNT 8u
#define MESHFILE_OFF_FACE_COUNT 12u
#define MESHFILE_OFF_BOX_LO 16u
#define MESHFILE_OFF_BOX_HI 22u
#define MESHFILE_OFF_FLAGS 28u

/* The size of a file of v vertices and f faces (no overflow for counts below 2^24): a constant
 * expression for buffers sized by a capacity, and a function. */
#define MESHFILE_BYTES(verts, faces) \
    (MESHFILE_HEADER_BYTES + MESHFILE_VERT_BYTES * (verts) + MESHFILE_FACE_BYTES * (faces) + \
     MESHFILE_CRC_BYTES)
static inline uint32_t meshfile_bytes(uint32_t verts, uint32_t faces)
{
    return MESHFILE_BYTES(verts, faces);
}


/* ---- validation -------------------------------------------------------------------------- */

/* Why a file was refused: each names one rule of docs/mesh-format.md. */
enum meshfile_error {
    MESHFILE_OK = 0,
    MESHFILE_E_SHORT,         /* shorter than a header and its CRC */
    MESHFILE_E_MAGIC,
    MESHFILE_E_VERSION,       /* value: the file's version */
    MESHFILE_E_FRAC_BITS,     /* value: the file's frac_bits */
    MESHFILE_E_FLAGS,         /* value: the header's flags */
    MESHFILE_E_VERT_COUNT,    /* value: count, limit: the build's capacity (or 3, the least) */
    MESHFILE_E_FACE_COUNT,    /* value: count, limit: the build's capacity */
    MESHFILE_E_SIZE,          /* value: the file's length, limit: what its counts make it */
    MESHFILE_E_CRC,           /* value: the stored CRC, limit: the computed one */
    MESHFILE_E_BOX,           /* item: the axis whose box is not the vertices' smallest and
                               * largest coordinate */
    MESHFILE_E_VERTEX_OUTSIDE,/* item: the vertex, value: its axis (outside the box, or -8.0) */
    MESHFILE_E_INDEX,         /* item: the face, value: the index, limit: vert_count */
    MESHFILE_E_REPEATED_INDEX,/* item: the face (two of its corners are one vertex) */
    MESHFILE_E_NORMAL,        /* item: the face (a component over 1.0 or |n| not 1) */
    MESHFILE_E_MATERIAL,      /* item: the face, value: the material */
    MESHFILE_E_FACE_FLAGS,    /* item: the face, value: its flags */
    MESHFILE_E_MISSING,       /* no file at all (a program without a built-in model) */
    MESHFILE_E_COUNT
};

struct meshfile_info {
    uint32_t verts;        /* the header's counts (valid from MESHFILE_E_VERT_COUNT on) */
    uint32_t faces;
    int16_t box_lo[3];
    int16_t box_hi[3];
    uint32_t item;         /* what the error names (above) */
    uint32_t value;
    uint32_t limit;
};

/* Check buf[0..len) against every rule, the counts against the build's capacities; fills *info
 * (counts and box on success). Returns MESHFILE_OK or the first rule broken. Reads nothing
 * outside buf; O(len). */
int meshfile_check(const uint8_t *buf, size_t len, uint32_t max_verts, uint32_t max_faces,
                   struct meshfile_info *info);

/* The same, for a caller that has just computed the CRC of buf[0 .. len-4) (body_crc): the
 * upload's COMMIT, which checks the transfer's CRC in the same pass. Meaningless for len < 36. */
int meshfile_check_known_crc(const uint8_t *buf, size_t len, uint32_t max_verts,
                             uint32_t max_faces, uint32_t body_crc, struct meshfile_info *info);

/* A one-line reason for err ("face 12: index 4000 out of range (1200 vertices)"), NUL-terminated
 * within cap bytes. */
void meshfile_message(int err, const struct meshfile_info *info, char *out, size_t cap);

/* ---- loading ------------------------------------------------------------------------------ */

struct mesh;

/* Fill m (mesh_init'ed by the caller with room for info->verts vertices, info->faces faces and as
 * many normals) from a file meshfile_check accepted, then mesh_finish it. Returns false (m then
 * holds nothing usable) when m's arrays are too small. */
bool meshfile_load(const uint8_t *buf, const struct meshfile_info *info, struct mesh *m);

#endif /* MESHFILE_H */
