/*
 * main.c — the walking skeleton: a rotating tetrahedron, one GPU batch per frame.
 *
 * Per frame: build the vertex/primitive words (render.c, pure), submit them as one batch with
 * CLEAR|SWAP, wait for DONE_SEQ, read the GPU's counters, print one line:
 *
 *   frame %u: tris submitted %u drawn %u | fw instr %lu | gpu cycles %lu | errors 0x%x
 *
 * "fw instr" is the retired-instruction count of the frame's CPU work — build, submit, reading
 * the counters back — without the DONE_SEQ polling and without the printing, so it is
 * reproducible under QEMU -icount whatever the GPU's speed.
 *
 * Only this file and gpu.c touch the platform (bsp.h).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bsp.h"
#include "fixed.h"
#include "fw_config.h"
#include "gpu.h"
#include "render.h"
#include "scene.h"
#include "xform.h"

static void fw_fail(int status) __attribute__((noreturn));
static void fw_fail(int status)
{
    fflush(stdout);
    exit(status);
}

static void report_init_error(int rc, const struct gpu_info *info)
{
    switch (rc) {
    case GPU_E_NOT_FOUND:
        printf("error: GPU not found (ID=0x%08lx, expected 0x%08lx at 0x%08lx)\n",
               (unsigned long)info->id, (unsigned long)GPU_ID_VALUE,
               (unsigned long)BSP_GPU_BASE);
        break;
    case GPU_E_VERSION:
        printf("error: unsupported GPU contract version (VERSION=0x%08lx, firmware built for "
               "0x%08lx)\n",
               (unsigned long)info->version, (unsigned long)GPU_VERSION_VALUE);
        break;
    case GPU_E_GEOMETRY:
        printf("error: unexpected framebuffer size (FB_SIZE=0x%08lx, expected %lux%lu)\n",
               (unsigned long)info->fb_size, (unsigned long)GPU_FB_WIDTH,
               (unsigned long)GPU_FB_HEIGHT);
        break;
    default:
        printf("error: GPU init failed: %s (%d)\n", gpu_strerror(rc), rc);
        break;
    }
}

static void report_gpu_errors(unsigned frame, uint32_t errors)
{
    printf("error: GPU reported ERRORS=0x%lx in frame %u:%s%s%s%s\n", (unsigned long)errors,
           frame, (errors & GPU_ERR_VTX_INDEX_MASK) ? " VTX_INDEX" : "",
           (errors & GPU_ERR_COUNT_MASK) ? " COUNT" : "",
           (errors & GPU_ERR_KIND_MASK) ? " KIND" : "",
           (errors & GPU_ERR_WRITE_BUSY_MASK) ? " WRITE_BUSY" : "");
}

int main(void)
{
    static struct render_frame frame_buf;  /* ~2 KiB: static rather than on the stack */
    struct gpu_dev gpu;
    struct gpu_stats stats;
    struct gpu_batch batch;
    xf_mat3 rot;
    fx_angle yaw = SCENE_YAW0;
    fx_angle pitch = SCENE_PITCH0;
    int rc;

    bsp_init();

    rc = gpu_init(&gpu, scene_palette, SCENE_PAL_COUNT);
    printf("tetra fw (%s): GPU id 0x%08lx version 0x%08lx caps 0x%08lx vtx_cap %lu tri_cap %lu "
           "fb %lux%lu | frames %u\n",
           BSP_NAME, (unsigned long)gpu.info.id, (unsigned long)gpu.info.version,
           (unsigned long)gpu.info.caps, (unsigned long)gpu.info.vtx_cap,
           (unsigned long)gpu.info.tri_cap, (unsigned long)(gpu.info.fb_size & 0xFFFFu),
           (unsigned long)(gpu.info.fb_size >> 16),
           (unsigned)FW_FRAMES);
    if (rc != GPU_OK) {
        report_init_error(rc, &gpu.info);
        fw_fail(FW_EXIT_GPU_INIT);
    }

    batch.vtx_words = frame_buf.vtx_words;
    batch.vtx_base = 0;
    batch.prim_words = frame_buf.prim_words;
    batch.tri_base = 0;
    batch.ctrl = GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK;
    batch.clear_color = SCENE_PAL_BG;

    for (unsigned frame = 0; frame < (unsigned)FW_FRAMES; frame++) {
        uint64_t t_start;
        uint64_t t_submitted;
        uint64_t t_done;
        uint64_t t_end;
        uint32_t tag;

        t_start = bsp_instret();
        xf_rot_yx(&rot, yaw, pitch);
        render_mesh_frame(&scene_tetra, &rot, scene_model_pos, &scene_camera, &frame_buf);
        batch.vtx_count = frame_buf.vtx_count;
        batch.prim_count = frame_buf.prim_count;
        rc = gpu_submit_batch(&gpu, &batch, &tag);
        if (rc != GPU_OK) {
            printf("error: frame %u: batch not submitted: %s\n", frame, gpu_strerror(rc));
            fw_fail(FW_EXIT_GPU_SUBMIT);
        }
        t_submitted = bsp_instret();

        rc = gpu_wait(&gpu, tag, FW_GPU_MAX_POLLS);
        t_done = bsp_instret();
        if (rc != GPU_OK) {
            printf("error: frame %u: GPU timeout: DONE_SEQ=0x%08lx, expected tag 0x%08lx after "
                   "%lu polls\n",
                   frame, (unsigned long)gpu.last_done_seq, (unsigned long)tag,
                   (unsigned long)FW_GPU_MAX_POLLS);
            fw_fail(FW_EXIT_GPU_TIMEOUT);
        }
        gpu_read_stats(&gpu, &stats);
        t_end = bsp_instret();

        printf("frame %u: tris submitted %u drawn %u | fw instr %lu | gpu cycles %lu | "
               "errors 0x%x\n",
               frame, (unsigned)scene_tetra.face_count, (unsigned)stats.tris_drawn,
               (unsigned long)((t_submitted - t_start) + (t_end - t_done)),
               (unsigned long)stats.busy_cycles, (unsigned)stats.errors);
        if (stats.errors != 0u) {
            report_gpu_errors(frame, stats.errors);
            fw_fail(FW_EXIT_GPU_ERRORS);
        }
        if (fx_overflow_count() != 0u) {
            printf("error: frame %u: %lu fixed-point overflow(s): a range argument failed\n",
                   frame, (unsigned long)fx_overflow_count());
            fw_fail(FW_EXIT_FX_OVERFLOW);
        }

        yaw = (fx_angle)(yaw + SCENE_YAW_STEP);
        pitch = (fx_angle)(pitch + SCENE_PITCH_STEP);
    }

    exit(FW_EXIT_OK);
}
