/*
 * fw_config.h — build-time settings of the frame loop (app/) and its exit statuses.
 * Override the settings with -D on the compiler command line (firmware/firmware.mk does).
 * The options every layer reads (FW_WITH_*, FW_SUBPIXEL_BITS) are config/build_options.h's,
 * included here so that the loop sees them too.
 */
#ifndef FW_CONFIG_H
#define FW_CONFIG_H

#include "config/build_options.h"

/* Scene shown at boot, a name of the scene table (scenes/scene_list.h). make SCENE=... */
#ifndef FW_SCENE
#define FW_SCENE "tetra"
#endif

/* Frames to render before exiting with status 0; 0 = run until Q is pressed. */
#ifndef FW_FRAMES
#define FW_FRAMES 24
#endif

/* 1: print where each frame's instructions went (update, draw, sort, batch, submit). */
#ifndef FW_PROFILE
#define FW_PROFILE 0
#endif

/* 1: the depth test starts on (if the GPU has a depth buffer, CAPS_ZBUF), as if Z had been pressed
 * before the first frame. Used by `make bench-error`; the Z key still toggles it. */
#ifndef FW_DEPTH_TEST
#define FW_DEPTH_TEST 0
#endif

/* Strips (contract "Strips", render/strips.h): 0, the default, sends each frame whole to a GPU
 * that draws into its frame; a power of two N draws it N lines at a time, each band given the
 * primitives that reach it (the frames are the same; the strip renderer's way, docs/strips.md).
 * A GPU with a strip buffer (STRIP_ROWS > 0) is always sent its own strips, whatever this says. */
#ifndef FW_STRIP_ROWS
#define FW_STRIP_ROWS 0
#endif
#if FW_STRIP_ROWS != 0 && (FW_STRIP_ROWS & (FW_STRIP_ROWS - 1)) != 0
#error "FW_STRIP_ROWS must be 0 or a power of two"
#endif
#if FW_STRIP_ROWS != 0 && !FW_WITH_STRIPS
#error "FW_STRIP_ROWS needs FW_WITH_STRIPS"
#endif

/* The GPU's binning, on a GPU with a strip buffer: 1 (the default where the binning is built in) sends a pass that fits one
 * batch once with CTRL.WALK, the GPU drawing it for every strip (fetching all its primitives each
 * time and keeping what reaches the strip); a pass of several batches is binned by the firmware
 * (render/strips.c). 0: the firmware always bins (a measurement: make bench-strips,
 * docs/strips.md). */
#ifndef FW_STRIP_WALK
#define FW_STRIP_WALK FW_WITH_STRIPS
#endif
#if FW_STRIP_WALK && !FW_WITH_STRIPS
#error "FW_STRIP_WALK needs FW_WITH_STRIPS"
#endif

/* Gouraud shading (needs FW_WITH_GOURAUD and a GPU with CAPS_GOURAUD): 1, the default, draws the
 * meshes that carry vertex normals (the landscape's) with per-vertex light, interpolated by the GPU;
 * 0 draws every scene flat. FW_DITHER: 1 sets CTRL_DITHER (4x4 ordered dither between adjacent
 * ramp levels), 0 rounds each pixel's level down. Both accuracy knobs of `make bench-error`. */
#ifndef FW_GOURAUD
#define FW_GOURAUD 1
#endif
#ifndef FW_DITHER
#define FW_DITHER 1
#endif

/* 1: models can be uploaded over the UART while the firmware runs (model/upload.c,
 * docs/upload-protocol.md); they are drawn by the model scene, so the default is 1 exactly where
 * that scene is built in (firmware.mk passes FW_MODEL_SCENE_BUILT). The staging buffer is one mesh
 * file of the model scene's capacity (20 KiB at the defaults). */
#ifndef FW_MODEL_SCENE_BUILT
#define FW_MODEL_SCENE_BUILT 0
#endif
#ifndef FW_WITH_UPLOAD
#define FW_WITH_UPLOAD FW_MODEL_SCENE_BUILT
#endif
/* UART bytes a frame takes while uploads are built in: at 60 frames/s, 60 KiB/s, five times a
 * 115200-baud line, so the line's rate is never the firmware's limit; the work stays bounded (the
 * receiver's CRC is about 20 instructions a byte). */
#ifndef FW_UART_BYTES_PER_FRAME
#define FW_UART_BYTES_PER_FRAME 1024u
#endif

/* 1: keys are read from a USB HID boot keyboard too (bsp_usb_key_nonblock; input/usb_keys.h), after
 * the UART's each frame and into the same counts, each key doing what its terminal bytes do on the
 * UART; a line is printed when the keyboard's port changes state (plugged in, ready, unplugged, an
 * error). 0, the default: none of it is compiled in. Such a program runs only on a platform whose
 * USB host is there: on the SoC a build with the USB host (soc_top USB_HOST; elsewhere its window
 * is a bus error); QEMU and the host build have none and read the UART only. */
#ifndef FW_USB_KEYBOARD
#define FW_USB_KEYBOARD 0
#endif
/* USB key events a frame takes at most: the host's event FIFO holds 16 (usb_ls_host FIFO_DEPTH), so
 * one frame empties it, and the work stays bounded whatever the keyboard sends (the rest waits for
 * the next frame; what the FIFO cannot hold the host drops and counts, OVERFLOWS). */
#ifndef FW_USB_EVENTS_PER_FRAME
#define FW_USB_EVENTS_PER_FRAME 16u
#endif
/* Typematic repeat of a held USB key, in frames (input/usb_keys.h): the first repeat
 * FW_USB_KEY_REPEAT_DELAY frames after the press, then one every FW_USB_KEY_REPEAT_PERIOD. 0, the
 * default: a held key acts once, as a key typed on the UART by a script does. Frames are not time
 * (the rate would follow each scene's frame rate), and frames that depend on how long a key is
 * held would not compare with a UART run's (tests/soc/usb_keys.sh). A board build for people may
 * set it: at 60 frames/s, 30 and 2 are a terminal's 500 ms delay and 30 repeats a second. */
#ifndef FW_USB_KEY_REPEAT_DELAY
#define FW_USB_KEY_REPEAT_DELAY 0u
#endif
#ifndef FW_USB_KEY_REPEAT_PERIOD
#define FW_USB_KEY_REPEAT_PERIOD 2u
#endif
#if FW_USB_KEY_REPEAT_DELAY != 0 && !FW_USB_KEYBOARD
#error "FW_USB_KEY_REPEAT_DELAY needs FW_USB_KEYBOARD"
#endif
#if FW_USB_KEY_REPEAT_DELAY > 65535 || FW_USB_KEY_REPEAT_PERIOD < 1 || \
    FW_USB_KEY_REPEAT_PERIOD > 65535
#error "FW_USB_KEY_REPEAT_DELAY must be 0..65535 frames, FW_USB_KEY_REPEAT_PERIOD 1..65535"
#endif

/* The watchdog: reads of DONE_SEQ before a batch counts as lost. One poll is 4 instructions
 * (lw, addi, bne, beq); under QEMU -icount 2^28 polls take about 3 s of host time (measured); 2^31
 * would then take ~25 s (extrapolated), two orders of magnitude more than a co-simulated batch needs (the vsync wait is
 * 1.68 M GPU cycles, ~0.2 s at 8 M simulated cycles/s). On an FPGA at 100 MHz 2^31 polls are ~90 s:
 * a board port should set it to about a second's worth (make FW_MAX_POLLS=...). */
#ifndef FW_GPU_MAX_POLLS
#define FW_GPU_MAX_POLLS (1u << 31)
#endif

/* Consecutive frames lost to the watchdog before the firmware gives up on the GPU (each one has
 * already reset it): a GPU that a reset does not bring back is an error, not a reason to hang. */
#ifndef FW_WATCHDOG_GIVE_UP
#define FW_WATCHDOG_GIVE_UP 3u
#endif

/* Exit statuses (the QEMU process exits with these). */
#define FW_EXIT_OK          0
#define FW_EXIT_CONFIG      1   /* unknown scene built in, or one its storage cannot hold, or a
                                 * projection unit the program was built for is missing */
#define FW_EXIT_GPU_INIT    2   /* no GPU, wrong version, geometry or capacities */
#define FW_EXIT_GPU_SUBMIT  3   /* batch rejected by the driver */
#define FW_EXIT_GPU_TIMEOUT 4   /* the GPU stayed hung through FW_WATCHDOG_GIVE_UP resets */
#define FW_EXIT_GPU_ERRORS  5   /* the GPU set an ERR_* flag */
#define FW_EXIT_FX_OVERFLOW 6   /* a fixed-point range argument failed (saturation happened) */

#endif /* FW_CONFIG_H */
