/*
 * fuzz_common.h — what the C fuzz harnesses share: REQUIRE, which reports a violated property
 * (where, the condition, a formatted detail) and aborts so that libFuzzer saves the input, and the
 * reader that consumes the fuzz input from the front (reads past the end give 0).
 */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define REQUIRE(cond, ...)                                                                \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            fprintf(stderr, "%s:%d: %s: ", __FILE__, __LINE__, #cond);                    \
            fprintf(stderr, __VA_ARGS__);                                                 \
            fprintf(stderr, "\n");                                                        \
            abort();                                                                      \
        }                                                                                 \
    } while (0)

struct reader {
    const uint8_t *p;
    size_t n;
};

static inline uint32_t take8(struct reader *r)
{
    if (r->n == 0u) {
        return 0u;
    }
    r->n--;
    return *r->p++;
}

static inline uint32_t take16(struct reader *r)
{
    const uint32_t lo = take8(r);
    return lo | take8(r) << 8;
}

static inline uint32_t take32(struct reader *r)
{
    const uint32_t lo = take16(r);
    return lo | take16(r) << 16;
}

#endif /* FUZZ_COMMON_H */
