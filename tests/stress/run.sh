#!/usr/bin/env bash
# `make stress` in make test's short form: every case of tests/stress/stress.c with fewer frames
# (--short), on the fixed and the float backend, at the contract's frame and at its largest
# (640x480), each under a timeout (a hang fails the suite), then at each frame a sample co-simulated: three frames (a vertex 1 ulp behind the near plane, clipped by the firmware;
# two slivers sharing a row of pixel centres; the ends of the Q12.4 range), rendered through the RTL by `gpusim raster` (RTL equal to the golden model)
# and compared with the frame the stress program's golden model drew through the driver.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
need_file "$BUILD/tests/stress" "$BUILD/tests/stress_float"
# The contract's largest frame: the stress program draws it on its model, the sample goes through
# a GPU built for it (mk/builds.toml's sim-f640-w8, with the depth buffer, unused by these lists).
gpusim_640="$BUILD/sim-f640-w8/gpusim"
need_file "$gpusim_640"
work=$(fresh_dir fw-stress)
sampled=0
summary=""
for frame in 320x240 640x480; do
    mkdir -p "$work/$frame/lists"
    for b in stress stress_float; do
        out="$work/$frame/$b.md"
        run_to "$out" 120 "$BUILD/tests/$b" --short --frame "$frame" --lists "$work/$frame/lists"
        cat "$out"
        [ "$status" -ne 124 ] || fail "$b --short --frame $frame hung (no end within 120 s)"
        expect_status 0 "$b --short --frame $frame"
        expect_line '^[0-9]+ passed, 0 failed$' "$out"
    done
    sim=$GPUSIM
    [ "$frame" = 640x480 ] && sim=$gpusim_640
    # The lists are the float build's (written last). About 1.5 s of CPU each at 320x240.
    for name in near-behind sliver-row q12-4-ends; do
        list="$work/$frame/lists/$name.txt"
        need_file "$list"
        run_to "$work/$frame/$name.raster" 60 "$sim" raster --in "$list" --out "$work/$frame/$name"
        [ "$status" -eq 0 ] || { cat "$work/$frame/$name.raster"; fail "$frame $name: RTL and model differ (status $status)"; }
        cmp -s "$work/$frame/$name/rtl.raw" "$work/$frame/lists/$name.raw" ||
            fail "$frame $name: the RTL's frame differs from the one the stress program's model drew"
        sampled=$((sampled + 1))
    done
    summary="$summary $frame: fixed $(tail -1 "$work/$frame/stress.md"), float $(tail -1 "$work/$frame/stress_float.md");"
done
pass "stress:$summary $sampled frames co-simulated, RTL = model = the stress run's"
