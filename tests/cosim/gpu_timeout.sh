#!/usr/bin/env bash
# A GPU that does not finish a batch in time ends the run with a clear message and a non-zero status
# (the cycle budget is made absurdly small to provoke it), and QEMU does not outlive the harness.
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD
work=$(fresh_dir cosim-gpu-timeout)
run_to "$work/out" 60 "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --max-batch-cycles 1000 \
    --summary "$work/summary"
cat "$work/out"
[ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "expected a prompt failure, got status $status"
[ "$(summary error "$work/summary")" = gpu-timeout ] || fail "the summary names another error"
expect_line "cosim: error: GPU timeout" "$work/out"
no_qemu_left
pass "gpu-timeout: reported and ended with status $status"
