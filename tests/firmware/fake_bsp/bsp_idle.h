/*
 * bsp_idle.h — the part of bsp/bsp.h's interface that the test doubles leave idle: nothing to
 * initialise, an empty console (no key ever waiting, output dropped), no USB keyboard, and
 * nothing counted (instructions and cycles read 0). Included by the unit tests' bsp_platform.h
 * (this folder) and the driver fuzzer's (tests/fuzz/driver_bsp/), which differ only in their GPU
 * bus and bsp_exit.
 */
#ifndef BSP_IDLE_H
#define BSP_IDLE_H

#include <stdint.h>

static inline void bsp_init(void)
{
}

static inline int bsp_uart_getc_nonblock(void)
{
    return -1;
}

static inline void bsp_uart_putc(char c)
{
    (void)c;
}

static inline int bsp_usb_key_nonblock(void)
{
    return -1;
}

static inline int bsp_usb_state(void)
{
    return -1;
}

static inline uint64_t bsp_instret(void)
{
    return 0u;
}

/* No cycles either: 0. */
static inline uint64_t bsp_cycles(void)
{
    return 0u;
}

#endif /* BSP_IDLE_H */
