#!/usr/bin/env bash
# make waves' trace path, end to end on the trace build (cosim/waves.mk: $BUILD/sim-trace-w8/gpusim,
# GPUSIM_TRACE to use another): a simulator built without tracing refuses --trace; the trace build
# writes an FST of frame 1 of the 4-frame tetra test firmware that is non-trivial, holds every
# signal of cosim/waves/gpu.gtkw (tests/cosim/waves_check.py, through fst2vcd) and exactly one
# frame (FRAME_COUNT 1 at its start, 2 once, nothing else); and gtkwave itself (headless, under
# xvfb-run) opens the trace with the save file and shows every one of its lines. Needs the trace
# build (make test builds it) and gtkwave (tools/packages.txt): missing, it fails.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD PYTHON
GPUSIM_TRACE=${GPUSIM_TRACE:-$BUILD/sim-trace-w8/gpusim}
FW=$BUILD/fw-test/tetra.elf
need_file "$FW"
[ -x "$GPUSIM_TRACE" ] || fail "missing $GPUSIM_TRACE: make $GPUSIM_TRACE (the trace build)"
command -v fst2vcd >/dev/null && command -v gtkwave >/dev/null ||
    fail "no fst2vcd/gtkwave: bash tools/setup.sh"
work=$(fresh_dir cosim-waves)

# The normal build: --trace is a usage error that says what to do.
run_to "$work/plain.out" 30 "$GPUSIM" cosim --fw "$FW" --frames "$work/plain" --trace "$work/plain.fst"
expect_status 2 "--trace on $GPUSIM"
expect_line "built without tracing: use make waves" "$work/plain.out"
[ ! -e "$work/plain.fst" ] || fail "$GPUSIM wrote a trace"

# The trace build: frame 1, the run goes on to the firmware's end (4 frames).
run_to "$work/out" 300 "$GPUSIM_TRACE" cosim --fw "$FW" --frames "$work/frames" --summary "$work/summary" \
    --trace "$work/frame1.fst" --trace-frame 1
expect_status 0 "the traced run"
[ "$(summary frames "$work/summary")" = 4 ] || fail "expected 4 frames, got $(summary frames "$work/summary")"
expect_line "^cosim: tracing frame 1 -> " "$work/out"
expect_line "^cosim: trace of frame 1 written: " "$work/out"
size=$(stat -c %s "$work/frame1.fst")
[ "$size" -gt 100000 ] || fail "the trace is only $size bytes"

# Every save-file signal in the FST, and FRAME_COUNT going 1 -> 2 exactly once inside it.
status=0
"$PYTHON" tests/cosim/waves_check.py "$work/frame1.fst" --gtkw cosim/waves/gpu.gtkw \
    --frame-count 'TOP.gpu_top.u_core.frame_count[31:0]' --frame 1 >"$work/check" 2>&1 || status=$?
cat "$work/check"
expect_status 0 "waves_check.py"

# gtkwave: as many traces in its window as the save file has signals and comments.
want=$(grep -cvE '^(\[|@|\*|$)' cosim/waves/gpu.gtkw)
run_to "$work/gtkwave.out" 60 xvfb-run -a gtkwave -S tests/cosim/waves_list.tcl "$work/frame1.fst" cosim/waves/gpu.gtkw
expect_status 0 "gtkwave -S"
expect_eq "$(count '^trace: ' "$work/gtkwave.out")" "$want" "traces gtkwave shows of cosim/waves/gpu.gtkw"
no_qemu_left
pass "waves: frame 1 traced ($((size / 1024)) KiB FST), $want save-file lines found by waves_check and gtkwave"
