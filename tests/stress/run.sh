#!/usr/bin/env bash
# `make stress` in make test's short form: every case of tests/stress/stress.c with fewer frames
# (--short), on the fixed and the float backend, each under a timeout (a hang fails the suite), then
# a sample co-simulated: three frames (a vertex 1 ulp behind the near plane, clipped by the firmware;
# two slivers sharing a row of pixel centres; the ends of the Q12.4 range), rendered through the RTL by `gpusim raster` (RTL equal to the golden model)
# and compared with the frame the stress program's golden model drew through the driver.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
need_file "$BUILD/tests/stress" "$BUILD/tests/stress_float"
work=$(fresh_dir fw-stress)
mkdir -p "$work/lists"
for b in stress stress_float; do
    run_to "$work/$b.md" 120 "$BUILD/tests/$b" --short --lists "$work/lists"
    cat "$work/$b.md"
    [ "$status" -ne 124 ] || fail "$b --short hung (no end within 120 s)"
    expect_status 0 "$b --short"
    expect_line '^[0-9]+ passed, 0 failed$' "$work/$b.md"
done
# The lists are the float build's (written last). About 1.5 s of CPU each.
sampled=0
for name in near-behind sliver-row q12-4-ends; do
    list="$work/lists/$name.txt"
    need_file "$list"
    run_to "$work/$name.raster" 60 "$GPUSIM" raster --in "$list" --out "$work/$name"
    [ "$status" -eq 0 ] || { cat "$work/$name.raster"; fail "$name: RTL and model differ (status $status)"; }
    cmp -s "$work/$name/rtl.raw" "$work/lists/$name.raw" ||
        fail "$name: the RTL's frame differs from the one the stress program's model drew"
    sampled=$((sampled + 1))
done
fixed=$(tail -1 "$work/stress.md")
pass "stress: fixed $fixed, float $(tail -1 "$work/stress_float.md"); $sampled frames co-simulated, RTL = model = the stress run's"
