#!/usr/bin/env bash
# Leave out what a scene does not need: the cubes built with every optional feature off
# (FW_WITH_WIREFRAME/ANAGLYPH/DEPTH/LIGHTING/STRIPS = 0, config/build_options.h) run in co-simulation on the depth
# GPU: every frame rendered and equal to the golden model, the F, G and Z keys answered with
# "not built in" and changing nothing, and the program smaller than the full build.
source "$(dirname "$0")/../lib.sh"
need BUILD
lean="$BUILD/fw-test/cubes-lean.elf"
full="$BUILD/fw-test/cubes.elf"
sim="$BUILD/sim-z-w8/gpusim"
need_file "$lean" "$full" "$sim"
work=$(fresh_dir scene-lean-build)

cosim_run "$sim" "$lean" 120 --keys-at "1:fgz"
tail -n 3 "$work/out"
expect_status 0 "the co-simulation"
expect_frames 4
for what in "wireframe: not built in" "anaglyph: not built in" "depth buffer: not built in"; do
    expect_line "^$what" "$work/uart.log"
done
expect_no_line '^(wireframe on|anaglyph on|depth buffer on)' "$work/uart.log"
# One pass a frame (no anaglyph): every frame line says one batch.
expect_eq "$(count ' batches 1 [|]' "$work/uart.log")" 4 "frames drawn in one batch"

size_of() { riscv64-unknown-elf-size "$1" | awk 'NR == 2 { print $1 }'; }
lean_text=$(size_of "$lean")
full_text=$(size_of "$full")
[ "$lean_text" -lt "$full_text" ] || fail "lean build not smaller: $lean_text >= $full_text bytes"
pass "lean build: 4 frames equal to the model, F/G/Z not built in, .text $lean_text bytes (full build $full_text)"
