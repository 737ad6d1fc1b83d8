#!/usr/bin/env bash
# The red/cyan anaglyph on the framebuffer write mask (issue #14): G on the cubes scene.
#  1. Host build (golden model): the last frame's pixels where the eyes overlap carry both eyes
#     (red and cyan at once: each eye wrote its own plane), each eye also shows alone at the
#     fringes, and no pixel is outside the anaglyph palette (tests/scenes/anaglyph_pixels.py).
#  2. Co-simulated (QEMU + the RTL, every frame checked against the model by the harness): the
#     same frames, byte for byte.
#  3. A GPU without the mask (fw-host --no-wmask, CAPS_WMASK = 0): the firmware falls back to
#     drawing the right eye over the left, so no pixel has both (the check can tell the two).
#  4. Depth per eye: with the depth buffer on (Z), each eye clears its own depths, so the anaglyph
#     frames equal the painter's-order ones (a right eye tested against the left eye's depths
#     would lose its pixels wherever the left eye's surface is nearer).
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
sim="$BUILD/sim-w8/gpusim"
PY=${PYTHON:-python3}
need_file "$dir/host-cubes" "$dir/cubes.elf" "$sim"
work=$(fresh_dir scene-anaglyph)
last=0003.png

# 1. host
"$dir/host-cubes" --frames "$work/host" --keys-at 1:g >"$work/host.log"
expect_line "^anaglyph on" "$work/host.log"
"$PY" tests/scenes/anaglyph_pixels.py "$work/host/$last" --expect-both || fail "host anaglyph frame: eyes do not overlap"

# 2. co-simulated
run_to "$work/cosim.out" 300 "$sim" cosim --fw "$dir/cubes.elf" --frames "$work/cosim" \
    --uart-log "$work/cosim.log" --keys-at 1:g
[ "$status" -eq 0 ] || { tail -n 5 "$work/cosim.out"; fail "anaglyph co-simulation failed (status $status)"; }
same_pngs "$work/cosim" "$work/host" "anaglyph co-simulated against the host build"
"$PY" tests/scenes/anaglyph_pixels.py "$work/cosim/$last" --expect-both >/dev/null || fail "co-simulated anaglyph frame: eyes do not overlap"

# 3. without the mask
"$dir/host-cubes" --no-wmask --frames "$work/nomask" --keys-at 1:g >"$work/nomask.log"
"$PY" tests/scenes/anaglyph_pixels.py "$work/nomask/$last" --expect-none || fail "no-mask fallback: a pixel has both eyes"

# 4. depth per eye
"$dir/host-cubes" --zbuf --frames "$work/painter" --keys-at 1:g >/dev/null
"$dir/host-cubes" --zbuf --frames "$work/zbuf" --keys-at 1:gz >"$work/zbuf.log"
expect_line "^depth buffer on" "$work/zbuf.log"
for f in 0002 0003; do
    cmp -s "$work/painter/$f.png" "$work/zbuf/$f.png" || fail "anaglyph frame $f: depth-tested eyes differ from the painter's order"
done
pass "anaglyph: both eyes in the overlap (host and co-simulated, identical), fallback without the mask, depth per eye"
