#!/usr/bin/env bash
# The test suites, one line each, and the runner. `make test` calls it with GPUSIM, FW_ELF, BUILD,
# PYTHON set (and SUITE when given); it prints one line per suite (the log's tail on failure) and
# ends with "N passed, N failed".
#
#   tests/run_all.sh               every suite
#   SUITE='rtl-* fw-unit' ...      only the suites whose names match one of the globs
#   tests/run_all.sh --list        the names, one per line (with SUITE: the selected ones)
#
# A suite's name starts with its group: contract, rtl (RTL units and RTL against the model), model
# (the golden model), fw (firmware units and boot), raster (the GPU without firmware), fuzz, cosim
# (the harness), scene (whole system, firmware + GPU), bench (benchmark machinery).
set -u
cd "$(dirname "$0")/.."
: "${GPUSIM:?}" "${FW_ELF:?}" "${BUILD:?}" "${PYTHON:=python3}" "${SUITE:=*}"
export GPUSIM FW_ELF BUILD PYTHON
list_only=0
[ "${1:-}" = "--list" ] && list_only=1
logs="$BUILD/test-logs"
mkdir -p "$logs"
passed=0
failed=0
selected=0

selected() {
    local glob
    for glob in $SUITE; do
        # shellcheck disable=SC2053 # the glob is meant to match
        [[ "$1" == $glob ]] && return 0
    done
    return 1
}

suite() {
    local name="$1"
    shift
    selected "$name" || return 0
    selected=$((selected + 1))
    if [ "$list_only" -eq 1 ]; then
        echo "$name"
        return 0
    fi
    local start=$SECONDS
    if "$@" >"$logs/$name.log" 2>&1; then
        passed=$((passed + 1))
        printf 'PASS  %-26s %4ss  %s\n' "$name" $((SECONDS - start)) "$(tail -n 1 "$logs/$name.log")"
    else
        failed=$((failed + 1))
        printf 'FAIL  %-26s %4ss  (log: %s)\n' "$name" $((SECONDS - start)) "$logs/$name.log"
        tail -n 15 "$logs/$name.log" | sed 's/^/      | /'
    fi
}

set -f  # the globs in SUITE are matched by `selected`, not expanded against file names
suite contract-generated     "$PYTHON" contract/gen_contract.py --check
suite rtl-lint               make --no-print-directory lint
suite rtl-div-unit           bash tests/rtl/div.sh
suite fw-unit                "$BUILD/tests/fw_unit"
suite fw-unit-float          "$BUILD/tests/fw_unit_float"
suite fw-no-gpu              bash tests/firmware/no_gpu.sh
suite model-unit             "$BUILD/tests/model_unit"
suite rtl-vs-model-seed1     "$GPUSIM" random --seed 1 --batches 40
suite rtl-vs-model-seed2     "$GPUSIM" random --seed 2 --batches 40 --tris 200
suite rtl-vs-model-100k      "$GPUSIM" random --seed 3 --batches 500 --tris 500 --swap-percent 10 --min-prims 100000
suite rtl-vs-model-span1     "$BUILD/sim-w1/gpusim" random --seed 4 --batches 20 --tris 100
suite rtl-vs-model-span4     "$BUILD/sim-w4/gpusim" random --seed 5 --batches 20 --tris 100
suite rtl-vs-model-span16    "$BUILD/sim-w16/gpusim" random --seed 6 --batches 20 --tris 100
suite rtl-vs-model-zbuf      "$BUILD/sim-z-w8/gpusim" random --seed 7 --batches 40 --tris 300
suite raster-mesh-exact-once bash tests/raster/mesh.sh
suite raster-bad-input       bash tests/raster/bad_input.sh
suite raster-list-roundtrip  bash tests/raster/roundtrip.sh
suite fuzz-prim-list         bash tests/fuzz/run_fuzz.sh short prim_list
suite fuzz-input             bash tests/fuzz/run_fuzz.sh short input
suite fuzz-gpu-model         bash tests/fuzz/run_fuzz.sh short gpu_model
suite fuzz-gpu-driver        bash tests/fuzz/run_fuzz.sh short gpu_driver
suite cosim-end-to-end       bash tests/cosim/end_to_end.sh
suite cosim-kill-qemu        bash tests/cosim/kill.sh qemu
suite cosim-kill-harness     bash tests/cosim/kill.sh harness
suite cosim-stop-signal      bash tests/cosim/kill.sh sigterm
suite cosim-gpu-timeout      bash tests/cosim/gpu_timeout.sh
suite scene-host-vs-cosim    bash tests/scenes/host_vs_cosim.sh
suite scene-watchdog         bash tests/scenes/watchdog.sh
suite scene-keys-burst       bash tests/scenes/keys_burst.sh
suite scene-host-features    bash tests/scenes/host_features.sh
suite scene-lean-build       bash tests/scenes/lean_build.sh
suite bench-error-machinery  bash tests/bench/error_machinery.sh
set +f

[ "$list_only" -eq 1 ] && exit 0
[ "$selected" -gt 0 ] || { echo "no suite matches SUITE='$SUITE' (tests/run_all.sh --list names them)"; exit 2; }
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
