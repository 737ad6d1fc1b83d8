#!/usr/bin/env bash
# The USB low-speed host (soc_rtl/usb/usb_ls_host.v, usb_ls_xfer.v, usb_hid_keys.v and the line and
# packet layers): lint under -Wall, then tests/usb/host_tb.cpp, the host Verilated at 50 MHz against
# the keyboard model (cosim/usb/usb_kbd_device.cpp) at the pins: enumeration, typed text, each fault
# switch, detach/re-attach, babble. Usage: BUILD=build bash tests/usb/host.sh [-v]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/usb-host"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"
src="soc_rtl/soc_pkg.sv soc_rtl/usb/usb_pkg.sv soc_rtl/usb/usb_ls_tx.v soc_rtl/usb/usb_ls_rx.v
     soc_rtl/usb/usb_ls_packet_tx.v soc_rtl/usb/usb_ls_packet_rx.v soc_rtl/usb/usb_ls_xfer.v
     soc_rtl/usb/usb_hid_keys.v soc_rtl/usb/usb_ls_host.v"
for m in usb_ls_xfer usb_hid_keys usb_ls_host; do
    verilator --lint-only -Wall --top-module $m soc_rtl/usb/lint.vlt $src
done
echo "lint: usb_ls_xfer, usb_hid_keys, usb_ls_host clean under -Wall"
verilator --cc --exe --build -j 1 --assert --x-assign fast --x-initial fast --top-module usb_ls_host \
    -GSYS_HZ=50000000 $src "$PWD/tests/usb/host_tb.cpp" "$PWD/cosim/usb/usb_kbd_device.cpp" \
    -CFLAGS "-O2 -std=c++17 -I$PWD/cosim/usb" -LDFLAGS "$VERILATOR_RT" \
    --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" -o "$dir/host_tb" \
    >"$dir/verilator.log" 2>&1 || { tail -30 "$dir/verilator.log"; exit 1; }
"$dir/host_tb" "$@"
