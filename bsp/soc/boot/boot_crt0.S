/* The boot program's start (bsp/soc/boot/boot.c): the stack, the SDRAM's pins taken from LiteDRAM
 * before anything else (its refresher runs from reset and would send the chip a command 7.96 us,
 * under 400 clocks, after it: bsp/soc/sdram/sdram_init.h; sdram_take_pins needs no .data or .bss),
 * then a zeroed .bss and boot_main, which never returns (it jumps to the firmware or stops).
 * linker/soc.ld lays it out in the on-chip RAM. */
    .section .text.init.enter, "ax"
    .globl _start
_start:
    la    sp, __stack
    call  sdram_take_pins
    la    t0, __bss_start
    la    t1, __bss_end
1:  bgeu  t0, t1, 2f
    sw    zero, 0(t0)
    addi  t0, t0, 4
    j     1b
2:  call  boot_main
3:  j     3b
