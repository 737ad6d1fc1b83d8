/*
 * test_gpu.c — the driver: the word layout per the contract macros (pure core) and, against a fake
 * aperture (fake_bsp/bsp_platform.h), init checks, tags, batch programming, fencing and timeouts.
 */
#include <stdint.h>
#include <string.h>

#include "bsp.h"
#include "gpu/gpu.h"
#include "render/proj.h"
#include "render/render.h"
#include "unit.h"

uint32_t fake_gpu_mem[FAKE_GPU_WORDS];
uint32_t fake_fence_count;
uint32_t fake_regs_at_fence[FAKE_REG_WORDS];
uint32_t fake_write_count;

void fake_bsp_fence(void)
{
    fake_fence_count++;
    memcpy(fake_regs_at_fence, fake_gpu_mem, sizeof fake_regs_at_fence);
}

#define REG(off) fake_gpu_mem[(off) / 4u]

/* The smallest batch the driver takes: one vertex, no primitives (the tests of tags, waits and
 * resets, where what is drawn does not matter). */
static const uint32_t test_gpu_tiny_words[2] = {0};
static const struct gpu_batch test_gpu_tiny_batch = {
    .vtx_words = test_gpu_tiny_words, .vtx_base = 0, .vtx_count = 1,
    .prim_words = test_gpu_tiny_words, .tri_base = 0, .prim_count = 0,
    .ctrl = 0, .clear_color = 0, .strip = GPU_STRIP_WHOLE,
};

/* A device as the contract describes it after reset. */
static void fake_reset(void)
{
    memset(fake_gpu_mem, 0, sizeof fake_gpu_mem);
    memset(fake_regs_at_fence, 0, sizeof fake_regs_at_fence);
    fake_fence_count = 0;
    fake_write_count = 0;
    REG(GPU_REG_ID) = GPU_ID_VALUE;
    REG(GPU_REG_VERSION) = GPU_VERSION_VALUE;
    REG(GPU_REG_CAPS) = 1u << GPU_CAPS_SPAN_W_LSB;
    REG(GPU_REG_VTX_CAP) = GPU_VTX_CAP;
    REG(GPU_REG_TRI_CAP) = GPU_TRI_CAP;
    REG(GPU_REG_FB_SIZE) = (GPU_FB_HEIGHT << 16) | GPU_FB_WIDTH;
}

static const uint16_t test_palette[3] = {0x000, 0x123, 0xFA5};

/* The driver brought up on a device just reset whose DOORBELL and DONE_SEQ read the given values
 * (as after earlier batches). Returns gpu_init's result. */
static int init_at_seq(struct gpu_dev *dev, uint32_t doorbell, uint32_t done_seq,
                       const uint16_t *palette, uint32_t n)
{
    fake_reset();
    REG(GPU_REG_DOORBELL) = doorbell;
    REG(GPU_REG_DONE_SEQ) = done_seq;
    return gpu_init(dev, palette, n);
}

/* The words batch.c copies are the contract's: proj_vertex's first word decodes, through the
 * contract's field definitions, to its x and y (sign-extended), render_prim's two words to its
 * indices, colour and kind (a narrow frame's primitive: a wide one has no such words, render.h). */
void test_gpu_native_words(void)
{
    const int16_t xs[] = {0, 1, -1, 2560, -32768, 32767, -16};
    struct render_prim p;

    for (unsigned i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        for (unsigned j = 0; j < sizeof xs / sizeof xs[0]; j++) {
            struct proj_vertex v;
            uint32_t w[GPU_VTX_WORDS];

            memset(&v, 0, sizeof v);
            proj_vertex_store(&v, xs[i], xs[j], i * 1000u + j, 77u);
            w[0] = v.sxy;
            w[1] = v.zbuf;
            CHECK_EQ((int16_t)((w[GPU_VTX_X_WORD] >> GPU_VTX_X_LSB) & GPU_VTX_X_MASK), xs[i]);
            CHECK_EQ((int16_t)((w[GPU_VTX_Y_WORD] >> GPU_VTX_Y_LSB) & GPU_VTX_Y_MASK), xs[j]);
            CHECK_EQ((w[GPU_VTX_Z_WORD] >> GPU_VTX_Z_LSB) & GPU_VTX_Z_MASK, i * 1000u + j);
        }
    }
#if !FW_RENDER_WIDE_INDEX
    p.v[0] = 0xFFFF;
    p.v[1] = 0x8000;
    p.v[2] = 1023;
    p.color = 0xA5;
    p.kind = GPU_PRIM_KIND_LINE;
    CHECK_EQ((p.w[GPU_PRIM_I0_WORD] >> GPU_PRIM_I0_LSB) & GPU_PRIM_I0_MASK, 0xFFFFu);
    CHECK_EQ((p.w[GPU_PRIM_I1_WORD] >> GPU_PRIM_I1_LSB) & GPU_PRIM_I1_MASK, 0x8000u);
    CHECK_EQ((p.w[GPU_PRIM_I2_WORD] >> GPU_PRIM_I2_LSB) & GPU_PRIM_I2_MASK, 1023u);
    CHECK_EQ((p.w[GPU_PRIM_COLOR_WORD] >> GPU_PRIM_COLOR_LSB) & GPU_PRIM_COLOR_MASK, 0xA5u);
    CHECK_EQ((p.w[GPU_PRIM_KIND_WORD] >> GPU_PRIM_KIND_LSB) & GPU_PRIM_KIND_MASK,
             GPU_PRIM_KIND_LINE);
#else
    (void)p;
#endif
}

void test_gpu_init_checks(void)
{
    struct gpu_dev dev;

    /* Nothing there: ID reads 0. */
    memset(fake_gpu_mem, 0, sizeof fake_gpu_mem);
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_E_NOT_FOUND);
    CHECK_EQ(dev.info.id, 0);
    CHECK_EQ(REG(GPU_WIN_PALETTE + 4u), 0);  /* nothing written to a device that is not ours */

    fake_reset();
    REG(GPU_REG_VERSION) = GPU_VERSION_VALUE + 0x10000u;  /* next major */
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_E_VERSION);
    CHECK_EQ(dev.info.version, GPU_VERSION_VALUE + 0x10000u);
    fake_reset();
    REG(GPU_REG_VERSION) = GPU_VERSION_VALUE + 1u;  /* newer minor: fine */
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);

    /* Any frame up to the contract's largest is drawn at its own size; an empty or larger one is
     * refused. */
    fake_reset();
    REG(GPU_REG_FB_SIZE) = (GPU_FB_MAX_HEIGHT << 16) | GPU_FB_MAX_WIDTH;
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);
    CHECK_EQ(gpu_fb_width(&dev.info), GPU_FB_MAX_WIDTH);
    CHECK_EQ(gpu_fb_height(&dev.info), GPU_FB_MAX_HEIGHT);
    {
        static const uint32_t bad[] = {
            ((GPU_FB_MAX_HEIGHT + 1u) << 16) | GPU_FB_WIDTH,
            (GPU_FB_HEIGHT << 16) | (GPU_FB_MAX_WIDTH + 1u),
            GPU_FB_WIDTH,                 /* no lines */
            GPU_FB_HEIGHT << 16,          /* no columns */
            0xFFFFFFFFu,
        };

        for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            fake_reset();
            REG(GPU_REG_FB_SIZE) = bad[i];
            CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_E_GEOMETRY);
            CHECK_EQ(REG(GPU_WIN_PALETTE + 4u), 0);  /* nothing written */
        }
    }

    fake_reset();
    CHECK_EQ(gpu_init(&dev, test_palette, GPU_PALETTE_ENTRIES + 1u), GPU_E_ARG);

    fake_reset();
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);
    CHECK_EQ(dev.info.id, GPU_ID_VALUE);
    CHECK_EQ(dev.info.vtx_cap, GPU_VTX_CAP);
    CHECK_EQ(dev.info.tri_cap, GPU_TRI_CAP);
    CHECK_EQ(dev.info.caps, 1u << GPU_CAPS_SPAN_W_LSB);
    CHECK_EQ(REG(GPU_WIN_PALETTE + 0u), 0x000u);
    CHECK_EQ(REG(GPU_WIN_PALETTE + 4u), 0x123u);
    CHECK_EQ(REG(GPU_WIN_PALETTE + 8u), 0xFA5u);
    CHECK_EQ(REG(GPU_WIN_PALETTE + 12u), 0u);
    CHECK(dev.pending == false);
    CHECK(gpu_strerror(GPU_E_NOT_FOUND)[0] != '\0');
    CHECK(gpu_strerror(12345)[0] != '\0');
}

/* The first tag differs from DOORBELL (an equal store would be invisible in co-simulation) and
 * from DONE_SEQ (gpu_wait would return at once), and is never 0. */
void test_gpu_init_first_tag(void)
{
    static const uint32_t cases[][3] = {
        /* DOORBELL, DONE_SEQ, expected first tag */
        {0u, 0u, 1u},
        {7u, 7u, 8u},
        {7u, 8u, 9u},
        {0xFFFFFFFFu, 0xFFFFFFFFu, 1u},
        {0xFFFFFFFFu, 1u, 2u},
    };
    struct gpu_dev dev;

    for (unsigned i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        CHECK_EQ(init_at_seq(&dev, cases[i][0], cases[i][1], NULL, 0), GPU_OK);
        CHECK_EQ(dev.next_tag, cases[i][2]);
    }
}

void test_gpu_submit(void)
{
    static const uint32_t vtx[3 * GPU_VTX_WORDS] = {0x00100010u, 1u, 0x00100100u, 2u,
                                                     0x01000010u, 3u};
    static const uint32_t prim[2 * GPU_PRIM_WORDS] = {0x00010000u, 0x00020002u, 0x00020001u,
                                                      0x00030000u};
    struct gpu_batch b = {
        .vtx_words = vtx, .vtx_base = 0, .vtx_count = 3,
        .prim_words = prim, .tri_base = 0, .prim_count = 2,
        .ctrl = GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK, .clear_color = 1,
        .strip = gpu_strip(16u, 31u),
    };
    struct gpu_dev dev;
    uint32_t tag = 0;
    uint32_t tag2 = 0;

    CHECK_EQ(init_at_seq(&dev, 41u, 41u, test_palette, 3), GPU_OK);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(tag, 42u);
    CHECK(dev.pending);
    CHECK_EQ(dev.pending_tag, tag);  /* what a caller that left it pending waits for */

    for (unsigned i = 0; i < 3u * GPU_VTX_WORDS; i++) {
        CHECK_EQ(REG(GPU_WIN_VTX + 4u * i), vtx[i]);
    }
    for (unsigned i = 0; i < 2u * GPU_PRIM_WORDS; i++) {
        CHECK_EQ(REG(GPU_WIN_IDX + 4u * i), prim[i]);
    }
    CHECK_EQ(REG(GPU_REG_CTRL), GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK);
    CHECK_EQ(REG(GPU_REG_VTX_BASE), 0u);
    CHECK_EQ(REG(GPU_REG_VTX_COUNT), 3u);
    CHECK_EQ(REG(GPU_REG_TRI_BASE), 0u);
    CHECK_EQ(REG(GPU_REG_TRI_COUNT), 2u);
    CHECK_EQ(REG(GPU_REG_CLEAR_COLOR), 1u);
    CHECK_EQ(REG(GPU_REG_STRIP), 16u | (31u << GPU_STRIP_LAST_LSB));
    CHECK_EQ(REG(GPU_REG_DOORBELL), 42u);

    /* Ordering: at the fence the batch registers held their values, DOORBELL still the old tag. */
    CHECK_EQ(fake_fence_count, 1u);
    CHECK_EQ(fake_regs_at_fence[GPU_REG_TRI_COUNT / 4u], 2u);
    CHECK_EQ(fake_regs_at_fence[GPU_REG_VTX_COUNT / 4u], 3u);
    CHECK_EQ(fake_regs_at_fence[GPU_REG_CTRL / 4u], GPU_CTRL_CLEAR_MASK | GPU_CTRL_SWAP_MASK);
    CHECK_EQ(fake_regs_at_fence[GPU_REG_DOORBELL / 4u], 41u);

    /* A second batch before the first is done is refused and writes nothing. */
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag2), GPU_E_PENDING);
    CHECK_EQ(REG(GPU_REG_DOORBELL), 42u);

    /* The GPU finishes: DONE_SEQ = tag. */
    REG(GPU_REG_DONE_SEQ) = 42u;
    CHECK_EQ(gpu_wait(&dev, tag, 10), GPU_OK);
    CHECK(!dev.pending);
    CHECK_EQ(fake_fence_count, 2u);  /* acquire after seeing DONE_SEQ */

    /* Next batch, at other bases: next tag, words at the bases, registers with the bases. */
    b.vtx_base = 10;
    b.tri_base = 20;
    b.ctrl = GPU_CTRL_SWAP_MASK;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag2), GPU_OK);
    CHECK_EQ(tag2, 43u);
    CHECK_EQ(REG(GPU_WIN_VTX + 4u * GPU_VTX_WORDS * 10u), vtx[0]);
    CHECK_EQ(REG(GPU_WIN_IDX + 4u * GPU_PRIM_WORDS * 20u + 4u), prim[1]);
    CHECK_EQ(REG(GPU_REG_VTX_BASE), 10u);
    CHECK_EQ(REG(GPU_REG_TRI_BASE), 20u);
    CHECK_EQ(REG(GPU_REG_CTRL), GPU_CTRL_SWAP_MASK);
    CHECK_EQ(REG(GPU_REG_DOORBELL), 43u);
}

/* A batch built in the GPU's own buffers (gpu_buffer_words) is submitted without a copy: only the
 * six batch registers and DOORBELL are written, and the words stay as built. */
void test_gpu_submit_in_place(void)
{
    uint32_t *vtx = gpu_buffer_words(GPU_WIN_VTX);
    uint32_t *prim = gpu_buffer_words(GPU_WIN_IDX);
    struct gpu_batch b = {
        .vtx_base = 0, .vtx_count = 3, .tri_base = 0, .prim_count = 1,
        .ctrl = GPU_CTRL_SWAP_MASK, .clear_color = 0, .strip = GPU_STRIP_WHOLE,
    };
    struct gpu_dev dev;
    uint32_t tag = 0;
    uint32_t writes;

    fake_reset();
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);
    CHECK(vtx != NULL && prim != NULL);
    for (unsigned i = 0; i < 3u * GPU_VTX_WORDS; i++) {
        vtx[i] = 0x00100010u + i;
    }
    prim[0] = 0x00010000u;
    prim[1] = 0x00000002u;
    b.vtx_words = vtx;
    b.prim_words = prim;
    writes = fake_write_count;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(fake_write_count - writes, 8u);  /* CTRL, VTX_BASE/COUNT, TRI_BASE/COUNT, CLEAR, STRIP,
                                                 DOORBELL */
    for (unsigned i = 0; i < 3u * GPU_VTX_WORDS; i++) {
        CHECK_EQ(REG(GPU_WIN_VTX + 4u * i), 0x00100010u + i);
    }
    CHECK_EQ(REG(GPU_WIN_IDX), 0x00010000u);
    CHECK_EQ(REG(GPU_REG_DOORBELL), tag);
    /* Staged words at another base are still copied. */
    REG(GPU_REG_DONE_SEQ) = tag;
    CHECK_EQ(gpu_wait(&dev, tag, 10), GPU_OK);
    b.vtx_base = 5;
    writes = fake_write_count;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(fake_write_count - writes, 8u + 3u * GPU_VTX_WORDS);
    CHECK_EQ(REG(GPU_WIN_VTX + 4u * 5u * GPU_VTX_WORDS), 0x00100010u);
}

void test_gpu_submit_capacity(void)
{
    static const uint32_t words[4] = {0};
    struct gpu_batch b = {
        .vtx_words = words, .vtx_base = GPU_VTX_CAP - 1u, .vtx_count = 2,
        .prim_words = words, .tri_base = 0, .prim_count = 1,
        .ctrl = 0, .clear_color = 0, .strip = GPU_STRIP_WHOLE,
    };
    struct gpu_dev dev;
    uint32_t tag = 0;

    fake_reset();
    CHECK_EQ(gpu_init(&dev, NULL, 0), GPU_OK);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_E_CAPACITY);
    b.vtx_base = 0;
    b.vtx_count = 0xFFFFFFFFu;  /* must not wrap around the check */
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_E_CAPACITY);
    b.vtx_count = 1;
    b.tri_base = GPU_TRI_CAP;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_E_CAPACITY);
    CHECK_EQ(REG(GPU_REG_DOORBELL), 0u);
    CHECK_EQ(fake_fence_count, 0u);
    CHECK(!dev.pending);
    /* Exactly full is fine. */
    b.vtx_base = GPU_VTX_CAP - 1u;
    b.tri_base = GPU_TRI_CAP - 1u;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    /* Capacities come from the device's registers, not from the header. */
    fake_reset();
    REG(GPU_REG_VTX_CAP) = 16u;
    CHECK_EQ(gpu_init(&dev, NULL, 0), GPU_OK);
    b.vtx_base = 15;
    b.tri_base = 0;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    REG(GPU_REG_DONE_SEQ) = tag;
    CHECK_EQ(gpu_wait(&dev, tag, 1), GPU_OK);
    b.vtx_base = 16;
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_E_CAPACITY);
}

/* A device reporting capacities beyond its bus windows (or below one triangle) is refused at
 * init (found by tests/fuzz/fuzz_gpu_driver: with VTX_CAP = 0xFFFFFFFF a batch at VTX_BASE
 * 0x20000000 wrapped the offset and wrote vertex slot 0; with VTX_CAP = 0x10000 vertex words
 * landed in the index window). */
void test_gpu_init_capacities(void)
{
    static const uint32_t bad[][2] = {
        {0xFFFFFFFFu, GPU_TRI_CAP}, {GPU_VTX_CAP_MAX + 1u, GPU_TRI_CAP}, {2u, GPU_TRI_CAP},
        {0u, GPU_TRI_CAP}, {GPU_VTX_CAP, GPU_TRI_CAP_MAX + 1u}, {GPU_VTX_CAP, 0u},
    };
    struct gpu_dev dev;

    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fake_reset();
        REG(GPU_REG_VTX_CAP) = bad[i][0];
        REG(GPU_REG_TRI_CAP) = bad[i][1];
        CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_E_BUFFERS);
        CHECK_EQ(fake_write_count, 0u);
        CHECK_EQ(dev.info.vtx_cap, bad[i][0]);  /* still read, for the error message */
    }
    fake_reset();
    REG(GPU_REG_VTX_CAP) = GPU_VTX_CAP_MAX;
    REG(GPU_REG_TRI_CAP) = 1u;
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);
    fake_reset();
    REG(GPU_REG_VTX_CAP) = 3u;
    REG(GPU_REG_TRI_CAP) = GPU_TRI_CAP_MAX;
    CHECK_EQ(gpu_init(&dev, test_palette, 3), GPU_OK);
    CHECK(gpu_strerror(GPU_E_BUFFERS)[0] != '\0');
}

void test_gpu_wait_timeout(void)
{
    const struct gpu_batch b = test_gpu_tiny_batch;
    struct gpu_dev dev;
    uint32_t tag = 0;

    fake_reset();
    CHECK_EQ(gpu_init(&dev, NULL, 0), GPU_OK);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    REG(GPU_REG_DONE_SEQ) = tag - 1u;  /* the GPU never gets there */
    CHECK_EQ(gpu_wait(&dev, tag, 1000), GPU_E_TIMEOUT);
    CHECK_EQ(dev.last_done_seq, tag - 1u);
    CHECK(dev.pending);
    CHECK_EQ(gpu_wait(&dev, tag, 0), GPU_E_TIMEOUT);  /* zero polls: immediate timeout */
    /* A late answer is still seen. */
    REG(GPU_REG_DONE_SEQ) = tag;
    CHECK_EQ(gpu_wait(&dev, tag, 1), GPU_OK);
}

void test_gpu_tag_wrap(void)
{
    const struct gpu_batch b = test_gpu_tiny_batch;
    struct gpu_dev dev;
    uint32_t tag = 0;

    CHECK_EQ(init_at_seq(&dev, 0xFFFFFFFEu, 0xFFFFFFFEu, NULL, 0), GPU_OK);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(tag, 0xFFFFFFFFu);
    REG(GPU_REG_DONE_SEQ) = tag;
    CHECK_EQ(gpu_wait(&dev, tag, 1), GPU_OK);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(tag, 1u);  /* 0 is skipped */
    CHECK_EQ(REG(GPU_REG_DOORBELL), 1u);
}

void test_gpu_read_stats(void)
{
    struct gpu_dev dev;
    struct gpu_stats s;

    fake_reset();
    CHECK_EQ(gpu_init(&dev, NULL, 0), GPU_OK);
    REG(GPU_REG_ERRORS) = GPU_ERR_KIND_MASK;
    REG(GPU_REG_PERF_BUSY_CYCLES) = 100001u;
    REG(GPU_REG_PERF_TRIS_IN) = 4u;
    REG(GPU_REG_PERF_TRIS_DRAWN) = 3u;
    REG(GPU_REG_PERF_TRIS_REJECTED) = 1u;
    REG(GPU_REG_PERF_PIXELS) = 5000u;
    REG(GPU_REG_PERF_SAMPLES) = 9000u;
    REG(GPU_REG_PERF_SPANS_WRITTEN) = 777u;
    gpu_read_stats(&dev, &s);
    CHECK_EQ(s.errors, GPU_ERR_KIND_MASK);
    CHECK_EQ(s.busy_cycles, 100001u);
    CHECK_EQ(s.tris_in, 4u);
    CHECK_EQ(s.tris_drawn, 3u);
    CHECK_EQ(s.tris_rejected, 1u);
    CHECK_EQ(s.pixels, 5000u);
    CHECK_EQ(s.samples, 9000u);
    CHECK_EQ(s.spans_written, 777u);
}

/* The watchdog's reset: RESET gets a new value each time (the co-simulation only sees changes),
 * the pending batch is forgotten so the next submit goes ahead, and tags continue. */
void test_gpu_reset(void)
{
    const struct gpu_batch b = test_gpu_tiny_batch;
    struct gpu_dev dev;
    uint32_t tag = 0;
    uint32_t tag2 = 0;

    fake_reset();
    REG(GPU_REG_RESET) = 0xFFFFFFFFu;
    CHECK_EQ(gpu_init(&dev, NULL, 0), GPU_OK);
    CHECK_EQ(dev.resets, 0u);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag), GPU_OK);
    CHECK_EQ(gpu_wait(&dev, tag, 100), GPU_E_TIMEOUT);  /* DONE_SEQ never comes */
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag2), GPU_E_PENDING);
    gpu_reset(&dev);
    CHECK_EQ(REG(GPU_REG_RESET), 0u);  /* 0xFFFFFFFF + 1: a new value, wrapping is fine */
    CHECK(!dev.pending);
    CHECK_EQ(dev.resets, 1u);
    gpu_reset(&dev);
    CHECK_EQ(REG(GPU_REG_RESET), 1u);
    CHECK_EQ(gpu_submit_batch(&dev, &b, &tag2), GPU_OK);
    CHECK_EQ(tag2, tag + 1u);
}
