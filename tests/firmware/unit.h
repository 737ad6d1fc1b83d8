/*
 * unit.h — a tiny unit-test harness for the firmware's host tests.
 *
 * A test case is a void function; it fails when any CHECK in it fails. The runner (unit_main.c)
 * prints each failure with file:line, then the line "N passed, N failed" and exits non-zero if
 * anything failed.
 */
#ifndef UNIT_H
#define UNIT_H

#include <stdint.h>

void unit_fail(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#define CHECK(cond)                                                  \
    do {                                                             \
        if (!(cond)) {                                               \
            unit_fail(__FILE__, __LINE__, "CHECK(%s)", #cond);       \
        }                                                            \
    } while (0)

#define CHECK_EQ(a, b)                                                                     \
    do {                                                                                   \
        const long long unit_a_ = (long long)(a);                                          \
        const long long unit_b_ = (long long)(b);                                          \
        if (unit_a_ != unit_b_) {                                                          \
            unit_fail(__FILE__, __LINE__, "%s == %s: %lld (0x%llx) != %lld (0x%llx)", #a, \
                      #b, unit_a_, (unsigned long long)unit_a_, unit_b_,                   \
                      (unsigned long long)unit_b_);                                        \
        }                                                                                  \
    } while (0)

/* Deterministic pseudo-random numbers (xorshift32), so failures reproduce. */
uint32_t unit_rand(void);
void unit_srand(uint32_t seed);

/* The test cases, one X(name) per case; each file defines its own. */
#define UNIT_TESTS(X)                 \
    X(test_fx_mul_basic)              \
    X(test_fx_mul_rounding_random)    \
    X(test_fx_mul_saturation)         \
    X(test_fx_overflow_sticky)        \
    X(test_fx_add_sub_saturation)     \
    X(test_fx_div)                    \
    X(test_fx_div_saturation)         \
    X(test_fx_round_to_int)           \
    X(test_fx_sin_cos_exact_points)   \
    X(test_fx_sin_cos_vs_libm)        \
    X(test_fx_angle_wrap)             \
    X(test_xf_rotation)               \
    X(test_render_project_vs_double) \
    X(test_render_project_near)       \
    X(test_render_project_range)      \
    X(test_render_signed_area)        \
    X(test_render_sort)               \
    X(test_render_sort_random)        \
    X(test_scene_mesh_valid)          \
    X(test_render_cull_vs_geometry)   \
    X(test_render_frame_output)       \
    X(test_gpu_pack_vertex)           \
    X(test_gpu_pack_prim)             \
    X(test_gpu_init_checks)           \
    X(test_gpu_init_first_tag)        \
    X(test_gpu_submit)                \
    X(test_gpu_submit_capacity)       \
    X(test_gpu_wait_timeout)          \
    X(test_gpu_tag_wrap)              \
    X(test_gpu_read_stats)

#define UNIT_DECLARE(name) void name(void);
UNIT_TESTS(UNIT_DECLARE)
#undef UNIT_DECLARE

#endif /* UNIT_H */
