#!/usr/bin/env bash
# socsim's UART as a pseudo-terminal (socsim --uart-pty): a client on the pty types H at once; the
# byte goes out on uart_rx at the line's baud, the firmware answers with its help (twice in the
# log: at boot and on H), the summary counts the one byte, and the client has received what the
# SoC sent on uart_tx: its transcript, '\r' dropped, equals the UART log byte for byte.
source "$(dirname "$0")/../lib.sh"
need BUILD
source "$(dirname "$0")/soc_lib.sh"
elf="$soc_test_dir/tetra.elf"
need_file "$socsim" "$elf.hex"
work=$(fresh_dir soc-uart-pty)
link="$work/tty"

timeout 300 "$socsim" --fw "$elf" --frames "$work/frames" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$link" >"$work/out" 2>&1 &
sim=$!
client=0
python3 tests/cosim/pty_keys.py "$link" "$work/transcript" 280 h >"$work/client.out" 2>&1 || client=$?
status=0
wait "$sim" || status=$?
cat "$work/client.out"
tail -n 3 "$work/out"
expect_status 0 "socsim"
[ "$client" -eq 0 ] || fail "the pty client did not get the help twice (client.out above)"
expect_line "^socsim: UART on $link \(/dev/pts/[0-9]+\)$" "$work/out"
[ ! -e "$link" ] || fail "the link $link is still there after the run"
expect_eq "$(count 'H this help' "$work/uart.log")" 2 "help texts in the log (boot and H)"
expect_eq "$(summary uart_pty_in "$work/summary")" 1 "bytes from the pty (summary)"
expect_eq "$(summary uart_pty_dropped "$work/summary")" 0 "bytes dropped (summary)"
expect_eq "$(summary uart_framing_errors "$work/summary")" 0 "framing errors"
tr -d '\r' <"$work/transcript" >"$work/transcript.lf"
cmp -s "$work/transcript.lf" "$work/uart.log" || fail "the pty's transcript differs from the UART log"
pass "soc-uart-pty: H typed through $(basename "$link"), the help came back, $(wc -c <"$work/transcript") bytes received"
