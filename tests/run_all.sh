#!/usr/bin/env bash
# The test suites, one line each, and the runner. `make test` calls it with GPUSIM, GPUSIM_FAST (the
# fast display path's simulator), FW_ELF, BUILD, PYTHON set (and SUITE when given); it prints one
# line per suite as each one ends (the log's tail on failure) and ends with "N passed, N failed".
#
#   tests/run_all.sh               every suite
#   SUITE='rtl-* fw-unit' ...      only the suites whose names match one of the globs
#   TEST_JOBS=N ...                N suites at a time (default: the number of cores, `nproc`);
#                                  TEST_JOBS=1: one after another, in the list's order
#   tests/run_all.sh --list        the names, one per line (with SUITE: the selected ones)
#
# A suite's line:   suite NAME [COST] COMMAND...
#   NAME     starts with its group: contract, rtl (RTL units and RTL against the model), model (the
#            golden model), fw (firmware units and boot), raster (the GPU without firmware), fuzz,
#            cosim (the harness), scene (whole system, firmware + GPU), soc (the whole SoC in RTL:
#            firmware on VexRiscv + GPU, socsim), boards (a board's build: its video PHY, pins,
#            tools), upload (models over the UART: the receiver, the host tool, into a running
#            system), tools (host tools: the model converter), bench (benchmark machinery), docs
#            (what the documentation shows: README.md's commands, run).
#   COST     the suite's CPU seconds on the reference machine (2 cores; what its NAME.cpu file
#            below says, rounded); without it, 30. The costliest start first, so that the lanes end
#            together; the duration recorded by the last run ($BUILD/test-logs/durations) takes its
#            place when there is one.
#   COMMAND  runs from the repository root, stdin /dev/null, stdout and stderr to
#            $BUILD/test-logs/NAME.log, in a session of its own; status 0 = passed. Its CPU time
#            (user and system seconds) goes to $BUILD/test-logs/NAME.cpu.
# `suite_alone` instead of `suite`: nothing else runs beside this suite (one that needs every core,
# or whose timing another suite would disturb); such suites run first, one at a time.
#
# Suites run side by side, so each keeps to its own files: tests/lib.sh's fresh_dir NAME gives
# $BUILD/tests-run/NAME, and no_qemu_left counts only the QEMUs the calling suite started.
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
suite contract-generated       1 "$PYTHON" contract/gen_contract.py --check
suite rtl-lint                 1 make --no-print-directory lint
suite rtl-div-unit            36 bash tests/rtl/div.sh
suite rtl-bus-slaves           8 bash tests/rtl/bus_slaves.sh
suite rtl-uart-fifo           14 bash tests/rtl/uart_fifo.sh
suite rtl-soc-lint             3 make --no-print-directory lint-soc
suite rtl-soc-smoke           16 make --no-print-directory soc-smoke
suite fw-unit                 60 make --no-print-directory fw-unit
suite fw-no-gpu                1 bash tests/firmware/no_gpu.sh
suite fw-fit                   5 bash tests/firmware/fit.sh
suite fw-stress                5 bash tests/stress/run.sh
suite fw-sin-sizes             2 bash tests/firmware/sin_sizes.sh
suite model-unit               2 "$BUILD/tests/model_unit"
suite rtl-vs-model-seed1      20 "$GPUSIM" random --seed 1 --batches 40 --swap-percent 25
suite rtl-vs-model-seed2      16 "$GPUSIM" random --seed 2 --batches 40 --tris 200 --swap-percent 10
# Every batch's back buffer is compared with the model's; a swapped frame costs a whole VGA scan
# (3.36 M clocks, most of a suite's time) to capture from the pins, so seed 1 swaps after a quarter
# of its batches, the other larger runs after a tenth (gpusim's default is 80 %: the span-1 and
# span-4 runs keep it). The 10^5
# primitives (issue #3) run on the fast display path, which reads the front bank from the RTL's own
# RAM instead of scanning it out (seed 1 and 2 and the scene suites keep the pins): 121 frames there
# cost less than the 12 a pin capture allowed.
suite rtl-vs-model-100k       45 "$GPUSIM_FAST" random --seed 3 --batches 500 --tris 500 --swap-percent 25 --min-prims 100000
suite rtl-vs-model-span1      11 "$BUILD/sim-w1/gpusim" random --seed 4 --batches 20 --tris 100
suite rtl-vs-model-span4      14 "$BUILD/sim-w4/gpusim" random --seed 5 --batches 20 --tris 100
suite rtl-vs-model-span16     18 "$BUILD/sim-w16/gpusim" random --seed 6 --batches 20 --tris 100 --swap-percent 10
suite rtl-vs-model-zbuf       25 "$BUILD/sim-z-w8/gpusim" random --seed 7 --batches 40 --tris 300 --swap-percent 10
suite rtl-vs-model-zbuf8      11 "$BUILD/sim-zb8-w8/gpusim" random --seed 8 --batches 20 --tris 300 --swap-percent 10
suite rtl-vs-model-gouraud     5 "$BUILD/sim-fast-g-w8/gpusim" random --seed 8 --batches 40 --tris 300 --swap-percent 25
suite raster-mesh-exact-once  19 bash tests/raster/mesh.sh
suite raster-bad-input         1 bash tests/raster/bad_input.sh
suite raster-list-roundtrip    1 bash tests/raster/roundtrip.sh
suite fuzz-prim-list           2 bash tests/fuzz/run_fuzz.sh short prim_list
suite fuzz-input               4 bash tests/fuzz/run_fuzz.sh short input
suite fuzz-gpu-model           6 bash tests/fuzz/run_fuzz.sh short gpu_model
suite fuzz-gpu-driver          6 bash tests/fuzz/run_fuzz.sh short gpu_driver
suite fuzz-upload              5 bash tests/fuzz/run_fuzz.sh short upload
suite fuzz-meshfile            2 bash tests/fuzz/run_fuzz.sh short meshfile
suite fuzz-meshconv            7 bash tests/fuzz/run_fuzz.sh short meshconv
suite tools-meshconv           3 bash tests/meshconv/run.sh
suite cosim-end-to-end        20 bash tests/cosim/end_to_end.sh
suite cosim-kill-qemu          3 bash tests/cosim/kill.sh qemu
suite cosim-kill-harness       1 bash tests/cosim/kill.sh harness
suite cosim-stop-signal        4 bash tests/cosim/kill.sh sigterm
suite cosim-gpu-timeout        1 bash tests/cosim/gpu_timeout.sh
suite cosim-debug-gdb          6 bash tests/cosim/debug_gdb.sh
suite cosim-window            15 bash tests/window/window.sh
suite cosim-waves             26 bash tests/cosim/waves.sh
suite upload-cosim            60 bash tests/upload/cosim_upload.sh
suite upload-host-tool-unit    1 bash tests/tools/mesh_upload.sh
suite upload-host-tool         2 bash tests/upload/host_tool.sh
suite cosim-uart-pty          11 bash tests/cosim/uart_pty.sh
suite scene-host-vs-cosim     67 bash tests/scenes/host_vs_cosim.sh
suite scene-watchdog          15 bash tests/scenes/watchdog.sh
suite scene-keys-burst         9 bash tests/scenes/keys_burst.sh
suite scene-host-features     13 bash tests/scenes/host_features.sh
suite scene-anaglyph          10 bash tests/scenes/anaglyph.sh
suite scene-gouraud            4 bash tests/scenes/gouraud.sh
suite scene-lean-build        12 bash tests/scenes/lean_build.sh
suite scene-manifest           3 bash tests/manifest/manifest.sh
suite soc-vs-cosim            55 bash tests/soc/vs_cosim.sh
suite soc-determinism         12 bash tests/soc/determinism.sh
suite soc-watchdog             7 bash tests/soc/watchdog.sh
suite soc-bus-error            1 bash tests/soc/bus_error.sh
suite soc-too-big              1 bash tests/soc/too_big.sh
suite soc-poll-cycles          1 bash tests/soc/poll_cycles.sh
suite soc-uart-pty            10 bash tests/soc/uart_pty.sh
suite soc-upload              20 bash tests/soc/upload.sh
suite boards-dvi-tx            15 bash tests/boards/dvi_tx.sh
suite boards-ulx3s-dvi         30 bash tests/boards/ulx3s_dvi.sh
suite boards-lint               12 make --no-print-directory lint-board
suite boards-ulx3s-tools        1 bash tests/boards/ulx3s_tools.sh
suite bench-error-machinery    1 bash tests/bench/error_machinery.sh
suite bench-exact-ref          3 bash tests/bench/exact_ref.sh
suite docs-readme-run        150 bash tests/docs/readme_commands.sh run
suite docs-readme-other      150 bash tests/docs/readme_commands.sh other
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
