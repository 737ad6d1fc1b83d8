/*
 * bsp.h (host test double) — the slice of the BSP interface that firmware/src/gpu.c uses, on the
 * host: the GPU aperture is a plain array, bsp_fence() takes a snapshot of the register window so
 * a test can check what had been written before the fence. See bsp/README.md for the real
 * interface.
 */
#ifndef BSP_H
#define BSP_H

#include <stdint.h>

#define BSP_NAME "host-test"

#define FAKE_GPU_WORDS (0x20000u / 4u)  /* the 128 KiB aperture */
#define FAKE_REG_WORDS (0x100u / 4u)    /* the register window */

extern uint32_t fake_gpu_mem[FAKE_GPU_WORDS];
extern uint32_t fake_fence_count;
extern uint32_t fake_regs_at_fence[FAKE_REG_WORDS];  /* registers at the last fence */

#define BSP_GPU_BASE ((uintptr_t)fake_gpu_mem)

void fake_bsp_fence(void);

static inline void bsp_fence(void)
{
    fake_bsp_fence();
}

#endif /* BSP_H */
