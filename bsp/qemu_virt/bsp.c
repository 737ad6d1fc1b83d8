/*
 * bsp.c — start-up and exit for QEMU `virt` (riscv32, machine mode); its trap hooks.
 *
 * Exit goes through QEMU's sifive_test device: 0x5555 ends QEMU with status 0, (code << 16) | 0x3333
 * ends it with status `code`. picolibc's exit() lands in _exit() below, so exit(n) and a return
 * from main() (crt0 "hosted") both end QEMU with status n.
 */
#include <stdint.h>

#include "bsp.h"
#include "bsp_internal.h"

#define SIFIVE_TEST_BASE PLATFORM_TEST_BASE
#define SIFIVE_TEST_PASS 0x5555u
#define SIFIVE_TEST_FAIL 0x3333u

void bsp_init(void)
{
    bsp_trap_install();
    bsp_uart_init();
}

void bsp_exit(int code)
{
    volatile uint32_t *test = (volatile uint32_t *)SIFIVE_TEST_BASE;
    uint32_t status = (uint32_t)code & 0xFFFFu;

    if (code != 0 && (status & 0xFFu) == 0u) {
        status = 1u;  /* the host only sees the low 8 bits: never turn a failure into success */
    }
    if (status == 0u) {
        *test = SIFIVE_TEST_PASS;
    } else {
        *test = (status << 16) | SIFIVE_TEST_FAIL;
    }
    for (;;) {
        __asm__ volatile("wfi");
    }
}

/* picolibc's exit() calls this after running atexit handlers. */
void _exit(int status) __attribute__((noreturn));
void _exit(int status)
{
    bsp_exit(status);
}

/* The trap handler (rv32/trap.c) needs no interrupt here and names every cause by the spec. */
void rv32_trap_platform_enable(void)
{
}

int rv32_trap_platform_describe(uint32_t mcause)
{
    (void)mcause;
    return 0;
}
