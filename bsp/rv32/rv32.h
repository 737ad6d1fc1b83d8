/*
 * rv32.h — the inline half of the platform interface (bsp/bsp.h) that every RV32 machine-mode
 * platform of this firmware shares: the counters, the fence and the memory-mapped GPU window.
 * A platform's bsp_platform.h defines BSP_GPU_BASE and then includes this file; the platforms
 * differ in their devices (UART, exit, traps), not in these.
 */
#ifndef BSP_RV32_H
#define BSP_RV32_H

#include <stdint.h>

#ifndef BSP_GPU_BASE
#error "define BSP_GPU_BASE before including rv32/rv32.h"
#endif

/* One memory-mapped register of a device: a 32-bit volatile word at base + offset. */
#define BSP_MMIO32(base, offset) (*(volatile uint32_t *)(uintptr_t)((base) + (offset)))

/* A 64-bit counter CSR pair read consistently: the high half is re-read to detect a carry out of
 * the low half between the two reads. */
#define BSP_READ_CSR64(lo, hi)                                                                 \
    __extension__({                                                                            \
        uint32_t h_;                                                                           \
        uint32_t l_;                                                                           \
        uint32_t h2_;                                                                          \
        do {                                                                                   \
            __asm__ volatile("csrr %0, " #hi : "=r"(h_));                                      \
            __asm__ volatile("csrr %0, " #lo : "=r"(l_));                                      \
            __asm__ volatile("csrr %0, " #hi : "=r"(h2_));                                     \
        } while (h_ != h2_);                                                                   \
        ((uint64_t)h_ << 32) | l_;                                                             \
    })

/* Retired instructions (minstret/minstreth), 64 bits: exact on a core, and under QEMU -icount. */
static inline uint64_t bsp_instret(void)
{
    return BSP_READ_CSR64(minstret, minstreth);
}

/* Clock cycles (mcycle/mcycleh), 64 bits. Under QEMU -icount they advance with the instruction
 * count (reproducible, but not a core's cycles); on the SoC they are the system clock's. */
static inline uint64_t bsp_cycles(void)
{
    return BSP_READ_CSR64(mcycle, mcycleh);
}

/* The GPU's bus window: aligned 32-bit accesses at a byte offset from BSP_GPU_BASE (offsets from
 * gpu_regs.h). Every device access of the driver goes through these three. */
static inline void bsp_gpu_write(uint32_t offset, uint32_t value)
{
    BSP_MMIO32(BSP_GPU_BASE, offset) = value;
}

static inline uint32_t bsp_gpu_read(uint32_t offset)
{
    return BSP_MMIO32(BSP_GPU_BASE, offset);
}

/* Copy n words to consecutive GPU addresses from offset on (staged batches only: with
 * BSP_GPU_BUFFERS_MAPPED the batch is written in place). Unrolled by four: where it is used it
 * is a per-triangle cost of the frame loop. */
static inline void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    volatile uint32_t *dst = &BSP_MMIO32(BSP_GPU_BASE, offset);
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

/* The GPU's vertex or index buffer at `offset` as CPU-writable memory (BSP_GPU_BUFFERS_MAPPED):
 * stores to the buffers have no side effects (block RAM on a board, shared RAM in co-simulation),
 * so batches are built in place; bsp_fence() before DOORBELL orders those stores. */
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

#endif /* BSP_RV32_H */
