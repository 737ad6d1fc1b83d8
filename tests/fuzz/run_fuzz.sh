#!/usr/bin/env bash
# Runs the libFuzzer targets built by tests/fuzz/fuzz.mk.
#
#   run_fuzz.sh short TARGET   the deterministic run of `make test`: -seed=1, the checked-in seed
#                              corpus tests/fuzz/corpus/TARGET, then a fixed number of generated
#                              inputs (SHORT_RUNS below); new inputs go to a scratch directory,
#                              never into the checked-in corpus.
#   run_fuzz.sh long TARGET..  `make fuzz`: FUZZ_SECONDS (60) per target, corpus kept in
#                              $FUZZ_DIR/corpus-TARGET (started from the seeds), a progress line
#                              every 10 s and a summary table at the end.
#
# A crash, a sanitizer report, a failed property check, a leak or an input slower than TIMEOUT
# seconds fails the run (non-zero status); the input is kept as $FUZZ_DIR/artifacts/TARGET-*
# and can be replayed with `$FUZZ_DIR/fuzz_TARGET FILE`.
set -uo pipefail
cd "$(dirname "$0")/../.."
: "${FUZZ_DIR:=${BUILD:-build}/fuzz}" "${FUZZ_SECONDS:=60}"
TIMEOUT=25

# Generated inputs per target in the short run: about 5 s each on one core of the reference
# machine (exec/s differ by target: the firmware's scenes and the model's rasterizer are slower).
declare -A SHORT_RUNS=([prim_list]=50000 [input]=3000 [gpu_model]=2000 [gpu_driver]=8000 [upload]=15000
                       [meshfile]=60000 [meshconv]=300)

mode="${1:?usage: run_fuzz.sh short|long TARGET...}"
shift
[ $# -gt 0 ] || { echo "run_fuzz.sh: no targets"; exit 2; }
mkdir -p "$FUZZ_DIR/artifacts" "$FUZZ_DIR/logs"

# Fields of libFuzzer's final statistics and last status line.
stat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1; }
status_field() { grep -E '^#[0-9]+' "$2" | tail -n 1 | sed -n "s/.*$1: \([^ ]*\).*/\1/p"; }

failed=0
summary=()
for t in "$@"; do
    bin="$FUZZ_DIR/fuzz_$t"
    seeds="tests/fuzz/corpus/$t"
    # A target whose seeds are generated (fuzz.mk: from our own scripts) has them in the build.
    [ -d "$seeds" ] || seeds="$FUZZ_DIR/seeds-$t"
    log="$FUZZ_DIR/logs/$t-$mode.log"
    [ -x "$bin" ] || { echo "run_fuzz.sh: $bin is not built (make fuzz-build)"; exit 2; }
    [ -d "$seeds" ] || { echo "run_fuzz.sh: no seed corpus $seeds"; exit 2; }
    common=(-timeout=$TIMEOUT -print_final_stats=1 -artifact_prefix="$FUZZ_DIR/artifacts/$t-")
    if [ "$mode" = short ]; then
        runs="${SHORT_RUNS[$t]:-5000}"
        work="$FUZZ_DIR/short-$t"
        rm -rf "$work" && mkdir -p "$work"
        # Address-space randomisation off where allowed: pointer comparisons then trace the same
        # values every run, so the same inputs are generated (the C targets; the C++ one still
        # varies a little from run to run).
        norandom=()
        setarch "$(uname -m)" -R true 2>/dev/null && norandom=(setarch "$(uname -m)" -R)
        "${norandom[@]}" "$bin" "${common[@]}" -seed=1 -runs="$runs" "$work" "$seeds" >"$log" 2>&1
        rc=$?
    else
        work="$FUZZ_DIR/corpus-$t"
        mkdir -p "$work"
        echo "fuzz_$t: ${FUZZ_SECONDS} s, corpus $work (seeds $seeds), log $log"
        "$bin" "${common[@]}" -max_total_time="$FUZZ_SECONDS" "$work" "$seeds" >"$log" 2>&1 &
        pid=$!
        while kill -0 "$pid" 2>/dev/null; do
            sleep 10
            kill -0 "$pid" 2>/dev/null || break
            line=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
            echo "  fuzz_$t: ${line:-starting}"
        done
        wait "$pid"
        rc=$?
    fi
    execs=$(stat number_of_executed_units "$log")
    speed=$(stat average_exec_per_sec "$log")
    cov=$(status_field cov "$log")
    corp=$(status_field corp "$log")
    if [ $rc -eq 0 ]; then
        result=ok
    else
        result="FAILED (status $rc)"
        failed=$((failed + 1))
        echo "fuzz_$t: FAILED, status $rc; log $log:"
        grep -E 'ERROR|SUMMARY|runtime error|fuzz_[a-z_]*: |Test unit written|artifact' "$log" \
            | head -n 12 | sed 's/^/  | /'
    fi
    summary+=("$(printf '%-12s %-20s %10s execs %7s exec/s  cov %-5s corpus %s' "$t" "$result" \
        "${execs:-?}" "${speed:-?}" "${cov:-?}" "${corp:-?}")")
done

if [ "$mode" = long ]; then
    echo "summary (${FUZZ_SECONDS} s per target):"
fi
printf '%s\n' "${summary[@]}"
[ $failed -eq 0 ]
