#!/usr/bin/env bash
# End to end: the firmware in QEMU drives the RTL; every frame captured from the VGA pins must equal
# the golden model's rendering of the same buffers (the harness checks each one and fails otherwise).
# Two runs must produce byte-identical PNG files and the same per-frame firmware statistics.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
# The test build of the default scene (FW_TEST_FRAMES frames): the same firmware as `make run`'s,
# with fewer frames, since the property does not grow with their number.
elf="$BUILD/fw-test/tetra.elf"
need_file "$elf"
work=$(fresh_dir cosim-end-to-end)

for run in a b; do
    run_to "$work/$run.out" 120 "$GPUSIM" cosim --fw "$elf" --frames "$work/$run" \
        --uart-log "$work/$run.uart" --summary "$work/$run.summary"
    expect_status 0 "co-simulation run $run"
done

frames=$(summary frames "$work/a.summary")
[ "$frames" -ge 2 ] || fail "only $frames frames written"
expect_eq "$(png_count "$work/a")" "$frames" "PNG files written"
expect_eq "$(summary frames_model_checked "$work/a.summary")" "$frames" "frames checked against the model"
same_pngs "$work/a" "$work/b" "two runs"
# Per-frame firmware lines, minus nothing: instruction counts are exact under -icount.
grep '^frame ' "$work/a.uart" >"$work/a.frames" || true
grep '^frame ' "$work/b.uart" >"$work/b.frames" || true
expect_eq "$(count '^frame ' "$work/a.uart")" "$frames" "firmware frame lines"
diff "$work/a.frames" "$work/b.frames" || fail "firmware statistics differ between runs"
# The scene moves: consecutive frames differ.
! cmp -s "$work/a/0000.png" "$work/a/0001.png" || fail "frames 0 and 1 are identical: nothing turns"
pass "end-to-end: $frames frames, identical across two runs, each equal to the golden model"
