#!/usr/bin/env bash
# The frame loop's watchdog: the harness ignores the 3rd doorbell (--drop-doorbell), as a hung GPU
# would. The firmware must give up on that batch after its bounded wait (this ELF: 2^28 polls,
# ~3 s), report it, reset the GPU through RESET, drop that frame and go on: all other frames
# rendered and checked against the golden model, exit status 0, never a hang.
set -euo pipefail
: "${GPUSIM:?}" "${BUILD:?}"
elf="$BUILD/fw-test/tetra-watchdog.elf"
work="$BUILD/test-scenes/watchdog"
rm -rf "$work" && mkdir -p "$work"
[ -f "$elf" ] || { echo "missing $elf (make fw-test-deps)"; exit 1; }

set +e
timeout 120 "$GPUSIM" cosim --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" \
    --drop-doorbell 3 >"$work/out" 2>&1
status=$?
set -e
cat "$work/out"
[ "$status" -eq 0 ] || { echo "expected exit status 0 after recovering, got $status"; exit 1; }
grep -q "doorbell 3 (tag .*) dropped on purpose" "$work/out" || { echo "the harness did not drop doorbell 3"; exit 1; }
grep -q "^watchdog: frame 2 batch 1: GPU did not finish" "$work/uart.log" || { echo "no watchdog report for frame 2"; exit 1; }
grep -q "cosim: GPU reset by the firmware" "$work/out" || { echo "RESET never reached the GPU"; exit 1; }
grep -q "^watchdog: 1 GPU reset(s) in this run" "$work/uart.log" || { echo "no reset summary"; exit 1; }
# Frames 0, 1, 3, 4 completed (5 built in, frame 2 lost), each one checked against the model.
[ "$(grep -c '^frame ' "$work/uart.log")" -eq 4 ] || { echo "expected 4 frame lines"; exit 1; }
grep -q '^frame 3: ' "$work/uart.log" && grep -q '^frame 4: ' "$work/uart.log" || { echo "frames after the reset missing"; exit 1; }
[ "$(ls "$work/frames" | wc -l)" -eq 4 ] || { echo "expected 4 PNG frames"; exit 1; }
[ "$(grep -c 'equals golden model' "$work/out")" -eq 4 ] || { echo "not every frame matched the model"; exit 1; }
echo "watchdog: doorbell 3 lost, GPU reset, frame 2 dropped, frames 3-4 rendered, status 0"
