#!/usr/bin/env bash
# A terminal on the board's UART: board_term.sh PORT. picocom at the SoC's 115200 8N1 (contract/
# soc_map.toml uart_baud): each key goes to the firmware as typed (the keys of `make run`), the
# firmware's frame lines come back. Ctrl-A Ctrl-X leaves.
set -uo pipefail
port=$1
baud=$(sed -n 's/^uart_baud *= *\([0-9]*\).*/\1/p' contract/soc_map.toml)
command -v picocom >/dev/null || { echo "term: picocom is missing (bash tools/setup.sh)"; exit 1; }
if [ ! -c "$port" ]; then
    echo "term: no serial port $port. Plug the board's US1 port (its FT231X shows up as /dev/ttyUSB0,"
    echo "  or the next free ttyUSB); name another one with TERM_PORT=/dev/ttyUSBn."
    exit 1
fi
[ -r "$port" ] && [ -w "$port" ] || { echo "term: $port is not readable and writable by $(id -un) (the dialout group)"; exit 1; }
echo "term: picocom -b $baud $port (Ctrl-A Ctrl-X leaves)"
exec picocom -q -b "$baud" "$port"
