/*
 * meshfile.c — see meshfile.h and docs/mesh-format.md.
 */
#include "model/meshfile.h"

#include <stdio.h>

#include "math/real.h"
#include "model/crc32.h"
#include "model/le.h"
#include "render/mesh.h"


static int meshfile_fail(struct meshfile_info *info, int err, uint32_t item, uint32_t value,
                         uint32_t limit)
{
    info->item = item;
    info->value = value;
    info->limit = limit;
    return err;
}

/* One face record's rules: indices, normal, material, flags. */
static int meshfile_check_face(const uint8_t *f, uint32_t fi, uint32_t verts,
                               struct meshfile_info *info)
{
    uint32_t v[3];
    int64_t n2 = 0;
    /* 16384^2 = 2^28; the tolerance is 2^28 >> 8 = 2^20. */
    const int64_t one2 = (int64_t)MESHFILE_NORMAL_ONE * MESHFILE_NORMAL_ONE;
    const int64_t tol = one2 >> MESHFILE_NORMAL_TOLERANCE_SHIFT;

    for (uint32_t k = 0; k < 3u; k++) {
        v[k] = le16_at(f + 2u * k);
        if (v[k] >= verts) {
            return meshfile_fail(info, MESHFILE_E_INDEX, fi, v[k], verts);
        }
    }
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
        return meshfile_fail(info, MESHFILE_E_REPEATED_INDEX, fi, 0, 0);
    }
    for (uint32_t k = 0; k < 3u; k++) {
        const int32_t c = le16s_at(f + 6u + 2u * k);

        if (c > MESHFILE_NORMAL_ONE || c < -MESHFILE_NORMAL_ONE) {
            return meshfile_fail(info, MESHFILE_E_NORMAL, fi, (uint32_t)c, 0);
        }
        n2 += (int64_t)c * c;  /* at most 3 * 2^28: int64 */
    }
    if (n2 < one2 - tol || n2 > one2 + tol) {
        return meshfile_fail(info, MESHFILE_E_NORMAL, fi, (uint32_t)(n2 >> 14), 0);
    }
    if (f[12] < MESHFILE_MAT_MIN || f[12] > MESHFILE_MAT_MAX) {
        return meshfile_fail(info, MESHFILE_E_MATERIAL, fi, f[12], MESHFILE_MAT_MAX);
    }
    if ((f[13] & ~MESHFILE_FACE_FLAGS_KNOWN) != 0u) {
        return meshfile_fail(info, MESHFILE_E_FACE_FLAGS, fi, f[13], 0);
    }
    return MESHFILE_OK;
}

/* meshfile_check's rules; known_crc: the CRC of buf[0 .. len-4) if the caller has it, else NULL. */
static int meshfile_check_rules(const uint8_t *buf, size_t len, uint32_t max_verts,
                                uint32_t max_faces, const uint32_t *known_crc,
                                struct meshfile_info *info)
{
    uint32_t verts;
    uint32_t faces;
    uint32_t size;
    uint32_t stored;
    uint32_t crc;
    const uint8_t *p;

    info->verts = 0;
    info->faces = 0;
    if (len < (size_t)MESHFILE_HEADER_BYTES + MESHFILE_CRC_BYTES) {
        return meshfile_fail(info, MESHFILE_E_SHORT, 0, (uint32_t)len,
                             MESHFILE_HEADER_BYTES + MESHFILE_CRC_BYTES);
    }
    if (buf[0] != MESHFILE_MAGIC0 || buf[1] != MESHFILE_MAGIC1 || buf[2] != MESHFILE_MAGIC2 ||
        buf[3] != MESHFILE_MAGIC3) {
        return meshfile_fail(info, MESHFILE_E_MAGIC, 0, 0, 0);
    }
    if (le16_at(buf + MESHFILE_OFF_VERSION) != MESHFILE_VERSION) {
        return meshfile_fail(info, MESHFILE_E_VERSION, 0, le16_at(buf + MESHFILE_OFF_VERSION),
                             MESHFILE_VERSION);
    }
    if (le16_at(buf + MESHFILE_OFF_FRAC_BITS) != MESHFILE_FRAC_BITS) {
        return meshfile_fail(info, MESHFILE_E_FRAC_BITS, 0, le16_at(buf + MESHFILE_OFF_FRAC_BITS),
                             MESHFILE_FRAC_BITS);
    }
    if (le32_at(buf + MESHFILE_OFF_FLAGS) != 0u) {
        return meshfile_fail(info, MESHFILE_E_FLAGS, 0, le32_at(buf + MESHFILE_OFF_FLAGS), 0);
    }
    verts = le32_at(buf + MESHFILE_OFF_VERT_COUNT);
    faces = le32_at(buf + MESHFILE_OFF_FACE_COUNT);
    info->verts = verts;
    info->faces = faces;
    if (verts < 3u || verts > max_verts || verts > 65536u) {
        return meshfile_fail(info, MESHFILE_E_VERT_COUNT, 0, verts, (verts < 3u) ? 3u : max_verts);
    }
    if (faces < 1u || faces > max_faces || faces > (1u << 24)) {
        return meshfile_fail(info, MESHFILE_E_FACE_COUNT, 0, faces, max_faces);
    }
    /* Both counts are now below 2^24 (65536 and 2^24), so the size cannot overflow. */
    size = meshfile_bytes(verts, faces);
    if (len != (size_t)size) {
        return meshfile_fail(info, MESHFILE_E_SIZE, 0, (uint32_t)len, size);
    }
    stored = le32_at(buf + size - MESHFILE_CRC_BYTES);
    crc = (known_crc != 0) ? *known_crc : crc32_update(0, buf, size - MESHFILE_CRC_BYTES);
    if (stored != crc) {
        return meshfile_fail(info, MESHFILE_E_CRC, 0, stored, crc);
    }
    for (uint32_t k = 0; k < 3u; k++) {
        info->box_lo[k] = (int16_t)le16s_at(buf + MESHFILE_OFF_BOX_LO + 2u * k);
        info->box_hi[k] = (int16_t)le16s_at(buf + MESHFILE_OFF_BOX_HI + 2u * k);
        if (info->box_lo[k] > info->box_hi[k]) {
            return meshfile_fail(info, MESHFILE_E_BOX, k, 0, 0);
        }
    }
    p = buf + MESHFILE_HEADER_BYTES;
    {
        int32_t lo[3] = {INT16_MAX, INT16_MAX, INT16_MAX};
        int32_t hi[3] = {INT16_MIN, INT16_MIN, INT16_MIN};

        for (uint32_t vi = 0; vi < verts; vi++, p += MESHFILE_VERT_BYTES) {
            for (uint32_t k = 0; k < 3u; k++) {
                const int32_t c = le16s_at(p + 2u * k);

                /* |c| < 8 units: -32768 (-8.0) is outside, so negating a coordinate stays in
                 * range. */
                if (c < info->box_lo[k] || c > info->box_hi[k] || c == INT16_MIN) {
                    return meshfile_fail(info, MESHFILE_E_VERTEX_OUTSIDE, vi, k, 0);
                }
                lo[k] = (c < lo[k]) ? c : lo[k];
                hi[k] = (c > hi[k]) ? c : hi[k];
            }
        }
        /* The box is the vertices' own, not merely one that holds them. */
        for (uint32_t k = 0; k < 3u; k++) {
            if (lo[k] != info->box_lo[k] || hi[k] != info->box_hi[k]) {
                return meshfile_fail(info, MESHFILE_E_BOX, k, 0, 0);
            }
        }
    }
    for (uint32_t fi = 0; fi < faces; fi++, p += MESHFILE_FACE_BYTES) {
        const int rc = meshfile_check_face(p, fi, verts, info);

        if (rc != MESHFILE_OK) {
            return rc;
        }
    }
    info->item = 0;
    info->value = 0;
    info->limit = 0;
    return MESHFILE_OK;
}

int meshfile_check(const uint8_t *buf, size_t len, uint32_t max_verts, uint32_t max_faces,
                   struct meshfile_info *info)
{
    return meshfile_check_rules(buf, len, max_verts, max_faces, 0, info);
}

int meshfile_check_known_crc(const uint8_t *buf, size_t len, uint32_t max_verts,
                             uint32_t max_faces, uint32_t body_crc, struct meshfile_info *info)
{
    return meshfile_check_rules(buf, len, max_verts, max_faces, &body_crc, info);
}

void meshfile_message(int err, const struct meshfile_info *info, char *out, size_t cap)
{
    static const char axis[3] = {'x', 'y', 'z'};
    const unsigned long item = info->item;
    const unsigned long value = info->value;
    const unsigned long limit = info->limit;

    if (cap == 0u) {
        return;
    }
    switch (err) {
    case MESHFILE_OK:
        snprintf(out, cap, "valid: %lu vertices, %lu faces", (unsigned long)info->verts,
                 (unsigned long)info->faces);
        break;
    case MESHFILE_E_SHORT:
        snprintf(out, cap, "%lu bytes: shorter than a header and its CRC (%lu)", value, limit);
        break;
    case MESHFILE_E_MAGIC:
        snprintf(out, cap, "not a mesh file (magic is not GMSH)");
        break;
    case MESHFILE_E_VERSION:
        snprintf(out, cap, "version %lu (this firmware reads version %lu)", value, limit);
        break;
    case MESHFILE_E_FRAC_BITS:
        snprintf(out, cap, "frac_bits %lu (version 1 has %lu)", value, limit);
        break;
    case MESHFILE_E_FLAGS:
        snprintf(out, cap, "header flags 0x%lx (reserved: 0)", value);
        break;
    case MESHFILE_E_VERT_COUNT:
        snprintf(out, cap, "%lu vertices (this build holds %s%lu)", value,
                 (value < 3u) ? "at least " : "at most ", limit);
        break;
    case MESHFILE_E_FACE_COUNT:
        snprintf(out, cap, "%lu faces (this build holds 1 to %lu)", value, limit);
        break;
    case MESHFILE_E_SIZE:
        snprintf(out, cap, "%lu bytes, but its counts make it %lu", value, limit);
        break;
    case MESHFILE_E_CRC:
        snprintf(out, cap, "CRC 0x%08lx stored, 0x%08lx computed", value, limit);
        break;
    case MESHFILE_E_BOX:
        snprintf(out, cap, "box: not the vertices' smallest and largest %c", axis[item % 3u]);
        break;
    case MESHFILE_E_VERTEX_OUTSIDE:
        snprintf(out, cap, "vertex %lu: %c outside the header's box or at -8.0", item,
                 axis[value % 3u]);
        break;
    case MESHFILE_E_INDEX:
        snprintf(out, cap, "face %lu: index %lu out of range (%lu vertices)", item, value, limit);
        break;
    case MESHFILE_E_REPEATED_INDEX:
        snprintf(out, cap, "face %lu: two corners are the same vertex", item);
        break;
    case MESHFILE_E_NORMAL:
        snprintf(out, cap, "face %lu: normal not a unit vector in Q1.14", item);
        break;
    case MESHFILE_E_MATERIAL:
        snprintf(out, cap, "face %lu: material %lu (1 to %lu)", item, value, limit);
        break;
    case MESHFILE_E_FACE_FLAGS:
        snprintf(out, cap, "face %lu: unknown flags 0x%lx", item, value);
        break;
    case MESHFILE_E_MISSING:
        snprintf(out, cap, "no file (this program was built without a model)");
        break;
    default:
        snprintf(out, cap, "error %d", err);
        break;
    }
}

/* Normals within two units of Q1.14 per component count as the same plane's: a stored normal is
 * rounded to Q1.14, and the two halves of a planar quad round from normals equal up to the
 * converter's vertex rounding. Components are within +-1 and the tolerance tiny, so c + tol
 * stays inside unit_t's range (q2_30: [-2, 2)). */
#define MESHFILE_COPLANAR_TOL UNIT_C(2.0 / 16384.0)

static bool meshfile_close(unit_t a, unit_t b)
{
    return a <= b + MESHFILE_COPLANAR_TOL && b <= a + MESHFILE_COPLANAR_TOL;
}

static bool meshfile_same_plane(const struct mesh *m, const struct mesh_face *a,
                                const struct mesh_face *b)
{
    const uvec3 na = m->normals[a->normal];
    const uvec3 nb = m->normals[b->normal];

    return a->material == b->material && meshfile_close(na.x, nb.x) &&
           meshfile_close(na.y, nb.y) && meshfile_close(na.z, nb.z);
}

/* Faces this far back are searched for a coplanar neighbour: a converter emits a triangulated
 * polygon's triangles one after the other, so its inner edges are found without a table (and an
 * inner edge between faces further apart stays drawn: an extra line, never a missing one). */
#define MESHFILE_POLYGON_WINDOW 8u

/* The edges two coplanar faces of one material share (in opposite directions, as a consistently
 * wound mesh has them) are inside one polygon of the model: MESH_FACE_EDGE_HIDDEN on both. */
static void meshfile_hide_inner_edges(struct mesh *m)
{
    for (uint32_t fi = 1; fi < m->face_count; fi++) {
        struct mesh_face *f = &m->faces[fi];
        const uint32_t first = (fi > MESHFILE_POLYGON_WINDOW) ? fi - MESHFILE_POLYGON_WINDOW : 0u;

        for (uint32_t gi = first; gi < fi; gi++) {
            struct mesh_face *g = &m->faces[gi];

            if (!meshfile_same_plane(m, f, g)) {
                continue;
            }
            for (uint32_t k = 0; k < 3u; k++) {
                for (uint32_t j = 0; j < 3u; j++) {
                    if (f->v[k] == g->v[(j + 1u) % 3u] && f->v[(k + 1u) % 3u] == g->v[j]) {
                        f->flags |= (uint8_t)MESH_FACE_EDGE_HIDDEN(k);
                        g->flags |= (uint8_t)MESH_FACE_EDGE_HIDDEN(j);
                    }
                }
            }
        }
    }
}

bool meshfile_load(const uint8_t *buf, const struct meshfile_info *info, struct mesh *m)
{
    const uint8_t *p = buf + MESHFILE_HEADER_BYTES;

    mesh_clear(m);
    if (m->vert_cap < info->verts || m->face_cap < info->faces || m->normal_cap < info->faces) {
        return false;
    }
    /* Q3.12 -> Q16.16 is a shift by 4 (|c| < 8 units: far inside the +-8192 model range). */
    for (uint32_t vi = 0; vi < info->verts; vi++, p += MESHFILE_VERT_BYTES) {
        mesh_add_vertex(m, vec3_make(real_from_q16(le16s_at(p) * 16),
                                     real_from_q16(le16s_at(p + 2) * 16),
                                     real_from_q16(le16s_at(p + 4) * 16)));
    }
    /* Face fi takes normal fi: Q1.14 -> Q16.16 is a shift by 2 (|n_i| <= 1). */
    for (uint32_t fi = 0; fi < info->faces; fi++, p += MESHFILE_FACE_BYTES) {
        uvec3 n;
        uint16_t ni;

        n.x = unit_from_q16(le16s_at(p + 6) * 4);
        n.y = unit_from_q16(le16s_at(p + 8) * 4);
        n.z = unit_from_q16(le16s_at(p + 10) * 4);
        ni = mesh_add_normal(m, n);
        mesh_add_face_normal(m, (uint16_t)le16_at(p), (uint16_t)le16_at(p + 2), (uint16_t)le16_at(p + 4),
                             ni, p[12]);
        if ((p[13] & MESHFILE_FACE_FLAG_QUAD) != 0u) {
            m->faces[m->face_count - 1u].flags |= MESH_FACE_QUAD;
        }
    }
    meshfile_hide_inner_edges(m);
    mesh_finish(m);
    return !m->full;
}
