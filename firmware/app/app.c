/*
 * app.c — the frame loop: keys in, scene update, one or two render passes, GPU batches out, one
 * statistics line per frame. This file and the driver edge (gpu.c) are the only ones that touch
 * the platform (bsp.h); everything they call is pure and host-tested.
 *
 * Layout: app_run is boot, then per frame the named stages app_input (steps 0-2's keys),
 * app_update (the scene), app_draw (per pass app_render_pass, then app_submit: step 3-4),
 * app_print_notes and app_statistics; the frame's counters are one struct frame_stats and its
 * frame_stats_* functions; what a build leaves out (uploads, the USB keyboard, the platform's GPU
 * buffers and hooks, the measurement camera) is decided in one block of #if's, each giving the
 * stages a function that is empty where the feature is not built.
 *
 * Per frame:
 *   0. a model uploaded over the UART and committed in the last frame is swapped in: the model
 *      scene starts from it (model/upload.h; FW_WITH_UPLOAD);
 *   1. the keys the last frame collected before its first batch went out (app_collect_input; the
 *      first frame reads its own): at most INPUT_MAX_BYTES_PER_FRAME bytes from the UART
 *      (FW_UART_BYTES_PER_FRAME where uploads are built in; never blocks, the rest waits for the
 *      next frame); the upload's receiver takes its frames, the rest is decoded into key counts;
 *      with FW_USB_KEYBOARD, then at most FW_USB_EVENTS_PER_FRAME events of the USB keyboard, into
 *      the same counts (input/usb_keys.h: each key acts as its terminal bytes do on the UART). So
 *      keys typed at any doorbell of frame F act from frame F + 2;
 *   2. global keys (quit, scene, wireframe, anaglyph, depth buffer, help), then scene_update
 *      (camera keys, animation, scene keys);
 *   3. per pass (two for anaglyph: left eye red, right eye cyan): render the scene into the
 *      frame's primitive list, sort it, add the overlay, and stream it to the GPU batch by batch
 *      (batch.c). The first batch of the frame sets CTRL_CLEAR, the last CTRL_SWAP; with the depth
 *      test the first batch of each pass sets CTRL_ZCLEAR (each eye has its own depth order). On
 *      a GPU with the write mask (CAPS_WMASK) the anaglyph's eyes write their own plane of the
 *      framebuffer (the left eye the high nibble, the right eye the low one: FB_WRITE_MASK), each
 *      clearing it first, through the anaglyph palette (palette.h), so a pixel both eyes cover
 *      shows both; without it the right eye's pass draws over the left eye's.
 *      On a GPU with a strip buffer the pass goes out in strips: one batch the GPU walks over
 *      every strip (CTRL.WALK) where the pass fits one, else the firmware's binning (strips.h).
 *   4. after each doorbell, wait for DONE_SEQ with a bounded poll — the watchdog. A batch that
 *      never finishes is reported, the GPU is reset (RESET register), the rest of the frame is
 *      dropped and the loop goes on with the next frame; after FW_WATCHDOG_GIVE_UP consecutive
 *      lost frames the firmware stops with FW_EXIT_GPU_TIMEOUT.
 *   5. but the frame's last batch (the one that swaps) is left pending: the CPU goes on with the
 *      next frame's steps 0-3 while the GPU draws it and waits for vertical blank, and waits for
 *      it (step 4, app_settle) only before it writes the GPU again — the next frame's buffers, a
 *      palette — or stops. So a frame's CPU work and the last frame's GPU work overlap: a frame
 *      takes the longer of the two, not their sum.
 *
 * Output: the upload's responses to what the frame read ("@up ...", one per protocol frame
 * received, printed before the frame is drawn), then one line per frame, once its last batch is
 * done (so after the next frame's upload responses):
 *   frame N: tris submitted S drawn D | fw instr I | gpu cycles C | errors 0xE | prims P batches B
 *     | culled object O frustum F back K clipped L
 *     | cpu cycles Y
 * "fw instr" counts the frame's CPU work (steps 1-4, including the buffer copies and the counter
 * reads) with bsp_instret(), minus the DONE_SEQ polling: exact and reproducible under QEMU -icount.
 * "cpu cycles" is bsp_cycles() over the same span, minus the same polling: the clock cycles the
 * work took on a real core (0 where the platform has no cycle counter; under QEMU it follows the
 * emulation, not a core). Printing is not counted.
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "app/app.h"
#include "gpu/batch.h"
#include "bsp.h"
#include "camera/camera.h"
#include "math/fixed.h"
#include "model/upload.h"
#include "app/fw_config.h"
#include "gpu/gpu.h"
#include "input/input.h"
#include "input/usb_keys.h"
#include "render/palette.h"
#include "render/proj.h"
#include "render/proj_unit.h"
#include "math/real.h"
#include "render/render.h"
#include "render/strips.h"
#include "scenes/scene.h"
#include "app/pipeline.h"
#include "app/cam_path.h"
/* This program's scenes (FW_BUILT_SCENES, from firmware.mk: every scene, or only FW_SCENE) and
 * their memory, sized for the largest of them: app.c is the one file of the program that says. */
#include "scenes/scene_set.h"

/* ---- the frame's counters: one struct, changed only by these functions ----------------------- */

/* What one frame sent and what the GPU reported, summed over its batches and passes, and where
 * its instructions went. */
struct frame_stats {
    uint64_t t_start;     /* bsp_instret() at the frame's start */
    uint64_t c_start;     /* bsp_cycles() at the frame's start */
    uint64_t instr;       /* fw instr: the frame's instructions, the excluded spans taken out */
    uint64_t cycles;      /* cpu cycles, likewise */
    uint32_t batches;
    uint32_t prims;
    uint32_t drawn;
    uint32_t busy_cycles;
    uint32_t errors;
    uint64_t wait_instr;  /* instructions spent polling DONE_SEQ or printing (excluded) */
    uint64_t wait_cycles; /* cycles spent likewise (excluded) */
    /* Where the instructions went (FW_PROFILE=1 prints them): */
    uint64_t t_update;    /* keys, camera, scene update */
    uint64_t t_draw;      /* transform, project, cull, clip, light, emit */
    uint64_t t_sort;
    uint64_t t_batch;     /* batch_fill: renumbering and packing */
    uint64_t t_submit;    /* driver: copies, registers, doorbell, counters */
    struct render_stats render;
};

/* An excluded span's start (frame_stats_exclude). */
struct frame_span {
    uint64_t instr;
    uint64_t cycles;
};

/* Everything the loop owns. One instance, static, handed to the pure code by pointer; the frame's
 * arrays and the scene's state are this program's storage (scene_set.h), sized per build. */
struct app {
    struct gpu_dev gpu;
    struct scene scene;
    struct render_frame frame;
    struct batch_words words;
    struct input_decoder decoder;
    uint16_t palette[PAL_ENTRIES];
    bool wireframe;
    bool anaglyph;
    bool depth_test;
    uint32_t write_mask;     /* FB_WRITE_MASK as last written; APP_WRITE_MASK_UNKNOWN at first */
    uint32_t lost_in_a_row;  /* consecutive frames dropped by the watchdog */
    /* The frame whose last batch the GPU may still be drawing (its swap waits for vertical
     * blank; the driver's gpu.pending, gpu.pending_tag) while the CPU computes the next: its
     * number and statistics (app_settle). */
    unsigned pending_frame;
    struct frame_stats pending_st;
    /* The next frame's keys, collected before this frame's first batch went out (app_collect_input). */
    struct input_counts keys_next;
    bool keys_collected;
#if FW_WITH_UPLOAD
    struct upload_rx upload;
    bool model_from_upload;  /* the model scene's source is the staging buffer */
#endif
#if FW_USB_KEYBOARD
    struct usb_keys usb;     /* the USB keyboard's own decoder, Shift and held key */
    int usb_state;           /* bsp_usb_state() as last reported */
#endif
#if FW_WITH_STRIPS
    uint32_t strip_rows;       /* lines per strip a frame is sent in; 0: whole */
    struct strip_bins strips;  /* the pass's primitives binned into strips (render/strips.h) */
#endif
};

static void frame_stats_begin(struct frame_stats *st)
{
    *st = (struct frame_stats){0};
    st->c_start = bsp_cycles();
    st->t_start = bsp_instret();
}

static inline struct frame_span frame_span_begin(void)
{
    struct frame_span s;

    s.instr = bsp_instret();
    s.cycles = bsp_cycles();
    return s;
}

/* Work since span s that is not the firmware's (printing, the measurement camera): not counted. */
static inline void frame_stats_exclude(struct frame_stats *st, struct frame_span s)
{
    st->wait_instr += bsp_instret() - s.instr;
    st->wait_cycles += bsp_cycles() - s.cycles;
}

/* The instruction counter: a mark that a frame_stats_* function below closes, and pipeline_pass's
 * clock (inlined there). */
static inline uint64_t frame_stats_mark(void)
{
    return bsp_instret();
}

/* batch_fill, from mark t0, is done: its instructions; returns the mark where submitting starts. */
static inline uint64_t frame_stats_batch_filled(struct frame_stats *st, uint64_t t0)
{
    const uint64_t t1 = bsp_instret();

    st->t_batch += t1 - t0;
    return t1;
}

/* The batch went out (submitting since mark t1); the wait for DONE_SEQ starts, not counted. */
static inline struct frame_span frame_stats_wait_begin(struct frame_stats *st, uint64_t t1)
{
    st->t_submit += bsp_instret() - t1;
    return frame_span_begin();
}

/* The wait is over; returns the mark where reading the GPU's counters starts. */
static inline uint64_t frame_stats_wait_end(struct frame_stats *st, struct frame_span s)
{
    frame_stats_exclude(st, s);
    return bsp_instret();
}

/* The GPU's counters are read (since mark t0): the driver's part of the batch is done. */
static inline void frame_stats_submitted(struct frame_stats *st, uint64_t t0)
{
    st->t_submit += bsp_instret() - t0;
}

/* pipeline_pass's times go on from the frame's and come back to it. */
static inline struct pipeline_times frame_stats_pass_times(const struct frame_stats *st)
{
    const struct pipeline_times t = {st->t_draw, st->t_sort};

    return t;
}

static inline void frame_stats_set_pass_times(struct frame_stats *st,
                                              const struct pipeline_times *t)
{
    st->t_draw = t->draw;
    st->t_sort = t->sort;
}

/* Keys, camera and scene are done: what they took, counted from the frame's start. */
static inline void frame_stats_updated(struct frame_stats *st)
{
    st->t_update = bsp_instret() - st->t_start;
}

/* A batch went out; the GPU's counters of it once it finished. */
static inline void frame_stats_add_batch(struct frame_stats *st, uint32_t prims)
{
    st->batches++;
    st->prims += prims;
}

static inline void frame_stats_add_gpu(struct frame_stats *st, const struct gpu_stats *gpu)
{
    st->drawn += gpu->tris_drawn;
    st->busy_cycles += gpu->busy_cycles;
    st->errors |= gpu->errors;
}

/* A pass's pipeline statistics (the frame's primitive list's), added to the frame's. */
static inline void frame_stats_add_pass(struct frame_stats *st, const struct render_stats *pass)
{
    st->render.faces_in += pass->faces_in;
    st->render.faces_culled_object += pass->faces_culled_object;
    st->render.faces_frustum += pass->faces_frustum;
    st->render.faces_back += pass->faces_back;
    st->render.faces_clipped += pass->faces_clipped;
    st->render.dropped += pass->dropped;
}

static void frame_stats_end(struct frame_stats *st)
{
    const uint64_t t_end = bsp_instret();
    const uint64_t c_end = bsp_cycles();

    st->instr = (t_end - st->t_start) - st->wait_instr;
    st->cycles = (c_end - st->c_start) - st->wait_cycles;
}

/* The frame's line (app.c's header), and with FW_PROFILE its instructions per stage. */
static void frame_stats_print(unsigned frame, const struct frame_stats *st)
{
    printf("frame %u: tris submitted %lu drawn %lu | fw instr %lu | gpu cycles %lu | errors "
           "0x%lx | prims %lu batches %lu | culled object %lu frustum %lu back %lu | clipped "
           "%lu | cpu cycles %lu\n",
           frame, (unsigned long)st->render.faces_in, (unsigned long)st->drawn,
           (unsigned long)st->instr, (unsigned long)st->busy_cycles, (unsigned long)st->errors,
           (unsigned long)st->prims, (unsigned long)st->batches,
           (unsigned long)st->render.faces_culled_object,
           (unsigned long)st->render.faces_frustum, (unsigned long)st->render.faces_back,
           (unsigned long)st->render.faces_clipped, (unsigned long)st->cycles);
    if (FW_PROFILE) {
        printf("profile %u: update %lu draw %lu sort %lu batch %lu submit %lu\n", frame,
               (unsigned long)st->t_update, (unsigned long)st->t_draw, (unsigned long)st->t_sort,
               (unsigned long)st->t_batch, (unsigned long)st->t_submit);
    }
}

static struct app app_state;

static void app_fail(int status) __attribute__((noreturn));
static void app_fail(int status)
{
    fflush(stdout);
    exit(status);
}

static const char *const app_key_map =
    "keys: W/S forward/back, A/D left/right, space/C up/down (fly: move the eye;\n"
    "        orbit/object: W/S zoom, A/D and space/C move the target)\n"
    "      I/K look up/down, J/L look left/right (arrow keys too); object mode: turn the scene,\n"
    "        U/O roll\n"
    "      M camera mode (fly -> orbit -> object), F wireframe, G anaglyph stereo (red/cyan),\n"
    "        Z depth buffer (if the GPU has one), T animation on/off, R reset view\n";

static void app_print_keys(const struct scene *s)
{
    fputs(app_key_map, stdout);
    /* "1-5 scene (tetra, cubes, landscape, voxel, knot)": the names of the scenes this program is
     * built with (all of the table's, or one: "1 scene (tetra; the only one built in)"). */
    if (scene_count() == 1u) {
        printf("      1 scene (%s: the only one built in)", scene_at(0)->name);
    } else {
        printf("      1-%u scene (", (unsigned)scene_count());
        for (uint32_t k = 0; k < scene_count(); k++) {
            printf("%s%s", (k == 0u) ? "" : ", ", scene_at(k)->name);
        }
        fputs(")", stdout);
    }
    fputs(", H this help, Q quit\n", stdout);
    if (s->desc->keys != 0) {
        printf("      %s: %s\n", s->desc->name, s->desc->keys);
    }
}

#if FW_WITH_STRIPS
#define APP_STRIPS_EXPECTED "0 or a power of two up to the height"
#else
#define APP_STRIPS_EXPECTED "0 (built without FW_WITH_STRIPS)"
#endif

static void app_report_init_error(int rc, const struct gpu_info *info)
{
    switch (rc) {
    case GPU_E_NOT_FOUND:
        printf("error: GPU not found (ID=0x%08lx, expected 0x%08lx at 0x%08lx)\n",
               (unsigned long)info->id, (unsigned long)GPU_ID_VALUE,
               (unsigned long)BSP_GPU_BASE);
        break;
    case GPU_E_VERSION:
        printf("error: unsupported GPU contract version (VERSION=0x%08lx, firmware built for "
               "0x%08lx)\n",
               (unsigned long)info->version, (unsigned long)GPU_VERSION_VALUE);
        break;
    case GPU_E_GEOMETRY:
        printf("error: unexpected frame (FB_SIZE=0x%08lx STRIP_ROWS=%lu; expected 1x1 .. %lux%lu, "
               "strips " APP_STRIPS_EXPECTED ")\n",
               (unsigned long)info->fb_size, (unsigned long)info->strip_rows,
               (unsigned long)GPU_FB_MAX_WIDTH, (unsigned long)GPU_FB_MAX_HEIGHT);
        break;
    case GPU_E_BUFFERS:
        printf("error: GPU buffer capacities out of range (VTX_CAP=%lu, TRI_CAP=%lu; expected "
               "3..%lu and 1..%lu)\n",
               (unsigned long)info->vtx_cap, (unsigned long)info->tri_cap,
               (unsigned long)GPU_VTX_CAP_MAX, (unsigned long)GPU_TRI_CAP_MAX);
        break;
    default:
        printf("error: GPU init failed: %s (%d)\n", gpu_strerror(rc), rc);
        break;
    }
}

static void app_report_gpu_errors(unsigned frame, uint32_t errors)
{
    printf("error: GPU reported ERRORS=0x%lx in frame %u:%s%s%s%s%s\n", (unsigned long)errors,
           frame, (errors & GPU_ERR_VTX_INDEX_MASK) ? " VTX_INDEX" : "",
           (errors & GPU_ERR_COUNT_MASK) ? " COUNT" : "",
           (errors & GPU_ERR_KIND_MASK) ? " KIND" : "",
           (errors & GPU_ERR_WRITE_BUSY_MASK) ? " WRITE_BUSY" : "",
           (errors & GPU_ERR_STRIP_MASK) ? " STRIP" : "");
}

static void app_report_lines(const struct app *app)
{
    if (gpu_caps_lines(app->gpu.info.caps)) {
        printf("wireframe: GPU line primitives\n");
    } else if (FW_WITH_LINE_EMULATION) {
        printf("wireframe: the GPU has no lines (CAPS_LINES = 0): edges drawn as 1-pixel-wide "
               "triangle pairs\n");
    } else {
        printf("wireframe: the GPU has no lines (CAPS_LINES = 0) and this build no line "
               "emulation (FW_WITH_LINE_EMULATION=0): F stays off\n");
    }
}

/* What the global keys changed, printed after the frame so printing stays out of the count. */
struct app_notes {
    bool help;
    bool scene_changed;
    const char *msg[3];  /* one per toggle (wireframe, anaglyph, depth): all of a frame's shown */
    uint32_t msg_count;
};

/* FB_WRITE_MASK before the frame loop has written it: no value the register can hold. */
#define APP_WRITE_MASK_UNKNOWN 0xFFFFFFFFu

/* A GPU with a strip buffer (contract "The strip buffer"): it draws each strip once a frame, so
 * the anaglyph's second pass cannot go over the first's strips. */
static bool app_gpu_strips(const struct app *app)
{
    return app->gpu.info.strip_rows != 0u;
}

/* The anaglyph through the write mask: built in, and the GPU has the mask. */
static bool app_eye_planes(const struct app *app)
{
    return FW_WITH_ANAGLYPH && gpu_caps_wmask(app->gpu.info.caps);
}

static void app_settle(struct app *app, struct frame_stats *now);

/* The palette for the view the anaglyph toggle just chose: the anaglyph's two planes
 * (palette_build_anaglyph) or the materials, once the last frame's batch is done (st: the frame
 * being counted). */
static void app_anaglyph_palette(struct app *app, struct frame_stats *st)
{
    int rc;

    if (!app_eye_planes(app)) {
        return;  /* without the mask the eyes use the material palette's red and cyan ramps */
    }
    app_settle(app, st);
    if (app->anaglyph) {
        palette_build_anaglyph(app->palette);
    } else {
        palette_build(app->palette);
    }
    rc = gpu_load_palette(&app->gpu, app->palette, PAL_ENTRIES);
    if (rc != GPU_OK) {
        printf("error: palette not loaded: %s\n", gpu_strerror(rc));
        app_fail(FW_EXIT_GPU_SUBMIT);
    }
}

/* The planes a pass writes: the left eye's (-1) the high one, the right eye's (+1) the low one,
 * a normal pass's (0) both; written only when it changes, on a GPU with the mask. */
static void app_set_write_mask(struct app *app, int eye)
{
    uint32_t planes = GPU_WMASK_LO_MASK | GPU_WMASK_HI_MASK;
    int rc;

    if (!app_eye_planes(app)) {
        return;
    }
    if (eye != 0) {
        planes = (eye < 0) ? GPU_WMASK_HI_MASK : GPU_WMASK_LO_MASK;
    }
    if (planes == app->write_mask) {
        return;
    }
    rc = gpu_set_write_mask(&app->gpu, planes);
    if (rc != GPU_OK) {
        printf("error: FB_WRITE_MASK not set: %s\n", gpu_strerror(rc));
        app_fail(FW_EXIT_GPU_SUBMIT);
    }
    app->write_mask = planes;
}

static void app_note(struct app_notes *notes, const char *msg)
{
    if (notes->msg_count < sizeof notes->msg / sizeof notes->msg[0]) {
        notes->msg[notes->msg_count++] = msg;
    }
}

/* Start a scene, or stop: a scene this program's storage cannot hold is a build error. */
static void app_start_scene(struct app *app, const struct scene_desc *desc)
{
    if (!scene_start(&app->scene, desc)) {
        printf("error: scene %s does not fit this build (state %lu of %lu bytes, objects %lu of "
               "%lu, %lu refused)\n",
               desc->name, (unsigned long)desc->state_bytes, (unsigned long)app->scene.state_cap,
               (unsigned long)desc->max_objects, (unsigned long)app->scene.object_cap,
               (unsigned long)app->scene.objects_refused);
        app_fail(FW_EXIT_CONFIG);
    }
}

/* ---- what the build leaves out: every #if of the loop ---------------------------------------- *
 * Each feature gives the stages the same functions; where it is not built they are empty (or the
 * plain alternative) and compile to nothing. */

#if FW_WITH_UPLOAD
/* The upload's staging buffer: one mesh file of the model scene's capacity, and its chunk map. */
#define APP_UPLOAD_BYTES MESHFILE_BYTES(FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES)
static uint8_t app_upload_file[APP_UPLOAD_BYTES];
static uint8_t app_upload_map[UPLOAD_MAP_BYTES(APP_UPLOAD_BYTES)];
#define APP_UART_BYTES_PER_FRAME FW_UART_BYTES_PER_FRAME
/* UART bytes drained while the GPU works (app_drain_uart), read at the next frame's start: a
 * UART's own FIFO may hold only 16 (QEMU's 16550), far less than a frame's worth of upload. */
static struct {
    uint8_t byte[FW_UART_BYTES_PER_FRAME];
    uint32_t head;   /* next to read */
    uint32_t count;
} app_uart_ring;

/* gpu_wait_idle's work: move what the UART holds into the ring, until the ring is full (the rest
 * waits in the UART). */
static void app_drain_uart(void *unused)
{
    (void)unused;
    while (app_uart_ring.count < FW_UART_BYTES_PER_FRAME) {
        const int c = bsp_uart_getc_nonblock();

        if (c < 0) {
            break;
        }
        app_uart_ring.byte[(app_uart_ring.head + app_uart_ring.count) % FW_UART_BYTES_PER_FRAME] =
            (uint8_t)c;
        app_uart_ring.count++;
    }
}

/* The next UART byte: the ring's first, then the UART's; -1 when neither has one. */
static int app_uart_getc(void)
{
    if (app_uart_ring.count != 0u) {
        const uint8_t c = app_uart_ring.byte[app_uart_ring.head];

        app_uart_ring.head = (app_uart_ring.head + 1u) % FW_UART_BYTES_PER_FRAME;
        app_uart_ring.count--;
        return c;
    }
    return bsp_uart_getc_nonblock();
}

/* A UART byte the upload's receiver takes (true), or a key (false). */
static inline bool app_upload_feed(struct app *app, uint8_t c)
{
    return upload_feed(&app->upload, c);
}

/* The frame's bytes are read: the receiver's timeouts; a new transfer filling the staging buffer
 * makes the model scene's key restart the scene from the built-in model instead (the running
 * scene keeps its own copy). */
static void app_upload_frame_end(struct app *app)
{
    upload_frame_end(&app->upload);
    if (app->model_from_upload && !app->upload.staging_valid) {
        model_scene_source(0, 0);
        app->model_from_upload = false;
    }
}

/* This frame's upload responses, one line each, at once, before the frame is drawn: the sender's
 * next frames then arrive during this frame's GPU wait. Printing is not counted. */
static void app_print_upload(struct app *app, struct frame_stats *st)
{
    const struct frame_span span = frame_span_begin();
    char line[112];

    for (uint32_t i = 0; i < app->upload.resp_count; i++) {
        upload_response_line(&app->upload, i, line, sizeof line);
        puts(line);
    }
    upload_responses_clear(&app->upload);
    frame_stats_exclude(st, span);
}

/* A model committed in the last frame: the model scene starts from it, at this frame boundary. */
static void app_swap_upload(struct app *app, struct app_notes *notes)
{
    const struct scene_desc *model = scene_find("model");

    if (!upload_ready(&app->upload) || model == 0) {
        return;
    }
    model_scene_source(app->upload.buf, app->upload.total);
    app->model_from_upload = true;
    app_start_scene(app, model);
    upload_taken(&app->upload);
    notes->scene_changed = true;
}

static void app_upload_init(struct app *app)
{
    upload_init(&app->upload, app_upload_file, sizeof app_upload_file, app_upload_map,
                sizeof app_upload_map, FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES);
}

/* The batch's wait (the watchdog), draining the UART meanwhile. */
static inline int app_wait_batch(struct app *app, uint32_t tag)
{
    return gpu_wait_idle(&app->gpu, tag, FW_GPU_MAX_POLLS, app_drain_uart, 0);
}
#else
#define APP_UART_BYTES_PER_FRAME INPUT_MAX_BYTES_PER_FRAME
#define app_uart_getc bsp_uart_getc_nonblock
static inline bool app_upload_feed(struct app *app, uint8_t c)
{
    (void)app;
    (void)c;
    return false;
}
static inline void app_upload_frame_end(struct app *app)
{
    (void)app;
}
static inline void app_print_upload(struct app *app, struct frame_stats *st)
{
    (void)app;
    (void)st;
}
static inline void app_swap_upload(struct app *app, struct app_notes *notes)
{
    (void)app;
    (void)notes;
}
static inline void app_upload_init(struct app *app)
{
    (void)app;
}
static inline int app_wait_batch(struct app *app, uint32_t tag)
{
    return gpu_wait(&app->gpu, tag, FW_GPU_MAX_POLLS);
}
#endif

#if FW_USB_KEYBOARD
static void app_usb_init(struct app *app)
{
    usb_keys_init(&app->usb, FW_USB_KEY_REPEAT_DELAY, FW_USB_KEY_REPEAT_PERIOD);
    app->usb_state = BSP_USB_DETACHED;  /* as the port starts: a line once something happens */
}

/* This frame's USB key events, never waiting, into the counts the UART's keys are in: a held
 * key's repeat first (FW_USB_KEY_REPEAT_DELAY), then at most FW_USB_EVENTS_PER_FRAME events. */
static void app_read_usb(struct app *app, struct input_counts *keys)
{
    if (FW_USB_KEY_REPEAT_DELAY != 0u) {
        usb_keys_frame(&app->usb, keys);
    }
    for (uint32_t i = 0; i < FW_USB_EVENTS_PER_FRAME; i++) {
        const int ev = bsp_usb_key_nonblock();

        if (ev < 0) {
            break;
        }
        usb_keys_event(&app->usb, keys, (uint8_t)((uint32_t)ev & BSP_USB_KEY_USAGE_MASK),
                       ((uint32_t)ev & BSP_USB_KEY_PRESS) != 0u);
    }
}

/* What a change of the USB port's state means to someone at the keyboard; 0: nothing worth a line
 * (the steps between plugged in and ready, which take about 140 ms). */
static const char *app_usb_state_line(int state)
{
    switch (state) {
    case BSP_USB_DETACHED:
        return "usb: keyboard unplugged";
    case BSP_USB_ATTACHED:
        return "usb: device plugged in";
    case BSP_USB_RUNNING:
        return "usb: keyboard ready";
    case BSP_USB_NOT_KEYBOARD:
        return "usb: error: the device is not a boot keyboard (unplug it)";
    case BSP_USB_BABBLE:
        return "usb: error: the device babbled; the port is off until it is unplugged";
    default:
        return 0;
    }
}

/* A line when the USB port's state changed since the last frame (none on a platform without a
 * USB host). Reading the state is counted, printing is not. */
static void app_print_usb(struct app *app, struct frame_stats *st)
{
    const int state = bsp_usb_state();
    const char *line;

    if (state == app->usb_state || state < 0) {
        return;
    }
    app->usb_state = state;
    line = app_usb_state_line(state);
    if (line != 0) {
        const struct frame_span span = frame_span_begin();

        puts(line);
        frame_stats_exclude(st, span);
    }
}
#else
static inline void app_usb_init(struct app *app)
{
    (void)app;
}
static inline void app_read_usb(struct app *app, struct input_counts *keys)
{
    (void)app;
    (void)keys;
}
static inline void app_print_usb(struct app *app, struct frame_stats *st)
{
    (void)app;
    (void)st;
}
#endif

/* Where batches are built: in the GPU's own buffers where the platform maps them, else staged. */
static void app_attach_mapped_words(struct app *app)
{
    app->words.vtx = gpu_buffer_words(GPU_WIN_VTX);
    app->words.prim = gpu_buffer_words(GPU_WIN_IDX);
    app->words.vtx_room = GPU_VTX_CAP_MAX;  /* the windows: a batch takes what the GPU holds */
    app->words.prim_room = GPU_TRI_CAP_MAX;
}

#if BSP_GPU_BUFFERS_MAPPED
static void app_attach_words(struct app *app)
{
    app_attach_mapped_words(app);
}

/* After the boot banner: a platform that promised mapped buffers must have them. */
static void app_check_words(const struct app *app)
{
    if (app->words.vtx == NULL || app->words.prim == NULL) {
        printf("error: the platform says its GPU buffers are mapped (BSP_GPU_BUFFERS_MAPPED) but "
               "bsp_gpu_buffer returned NULL\n");
        app_fail(FW_EXIT_CONFIG);
    }
}
#else
/* Batch staging, for platforms whose GPU buffers are not CPU memory (bsp_gpu_buffer NULL); where
 * they are (BSP_GPU_BUFFERS_MAPPED), batches are built in place and these 12 KiB are not needed. */
static uint32_t app_vtx_staging[GPU_VTX_CAP * GPU_VTX_WORDS];
static uint32_t app_prim_staging[GPU_TRI_CAP * GPU_PRIM_WORDS];

static void app_attach_words(struct app *app)
{
    static const struct batch_words staged = BATCH_WORDS_ON(app_vtx_staging, app_prim_staging);

    app_attach_mapped_words(app);
    if (app->words.vtx == NULL || app->words.prim == NULL) {
        app->words = staged;  /* the contract's default capacities: larger GPUs get batches of that size */
    }
}

static inline void app_check_words(const struct app *app)
{
    (void)app;
}
#endif

/* The host build's hooks (bsp/host/bsp_platform.h): the scene of every frame for the exact
 * reference (--dump-scene), and a model file given on the command line (--model). */
#if BSP_HOST_SCENE_DUMP
static inline void app_scene_dump(const struct app *app, unsigned frame)
{
    bsp_host_scene_dump(&app->scene, app->palette, frame);
}
#else
static inline void app_scene_dump(const struct app *app, unsigned frame)
{
    (void)app;
    (void)frame;
}
#endif
#if BSP_HOST_BOOT_MODEL && FW_MODEL_SCENE_BUILT
/* The model scene starts from it, as if it had been uploaded before the first frame. */
static void app_boot_model(void)
{
    const uint8_t *file;
    const uint32_t bytes = bsp_host_boot_model(&file);

    if (file != NULL) {
        model_scene_source(file, bytes);
    }
}
#elif BSP_HOST_BOOT_MODEL
static void app_boot_model(void)
{
    const uint8_t *file;

    (void)bsp_host_boot_model(&file);
    if (file != NULL) {
        printf("error: a model file was given, but the model scene is not built in\n");
        app_fail(FW_EXIT_CONFIG);
    }
}
#else
static inline void app_boot_model(void)
{
}
#endif

/* The measurement's seeded camera path (cam_path.h, FW_CAMERA_PATH): it is not the firmware's
 * work, so its instructions are not counted. */
#if FW_CAMERA_PATH
static void app_path_start(struct app *app)
{
    cam_path_start(&app->scene);
}

static void app_path_apply(struct app *app, unsigned frame, struct frame_stats *st)
{
    const struct frame_span span = frame_span_begin();

    cam_path_apply(&app->scene, frame);
    frame_stats_exclude(st, span);
}
#else
static inline void app_path_start(struct app *app)
{
    (void)app;
}

static inline void app_path_apply(struct app *app, unsigned frame, struct frame_stats *st)
{
    (void)app;
    (void)frame;
    (void)st;
}
#endif

/* ---- the stages --------------------------------------------------------------------------- */

/* Read this frame's UART bytes, never waiting: the upload's frames to its receiver, the rest
 * decoded into keys. */
static void app_read_uart(struct app *app, struct input_counts *keys)
{
    input_counts_clear(keys);
    for (uint32_t i = 0; i < APP_UART_BYTES_PER_FRAME; i++) {
        const int c = app_uart_getc();

        if (c < 0) {
            break;
        }
        if (app_upload_feed(app, (uint8_t)c)) {
            continue;
        }
        input_counts_add(keys, input_decode(&app->decoder, (uint8_t)c));
    }
    app_upload_frame_end(app);
}

/*
 * The next frame's input: the UART's bytes (the upload's frames, then keys) and the USB keyboard's
 * events, read before this frame's first batch goes out. With the frame's last batch left pending
 * (app_send_group) the next frame starts right after its doorbell; keys read then would be those
 * that happened to arrive by then. Read here, whatever is typed at any of a frame's doorbells —
 * where a co-simulation or a test types them — reaches the frame after next, on every platform
 * however long the bytes take on the wire.
 */
static void app_collect_input(struct app *app)
{
    app_read_uart(app, &app->keys_next);
    app_read_usb(app, &app->keys_next);
    app->keys_collected = true;
}

/* Keys that belong to the loop rather than the scene. Returns false to quit. */
static bool app_global_keys(struct app *app, const struct input_counts *keys,
                            struct app_notes *notes, struct frame_stats *st)
{
    notes->help = keys->n[KEY_HELP] != 0u;
    notes->msg_count = 0;
    if (keys->n[KEY_QUIT] != 0u) {
        return false;
    }
    for (uint32_t k = 0; k < scene_count(); k++) {
        if (keys->n[KEY_SCENE_1 + k] != 0u) {
            app_start_scene(app, scene_at(k));
            notes->scene_changed = true;
        }
    }
    if (input_toggled(keys, KEY_WIREFRAME)) {
        if (FW_WITH_WIREFRAME && !FW_WITH_LINE_EMULATION &&
            !gpu_caps_lines(app->gpu.info.caps)) {
            /* Its frame is sized for GPU lines only: emulated edges would not fit it. */
            app_note(notes, "wireframe: the GPU has no lines and line emulation is not built in "
                            "(FW_WITH_LINE_EMULATION=0)");
        } else if (FW_WITH_WIREFRAME) {
            app->wireframe = !app->wireframe;
            app_note(notes, app->wireframe ? "wireframe on" : "wireframe off");
        } else {
            app_note(notes, "wireframe: not built in (FW_WITH_WIREFRAME=0)");
        }
    }
    if (input_toggled(keys, KEY_ANAGLYPH)) {
        if (FW_WITH_ANAGLYPH && FW_WITH_STRIPS && app_gpu_strips(app)) {
            app_note(notes, "anaglyph: not on a GPU that draws in strips (STRIP_ROWS > 0): its two "
                            "passes would draw each strip twice");
        } else if (FW_WITH_ANAGLYPH) {
            app->anaglyph = !app->anaglyph;
            app_anaglyph_palette(app, st);
            app_note(notes, app->anaglyph ? "anaglyph on (left eye red, right eye cyan)"
                                          : "anaglyph off");
        } else {
            app_note(notes, "anaglyph: not built in (FW_WITH_ANAGLYPH=0)");
        }
    }
    if (input_toggled(keys, KEY_DEPTH)) {
        if (!FW_WITH_DEPTH) {
            app_note(notes, "depth buffer: not built in (FW_WITH_DEPTH=0)");
        } else if (gpu_caps_zbuf(app->gpu.info.caps)) {
            app->depth_test = !app->depth_test;
            app_note(notes, app->depth_test ? "depth buffer on" : "depth buffer off");
        } else {
            app_note(notes, "depth buffer: the GPU has none (CAPS_ZBUF = 0)");
        }
    }
    return true;
}

/* A batch's CTRL: the first of a group (the pass, or a strip of it) clears the colour when
 * `clear` and, with the depth test on, the depth; the frame's last swaps. */
static uint32_t app_batch_ctrl(const struct app *app, bool first, bool clear, bool last)
{
    uint32_t ctrl = ((first && clear) ? GPU_CTRL_CLEAR_MASK : 0u) |
                    (last ? GPU_CTRL_SWAP_MASK : 0u);

    if (app->depth_test) {
        ctrl |= GPU_CTRL_ZTEST_MASK | (first ? GPU_CTRL_ZCLEAR_MASK : 0u);
    }
    if (FW_WITH_GOURAUD && FW_GOURAUD && FW_DITHER && gpu_caps_gouraud(app->gpu.info.caps)) {
        ctrl |= GPU_CTRL_DITHER_MASK;  /* acts on Gouraud triangles only */
    }
    return ctrl;
}

/* What a group of batches sends: the pass's primitives in draw order, or a strip's list
 * (render/strips.h). */
enum app_group { APP_GROUP_PASS, APP_GROUP_LIST };

/* The GPU did not finish a batch: reset it (the frame is abandoned). */
static void app_watchdog_fired(struct app *app, unsigned frame_no, uint32_t batch, uint32_t tag)
{
    printf("watchdog: frame %u batch %lu: GPU did not finish (DONE_SEQ=0x%08lx, expected "
           "tag 0x%08lx after %lu polls): resetting it, dropping the frame\n",
           frame_no, (unsigned long)batch, (unsigned long)app->gpu.last_done_seq,
           (unsigned long)tag, (unsigned long)FW_GPU_MAX_POLLS);
    gpu_reset(&app->gpu);
}

/*
 * Send a group of batches: the primitives of the cursor (`what`: the pass's draw order, or a
 * strip's list), drawing rows `strip`; its first batch clears (app_batch_ctrl), and when `final`
 * (the frame's last group) its last batch swaps. `walk` (0 or GPU_CTRL_WALK_MASK) goes into every
 * batch's CTRL. The frame's last batch is not waited for: it is left pending (the driver's gpu.pending), and
 * the CPU goes on with the next frame while the GPU draws and waits for vertical blank
 * (app_settle). Returns false when the watchdog fired (the GPU has been reset and the frame is
 * abandoned). Inlined into each caller, so that each keeps its own path (`what` a constant): out
 * of line, with the strips' caller beside the whole frame's, it cost the whole frame 153
 * instructions (tetra, make bench-strips).
 */
static inline __attribute__((always_inline)) bool
app_send_group(struct app *app, unsigned frame_no, struct batch_cursor *cur, enum app_group what,
               bool clear, bool final, uint32_t strip, uint32_t walk, uint8_t clear_color,
               struct frame_stats *tot)
{
    bool first = true;
    bool done;

    do {
        struct gpu_batch batch;
        struct gpu_stats stats;
        uint32_t tag;
        struct frame_span wait;
        uint64_t t0;
        uint64_t t1;
        int rc;

        t0 = frame_stats_mark();
        if (what == APP_GROUP_LIST) {
            batch_fill_list(cur, &app->frame, app->gpu.info.vtx_cap, app->gpu.info.tri_cap,
                            &app->words);
            done = batch_list_done(cur);
        } else {
            batch_fill(cur, &app->frame, app->gpu.info.vtx_cap, app->gpu.info.tri_cap,
                       &app->words);
            done = batch_done(cur, &app->frame);
        }
        t1 = frame_stats_batch_filled(tot, t0);
        batch = batch_descriptor(&app->words,
                                 app_batch_ctrl(app, first, clear, final && done) | walk,
                                 clear_color);
        batch.strip = strip;
        rc = gpu_submit_batch(&app->gpu, &batch, &tag);
        if (rc != GPU_OK) {
            printf("error: frame %u: batch not submitted: %s\n", frame_no, gpu_strerror(rc));
            app_fail(FW_EXIT_GPU_SUBMIT);
        }
        frame_stats_add_batch(tot, batch.prim_count);
        if (final && done) {
            frame_stats_submitted(tot, t1);
            return true;  /* left pending (the driver's gpu.pending) */
        }

        wait = frame_stats_wait_begin(tot, t1);
        rc = app_wait_batch(app, tag);
        t0 = frame_stats_wait_end(tot, wait);
        if (rc != GPU_OK) {
            app_watchdog_fired(app, frame_no, tot->batches, tag);
            return false;
        }
        gpu_read_stats(&app->gpu, &stats);
        frame_stats_submitted(tot, t0);
        frame_stats_add_gpu(tot, &stats);
        first = false;
    } while (!done);
    return true;
}

/*
 * The frame left pending (app_send_group), finished: its last batch waited for, its GPU counters
 * added, its statistics printed (app_statistics). Called before anything the GPU must not be busy
 * for (buffers, batch registers, the palette) and at the end; the wait and the printing are left
 * out of the frame `now`'s counts (NULL: none is being counted).
 */
static void app_statistics(struct app *app, unsigned frame, bool completed,
                           const struct frame_stats *st);

static void app_settle(struct app *app, struct frame_stats *now)
{
    struct frame_span span;
    struct gpu_stats stats;
    bool completed = true;

    if (!app->gpu.pending) {
        return;
    }
    span = frame_span_begin();
    if (app_wait_batch(app, app->gpu.pending_tag) != GPU_OK) {
        app_watchdog_fired(app, app->pending_frame, app->pending_st.batches, app->gpu.pending_tag);
        completed = false;
    } else {
        gpu_read_stats(&app->gpu, &stats);
        frame_stats_add_gpu(&app->pending_st, &stats);
    }
    app_statistics(app, app->pending_frame, completed, &app->pending_st);
    if (now != NULL) {
        frame_stats_exclude(now, span);
    }
}

#if FW_WITH_STRIPS
/*
 * The pass in strips of app->strip_rows lines. On a GPU with a strip buffer, a pass that fits one
 * batch (FW_STRIP_WALK) is sent once, with CTRL.WALK: the GPU draws it for the first strip and
 * then for every other, fetching all its primitives each time and drawing what reaches the strip
 * (the GPU's binning: no work of the firmware's). Otherwise each strip's batches carry the
 * primitives that reach it, in draw order, and draw its rows only (the firmware's binning). On a
 * GPU that draws into its frame, a strip no primitive reaches is cleared with the next one that is
 * drawn (their rows as one band: the band's primitives reach none of the empty strip's rows), and
 * after the last strip drawn the rows left are cleared by one more batch where the pass clears. A
 * GPU with a strip buffer is sent every strip, each with its own rows, its first batch clearing it
 * (the contract's rules for opening a strip). The frame's last batch swaps.
 */
static bool app_submit_strips(struct app *app, unsigned frame_no, bool clear, bool last_pass,
                              uint8_t clear_color, struct frame_stats *tot)
{
    struct strip_bins *b = &app->strips;
    const bool every_strip = app_gpu_strips(app);
    uint32_t band_first = 0;  /* the first row not yet drawn or cleared */
    struct batch_cursor cur;

    if (FW_STRIP_WALK && every_strip &&
        batch_whole_fits(&app->frame, app->gpu.info.vtx_cap, app->gpu.info.tri_cap, &app->words)) {
        batch_begin(&cur);
        return app_send_group(app, frame_no, &cur, APP_GROUP_PASS, clear, last_pass,
                              gpu_strip(0, app->strip_rows - 1u), GPU_CTRL_WALK_MASK, clear_color,
                              tot);
    }
    strips_bin(b, &app->frame, app->strip_rows, gpu_fb_height(&app->gpu.info));
    for (uint32_t s = 0; s < b->count; s++) {
        const uint32_t pos = strips_take(b, &app->frame, s);
        const bool final = last_pass && s + 1u == b->count;

        if (pos == RENDER_NO_POSITION && s + 1u < b->count && !every_strip) {
            continue;
        }
        if (pos == RENDER_NO_POSITION && !clear && !final) {
            break;  /* the rows left: nothing to draw or clear */
        }
        batch_begin_list(&cur, pos);
        if (!app_send_group(app, frame_no, &cur, APP_GROUP_LIST, clear, final,
                            gpu_strip(band_first, strips_last_row(b, s)), 0, clear_color, tot)) {
            return false;
        }
        band_first = strips_last_row(b, s) + 1u;
    }
    return true;
}
#endif

/*
 * Stream the pass's primitives to the GPU: its first batch clears the colour when `clear` and
 * (depth test on) the depth buffer always, the pass's own; in strips where the GPU draws in
 * strips (STRIP_ROWS) or the build says so (FW_STRIP_ROWS). Returns false when the watchdog fired (the GPU has been reset and the frame is
 * abandoned).
 */
static bool app_submit(struct app *app, unsigned frame_no, bool clear, bool last_pass,
                       struct frame_stats *tot)
{
    const uint8_t clear_color = !app->anaglyph ? PAL_SKY
                                : (app_eye_planes(app) ? PAL_ANAGLYPH_BACKGROUND : PAL_NIGHT);
    struct batch_cursor cur;

#if FW_WITH_STRIPS
    if (app->strip_rows != 0u) {
        return app_submit_strips(app, frame_no, clear, last_pass, clear_color, tot);
    }
#endif
    batch_begin(&cur);
    return app_send_group(app, frame_no, &cur, APP_GROUP_PASS, clear, last_pass, GPU_STRIP_WHOLE, 0,
                          clear_color, tot);
}

/* One pass (pipeline.h): the scene seen from one eye, sorted, then the overlay. */
static void app_render_pass(struct app *app, int eye, struct frame_stats *tot)
{
    struct pipeline_opts opts;
    struct pipeline_times times = frame_stats_pass_times(tot);

    opts.wireframe = app->wireframe;
    opts.depth_test = app->depth_test;
    opts.gpu_lines = gpu_caps_lines(app->gpu.info.caps);
    opts.eye_planes = app_eye_planes(app);
    opts.gouraud = FW_WITH_GOURAUD && FW_GOURAUD && gpu_caps_gouraud(app->gpu.info.caps);
    pipeline_pass(&app->frame, &app->scene, &opts, eye, frame_stats_mark, &times);
    frame_stats_set_pass_times(tot, &times);
}

/* The running scene's line; the model scene's says where its model came from, or why it has
 * none. */
static void app_print_scene(const struct app *app)
{
    const struct scene *s = &app->scene;

    printf("scene %s: %lu triangles, camera %s\n", s->desc->name,
           (unsigned long)scene_triangle_count(s), cam_mode_name(s->cam.mode));
#if FW_MODEL_SCENE_BUILT
    if (s->desc == &scene_model_desc) {
        struct meshfile_info info;
        const int rc = model_scene_status(s, &info);

        if (rc == MESHFILE_OK) {
            printf("model: %lu faces, %lu vertices, %s\n", (unsigned long)info.faces,
                   (unsigned long)info.verts, model_scene_uploaded(s) ? "uploaded" : "built in");
        } else {
            char why[80];

            meshfile_message(rc, &info, why, sizeof why);
            printf("error: model: %s model refused: %s\n",
                   model_scene_uploaded(s) ? "the uploaded" : "the built-in", why);
        }
    }
#endif
}

/* What the scene reported (the voxel scene's edits), prefixed with its name. */
static void app_print_event(const struct scene *s, const struct scene_event *ev)
{
    const char *name = s->desc->name;
    const char *block = (ev->block_name != NULL) ? ev->block_name : "?";

    switch (ev->kind) {
    case SCENE_EVENT_BROKE:
        printf("%s: broke block (%ld, %ld, %ld)\n", name, (long)ev->x, (long)ev->y, (long)ev->z);
        break;
    case SCENE_EVENT_PLACED:
        printf("%s: placed %s at (%ld, %ld, %ld)\n", name, block, (long)ev->x, (long)ev->y,
               (long)ev->z);
        break;
    case SCENE_EVENT_NO_TARGET:
        printf("%s: nothing under the crosshair within reach\n", name);
        break;
    case SCENE_EVENT_BLOCK_TYPE:
        printf("%s: placing %s\n", name, block);
        break;
    case SCENE_EVENT_MESH_FULL:
        printf("error: %s: mesh storage full (%ld faces, %ld vertices): %ld chunk(s) not drawn "
               "until edits make room\n", name, (long)ev->y, (long)ev->z, (long)ev->x);
        break;
    default:
        break;
    }
}

/* What the frame's keys changed and what the scene reported, printed after the frame so printing
 * stays out of the count. */
static void app_print_notes(const struct app *app, const struct app_notes *notes,
                            enum cam_mode mode_before, const struct scene_event *ev)
{
    if (notes->scene_changed) {
        app_print_scene(app);
    }
    for (uint32_t m = 0; m < notes->msg_count; m++) {
        printf("%s\n", notes->msg[m]);
    }
    if (app->scene.cam.mode != mode_before && !notes->scene_changed) {
        printf("camera: %s\n", cam_mode_name(app->scene.cam.mode));
    }
    app_print_event(&app->scene, ev);
    if (notes->help) {
        app_print_keys(&app->scene);
    }
}

/* Boot: the platform, the GPU (or stop with its error), the batch buffers, the boot scene. */
static void app_boot(struct app *app)
{
    const struct scene_desc *desc;
    int rc;

    bsp_init();
    scene_set_attach(&app->scene, &app->frame);
    palette_build(app->palette);
    rc = gpu_init(&app->gpu, app->palette, PAL_ENTRIES);
    app_attach_words(app);
    printf("%s fw (%s, %s): GPU id 0x%08lx version 0x%08lx caps 0x%08lx vtx_cap %lu tri_cap %lu "
           "fb %lux%lu | frames %u\n",
           FW_SCENE, BSP_NAME, REAL_BACKEND_NAME, (unsigned long)app->gpu.info.id,
           (unsigned long)app->gpu.info.version, (unsigned long)app->gpu.info.caps,
           (unsigned long)app->gpu.info.vtx_cap, (unsigned long)app->gpu.info.tri_cap,
           (unsigned long)gpu_fb_width(&app->gpu.info),
           (unsigned long)gpu_fb_height(&app->gpu.info), (unsigned)FW_FRAMES);
    if (rc != GPU_OK) {
        app_report_init_error(rc, &app->gpu.info);
        app_fail(FW_EXIT_GPU_INIT);
    }
#if PROJ_UNIT_USED
    if (!proj_unit_present()) {
        printf("error: this program projects its vertices with the SoC's projection unit, and this "
               "SoC has none (soc_top PROJ_UNIT = 0): build it with FW_DEFS=-DFW_PROJ_UNIT=0\n");
        app_fail(FW_EXIT_CONFIG);
    }
#endif
#if FW_WITH_STRIPS  /* (without, gpu_init refuses a GPU with strips) */
    app->strip_rows = app_gpu_strips(app) ? app->gpu.info.strip_rows : FW_STRIP_ROWS;
    if (app_gpu_strips(app)) {
        printf("strips: the GPU draws %lu rows at a time on chip (STRIP_ROWS)\n",
               (unsigned long)app->gpu.info.strip_rows);
    }
#endif
    scene_set_frame(&app->scene, gpu_fb_width(&app->gpu.info), gpu_fb_height(&app->gpu.info));
    app_check_words(app);
    desc = scene_find(FW_SCENE);
    if (desc == 0) {
        printf("error: no scene named '%s' built in\n", FW_SCENE);
        app_fail(FW_EXIT_CONFIG);
    }
    input_decoder_init(&app->decoder);
    app_upload_init(app);
    app_usb_init(app);
    app->wireframe = false;
    app->anaglyph = false;
    app->write_mask = APP_WRITE_MASK_UNKNOWN;
    app->depth_test = FW_WITH_DEPTH && FW_DEPTH_TEST && gpu_caps_zbuf(app->gpu.info.caps);
    if (app->depth_test) {
        printf("depth buffer on (FW_DEPTH_TEST, %u-bit depths)\n",
               (unsigned)gpu_caps_zbuf_bits(app->gpu.info.caps));
    }
    app->lost_in_a_row = 0;
    app_boot_model();
    app_start_scene(app, desc);
    app_path_start(app);
    app_report_lines(app);
    app_print_keys(&app->scene);
    app_print_scene(app);
}

/* Input: a model committed in the last frame swapped in, this frame's UART bytes (the upload's
 * frames, then keys) and USB keyboard's keys as the last frame collected them, the upload's
 * answers, the USB port's news, the global keys. Returns false to quit. */
static bool app_input(struct app *app, struct input_counts *keys, struct app_notes *notes,
                      struct frame_stats *st)
{
    notes->scene_changed = false;
    app_swap_upload(app, notes);
    if (!app->keys_collected) {
        app_collect_input(app);  /* the first frame */
    }
    *keys = app->keys_next;
    app->keys_collected = false;
    app_print_upload(app, st);
    app_print_usb(app, st);
    return app_global_keys(app, keys, notes, st);
}

/* Update: the scene's camera keys, animation and own keys (or the measurement's camera). */
static void app_update(struct app *app, unsigned frame, const struct input_counts *keys,
                       struct scene_event *ev, struct frame_stats *st)
{
    scene_update(&app->scene, keys, ev);
    app_path_apply(app, frame, st);
    frame_stats_updated(st);
    app_scene_dump(app, frame);
}

/* The frame's passes, each rendered then submitted: one, or two for the anaglyph (left eye red,
 * right eye cyan). Returns false when the watchdog dropped the frame. */
static bool app_draw(struct app *app, unsigned frame, struct frame_stats *st)
{
    const int passes = (FW_WITH_ANAGLYPH && app->anaglyph) ? 2 : 1;
    bool completed = true;

    for (int p = 0; p < passes && completed; p++) {
        const int eye = app->anaglyph ? ((p == 0) ? -1 : 1) : 0;

        app_render_pass(app, eye, st);
        app_settle(app, st);  /* the last frame's batch: done before this one's are written */
        if (p == 0) {
            app_collect_input(app);
        }
        app_set_write_mask(app, eye);
        completed = app_submit(app, frame, p == 0 || app_eye_planes(app), p == passes - 1, st);
        frame_stats_add_pass(st, &app->frame.stats);
    }
    return completed;
}

/* Statistics: the frame's line, or the watchdog's count of lost frames; the frame's errors stop
 * the firmware. */
static void app_statistics(struct app *app, unsigned frame, bool completed,
                           const struct frame_stats *st)
{
    if (!completed) {
        app->lost_in_a_row++;
        if (app->lost_in_a_row >= FW_WATCHDOG_GIVE_UP) {
            printf("error: frame %u: the GPU is still hung after %u resets; giving up\n", frame,
                   (unsigned)app->lost_in_a_row);
            app_fail(FW_EXIT_GPU_TIMEOUT);
        }
        return;
    }
    app->lost_in_a_row = 0;
    frame_stats_print(frame, st);
    if (st->render.dropped != 0u) {
        /* A capacity of this build (scene_list.h) was too small: what did not fit was not
         * drawn. Reported on every such frame; the run goes on. */
        printf("error: frame %u: %lu primitives or vertices dropped: the frame holds %lu "
               "vertices and %lu primitives in this build (scenes/scene_list.h)\n",
               frame, (unsigned long)st->render.dropped, (unsigned long)app->frame.vert_cap,
               (unsigned long)app->frame.prim_cap);
    }
    if (st->errors != 0u) {
        app_report_gpu_errors(frame, st->errors);
        app_fail(FW_EXIT_GPU_ERRORS);
    }
    if (fx_overflow_count() != 0u) {
        printf("error: frame %u: %lu fixed-point overflow(s): a range argument failed\n",
               frame, (unsigned long)fx_overflow_count());
        app_fail(FW_EXIT_FX_OVERFLOW);
    }
}

int app_run(void)
{
    struct app *app = &app_state;

    app_boot(app);
    /* FW_FRAMES frames, or (FW_FRAMES = 0) until Q; the frame number wraps after 2^32 frames. */
    for (unsigned frame = 0, left = FW_FRAMES; FW_FRAMES == 0 || left > 0u; frame++, left--) {
        struct input_counts keys;
        struct scene_event ev;
        struct app_notes notes;
        struct frame_stats st;
        const enum cam_mode mode_before = app->scene.cam.mode;
        bool completed;

        frame_stats_begin(&st);
        if (!app_input(app, &keys, &notes, &st)) {
            app_settle(app, NULL);
            printf("quit at frame %u\n", frame);
            break;
        }
        app_update(app, frame, &keys, &ev, &st);
        completed = app_draw(app, frame, &st);
        frame_stats_end(&st);
        app_print_notes(app, &notes, mode_before, &ev);
        if (completed && app->gpu.pending) {
            app->pending_frame = frame;  /* its statistics once its last batch is done */
            app->pending_st = st;
        } else {
            app_statistics(app, frame, completed, &st);
        }
    }
    app_settle(app, NULL);
    if (app->gpu.resets != 0u) {
        printf("watchdog: %lu GPU reset(s) in this run\n", (unsigned long)app->gpu.resets);
    }
    fflush(stdout);
    return FW_EXIT_OK;
}
