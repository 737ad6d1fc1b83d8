#!/usr/bin/env bash
# The primitive-list writer is the parser's inverse (cosim/prim_list.h): parse -> write -> parse gives
# the same ops, and the written text is a fixed point, on the example lists, on the exact-once meshes,
# and on generated lists holding every op kind (ztri included) with values at the ends of their
# ranges. `gpusim cosim --dump-lists` writes its lists with the same writer.
# The same property is checked on arbitrary input by tests/fuzz/fuzz_prim_list.cpp.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD PYTHON
work=$(fresh_dir raster-list-roundtrip)
mkdir -p "$work/lists"
for kind in grid fan; do
    "$PYTHON" tests/raster/gen_mesh.py "$kind" 1 >"$work/lists/$kind.txt"
done
run_to "$work/files.out" 60 "$GPUSIM" list-roundtrip tests/raster/*.txt "$work"/lists/*.txt
[ "$status" -eq 0 ] || { cat "$work/files.out"; fail "a list does not round-trip (status $status)"; }
run_to "$work/generated.out" 60 "$GPUSIM" list-roundtrip --generate 200 --seed 1
[ "$status" -eq 0 ] || { cat "$work/generated.out"; fail "a generated list does not round-trip (status $status)"; }
expect_line 'ztri [1-9]' "$work/files.out"  # an example list holds a ztri
lists=$(($(grep -c 'read back equal$' "$work/files.out") + $(grep -c 'read back equal$' "$work/generated.out")))
pass "roundtrip: $lists lists (examples, meshes, generated with every op kind) read back as the same ops"

