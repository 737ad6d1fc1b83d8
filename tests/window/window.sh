#!/usr/bin/env bash
# The window, as a user meets it: on an X display (Xvfb here), outside CI, `make run SCENE=voxel`
# opens a window on the fast display path. The test finds it by its title, types keys into it with
# xdotool (letters and two arrow keys, through the X server's keyboard as a user's would arrive),
# waits until the window has shown more frames, takes a screenshot of it with xwd, types Q, and
# expects the run to end with status 0 and no QEMU left. The screenshot must equal, pixel for
# pixel, the golden model's frame after the same keys (the host build, $BUILD/fw-test/host-voxel:
# the voxel world is still unless keys move the camera, so the frame depends on the keys only).
# Then the SoC simulation's window (socsim --window, frames from the VGA pins), on the SoC with its
# USB keyboard host (socsim-usb-192k, the firmware built with FW_USB_KEYBOARD; --usb-window: the
# window's keys typed on socsim's USB keyboard, not the UART): its first frame's screenshot must
# equal the golden model's; once the keyboard is enumerated, M typed into the window must reach the
# firmware from the USB keyboard (its camera mode changes); then the window is closed as a window
# manager closes it (WM_DELETE_WINDOW, sent with python3-xlib), and the firmware — built to run
# until Q — must quit as on Q (typed on the UART), status 0, within 60 s.
#   usage: window.sh SOCSIM_USB
# Skips, saying so, where Xvfb, xdotool or xwd is missing (tools/packages.txt lists them).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/../soc/soc_lib.sh"
need BUILD PYTHON
for tool in Xvfb xdotool xwd; do
    command -v "$tool" >/dev/null || pass "window: skipped: $tool is not installed (tools/setup.sh installs it)"
done
/usr/bin/python3 -c 'import Xlib' 2>/dev/null || pass "window: skipped: python3-xlib is not installed (tools/setup.sh installs it)"
host="$BUILD/fw-test/host-voxel"
socsim=${1:?usage: window.sh SOCSIM_USB}
need_file "$host" "$BUILD/fw-test/host-tetra" "$socsim" "$soc_test_dir/tetra-usb-window.elf"
work=$(fresh_dir window)

# A display of its own: Xvfb picks a free number and writes it to fd 3. TrueColor, 24 bits.
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$work/display" >"$work/xvfb.log" 2>&1 &
xvfb=$!
run_pid=
cleanup() {  # under set -e: every command here must succeed, or the rest is skipped
    if [ -n "$run_pid" ]; then
        kill -- "-$run_pid" 2>/dev/null || true  # make run and the simulator it started
    fi
    kill "$xvfb" 2>/dev/null || true
    wait 2>/dev/null || true
}
trap cleanup EXIT
for _ in $(seq 100); do
    [ -s "$work/display" ] && break
    sleep 0.1
done
[ -s "$work/display" ] || fail "Xvfb did not start: $(tail -n 3 "$work/xvfb.log")"
export DISPLAY=":$(cat "$work/display")"

# make run as on a desktop: a display, neither CI nor HEADLESS; FRAMES=0 (until Q) is its default.
# In a process group of its own (setsid), which the clean-up stops whole if the test fails.
env -u CI -u HEADLESS -u FRAMES setsid make --no-print-directory run SCENE=voxel FULL=1 BUILD="$BUILD" OUT="$work/out" \
    </dev/null >"$work/run.out" 2>&1 &
run_pid=$!

# The window's title: "gpusim voxel.elf | frame N | F fps | fw instr I | gpu busy C cycles".
title() { xdotool getwindowname "$win" 2>/dev/null || true; }
find_window() {  # find_window TITLE_REGEX WHAT: sets $win, waiting up to 120 s (make may build first)
    local _
    win=
    for _ in $(seq 1200); do
        win=$(xdotool search --name "$1" 2>/dev/null | head -n 1 || true)
        [ -n "$win" ] && return 0
        kill -0 "$run_pid" 2>/dev/null || fail "$2 ended without a window: $(tail -n 5 "$work/run.out")"
        sleep 0.1
    done
    fail "no window titled '$1' within 120 s"
}
frame_no() { title | sed -nE 's/.*\| frame ([0-9]+) \|.*/\1/p'; }
wait_frames() {  # until the window has shown at least $1 frames
    local _ n
    for _ in $(seq 600); do
        n=$(frame_no)
        [ -n "$n" ] && [ "$n" -ge "$1" ] && return 0
        kill -0 "$run_pid" 2>/dev/null || fail "make run ended early: $(tail -n 5 "$work/run.out")"
        sleep 0.1
    done
    fail "the window showed ${n:-no} frames, waiting for $1 (title: $(title))"
}
find_window '^gpusim voxel\.elf' "make run"
wait_frames 3

xdotool windowfocus --sync "$win"
xdotool type --delay 30 wwdd
xdotool key --delay 30 Left Left
typed_at=$(frame_no)
wait_frames $((typed_at + 10))
xwd -id "$win" -silent >"$work/window.xwd" || fail "xwd could not dump the window"
"$PYTHON" tests/window/xwd_to_png.py "$work/window.xwd" "$work/window.png"
shown=$(title)
xdotool type q
status=0
for _ in $(seq 100); do
    kill -0 "$run_pid" 2>/dev/null || break
    sleep 0.1
done
wait "$run_pid" || status=$?
run_pid=
expect_status 0 "make run after Q"
expect_line 'quit at frame' "$work/out/uart.log"
no_qemu_left

# The golden model's frame after the same keys: the arrows as the bytes a terminal sends.
run_to "$work/host.out" 60 "$host" --frames "$work/ref" --keys-at $'1:wwdd\e[D\e[D'
expect_status 0 "the host build"
ref="$work/ref/$(ls "$work/ref" | tail -n 1)"
run_to "$work/diff.out" 10 "$BUILD/tools/png_diff" "$ref" "$work/window.png"
grep -q ' differing 0 ' "$work/diff.out" || fail "the window's picture differs from the golden model's: $(cat "$work/diff.out")"
cmp -s "$ref" "$work/ref/0000.png" && fail "the keys moved nothing: the test would not see them"

# The SoC: tetra until Q, its keys on the USB keyboard.
setsid "$socsim" --fw "$soc_test_dir/tetra-usb-window.elf" --window --usb-window </dev/null >"$work/run.out" 2>&1 &
run_pid=$!
find_window '^socsim tetra-usb-window\.elf' "socsim --window"
wait_frames 1
xwd -id "$win" -silent >"$work/soc.xwd" || fail "xwd could not dump the SoC's window"
"$PYTHON" tests/window/xwd_to_png.py "$work/soc.xwd" "$work/soc.png"
wait_line() {  # wait_line REGEX WHAT: up to 60 s for a line of socsim's output
    local _
    for _ in $(seq 600); do
        grep -qE "$1" "$work/run.out" && return 0
        kill -0 "$run_pid" 2>/dev/null || fail "socsim ended early: $(tail -n 5 "$work/run.out")"
        sleep 0.1
    done
    fail "socsim --usb-window: no $2 within 60 s (log: $work/run.out)"
}
wait_line '^usb: keyboard ready' "keyboard enumerated"
xdotool windowfocus --sync "$win"
xdotool type m
wait_line '^socsim: usb key 0x10 press' "M (usage 0x10) from the USB keyboard"
wait_line '^camera: fly' "answer to M"
/usr/bin/python3 - "$win" <<'EOF' || fail "could not close the window"
import sys
from Xlib import X, display
from Xlib.protocol import event
d = display.Display()
window = d.create_resource_object("window", int(sys.argv[1]))
close = event.ClientMessage(window=window, client_type=d.intern_atom("WM_PROTOCOLS"),
                            data=(32, [d.intern_atom("WM_DELETE_WINDOW"), X.CurrentTime, 0, 0, 0]))
window.send_event(close)
d.flush()
EOF
for _ in $(seq 600); do
    kill -0 "$run_pid" 2>/dev/null || break
    sleep 0.1
done
kill -0 "$run_pid" 2>/dev/null && fail "socsim still runs 60 s after its window was closed"
status=0
wait "$run_pid" || status=$?
run_pid=
expect_status 0 "socsim --window, closed"
expect_line '^quit at frame [0-9]+$' "$work/run.out"  # the Q the closing typed
n=$(count '^socsim: frame [0-9]+ -> \(not written\)' "$work/run.out")
run_to "$work/tetra.out" 60 "$BUILD/fw-test/host-tetra" --frames "$work/tetra"
run_to "$work/diff.out" 10 "$BUILD/tools/png_diff" "$work/tetra/0000.png" "$work/soc.png"
grep -q ' differing 0 ' "$work/diff.out" || fail "the SoC window's first frame differs from the golden model's: $(cat "$work/diff.out")"
pass "window: make run SCENE=voxel opened '$shown'; keys typed into it, its screenshot equals the golden model's frame; Q ended it with status 0; socsim's window too, M typed into it taken from the USB keyboard, closed after $n frames with status 0"
