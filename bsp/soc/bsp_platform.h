/*
 * bsp_platform.h — the FPGA SoC (soc_rtl/soc_top: VexRiscv_Full rv32im, machine mode, no OS): the
 * macros and the inline half of the platform interface declared in bsp/bsp.h (which includes this
 * file; include that one). bsp.c, uart.c, usb.c and trap.c define the rest; rv32/ the parts every
 * RV32 platform shares (the inline counters and GPU accessors, the trap handler, the C streams).
 *
 * Memory map (contract/soc_map.h, generated with the RTL's decoder, so both agree):
 *   0x0000_0000  on-chip RAM, SOC_RAM_BYTES (make SOC_RAM_KIB=..., default SOC_RAM_DEFAULT_BYTES):
 *                code, data, bss, stack at the top (linker/soc.ld); cached by the core's I$ / D$
 *   0x8000_0000  the GPU's 128 KiB bus window (uncached: the core bypasses its caches for bit 31)
 *   0x8100_0000  UART 115200 8N1            0x8200_0000  SYS: ID, clock, RAM size, EXIT, LEDs, mtime
 *   0x8500_0000  the USB keyboard host, in a SoC built with it (usb.c: touched only by a program
 *                built with FW_USB_KEYBOARD)
 * Any other address answers with a bus error, which SYS records and raises as an interrupt
 * (trap.c: the packaged VexRiscv ignores Wishbone ERR, so there is no precise access fault).
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

/* Counters, fence and the memory-mapped GPU window: shared by the RV32 platforms. */
#include "rv32/rv32.h"

#endif /* BSP_PLATFORM_H */
