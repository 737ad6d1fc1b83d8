#!/usr/bin/env bash
# Load a bitstream onto a board with openFPGALoader (Debian's openfpgaloader, which knows the
# ULX3S's FT231X as its JTAG cable): board_load.sh BOARD sram|flash FILE.bit
#   sram   into the FPGA's configuration memory: runs at once, gone at power-off
#   flash  into the board's SPI flash (-f): the FPGA loads it at every power-up
# Without a board on USB, openFPGALoader finds no cable and this says what to check.
set -uo pipefail
board=$1 where=$2 bit=$3
[ -f "$bit" ] || { echo "board_load: no bitstream $bit"; exit 1; }
command -v openFPGALoader >/dev/null || { echo "board_load: openFPGALoader is missing (bash tools/setup.sh)"; exit 1; }
args=(-b "$board")
[ "$where" = flash ] && args+=(-f)
echo "board_load: openFPGALoader ${args[*]} $bit"
if ! openFPGALoader "${args[@]}" "$bit"; then
    echo "board_load: openFPGALoader could not load $bit. Check: the board's US1 port (the FT231X) is"
    echo "  on USB (lsusb shows 0403:6015); this user may open it (a udev rule for 0403:6015, or the"
    echo "  plugdev/dialout group); no other program (make term, a terminal) holds the port."
    exit 1
fi
