#!/usr/bin/env bash
# Leave out what a scene does not need: the cubes built with every optional feature off
# (FW_WITH_WIREFRAME/ANAGLYPH/DEPTH/LIGHTING = 0, fw_config.h) run in co-simulation on the depth
# GPU: every frame rendered and equal to the golden model, the F, G and Z keys answered with
# "not built in" and changing nothing, and the program smaller than the full build.
set -euo pipefail
: "${BUILD:?}"
lean="$BUILD/fw-test/cubes-lean.elf"
full="$BUILD/fw-test/cubes.elf"
sim="$BUILD/sim-z-w8/gpusim"
work="$BUILD/test-scenes/lean-build"
rm -rf "$work" && mkdir -p "$work"
for f in "$lean" "$full" "$sim"; do [ -f "$f" ] || { echo "missing $f (make test builds it)"; exit 1; }; done

set +e
timeout 120 "$sim" cosim --fw "$lean" --frames "$work/frames" --uart-log "$work/uart.log" \
    --keys-at "1:fgz" >"$work/out" 2>&1
status=$?
set -e
tail -n 3 "$work/out"
[ "$status" -eq 0 ] || { echo "expected status 0, got $status"; exit 1; }
[ "$(grep -c '^frame ' "$work/uart.log")" -eq 4 ] || { echo "not every frame rendered"; exit 1; }
[ "$(grep -c 'equals golden model' "$work/out")" -eq 4 ] || { echo "not every frame matched the model"; exit 1; }
for what in "wireframe: not built in" "anaglyph: not built in" "depth buffer: not built in"; do
    grep -q "^$what" "$work/uart.log" || { echo "no '$what' answer"; exit 1; }
done
! grep -Eq '^(wireframe on|anaglyph on|depth buffer on)' "$work/uart.log" || { echo "a left-out feature turned on"; exit 1; }
# One pass a frame (no anaglyph), and the GPU's depth test never asked for.
! grep -q 'batches 2' "$work/uart.log" || { echo "two passes in a frame"; exit 1; }

size_of() { riscv64-unknown-elf-size "$1" | awk 'NR == 2 { print $1 }'; }
lean_text=$(size_of "$lean")
full_text=$(size_of "$full")
[ "$lean_text" -lt "$full_text" ] || { echo "lean build not smaller: $lean_text >= $full_text bytes"; exit 1; }
echo "lean build: 4 frames equal to the model, F/G/Z not built in, .text $lean_text bytes (full build $full_text)"
