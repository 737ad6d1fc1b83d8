/*
 * scene.c — the scene table (scene_list.h) and what all scenes share (see scene.h).
 */
#include "scenes/scene.h"

#include "config/hot_path.h"

#include "render/palette.h"

/* The table itself, scene_built[], is the program's: scenes/scene_set.h, included by one file of
 * each program, lists the scenes it is built with, so a one-scene build links no other scene. */

_Static_assert(SCENE_COUNT >= 1 && SCENE_COUNT <= KEY_SCENE_LAST - KEY_SCENE_1 + 1,
               "scene_list.h: 1 to 9 scenes (the keys 1..9 choose them)");

static int scene_name_equal(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

const struct scene_desc *scene_find(const char *name)
{
    for (uint32_t i = 0; i < scene_built_count; i++) {
        if (scene_name_equal(scene_built[i]->name, name)) {
            return scene_built[i];
        }
    }
    return 0;
}

const struct scene_desc *scene_at(uint32_t index)
{
    return (index < scene_built_count) ? scene_built[index] : 0;
}

uint32_t scene_count(void)
{
    return scene_built_count;
}

void scene_attach(struct scene *s, struct render_object *objects, uint32_t object_cap,
                  unsigned char *state, size_t state_cap)
{
    s->object = objects;
    s->object_cap = object_cap;
    s->object_count = 0;
    s->state = state;
    s->state_cap = state_cap;
    s->desc = 0;
    scene_set_frame(s, GPU_FB_WIDTH, GPU_FB_HEIGHT);
}

void scene_set_frame(struct scene *s, uint32_t width, uint32_t height)
{
    s->frame_width = width;
    s->frame_height = height;
}

void scene_camera_keys(struct camera *cam, const struct input_counts *keys)
{
    cam_move(cam, input_axis(keys, KEY_FORWARD, KEY_BACK), input_axis(keys, KEY_RIGHT, KEY_LEFT),
             input_axis(keys, KEY_UP, KEY_DOWN), input_axis(keys, KEY_LOOK_RIGHT, KEY_LOOK_LEFT),
             input_axis(keys, KEY_LOOK_UP, KEY_LOOK_DOWN),
             input_axis(keys, KEY_ROLL_RIGHT, KEY_ROLL_LEFT), keys->n[KEY_MODE]);
}

struct cam_config scene_default_cam_config(void)
{
    struct cam_config cfg;

    cfg.box_min = vec3_make(REAL_C(-64), REAL_C(-64), REAL_C(-64));
    cfg.box_max = vec3_make(REAL_C(64), REAL_C(64), REAL_C(64));
    cfg.dist_min = REAL_C(1.0);
    cfg.dist_max = REAL_C(60.0);
    cfg.move_step = REAL_C(0.25);
    cfg.zoom_step = REAL_C(0.25);
    cfg.look_step = (fx_angle)(FX_TURN / 128u);  /* 2.8125 degrees */
    cfg.focus = vec3_make(0, 0, 0);
    return cfg;
}

void scene_set_camera(struct scene *s, enum cam_mode mode, vec3 target, real_t distance,
                      fx_angle yaw, int32_t pitch, const struct cam_config *cfg)
{
    s->cam_default = *cfg;
    s->mode_default = mode;
    s->target_default = target;
    s->distance_default = distance;
    s->yaw_default = yaw;
    s->pitch_default = pitch;
    cam_init(&s->cam, cfg, mode, target, distance, yaw, pitch);
}

/* A world coordinate within +-1024 (real.h's range rule; render.c forms object offsets exactly
 * on the strength of it): one outside is clamped and counted as an overflow, so the frame loop
 * reports the failed range argument instead of drawing with a wrong offset. */
static real_t scene_world_coord(real_t v)
{
    if (v > REAL_C(1024.0) || v < REAL_C(-1024.0)) {
        fx_overflow_note();
        return (v > 0) ? REAL_C(1024.0) : REAL_C(-1024.0);
    }
    return v;
}

/* The next object, projected by `project` and drawn with face loop `faces` (when the scene has
 * room for it). */
static FW_BUILD_ONCE void scene_new_object(struct scene *s, const struct mesh *m, const mat3 *rot,
                                           vec3 pos, uint8_t material, render_faces_fn faces,
                                           render_project_fn project)
{
    struct render_object *o;

    if (s->object_count >= s->object_cap) {
        s->objects_refused++;  /* scene_start reports it: never a silently missing object */
        return;
    }
    pos = vec3_make(scene_world_coord(pos.x), scene_world_coord(pos.y), scene_world_coord(pos.z));
    o = &s->object[s->object_count++];
    o->mesh = m;
    o->rot = *rot;
    o->pos = pos;
    o->material = material;
    o->levels = 0;
    o->vnormal14 = 0;
    o->faces = faces;
    o->project = project;
}

/* Four functions, each naming its own loop (the general and quad ones the box projection too: a
 * grid or lattice mesh is never a box; the lattice one the lattice projection): a program links
 * the loop only when a scene of its calls the function (render_object.faces, .project). */
void scene_add_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                      uint8_t material)
{
    scene_new_object(s, m, rot, pos, material, render_general_faces_loop, render_project_boxed);
}

void scene_add_quad_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                           uint8_t material)
{
    scene_new_object(s, m, rot, pos, material, render_quad_faces_loop, render_project_boxed);
}

void scene_add_grid_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                           uint8_t material)
{
    scene_new_object(s, m, rot, pos, material, render_grid_faces_loop, 0);
}

void scene_add_lattice_object(struct scene *s, const struct mesh *m, const mat3 *rot, vec3 pos,
                              uint8_t material)
{
    scene_new_object(s, m, rot, pos, material, render_lattice_faces_loop, render_project_lattice);
}

FW_BUILD_ONCE bool scene_start(struct scene *s, const struct scene_desc *desc)
{
    if (desc->state_bytes > s->state_cap || desc->max_objects > s->object_cap) {
        return false;  /* this program's storage was not sized for it: *s is left as it was */
    }
    s->desc = desc;
    s->object_count = 0;
    s->objects_refused = 0;
    s->frame = 0;
    s->animate = true;
    s->crosshair = false;
    s->focal_px = 200;  /* vertical field of view 2 atan(120 / 200) = 62 degrees at any frame */
    s->far = REAL_C(160.0);
    /* Towards the light: up, a little left and towards the viewer. */
    s->light = vec3_direction(vec3_make(REAL_C(-0.45), REAL_C(0.8), REAL_C(-0.4)));
    s->ambient = 4;
    s->eye_separation = REAL_C(0.15);
    s->grid = NULL;
    desc->init(s);
    proj_setup_init(&s->proj, s->focal_px, s->far, s->frame_width, s->frame_height);
    for (uint32_t i = 0; i < s->object_count; i++) {
        render_level_cache_fill(&s->object[i], &s->cam.scene_rot, s->light, s->ambient);
    }
    if (s->objects_refused != 0u || s->object_count > desc->max_objects) {
        s->desc = 0;  /* its objects column is wrong: refuse rather than draw part of it */
        return false;
    }
    return true;
}

void scene_update(struct scene *s, const struct input_counts *keys, struct scene_event *ev)
{
    ev->kind = SCENE_EVENT_NONE;
    if (input_toggled(keys, KEY_RESET_VIEW)) {
        cam_init(&s->cam, &s->cam_default, s->mode_default, s->target_default,
                 s->distance_default, s->yaw_default, s->pitch_default);
    }
    scene_camera_keys(&s->cam, keys);
    if (input_toggled(keys, KEY_ANIMATE)) {
        s->animate = !s->animate;
    }
    s->desc->update(s, keys, ev);
    s->frame++;
}

void scene_spin_first(struct scene *s, const mat3 *spin)
{
    if (s->animate && s->object_count != 0u) {
        struct render_object *o = &s->object[0];

        o->rot = mat3_mul(spin, &o->rot);
        mat3_renormalize(&o->rot);
    }
}

/* ---- the grid's painter's order (scene_set_grid) ------------------------------------------ */

FW_BUILD_ONCE bool scene_set_grid(struct scene *s, const struct scene_grid_layout *layout)
{
    const uint8_t *n = layout->count;

    s->grid = (FW_SCENE_ORDER && s->object_count == (uint32_t)n[0] * n[1] * n[2]) ? layout : NULL;
    return s->grid != NULL;
}

/* The objects of a grid far to near (scene_set_grid): a few instructions an object, so built for
 * size; render_object is the work. */
static FW_ONCE_A_FRAME __attribute__((noinline)) void
scene_draw_grid(const struct scene *s, struct render_frame *f, const struct render_pass *pass)
{
    const struct scene_grid_layout *g = s->grid;
    /* The eye in the scene's frame: the point the pass's transform takes to the view's origin. */
    const vec3 eye = vec3_add(pass->focus, xf_eye(&pass->focus_to_view));
    const real_t e[3] = {eye.x, eye.y, eye.z};
    uint32_t split[3];

    /* The eye's cell on each axis (an axis not divided has one cell, walked the same from 0). */
    for (int k = 0; k < 3; k++) {
        split[k] = (g->cell[k] == 0) ? 0u : render_walk_split(e[k], g->origin[k], g->cell[k],
                                                               g->count[k]);
    }
    f->painter_ordered = true;  /* the face loops keep it or drop it */
    for (uint32_t z = 0; z < g->count[2]; z++) {
        for (uint32_t y = 0; y < g->count[1]; y++) {
            const uint32_t row = (render_walk_at(z, g->count[2], split[2]) * g->count[1] +
                                  render_walk_at(y, g->count[1], split[1])) * g->count[0];

            for (uint32_t x = 0; x < g->count[0]; x++) {
                render_object(f, pass, &s->object[row + render_walk_at(x, g->count[0], split[0])]);
            }
        }
    }
}

void scene_draw(const struct scene *s, struct render_frame *f, const struct render_pass *pass)
{
    if (s->grid != NULL) {
        scene_draw_grid(s, f, pass);
        return;
    }
    for (uint32_t i = 0; i < s->object_count; i++) {
        render_object(f, pass, &s->object[i]);
    }
}

uint32_t scene_triangle_count(const struct scene *s)
{
    uint32_t n = 0;

    for (uint32_t i = 0; i < s->object_count; i++) {
        n += s->object[i].mesh->face_count;
    }
    return n;
}
