#!/usr/bin/env bash
# Runs every test suite, prints one line per suite (with the log's tail on failure) and ends with
# the summary line "N passed, N failed". Called by `make test` with GPUSIM, FW_ELF, BUILD, PYTHON set.
set -u
cd "$(dirname "$0")/.."
: "${GPUSIM:?}" "${FW_ELF:?}" "${BUILD:?}" "${PYTHON:=python3}"
export GPUSIM FW_ELF BUILD PYTHON
logs="$BUILD/test-logs"
mkdir -p "$logs"
passed=0
failed=0

suite() {
    local name="$1"
    shift
    local start=$SECONDS
    if "$@" >"$logs/$name.log" 2>&1; then
        passed=$((passed + 1))
        printf 'PASS  %-28s %4ss  %s\n' "$name" $((SECONDS - start)) "$(tail -n 1 "$logs/$name.log")"
    else
        failed=$((failed + 1))
        printf 'FAIL  %-28s %4ss  (log: %s)\n' "$name" $((SECONDS - start)) "$logs/$name.log"
        tail -n 15 "$logs/$name.log" | sed 's/^/      | /'
    fi
}

suite contract-generated     "$PYTHON" contract/gen_contract.py --check
suite rtl-lint               verilator --lint-only -Wall --top-module gpu_top -Igpu_rtl gpu_rtl/lint.vlt gpu_rtl/*.v
suite rtl-div-unit           bash tests/rtl/div.sh
suite firmware-unit          "$BUILD/tests/fw_unit"
suite firmware-unit-float    "$BUILD/tests/fw_unit_float"
suite firmware-no-gpu         bash tests/firmware/no_gpu.sh
suite model-unit             "$BUILD/tests/model_unit"
suite rtl-vs-model-seed1     "$GPUSIM" random --seed 1 --batches 40
suite rtl-vs-model-seed2     "$GPUSIM" random --seed 2 --batches 40 --tris 200
suite rtl-vs-model-100k      "$GPUSIM" random --seed 3 --batches 500 --tris 500 --swap-percent 10 --min-prims 100000
suite rtl-vs-model-span1     "$BUILD/sim-w1/gpusim" random --seed 4 --batches 20 --tris 100
suite rtl-vs-model-span4     "$BUILD/sim-w4/gpusim" random --seed 5 --batches 20 --tris 100
suite rtl-vs-model-span16    "$BUILD/sim-w16/gpusim" random --seed 6 --batches 20 --tris 100
suite rtl-vs-model-zbuf      "$BUILD/sim-z-w8/gpusim" random --seed 7 --batches 40 --tris 300
suite rtl-mesh-exact-once    bash tests/raster/mesh.sh
suite raster-bad-input       bash tests/raster/bad_input.sh
suite fuzz-prim-list         bash tests/fuzz/run_fuzz.sh short prim_list
suite fuzz-input             bash tests/fuzz/run_fuzz.sh short input
suite fuzz-gpu-model         bash tests/fuzz/run_fuzz.sh short gpu_model
suite fuzz-gpu-driver        bash tests/fuzz/run_fuzz.sh short gpu_driver
suite cosim-end-to-end       bash tests/cosim/end_to_end.sh
suite cosim-kill-qemu        bash tests/cosim/kill.sh qemu
suite cosim-kill-harness     bash tests/cosim/kill.sh harness
suite cosim-stop-signal      bash tests/cosim/kill.sh sigterm
suite cosim-gpu-timeout      bash tests/cosim/gpu_timeout.sh
suite fw-scenes-host-vs-cosim bash tests/scenes/host_vs_cosim.sh
suite fw-watchdog            bash tests/scenes/watchdog.sh
suite fw-keys-burst          bash tests/scenes/keys_burst.sh
suite fw-host-features       bash tests/scenes/host_features.sh
suite fw-lean-build          bash tests/scenes/lean_build.sh
suite bench-error-machinery  bash tests/bench/error_machinery.sh

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
