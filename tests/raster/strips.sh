#!/usr/bin/env bash
# `gpusim raster` on GPUs that draw in strips (suite raster-strips): the same lists on the 640x480
# GPU that draws its frame whole (sim-f640-w8), on the one with strips of 16 rows on chip
# (sim-s16-f640-w8, raster rings each batch once per strip, every strip opened with its clear) and
# on the one whose frames are behind the SDRAM's port model (sim-dram-s16-f640-w8): each run's
# frame from the VGA pins equals the golden model's, and the three frames are the same bytes. The
# flat example and the depth-tested one (two triangles piercing each other, a flat tri and a line
# over them: the strip's depths cleared where it opens), and 3,000 small depth-tested triangles
# piled across three strip boundaries (tests/raster/depth_tiny.py: spans cleared by epoch, written
# in part by one triangle and tested by the next).
source "$(dirname "$0")/../lib.sh"
need BUILD
whole=${1:?usage: strips.sh WHOLE_SIM STRIP_SIM DRAM_SIM} strips=${2:?} dram=${3:?}
need_file "$whole" "$strips" "$dram"
work=$(fresh_dir raster-strips)
python3 tests/raster/depth_tiny.py "$work/depth_tiny.txt" || fail "depth_tiny.py did not write its list"
n=0
for list in tests/raster/example.txt tests/raster/depth_example.txt "$work/depth_tiny.txt"; do
    name=$(basename "$list" .txt)
    for gpu in whole strips dram; do
        sim=${!gpu}
        run_to "$work/$name-$gpu.out" 120 "$sim" raster --in "$list" --out "$work/$name-$gpu"
        expect_status 0 "$name on the $gpu GPU: RTL against the model (log: $work/$name-$gpu.out)"
        n=$((n + 1))
    done
    expect_eq "$(sed -n 's/.*"strip_rows": \([0-9]*\).*/\1/p' "$work/$name-strips/stats.json")" 16 "$name: strip rows of the strip GPU"
    expect_eq "$(sed -n 's/.*"batches": \([0-9]*\).*/\1/p' "$work/$name-dram/stats.json")" \
        $((30 * $(sed -n 's/.*"batches": \([0-9]*\).*/\1/p' "$work/$name-whole/stats.json"))) "$name: batches, once per strip"
    for gpu in strips dram; do
        cmp -s "$work/$name-whole/rtl.raw" "$work/$name-$gpu/rtl.raw" || fail "$name: the $gpu GPU's frame differs from the whole frame's"
    done
done
pass "raster-strips: 3 lists on 3 GPUs at 640x480 ($n runs): drawn whole, in strips of 16 on chip and with the frames behind the SDRAM port, every frame = model, the three the same bytes"
