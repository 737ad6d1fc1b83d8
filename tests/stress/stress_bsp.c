/*
 * stress_bsp.c — bsp.h for the stress program: every GPU access goes to one golden model
 * (gpu_model/), reset by bsp_init(); no console input; output to stdout. The host's
 * bsp_platform.h (bsp/host/) defines the rest inline: the counters, the fence, no mapped GPU
 * buffers, no USB keyboard (bsp_usb_key_nonblock and bsp_usb_state return -1).
 */
#include <stdio.h>
#include <stdlib.h>

#include "bsp.h"
#include "stress_bsp.h"

static gpu_model stress_model;
static uint32_t stress_fb_width = GPU_FB_WIDTH;
static uint32_t stress_fb_height = GPU_FB_HEIGHT;

gpu_model *stress_bsp_gpu(void)
{
    return &stress_model;
}

void stress_bsp_set_frame(uint32_t width, uint32_t height)
{
    stress_fb_width = width;
    stress_fb_height = height;
}

uint32_t stress_bsp_frame_width(void)
{
    return stress_fb_width;
}

uint32_t stress_bsp_frame_height(void)
{
    return stress_fb_height;
}

void bsp_init(void)
{
    gpu_model_config cfg;

    gpu_model_reset(&stress_model);  /* the defaults, then the frame */
    cfg = stress_model.cfg;
    cfg.fb_width = stress_fb_width;
    cfg.fb_height = stress_fb_height;
    gpu_model_reset_config(&stress_model, &cfg);
}

void bsp_exit(int code)
{
    fflush(stdout);
    exit(code);
}

int bsp_uart_getc_nonblock(void)
{
    return -1;
}

void bsp_uart_putc(char c)
{
    putchar(c);
}

void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    gpu_model_write(&stress_model, offset, value);
}

uint32_t bsp_gpu_read(uint32_t offset)
{
    return gpu_model_read(&stress_model, offset);
}

void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        gpu_model_write(&stress_model, offset + 4u * i, src[i]);
    }
}
