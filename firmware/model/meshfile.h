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
#define MESHFILE_DEFAULT_MAX_FACES 4096u  /* the firmware's model capacity: meshconv's defaults */
#define MESHFILE_DEFAULT_MAX_VERTS 4096u

/* Header field offsets. */
#define MESHFILE_OFF_VERSION 4u
#define MESHFILE_OFF_FRAC_BITS 6u
#define MESHFILE_OFF_VERT_COUNT 8u
#define MESHFILE_OFF_FACE_COUNT 12u
#define MESHFILE_OFF_BOX_LO 16u
#define MESHFILE_OFF_BOX_HI 22u
#define MESHFILE_OFF_FLAGS 28u

/* The size of a file of v vertices and f faces (no overflow for counts below 2^24). */
static inline uint32_t meshfile_bytes(uint32_t verts, uint32_t faces)
{
    return MESHFILE_HEADER_BYTES + MESHFILE_VERT_BYTES * verts + MESHFILE_FACE_BYTES * faces +
           MESHFILE_CRC_BYTES;
}

#endif /* MESHFILE_H */
