#!/usr/bin/env bash
# soc_uart alone with the contract's parameters: its RX FIFO filled to depth exactly (the next byte an
# overrun), read back in order across the wrap of its block RAM, then streamed through under a
# reader with random gaps; every access answered in the next clock (tests/rtl/uart_fifo_tb.cpp).
# The line is the real 8N1 one at SOC_UART_BAUD (cosim/soc/uart_line's sender), ~40 M clocks.
# Usage: BUILD=build bash tests/rtl/uart_fifo.sh [SEED]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/uart-fifo"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
verilator --cc --exe --build -j 2 --assert --x-assign fast --x-initial fast --top-module soc_uart \
    soc_rtl/soc_pkg.sv soc_rtl/soc_uart.v "$PWD/tests/rtl/uart_fifo_tb.cpp" "$PWD/cosim/soc/uart_line.cpp" \
    -CFLAGS "-O2 -std=c++17 -I$PWD/contract -I$PWD/cosim/soc" \
    -LDFLAGS "$VERILATOR_RT" --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" \
    --Mdir "$dir/obj" -o "$dir/uart_fifo_tb" \
    >"$dir/verilator.log" 2>&1 || { tail -30 "$dir/verilator.log"; exit 1; }
"$dir/uart_fifo_tb" "${1:-1}"
