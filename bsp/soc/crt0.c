/*
 * crt0.c — the firmware's start on the SoC: what picolibc's crt0 "hosted" does (the stack and the
 * global pointer, .bss cleared, the TLS block, the constructors, exit(main())), for one reason
 * written here (bsp.mk links with -nostartfiles):
 *
 * picolibc's crt0 loads .bss's size from the absolute symbol __bss_size with lui/addi, which GNU ld
 * 2.40 (Debian 12's) relaxes to one gp-relative addi whenever the number is within 2 KiB of the
 * global pointer. On the SoC the RAM starts at 0, so a program's .bss size and its global pointer
 * (its .data's address + 2 KiB) are numbers of the same range; and as the linker's relaxation then
 * shrinks .text, the global pointer moves down while the absolute number stays: the link fails with
 * "relocation truncated to fit: R_RISCV_GPREL_I against symbol `__bss_size'" (a build whose .bss
 * was 6,612 bytes above the final global pointer did). Here .bss's extent comes from __bss_start
 * and __bss_end, addresses that move with the global pointer, and the start's own loads are not
 * relaxed.
 *
 * .data needs no copy: linker/soc.ld links it where it is loaded (the RAM's image, or the SDRAM's
 * image the boot program copies). The fast RAM's objects (linker/soc.ld's .fast, FW_FAST_DATA: a
 * build that runs from the SDRAM; empty in any other) are cleared with .bss.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern char __bss_start[], __bss_end[], __fast_start[], __fast_end[], __tls_base[];
extern void __libc_init_array(void);
extern void _set_tls(void *tls);  /* picolibc's (picotls.h declares it only where PICOLIBC_TLS is) */
extern int main(int argc, char **argv);
void bsp_cstart(void) __attribute__((noreturn, used));

__asm__("    .section .text.init.enter, \"ax\", @progbits\n"
        "    .global _start\n"
        "_start:\n"
        "    .option push\n"
        "    .option norelax\n"
        "    la    sp, __stack\n"
        "    la    gp, __global_pointer$\n"
        "    .option pop\n"
        "    j     bsp_cstart\n"
        "    .text\n");

void bsp_cstart(void)
{
    memset(__bss_start, 0, (size_t)(__bss_end - __bss_start));
    memset(__fast_start, 0, (size_t)(__fast_end - __fast_start));
    _set_tls(__tls_base);
    __libc_init_array();
    exit(main(0, NULL));
}
