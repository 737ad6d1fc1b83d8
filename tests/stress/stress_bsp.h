/*
 * stress_bsp.h — the stress program's BSP (bsp.h): the golden model as the GPU, like bsp/host, but
 * the model is the program's to inspect (framebuffer hashes, error bits) and the UART is silent.
 */
#ifndef STRESS_BSP_H
#define STRESS_BSP_H

#include "gpu_model.h"

/* The model behind bsp_gpu_*: reset to power-on by every bsp_init(). */
gpu_model *stress_bsp_gpu(void);

/* The frame the model draws from the next bsp_init() on: the contract's (the default) or its
 * largest. */
void stress_bsp_set_frame(uint32_t width, uint32_t height);
uint32_t stress_bsp_frame_width(void);
uint32_t stress_bsp_frame_height(void);

#endif /* STRESS_BSP_H */
