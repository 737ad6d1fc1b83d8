/*
 * pipeline.h — one render pass of a frame, wired once: the scene seen from one eye, drawn into the
 * frame's primitive list (transform, cull, clip, light, emit), sorted far to near, then the
 * overlay (the crosshair). Pure code. The frame loop (app.c) calls it once per pass, then cuts the
 * frame into GPU batches (gpu/batch.h); the unit tests and the input fuzzer call the same
 * function, so what they check is what the firmware runs.
 *
 * It is inline because the frame loop times its stages with the platform's instruction counter:
 * with the clock given as a constant function the marks compile to the counter reads the loop made
 * before the wiring moved here, and with a NULL clock (tests) to nothing.
 */
#ifndef PIPELINE_H
#define PIPELINE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "camera/camera.h"
#include "math/real.h"
#include "render/palette.h"
#include "render/render.h"
#include "scenes/scene.h"

/* The frame loop's switches that a pass depends on. */
struct pipeline_opts {
    bool wireframe;   /* F: outlines instead of filled faces */
    bool depth_test;  /* Z: every vertex gets its GPU depth (CTRL_ZTEST is the batch's) */
    bool gpu_lines;   /* the GPU draws line primitives (CAPS_LINES) */
    bool eye_planes;  /* anaglyph through the write mask (CAPS_WMASK): an eye's colours are levels
                       * in both nibbles (palette.h, palette_build_anaglyph), its pass writing one */
    bool gouraud;     /* meshes with vertex normals as Gouraud triangles (CAPS_GOURAUD, FW_GOURAUD) */
};

/* An eye pass's colours as the write mask's anaglyph wants them: each primitive's light level (the
 * low nibble of its eye-ramp colour) in both nibbles, PAL_ANAGLYPH_LEVEL so never the background. */
static inline void pipeline_eye_planes(struct render_frame *f)
{
    for (uint32_t i = 0; i < f->prim_count; i++) {
        const uint32_t shade = f->prim[i].color & 0xFu;

        f->prim[i].color = PAL_ANAGLYPH_BOTH(PAL_ANAGLYPH_LEVEL(shade));
    }
}

/* Where a pass's instructions went, in the units of the clock given to pipeline_pass. */
struct pipeline_times {
    uint64_t draw;  /* view, transform, project, cull, clip, light, emit; the overlay */
    uint64_t sort;
};

typedef uint64_t (*pipeline_clock_fn)(void);

/* The scene from one eye: 0 = the one eye of a normal frame, -1 / +1 = anaglyph left (red) and
 * right (cyan), each shifted half the scene's eye separation along the view's right axis. The
 * frame's primitive list and statistics start empty. clock may be NULL (then times is not
 * touched); else times->draw and ->sort are increased. */
static inline void pipeline_pass(struct render_frame *f, const struct scene *s,
                                 const struct pipeline_opts *opts, int eye,
                                 pipeline_clock_fn clock, struct pipeline_times *times)
{
    uint64_t t_begin = 0;
    struct cam_view view;
    struct render_pass pass;
    real_t offset = 0;
    uint64_t t_drawn = 0;
    uint64_t t_sorted = 0;

    render_stats_clear(&f->stats);
    if (clock != NULL) {
        t_begin = clock();
    }
    if (eye != 0) {
        offset = real_half(s->eye_separation);
        offset = (eye < 0) ? real_sub(0, offset) : offset;
    }
    cam_get_view(&s->cam, offset, &view);
    render_pass_init(&pass, &s->proj, &view, &s->cam.scene_rot, s->cam.cfg.focus, s->light,
                     s->ambient);
    pass.proj.zbuf = opts->depth_test;
    pass.wireframe = opts->wireframe;
    pass.gpu_lines = opts->gpu_lines;
    pass.gouraud = FW_WITH_GOURAUD && opts->gouraud;
    pass.eye_material = (eye < 0) ? MAT_ANAGLYPH_LEFT : ((eye > 0) ? MAT_ANAGLYPH_RIGHT : 0u);
    render_frame_begin(f);
    scene_draw(s, f, &pass);
    if (clock != NULL) {
        t_drawn = clock();
    }
    render_sort(f);
    if (clock != NULL) {
        t_sorted = clock();
    }
    if (s->crosshair) {
        render_overlay_crosshair(f, &pass, 5,
                                 (eye == 0) ? PAL_WHITE : PAL_INDEX(pass.eye_material, 15u));
    }
    if (eye != 0 && opts->eye_planes) {
        pipeline_eye_planes(f);
    }
    if (clock != NULL) {
        times->draw += (t_drawn - t_begin) + (clock() - t_sorted);
        times->sort += t_sorted - t_drawn;
    }
}

#endif /* PIPELINE_H */
