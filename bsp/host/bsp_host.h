/*
 * bsp_host.h — configuration of the host BSP, set by host_main.c (bsp_args) before the frame loop
 * runs. Not part of the bsp.h interface.
 */
#ifndef BSP_HOST_H
#define BSP_HOST_H

#include <stdbool.h>
#include <stdint.h>

#define BSP_HOST_MAX_KEY_EVENTS 64

struct bsp_host_keys {
    uint32_t at;        /* typed just before this doorbell (1 = the first) is serviced, or with */
    bool frame;         /* frame, the doorbell that starts frame `at` (0 = the first) */
    const char *text;
};

struct bsp_host_config {
    const char *frames_dir;  /* PNG per swapped frame, NULL: none */
    struct bsp_host_keys keys[BSP_HOST_MAX_KEY_EVENTS];
    uint32_t key_events;
    unsigned span_w;         /* model build options (CAPS), as gpu_model_config */
    bool lines;
    bool zbuf;
    bool no_wmask;           /* a GPU built without the write mask (CAPS_WMASK = 0) */
    bool gouraud;            /* a GPU built with Gouraud triangles (CAPS_GOURAUD) */
    unsigned zbuf_bits;      /* ZBUF_BITS, 1 .. 16 */
    uint32_t fb_width;       /* the frame (FB_SIZE): the contract's default or its largest */
    uint32_t fb_height;
    const char *dump_dir;    /* the scene of every frame for bench/exact_ref, NULL: none */
    const char *unquantised_dir;  /* PNG per swapped frame in unquantised Gouraud colours, NULL: none */
    const uint8_t *model_file;    /* --model's mesh file, NULL: none (bsp_host_boot_model) */
    uint32_t model_bytes;
};

/* Set before the frame loop runs; bsp_init() applies it. */
void bsp_host_configure(const struct bsp_host_config *cfg);
/* --dump-scene's directory, or NULL (scene_dump.c). */
const char *bsp_host_dump_dir(void);

#endif /* BSP_HOST_H */
