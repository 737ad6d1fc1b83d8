#!/usr/bin/env bash
# A burst of keys never stalls rendering: 300 bytes (escape sequences, control and high bytes,
# unknown letters, valid keys) typed at once into the UART of the co-simulated firmware. The frame
# loop reads at most 32 bytes per frame, ignores what it does not know, and keeps rendering: every
# frame completes and matches the golden model, and the firmware ends normally.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
elf="$BUILD/fw-test/cubes.elf"
need_file "$elf"
work=$(fresh_dir scene-keys-burst)

junk="f"  # first: wireframe on, so the log shows the burst arrived
for _ in $(seq 1 20); do
    junk+=$'\e[A\e[15~xyzXYZ!@#\x01\x7f\xffjjl'
done
[ "${#junk}" -ge 300 ] || fail "burst too short"
cosim_run "$GPUSIM" "$elf" 120 --keys-at "1:$junk"
tail -n 4 "$work/out"
expect_status 0 "the co-simulation"
expect_frames 4
expect_no_line '^error' "$work/uart.log"
expect_line '^wireframe on' "$work/uart.log"  # the burst reached the firmware
pass "keys-burst: ${#junk} bytes typed at once, all 4 frames rendered, status 0"
