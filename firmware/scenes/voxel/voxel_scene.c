/*
 * voxel_scene.c — the 16 x 16 x 16 block world: eight 8^3 chunk meshes (hidden faces left out),
 * rebuilt when an edit touches them; P places and B breaks the block under the crosshair (ray
 * cast from the eye), N picks the block type. Fly mode.
 */
#include "render/palette.h"
#include "scenes/scene.h"
#include "scenes/voxel/voxel_scene.h"

#define VOXEL_REACH REAL_C(32.0)  /* units the crosshair reaches: the whole world from the default view */

SCENE_STATE_FITS(voxel, struct voxel_scene_state);

static const char *const voxel_block_names[BLOCK_TYPES] = {
    "air", "grass", "dirt", "stone", "sand", "wood", "leaves",
};

/*
 * Rebuild the chunks from the first dirty one on, packed into the pool in chunk order after the
 * chunks before it (which keep their place): a chunk's size changes with an edit, so every later
 * one moves. A chunk that does not fit the rest of the pool is left out (an empty mesh: not
 * drawn), marked in left_out_mask and reported through ev; later chunks still get their turn.
 */
static void voxel_rebuild_dirty(struct voxel_scene_state *v, struct scene_event *ev)
{
    uint32_t first = 0;
    uint32_t vert_at = 0;
    uint32_t face_at = 0;
    uint32_t left_out = 0;

    while (first < VOXEL_CHUNK_COUNT && !v->world.chunk_dirty[first]) {
        first++;
    }
    if (first == VOXEL_CHUNK_COUNT) {
        return;
    }
    if (first > 0u) {
        const struct mesh *prev = &v->chunk[first - 1u].mesh;

        /* Where the previous chunk's storage ends (an empty one began where it would have). */
        vert_at = (uint32_t)(prev->verts - v->pool_verts) + prev->vert_count;
        face_at = (uint32_t)(prev->faces - v->pool_faces) + prev->face_count;
    }
    for (uint32_t i = first; i < VOXEL_CHUNK_COUNT; i++) {
        struct voxel_chunk *c = &v->chunk[i];
        const int32_t cx = (int32_t)(i % VOXEL_CHUNKS_X);
        const int32_t cz = (int32_t)((i / VOXEL_CHUNKS_X) % VOXEL_CHUNKS_Z);
        const int32_t cy = (int32_t)(i / (VOXEL_CHUNKS_X * VOXEL_CHUNKS_Z));

        voxel_chunk_attach(c, &v->pool_verts[vert_at], VOXEL_POOL_VERTS - vert_at,
                           &v->pool_faces[face_at], VOXEL_POOL_FACES - face_at);
        voxel_build_chunk(&v->world, cx, cy, cz, c, v->grid_index);
        v->left_out_mask = (uint8_t)(v->left_out_mask & ~(1u << i));
        if (c->mesh.full) {
            mesh_clear(&c->mesh);  /* left out whole, never drawn half */
            v->left_out_mask = (uint8_t)(v->left_out_mask | (1u << i));
        }
        vert_at += c->mesh.vert_count;
        face_at += c->mesh.face_count;
        v->world.chunk_dirty[i] = false;
    }
    /* Chunks before `first` were not rebuilt: any left out before stay so until they are. */
    for (uint32_t i = 0; i < VOXEL_CHUNK_COUNT; i++) {
        left_out += (v->left_out_mask >> i) & 1u;
    }
    if (left_out != 0u && ev != 0) {
        ev->kind = SCENE_EVENT_MESH_FULL;
        ev->x = (int32_t)left_out;
        ev->y = (int32_t)VOXEL_POOL_FACES;
        ev->z = (int32_t)VOXEL_POOL_VERTS;
    }
}

static void voxel_scene_init(struct scene *s)
{
    struct voxel_scene_state *v = voxel_scene_state(s);
    struct cam_config cfg = scene_default_cam_config();
    const mat3 id = mat3_identity();

    voxel_generate(&v->world);
    for (int32_t cy = 0; cy < VOXEL_CHUNKS_Y; cy++) {
        for (int32_t cz = 0; cz < VOXEL_CHUNKS_Z; cz++) {
            for (int32_t cx = 0; cx < VOXEL_CHUNKS_X; cx++) {
                struct voxel_chunk *c = &v->chunk[voxel_chunk_index(cx, cy, cz)];

                voxel_chunk_init(c, cx, cy, cz);
                scene_add_quad_object(s, &c->mesh, &id, c->origin, 0);
                render_level_cache_init(&c->levels, c->level, 6u);
                s->object[s->object_count - 1u].levels = &c->levels;
            }
        }
    }
    v->left_out_mask = 0;
    voxel_rebuild_dirty(v, 0);
    v->place_block = BLOCK_STONE;
    s->crosshair = true;
    cfg.box_min = vec3_make(REAL_C(-32), REAL_C(-16), REAL_C(-32));
    cfg.box_max = vec3_make(REAL_C(48), REAL_C(48), REAL_C(48));
    cfg.focus = vec3_make(REAL_C(8), REAL_C(8), REAL_C(8));
    scene_set_camera(s, CAM_FLY, vec3_make(REAL_C(8), REAL_C(5), REAL_C(8)), REAL_C(21.0),
                     FX_ANGLE_DEG(35), -(int32_t)(32 * 65536 / 360), &cfg);
}

/* The crosshair's ray in world (unrotated scene) coordinates: object mode turns the scene about
 * its focus by R, so a world point w is drawn at R (w - focus) + focus; the eye's ray maps back
 * through R^T. */
static bool voxel_pick(const struct scene *s, struct voxel_hit *hit)
{
    const struct camera *cam = &s->cam;
    const mat3 rt = mat3_transpose(&cam->scene_rot);
    const vec3 focus = cam->cfg.focus;
    const vec3 origin = vec3_add(mat3_apply(&rt, vec3_sub(cam->eye, focus)), focus);
    const uvec3 dir = mat3_apply_unit(&rt, cam_forward(cam));

    return voxel_raycast(&SCENE_STATE(s, const struct voxel_scene_state)->world, origin, dir,
                         VOXEL_REACH, hit);
}

static void voxel_scene_update(struct scene *s, const struct input_counts *keys,
                               struct scene_event *ev)
{
    struct voxel_scene_state *v = voxel_scene_state(s);
    struct voxel_hit hit;

    if (keys->n[KEY_NEXT_BLOCK] != 0u) {
        v->place_block = (uint8_t)(BLOCK_GRASS + (v->place_block - BLOCK_GRASS + keys->n[KEY_NEXT_BLOCK]) %
                                                     (BLOCK_TYPES - BLOCK_GRASS));
        ev->kind = SCENE_EVENT_BLOCK_TYPE;
        ev->block_name = voxel_block_names[v->place_block];
    }
    /* One edit per press, each with a fresh ray: three B presses dig three blocks deep. */
    for (uint32_t i = 0; i < keys->n[KEY_BREAK]; i++) {
        if (!voxel_pick(s, &hit)) {
            ev->kind = SCENE_EVENT_NO_TARGET;
            break;
        }
        voxel_set(&v->world, hit.x, hit.y, hit.z, BLOCK_AIR);
        ev->kind = SCENE_EVENT_BROKE;
        ev->x = hit.x;
        ev->y = hit.y;
        ev->z = hit.z;
    }
    for (uint32_t i = 0; i < keys->n[KEY_PLACE]; i++) {
        const struct camera *cam = &s->cam;

        if (!voxel_pick(s, &hit) || !hit.prev_valid || !voxel_inside(hit.px, hit.py, hit.pz)) {
            ev->kind = SCENE_EVENT_NO_TARGET;
            break;
        }
        /* Never wall the eye in. (In object mode the eye's cell is meaningless; checked anyway.) */
        if (hit.px == real_floor_int(cam->eye.x) && hit.py == real_floor_int(cam->eye.y) &&
            hit.pz == real_floor_int(cam->eye.z)) {
            ev->kind = SCENE_EVENT_NO_TARGET;
            break;
        }
        voxel_set(&v->world, hit.px, hit.py, hit.pz, v->place_block);
        ev->kind = SCENE_EVENT_PLACED;
        ev->x = hit.px;
        ev->y = hit.py;
        ev->z = hit.pz;
        ev->block_name = voxel_block_names[v->place_block];
    }
    voxel_rebuild_dirty(v, ev);
}

const struct scene_desc scene_voxel_desc = {
    SCENE_DESC_NEEDS(voxel, struct voxel_scene_state),
    .keys = "P place block, B break block, N next block type (crosshair at the screen centre)",
    .init = voxel_scene_init,
    .update = voxel_scene_update,
};
