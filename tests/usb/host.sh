#!/usr/bin/env bash
# The USB low-speed host (soc_rtl/usb/usb_ls_host.v, usb_ls_xfer.v, usb_hid_keys.v and the line and
# packet layers): lint under -Wall, then tests/usb/host_tb.cpp, the host Verilated at 50 MHz against
# the keyboard model (cosim/usb/usb_kbd_device.cpp) at the pins: enumeration, typed text, each fault
# switch, detach/re-attach, babble. Usage: BUILD=build bash tests/usb/host.sh [-v]
set -euo pipefail
: "${BUILD:=build}" "${VERILATOR_RT:?}"
source "$(dirname "$0")/host_tb_build.sh"
# usb_ls_xfer and usb_hid_keys linted alone too (usb_host_bench lints the top)
for m in usb_ls_xfer usb_hid_keys; do
    verilator --lint-only -Wall --top-module $m soc_rtl/usb/lint.vlt $usb_host_src
done
echo "lint: usb_ls_xfer, usb_hid_keys clean under -Wall"
bench=$(usb_host_bench usb_ls_host host_tb)
"$bench" "$@"
