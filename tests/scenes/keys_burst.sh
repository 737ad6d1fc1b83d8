#!/usr/bin/env bash
# A burst of keys never stalls rendering: 300 bytes (escape sequences, control and high bytes,
# unknown letters, valid keys) typed at once into the UART of the co-simulated firmware. The frame
# loop reads at most 32 bytes per frame, ignores what it does not know, and keeps rendering: every
# frame completes and matches the golden model, and the firmware ends normally.
set -euo pipefail
: "${GPUSIM:?}" "${BUILD:?}"
elf="$BUILD/fw-test/cubes.elf"
work="$BUILD/test-scenes/keys-burst"
rm -rf "$work" && mkdir -p "$work"
[ -f "$elf" ] || { echo "missing $elf (make fw-test-deps)"; exit 1; }

junk="f"  # first: wireframe on, so the log shows the burst arrived
for i in $(seq 1 20); do
    junk+=$'\e[A\e[15~xyzXYZ!@#\x01\x7f\xffjjl'
done
[ "${#junk}" -ge 300 ] || { echo "burst too short"; exit 1; }
set +e
timeout 120 "$GPUSIM" cosim --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" \
    --keys-at "1:$junk" >"$work/out" 2>&1
status=$?
set -e
tail -n 4 "$work/out"
[ "$status" -eq 0 ] || { echo "expected status 0, got $status"; exit 1; }
[ "$(grep -c '^frame ' "$work/uart.log")" -eq 4 ] || { echo "not every frame rendered"; exit 1; }
[ "$(grep -c 'equals golden model' "$work/out")" -eq 4 ] || { echo "not every frame matched the model"; exit 1; }
! grep -q '^error' "$work/uart.log" || { echo "the firmware reported an error"; exit 1; }
grep -q '^wireframe on' "$work/uart.log" || { echo "the burst never reached the firmware"; exit 1; }
echo "keys-burst: ${#junk} bytes typed at once, all 4 frames rendered, status 0"
