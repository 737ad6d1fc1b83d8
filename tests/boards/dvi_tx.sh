#!/usr/bin/env bash
# dvi_tx (boards/common/dvi_tx.v, tmds_encoder.v) against the C++ TMDS decoder (cosim/soc/tmds_decoder.*):
# six phase offsets between clk_pix and clk_tmds (1:5), a seeded random pixel stream with the DC-balance
# worst cases, decoded back exactly at a constant latency with every link check passing.
set -euo pipefail
: "${BUILD:?}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/dvi_tx"
mkdir -p "$dir"
verilator --cc --exe --build -j 2 -O3 --assert -Wall --top-module dvi_tx \
    boards/common/dvi_tx.v boards/common/tmds_encoder.v \
    "$PWD/tests/boards/dvi_tx_tb.cpp" "$PWD/cosim/soc/tmds_decoder.cpp" \
    -CFLAGS "-O2 -std=c++17 -I$PWD/cosim/soc" -LDFLAGS "$VERILATOR_RT" \
    --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" -o "$PWD/$dir/dvi_tx_tb" \
    >"$dir/verilator.log" 2>&1 || { tail -20 "$dir/verilator.log"; exit 1; }
"$dir/dvi_tx_tb" "${DVI_TX_SEED:-1}" 100000
