#!/usr/bin/env bash
# gpu_div against exact division (tests/rtl/div_tb.cpp), built with 1, 2 (the default) and 3 quotient
# bits per clock: boundaries of saturation and of the operand ranges, random operands, latency.
set -euo pipefail
: "${BUILD:?}" "${VERILATOR_RT:?}"
for q in 1 2 3; do
    dir="$BUILD/tests/div-q$q"
    mkdir -p "$dir"
    verilator --cc --exe --build -j 2 -O3 --assert -GQBITS=$q --top-module gpu_div -Igpu_rtl gpu_rtl/gpu_div.v \
        "$PWD/tests/rtl/div_tb.cpp" -CFLAGS "-O2 -std=c++17" \
        -LDFLAGS "$VERILATOR_RT" --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" -o "$PWD/$dir/div_tb" \
        >"$dir/verilator.log" 2>&1 || { tail -20 "$dir/verilator.log"; exit 1; }
    echo "QBITS=$q: $("$dir/div_tb" 100000)"
done
