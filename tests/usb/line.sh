#!/usr/bin/env bash
# The USB low-speed host's line layer (soc_rtl/usb/usb_ls_tx.v, usb_ls_rx.v) and packet layer
# (usb_ls_packet_tx.v, usb_ls_packet_rx.v): lint under -Wall, the module's refusal of a system clock
# outside the low-speed jitter (usb_pkg::ls_sys_hz_ok), and the Verilated testbenches
# (tests/usb/line_tb.cpp: wire against a reference encoder, loopback, receiver at +-1.5 %, errors,
# timeout). Usage: BUILD=build bash tests/usb/line.sh [SEED]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/usb-line"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
pkg="soc_rtl/soc_pkg.sv soc_rtl/usb/usb_pkg.sv"
for m in usb_ls_tx usb_ls_rx usb_ls_packet_tx usb_ls_packet_rx; do
    verilator --lint-only -Wall --top-module $m soc_rtl/usb/lint.vlt $pkg soc_rtl/usb/$m.v
done
# 40 MHz: bit edges 2/3 of a clock (16.7 ns) apart from their ideal places, over TDDJ2's 14 ns.
for m in usb_ls_tx usb_ls_rx; do
    if verilator --lint-only -Wall -GSYS_HZ=40000000 --top-module $m soc_rtl/usb/lint.vlt $pkg \
        soc_rtl/usb/$m.v >"$dir/refuse.log" 2>&1; then
        echo "line.sh: $m accepted SYS_HZ 40 MHz"; exit 1
    fi
done
echo "lint: usb_ls_tx, usb_ls_rx, usb_ls_packet_tx, usb_ls_packet_rx clean under -Wall; SYS_HZ 40 MHz refused by usb_ls_tx and usb_ls_rx"
build() {   # build TOP TB SYS_HZ: Verilate tests/usb/TOP.v with the host's modules and tests/usb/TB.cpp
    verilator --cc --exe --build -j 1 --assert --x-assign fast --x-initial fast --top-module "$1" -GSYS_HZ="$3" \
        $pkg soc_rtl/usb/usb_ls_tx.v soc_rtl/usb/usb_ls_rx.v soc_rtl/usb/usb_ls_packet_tx.v \
        soc_rtl/usb/usb_ls_packet_rx.v "tests/usb/$1.v" "$PWD/tests/usb/$2.cpp" -CFLAGS "-O2 -std=c++17 -DTB_SYS_HZ=$3" \
        -LDFLAGS "$VERILATOR_RT" --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" \
        --Mdir "$dir/obj-$2-$3" -o "$dir/$2-$3" \
        >"$dir/verilator-$2-$3.log" 2>&1 || { tail -30 "$dir/verilator-$2-$3.log"; exit 1; }
}
# The SoC's clock (50 MHz: 33 1/3 clocks a bit, the fractional step's three phases), and 48 MHz
# (exactly 32 clocks a bit) for the line layer.
build usb_line_top line_tb 50000000
build usb_line_top line_tb 48000000
build usb_packet_top packet_tb 50000000
"$dir/line_tb-50000000" "${1:-1}"
"$dir/line_tb-48000000" "${1:-1}"
"$dir/packet_tb-50000000" "${1:-1}"
