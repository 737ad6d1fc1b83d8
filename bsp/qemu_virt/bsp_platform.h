/*
 * bsp_platform.h — QEMU `virt` (riscv32, rv32im, machine mode, no OS): the macros and the inline
 * half of the platform interface declared in bsp/bsp.h (which includes this file; include that
 * one). bsp.c, uart.c and trap.c define the rest.
 *
 * Memory map used here (QEMU 7.2 `virt`):
 *   0x0010_0000  sifive_test   (exit QEMU with a status)
 *   0x1000_0000  NS16550 UART  (stdin/stdout/stderr)
 *   0x8000_0000  RAM, 128 MiB; the firmware uses 0x8000_0000 .. 0x807F_FFFF (linker/qemu_virt.ld)
 *   0x8700_0000  GPU aperture, 128 KiB (guest RAM shared with the Verilator GPU in co-simulation)
 */
#ifndef BSP_PLATFORM_H
#define BSP_PLATFORM_H

#include <stdint.h>

#include "platform.h"  /* the memory map as numbers, shared with the co-simulation harness */

#define BSP_NAME      "qemu_virt"

/* Base address of the GPU's bus window (contract/gpu-contract.md, "Platforms"): 0x8700_0000. */
#define BSP_GPU_BASE  PLATFORM_GPU_BASE

/* Exit status used when a CPU trap (exception or unexpected interrupt) ends the program. */
#define BSP_EXIT_TRAP 126

/* The GPU window is memory (shared RAM in co-simulation): bsp_gpu_buffer never returns NULL, so
 * the firmware builds batches in place and has no staging arrays. */
#define BSP_GPU_BUFFERS_MAPPED 1

/* bsp_init (bsp.c): the trap vector (trap.c), the UART (uart.c). bsp_exit (bsp.c): the QEMU process
 * exits with status & 0xFF through sifive_test; a non-zero status that would read as 0 becomes 1.
 * bsp_uart_getc_nonblock, bsp_uart_putc (uart.c): the NS16550. */

/* Retired-instruction counter, 64 bits. minstreth is re-read to detect a carry out of minstret
 * between the two reads, so the pair is consistent. Exact and reproducible under -icount. */
static inline uint64_t bsp_instret(void)
{
    uint32_t hi;
    uint32_t lo;
    uint32_t hi2;

    do {
        __asm__ volatile("csrr %0, minstreth" : "=r"(hi));
        __asm__ volatile("csrr %0, minstret" : "=r"(lo));
        __asm__ volatile("csrr %0, minstreth" : "=r"(hi2));
    } while (hi != hi2);
    return ((uint64_t)hi << 32) | lo;
}

/* Cycle counter, 64 bits, read like bsp_instret. QEMU 7.2 implements mcycle; under -icount it
 * advances with the instruction count (so it is reproducible, but it is not a core's cycles). */
static inline uint64_t bsp_cycles(void)
{
    uint32_t hi;
    uint32_t lo;
    uint32_t hi2;

    do {
        __asm__ volatile("csrr %0, mcycleh" : "=r"(hi));
        __asm__ volatile("csrr %0, mcycle" : "=r"(lo));
        __asm__ volatile("csrr %0, mcycleh" : "=r"(hi2));
    } while (hi != hi2);
    return ((uint64_t)hi << 32) | lo;
}

/* The GPU's bus window: aligned 32-bit accesses at a byte offset from BSP_GPU_BASE (offsets from
 * gpu_regs.h). Every device access of the driver goes through these three. */
static inline void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    *(volatile uint32_t *)(uintptr_t)(BSP_GPU_BASE + offset) = value;
}

static inline uint32_t bsp_gpu_read(uint32_t offset)
{
    return *(volatile uint32_t *)(uintptr_t)(BSP_GPU_BASE + offset);
}

/* Copy n words to consecutive GPU addresses from offset on (vertex and index buffers). Unrolled
 * by four: the copy is a per-triangle cost of the frame loop. */
static inline void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    volatile uint32_t *dst = (volatile uint32_t *)(uintptr_t)(BSP_GPU_BASE + offset);
    uint32_t i = 0;

    for (; i + 4u <= n; i += 4u) {
        const uint32_t a = src[i];
        const uint32_t b = src[i + 1u];
        const uint32_t c = src[i + 2u];
        const uint32_t d = src[i + 3u];

        dst[i] = a;
        dst[i + 1u] = b;
        dst[i + 2u] = c;
        dst[i + 3u] = d;
    }
    for (; i < n; i++) {
        dst[i] = src[i];
    }
}

/* The GPU's vertex or index buffer at `offset` as ordinary CPU memory, or NULL where the platform
 * reaches the window only through the accessors above. Here the window is mapped (block RAM on a
 * board, shared RAM in co-simulation) and stores to the buffers have no side effects, so the
 * firmware may build a batch in place; bsp_fence() before DOORBELL orders those stores. */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    return (uint32_t *)(uintptr_t)(BSP_GPU_BASE + offset);
}

/* Full memory barrier (fence rw,rw): every earlier load/store is ordered before every later one.
 * The GPU driver uses it before ringing DOORBELL and after seeing DONE_SEQ. */
static inline void bsp_fence(void)
{
    __asm__ volatile("fence rw, rw" ::: "memory");
}

#endif /* BSP_PLATFORM_H */
