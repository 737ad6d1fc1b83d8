#!/usr/bin/env bash
# The frame loop's watchdog: the harness ignores the 3rd doorbell (--drop-doorbell), as a hung GPU
# would. The firmware must give up on that batch after its bounded wait (this ELF: 2^28 polls,
# ~3 s), report it, reset the GPU through RESET, drop that frame and go on: all other frames
# rendered and checked against the golden model, exit status 0, never a hang.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
elf="$BUILD/fw-test/tetra-watchdog.elf"
need_file "$elf"
work=$(fresh_dir scene-watchdog)

cosim_run "$GPUSIM" "$elf" 120 --drop-doorbell 3
cat "$work/out"
expect_status 0 "the co-simulation, after recovering"
expect_eq "$(summary doorbells_dropped "$work/summary")" 1 "doorbells dropped by the harness"
expect_eq "$(summary gpu_resets "$work/summary")" 1 "GPU resets seen by the harness"
expect_line "^watchdog: frame 2 batch 1: GPU did not finish" "$work/uart.log"
expect_line "^watchdog: 1 GPU reset\(s\) in this run" "$work/uart.log"
# Frames 0, 1, 3, 4 completed (5 built in, frame 2 lost), each one checked against the model.
expect_frames 4
expect_line '^frame 3: ' "$work/uart.log"
expect_line '^frame 4: ' "$work/uart.log"
expect_eq "$(summary frames "$work/summary")" 4 "frames captured"
expect_eq "$(png_count "$work/frames")" 4 "PNG files written"
pass "watchdog: doorbell 3 lost, GPU reset, frame 2 dropped, frames 3-4 rendered, status 0"
