/*
 * host_main.c — command line of the host build: the firmware's frame loop on Linux, rendering
 * through the golden model. firmware/app/main.c's main() hands argc and argv to bsp_args (this
 * file) before it runs the loop, so the BSP knows nothing of the loop or the scenes: the options
 * become a bsp_host_config, which bsp_init() applies and the loop's hooks read (bsp_platform.h).
 *
 *   fw-host [--frames DIR] [--keys-at N:TEXT]... [--no-lines] [--zbuf] [--zbuf-bits N] [--no-wmask]
 *           [--gouraud] [--span-w N] [--frame WxH] [--model FILE] [--dump-scene DIR]
 *           [--unquantised-frames DIR]
 *
 *   --frames DIR      write each swapped frame as DIR/NNNN.png (as gpusim cosim does)
 *   --unquantised-frames DIR  also write each swapped frame as DIR/NNNN.png with its Gouraud pixels
 *                     in their unquantised colours (the model's shade probe: the intensity before
 *                     the level is rounded or dithered, mixed between its ramp's entries):
 *                     bench-error's undithered reference
 *   --keys-at N:TEXT  type TEXT just before doorbell N (1 = first) is serviced, byte for byte
 *                     (as gpusim cosim; use the shell's $'...' for control bytes); fF:TEXT just
 *                     before the doorbell that starts frame F (0 = first: the first doorbell after
 *                     F swaps), as socsim's
 *   --no-lines        model a GPU built without line primitives (CAPS_LINES = 0)
 *   --zbuf            model a GPU built with the depth buffer (CAPS_ZBUF = 1)
 *   --no-wmask        model a GPU built without the framebuffer write mask (CAPS_WMASK = 0)
 *   --zbuf-bits N     the depth bits its buffer keeps (ZBUF_BITS, CAPS_ZBUF_BITS: 1 .. 16; default 16)
 *   --gouraud         model a GPU built with Gouraud triangles (CAPS_GOURAUD = 1)
 *   --span-w N        SPAN_W the model reports (1, 4, 8, 16; default 8)
 *   --frame WxH       the frame the model draws (FB_SIZE): the contract's 320x240 (the default) or
 *                     its largest, 640x480, as a GPU built with FB_WIDTH x FB_HEIGHT
 *   --dump-scene DIR  write each frame's scene after its update as DIR/NNNN.scene: world-space
 *                     triangles with their normals and materials, light, camera, palette (the
 *                     exact reference's input, bench/exact_ref; format in bsp/host/scene_dump.c)
 *   --model FILE      the model scene draws this mesh file (docs/mesh-format.md) instead of the
 *                     built-in one, as if it had been uploaded before the first frame: the
 *                     reference renders of the upload test, and a quick look at a converted model
 *                     (read here; the frame loop takes it at boot, bsp_host_boot_model)
 *
 * The scene and the number of frames are built in, like the target's (make SCENE=... FRAMES=...).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bsp.h"
#include "bsp_host.h"
#include "gpu_model.h"
#include "gpu_regs.h"

/* A mesh file for --model: read whole (the validator, at the scene's start, says what is wrong). */
static int host_load_model(const char *path, struct bsp_host_config *cfg)
{
    static uint8_t file[4u << 20];
    FILE *f = fopen(path, "rb");
    size_t n;

    if (f == NULL) {
        fprintf(stderr, "fw-host: cannot open %s\n", path);
        return -1;
    }
    n = fread(file, 1, sizeof file, f);
    fclose(f);
    cfg->model_file = file;
    cfg->model_bytes = (uint32_t)n;
    return 0;
}

/* An output directory: made, or already there. */
static int host_make_dir(const char *dir)
{
    struct stat st;

    if (mkdir(dir, 0755) != 0 && (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))) {
        fprintf(stderr, "fw-host: cannot create %s\n", dir);
        return -1;
    }
    return 0;
}

static int host_usage(void)
{
    fprintf(stderr, "usage: fw-host [--frames DIR] [--keys-at N:TEXT]... [--no-lines] [--zbuf] "
                    "[--zbuf-bits N] [--no-wmask] [--gouraud] [--span-w N] [--frame WxH] [--model FILE] "
                    "[--dump-scene DIR] "
                    "[--unquantised-frames DIR]\n");
    return 2;
}

int bsp_args(int argc, char **argv)
{
    struct bsp_host_config cfg;

    memset(&cfg, 0, sizeof cfg);
    cfg.span_w = 8;
    cfg.lines = true;
    cfg.zbuf = false;
    cfg.zbuf_bits = 16;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const int has_value = i + 1 < argc;

        if (strcmp(a, "--frames") == 0 && has_value) {
            cfg.frames_dir = argv[++i];
            if (host_make_dir(cfg.frames_dir) != 0) {
                return 2;
            }
        } else if (strcmp(a, "--unquantised-frames") == 0 && has_value) {
            cfg.unquantised_dir = argv[++i];
            if (host_make_dir(cfg.unquantised_dir) != 0) {
                return 2;
            }
        } else if (strcmp(a, "--keys-at") == 0 && has_value) {
            const char *spec = argv[++i];
            const bool frame = spec[0] == 'f';
            const char *number = frame ? spec + 1 : spec;
            const char *colon = strchr(spec, ':');
            char *end = NULL;
            const unsigned long at = strtoul(number, &end, 10);

            if (colon == NULL || end != colon || end == number || number[0] == '-' || at > UINT32_MAX ||
                (!frame && at == 0) || cfg.key_events >= BSP_HOST_MAX_KEY_EVENTS) {
                fprintf(stderr, "fw-host: --keys-at wants N:TEXT (N from 1) or fF:TEXT, at most %d of them, "
                                "got '%s'\n", BSP_HOST_MAX_KEY_EVENTS, spec);
                return 2;
            }
            cfg.keys[cfg.key_events].at = (uint32_t)at;
            cfg.keys[cfg.key_events].frame = frame;
            cfg.keys[cfg.key_events].text = colon + 1;
            cfg.key_events++;
        } else if (strcmp(a, "--no-lines") == 0) {
            cfg.lines = false;
        } else if (strcmp(a, "--zbuf") == 0) {
            cfg.zbuf = true;
        } else if (strcmp(a, "--no-wmask") == 0) {
            cfg.no_wmask = true;
        } else if (strcmp(a, "--zbuf-bits") == 0 && has_value) {
            char *end;
            const unsigned long bits = strtoul(argv[++i], &end, 10);

            if (*argv[i] == '\0' || *end != '\0' || bits < 1 || bits > 16) {
                fprintf(stderr, "fw-host: --zbuf-bits wants 1 .. 16, got '%s'\n", argv[i]);
                return 2;
            }
            cfg.zbuf_bits = (unsigned)bits;
        } else if (strcmp(a, "--gouraud") == 0) {
            cfg.gouraud = true;
        } else if (strcmp(a, "--dump-scene") == 0 && has_value) {
            cfg.dump_dir = argv[++i];
            if (host_make_dir(cfg.dump_dir) != 0) {
                return 2;
            }
        } else if (strcmp(a, "--model") == 0 && has_value) {
            if (host_load_model(argv[++i], &cfg) != 0) {
                return 2;
            }
        } else if (strcmp(a, "--frame") == 0 && has_value) {
            if (!gpu_model_parse_frame(argv[++i], &cfg.fb_width, &cfg.fb_height)) {
                fprintf(stderr, "fw-host: --frame wants %ux%u or %ux%u, got '%s'\n",
                        (unsigned)GPU_FB_WIDTH, (unsigned)GPU_FB_HEIGHT,
                        (unsigned)GPU_FB_MAX_WIDTH, (unsigned)GPU_FB_MAX_HEIGHT, argv[i]);
                return 2;
            }
        } else if (strcmp(a, "--span-w") == 0 && has_value) {
            cfg.span_w = (unsigned)strtoul(argv[++i], NULL, 10);
        } else {
            return host_usage();
        }
    }
    bsp_host_configure(&cfg);
    return 0;
}
