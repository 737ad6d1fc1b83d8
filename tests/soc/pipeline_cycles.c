/*
 * pipeline_cycles.c — what VexRiscv_FullCfu's pipeline charges for the hazards the firmware's hot
 * loops meet (docs/soc.md, issue #27's CPI). Each case is a pair or short group of instructions
 * repeated PIPE_REPEAT times in a row (`.rept`), timed with mcycle (its second run: the
 * instruction cache warm), less the same count of plain adds: over the repeats, the case's extra
 * cycles a group. Its data word is in the data cache (loaded once before). Prints a line a case,
 * "pipeline: NAME EXTRA.EE", then "pipeline: done" (`make bench-cpu`,
 * tests/soc/pipeline_cycles.sh).
 */
#include <stdint.h>
#include <stdio.h>

#include "bsp.h"

#define PIPE_REPEAT 64
#define PIPE_STR2(x) #x
#define PIPE_STR(x) PIPE_STR2(x)

static volatile uint32_t pipe_word[8] = {1, 2, 3, 4, 5, 6, 7, 8};

/* One case: `body` (instructions separated by ";", on t0..t3 with a0 the data word's address)
 * PIPE_REPEAT times, run twice; the second run's cycles. */
#define PIPE_CASE(fn, body)                                                                        \
    static uint32_t fn(void)                                                                       \
    {                                                                                              \
        uint32_t cycles = 0;                                                                       \
        for (int run = 0; run < 2; run++) {                                                        \
            const uint64_t t0 = bsp_cycles();                                                      \
            __asm__ volatile("mv a0, %0\n"                                                         \
                             ".rept " PIPE_STR(PIPE_REPEAT) "\n" body "\n.endr\n"                 \
                             :                                                                     \
                             : "r"(pipe_word)                                                      \
                             : "a0", "t0", "t1", "t2", "t3", "ra", "memory");                    \
            const uint64_t t1 = bsp_cycles();                                                      \
            cycles = (uint32_t)(t1 - t0);                                                          \
        }                                                                                          \
        return cycles;                                                                             \
    }

/* Straight-line code with no hazard: the reference, one cycle an instruction if the core keeps
 * up. */
PIPE_CASE(pipe_add1, "add t0, t1, t2")
PIPE_CASE(pipe_add2, "add t0, t1, t2; add t1, t2, t3")
PIPE_CASE(pipe_add3, "add t0, t1, t2; add t1, t2, t3; add t2, t3, t3")
PIPE_CASE(pipe_add4, "add t0, t1, t2; add t1, t2, t3; add t2, t3, t3; add t3, t3, t3")
/* A chain: each add uses the one before (the bypass). */
PIPE_CASE(pipe_chain, "add t0, t0, t1; add t0, t0, t1")
/* A load and a use of its result by the next instruction, by the one after, two after. */
PIPE_CASE(pipe_load_use0, "lw t0, 0(a0); add t1, t0, t0")
PIPE_CASE(pipe_load_use1, "lw t0, 0(a0); add t2, t3, t3; add t1, t0, t0")
PIPE_CASE(pipe_load_use2, "lw t0, 0(a0); add t2, t3, t3; add t3, t2, t2; add t1, t0, t0")
/* A load's result as the next load's address (pointer chasing: a face's vertex look-up). */
PIPE_CASE(pipe_load_addr, "lw t0, 0(a0); add t0, a0, zero; lw t1, 0(t0)")
/* Independent loads back to back. */
PIPE_CASE(pipe_loads, "lw t0, 0(a0); lw t1, 4(a0)")
/* A multiply and a use of its result by the next instruction, by the one after, two after. */
PIPE_CASE(pipe_mul_use0, "mul t0, t1, t2; add t1, t0, t0")
PIPE_CASE(pipe_mul_use1, "mul t0, t1, t2; add t2, t3, t3; add t1, t0, t0")
PIPE_CASE(pipe_mul_use2, "mul t0, t1, t2; add t2, t3, t3; add t3, t2, t2; add t1, t0, t0")
PIPE_CASE(pipe_mulh_use0, "mulh t0, t1, t2; add t1, t0, t0")
/* Independent multiplies back to back. */
PIPE_CASE(pipe_muls, "mul t0, t1, t2; mul t3, t1, t2")
/* A store, and a store then a load of another word. */
PIPE_CASE(pipe_store, "sw t1, 8(a0); add t2, t3, t3")
PIPE_CASE(pipe_stores, "sw t1, 8(a0); sw t2, 12(a0)")
PIPE_CASE(pipe_store_load, "sw t1, 8(a0); lw t0, 0(a0)")
/* Branches: a forward branch taken (predicted not taken), not taken, a backward one not taken
 * (predicted taken), each over the next instruction's label; a jump. */
PIPE_CASE(pipe_fwd_taken, "beq zero, zero, 1f; 1: add t0, t1, t2")
PIPE_CASE(pipe_fwd_not, "bne zero, zero, 1f; 1: add t0, t1, t2")
PIPE_CASE(pipe_back_not, "1: add t0, t1, t2; bne zero, zero, 1b")
PIPE_CASE(pipe_jump, "j 1f; 1: add t0, t1, t2")

/* A backward branch taken (predicted taken): a loop of an add and the branch, PIPE_REPEAT times
 * round (its one `li` more than the adds it is compared with; the loop's last branch falls
 * through). */
static uint32_t pipe_back_taken(void)
{
    uint32_t cycles = 0;

    for (int run = 0; run < 2; run++) {
        const uint64_t t0 = bsp_cycles();
        __asm__ volatile("li t0, " PIPE_STR(PIPE_REPEAT) "\n"
                         "1: addi t0, t0, -1\n"
                         "bnez t0, 1b\n"
                         :
                         :
                         : "t0");
        const uint64_t t1 = bsp_cycles();
        cycles = (uint32_t)(t1 - t0);
    }
    return cycles;
}

/* A call and its return: `jal` to a function of one `ret`. */
PIPE_CASE(pipe_call, "jal ra, pipe_leaf")
__asm__(".text\n.align 2\npipe_leaf: ret\n");

struct pipe_case {
    const char *name;
    uint32_t (*run)(void);
    uint32_t instructions;  /* a group */
};

static const struct pipe_case pipe_cases[] = {
    {"chain", pipe_chain, 2},
    {"load_use_next", pipe_load_use0, 2},
    {"load_use_after_one", pipe_load_use1, 3},
    {"load_use_after_two", pipe_load_use2, 4},
    {"load_address", pipe_load_addr, 3},
    {"loads", pipe_loads, 2},
    {"mul_use_next", pipe_mul_use0, 2},
    {"mul_use_after_one", pipe_mul_use1, 3},
    {"mul_use_after_two", pipe_mul_use2, 4},
    {"mulh_use_next", pipe_mulh_use0, 2},
    {"muls", pipe_muls, 2},
    {"store", pipe_store, 2},
    {"stores", pipe_stores, 2},
    {"store_load", pipe_store_load, 2},
    {"branch_forward_taken", pipe_fwd_taken, 2},
    {"branch_forward_not_taken", pipe_fwd_not, 2},
    {"branch_backward_not_taken", pipe_back_not, 2},
    {"jump", pipe_jump, 2},
    {"branch_backward_taken", pipe_back_taken, 2},
    {"call_return", pipe_call, 2},
};

int main(void)
{
    uint32_t plain[5];

    bsp_init();
    (void)pipe_word[0];
    plain[0] = 0;
    plain[1] = pipe_add1();
    plain[2] = pipe_add2();
    plain[3] = pipe_add3();
    plain[4] = pipe_add4();
    /* The reference: n adds a group cost plain[n]; their slope must be one cycle an instruction. */
    printf("pipeline: adds %lu %lu %lu %lu cycles for %d groups of 1..4\n", (unsigned long)plain[1],
           (unsigned long)plain[2], (unsigned long)plain[3], (unsigned long)plain[4], PIPE_REPEAT);
    for (uint32_t i = 0; i < sizeof pipe_cases / sizeof pipe_cases[0]; i++) {
        const struct pipe_case *c = &pipe_cases[i];
        const int32_t extra = (int32_t)(c->run() - plain[c->instructions]);
        const int32_t hundredths = extra * 100 / PIPE_REPEAT;

        printf("pipeline: %s %s%ld.%02ld\n", c->name, (hundredths < 0) ? "-" : "",
               (long)((hundredths < 0 ? -hundredths : hundredths) / 100),
               (long)((hundredths < 0 ? -hundredths : hundredths) % 100));
    }
    printf("pipeline: done\n");
    return 0;
}
