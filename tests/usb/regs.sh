#!/usr/bin/env bash
# The USB host's register block (soc_rtl/usb/soc_usb.v): lint under -Wall, then tests/usb/regs_tb.cpp,
# soc_usb Verilated at 50 MHz with the keyboard model (cosim/usb/usb_kbd_device.cpp) at its pins and
# a Wishbone master in C++: CTRL ENABLE, STATUS polled until running, typed text read back as KEY
# events (one pop per read, 0 when empty), the counters, err for unnamed offsets, ENABLE cleared.
# Usage: BUILD=build bash tests/usb/regs.sh [-v]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
source "$(dirname "$0")/host_tb_build.sh"
bench=$(usb_host_bench soc_usb regs_tb)
"$bench" "$@"
