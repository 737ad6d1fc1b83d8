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
    X(test_fx_sin_table_entries)      \
    X(test_cam_path_sin_entries)      \
    X(test_cam_path_sin_is_fx_sin)    \
    X(test_fx_angle_wrap)             \
    X(test_fx_recip_mantissa)         \
    X(test_fx_isqrt64)                \
    X(test_rv32_memset)               \
    X(test_q30_ops)                   \
    X(test_vec_rotation_conventions)  \
    X(test_vec_yaw_pitch_exact)       \
    X(test_vec_yaw_pitch_accuracy)    \
    X(test_vec_mat3_vs_double)        \
    X(test_vec_xf_apply_error)        \
    X(test_vec_xf_apply_box_exact)    \
    X(test_vec_triangle_normal)       \
    X(test_vec_direction_exact)       \
    X(test_vec_million_rotations)     \
    X(test_cam_pitch_limits)          \
    X(test_cam_fly_moves_and_clamps)  \
    X(test_cam_mode_cycle)            \
    X(test_cam_object_turns)          \
    X(test_input_key_map)             \
    X(test_input_escape_and_unknown)  \
    X(test_input_counts_saturate)     \
    X(test_usb_keys_same_as_uart)     \
    X(test_usb_keys_key_map)          \
    X(test_usb_keys_shift)            \
    X(test_usb_keys_releases_and_unknown) \
    X(test_usb_keys_sequence)         \
    X(test_usb_keys_decoders_independent) \
    X(test_usb_keys_repeat)           \
    X(test_proj_vs_double)            \
    X(test_proj_vertex_path_vs_double) \
    X(test_proj_near_plane)           \
    X(test_proj_focal_scaling)        \
    X(test_proj_outcodes)             \
    X(test_proj_guard_band)           \
    X(test_proj_depths)               \
    X(test_proj_inside_matches)       \
    X(test_clip_one_vertex_behind)    \
    X(test_clip_two_vertices_behind)  \
    X(test_clip_three_vertices_behind) \
    X(test_clip_vertex_on_plane)      \
    X(test_clip_guard_band)           \
    X(test_clip_random)               \
    X(test_sort_order_and_stability)  \
    X(test_sort_reverse_input)        \
    X(test_sort_small_without_scratch) \
    X(test_palette_ramps)             \
    X(test_palette_light_levels)      \
    X(test_palette_light_intensity)   \
    X(test_vertex_normal_average)     \
    X(test_scene_landscape_normals)   \
    X(test_scene_grid_cells)          \
    X(test_render_backface)           \
    X(test_render_mesh_model_range)   \
    X(test_render_level_cache)        \
    X(test_render_frustum_culling)    \
    X(test_render_near_clipping)      \
    X(test_render_painter_order)      \
    X(test_render_wireframe)          \
    X(test_render_lighting_and_colour) \
    X(test_render_overlay)            \
    X(test_render_capacity)           \
    X(test_render_inside_shortcut)    \
    X(test_render_lattice_loop)       \
    X(test_render_lattice_walk)       \
    X(test_render_lattice_projection) \
    X(test_render_quad_loop)          \
    X(test_batch_split_and_renumber)  \
    X(test_batch_shares_vertices)     \
    X(test_batch_outlines)            \
    X(test_batch_wide_frame)          \
    X(test_strips_match_brute_force)  \
    X(test_strips_batches)            \
    X(test_voxel_hidden_faces)        \
    X(test_voxel_chunk_border)        \
    X(test_voxel_worst_case)          \
    X(test_voxel_edit_marks_chunks)   \
    X(test_voxel_raycast)             \
    X(test_scene_meshes_valid)        \
    X(test_scene_object_range)        \
    X(test_scene_state_storage)       \
    X(test_scene_storage_refused)     \
    X(test_scene_capacities)          \
    X(test_scene_sizes)               \
    X(test_scene_frames)              \
    X(test_scene_cubes_wireframe_edges) \
    X(test_scene_voxel_place_break)   \
    X(test_scene_voxel_pool)          \
    X(test_gpu_native_words)          \
    X(test_gpu_init_checks)           \
    X(test_gpu_init_first_tag)        \
    X(test_gpu_submit)                \
    X(test_gpu_submit_in_place)       \
    X(test_gpu_submit_capacity)       \
    X(test_gpu_init_capacities)       \
    X(test_gpu_wait_timeout)          \
    X(test_gpu_tag_wrap)              \
    X(test_gpu_read_stats)            \
    X(test_gpu_reset)                 \
    X(test_crc32_vectors)             \
    X(test_meshfile_valid_and_loaded) \
    X(test_meshfile_rules)            \
    X(test_upload_transfer)           \
    X(test_upload_line_faults)        \
    X(test_upload_refusals)           \
    X(test_upload_sessions)           \
    X(test_upload_response_queue)

#define UNIT_DECLARE(name) void name(void);
UNIT_TESTS(UNIT_DECLARE)
#undef UNIT_DECLARE

#endif /* UNIT_H */
