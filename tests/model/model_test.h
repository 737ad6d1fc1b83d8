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

/* A freshly reset model (heap-allocated, ~1.2 MiB) with the default build
 * options (SPAN_W 8, lines, no depth buffer). Never returns NULL. */
gpu_model *test_new_model(void);

/* The same with the given build options. */
gpu_model *test_new_model_cfg(unsigned span_w, bool lines, bool zbuf);

/* Vertex i (absolute index) at Q12.4 (x, y), z = 0. */
void test_set_vtx(gpu_model *m, uint32_t i, int32_t x, int32_t y);

/* Vertex i (absolute index) at Q12.4 (x, y) with depth z (VTX_Z). */
void test_set_vtxz(gpu_model *m, uint32_t i, int32_t x, int32_t y,
                   uint32_t z);

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

/* Depth-buffer entry. */
uint16_t test_z(const gpu_model *m, int px, int py);

/* Check the back buffer holds `color` at exactly the n listed pixels and
 * `other` everywhere else; prints up to 8 differing pixels. */
bool test_check_pixels(const gpu_model *m, const int (*pix)[2], int n,
                       uint8_t color, uint8_t other, const char *file,
                       int line);

#define CHECK_PIXELS(m, list, color, other)                                \
    test_check_pixels((m), (list), (int)(sizeof(list) / sizeof((list)[0])), \
                      (color), (other), __FILE__, __LINE__)

/* Check the PERF_* counters of the last batch (PERF_BUSY_CYCLES and
 * PERF_SPANS_VISITED must read 0 in the model). */
void test_check_perf(const gpu_model *m, uint32_t in, uint32_t drawn,
                     uint32_t rejected, uint32_t pixels, uint32_t samples,
                     uint32_t spans, const char *file, int line);

#define CHECK_PERF6(m, in, drawn, rej, pix, smp, spans) \
    test_check_perf((m), (in), (drawn), (rej), (pix), (smp), (spans), \
                    __FILE__, __LINE__)

/* Deterministic xorshift32 random numbers for reproducible tests. */
uint32_t test_rand(void);
void test_srand(uint32_t seed);
/* Uniform in [lo, hi]. */
int32_t test_rand_range(int32_t lo, int32_t hi);

/* Test groups. */
void test_bus(void);
void test_batch_rules(void);
void test_raster(void);
void test_config(void);  /* test_config.c: CAPS, CTRL, RESET, spans */
void test_lines(void);   /* test_lines.c: the line rule */
void test_depth(void);   /* test_depth.c: the depth buffer */
void test_gouraud(void); /* test_gouraud.c: Gouraud triangles */
void test_gouraud_probe(void); /* test_gouraud.c: the shade probe, the unquantised scan-out */

#endif /* MODEL_TEST_H */
