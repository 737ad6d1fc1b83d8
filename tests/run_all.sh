#!/usr/bin/env bash
# The runner of tests/suites.toml's suites. `make test` calls it with GPUSIM, GPUSIM_FAST (the
# fast display path's simulator), FW_ELF, BUILD, PYTHON set (and SUITE when given); it prints one
# line per suite as each one ends (the log's tail on failure) and ends with "N passed, N failed".
#
#   tests/run_all.sh               every suite
#   SUITE='rtl-* fw-unit' ...      only the suites whose names match one of the globs
#   TEST_JOBS=N ...                N suites at a time (default: the number of cores, `nproc`);
#                                  TEST_JOBS=1: one after another, in the list's order
#   tests/run_all.sh --list        the names, one per line (with SUITE: the selected ones)
#
# The suites are tests/suites.toml's (their names, costs, what they need and their commands), as
# `suite NAME COST COMMAND...` lines (mk/gen_builds.py --suites; suite_alone: nothing runs beside
# it). A suite's output goes to $BUILD/test-logs/NAME.log, its CPU time (user and system seconds)
# to $BUILD/test-logs/NAME.cpu; each runs in a session of its own, stdin /dev/null. The costliest
# start first (the duration the last run recorded in $BUILD/test-logs/durations, else its cost),
# so that the lanes end together; the suites to run alone run first, one at a time.
set -u
cd "$(dirname "$0")/.."
: "${GPUSIM:?}" "${GPUSIM_FAST:?}" "${FW_ELF:?}" "${BUILD:?}" "${PYTHON:=python3}" "${SUITE:=*}"
: "${TEST_JOBS:=$(nproc 2>/dev/null || echo 1)}"
export GPUSIM GPUSIM_FAST FW_ELF BUILD PYTHON
[[ "$TEST_JOBS" =~ ^[1-9][0-9]*$ ]] || { echo "TEST_JOBS=$TEST_JOBS: expected a number of suites (1 or more)"; exit 2; }
list_only=0
[ "${1:-}" = "--list" ] && list_only=1
logs="$BUILD/test-logs"
mkdir -p "$logs"

selected() {
    local glob
    for glob in $SUITE; do
        # shellcheck disable=SC2053 # the glob is meant to match
        [[ "$1" == $glob ]] && return 0
    done
    return 1
}

# The selected suites, in the list's order: name, cost, alone (0/1), command (quoted for eval).
names=()
costs=()
alone=()
cmds=()
add_suite() {
    local solo="$1" name="$2" cost=30
    shift 2
    if [[ "$1" =~ ^[0-9]+$ ]]; then
        cost=$1
        shift
    fi
    selected "$name" || return 0
    if [ "$list_only" -eq 1 ]; then
        echo "$name"
        return 0
    fi
    names+=("$name")
    costs+=("$cost")
    alone+=("$solo")
    cmds+=("$(printf '%q ' "$@")")
}
suite() { add_suite 0 "$@"; }
suite_alone() { add_suite 1 "$@"; }

set -f  # the globs in SUITE are matched by `selected`, not expanded against file names
suites=$("$PYTHON" mk/gen_builds.py --suites) || exit 2
eval "$suites"
set +f

[ "$list_only" -eq 1 ] && exit 0
count=${#names[@]}
[ "$count" -gt 0 ] || { echo "no suite matches SUITE='$SUITE' (tests/run_all.sh --list names them)"; exit 2; }

# The order: with one lane the list's; otherwise the suites to run alone first, then the longest
# first (recorded duration, else cost), ties in the list's order.
declare -A recorded=()
if [ -f "$logs/durations" ]; then
    while read -r n s; do
        [[ "$s" =~ ^[0-9]+$ ]] && recorded[$n]=$s
    done <"$logs/durations"
fi
if [ "$TEST_JOBS" -eq 1 ]; then
    order=$(seq 0 $((count - 1)))
else
    order=$(for i in "${!names[@]}"; do
                echo "${alone[$i]} ${recorded[${names[$i]}]:-${costs[$i]}} $i"
            done | sort -k1,1nr -k2,2nr -k3,3n | cut -d' ' -f3)
fi

passed=0
failed=0
declare -A running=()  # pid -> suite index
started=()             # suite index -> $SECONDS at its start
took=()                # suite index -> seconds

# Each suite in its own session (setsid): its processes can be told from the other suites', and
# stopped together if the run is interrupted. `times` after the command: the CPU its processes took.
start_suite() {
    local i=$1 name=${names[$1]}
    started[$i]=$SECONDS
    rm -f "$logs/$name.cpu"
    setsid -w bash -c "${cmds[$i]}"'
rc=$?; times >"$0"; exit $rc' "$logs/$name.cpu" </dev/null >"$logs/$name.log" 2>&1 &
    running[$!]=$i
}

# User + system seconds of a suite, from its .cpu file (the children's line of `times`).
cpu_of() {
    sed -n 2p "$logs/$1.cpu" 2>/dev/null | tr 'ms' '  ' | awk 'NF == 4 { printf "%.1f\n", 60 * $1 + $2 + 60 * $3 + $4 }'
}

# Waits for one running suite to end and prints its line.
finish_one() {
    local pid=0 rc i name
    wait -n -p pid "${!running[@]}"
    rc=$?
    i=${running[$pid]}
    unset "running[$pid]"
    name=${names[$i]}
    took[$i]=$((SECONDS - started[$i]))
    if [ "$rc" -eq 0 ]; then
        passed=$((passed + 1))
        printf 'PASS  %-26s %4ss  %s\n' "$name" "${took[$i]}" "$(tail -n 1 "$logs/$name.log")"
    else
        failed=$((failed + 1))
        printf 'FAIL  %-26s %4ss  (log: %s)\n' "$name" "${took[$i]}" "$logs/$name.log"
        tail -n 15 "$logs/$name.log" | sed 's/^/      | /'
    fi
}

stop_all() {
    local pid
    for pid in "${!running[@]}"; do
        # The suite's session, if setsid made it one (it did unless it had to fork: then only pid).
        if [ "$(ps -o sid= -p "$pid" 2>/dev/null | tr -d ' ')" = "$pid" ]; then
            pkill -TERM -s "$pid" 2>/dev/null
        else
            kill -TERM "$pid" 2>/dev/null
        fi
    done
    echo "interrupted: $passed passed, $failed failed, ${#running[@]} stopped"
    exit 130
}
trap stop_all INT TERM

for i in $order; do
    if [ "${alone[$i]}" -eq 1 ]; then
        while [ ${#running[@]} -gt 0 ]; do finish_one; done
        start_suite "$i"
        finish_one
        continue
    fi
    while [ ${#running[@]} -ge "$TEST_JOBS" ]; do finish_one; done
    start_suite "$i"
done
while [ ${#running[@]} -gt 0 ]; do finish_one; done

# Record the durations for the next run's order (the suites that did not run keep theirs).
for i in "${!names[@]}"; do
    recorded[${names[$i]}]=${took[$i]}
done
for n in "${!recorded[@]}"; do
    echo "$n ${recorded[$n]}"
done | sort >"$logs/durations.tmp" && mv "$logs/durations.tmp" "$logs/durations"

cpu=$(for n in "${names[@]}"; do cpu_of "$n"; done | awk '{ t += $1 } END { printf "%.0f", t }')
echo "suites: ${cpu} s of CPU in $SECONDS s, $TEST_JOBS at a time"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
