/*
 * test_batch.c — cutting a frame into GPU batches: capacities respected, every primitive sent
 * once and in draw order, each batch's vertex words and renumbered indices decoding back to the
 * frame's vertices, shared vertices written once per batch.
 */
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "gpu/batch.h"
#include "render/palette.h"
#include "render/render.h"
#include "test_frame.h"
#include "test_util.h"
#include "unit.h"

static uint32_t vtx_words[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t prim_words[GPU_TRI_CAP * GPU_PRIM_WORDS];
static struct batch_words words = BATCH_WORDS_ON(vtx_words, prim_words);

/* A grid of n x n quads facing the eye at z = 5 (two triangles each, shared vertices). */
static void build_grid(struct mesh *m, vec3 *v, struct mesh_face *f, uvec3 *nrm, int n)
{
    mesh_init(m, v, (uint32_t)((n + 1) * (n + 1)), f, (uint32_t)(2 * n * n), nrm, 1);
    mesh_add_normal(m, u3(0, 0, -1));
    for (int j = 0; j <= n; j++) {
        for (int i = 0; i <= n; i++) {
            mesh_add_vertex(m, v3(-2.0 + 4.0 * i / n, -1.5 + 3.0 * j / n, 5.0 + 0.01 * i));
        }
    }
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) {
            const uint16_t a = (uint16_t)(j * (n + 1) + i);
            const uint16_t b = (uint16_t)((j + 1) * (n + 1) + i);
            const uint16_t c = (uint16_t)((j + 1) * (n + 1) + i + 1);
            const uint16_t d = (uint16_t)(j * (n + 1) + i + 1);

            /* u = +y, v = +x: u x v = -z, towards the eye */
            mesh_add_quad(m, a, b, c, d, 0, (uint8_t)(1 + (i + j) % 8));
        }
    }
    mesh_finish(m);
}

/* The largest grid a test draws: 190 x 190 quads, 72,200 triangles on 36,481 vertices (a frame
 * past the 65,536 primitives a narrow index reaches, test_batch_wide_frame). */
#define GRID_MAX_N 190

static void render_grid_into(struct render_frame *frame, int n, bool wireframe)
{
    static struct mesh m;
    static vec3 v[(GRID_MAX_N + 1) * (GRID_MAX_N + 1)];
    static struct mesh_face f[2 * GRID_MAX_N * GRID_MAX_N];
    static uvec3 nrm[1];
    struct render_pass pass;
    struct proj_setup ps;
    struct cam_view view;
    struct render_object o = {0};
    const mat3 id = mat3_identity();

    build_grid(&m, v, f, nrm, n);
    proj_setup_init(&ps, 200, to_real(160.0), GPU_FB_WIDTH, GPU_FB_HEIGHT);
    view.rot = mat3_identity();
    view.eye = v3(0, 0, 0);
    render_pass_init(&pass, &ps, &view, &id, v3(0, 0, 0), u3(0, 0, -1), 4);
    pass.wireframe = wireframe;
    o.mesh = &m;
    o.faces = render_general_faces_loop;
    o.rot = mat3_identity();
    o.pos = v3(0, 0, 0);
    o.material = 0;
    o.levels = 0;
    render_frame_begin(frame);
    render_stats_clear(&frame->stats);
    render_object(frame, &pass, &o);
    render_sort(frame);
    render_overlay_crosshair(frame, &pass, 4, PAL_WHITE);
}

static void render_grid_pass(int n, bool wireframe)
{
    render_grid_into(&test_frame, n, wireframe);
}

static void render_grid(int n)
{
    render_grid_pass(n, false);
}

/* Run all of a frame's batches with the given capacities and check everything about them. */
static void check_frame_batches(struct render_frame *frame, uint32_t vtx_cap, uint32_t tri_cap,
                                uint32_t *batches_out)
{
    struct batch_cursor cur;
    uint32_t next = 0;  /* draw position expected next */
    uint32_t batches = 0;

    batch_begin(&cur);
    do {
        batch_fill(&cur, frame, vtx_cap, tri_cap, &words);
        batches++;
        CHECK(words.prim_count >= 1u);
        CHECK(words.prim_count <= tri_cap);
        CHECK(words.vtx_count <= vtx_cap);
        for (uint32_t i = 0; i < words.prim_count; i++) {
            const uint32_t *pw = &words.prim[i * GPU_PRIM_WORDS];
            const struct render_prim *p = &frame->prim[render_draw_index(frame, next)];
            const uint32_t idx[3] = {(pw[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK,
                                     (pw[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK,
                                     (pw[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK};

            CHECK_EQ((pw[GPU_PRIM_COLOR_WORD] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK, p->color);
            CHECK_EQ((pw[GPU_PRIM_KIND_WORD] >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK, p->kind);
            for (int k = 0; k < 3; k++) {
                const uint32_t *vw = &words.vtx[idx[k] * GPU_VTX_WORDS];
                const struct proj_vertex *want = &frame->vert[p->v[k]];

                CHECK(idx[k] < words.vtx_count);
                CHECK_EQ((int16_t)((vw[GPU_VTX_X_WORD] >> GPU_VTX_X_LSB) & GPU_VTX_X_MASK), want->sx);
                CHECK_EQ((int16_t)((vw[GPU_VTX_Y_WORD] >> GPU_VTX_Y_LSB) & GPU_VTX_Y_MASK), want->sy);
                CHECK_EQ((vw[GPU_VTX_Z_WORD] >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK, want->zbuf);
            }
            next++;
        }
        /* Each vertex is written once per batch: no two slots hold the same frame vertex... */
        for (uint32_t a = 0; a < words.vtx_count && a < 64u; a++) {
            for (uint32_t b = a + 1u; b < words.vtx_count; b++) {
                CHECK(words.vtx[a * GPU_VTX_WORDS] != words.vtx[b * GPU_VTX_WORDS] ||
                      words.vtx[a * GPU_VTX_WORDS + 1u] != words.vtx[b * GPU_VTX_WORDS + 1u]);
            }
        }
    } while (!batch_done(&cur, frame));
    CHECK_EQ(next, frame->prim_count);  /* every primitive, once, in draw order */
    *batches_out = batches;
}

static void check_batches(uint32_t vtx_cap, uint32_t tri_cap, uint32_t *batches_out)
{
    check_frame_batches(&test_frame, vtx_cap, tri_cap, batches_out);
}

void test_batch_split_and_renumber(void)
{
    uint32_t b;

    render_grid(40);  /* 3200 triangles, 1681 vertices, plus the crosshair */
    CHECK_EQ(test_frame.prim_count, 3202);
    check_batches(GPU_VTX_CAP, GPU_TRI_CAP, &b);
    CHECK(b >= 7u);  /* 3202 / 512 */
    check_batches(30, 7, &b);
    CHECK(b >= 3202u / 7u);
    check_batches(3, 1, &b);  /* the smallest batch: one triangle */
    CHECK_EQ(b, 3202);
    check_batches(100000, 100000, &b);  /* more than the header's buffers: clamped to them */
    CHECK(b >= 7u);
}

/* Shared vertices stay shared inside a batch: a 10 x 10 grid (121 vertices, 200 triangles) fits
 * one batch with each vertex written once. */
void test_batch_shares_vertices(void)
{
    struct batch_cursor cur;

    render_grid(10);
    batch_begin(&cur);
    batch_fill(&cur, &test_frame, GPU_VTX_CAP, GPU_TRI_CAP, &words);
    CHECK(batch_done(&cur, &test_frame));
    CHECK_EQ(words.prim_count, 202);
    CHECK_EQ(words.vtx_count, 121u + 4u);
    /* An empty frame still makes one (empty) batch: the frame's clear and swap must happen. */
    render_frame_begin(&test_frame);
    batch_begin(&cur);
    batch_fill(&cur, &test_frame, GPU_VTX_CAP, GPU_TRI_CAP, &words);
    CHECK_EQ(words.prim_count, 0);
    CHECK(batch_done(&cur, &test_frame));
}

/* A wireframe frame with GPU lines: each outline primitive becomes its edges' LINE primitives,
 * never split across batches, however small the batches are; every line's vertices decode back to
 * the outline's. The 10 x 10 grid of quads draws its polygons' edges only, each once: 2 x 10 x 11
 * lines (the diagonals hidden, an edge two quads share drawn by the first), where drawing every
 * triangle's edges would take 600. */
void test_batch_outlines(void)
{
    static const uint32_t caps[][2] = {{GPU_VTX_CAP, GPU_TRI_CAP}, {30, 7}, {3, 1}, {3, 3}};

    render_grid_pass(10, true);  /* 200 outlines (each keeps an edge), the crosshair's 2 lines */
    CHECK_EQ(test_frame.prim_count, 202);
    CHECK_EQ(test_frame.outline_count, 200);
    for (uint32_t c = 0; c < sizeof caps / sizeof caps[0]; c++) {
        struct batch_cursor cur;
        uint32_t lines = 0;
        uint32_t next = 0;

        batch_begin(&cur);
        do {
            uint32_t i = 0;

            batch_fill(&cur, &test_frame, caps[c][0], caps[c][1], &words);
            CHECK(words.prim_count >= 1u);
            CHECK(words.prim_count <= ((caps[c][1] < 3u) ? 3u : caps[c][1]));
            CHECK(words.vtx_count <= ((caps[c][0] < 3u) ? 3u : caps[c][0]));
            /* Walk the frame's primitives this batch took, matching its lines in order. */
            while (next < cur.next) {
                const struct render_prim *p = &test_frame.prim[render_draw_index(&test_frame, next)];
                const uint32_t edges = ((p->kind & RENDER_PRIM_OUTLINE) != 0u)
                                           ? (p->kind & RENDER_PRIM_OUTLINE_EDGES) : 0u;

                for (uint32_t k = 0; k < 3u; k++) {
                    const uint32_t *pw = &words.prim[i * GPU_PRIM_WORDS];
                    const uint32_t a = pw[0] & 0xFFFFu;
                    const uint32_t b = pw[0] >> 16;

                    if (edges != 0u && (edges & (1u << k)) == 0u) {
                        continue;
                    }
                    CHECK(i < words.prim_count);
                    CHECK_EQ(pw[1] >> GPU_PRIM_KIND_LSB, GPU_PRIM_KIND_LINE);
                    CHECK_EQ((pw[1] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK, p->color);
                    if (edges != 0u) {
                        CHECK_EQ(words.vtx[a * GPU_VTX_WORDS], test_frame.vert[p->v[k]].sxy);
                        CHECK_EQ(words.vtx[b * GPU_VTX_WORDS], test_frame.vert[p->v[(k + 1u) % 3u]].sxy);
                    }
                    i++;
                    lines++;
                    if (edges == 0u) {
                        break;  /* a plain LINE primitive (the crosshair) */
                    }
                }
                next++;
            }
            CHECK_EQ(i, words.prim_count);
        } while (!batch_done(&cur, &test_frame));
        CHECK_EQ(lines, 2u * 10u * 11u + 2u);
    }
}

/* A frame past 16-bit indices: 72,200 triangles of one grid (and the crosshair's 2 lines) into a
 * frame of 80,000 primitives. With wide indices (config/build_options.h, the SDRAM builds' model
 * capacities: make fw-unit's fw_unit_wide) every primitive is kept, sorted far to near (each
 * primitive once) and sent, primitive numbers past 65,535 included; with narrow ones the frame's
 * capacity is cut to RENDER_INDEX_LIMIT and the rest is counted as dropped, never wrapped. */
void test_batch_wide_frame(void)
{
    enum { VERTS = 40000, PRIMS = 80000, TRIS = 2 * GRID_MAX_N * GRID_MAX_N };
    static struct proj_vertex vert[VERTS];
    static struct render_prim prim[PRIMS];
    static sort_item_t item[PRIMS], tmp[PRIMS];
    static struct sort_scratch scratch;
    static uint8_t seen[PRIMS];
    static struct render_frame frame;
    uint32_t batches;

    render_frame_init(&frame, vert, VERTS, prim, item, tmp, PRIMS, &scratch);
    render_grid_into(&frame, GRID_MAX_N, false);
    if (RENDER_INDEX_LIMIT < (uint32_t)PRIMS) {
        CHECK_EQ(frame.prim_cap, RENDER_INDEX_LIMIT);
        CHECK_EQ(frame.prim_count, RENDER_INDEX_LIMIT);
        CHECK(frame.stats.dropped > 0u);
        return;
    }
    CHECK_EQ(frame.prim_count, (uint32_t)TRIS + 2u);
    CHECK_EQ(frame.stats.dropped, 0);
    CHECK_EQ(frame.sorted_count, (uint32_t)TRIS);
    memset(seen, 0, sizeof seen);
    for (uint32_t i = 0; i < frame.sorted_count; i++) {
        const uint32_t p = render_draw_index(&frame, i);

        CHECK(p < (uint32_t)TRIS);
        CHECK_EQ(seen[p], 0);
        seen[p] = 1;
        if (i > 0u) {  /* far to near: draw keys ascending */
            CHECK(sort_item_key(frame.sort_item[i]) >= sort_item_key(frame.sort_item[i - 1u]));
        }
    }
    CHECK_EQ(render_draw_index(&frame, frame.prim_count - 1u), frame.prim_count - 1u);  /* the overlay */
    check_frame_batches(&frame, GPU_VTX_CAP, GPU_TRI_CAP, &batches);
    CHECK(batches >= ((uint32_t)TRIS + 2u) / GPU_TRI_CAP);
}
