#!/usr/bin/env bash
# Killing either side of the co-simulation ends the other within a bounded time, with a non-zero
# status, and leaves no shared-memory file behind.
#   kill.sh qemu     SIGKILL QEMU mid-run: the harness must report it and exit non-zero
#   kill.sh harness  SIGKILL the harness mid-run: QEMU must die with it
#   kill.sh sigterm  SIGTERM the harness mid-run: it stops QEMU and exits non-zero
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD
mode="${1:?usage: kill.sh qemu|harness|sigterm}"
work=$(fresh_dir "cosim-kill-$mode")

"$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --summary "$work/summary" >"$work/out" 2>&1 &
harness=$!

# Wait (bounded) until the run is under way: the first frame exists.
for _ in $(seq 1 300); do
    [ -e "$work/frames/0000.png" ] && break
    sleep 0.1
done
[ -e "$work/frames/0000.png" ] || { kill -9 "$harness"; fail "no frame within 30 s"; }
qemu=$(pgrep -P "$harness" -f qemu-system-riscv32 | head -n 1)
[ -n "$qemu" ] || fail "QEMU child not found"
shm_before=$(ls /dev/shm | grep -c "^gpu-cosim-$harness-" || true)

case "$mode" in
    qemu) kill -9 "$qemu" ;;
    harness) kill -9 "$harness" ;;
    sigterm) kill -TERM "$harness" ;;
    *) fail "unknown mode $mode" ;;
esac

# Both processes must be gone within 10 s.
for _ in $(seq 1 100); do
    if ! kill -0 "$harness" 2>/dev/null && ! kill -0 "$qemu" 2>/dev/null; then
        break
    fi
    sleep 0.1
done
kill -0 "$qemu" 2>/dev/null && { kill -9 "$qemu"; fail "QEMU still running 10 s after the $mode kill"; }
kill -0 "$harness" 2>/dev/null && { kill -9 "$harness"; fail "harness still running 10 s after the $mode kill"; }
status=0
wait "$harness" || status=$?
[ "$status" -ne 0 ] || fail "harness exited 0 after the $mode kill"
[ "$shm_before" -eq 0 ] || fail "a shared-memory file was visible during the run"
! ls /dev/shm | grep -q "^gpu-cosim-$harness-" || fail "shared-memory file left behind"
case "$mode" in
    qemu) [ "$(summary error "$work/summary")" = qemu-died ] || fail "QEMU's death not reported" ;;
    sigterm) [ "$(summary error "$work/summary")" = signal ] || fail "the signal not reported" ;;
esac
pass "kill $mode: both sides ended (harness status $status), no shared-memory file left"
