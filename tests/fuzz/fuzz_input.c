/*
 * fuzz_input — libFuzzer target for the firmware's keyboard path: UART bytes -> input.c decoder
 * -> key counts -> the global keys and scene_update (camera.c, the scenes' own keys), driven the
 * way app.c drives them, on the host build of the pure sources.
 *
 * The input: byte 0 picks the starting scene; the rest is a sequence of arrivals, each a length
 * byte L (0..63) and L bytes that "arrive at the UART" before the next frame. Every frame reads
 * at most INPUT_MAX_BYTES_PER_FRAME bytes, as app_read_keys does; what is left waits for the next
 * frame. After the last arrival the frames go on until the UART is empty.
 *
 * Properties (a violation aborts, reported by libFuzzer as a crash; ASan + UBSan are on):
 *   - bounded work: a frame reads at most 32 bytes and counts at most 32 keys; the backlog drains
 *     in exactly ceil(backlog / 32) frames once nothing new arrives (never a stall);
 *   - chunking does not matter: the keys counted over all frames equal those of the same bytes
 *     decoded in one go by a fresh decoder;
 *   - the decoder resynchronises: whatever came before, "ww" yields at least one W;
 *   - after every frame the camera keeps its documented invariants (camera.h): a valid mode,
 *     |pitch| <= 89 degrees, eye and target inside the scene's box, distance within its limits,
 *     the view basis and the object-mode scene rotation orthonormal within 1e-3, finite;
 *     the voxel scene's block type valid; no fixed-point saturation (the firmware stops with
 *     status 6 on one);
 *   - the last frame is rendered and cut into batches as app.c does, and still nothing saturates.
 */
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/batch.h"
#include "camera/camera.h"
#include "math/fixed.h"
#include "input/input.h"
#include "render/palette.h"
#include "render/proj.h"
#include "math/real.h"
#include "render/render.h"
#include "scenes/scene.h"
/* This program has every scene (no FW_BUILT_SCENES): the table and its storage. */
#include "scenes/scene_set.h"
#include "scenes/voxel/voxel_scene.h"
#include "app/pipeline.h"
#include "fuzz_common.h"

#define FUZZ_MAX_BACKLOG 4096u  /* the simulated UART holds what has arrived and not been read */

static struct scene scene;          /* large: static, like app.c's */
/* scene_start(&scene, scene_at(k)) as it leaves `scene` and its state storage: building the
 * meshes (normals, square roots) costs far more than the keys, and has no input, so it is done
 * once per scene and then copied back. The copies land at the same addresses (the struct, its
 * objects and its state: scene_set.h's storage), so the scene's pointers into itself hold. */
static struct scene started[SCENE_COUNT];
static struct render_object started_objects[SCENE_COUNT][SCENE_SET_OBJECTS];
static _Alignas(8) unsigned char started_state[SCENE_COUNT][SCENE_SET_STATE_BYTES];
static bool started_valid[SCENE_COUNT];
static struct render_frame frame;
static uint32_t batch_vtx[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t batch_prim[GPU_TRI_CAP * GPU_PRIM_WORDS];
static struct batch_words words = BATCH_WORDS_ON(batch_vtx, batch_prim);

static double unit_d(unit_t u)
{
#if REAL_IS_FIXED
    return (double)u / (double)Q30_ONE;
#else
    return (double)u;
#endif
}

static double real_d(real_t r)
{
#if REAL_IS_FIXED
    return (double)r / (double)FX_ONE;
#else
    return (double)r;
#endif
}

/* Rows orthonormal within tol, determinant near +1, every entry finite. */
static void check_rotation(const mat3 *m, double tol, const char *what)
{
    double r[3][3];

    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            r[i][j] = unit_d(m->m[i][j]);
            REQUIRE(isfinite(r[i][j]), "%s[%d][%d] not finite", what, i, j);
        }
    }
    for (int i = 0; i < 3; i++) {
        for (int j = i; j < 3; j++) {
            const double dot = r[i][0] * r[j][0] + r[i][1] * r[j][1] + r[i][2] * r[j][2];
            const double want = (i == j) ? 1.0 : 0.0;
            REQUIRE(fabs(dot - want) <= tol, "%s rows %d.%d = %g", what, i, j, dot);
        }
    }
    const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    REQUIRE(fabs(det - 1.0) <= 3.0 * tol, "%s determinant %g", what, det);
}

static void check_in_box(const struct cam_config *cfg, vec3 p, const char *what)
{
    REQUIRE(isfinite(real_d(p.x)) && isfinite(real_d(p.y)) && isfinite(real_d(p.z)),
            "%s not finite", what);
    REQUIRE(p.x >= cfg->box_min.x && p.x <= cfg->box_max.x && p.y >= cfg->box_min.y &&
                p.y <= cfg->box_max.y && p.z >= cfg->box_min.z && p.z <= cfg->box_max.z,
            "%s (%g, %g, %g) outside the box", what, real_d(p.x), real_d(p.y), real_d(p.z));
}

static void check_camera(const struct scene *s)
{
    const struct camera *cam = &s->cam;
    const struct cam_config *cfg = &cam->cfg;
    struct cam_view view;

    REQUIRE(cam->mode == CAM_FLY || cam->mode == CAM_ORBIT || cam->mode == CAM_OBJECT, "mode %d",
            (int)cam->mode);
    REQUIRE(cam->pitch >= -CAM_PITCH_LIMIT && cam->pitch <= CAM_PITCH_LIMIT, "pitch %ld",
            (long)cam->pitch);
    check_in_box(cfg, cam->eye, "eye");
    check_in_box(cfg, cam->target, "target");
    REQUIRE(cam->distance >= cfg->dist_min && cam->distance <= cfg->dist_max, "distance %g",
            real_d(cam->distance));
    cam_get_view(cam, 0, &view);
    check_rotation(&view.rot, 1e-3, "view basis");
    check_rotation(&cam->scene_rot, 1e-3, "scene rotation");
    /* The firmware's range rule (real.h): the eye within +-1024 per axis. */
    REQUIRE(fabs(real_d(view.eye.x)) <= 1024.0 && fabs(real_d(view.eye.y)) <= 1024.0 &&
                fabs(real_d(view.eye.z)) <= 1024.0,
            "view eye outside +-1024");
    if (s->desc == &scene_voxel_desc) {
        const uint8_t b = voxel_scene_state((struct scene *)s)->place_block;

        REQUIRE(b >= BLOCK_GRASS && b < BLOCK_TYPES, "block type %u", b);
    }
    REQUIRE(fx_overflow_count() == 0u, "%lu fixed-point saturations",
            (unsigned long)fx_overflow_count());
}

static void start_scene(uint32_t k)
{
    if (scene.state == NULL) {
        scene_set_attach(&scene, &frame);
    }
    if (!started_valid[k]) {
        REQUIRE(scene_start(&scene, scene_at(k)), "scene %s refused", scene_at(k)->name);
        memcpy(&started[k], &scene, sizeof scene);
        memcpy(started_objects[k], scene.object, sizeof started_objects[k]);
        memcpy(started_state[k], scene.state, sizeof started_state[k]);
        started_valid[k] = true;
    }
    memcpy(&scene, &started[k], sizeof scene);
    memcpy(scene.object, started_objects[k], sizeof started_objects[k]);
    memcpy(scene.state, started_state[k], sizeof started_state[k]);
}

/* One render pass (the frame loop's, pipeline.h) and its batches, as app_submit cuts them (without
 * a GPU). */
static void render_and_batch(struct scene *s)
{
    const struct pipeline_opts opts = {.wireframe = false, .depth_test = false, .gpu_lines = true};
    struct batch_cursor cur;
    uint32_t prims = 0;

    pipeline_pass(&frame, s, &opts, 0, NULL, NULL);
    batch_begin(&cur);
    do {
        batch_fill(&cur, &frame, GPU_VTX_CAP, GPU_TRI_CAP, &words);
        REQUIRE(words.vtx_count <= GPU_VTX_CAP && words.prim_count <= GPU_TRI_CAP, "batch size");
        REQUIRE(words.prim_count > 0u || frame.prim_count == 0u, "empty batch: no progress");
        prims += words.prim_count;
    } while (!batch_done(&cur, &frame));
    REQUIRE(prims == frame.prim_count, "%lu of %lu primitives batched", (unsigned long)prims,
            (unsigned long)frame.prim_count);
    REQUIRE(fx_overflow_count() == 0u, "saturation while rendering");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t uart[FUZZ_MAX_BACKLOG];   /* bytes arrived and not read, uart[head..tail) */
    static uint8_t consumed[1u << 16];       /* every byte the frames read, in order */
    struct input_decoder decoder;
    uint32_t head = 0;
    uint32_t tail = 0;
    uint32_t n_consumed = 0;
    uint32_t counted[KEY_COUNT] = {0};       /* keys summed over the frames */
    size_t pos = 1;
    bool quit = false;
    uint32_t drain_frames = 0;
    uint32_t drain_expected = 0;

    if (size < 1u || size > 8192u) {
        return 0;
    }
    fx_overflow_clear();
    start_scene(data[0] % SCENE_COUNT);
    input_decoder_init(&decoder);
    check_camera(&scene);

    while (!quit) {
        struct input_counts keys;
        struct scene_event ev;

        /* Arrivals before this frame (none once the input is used up: the drain). */
        if (pos < size) {
            const uint32_t len = data[pos++] % 64u;

            for (uint32_t i = 0; i < len && pos < size; i++) {
                if (tail - head < FUZZ_MAX_BACKLOG) {
                    uart[tail++ % FUZZ_MAX_BACKLOG] = data[pos];
                }
                pos++;
            }
        } else {
            if (drain_frames == 0u) {
                drain_expected = (tail - head + INPUT_MAX_BYTES_PER_FRAME - 1u) /
                                 INPUT_MAX_BYTES_PER_FRAME;
            }
            if (head == tail) {
                break;
            }
            drain_frames++;
            REQUIRE(drain_frames <= drain_expected, "the backlog did not drain in %lu frames",
                    (unsigned long)drain_expected);
        }

        /* app_read_keys: at most INPUT_MAX_BYTES_PER_FRAME bytes, never waiting. */
        input_counts_clear(&keys);
        uint32_t read = 0;
        for (uint32_t i = 0; i < INPUT_MAX_BYTES_PER_FRAME; i++) {
            if (head == tail) {
                break;
            }
            const uint8_t c = uart[head++ % FUZZ_MAX_BACKLOG];
            consumed[n_consumed++ % sizeof consumed] = c;
            read++;
            input_counts_add(&keys, input_decode(&decoder, c));
        }
        REQUIRE(read <= INPUT_MAX_BYTES_PER_FRAME, "read %lu bytes", (unsigned long)read);
        uint32_t sum = 0;
        for (uint32_t k = 0; k < KEY_COUNT; k++) {
            sum += keys.n[k];
            counted[k] += keys.n[k];
        }
        REQUIRE(keys.n[KEY_NONE] == 0u && sum == keys.total && keys.total <= read,
                "counts: total %u, sum %lu, read %lu", keys.total, (unsigned long)sum,
                (unsigned long)read);

        /* app_global_keys: quit, then scene switches (in key order), then scene_update. */
        if (keys.n[KEY_QUIT] != 0u) {
            quit = true;
            break;
        }
        for (uint32_t k = 0; k < SCENE_COUNT; k++) {
            if (keys.n[KEY_SCENE_1 + k] != 0u) {
                start_scene(k);  /* = scene_start(&scene, scene_at(k)) */
            }
        }
        scene_update(&scene, &keys, &ev);
        check_camera(&scene);
    }

    /* The same bytes decoded in one go count the same keys. */
    if (n_consumed <= sizeof consumed) {
        struct input_decoder whole;
        uint32_t once[KEY_COUNT] = {0};

        input_decoder_init(&whole);
        for (uint32_t i = 0; i < n_consumed; i++) {
            once[input_decode(&whole, consumed[i])]++;
        }
        for (uint32_t k = 1; k < KEY_COUNT; k++) {
            REQUIRE(once[k] == counted[k], "key %lu: %lu in one go, %lu over the frames",
                    (unsigned long)k, (unsigned long)once[k], (unsigned long)counted[k]);
        }
    }

    /* Resynchronisation: from whatever state the stream left, "ww" gives a W. */
    {
        struct input_decoder d = decoder;
        const enum input_key k1 = input_decode(&d, 'w');
        const enum input_key k2 = input_decode(&d, 'w');

        REQUIRE(k1 == KEY_FORWARD || k2 == KEY_FORWARD, "\"ww\" gave keys %d, %d", (int)k1,
                (int)k2);
    }

    if (!quit) {
        render_and_batch(&scene);
    }
    return 0;
}
