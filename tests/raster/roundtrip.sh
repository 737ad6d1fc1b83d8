#!/usr/bin/env bash
# The primitive-list writer is the parser's inverse (cosim/prim_list.h): parse -> write -> parse gives
# the same ops, and the written text is a fixed point, on the example lists, on the exact-once meshes,
# and on generated lists holding every op kind (ztri included) with values at the ends of their
# ranges. `gpusim cosim --dump-lists` writes its lists with the same writer.
# The same property is checked on arbitrary input by tests/fuzz/fuzz_prim_list.cpp.
set -euo pipefail
: "${GPUSIM:?}" "${BUILD:?}" "${PYTHON:=python3}"
work="$BUILD/test-roundtrip"
rm -rf "$work" && mkdir -p "$work/lists"
for kind in grid fan; do
    "$PYTHON" tests/raster/gen_mesh.py "$kind" 1 >"$work/lists/$kind.txt"
done
"$GPUSIM" list-roundtrip tests/raster/*.txt "$work"/lists/*.txt >"$work/files.out"
"$GPUSIM" list-roundtrip --generate 200 --seed 1 >"$work/generated.out"
# A generated list holds every kind: the census of each names all four with a count above zero.
if grep -q -E '(clear|tri|line|ztri) 0[,)]' "$work/generated.out"; then
    echo "a generated list misses an op kind:"; grep -E '(clear|tri|line|ztri) 0[,)]' "$work/generated.out" | head -n 3
    exit 1
fi
grep -q 'ztri [1-9]' "$work/files.out" || { echo "no example list holds a ztri"; exit 1; }
lists=$(($(grep -c 'read back equal$' "$work/files.out") + $(grep -c 'read back equal$' "$work/generated.out")))
echo "roundtrip: $lists lists (examples, meshes, generated with every op kind) read back as the same ops"

