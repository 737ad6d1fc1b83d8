#!/usr/bin/env bash
# The UART as a pseudo-terminal (gpusim cosim --uart-pty): a client on the pty, as a serial-port
# program would be, types H and then Q. The firmware must print its help in answer (twice in the
# log: at boot and on H), quit early at Q with status 0, the summary must count the client's two
# bytes, and the client must have received the firmware's whole output: its transcript, '\r'
# dropped, equals the UART log byte for byte.
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD
need_file "$GPUSIM" "$FW_ELF"
work=$(fresh_dir cosim-uart-pty)
link="$work/tty"

# FW_ELF renders 24 frames (about 35 s here): time enough to type before it ends by itself.
timeout 120 "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$link" >"$work/out" 2>&1 &
sim=$!

# The client (tests/cosim/pty_keys.py): H after the first frame, Q after the help.
client=0
python3 tests/cosim/pty_keys.py "$link" "$work/transcript" >"$work/client.out" 2>&1 || client=$?
status=0
wait "$sim" || status=$?
cat "$work/client.out"
tail -n 3 "$work/out"
expect_status 0 "the co-simulation"
[ "$client" -eq 0 ] || fail "the pty client did not get its answers (client.out above)"
expect_line "^cosim: UART on $link \(/dev/pts/[0-9]+\)$" "$work/out"
[ ! -e "$link" ] || fail "the link $link is still there after the run"
expect_eq "$(count 'H this help' "$work/uart.log")" 2 "help texts in the log (boot and H)"
quit_frame=$(sed -n 's/^quit at frame \([0-9]*\).*/\1/p' "$work/uart.log")
[ -n "$quit_frame" ] && [ "$quit_frame" -lt 23 ] || fail "no early quit in the log (frame '$quit_frame')"
expect_eq "$(summary uart_pty_in "$work/summary")" 2 "bytes from the pty (summary)"
expect_eq "$(summary uart_pty_dropped "$work/summary")" 0 "bytes dropped (summary)"
tr -d '\r' <"$work/transcript" >"$work/transcript.lf"
cmp -s "$work/transcript.lf" "$work/uart.log" || fail "the pty's transcript differs from the UART log"
no_qemu_left
pass "uart-pty: H and Q typed through $(basename "$link"), help and quit at frame $quit_frame came back, $(wc -c <"$work/transcript") bytes received"
