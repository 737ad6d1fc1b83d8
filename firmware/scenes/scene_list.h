/*
 * scene_list.h — the scene table: one SCENE(name) line per scene, nothing else.
 *
 * The order is the order of the keys 1..9 and of the key map. Scene `name` is the file
 * scenes/<name>.c (or the folder scenes/<name>/), which defines `const struct scene_desc
 * scene_<name>_desc` with .name = "<name>". firmware/firmware.mk reads the names from these lines
 * (FW_SCENES: what `make SCENE=` accepts, the builds of every scene); scene.c includes this file
 * to build its table. At most 9 scenes (the keys 1..9).
 */
SCENE(tetra)
SCENE(cubes)
SCENE(landscape)
SCENE(voxel)
SCENE(knot)
