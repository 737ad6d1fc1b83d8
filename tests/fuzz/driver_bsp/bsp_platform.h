/*
 * bsp_platform.h (fuzz double) — bsp/bsp.h's interface for tests/fuzz/fuzz_gpu_driver.c: every
 * bus access goes to the harness, which checks it and forwards it to the golden model (or answers
 * for a device that lies about itself); the console is empty, nothing is counted, and bsp_exit()
 * aborts (the driver never calls it).
 */
#ifndef BSP_PLATFORM_H
#define BSP_PLATFORM_H

#include <stdint.h>
#include <stdlib.h>

#include "../../firmware/fake_bsp/bsp_idle.h"  /* init, console, counters: idle */

#define BSP_NAME "fuzz"
#define BSP_GPU_BASE 0u
#define BSP_EXIT_TRAP 126
#define BSP_GPU_BUFFERS_MAPPED 0  /* bsp_gpu_buffer returns NULL: every word through the bus */

void fuzz_bus_write(uint32_t offset, uint32_t value);
uint32_t fuzz_bus_read(uint32_t offset);
void fuzz_bus_fence(void);

static inline void bsp_fence(void)
{
    fuzz_bus_fence();
}

static inline void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    fuzz_bus_write(offset, value);
}

static inline uint32_t bsp_gpu_read(uint32_t offset)
{
    return fuzz_bus_read(offset);
}

static inline void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        fuzz_bus_write(offset + 4u * i, src[i]);
    }
}

/* NULL: every buffer word goes through the checked bus above (batches are staged and copied). */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    (void)offset;
    return 0;
}

static inline void bsp_exit(int code) __attribute__((noreturn));
static inline void bsp_exit(int code)
{
    (void)code;
    abort();
}

#endif /* BSP_PLATFORM_H */
