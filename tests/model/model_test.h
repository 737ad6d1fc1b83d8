/*
 * model_test.h - tiny self-contained test harness for the GPU model unit tests.
 *
 * CHECK* macros print one line per failed check (file:line and what failed)
 * and count passes/failures; main() in test_model.c prints
 * "N passed, N failed" and exits non-zero on any failure.
 */
#ifndef MODEL_TEST_H
#define MODEL_TEST_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "gpu_model.h"

extern unsigned test_passed;
extern unsigned test_failed;

/* Record one check; print a line when it fails.  Returns the condition so a
 * caller can stop early on a failure that would cascade. */
bool test_check(bool ok, const char *file, int line, const char *what);

#define CHECK(cond) test_check((cond), __FILE__, __LINE__, #cond)

/* Equality of two integers, printing both values on failure. */
bool test_check_eq(long long got, long long want, const char *file, int line,
                   const char *what);

#define CHECK_EQ(got, want) \
    test_check_eq((long long)(got), (long long)(want), __FILE__, __LINE__, \
                  #got " == " #want)

/* ---- helpers driving the model through its bus, like the firmware would */

/* A freshly reset model (heap-allocated, ~160 KiB). Never returns NULL. */
gpu_model *test_new_model(void);

/* Vertex i (absolute index) at Q12.4 (x, y), z = 0. */
void test_set_vtx(gpu_model *m, uint32_t i, int32_t x, int32_t y);

/* Primitive i (absolute index). */
void test_set_prim(gpu_model *m, uint32_t i, uint32_t i0, uint32_t i1,
                   uint32_t i2, uint32_t color, uint32_t kind);

/* Write the batch registers then the doorbell. */
void test_batch(gpu_model *m, uint32_t ctrl, uint32_t vtx_base,
                uint32_t vtx_count, uint32_t tri_base, uint32_t tri_count,
                uint32_t clear_color, uint32_t tag);

/* Clear the back buffer to 0 and draw one triangle of colour `color` from
 * vertices 0..2 (no swap).  Returns PERF_PIXELS. */
uint32_t test_draw_one(gpu_model *m, const int32_t xy[6], uint32_t color);

/* Back-buffer pixel. */
uint8_t test_back_px(const gpu_model *m, int px, int py);

/* Deterministic xorshift32 random numbers for reproducible tests. */
uint32_t test_rand(void);
void test_srand(uint32_t seed);
/* Uniform in [lo, hi]. */
int32_t test_rand_range(int32_t lo, int32_t hi);

/* Test groups. */
void test_bus(void);
void test_batch_rules(void);
void test_raster(void);

#endif /* MODEL_TEST_H */
