/*
 * hot_path.h — compiler hints for the per-face and per-vertex loops, measured with `make bench-fw`
 * and `make profile-fw` (docs/firmware.md). Each says what the code does anyway; none changes a
 * result. GCC and Clang (every compiler of this firmware: rv32, MicroBlaze, the host) take them.
 * Like build_options.h, it includes nothing and any layer may include it.
 */
#ifndef CONFIG_HOT_PATH_H
#define CONFIG_HOT_PATH_H

/* The condition is seldom true: its code goes out of the straight path. */
#define FW_UNLIKELY(c) __builtin_expect(!!(c), 0)

/* Keep pointer p in one register from here on: GCC would otherwise re-form addresses from its parts
 * (the frame's vertex array and an object's first vertex) in every iteration of a loop. */
#define FW_ONE_REGISTER(p) __asm__("" : "+r"(p))

/* The compiler no longer knows v's value, so a product by v stays one multiply: GCC turns a
 * constant factor such as 12 into four shifts and adds, where rv32im's mul (pipelined on VexRiscv)
 * is one instruction. */
#define FW_AS_MULTIPLIER(v) __asm__("" : "+r"(v))

/* Code that builds meshes (a scene's start, a voxel edit, a model upload) rather than draws them:
 * optimised for size, out of the hot code's way (GCC's and Clang's `cold`). A one-scene image
 * must fit the SoC's 192 KiB, and no frame's drawing runs this code. */
#define FW_BUILD_ONCE __attribute__((cold))

/* Code a frame runs once or not at all (a spinning object's renormalisation, the walk over a
 * grid's objects): optimised for size as FW_BUILD_ONCE is, for the same reason. It costs a few
 * hundred instructions a frame (`make bench-fw`: the renormalisation 590-760), nothing next to
 * the per-vertex and per-face loops; code a frame runs per object or more stays fast. */
#define FW_ONCE_A_FRAME __attribute__((cold))

/* A zero-initialised object the frame loop works hard (the sort's digit slots): in a SoC build whose
 * firmware runs from the SDRAM (bsp/soc/bsp.mk sets FW_FAST_RAM), it goes to the on-chip RAM above
 * the boot program (linker/soc.ld's .fast, beside the stack), where a store takes a clock or two
 * instead of an SDRAM write's many; everywhere else it is ordinary .bss. The start-up zeroes it with
 * .bss (bsp/soc/crt0.c). */
#if defined(FW_FAST_RAM) && FW_FAST_RAM
#define FW_FAST_DATA __attribute__((section(".fast.bss")))
#else
#define FW_FAST_DATA
#endif

#endif /* CONFIG_HOT_PATH_H */
