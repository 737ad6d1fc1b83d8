/*
 * bsp_platform.h — the FPGA SoC (soc_rtl/soc_top: VexRiscv_Full rv32im, machine mode, no OS): the
 * macros and the inline half of the platform interface declared in bsp/bsp.h (which includes this
 * file; include that one). bsp.c, uart.c and trap.c define the rest.
 *
 * Memory map (contract/soc_map.h, generated with the RTL's decoder, so both agree):
 *   0x0000_0000  on-chip RAM, SOC_RAM_BYTES (make SOC_RAM_KIB=..., default SOC_RAM_DEFAULT_BYTES):
 *                code, data, bss, stack at the top (linker/soc.ld); cached by the core's I$ / D$
 *   0x8000_0000  the GPU's 128 KiB bus window (uncached: the core bypasses its caches for bit 31)
 *   0x8100_0000  UART 115200 8N1            0x8200_0000  SYS: ID, clock, RAM size, EXIT, LEDs, mtime
 * Any other address answers with a bus error: a load or store access fault (trap.c).
 */
#ifndef BSP_PLATFORM_H
#define BSP_PLATFORM_H

#include <stdint.h>

#include "soc_map.h"

#define BSP_NAME      "soc"

/* Base address of the GPU's bus window (contract/gpu-contract.md, "Platforms"). */
#define BSP_GPU_BASE  SOC_GPU_BASE

/* Exit status used when a CPU trap (exception or unexpected interrupt) ends the program: the same
 * as qemu_virt's, so tests read one number. */
#define BSP_EXIT_TRAP 126

/* bsp_gpu_buffer() returns CPU-writable memory: the window's buffers answer stores like RAM
 * (reads of them are not promised), and a store has no side effect, so batches are built in place. */
#define BSP_GPU_BUFFERS_MAPPED 1

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

/* Retired instructions (minstret/minstreth), 64 bits: exact in the core and in socsim. */
static inline uint64_t bsp_instret(void)
{
    return BSP_READ_CSR64(minstret, minstreth);
}

/* Clock cycles since reset (mcycle/mcycleh), 64 bits, at SOC_SYS_REG_CLK_HZ. */
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

/* Copy n words to consecutive GPU addresses from offset on (used only for staged batches; with
 * BSP_GPU_BUFFERS_MAPPED the batch is written in place). */
static inline void bsp_gpu_write_words(uint32_t offset, const uint32_t *src, uint32_t n)
{
    volatile uint32_t *dst = &BSP_MMIO32(BSP_GPU_BASE, offset);

    for (uint32_t i = 0; i < n; i++) {
        dst[i] = src[i];
    }
}

/* The GPU's vertex or index buffer at `offset` as CPU-writable memory (BSP_GPU_BUFFERS_MAPPED):
 * each store is one uncached bus write into the GPU's buffer RAM; bsp_fence() before DOORBELL
 * orders them. */
static inline uint32_t *bsp_gpu_buffer(uint32_t offset)
{
    return (uint32_t *)(uintptr_t)(BSP_GPU_BASE + offset);
}

/* Full memory barrier (fence rw,rw). VexRiscv keeps uncached I/O accesses in program order and
 * its write-through D$ never holds a GPU word, so this also orders the doorbell after the buffers. */
static inline void bsp_fence(void)
{
    __asm__ volatile("fence rw, rw" ::: "memory");
}

#endif /* BSP_PLATFORM_H */
