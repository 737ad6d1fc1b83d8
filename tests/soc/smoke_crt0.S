/* The smoke program's start: stack, zeroed .bss, main; its return value goes to SYS EXIT. */
    .section .text.init.enter, "ax"
    .globl _start
_start:
    la    sp, __stack
    la    t0, __bss_start
    la    t1, __bss_end
1:  bgeu  t0, t1, 2f
    sw    zero, 0(t0)
    addi  t0, t0, 4
    j     1b
2:  call  main
    call  smoke_exit
3:  j     3b
