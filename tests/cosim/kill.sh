#!/usr/bin/env bash
# Killing either side of the co-simulation ends the other within a bounded time, with a non-zero
# status, and leaves no shared-memory file behind.
#   kill.sh qemu     SIGKILL QEMU mid-run: the harness must report it and exit non-zero
#   kill.sh harness  SIGKILL the harness mid-run: QEMU must die with it
#   kill.sh sigterm  SIGTERM the harness mid-run: it stops QEMU and exits non-zero
set -euo pipefail
: "${GPUSIM:?}" "${FW_ELF:?}" "${BUILD:?}"
mode="$1"
work="$BUILD/test-kill-$mode"
rm -rf "$work" && mkdir -p "$work"

"$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" >"$work/out" 2>&1 &
harness=$!

# Wait (bounded) until the run is under way: the first frame exists.
for _ in $(seq 1 300); do
    [ -e "$work/frames/0000.png" ] && break
    sleep 0.1
done
[ -e "$work/frames/0000.png" ] || { echo "no frame within 30 s"; kill -9 "$harness"; exit 1; }
qemu=$(pgrep -P "$harness" -f qemu-system-riscv32 | head -n 1)
[ -n "$qemu" ] || { echo "QEMU child not found"; exit 1; }
shm_before=$(ls /dev/shm | grep -c "^gpu-cosim-$harness-" || true)

case "$mode" in
    qemu) kill -9 "$qemu" ;;
    harness) kill -9 "$harness" ;;
    sigterm) kill -TERM "$harness" ;;
esac

# Both processes must be gone within 10 s.
for _ in $(seq 1 100); do
    if ! kill -0 "$harness" 2>/dev/null && ! kill -0 "$qemu" 2>/dev/null; then
        break
    fi
    sleep 0.1
done
kill -0 "$qemu" 2>/dev/null && { echo "QEMU still running 10 s after the $mode kill"; kill -9 "$qemu"; exit 1; }
kill -0 "$harness" 2>/dev/null && { echo "harness still running 10 s after the $mode kill"; kill -9 "$harness"; exit 1; }
set +e
wait "$harness"
status=$?
set -e
[ "$status" -ne 0 ] || { echo "harness exited 0 after the $mode kill"; exit 1; }
[ "$shm_before" -eq 0 ] || { echo "a shared-memory file was visible during the run"; exit 1; }
if ls /dev/shm | grep -q "^gpu-cosim-$harness-"; then
    echo "shared-memory file left behind"
    exit 1
fi
[ "$mode" = harness ] || grep -E "cosim: error: (QEMU was killed|stopped by signal)" "$work/out"
echo "kill $mode: both sides ended (harness status $status), no shared-memory file left"
