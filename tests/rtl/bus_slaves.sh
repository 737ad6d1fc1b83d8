#!/usr/bin/env bash
# gpu_wb_slave and gpu_axil_slave in front of gpu_top (tests/rtl/bus_slaves_top.v), each under seeded
# random traffic with random stalls, against a register model, the native bus and the protocol rules
# (tests/rtl/bus_slaves_tb.cpp). Usage: BUILD=build bash tests/rtl/bus_slaves.sh [OPS_PER_PROTOCOL [SEED]]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/bus-slaves"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
verilator --cc --exe --build -j 2 --output-split 20000 --assert --x-assign fast --x-initial fast --top-module bus_slaves_top \
    -f gpu_rtl/files.f tests/rtl/bus_slaves_top.v "$PWD/tests/rtl/bus_slaves_tb.cpp" \
    -CFLAGS "-O0 -std=c++17 -I$PWD/contract" -LDFLAGS "$VERILATOR_RT" \
    --MAKEFLAGS "OPT_FAST=-O0 OPT_SLOW=-O0 VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" \
    --Mdir "$dir/obj" -o "$dir/bus_slaves_tb" \
    >"$dir/verilator.log" 2>&1 || { tail -30 "$dir/verilator.log"; exit 1; }
"$dir/bus_slaves_tb" "${1:-20000}" "${2:-1}"
