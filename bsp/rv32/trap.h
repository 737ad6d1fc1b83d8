/*
 * rv32/trap.h — the machine-mode trap handler the RV32 platforms share (rv32/trap.c), and the two
 * hooks through which a platform adds what only it knows. Not part of the platform interface.
 */
#ifndef BSP_RV32_TRAP_H
#define BSP_RV32_TRAP_H

#include <stdint.h>

/* Point mtvec at the handler, then call rv32_trap_platform_enable(). From bsp_init(). */
void bsp_trap_install(void);

/* The handler's own output: straight to bsp_uart_putc, not stdio, so that it works when the fault
 * came from inside printf. For the platform's describe hook. */
void rv32_trap_puts(const char *s);
void rv32_trap_puthex(uint32_t v);

/* Defined by each platform. enable: the interrupts the platform reports as traps (none on
 * qemu_virt; the bus-error interrupt on the SoC). describe: write what the trap was, after
 * "TRAP: mcause=… mepc=… mtval=… (", and return 1 — or return 0 for the privileged spec's name of
 * mcause. */
void rv32_trap_platform_enable(void);
int rv32_trap_platform_describe(uint32_t mcause);

#endif /* BSP_RV32_TRAP_H */
