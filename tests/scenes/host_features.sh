#!/usr/bin/env bash
# Features that depend on how the GPU was built, and runtime scene switching:
#  1. A GPU without line primitives (CAPS_LINES = 0): wireframe still works, edges drawn as thin
#     triangle pairs; no GPU error (a LINE primitive would set ERR_KIND and stop the firmware).
#  2. A GPU with the depth buffer (the RTL built with ENABLE_ZBUF, $BUILD/sim-z-w8): Z turns the
#     depth test on; co-simulation and the host build (model with --zbuf) agree on every frame.
#  3. Keys 1-5 switch scenes while running.
#  4. The painter's order is right: on each scene's default view, frames drawn in sorted order
#     without a depth test equal the frames drawn with the depth buffer on (host, model --zbuf).
set -euo pipefail
: "${BUILD:?}"
dir="$BUILD/fw-test"
work="$BUILD/test-scenes/features"
rm -rf "$work" && mkdir -p "$work"

# 1. no lines
"$dir/host-voxel" --no-lines --frames "$work/nolines" --keys-at 2:f >"$work/nolines.log"
grep -q "wireframe: the GPU has no lines" "$work/nolines.log" || { echo "no-lines mode not reported"; exit 1; }
grep -q "^wireframe on" "$work/nolines.log" || { echo "wireframe did not switch on"; exit 1; }
[ "$(grep -c '^frame ' "$work/nolines.log")" -eq 4 ] || { echo "frames missing without lines"; exit 1; }
"$dir/host-voxel" --frames "$work/lines" --keys-at 2:f >"$work/lines.log"
# With lines the wireframe frames use fewer primitives than the triangle-pair emulation.
p_lines=$(grep '^frame 3:' "$work/lines.log" | sed -E 's/.*prims ([0-9]+).*/\1/')
p_tris=$(grep '^frame 3:' "$work/nolines.log" | sed -E 's/.*prims ([0-9]+).*/\1/')
[ "$p_tris" -eq $((2 * p_lines)) ] || { echo "expected two triangles per line: $p_tris vs $p_lines"; exit 1; }
echo "no-lines: wireframe as $p_tris triangles instead of $p_lines lines"

# 2. depth buffer, co-simulated against the host build
zsim="$BUILD/sim-z-w8/gpusim"
if [ -x "$zsim" ]; then
    "$zsim" cosim --fw "$dir/knot.elf" --frames "$work/z-cosim" --uart-log "$work/z-cosim.log" \
        --keys-at 1:z >"$work/z-cosim.out" 2>&1 || { echo "z co-simulation failed"; tail -n 5 "$work/z-cosim.out"; exit 1; }
    "$dir/host-knot" --zbuf --frames "$work/z-host" --keys-at 1:z >"$work/z-host.log"
    grep -q "^depth buffer on" "$work/z-host.log" || { echo "depth test not enabled"; exit 1; }
    for f in "$work/z-cosim"/*.png; do
        cmp -s "$f" "$work/z-host/$(basename "$f")" || { echo "depth buffer: $(basename "$f") differs"; exit 1; }
    done
    echo "zbuf: $(ls "$work/z-cosim" | wc -l) frames with the depth test, identical in co-simulation and on the host"
else
    echo "missing $zsim"; exit 1
fi
# Without a depth buffer the key is refused politely.
"$dir/host-knot" --keys-at 1:z >"$work/noz.log"
grep -q "the GPU has none" "$work/noz.log" || { echo "missing CAPS_ZBUF message"; exit 1; }

# 3. scene switching
"$dir/host-tetra" --frames "$work/switch" --keys-at 1:4 --keys-at 3:2 >"$work/switch.log"
grep -q "^scene voxel: " "$work/switch.log" && grep -q "^scene cubes: 768 triangles" "$work/switch.log" || { echo "scene switch failed"; exit 1; }
# 4. painter's order against the depth buffer
for scene in cubes landscape voxel knot; do
    "$dir/host-$scene" --zbuf --frames "$work/painter-$scene" >/dev/null
    "$dir/host-$scene" --zbuf --frames "$work/zbuf-$scene" --keys-at 1:z >/dev/null
    for f in 0001 0002 0003; do
        cmp -s "$work/painter-$scene/$f.png" "$work/zbuf-$scene/$f.png" || { echo "$scene frame $f: painter's order differs from the depth buffer"; exit 1; }
    done
done
echo "painter: sorted frames equal depth-buffered frames on cubes, landscape, voxel, knot"
echo "host-features: no-lines wireframe, depth buffer (co-simulated), scene switching, painter = depth buffer"
