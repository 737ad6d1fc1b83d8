#!/usr/bin/env bash
# `make synth`: yosys on the GPU.
#  1. 7-series (synth_xilinx) of gpu_top in its default configuration: LUT, FF, BRAM36, DSP counts.
#  2. iCE40 HX8K place-and-route (nextpnr-ice40) of the span walker (synth/ice40_walker_core.v,
#     SPAN_W=4): utilisation and fmax. (The whole rasterizer needs ~12k LUT4 on an iCE40 for its
#     set-up multipliers, measured, and does not fit the 7680 of the largest part.)
# Usage: [ZBUF=1] [GOURAUD=1] synth.sh BUILD_DIR (ZBUF=1: gpu_top with ENABLE_ZBUF in step 1;
# GOURAUD=1: with ENABLE_GOURAUD, the intensity interpolator). Prints a Markdown table; logs in
# BUILD_DIR/synth/.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build}/synth"
mkdir -p "$out"
# The RTL in compilation order, from the one list (gpu_rtl/files.f; `//` starts a comment).
rtl=$(sed -e 's://.*::' gpu_rtl/files.f | tr '\n' ' ')
zbuf="${ZBUF:-0}"
[ "$zbuf" = 1 ] && zlabel="depth buffer" || zlabel="no z"
gouraud="${GOURAUD:-0}"
[ "$gouraud" = 1 ] && zlabel="$zlabel, Gouraud"

echo "synth: yosys synth_xilinx (xc7) on gpu_top, ENABLE_ZBUF=$zbuf ENABLE_GOURAUD=$gouraud ..." >&2
yosys -q -l "$out/xc7.log" 2>"$out/xc7.warnings" -p "read_verilog -sv $rtl; \
    chparam -set ENABLE_ZBUF $zbuf -set ENABLE_GOURAUD $gouraud gpu_top; synth_xilinx -family xc7 -top gpu_top -flatten; tee -q -o $out/xc7_stat.txt stat" >/dev/null

count() { awk -v pat="$1" '$1 ~ pat && $2 ~ /^[0-9]+$/ { n += $2 } END { print n + 0 }' "$out/xc7_stat.txt"; }
luts=$(count '^LUT[1-6]$')
lutram=$(count '^RAM(32|64|128|256)')
ffs=$(count '^FD[RSCP]E$')
bram36=$(count '^RAMB36E1$')
bram18=$(count '^RAMB18E1$')
dsps=$(count '^DSP48E1$')
carry=$(count '^CARRY4$')

echo "synth: yosys synth_ice40 + nextpnr-ice40 (hx8k) on the span walker ..." >&2
yosys -q -l "$out/ice40.log" 2>"$out/ice40.warnings" -p "read_verilog -sv $rtl synth/ice40_walker_core.v; \
    synth_ice40 -top ice40_walker_core -json $out/ice40.json" >/dev/null
nextpnr-ice40 --hx8k --package ct256 --json "$out/ice40.json" --freq 50 --seed 1 \
    --timing-allow-fail --report "$out/ice40_report.json" >"$out/nextpnr.log" 2>&1 || { tail -20 "$out/nextpnr.log"; exit 1; }
fmax=$(grep -o "Max frequency for clock[^:]*: [0-9.]* MHz" "$out/nextpnr.log" | tail -1 | grep -o "[0-9.]* MHz")
lcs=$(grep -o "ICESTORM_LC: *[0-9]*/ *[0-9]*" "$out/nextpnr.log" | tail -1 | tr -s ' ')
ebr=$(grep -o "ICESTORM_RAM: *[0-9]*/ *[0-9]*" "$out/nextpnr.log" | tail -1 | tr -s ' ')

echo "| target | design | LUT | FF | BRAM36 (+BRAM18) | LUTRAM | DSP | CARRY4 | fmax |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
echo "| xc7 (synth_xilinx) | gpu_top, SPAN_W=8, lines, $zlabel | $luts | $ffs | $bram36 (+$bram18) | $lutram | $dsps | $carry | (not placed) |"
echo "| iCE40 HX8K (nextpnr) | span walker, SPAN_W=4 | ${lcs#ICESTORM_LC: } LC | | ${ebr#ICESTORM_RAM: } EBR | | | | $fmax |"
