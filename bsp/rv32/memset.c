/*
 * rv32/memset.c — memset for the rv32 platforms, in place of picolibc's, which this toolchain
 * builds for size: a byte a store, 4 instructions a byte. crt0 clears .bss with it before main,
 * and the firmware's memory is most of the RAM: measured in QEMU, the knot's bench build spent
 * 3.25 M instructions (36 % of its start-up) there; an SDRAM build with the model scene's SDRAM
 * capacities clears megabytes. This one stores words from a word-aligned start: 3 instructions for
 * 4 bytes (a store, an add, a branch), and bytes otherwise (small: the one-scene builds are sized
 * to the byte). The same C semantics; the unit test (tests/firmware/test_memset.c) compares it
 * with the host's memset over every alignment and length up to 80 bytes and some longer ones.
 */
#include <stddef.h>
#include <stdint.h>

/* The name it is built under: the C library's, which it replaces at link time (the firmware's
 * objects come before libc), or another for the unit test. */
#ifndef BSP_MEMSET_NAME
#define BSP_MEMSET_NAME memset
#endif

/* Word stores into memory of any type, as a C library's memset does. */
typedef uint32_t __attribute__((may_alias)) memset_word;

void *BSP_MEMSET_NAME(void *dst, int c, size_t n);

/* Without loop-pattern distribution: GCC would turn these loops into a call to memset, itself. */
__attribute__((optimize("no-tree-loop-distribute-patterns")))
void *BSP_MEMSET_NAME(void *dst, int c, size_t n)
{
    unsigned char *p = dst;
    const unsigned char byte = (unsigned char)c;

    if (((uintptr_t)p & 3u) == 0u) {  /* word-aligned, as .bss and the firmware's structures are */
        const uint32_t word = 0x01010101u * byte;

        for (; n >= 4u; n -= 4u, p += 4) {
            *(memset_word *)(void *)p = word;
        }
    }
    while (n > 0u) {  /* the tail, or all of an unaligned range */
        *p++ = byte;
        n--;
    }
    return dst;
}
