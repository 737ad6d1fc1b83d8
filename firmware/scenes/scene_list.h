/*
 * scene_list.h — the scene table: one SCENE(name, state, objects, verts, prims, wverts, wprims) line per scene,
 * nothing else.
 *
 * The order is the order of the keys 1..9 and of the key map (in a program built with every
 * scene; a program built with some of them, scene_set.h, numbers those in this order). Scene
 * `name` is the file scenes/<name>.c (or the folder scenes/<name>/), which defines `const struct
 * scene_desc scene_<name>_desc` with SCENE_DESC_NEEDS(<name>, ...): .name = "<name>" and this
 * line's columns. firmware/firmware.mk reads the names from
 * these lines (FW_SCENES: what `make SCENE=` accepts, the builds of every scene); scene.h includes
 * this file to declare the table, scene_set.h to size a program's memory. At most 9 scenes.
 *
 * The columns are what the scene needs, its build's memory (firmware/README.md, "Memory per
 * scene", has the argument for each number):
 *   state    bytes of its state struct (SCENE_STATE_FITS checks it at compile time; the unit tests,
 *            that it is the host's sizeof rounded up to 64, the larger of the two ABIs)
 *   objects  scene_add_object calls its init makes
 *   verts    frame vertices one filled pass can need: the visible objects' mesh vertices, the
 *            clipper's new ones, 4 for the crosshair
 *   prims    frame primitives one filled pass can need: triangles (a clipped face's fan), the
 *            crosshair's 2 lines. A wireframe pass with GPU lines needs exactly these two (one
 *            outline primitive per triangle, render.h)
 *   wverts   the same for a wireframe pass with emulated lines (4 vertices and 2 triangles per
 *   wprims   edge): what a build with FW_WITH_WIREFRAME and FW_WITH_LINE_EMULATION reserves
 * A frame that would need more drops the rest and counts it (render_stats.dropped: the frame
 * loop prints an error line); test_scene_capacities (tests/firmware/test_scene.c) drives every
 * scene through camera sweeps in filled, wireframe (GPU lines and emulated) and anaglyph passes,
 * and requires every pass to fit its columns.
 *
 *     name       state   objects  verts  prims  wverts  wprims */
SCENE(tetra,        320,     1,      32,    21,    140,     54)
SCENE(cubes,        448,    64,     640,   512,   5376,   2432)
SCENE(landscape,  72960,    16,    1536,  2304,  29120,  13824)
SCENE(voxel,      65408,     8,    2048,  2048,  17024,   7808)
SCENE(knot,       45312,     1,    2880,  2816,  36480,  16832)
/* model's columns follow its build switches (FW_MODEL_MAX_*): scenes/model/model.h argues them. */
SCENE(model, MODEL_STATE_COLUMN, 1, MODEL_FRAME_VERTS, MODEL_FRAME_PRIMS, MODEL_WIRE_VERTS, MODEL_WIRE_PRIMS)
