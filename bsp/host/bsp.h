/*
 * bsp.h — board support for the host build: the same firmware, compiled for Linux, with the GPU
 * replaced by the bit-exact golden model (gpu_model/) and the UART by scripted keys. Same names
 * and meaning as every bsp.h (bsp/README.md); what differs:
 *
 *   - bsp_gpu_write/read go to a gpu_model instance; a DOORBELL write runs the whole batch at
 *     once, and every buffer swap is written as a PNG (640 x 480, the model's scan-out), numbered
 *     like the co-simulation's frames.
 *   - bsp_uart_getc_nonblock() returns keys scheduled with --keys-at N:TEXT, delivered just
 *     before the N-th doorbell is serviced — the co-simulation harness's rule, so a host run and a
 *     co-simulation run with the same key script render the same frames.
 *   - bsp_instret() has nothing to count and returns 0.
 *
 * bsp/host/host_main.c parses the options and calls app_run().
 */
#ifndef BSP_H
#define BSP_H

#include <stdint.h>

#define BSP_NAME      "host"
#define BSP_GPU_BASE  0u  /* offsets go straight to the model; printed only in error messages */
#define BSP_EXIT_TRAP 126

void bsp_init(void);
void bsp_exit(int code) __attribute__((noreturn));
int bsp_uart_getc_nonblock(void);
void bsp_uart_putc(char c);

static inline uint64_t bsp_instret(void)
{
    return 0u;
}

static inline void bsp_fence(void)
{
    __asm__ volatile("" ::: "memory");  /* the model runs in this thread: a compiler barrier */
}

void bsp_gpu_write(uint32_t offset, uint32_t value);
uint32_t bsp_gpu_read(uint32_t offset);
void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n);
/* NULL: the golden model's buffers are reached only through bsp_gpu_write (batches are staged). */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    (void)offset;
    return 0;
}

#endif /* BSP_H */
