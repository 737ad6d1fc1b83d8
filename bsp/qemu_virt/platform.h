/*
 * platform.h — the QEMU `virt` memory map as plain numbers, with no code, so that host programs
 * (the co-simulation harness) and the firmware's BSP agree on it from one place.
 */
#ifndef PLATFORM_H
#define PLATFORM_H

#define PLATFORM_RAM_BASE   0x80000000u  /* guest RAM, shared with the harness in co-simulation */
#define PLATFORM_RAM_BYTES  0x08000000u  /* 128 MiB: QEMU's -m and the shared file's size */
#define PLATFORM_GPU_BASE   0x87000000u  /* the GPU's 128 KiB bus window, inside guest RAM here */
#define PLATFORM_TEST_BASE  0x00100000u  /* sifive_test: ends QEMU with a status */
#define PLATFORM_UART_BASE  0x10000000u  /* NS16550 */

#endif
