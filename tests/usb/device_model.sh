#!/usr/bin/env bash
# The USB low-speed keyboard model (cosim/usb/usb_kbd_device.cpp) on its own, no Verilator:
# tests/usb/device_model_test.cpp drives its pins with a host written in the test (its own NRZI, bit
# stuffing and CRCs) — the CRCs against published values, a whole enumeration with the descriptors and
# typed text read back report by report (once stepped coarsely, once at every 50 MHz clock), STALLed HID
# requests, halt, reset, suspend/resume, detach — and, for every check the model makes, a sequence that
# breaks exactly it and must be reported as exactly that; every fault switch is shown at work.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir usb-device-model)

# -O1: the build is most of the suite's time (the cases run in a fraction of a second either way).
run_to "$work/build.log" 300 g++ -std=c++17 -O1 -Wall -Wextra -Werror -Icosim/usb \
    tests/usb/device_model_test.cpp cosim/usb/usb_kbd_device.cpp -o "$work/device_model_test"
expect_status 0 "building the keyboard model's test (log: $work/build.log)"
[ -s "$work/build.log" ] && fail "the build printed warnings or notes (log: $work/build.log)"
run_to "$work/out" 60 "$work/device_model_test" -v
expect_status 0 "the keyboard model's test (log: $work/out)"
last=$(tail -n 1 "$work/out")
[[ "$last" =~ ^device_model:\ ok\ ([0-9]+)\ cases$ ]] || fail "the last line is '$last', not 'device_model: ok N cases' (log: $work/out)"
pass "usb-device-model: the low-speed keyboard model passes ${BASH_REMATCH[1]} cases: CRCs on published values, an enumeration and typed text read back at the pins, each signalling, packet, transfer and timing violation reported as itself, each fault switch at work"
