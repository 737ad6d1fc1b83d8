/*
 * test_scene.c — the built-in scenes: meshes well formed (indices, normals, winding, ranges the
 * fixed-point arguments assume), each scene renders without overflow or dropped primitives, the
 * voxel scene's place and break, the sizes the issue asks for.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "gpu/batch.h"
#include "render/palette.h"
#include "render/render.h"
#include "scenes/scene.h"
/* The unit tests' program has every scene (no FW_BUILT_SCENES): its table and storage. */
#include "scenes/scene_set.h"
#include "scenes/voxel/voxel_scene.h"
#include "app/pipeline.h"
#include "test_util.h"
#include "unit.h"

static struct scene scene;
static struct render_frame frame;

/* The program's storage, as app.c gives it, before any case runs. */
static void attach_storage(void) __attribute__((constructor));
static void attach_storage(void)
{
    scene_set_attach(&scene, &frame);
}

/* The frame loop's pass (pipeline.h), with GPU lines. */
static void render_scene(const struct scene *s, struct render_frame *f, bool wire)
{
    const struct pipeline_opts opts = {.wireframe = wire, .depth_test = false, .gpu_lines = true};

    pipeline_pass(f, s, &opts, 0, NULL, NULL);
}

static void check_mesh(const struct mesh *m, const struct render_object *o)
{
    CHECK(!m->full);
    CHECK(rd(m->radius) + fabs(rd(o->pos.x)) + fabs(rd(o->pos.y)) + fabs(rd(o->pos.z)) < 1024.0);
    for (uint32_t i = 0; i < m->vert_count; i++) {
        CHECK(fabs(rd(m->verts[i].x)) < 8192.0 && fabs(rd(m->verts[i].y)) < 8192.0 &&
              fabs(rd(m->verts[i].z)) < 8192.0);
        CHECK(rd(vec3_length(vec3_sub(m->verts[i], m->center))) <= rd(m->radius));
    }
    for (uint32_t i = 0; i < m->normal_count; i++) {
        const uvec3 n = mesh_normal(m, i);
        const double len = sqrt(ud(n.x) * ud(n.x) + ud(n.y) * ud(n.y) + ud(n.z) * ud(n.z));

        CHECK(fabs(len - 1.0) < 1e-3);
    }
    for (uint32_t i = 0; i < m->face_count; i++) {
        struct mesh_face tmp;
        const struct mesh_face *f = mesh_face_at(m, i, &tmp);  /* grid meshes: implicit faces */
        uvec3 w;
        uvec3 s;

        CHECK(f->v[0] < m->vert_count && f->v[1] < m->vert_count && f->v[2] < m->vert_count);
        CHECK(f->normal < m->normal_count);
        CHECK((f->material > 0u && f->material < MAT_ANAGLYPH_LEFT) || o->material != 0u);
        /* The winding's normal is the stored one: front faces keep a positive screen area. */
        w = vec3_triangle_normal(m->verts[f->v[0]], m->verts[f->v[1]], m->verts[f->v[2]]);
        s = mesh_normal(m, f->normal);
        CHECK(ud(w.x) * ud(s.x) + ud(w.y) * ud(s.y) + ud(w.z) * ud(s.z) > 0.99);
    }
}

void test_scene_meshes_valid(void)
{
    /* The table's names, in its order: each scene's .name is its SCENE(name) line's. */
    static const char *const table_names[] = {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) #name,
#include "scenes/scene_list.h"
#undef SCENE
    };

    CHECK_EQ(sizeof table_names / sizeof table_names[0], SCENE_COUNT);
    CHECK_EQ(scene_count(), SCENE_COUNT);  /* this program is built with every scene */
    for (uint32_t k = 0; k < SCENE_COUNT; k++) {
        const struct scene_desc *d = scene_at(k);

        CHECK(strcmp(d->name, table_names[k]) == 0);
        CHECK(scene_find(d->name) == d);
        scene_start(&scene, d);
        CHECK(scene.object_count > 0u);
        CHECK(scene_triangle_count(&scene) > 0u);
        for (uint32_t i = 0; i < scene.object_count; i++) {
            check_mesh(scene.object[i].mesh, &scene.object[i]);
        }
        /* Camera inside the +-1024 box of the range arguments. */
        CHECK(fabs(rd(scene.cam.eye.x)) < 1024.0 && fabs(rd(scene.cam.eye.y)) < 1024.0 &&
              fabs(rd(scene.cam.eye.z)) < 1024.0);
        CHECK(rd(scene.cam.cfg.box_max.x) + rd(scene.cam.cfg.dist_max) < 1024.0);
    }
    CHECK(scene_find("nonesuch") == 0);
    CHECK(scene_at(SCENE_COUNT) == 0);
    CHECK_EQ(fx_overflow_count(), 0);
}

/* An object placed outside the +-1024 world box (the range rule render.c's exact object offsets
 * rely on) is clamped into it and counted as an overflow, never drawn with a wrapped offset; the
 * cubes' mesh is recognised as a box (xf_apply_box). */
void test_scene_object_range(void)
{
    const mat3 id = mat3_identity();
    uint32_t n;

    scene_start(&scene, scene_find("cubes"));
    CHECK(scene.object[0].mesh->box);
    scene_start(&scene, scene_find("tetra"));
    CHECK(!scene.object[0].mesh->box);
    fx_overflow_clear();
    n = scene.object_count;
    scene_add_object(&scene, scene.object[0].mesh, &id, v3(1000.0, -1000.0, 5.0), 0);
    CHECK_EQ(fx_overflow_count(), 0);
    scene_add_object(&scene, scene.object[0].mesh, &id, v3(2000.0, 0.0, -1500.0), 0);
    CHECK_EQ(fx_overflow_count(), 2);
    CHECK_EQ(scene.object_count, n + 2u);
    CHECK(rd(scene.object[n + 1u].pos.x) == 1024.0 && rd(scene.object[n + 1u].pos.z) == -1024.0);
    fx_overflow_clear();
}

/* Each scene's state column (scene_list.h) is its state's size on this host, rounded up to 64
 * bytes: no state exceeds its column (SCENE_STATE_FITS also stops the compile), and no column is
 * larger than it needs to be (on the 64-bit host, whose pointers make every state at least as
 * large as on rv32), so the columns follow the scenes instead of growing stale. The program's
 * storage is the largest column of its scenes (scene_set.h). */
void test_scene_state_storage(void)
{
    static const size_t column[] = {
#define SCENE(name, state, objects, verts, prims, wverts, wprims) (state),
#include "scenes/scene_list.h"
#undef SCENE
    };
    size_t largest = 0;

    for (uint32_t k = 0; k < SCENE_COUNT; k++) {
        const size_t bytes = scene_at(k)->state_bytes;

        CHECK(bytes > 0u);
        CHECK(bytes <= column[k]);
        if ((bytes + 63u) / 64u * 64u != column[k]) {
            unit_fail(__FILE__, __LINE__, "scene %s: state column %lu, sizeof %lu: make it %lu",
                      scene_at(k)->name, (unsigned long)column[k], (unsigned long)bytes,
                      (unsigned long)((bytes + 63u) / 64u * 64u));
        }
        largest = column[k] > largest ? column[k] : largest;
    }
    CHECK_EQ(SCENE_SET_STATE_BYTES, largest);
    CHECK_EQ(scene.state_cap, largest);
}

/* A scene whose state or objects do not fit the storage it is given is refused by scene_start,
 * which leaves the running scene as it was; one whose init adds more objects than its column
 * says is refused too (never drawn with objects missing). */
void test_scene_storage_refused(void)
{
    static _Alignas(8) unsigned char small_state[64];
    static struct render_object objects[SCENE_SET_OBJECTS];
    static const struct scene_desc greedy = {
        .name = "greedy", .keys = 0, .state_bytes = 8, .max_objects = 1, .max_verts = 8,
        .max_prims = 8, .init = 0, .update = 0,
    };
    struct scene s;
    const struct scene_desc *tetra = scene_find("tetra");
    const struct scene_desc *knot = scene_find("knot");
    struct scene_desc greedy_run;

    memset(&s, 0, sizeof s);
    CHECK(tetra != 0 && knot != 0);
    CHECK(tetra->state_bytes > sizeof small_state || knot->state_bytes > sizeof small_state);
    scene_attach(&s, objects, SCENE_SET_OBJECTS, small_state, sizeof small_state);
    CHECK(!scene_start(&s, knot));          /* 140 KB of state into 64 bytes */
    CHECK(s.desc == 0 && s.object_count == 0u);
    /* Enough state but too few objects: refused before init runs. */
    scene_attach(&s, objects, 0, scene_set_state, sizeof scene_set_state);
    CHECK(!scene_start(&s, tetra));
    /* Storage that fits: started. */
    scene_attach(&s, objects, SCENE_SET_OBJECTS, scene_set_state, sizeof scene_set_state);
    CHECK(scene_start(&s, tetra));
    CHECK(s.desc == tetra);
    /* Now a scene that does not fit: tetra keeps running, untouched. */
    s.state_cap = 64;
    CHECK(!scene_start(&s, knot));
    CHECK(s.desc == tetra && s.object_count == 1u);
    /* An init adding more objects than its column: refused, nothing half-built left running. */
    greedy_run = greedy;
    greedy_run.init = tetra->init;   /* tetra's init adds one object... */
    greedy_run.update = tetra->update;
    greedy_run.max_objects = 0;      /* ...which this descriptor does not declare */
    greedy_run.state_bytes = tetra->state_bytes;
    s.state_cap = sizeof scene_set_state;
    CHECK(!scene_start(&s, &greedy_run));
    CHECK(s.desc == 0);
    /* The table's own storage is back for the other cases. */
    scene_set_attach(&scene, &frame);
    fx_overflow_clear();
}

/* The sizes of issue #4: a 16^3 voxel world, a 5000-triangle model. */

void test_scene_sizes(void)
{
    scene_start(&scene, scene_find("knot"));
    CHECK_EQ(scene_triangle_count(&scene), 5000);
    scene_start(&scene, scene_find("voxel"));
    CHECK(scene_triangle_count(&scene) > 1000u);
    scene_start(&scene, scene_find("landscape"));
    CHECK_EQ(scene_triangle_count(&scene), 2048);
    scene_start(&scene, scene_find("cubes"));
    CHECK_EQ(scene_triangle_count(&scene), 64u * 12u);
    scene_start(&scene, scene_find("tetra"));
    CHECK_EQ(scene_triangle_count(&scene), 4);
}

/* Every scene renders frames, with keys, in filled and wireframe mode: something is drawn, the
 * frame's buffers suffice, and no fixed-point range argument fails. */
void test_scene_frames(void)
{
    static const char *const keys[] = {"", "wwwwjjjii", "m", "ddd  kkk", "mllluo", "sssss", "r"};

    for (uint32_t k = 0; k < SCENE_COUNT; k++) {
        scene_start(&scene, scene_at(k));
        for (uint32_t fr = 0; fr < 14u; fr++) {
            struct input_decoder dec;
            struct input_counts c;
            struct scene_event ev;
            const char *text = keys[fr % 7u];

            input_decoder_init(&dec);
            input_counts_clear(&c);
            input_feed(&dec, &c, (const uint8_t *)text, (uint32_t)strlen(text));
            scene_update(&scene, &c, &ev);
            render_scene(&scene, &frame, fr >= 7u);
            CHECK(frame.prim_count > 0u);
            CHECK_EQ(frame.stats.dropped, 0);
        }
        if (fx_overflow_count() != 0u) {
            unit_fail(__FILE__, __LINE__, "scene %s: %u fixed-point overflows", scene_at(k)->name,
                      (unsigned)fx_overflow_count());
        }
    }
}

/* The cubes' wireframe (issue #14): every line drawn is an edge of a cube, never a face's
 * diagonal, and an edge two visible faces share is drawn once, so a cube shows at most its 9
 * visible edges (three faces). Each cube is the 8-vertex box, vertex = corner bits (cubes.c), and
 * a pass without clipping projects the visible cubes' vertices in blocks of 8: lines a-b of one
 * block whose indices differ in one bit are edges; two bits, a diagonal. Before the fix every
 * triangle drew its three edges: 18 lines (6 diagonals, the shared edges twice) for a cube seen
 * from a corner. */
void test_scene_cubes_wireframe_edges(void)
{
    static const char *const keys[] = {"", "llll", "iiii", "kkkkjj", "uuu", "oooooo", "jjjjjjjj"};
    uint32_t checked = 0;
    uint32_t edges_total = 0;

    scene_start(&scene, scene_find("cubes"));
    for (uint32_t fr = 0; fr < 21u; fr++) {
        struct input_decoder dec;
        struct input_counts c;
        struct scene_event ev;
        const char *text = keys[fr % 7u];
        uint64_t pairs[64] = {0}; /* per block: bit 8 a + b for the edge a < b (local corners) */
        uint32_t objects_blocks;

        input_decoder_init(&dec);
        input_counts_clear(&c);
        input_feed(&dec, &c, (const uint8_t *)text, (uint32_t)strlen(text));
        scene_update(&scene, &c, &ev);
        render_scene(&scene, &frame, true);
        CHECK_EQ(frame.stats.dropped, 0);
        if (frame.stats.faces_clipped != 0u) {
            continue;  /* a clipped face's vertices break the blocks of 8 */
        }
        objects_blocks = 0;
        for (uint32_t i = 0; i < frame.prim_count; i++) {
            const struct render_prim *p = &frame.prim[i];

            if ((p->kind & RENDER_PRIM_OUTLINE) == 0u) {
                continue;  /* the crosshair's lines */
            }
            for (uint32_t k = 0; k < 3u; k++) {
                uint32_t a = p->v[k];
                uint32_t b = p->v[(k + 1u) % 3u];
                uint32_t t;
                uint32_t diff;

                if ((p->kind & (1u << k)) == 0u) {
                    continue;
                }
                if (a > b) {
                    t = a;
                    a = b;
                    b = t;
                }
                CHECK((a >> 3) == (b >> 3) && (a >> 3) < 64u);
                if ((a >> 3) != (b >> 3) || (a >> 3) >= 64u) {
                    return;
                }
                diff = (a ^ b) & 7u;
                if (diff != 1u && diff != 2u && diff != 4u) {
                    unit_fail(__FILE__, __LINE__, "cubes frame %u: line %u-%u is a diagonal",
                              (unsigned)fr, (unsigned)a, (unsigned)b);
                }
                if ((pairs[a >> 3] >> (8u * (a & 7u) + (b & 7u)) & 1u) != 0u) {
                    unit_fail(__FILE__, __LINE__, "cubes frame %u: edge %u-%u drawn twice",
                              (unsigned)fr, (unsigned)a, (unsigned)b);
                }
                pairs[a >> 3] |= 1ull << (8u * (a & 7u) + (b & 7u));
                objects_blocks = ((a >> 3) + 1u > objects_blocks) ? (a >> 3) + 1u : objects_blocks;
                edges_total++;
            }
        }
        for (uint32_t blk = 0; blk < objects_blocks; blk++) {
            CHECK(__builtin_popcountll(pairs[blk]) <= 9);
        }
        CHECK(objects_blocks > 0u);
        checked++;
    }
    CHECK(checked >= 10u);
    CHECK(edges_total > 0u);
}

/* Voxel: B breaks the block under the crosshair, P puts one back in front of the hit face. */
void test_scene_voxel_place_break(void)
{
    struct voxel_scene_state *v = voxel_scene_state(&scene);
    struct input_decoder dec;
    struct input_counts c;
    struct scene_event ev;
    struct voxel_hit hit;
    uint32_t faces_before;

    scene_start(&scene, scene_find("voxel"));
    /* Look straight down from above the middle of the world. */
    scene.cam.mode = CAM_FLY;
    scene.cam.eye = v3(8.5, 11.5, 8.5);  /* above the terrain (at most 9 high), within reach */
    scene.cam.pitch = -CAM_PITCH_LIMIT;
    CHECK(voxel_raycast(&v->world, scene.cam.eye, cam_forward(&scene.cam), to_real(10.0), &hit));
    faces_before = scene_triangle_count(&scene);

    input_decoder_init(&dec);
    input_counts_clear(&c);
    input_feed(&dec, &c, (const uint8_t *)"b", 1);
    scene_update(&scene, &c, &ev);
    CHECK_EQ(ev.kind, SCENE_EVENT_BROKE);
    CHECK(ev.x == hit.x && ev.y == hit.y && ev.z == hit.z);
    CHECK_EQ(voxel_get(&v->world, hit.x, hit.y, hit.z), BLOCK_AIR);
    /* The chunk mesh was rebuilt: no face is left on top of the removed block. */
    {
        const struct voxel_chunk *ch = &v->chunk[voxel_chunk_index(hit.x / VOXEL_CHUNK,
                                                                   hit.y / VOXEL_CHUNK,
                                                                   hit.z / VOXEL_CHUNK)];
        const int lx = hit.x % VOXEL_CHUNK;
        const int ly = hit.y % VOXEL_CHUNK;
        const int lz = hit.z % VOXEL_CHUNK;
        int top_faces = 0;

        for (uint32_t i = 0; i < ch->mesh.face_count; i++) {
            int on_top = 1;

            for (int k = 0; k < 3; k++) {
                const vec3 p = ch->mesh.verts[ch->mesh.faces[i].v[k]];

                on_top &= rd(p.y) == ly + 1 && rd(p.x) >= lx && rd(p.x) <= lx + 1 &&
                          rd(p.z) >= lz && rd(p.z) <= lz + 1;
            }
            top_faces += on_top;
        }
        CHECK_EQ(top_faces, 0);
        CHECK(scene_triangle_count(&scene) >= faces_before - 2u);
    }

    input_counts_clear(&c);
    input_feed(&dec, &c, (const uint8_t *)"p", 1);
    scene_update(&scene, &c, &ev);
    CHECK_EQ(ev.kind, SCENE_EVENT_PLACED);
    CHECK(ev.x == hit.x && ev.y == hit.y && ev.z == hit.z);  /* fills the hole again */
    CHECK_EQ(voxel_get(&v->world, hit.x, hit.y, hit.z), BLOCK_STONE);

    input_counts_clear(&c);
    input_feed(&dec, &c, (const uint8_t *)"np", 2);
    scene_update(&scene, &c, &ev);
    CHECK_EQ(ev.kind, SCENE_EVENT_PLACED);
    CHECK_EQ(ev.y, hit.y + 1);  /* on top of it, the next block type */
    CHECK(voxel_get(&v->world, ev.x, ev.y, ev.z) != BLOCK_STONE);

    /* Nothing in reach: looking straight up. */
    scene.cam.pitch = CAM_PITCH_LIMIT;
    input_counts_clear(&c);
    input_feed(&dec, &c, (const uint8_t *)"b", 1);
    scene_update(&scene, &c, &ev);
    CHECK_EQ(ev.kind, SCENE_EVENT_NO_TARGET);
    CHECK_EQ(fx_overflow_count(), 0);
}

/* ---- capacities ---------------------------------------------------------------------------- */

/* A frame larger than any pass of the scenes needs (each pass below checks nothing was dropped),
 * to measure what a pass really needs: a narrow frame's most, in a wide build too (whose limit,
 * 2^24, would be a gigabyte of storage). */
#define MEASURE_FRAME_CAP 65535u
RENDER_FRAME_STORAGE(measure_frame, MEASURE_FRAME_CAP, MEASURE_FRAME_CAP);
static struct render_frame measure;

struct cap_need {
    uint32_t verts;
    uint32_t prims;
    uint32_t kind_verts[3];  /* filled (both eyes too), wireframe with lines, emulated */
    uint32_t kind_prims[3];
};

static void cap_pass(const struct scene *s, bool wire, bool lines, int eye, struct cap_need *need)
{
    const struct pipeline_opts opts = {.wireframe = wire, .depth_test = false, .gpu_lines = lines};

    pipeline_pass(&measure, s, &opts, eye, NULL, NULL);
    CHECK_EQ(measure.stats.dropped, 0);
    const int kind = !wire ? 0 : (lines ? 1 : 2);

    need->verts = (measure.vert_count > need->verts) ? measure.vert_count : need->verts;
    need->prims = (measure.prim_count > need->prims) ? measure.prim_count : need->prims;
    if (measure.vert_count > need->kind_verts[kind]) {
        need->kind_verts[kind] = measure.vert_count;
    }
    if (measure.prim_count > need->kind_prims[kind]) {
        need->kind_prims[kind] = measure.prim_count;
    }
}

/*
 * Each scene's declared frame capacities (scene_list.h's verts and prims columns) hold under
 * stress: camera sweeps (the scene's own mode, orbit and fly; five distances over the camera's
 * range, sixteen headings, five pitches), the animation running, and every pass kind a frame can
 * make: filled, wireframe with GPU lines, wireframe emulated by triangle pairs (the largest: 4
 * vertices and 2 triangles per edge), and the anaglyph's two eyes, filled and emulated
 * wireframe; at the contract's default frame and at its largest (the field of view is the same,
 * but the guard band, 1536 px at either, is a narrower angle at 640 x 480: more triangles are
 * clipped there). No pass may exceed a column; the measured largest needs are printed (the
 * README's capacity table quotes them). A pass through the program's own frame (sized by
 * scene_set.h for the largest column) drops nothing either.
 */
void test_scene_capacities(void)
{
    const enum cam_mode modes[] = {CAM_ORBIT, CAM_FLY, CAM_OBJECT};
    const uint32_t frame_w[] = {GPU_FB_WIDTH, GPU_FB_MAX_WIDTH};
    const uint32_t frame_h[] = {GPU_FB_HEIGHT, GPU_FB_MAX_HEIGHT};

    RENDER_FRAME_ATTACH(&measure, measure_frame);
    for (uint32_t k = 0; k < 2u * SCENE_COUNT; k++) {
        const struct scene_desc *d = scene_at(k % SCENE_COUNT);
        const uint32_t fi = k / SCENE_COUNT;
        struct cap_need need;
        struct input_counts none;
        struct scene_event ev;

        memset(&need, 0, sizeof need);
        scene_set_frame(&scene, frame_w[fi], frame_h[fi]);
        CHECK(scene_start(&scene, d));
        input_counts_clear(&none);
        for (uint32_t mi = 0; mi < 4u; mi++) {
            const enum cam_mode mode = (mi == 0u) ? scene.mode_default : modes[mi - 1u];

            for (int32_t di = 0; di < 5; di++) {
                const real_t dist =
                    scene.cam_default.dist_min +
                    (real_t)((scene.cam_default.dist_max - scene.cam_default.dist_min) / 4 * di);

                for (uint32_t yi = 0; yi < 16u; yi++) {
                    for (int32_t pi = -2; pi <= 2; pi++) {
                        cam_init(&scene.cam, &scene.cam_default, mode, scene.target_default, dist,
                                 (fx_angle)(yi * (FX_TURN / 16u)),
                                 pi * (CAM_PITCH_LIMIT / 5) * 2);
                        scene_update(&scene, &none, &ev);  /* the animation moves on */
                        cap_pass(&scene, false, true, 0, &need);
                        cap_pass(&scene, true, true, 0, &need);
                        cap_pass(&scene, true, false, 0, &need);
                        cap_pass(&scene, false, true, -1, &need);
                        cap_pass(&scene, false, true, 1, &need);
                        cap_pass(&scene, true, false, 1, &need);
                    }
                }
            }
        }
        printf("capacity %-9s %ux%u verts %5lu of %5lu, prims %5lu of %5lu (filled %lu/%lu, "
               "lines %lu/%lu, emulated lines %lu/%lu)\n", d->name, (unsigned)frame_w[fi],
               (unsigned)frame_h[fi],
               (unsigned long)need.verts, (unsigned long)d->max_verts, (unsigned long)need.prims,
               (unsigned long)d->max_prims, (unsigned long)need.kind_verts[0],
               (unsigned long)need.kind_prims[0], (unsigned long)need.kind_verts[1],
               (unsigned long)need.kind_prims[1], (unsigned long)need.kind_verts[2],
               (unsigned long)need.kind_prims[2]);
        if (need.kind_verts[0] > d->filled_verts || need.kind_prims[0] > d->filled_prims) {
            unit_fail(__FILE__, __LINE__, "scene %s: a filled pass needs %lu vertices and %lu "
                      "primitives: its scene_list.h columns say %lu and %lu", d->name,
                      (unsigned long)need.kind_verts[0], (unsigned long)need.kind_prims[0],
                      (unsigned long)d->filled_verts, (unsigned long)d->filled_prims);
        }
        CHECK(need.verts <= d->wire_verts && need.prims <= d->wire_prims);
        if (need.verts > d->max_verts || need.prims > d->max_prims) {
            unit_fail(__FILE__, __LINE__, "scene %s needs %lu vertices and %lu primitives: its "
                      "scene_list.h columns say %lu and %lu", d->name, (unsigned long)need.verts,
                      (unsigned long)need.prims, (unsigned long)d->max_verts,
                      (unsigned long)d->max_prims);
        }
        CHECK(d->max_verts <= SCENE_SET_VERTS && d->max_prims <= SCENE_SET_PRIMS);
        /* The program's own frame, sized for the largest column, at the default view. */
        scene_start(&scene, d);
        render_scene(&scene, &frame, true);
        CHECK_EQ(frame.stats.dropped, 0);
        CHECK_EQ(fx_overflow_count(), 0);
        fx_overflow_clear();
    }
    scene_set_frame(&scene, GPU_FB_WIDTH, GPU_FB_HEIGHT);
}

/*
 * Voxel: the chunks share one pool (voxel_scene.h). The generated world needs exactly
 * VOXEL_POOL_GEN_FACES faces and VOXEL_POOL_GEN_VERTS vertices (the README's argument quotes
 * them), packed without gaps; an edit that makes the world need more than the pool leaves whole
 * chunks out and says so (SCENE_EVENT_MESH_FULL), never draws half a chunk, and undoing it draws
 * everything again.
 */
void test_scene_voxel_pool(void)
{
    struct voxel_scene_state *v = voxel_scene_state(&scene);
    struct input_counts none;
    struct scene_event ev;
    uint32_t faces = 0;
    uint32_t verts = 0;

    CHECK(scene_start(&scene, scene_find("voxel")));
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        const struct mesh *m = &v->chunk[i].mesh;

        CHECK(m->verts == &v->pool_verts[verts]);  /* packed in chunk order */
        CHECK(m->faces == &v->pool_faces[faces]);
        faces += m->face_count;
        verts += m->vert_count;
    }
    printf("voxel pool: generated world %lu faces of %u, %lu vertices of %u\n",
           (unsigned long)faces, VOXEL_POOL_FACES, (unsigned long)verts, VOXEL_POOL_VERTS);
    CHECK_EQ(faces, VOXEL_POOL_GEN_FACES);
    CHECK_EQ(verts, VOXEL_POOL_GEN_VERTS);
    CHECK_EQ(v->left_out_mask, 0);

    /* A 3-D checkerboard over the air above the terrain: far more faces than the pool holds. */
    for (int32_t y = 10; y < VOXEL_NY; y++) {
        for (int32_t z = 0; z < VOXEL_NZ; z++) {
            for (int32_t x = 0; x < VOXEL_NX; x++) {
                if (((x + y + z) & 1) == 0) {
                    voxel_set(&v->world, x, y, z, BLOCK_STONE);
                }
            }
        }
    }
    input_counts_clear(&none);
    scene_update(&scene, &none, &ev);
    CHECK_EQ(ev.kind, SCENE_EVENT_MESH_FULL);
    CHECK(ev.x >= 1 && ev.x == __builtin_popcount(v->left_out_mask));
    faces = 0;
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        const struct mesh *m = &v->chunk[i].mesh;

        CHECK(!m->full);
        if ((v->left_out_mask >> i) & 1u) {
            CHECK_EQ(m->face_count, 0);  /* whole chunks left out */
        }
        faces += m->face_count;
    }
    CHECK(faces <= VOXEL_POOL_FACES);
    /* Undo: everything fits and is drawn again, with no error. */
    for (int32_t y = 10; y < VOXEL_NY; y++) {
        for (int32_t z = 0; z < VOXEL_NZ; z++) {
            for (int32_t x = 0; x < VOXEL_NX; x++) {
                voxel_set(&v->world, x, y, z, BLOCK_AIR);
            }
        }
    }
    voxel_generate(&v->world);
    scene_update(&scene, &none, &ev);
    CHECK(ev.kind != SCENE_EVENT_MESH_FULL);
    CHECK_EQ(v->left_out_mask, 0);
    faces = 0;
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        faces += v->chunk[i].mesh.face_count;
    }
    CHECK_EQ(faces, VOXEL_POOL_GEN_FACES);
}

/* A scene's grid (scene_set_grid) is its promise that object i = x + nx (y + ny z) stays in cell
 * (x, y, z): every vertex of it, turned and placed as render_object places it, in every frame of
 * its animation; and its cells' sizes are positive, or 0 on an axis of one cell. The cubes' and
 * the landscape's grids are on (FW_SCENE_ORDER), and hold. */
void test_scene_grid_cells(void)
{
    uint32_t grids = 0;

    for (uint32_t k = 0; k < SCENE_COUNT; k++) {
        const struct scene_grid_layout *g;

        CHECK(scene_start(&scene, scene_at(k)));
        if (scene.grid == NULL) {
            continue;
        }
        g = scene.grid;
        grids++;
        for (int a = 0; a < 3; a++) {
            CHECK(rd(g->cell[a]) > 0.0 || (rd(g->cell[a]) == 0.0 && g->count[a] == 1u));
        }
        for (uint32_t fr = 0; fr < 120u; fr++) {
            struct input_counts c;
            struct scene_event ev;

            input_counts_clear(&c);
            scene_update(&scene, &c, &ev);
            for (uint32_t i = 0; i < scene.object_count; i++) {
                const struct render_object *o = &scene.object[i];
                const uint32_t cell[3] = {i % g->count[0], (i / g->count[0]) % g->count[1],
                                          i / (g->count[0] * g->count[1])};

                for (uint32_t v = 0; v < o->mesh->vert_count; v++) {
                    const vec3 p = vec3_add(o->pos, mat3_apply(&o->rot, o->mesh->verts[v]));
                    const double q[3] = {rd(p.x), rd(p.y), rd(p.z)};

                    for (int a = 0; a < 3; a++) {
                        const double lo = rd(g->origin[a]) + cell[a] * rd(g->cell[a]);

                        if (rd(g->cell[a]) != 0.0) {
                            CHECK(q[a] >= lo && q[a] <= lo + rd(g->cell[a]));
                        }
                    }
                }
            }
        }
    }
    CHECK(!FW_SCENE_ORDER || grids >= 2u);
    CHECK(FW_SCENE_ORDER || grids == 0u);
}

/* The landscape asks for Gouraud shading: every tile carries vertex normals, unit length and
 * facing up (a height field), and a grid point shared by two tiles has the same normal in both
 * (averaged over the whole terrain's faces: no seam in the shading at a tile border). */
void test_scene_landscape_normals(void)
{
    uint32_t shared = 0;

    CHECK(scene_start(&scene, scene_find("landscape")));
    for (uint32_t a = 0; a < scene.object_count; a++) {
        const struct render_object *oa = &scene.object[a];

        CHECK(FW_WITH_GOURAUD == 0 || oa->vnormal14 != 0);
        if (oa->vnormal14 == 0) {
            continue;
        }
        for (uint32_t i = 0; i < oa->mesh->vert_count; i++) {
            const uvec3 n = mesh_q14_normal(oa->vnormal14, i);
            const double len = sqrt(ud(n.x) * ud(n.x) + ud(n.y) * ud(n.y) + ud(n.z) * ud(n.z));

            CHECK(fabs(len - 1.0) < 1e-3 && ud(n.y) > 0.0);
            for (uint32_t b = a + 1u; b < scene.object_count; b++) {
                const struct render_object *ob = &scene.object[b];

                for (uint32_t j = 0; j < ob->mesh->vert_count; j++) {
                    const vec3 p = oa->mesh->verts[i];
                    const vec3 q = ob->mesh->verts[j];

                    if (p.x == q.x && p.y == q.y && p.z == q.z) {
                        shared++;
                        CHECK(memcmp(&oa->vnormal14[3u * i], &ob->vnormal14[3u * j], 6) == 0);
                    }
                }
            }
        }
    }
    CHECK(FW_WITH_GOURAUD == 0 || shared > 0u);
}
