/*
 * bsp_platform.h — the host build: the same firmware, compiled for Linux, with the GPU replaced by
 * the bit-exact golden model (gpu_model/) and the UART by scripted keys. The macros and the inline
 * half of bsp/bsp.h's interface (bsp_host.c defines the rest); what differs from a board:
 *
 *   - bsp_gpu_write/read go to a gpu_model instance; a DOORBELL write runs the whole batch at
 *     once, and every buffer swap is written as a PNG (640 x 480, the model's scan-out), numbered
 *     like the co-simulation's frames.
 *   - bsp_uart_getc_nonblock() returns keys scheduled with --keys-at N:TEXT, delivered just
 *     before the N-th doorbell is serviced — the co-simulation harness's rule, so a host run and a
 *     co-simulation run with the same key script render the same frames.
 *   - bsp_instret() and bsp_cycles() have nothing to count and return 0.
 *   - the GPU's buffers are not memory (BSP_GPU_BUFFERS_MAPPED 0): batches are staged.
 *   - no USB host: bsp_usb_key_nonblock() and bsp_usb_state() return -1 (scripted keys come
 *     through the UART only; a USB key gives the same action as its terminal bytes, which
 *     --keys-at types).
 *   - with --dump-scene DIR, every frame's scene is written as DIR/NNNN.scene for the exact
 *     reference (bsp_host_scene_dump, scene_dump.c; bench/exact_ref/exact_ref.c reads it).
 *
 * bsp/host/host_main.c parses the options (bsp_args, called by the firmware's main before the
 * frame loop).
 */
#ifndef BSP_PLATFORM_H
#define BSP_PLATFORM_H

#include <stdint.h>

#define BSP_NAME      "host"
#define BSP_GPU_BASE  0u  /* offsets go straight to the model; printed only in error messages */
#define BSP_EXIT_TRAP 126
#define BSP_GPU_BUFFERS_MAPPED 0  /* bsp_gpu_buffer returns NULL: batches are staged, then copied */

static inline uint64_t bsp_instret(void)
{
    return 0u;
}

static inline uint64_t bsp_cycles(void)
{
    return 0u;
}

static inline void bsp_fence(void)
{
    __asm__ volatile("" ::: "memory");  /* the model runs in this thread: a compiler barrier */
}

static inline int bsp_usb_key_nonblock(void)
{
    return -1;
}

static inline int bsp_usb_state(void)
{
    return -1;
}

/* bsp_gpu_write, bsp_gpu_read, bsp_gpu_write_words: functions into the model (bsp_host.c). */

/* NULL: the golden model's buffers are reached only through bsp_gpu_write (batches are staged). */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    (void)offset;
    return 0;
}

/* The platform has a command line: main() passes it to bsp_args first, which returns 0 to run
 * the frame loop, else the exit status (bad options). */
#define BSP_HAS_ARGS 1
int bsp_args(int argc, char **argv);

/* The frame's scene after its update, as bench/exact_ref reads it: app.c calls it once per frame
 * (a no-op without --dump-scene). The scene is opaque here: scene_dump.c reads it through
 * scenes/scene_export.h. */
#define BSP_HOST_SCENE_DUMP 1
struct scene;
void bsp_host_scene_dump(const struct scene *s, const uint16_t *palette, unsigned frame);

/* --model's mesh file: its bytes, *file set (NULL and 0: none). The frame loop asks once at boot
 * and gives it to the model scene as if it had been uploaded before the first frame. */
#define BSP_HOST_BOOT_MODEL 1
uint32_t bsp_host_boot_model(const uint8_t **file);

#endif /* BSP_PLATFORM_H */
