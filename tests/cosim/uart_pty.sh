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

# FW_ELF renders 24 frames (about 35 s here): time enough to type before it ends by itself. The
# client (tests/cosim/pty_keys.py, its defaults): H after the first frame, Q after the help.
pty_session 120 "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$work/tty" --
expect_status 0 "the co-simulation"
[ "$client" -eq 0 ] || fail "the pty client did not get its answers (client.out above)"
expect_pty_echo cosim
quit_frame=$(sed -n 's/^quit at frame \([0-9]*\).*/\1/p' "$work/uart.log")
[ -n "$quit_frame" ] && [ "$quit_frame" -lt 23 ] || fail "no early quit in the log (frame '$quit_frame')"
expect_eq "$(summary uart_pty_in "$work/summary")" 2 "bytes from the pty (summary)"
no_qemu_left
pass "uart-pty: H and Q typed through tty, help and quit at frame $quit_frame came back, $(wc -c <"$work/transcript") bytes received"
