#!/usr/bin/env bash
# Scene manifests (firmware/scenes/<scene>.manifest.toml, mk/manifest.py): every scene's parses
# and its capacities cover its columns of the scene table; a bad manifest is refused with the file
# and the key; and the cubes' manifest build ($BUILD/lean-test/cubes/firmware/cubes.elf: one scene,
# no anaglyph, no depth test, no line emulation) co-simulated renders the same frames as make
# test's full build of cubes, and is smaller. And a GPU with a manifest's small buffers (VTX_CAP 32,
# TRI_CAP 16, mk/builds.toml's sim-fast-cfg-w8-v32-t16) stands beside a golden model of the same sizes: random
# batches past the capacities agree on ERR_COUNT, bad indices, dropped and drawn primitives; and the
# full cubes build, batched to those buffers, renders the full-size GPU's frames, model-checked.
source "$(dirname "$0")/../lib.sh"
need BUILD PYTHON GPUSIM_FAST
lean="$BUILD/lean-test/cubes/firmware/cubes.elf"
full="$BUILD/fw-test/cubes.elf"
small="$BUILD/sim-fast-cfg-w8-v32-t16/gpusim"
need_file "$lean" "$full" "$GPUSIM_FAST" "$small"
work=$(fresh_dir manifest)

run_to "$work/check.out" 20 "$PYTHON" mk/manifest.py --check
expect_status 0 "manifest.py --check: $(cat "$work/check.out")"

# refused MESSAGE-REGEX: the manifest on stdin must be refused with a message matching it.
refused() {
    cat >"$work/bad.toml"
    run_to "$work/bad.out" 20 "$PYTHON" mk/manifest.py --file "$work/bad.toml"
    [ "$status" -ne 0 ] || fail "a bad manifest accepted (expected: $1)"
    grep -Eq "$1" "$work/bad.out" || fail "refused, but not with '$1': $(cat "$work/bad.out")"
}
good=$(cat firmware/scenes/tetra.manifest.toml)
"$PYTHON" mk/manifest.py --file firmware/scenes/tetra.manifest.toml >/dev/null || fail "tetra's manifest refused"
printf '%s\nshadows = true\n' "$good" | refused "unknown key 'gpu.shadows'"
sed 's/^lines = true /lines = 1 /' <<<"$good" | refused "'features.lines' must be bool"
sed '/^lighting = /d' <<<"$good" | refused "missing key 'features.lighting'"
sed 's/^span_w = 8 /span_w = 3 /' <<<"$good" | refused "gpu.span_w = 3"
sed 's/^vtx_cap = 1024 /vtx_cap = 16 /' <<<"$good" | refused "gpu.vtx_cap = 16 is smaller than scene tetra's verts column \\(32"
sed 's/^tri_cap = 512 /tri_cap = 48 /' <<<"$good" | refused "gpu.tri_cap = 48: a power of two"
# Emulated lines (lines = false with the wireframe) reserve the wireframe columns: 140 > 64.
sed 's/^lines = true /lines = false /; s/^vtx_cap = 1024 /vtx_cap = 64 /' <<<"$good" |
    refused "gpu.vtx_cap = 64 is smaller than scene tetra's wverts column \\(140"
printf '%s\n[memory]\nram_kib = 64\n' "$good" | refused "\\[memory\\]: a manifest names no RAM size"
sed 's/^scene = "tetra"/scene = "teapot"/' <<<"$good" | refused "scene 'teapot' is not"
# The model scene: its [model] table is required there and refused elsewhere, and its columns
# follow the capacities (model.h's macros: 1024 faces need 1282 primitives, over the contract's 512;
# 64 faces need 82).
model=$(cat firmware/scenes/model.manifest.toml)
"$PYTHON" mk/manifest.py --file firmware/scenes/model.manifest.toml >/dev/null || fail "model's manifest refused"
printf '%s\n[model]\nupload = true\nmax_verts = 64\nmax_faces = 64\n' "$good" | refused "unknown key 'model'"
sed '/^\[model\]/,$d' <<<"$model" | refused "missing key 'model'"
sed 's/^tri_cap = 512 /tri_cap = 256 /' <<<"$model" | refused "gpu.tri_cap = 256 is smaller than scene model's prims column \\(1282"
sed 's/^max_faces = 1024 /max_faces = 64 /; s/^tri_cap = 512 /tri_cap = 64 /' <<<"$model" |
    refused "gpu.tri_cap = 64 is smaller than scene model's prims column \\(82"
sed 's/^max_faces = 1024 /max_faces = 70000 /' <<<"$model" | refused "model.max_faces = 70000: from 4 to 65536"
# From the SDRAM, the same bound: a face's vertex and normal indices are 16 bits (render/mesh.h).
sed 's/^sdram_max_faces = 65536 /sdram_max_faces = 65537 /' <<<"$model" | refused "model.sdram_max_faces = 65537: from 4 to 65536"

# The manifest build against the full one: the same frames, co-simulated on the fast display path
# (the RTL's front bank after each swap, each frame checked against the golden model as well).
for b in lean full; do
    elf=$lean; [ "$b" = full ] && elf=$full
    run_to "$work/$b.out" 120 "$GPUSIM_FAST" cosim --fw "$elf" --frames "$work/$b" --uart-log "$work/$b.log" \
        --summary "$work/$b.summary"
    expect_status 0 "the $b build's co-simulation: $(tail -n 3 "$work/$b.out")"
    expect_eq "$(summary frames_model_checked "$work/$b.summary")" 4 "$b frames equal to the model"
done
same_pngs "$work/lean" "$work/full" "cubes, manifest build against full build"

# The small GPU: its random batches (a quarter past the buffers), then cubes on it.
run_to "$work/small-random.out" 60 "$small" random --seed 8 --batches 150 --tris 40 --swap-percent 25 --min-overflows 15
expect_status 0 "small buffers against the model: $(tail -n 2 "$work/small-random.out")"
grep -q "VTX_CAP 32 TRI_CAP 16" "$work/small-random.out" || fail "the small GPU's model has other sizes: $(cat "$work/small-random.out")"
run_to "$work/small.out" 120 "$small" cosim --fw "$full" --frames "$work/small" --uart-log "$work/small.log" \
    --summary "$work/small.summary"
expect_status 0 "cubes on the small GPU: $(tail -n 3 "$work/small.out")"
expect_eq "$(summary frames_model_checked "$work/small.summary")" 4 "small-GPU frames equal to the model"
grep -q "vtx_cap 32 tri_cap 16" "$work/small.log" || fail "the firmware did not see the small buffers: $(head -n 3 "$work/small.log")"
same_pngs "$work/small" "$work/full" "cubes, VTX_CAP 32 / TRI_CAP 16 against the contract's buffers"
small_batches=$(awk '/^frame 1:/ { for (i = 1; i < NF; i++) if ($(i + 1) == "batches") print $(i + 2) }' "$work/small.log")
size_of() { riscv64-unknown-elf-size "$1" | awk 'NR == 2 { print $1 + $2 + $3 }'; }
lean_size=$(size_of "$lean")
full_size=$(size_of "$full")
[ "$lean_size" -lt "$full_size" ] || fail "the manifest build is not smaller: $lean_size >= $full_size bytes"
pass "manifest: every scene's manifest valid, 14 bad ones refused; cubes' manifest build: 4 frames equal to the full build's, text+data+bss $lean_size bytes (full $full_size); VTX_CAP 32 / TRI_CAP 16 GPU: $(grep -o '[0-9]* over the capacities' "$work/small-random.out") of 150 random batches, model-checked; cubes in $small_batches batches a frame, frames equal"
