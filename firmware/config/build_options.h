/*
 * build_options.h — the firmware's build options that leave code out or size storage: the
 * features a scene may not need (FW_WITH_*) and the projection's sub-pixel precision. Override
 * them with -D on the compiler command line (firmware/firmware.mk does: FW_DEFS, FW_SUBPIXEL_BITS,
 * FW_LINE_EMULATION).
 *
 * Why a folder of its own, at the bottom: every layer reads these switches (render/ leaves the
 * wireframe and Gouraud code out, scenes/ size their frames by them, gpu/ packs the vertex words
 * by them, app/ refuses the keys of what is not built in), so they belong to none of those layers;
 * a header that includes nothing can be included from anywhere without an upward edge. What the
 * frame loop chooses while running (depth test on or off, wireframe, Gouraud or flat, the GPU's
 * capabilities) is not here: it reaches the render stages as data, struct render_pass
 * (render/render.h). The loop's own settings (scene, frames, watchdog, exit statuses, the
 * start-up state of its toggles) stay in app/fw_config.h.
 */
#ifndef CONFIG_BUILD_OPTIONS_H
#define CONFIG_BUILD_OPTIONS_H

/* Fraction bits kept in projected screen coordinates, 0..4 (the contract's Q12.4 carries 4):
 * fewer bits round every vertex to a coarser grid (0: whole pixels). An accuracy knob for
 * `make bench-error`; 4, the default, builds exactly the full-precision code. make FW_SUBPIXEL_BITS=... */
#ifndef FW_SUBPIXEL_BITS
#define FW_SUBPIXEL_BITS 4
#endif

/* Features a scene may not need: 1 builds them in (the default), 0 leaves their code out, and
 * their key then says so. make FW_DEFS="-DFW_WITH_LIGHTING=0 ..." (firmware/README.md):
 *   FW_WITH_WIREFRAME  the F key's outline mode (the crosshair's lines stay)
 *   FW_WITH_LINE_EMULATION  the wireframe on a GPU without line primitives (CAPS_LINES = 0): each
 *                      edge as two triangles on four new vertices, so the wireframe columns of
 *                      scenes/scene_list.h (wverts, wprims) are reserved; 0 (a platform whose GPU
 *                      draws lines: bsp/<platform>/bsp.mk) reserves only the filled columns, and
 *                      the F key on a GPU without lines then says so and stays off
 *   FW_WITH_ANAGLYPH   the G key's red/cyan stereo (a second pass per frame)
 *   FW_WITH_DEPTH      the GPU's depth test: VTX_Z per vertex and the Z key
 *   FW_WITH_LIGHTING   flat light per face; without, every face shows its material at full level
 *   FW_WITH_GOURAUD    per-vertex light and Gouraud triangles for meshes with vertex normals;
 *                      without, every face is flat (and the scenes keep no vertex normals)
 *   FW_WITH_STRIPS     frames binned into strips (render/strips.c): what a GPU with a strip buffer
 *                      (STRIP_ROWS > 0) needs, and FW_STRIP_ROWS; without, such a GPU is refused at
 *                      start-up with a message */
#ifndef FW_WITH_WIREFRAME
#define FW_WITH_WIREFRAME 1
#endif
#ifndef FW_WITH_LINE_EMULATION
#define FW_WITH_LINE_EMULATION 1
#endif
#ifndef FW_WITH_ANAGLYPH
#define FW_WITH_ANAGLYPH 1
#endif
#ifndef FW_WITH_DEPTH
#define FW_WITH_DEPTH 1
#endif
#ifndef FW_WITH_LIGHTING
#define FW_WITH_LIGHTING 1
#endif
#ifndef FW_WITH_GOURAUD
#define FW_WITH_GOURAUD 1
#endif
#ifndef FW_WITH_STRIPS
#define FW_WITH_STRIPS 1
#endif

/* The painter's order by construction (1, the default): a scene whose objects lie in the cells of
 * a grid (scene_set_grid) draws them far to near from the eye, a regular lattice's quads are
 * walked far to near (render.c), and a pass drawn only so is not sorted. Exact where the sort's
 * depth keys are not, and cheaper; 0 sorts every pass, as before (for comparison:
 * make bench-fw FW_DEFS=-DFW_SCENE_ORDER=0). */
#ifndef FW_SCENE_ORDER
#define FW_SCENE_ORDER 1
#endif

/* Whether a frame is sized by the scenes' wireframe columns (an outline emulated with triangles
 * needs more vertices and primitives than the filled faces) or their filled ones (scene_list.h). */
#define FW_FRAME_WIRE_COLUMNS (FW_WITH_WIREFRAME && FW_WITH_LINE_EMULATION)

/* The model scene's frame columns (scenes/model/model.h explains each) for its capacities of v
 * vertices and f faces: the one scene whose frame is sized by switches (FW_MODEL_MAX_VERTS and
 * FW_MODEL_MAX_FACES, which firmware.mk passes to every object). Constant expressions the
 * preprocessor can evaluate, so the index width below follows from them. */
#define FW_MODEL_FRAME_VERTS(v, f) ((v) + (f) / 2u + 4u)
#define FW_MODEL_FRAME_PRIMS(f) ((f) + (f) / 4u + 2u)
#define FW_MODEL_WIRE_VERTS(f) (12u * ((f) + (f) / 4u) + 4u)
#define FW_MODEL_WIRE_PRIMS(f) (6u * ((f) + (f) / 4u) + 2u)

/* The render frame's vertex and primitive numbers (render/render.h): 16 bits, which bound a frame
 * to 65,535 of each (the last value marks no position) and keep a primitive 8 bytes (the GPU's two words) and a sort item 32 bits, or
 * (FW_RENDER_WIDE_INDEX 1) 32 bits, with 16-byte primitives and 64-bit sort items, where the model
 * scene's frame needs more: the SDRAM's builds, whose model holds 65,536 faces. Derived, never set:
 * every object of a program sees the same capacities and so agrees on it. (Without the capacities,
 * as in a test that builds no model scene, both are 0 here and the frame is narrow.) */
#define FW_MODEL_FRAME_WIDEST_ \
    ((FW_FRAME_WIRE_COLUMNS ? FW_MODEL_WIRE_VERTS(FW_MODEL_MAX_FACES) \
                            : FW_MODEL_FRAME_VERTS(FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES)) > 65535u || \
     (FW_FRAME_WIRE_COLUMNS ? FW_MODEL_WIRE_PRIMS(FW_MODEL_MAX_FACES) \
                            : FW_MODEL_FRAME_PRIMS(FW_MODEL_MAX_FACES)) > 65535u)
#if FW_MODEL_FRAME_WIDEST_
#define FW_RENDER_WIDE_INDEX 1
#else
#define FW_RENDER_WIDE_INDEX 0
#endif
#undef FW_MODEL_FRAME_WIDEST_

#endif /* CONFIG_BUILD_OPTIONS_H */
