#!/usr/bin/env bash
# A GPU that does not finish a batch in time ends the run with a clear message and a non-zero status
# (the cycle budget is made absurdly small to provoke it), and QEMU does not outlive the harness.
set -euo pipefail
: "${GPUSIM:?}" "${FW_ELF:?}" "${BUILD:?}"
work="$BUILD/test-timeout"
rm -rf "$work" && mkdir -p "$work"
set +e
timeout 60 "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --max-batch-cycles 1000 >"$work/out" 2>&1
status=$?
set -e
cat "$work/out"
[ "$status" -ne 0 ] && [ "$status" -ne 124 ] || { echo "expected a prompt failure, got status $status"; exit 1; }
grep -q "cosim: error: GPU timeout" "$work/out"
# Only a QEMU started from this directory counts: other checkouts may be co-simulating meanwhile.
for pid in $(pgrep -f "mem-path=/proc/self/fd" || true); do
    [ "$(readlink "/proc/$pid/cwd" 2>/dev/null)" != "$PWD" ] || { echo "a QEMU is still running"; exit 1; }
done
echo "gpu-timeout: reported and ended with status $status"
