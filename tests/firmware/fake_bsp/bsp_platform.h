/*
 * bsp_platform.h (unit-test double) — bsp/bsp.h's interface for the host unit tests: the GPU
 * aperture is a plain array, bsp_fence() takes a snapshot of the register window so a test can
 * check what had been written before the fence; the console is empty, nothing is counted, and
 * bsp_exit() ends the test program.
 */
#ifndef BSP_PLATFORM_H
#define BSP_PLATFORM_H

#include <stdint.h>
#include <stdlib.h>

#include "bsp_idle.h"

#define BSP_NAME "host-test"
#define BSP_EXIT_TRAP 126
#define BSP_GPU_BUFFERS_MAPPED 1  /* bsp_gpu_buffer: the aperture array itself */

#define FAKE_GPU_WORDS (0x20000u / 4u)  /* the 128 KiB aperture */
#define FAKE_REG_WORDS (0x100u / 4u)    /* the register window */

extern uint32_t fake_gpu_mem[FAKE_GPU_WORDS];
extern uint32_t fake_fence_count;
extern uint32_t fake_regs_at_fence[FAKE_REG_WORDS];  /* registers at the last fence */
extern uint32_t fake_write_count;                    /* bus writes so far */

#define BSP_GPU_BASE ((uintptr_t)fake_gpu_mem)

void fake_bsp_fence(void);

static inline void bsp_fence(void)
{
    fake_bsp_fence();
}

static inline void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    fake_gpu_mem[offset / 4u] = value;
    fake_write_count++;
}

static inline uint32_t bsp_gpu_read(uint32_t offset)
{
    return fake_gpu_mem[offset / 4u];
}

static inline void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        bsp_gpu_write(offset + 4u * i, src[i]);
    }
}

/* The aperture array itself, so the driver's in-place path can be tested. */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    return &fake_gpu_mem[offset / 4u];
}

static inline void bsp_exit(int code) __attribute__((noreturn));
static inline void bsp_exit(int code)
{
    exit(code);
}

#endif /* BSP_PLATFORM_H */
