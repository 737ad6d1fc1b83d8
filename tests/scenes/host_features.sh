#!/usr/bin/env bash
# Features that depend on how the GPU was built, and runtime scene switching:
#  1. A GPU without line primitives (CAPS_LINES = 0): wireframe still works, edges drawn as thin
#     triangle pairs; no GPU error (a LINE primitive would set ERR_KIND and stop the firmware).
#     A build without line emulation (FW_LINE_EMULATION=0, a chip's) refuses the wireframe on such
#     a GPU, with a message, and draws on; with GPU lines its wireframe frames equal the default
#     build's (the same outline primitives and lines).
#  2. A GPU with the depth buffer (the RTL built with ENABLE_ZBUF, $BUILD/sim-z-w8): Z turns the
#     depth test on; co-simulation and the host build (model with --zbuf) agree on every frame.
#  3. Keys 1-5 switch scenes while running.
#  4. The painter's order is right: on each scene's default view, frames drawn in sorted order
#     without a depth test equal the frames drawn with the depth buffer on (host, model --zbuf).
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
zsim="$BUILD/sim-z-w8/gpusim"
need_file "$dir/host-voxel" "$dir/host-voxel-chip" "$dir/host-knot" "$dir/host-tetra" "$dir/knot.elf" "$zsim"
work=$(fresh_dir scene-host-features)

# 1. no lines
"$dir/host-voxel" --no-lines --frames "$work/nolines" --keys-at 2:f >"$work/nolines.log"
expect_line "wireframe: the GPU has no lines" "$work/nolines.log"
expect_line "^wireframe on" "$work/nolines.log"
expect_eq "$(count '^frame ' "$work/nolines.log")" 4 "frames without lines"
"$dir/host-voxel" --frames "$work/lines" --keys-at 2:f >"$work/lines.log"
# With lines the wireframe frames use fewer primitives than the triangle-pair emulation.
p_lines=$(grep '^frame 3:' "$work/lines.log" | sed -E 's/.*prims ([0-9]+).*/\1/')
p_tris=$(grep '^frame 3:' "$work/nolines.log" | sed -E 's/.*prims ([0-9]+).*/\1/')
expect_eq "$p_tris" $((2 * p_lines)) "primitives without lines (two triangles per line)"
echo "no-lines: wireframe as $p_tris triangles instead of $p_lines lines"
"$dir/host-voxel-chip" --no-lines --frames "$work/chip-nolines" --keys-at 2:f >"$work/chip-nolines.log"
expect_line "line emulation is not built in" "$work/chip-nolines.log"
if grep -q "^wireframe on" "$work/chip-nolines.log"; then
    fail "a build without line emulation turned the wireframe on on a GPU without lines"
fi
expect_eq "$(count '^frame ' "$work/chip-nolines.log")" 4 "frames of the chip build without GPU lines"
"$dir/host-voxel-chip" --frames "$work/chip-lines" --keys-at 2:f >"$work/chip-lines.log"
expect_line "^wireframe on" "$work/chip-lines.log"
for f in "$work"/lines/*; do
    cmp -s "$f" "$work/chip-lines/$(basename "$f")" ||
        fail "chip build (no line emulation) frame $(basename "$f") differs from the default build's"
done

# 2. depth buffer, co-simulated against the host build
run_to "$work/z-cosim.out" 300 "$zsim" cosim --fw "$dir/knot.elf" --frames "$work/z-cosim" \
    --uart-log "$work/z-cosim.log" --keys-at 1:z
[ "$status" -eq 0 ] || { tail -n 5 "$work/z-cosim.out"; fail "z co-simulation failed (status $status)"; }
"$dir/host-knot" --zbuf --frames "$work/z-host" --keys-at 1:z >"$work/z-host.log"
expect_line "^depth buffer on" "$work/z-host.log"
same_pngs "$work/z-cosim" "$work/z-host" "depth buffer"
echo "zbuf: $(ls "$work/z-cosim" | wc -l) frames with the depth test, identical in co-simulation and on the host"
# Without a depth buffer the key is refused politely.
"$dir/host-knot" --keys-at 1:z >"$work/noz.log"
expect_line "the GPU has none" "$work/noz.log"

# 3. scene switching (keys typed at a frame's doorbell act from the frame after next: voxel from
# frame 2, cubes from frame 3 of the 4)
"$dir/host-tetra" --frames "$work/switch" --keys-at 1:4 --keys-at 2:2 >"$work/switch.log"
expect_line "^scene voxel: " "$work/switch.log"
expect_line "^scene cubes: 768 triangles" "$work/switch.log"
# 4. painter's order against the depth buffer
for scene in cubes landscape voxel knot; do
    "$dir/host-$scene" --zbuf --frames "$work/painter-$scene" >/dev/null
    "$dir/host-$scene" --zbuf --frames "$work/zbuf-$scene" --keys-at 1:z >/dev/null
    for f in 0001 0002 0003; do
        cmp -s "$work/painter-$scene/$f.png" "$work/zbuf-$scene/$f.png" || fail "$scene frame $f: painter's order differs from the depth buffer"
    done
done
echo "painter: sorted frames equal depth-buffered frames on cubes, landscape, voxel, knot"
pass "host-features: no-lines wireframe, depth buffer (co-simulated), scene switching, painter = depth buffer"
