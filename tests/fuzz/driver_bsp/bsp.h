/*
 * bsp.h (fuzz double) — the slice of the BSP interface firmware/src/gpu.c uses, for
 * tests/fuzz/fuzz_gpu_driver.c: every bus access goes to the harness, which checks it and
 * forwards it to the golden model (or answers for a device that lies about itself).
 */
#ifndef BSP_H
#define BSP_H

#include <stdint.h>

#define BSP_NAME "fuzz"
#define BSP_GPU_BASE 0u

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

#endif /* BSP_H */
