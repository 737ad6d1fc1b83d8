/*
 * stress_bsp.h — the stress program's BSP (bsp.h): the golden model as the GPU, like bsp/host, but
 * the model is the program's to inspect (framebuffer hashes, error bits) and the UART is silent.
 */
#ifndef STRESS_BSP_H
#define STRESS_BSP_H

#include "gpu_model.h"

/* The model behind bsp_gpu_*: reset to power-on by every bsp_init(). */
gpu_model *stress_bsp_gpu(void);

#endif /* STRESS_BSP_H */
