# tests/lib.sh — sourced by every shell test: strict mode, the checks they all make, and the one
# summary line that tests/run_all.sh shows for a passing suite (the log's last line).
#
#   need VAR...                  fail unless each environment variable is set (GPUSIM, BUILD, ...)
#   need_file FILE...            fail unless each file exists ("make test builds it")
#   work=$(fresh_dir NAME)       an empty $BUILD/tests-run/NAME
#   run_to FILE TIMEOUT CMD...   run CMD under `timeout`, stdout and stderr to FILE; sets $status
#                                (never stops the test: the caller judges the status)
#   fail MESSAGE                 print MESSAGE and end the test with status 1
#   expect_status WANT [WHAT]    fail unless $status is WANT
#   expect_eq GOT WANT WHAT      fail unless two numbers are equal
#   png_count DIR                the PNG files in DIR
#   count PATTERN FILE           lines of FILE matching the extended regex (0 when none, or no file)
#   expect_line PATTERN FILE     fail unless some line of FILE matches the extended regex
#   expect_no_line PATTERN FILE  fail if any line of FILE matches
#   same_pngs DIR_A DIR_B WHAT   fail unless both hold the same PNG names with identical bytes
#   summary KEY FILE             a field of a `gpusim cosim --summary` file (key=value lines)
#   pty_session TIMEOUT CMD... -- CLIENT_ARG...
#                                CMD (a simulator given --uart-pty "$work/tty") in the background,
#                                output to $work/out, while tests/cosim/pty_keys.py types into the
#                                pty (transcript to $work/transcript); sets $status (the simulator's)
#                                and $client (the client's), shows their last lines
#   expect_pty_echo WHO          after pty_session: WHO (cosim, socsim) announced the pty and removed
#                                its link, the help came twice, nothing was dropped, and the
#                                transcript ('\r' dropped) equals the UART log byte for byte
#   cosim_run SIM ELF TIMEOUT ARG...
#                                `SIM cosim` of ELF, frames to $work/frames, UART to $work/uart.log,
#                                summary to $work/summary, output to $work/out; sets $status
#   expect_frames N              N frame lines in $work/uart.log, all N equal to the golden model
#   no_qemu_left                 fail if a co-simulation QEMU started by this test still runs (other
#                                suites run beside it: their QEMUs do not count)
#   pass MESSAGE                 the summary line; the test ends with status 0
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# This test's mark, inherited by everything it starts (the harness, and the harness's QEMU): how
# no_qemu_left tells its own QEMUs from those of the suites running meanwhile.
TEST_RUN_TAG="$BASHPID.${EPOCHREALTIME/./}"
export TEST_RUN_TAG

need() {
    local v
    for v in "$@"; do
        [ -n "${!v:-}" ] || fail "$v is not set (tests/run_all.sh sets it; run through make test)"
    done
}

need_file() {
    local f
    for f in "$@"; do
        [ -e "$f" ] || fail "missing $f (make test builds it)"
    done
}

fresh_dir() {
    local dir="${BUILD:?}/tests-run/$1"
    rm -rf "$dir" && mkdir -p "$dir"
    echo "$dir"
}

run_to() {
    local out="$1" limit="$2"
    shift 2
    status=0
    timeout "$limit" "$@" >"$out" 2>&1 || status=$?
}

fail() {
    echo "FAILED: $*" >&2  # stderr: a fail inside $(...) must still be seen
    exit 1
}

expect_status() {
    [ "$status" -eq "$1" ] || fail "${2:-the command}: expected status $1, got $status"
}

expect_eq() {
    [ "$1" -eq "$2" ] || fail "$3: got $1, expected $2"
}

png_count() {
    find "$1" -maxdepth 1 -name '*.png' | wc -l
}

count() {
    [ -f "$2" ] || { echo 0; return; }
    grep -cE -- "$1" "$2" || true
}

# wait_for_pty LINK WHAT LOG [READY]: wait up to 20 s for a simulator's --uart-pty link, or fail
# naming WHAT and the tail of its LOG; with READY (a regex), then up to 60 s more for a line of LOG
# matching it: the firmware's UART is set up. Bytes sent before that are lost as on a board before
# its firmware runs (the UART's set-up clears its FIFOs), and a client would wait out its resend
# timeout for them.
wait_for_pty() {
    local _
    for _ in $(seq 100); do
        [ -e "$1" ] && break
        sleep 0.2
    done
    [ -e "$1" ] || fail "$2 made no pty ($(tail -n 3 "$3"))"
    [ -n "${4:-}" ] || return 0
    for _ in $(seq 300); do
        grep -qE -- "$4" "$3" && return 0
        sleep 0.2
    done
    fail "$2 printed no line matching '$4' ($(tail -n 3 "$3"))"
}

expect_line() {
    grep -qE -- "$1" "$2" || fail "no line matching '$1' in $2"
}

expect_no_line() {
    ! grep -qE -- "$1" "$2" || fail "a line matches '$1' in $2: $(grep -m1 -E -- "$1" "$2")"
}

same_pngs() {
    local a="$1" b="$2" what="$3" f n_a n_b
    n_a=$(png_count "$a")
    n_b=$(png_count "$b")
    [ "$n_a" -eq "$n_b" ] || fail "$what: $n_a frames against $n_b"
    [ "$n_a" -gt 0 ] || fail "$what: no frames"
    for f in "$a"/*.png; do
        cmp -s "$f" "$b/$(basename "$f")" || fail "$what: $(basename "$f") differs"
    done
}

summary() {
    local value
    value=$(sed -n "s/^$1=//p" "$2")
    [ -n "$value" ] || fail "no '$1' in $2"
    echo "$value"
}

pty_session() {
    local limit="$1" cmd=() sim
    shift
    while [ "$1" != -- ]; do
        cmd+=("$1")
        shift
    done
    shift
    timeout "$limit" "${cmd[@]}" >"$work/out" 2>&1 &
    sim=$!
    client=0
    python3 tests/cosim/pty_keys.py "$work/tty" "$work/transcript" "$@" >"$work/client.out" 2>&1 || client=$?
    status=0
    wait "$sim" || status=$?
    cat "$work/client.out"
    tail -n 3 "$work/out"
}

expect_pty_echo() {
    local link="$work/tty"
    expect_line "^$1: UART on $link \(/dev/pts/[0-9]+\)$" "$work/out"
    [ ! -e "$link" ] || fail "the link $link is still there after the run"
    expect_eq "$(count 'H this help' "$work/uart.log")" 2 "help texts in the log (boot and H)"
    expect_eq "$(summary uart_pty_dropped "$work/summary")" 0 "bytes dropped (summary)"
    tr -d '\r' <"$work/transcript" >"$work/transcript.lf"
    cmp -s "$work/transcript.lf" "$work/uart.log" || fail "the pty's transcript differs from the UART log"
}

cosim_run() {
    local sim="$1" elf="$2" limit="$3"
    shift 3
    run_to "$work/out" "$limit" "$sim" cosim --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" \
        --summary "$work/summary" "$@"
}

expect_frames() {
    expect_eq "$(count '^frame ' "$work/uart.log")" "$1" "frames rendered"
    expect_eq "$(summary frames_model_checked "$work/summary")" "$1" "frames equal to the model"
}

no_qemu_left() {
    # Only a QEMU that carries this test's TEST_RUN_TAG in its environment counts: other suites and
    # other checkouts may be co-simulating meanwhile.
    local pid
    for pid in $(pgrep -f "mem-path=/proc/self/fd" || true); do
        if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qxF "TEST_RUN_TAG=$TEST_RUN_TAG"; then
            fail "a QEMU is still running (pid $pid)"
        fi
    done
}

pass() {
    echo "$*"
    exit 0
}
