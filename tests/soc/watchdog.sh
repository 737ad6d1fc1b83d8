#!/usr/bin/env bash
# The watchdog on the SoC: tetra built with a watchdog of a few DONE_SEQ reads (mk/builds.toml's
# fw.soc-test, polls = 16), so every batch outlasts it (the first clears the framebuffer, 9,600 clocks; a swap
# waits for vertical blank). The firmware must report each lost frame, reset the GPU through RESET,
# and after FW_WATCHDOG_GIVE_UP (3) lost frames in a row give up with FW_EXIT_GPU_TIMEOUT (4), as
# `make fw-smoke` checks under QEMU with a silent GPU. Never a hang.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test tetra-watchdog-tiny soc-watchdog

run_socsim 120 --summary "$work/summary" --max-cycles 50e6
cat "$work/out"
expect_status 4 "socsim (the firmware's FW_EXIT_GPU_TIMEOUT)"
expect_eq "$(summary firmware_status "$work/summary")" 4 "firmware status in the summary"
expect_eq "$(count '^watchdog: frame [0-9]+ batch 1: GPU did not finish' "$work/uart.log")" 3 "watchdog reports"
expect_line 'still hung after 3 resets; giving up' "$work/uart.log"
expect_eq "$(summary gpu_resets "$work/summary")" 3 "RESET writes seen on the GPU's bus"
expect_eq "$(count '^frame ' "$work/uart.log")" 0 "completed frames"
pass "soc-watchdog: 3 frames lost to the watchdog, 3 GPU resets, exit status 4"
