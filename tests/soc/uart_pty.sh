#!/usr/bin/env bash
# socsim's UART as a pseudo-terminal (socsim --uart-pty): a client on the pty types H at once; the
# byte goes out on uart_rx at the line's baud, the firmware answers with its help (twice in the
# log: at boot and on H), the summary counts the one byte, and the client has received what the
# SoC sent on uart_tx: its transcript, '\r' dropped, equals the UART log byte for byte.
source "$(dirname "$0")/../lib.sh"
need BUILD
source "$(dirname "$0")/soc_lib.sh"
soc_test tetra soc-uart-pty

pty_session 300 "$socsim" --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$work/tty" -- 280 h
expect_status 0 "socsim"
[ "$client" -eq 0 ] || fail "the pty client did not get the help twice (client.out above)"
expect_pty_echo socsim
expect_eq "$(summary uart_pty_in "$work/summary")" 1 "bytes from the pty (summary)"
expect_eq "$(summary uart_framing_errors "$work/summary")" 0 "framing errors"
pass "soc-uart-pty: H typed through tty, the help came back, $(wc -c <"$work/transcript") bytes received"
