/*
 * bsp_platform.h — QEMU `virt` (riscv32, rv32im, machine mode, no OS): the macros and the inline
 * half of the platform interface declared in bsp/bsp.h (which includes this file; include that
 * one). bsp.c and uart.c define the rest; rv32/ the parts every RV32 platform shares (the inline
 * counters and GPU accessors, the trap handler, the C streams on the UART).
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

/* bsp_init (bsp.c): the trap vector (rv32/trap.c), the UART (uart.c). bsp_exit (bsp.c): the QEMU process
 * exits with status & 0xFF through sifive_test; a non-zero status that would read as 0 becomes 1.
 * bsp_uart_getc_nonblock, bsp_uart_putc (uart.c): the NS16550. */

/* No USB host: no key events, no port (a program built with FW_USB_KEYBOARD reads the UART's
 * keys only). */
static inline int bsp_usb_key_nonblock(void)
{
    return -1;
}

static inline int bsp_usb_state(void)
{
    return -1;
}

/* Counters, fence and the memory-mapped GPU window: shared by the RV32 platforms. */
#include "rv32/rv32.h"

#endif /* BSP_PLATFORM_H */
