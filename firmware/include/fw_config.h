/*
 * fw_config.h — build-time settings of the firmware and its exit statuses.
 * Override the settings with -D on the compiler command line (firmware/firmware.mk does).
 */
#ifndef FW_CONFIG_H
#define FW_CONFIG_H

/* Frames to render before exiting with status 0. */
#ifndef FW_FRAMES
#define FW_FRAMES 24
#endif

/* Reads of DONE_SEQ before a batch counts as lost. One poll is 4 instructions (lw, addi, bne,
 * beq); under QEMU -icount 2^28 polls take about 3 s of host time (measured); 2^31 gives ~25 s, two
 * orders of magnitude more than a co-simulated frame needs (the vsync wait is 1.68 M GPU cycles, ~0.2 s
 * at 8 M simulated cycles/s). Raise it for slower simulators: make FW_MAX_POLLS=... */
#ifndef FW_GPU_MAX_POLLS
#define FW_GPU_MAX_POLLS (1u << 31)
#endif

/* Exit statuses (the QEMU process exits with these). */
#define FW_EXIT_OK          0
#define FW_EXIT_GPU_INIT    2   /* no GPU, wrong version or geometry */
#define FW_EXIT_GPU_SUBMIT  3   /* batch rejected by the driver */
#define FW_EXIT_GPU_TIMEOUT 4   /* DONE_SEQ never reached the tag */
#define FW_EXIT_GPU_ERRORS  5   /* the GPU set an ERR_* flag */
#define FW_EXIT_FX_OVERFLOW 6   /* a fixed-point range argument failed (saturation happened) */

#endif /* FW_CONFIG_H */
