/*
 * bsp_host.c — the host BSP (see bsp.h): golden-model GPU, scripted UART, frames out
 * (frame_out.h: PNG files).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bsp.h"
#include "bsp_host.h"
#include "frame_out.h"
#include "gpu_model.h"

static struct bsp_host_config host_cfg;
static gpu_model *host_gpu;
static uint8_t host_rgb[GPU_MODEL_SCREEN_W * GPU_MODEL_SCREEN_H * 3];
static uint32_t host_doorbells;     /* doorbells serviced so far */
static uint32_t host_swaps;         /* of them, those whose batch swapped */
static bool host_frame_starts = true;  /* the next doorbell starts a frame (--keys-at fF:TEXT) */
static uint32_t host_frames_written;
static char host_uart_in[4096];     /* typed, not yet read */
static uint32_t host_uart_head;
static uint32_t host_uart_tail;

void bsp_host_configure(const struct bsp_host_config *cfg)
{
    host_cfg = *cfg;
}

const char *bsp_host_dump_dir(void)
{
    return host_cfg.dump_dir;
}

uint32_t bsp_host_boot_model(const uint8_t **file)
{
    *file = host_cfg.model_file;
    return host_cfg.model_bytes;
}

void bsp_init(void)
{
    gpu_model_config mc = {0}; /* capacities 0: the contract's, the full-size GPU */

    if (host_gpu == NULL) {
        host_gpu = malloc(sizeof *host_gpu);
        if (host_gpu == NULL) {
            fprintf(stderr, "host bsp: out of memory\n");
            exit(1);
        }
    }
    mc.span_w = host_cfg.span_w;
    mc.lines = host_cfg.lines;
    mc.zbuf = host_cfg.zbuf;
    mc.wmask = !host_cfg.no_wmask;
    mc.gouraud = host_cfg.gouraud;
    mc.zbuf_bits = host_cfg.zbuf_bits;
    mc.fb_width = host_cfg.fb_width;
    mc.fb_height = host_cfg.fb_height;
    gpu_model_reset_config(host_gpu, &mc);
    if (host_cfg.unquantised_dir != NULL) {
        static gpu_model_shade_probe probe;

        gpu_model_attach_shade_probe(host_gpu, &probe);
    }
    setvbuf(stdout, NULL, _IOLBF, 0);
}

void bsp_exit(int code)
{
    fflush(stdout);
    exit(code);
}

int bsp_uart_getc_nonblock(void)
{
    if (host_uart_head == host_uart_tail) {
        return -1;
    }
    return (unsigned char)host_uart_in[host_uart_head++ % sizeof host_uart_in];
}

void bsp_uart_putc(char c)
{
    putchar(c);
}

static void host_type(const char *text)
{
    for (; *text != '\0'; text++) {
        if (host_uart_tail - host_uart_head < sizeof host_uart_in) {
            host_uart_in[host_uart_tail++ % sizeof host_uart_in] = *text;
        }
    }
}

/* host_rgb as frame host_frames_written of dir (frame_out.h). */
static void host_write_frame(const char *dir)
{
    if (frame_out_write(dir, (unsigned)host_frames_written, host_rgb, GPU_MODEL_SCREEN_W,
                        GPU_MODEL_SCREEN_H) != 0) {
        exit(1);
    }
}

static void host_doorbell(uint32_t offset, uint32_t value)
{
    const uint32_t frames_before = gpu_model_read(host_gpu, GPU_REG_FRAME_COUNT);

    host_doorbells++;
    for (uint32_t i = 0; i < host_cfg.key_events; i++) {
        const struct bsp_host_keys *k = &host_cfg.keys[i];

        if (k->frame ? host_frame_starts && k->at == host_swaps : k->at == host_doorbells) {
            host_type(k->text);
        }
    }
    gpu_model_write(host_gpu, offset, value);
    host_frame_starts = gpu_model_read(host_gpu, GPU_REG_FRAME_COUNT) != frames_before;
    if (host_frame_starts) {
        host_swaps++;
        if (host_cfg.frames_dir != NULL) {
            gpu_model_scanout(host_gpu, host_rgb);
            host_write_frame(host_cfg.frames_dir);
        }
        if (host_cfg.unquantised_dir != NULL) {
            gpu_model_scanout_unquantised(host_gpu, host_rgb);
            host_write_frame(host_cfg.unquantised_dir);
        }
        host_frames_written++;
    }
}

void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    if (offset == GPU_REG_DOORBELL) {
        host_doorbell(offset, value);
    } else {
        gpu_model_write(host_gpu, offset, value);
    }
}

uint32_t bsp_gpu_read(uint32_t offset)
{
    return gpu_model_read(host_gpu, offset);
}

void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++) {
        bsp_gpu_write(offset + 4u * i, src[i]);
    }
}
