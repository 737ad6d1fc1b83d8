#!/usr/bin/env bash
# `make run PLATFORM=soc USB_KEYS=TEXT` (docs/usb.md): the SoC with its USB keyboard host, socsim's
# keyboard on its pins and the firmware built with FW_USB_KEYBOARD; TEXT typed on that keyboard
# once the host has enumerated it. Here tetra (FULL=1: not its manifest's lean build) on make test's
# USB socsim (SOC_RAM_KIB=192: the table's socsim-usb-192k, not built again) with M typed: the
# firmware must report the keyboard ready and change its camera mode (object -> fly), the key taken
# from the USB keyboard (socsim's tap), and end well after FRAMES frames. The firmware in the
# suite's own folder.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir soc-usb-run)
run_to "$work/make.log" 300 make --no-print-directory run PLATFORM=soc SCENE=tetra FULL=1 SOC_RAM_KIB=192 USB_KEYS=m \
    HEADLESS=1 FRAMES=11 BUILD="$BUILD" OUT="$work/out" SOC_FW_DIR="$work/fw-soc" </dev/null
expect_status 0 "make run PLATFORM=soc USB_KEYS=m ($(tail -n 3 "$work/make.log"))"
expect_line '^  RUN +socsim .*tetra-usb\.elf' "$work/make.log"
expect_line '^socsim: usb key 0x10 press' "$work/make.log"
expect_line '^usb: keyboard ready' "$work/out/uart.log"
expect_line '^camera: fly' "$work/out/uart.log"
expect_eq "$(png_count "$work/out/frames")" 11 "frames written"
pass "soc-usb-run: make run PLATFORM=soc USB_KEYS=m: the keyboard enumerated, M taken from it, the camera changed (object -> fly), 11 frames"
