/*
 * poll_cycles.c — what one DONE_SEQ poll of the GPU driver's watchdog costs on the SoC, in clock
 * cycles: gpu_wait() (firmware/gpu/gpu.c, the loop the frame loop runs) for a tag that never comes,
 * timed with mcycle. Each poll is an uncached load over the Wishbone bus to the GPU plus the loop.
 * Prints "poll_cycles: N polls in C cycles: P.PP cycles per poll" (tests/soc/poll_cycles.sh), which
 * sizes the soc platform's FW_MAX_POLLS default (about one second at 50 MHz, bsp/soc/bsp.mk).
 */
#include <stdint.h>
#include <stdio.h>

#include "bsp.h"
#include "gpu/gpu.h"

#define POLL_COUNT 10000u

int main(void)
{
    struct gpu_dev dev = {0};
    uint64_t t0;
    uint64_t t1;
    uint32_t cycles;
    int rc;

    bsp_init();
    t0 = bsp_cycles();
    rc = gpu_wait(&dev, 0xFFFFFFFFu, POLL_COUNT);  /* DONE_SEQ is 0 after reset: never this tag */
    t1 = bsp_cycles();
    cycles = (uint32_t)(t1 - t0);
    printf("poll_cycles: %lu polls in %lu cycles: %lu.%02lu cycles per poll (%s)\n",
           (unsigned long)POLL_COUNT, (unsigned long)cycles, (unsigned long)(cycles / POLL_COUNT),
           (unsigned long)((cycles % POLL_COUNT) * 100u / POLL_COUNT),
           rc == GPU_E_TIMEOUT ? "timed out as expected" : "unexpected return");
    return rc == GPU_E_TIMEOUT ? 0 : 1;
}
