#!/usr/bin/env bash
# The USB host's register block (soc_rtl/usb/soc_usb.v): lint under -Wall, then tests/usb/regs_tb.cpp,
# soc_usb Verilated at 50 MHz with the keyboard model (cosim/usb/usb_kbd_device.cpp) at its pins and
# a Wishbone master in C++: CTRL ENABLE, STATUS polled until running, typed text read back as KEY
# events (one pop per read, 0 when empty), the counters, err for unnamed offsets, ENABLE cleared.
# Usage: BUILD=build bash tests/usb/regs.sh [-v]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/usb-regs"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
src="soc_rtl/soc_pkg.sv soc_rtl/usb/usb_pkg.sv soc_rtl/usb/usb_ls_tx.v soc_rtl/usb/usb_ls_rx.v
     soc_rtl/usb/usb_ls_packet_tx.v soc_rtl/usb/usb_ls_packet_rx.v soc_rtl/usb/usb_ls_xfer.v
     soc_rtl/usb/usb_hid_keys.v soc_rtl/usb/usb_ls_host.v soc_rtl/usb/soc_usb.v"
verilator --lint-only -Wall --top-module soc_usb soc_rtl/usb/lint.vlt $src
echo "lint: soc_usb clean under -Wall"
verilator --cc --exe --build -j 1 --assert --x-assign fast --x-initial fast --top-module soc_usb \
    -GSYS_HZ=50000000 $src "$PWD/tests/usb/regs_tb.cpp" "$PWD/cosim/usb/usb_kbd_device.cpp" \
    -CFLAGS "-O2 -std=c++17 -I$PWD/cosim/usb -I$PWD/contract" -LDFLAGS "$VERILATOR_RT" \
    --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" -o "$dir/regs_tb" \
    >"$dir/verilator.log" 2>&1 || { tail -30 "$dir/verilator.log"; exit 1; }
"$dir/regs_tb" "$@"
