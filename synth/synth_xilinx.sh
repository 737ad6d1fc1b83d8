#!/usr/bin/env bash
# yosys synth_xilinx (xc7) of a Digilent Artix-7 board top (boards/<board>/<board>_top.v around
# digilent_top: digilent_clocks and soc_top), firmware-less (RAM_INIT ""), no place and route
# (Vivado's job: boards/<board>/build.tcl). Prints Markdown table rows: LUT (LUT1..LUT6 and INV), FF
# (FDRE/FDSE/FDCE/FDPE), block RAM in RAMB36 equivalents (RAMB36E1 + RAMB18E1 / 2), DSP48E1, LUT RAM
# (cells, and the LUTs they occupy), each against the part's capacity (Xilinx DS180), and a fits
# column per resource; then the block RAM per memory.
# Usage: [RAM_BYTES=n] [VENV=path/.venv] synth/synth_xilinx.sh basys3|nexys_a7 [BUILD_DIR]
#   RAM_BYTES overrides the top's RAM_BYTES (a multiple of 8 KiB); VENV is where
#   pythondata-cpu-vexriscv is installed (default: the repository's .venv); REPORT_ONLY=1 prints
#   the rows again from an earlier run's logs without running yosys.
# Logs in BUILD_DIR/synth-<board>/ (default BUILD_DIR: build), one set per RAM size.
set -euo pipefail
{ # (read whole before it runs: editing the script during a run does not change that run)
cd "$(dirname "$0")/.."
board="${1:?usage: synth_xilinx.sh basys3|nexys_a7 [BUILD_DIR]}"
out="${2:-build}/synth-$board"
case "$board" in
    # DS180 (7 Series overview): LUTs = 4 per slice; LUT RAM only in SLICEM (400 Kb / 1,188 Kb of
    # distributed RAM = 6,400 / 19,008 LUTs of 64 bits); BRAM in 36 Kb blocks.
    basys3)   part="XC7A35T";  cap_lut=20800; cap_ff=41600;  cap_bram=50;  cap_dsp=90;  cap_lutram=6400  ;;
    nexys_a7) part="XC7A100T"; cap_lut=63400; cap_ff=126800; cap_bram=135; cap_dsp=240; cap_lutram=19008 ;;
    *) echo "synth_xilinx: unknown board '$board' (basys3, nexys_a7)" >&2; exit 2 ;;
esac
top="${board}_top"
mkdir -p "$out"
venv="${VENV:-.venv}"
cpu_v="$("$venv/bin/python" -c 'import os, pythondata_cpu_vexriscv as p; print(os.path.join(p.data_location, "VexRiscv_FullCfu.v"))')"
# The sources in compilation order, from the lists (`//` starts a comment) and the packaged core.
lst() { sed -e 's://.*::' "$1" | tr '\n' ' '; }
rtl="$(lst gpu_rtl/files.f) $cpu_v $(lst soc_rtl/files.f) $(lst boards/digilent/files.f) boards/$board/$top.v"

chparam=""
tag="default"
if [ -n "${RAM_BYTES:-}" ]; then
    [ $((RAM_BYTES % 8192)) -eq 0 ] || { echo "synth_xilinx: RAM_BYTES must be a multiple of 8 KiB" >&2; exit 2; }
    chparam="chparam -set RAM_BYTES $RAM_BYTES $top;"
    tag="$((RAM_BYTES / 1024))k"
fi
ram_desc="${RAM_BYTES:+$((RAM_BYTES / 1024)) KiB}"
ram_desc="${ram_desc:-top default}"

if [ -z "${REPORT_ONLY:-}" ]; then
    echo "synth_xilinx: yosys synth_xilinx -family xc7 on $top, RAM $ram_desc (takes minutes) ..." >&2
    start=$SECONDS
    yosys -q -l "$out/xc7-$tag.log" 2>"$out/xc7-$tag.warnings" -p "read_verilog -sv -I. $rtl; $chparam \
        synth_xilinx -family xc7 -top $top; flatten; tee -q -o $out/xc7-${tag}_stat.txt stat; \
        tee -q -o $out/xc7-${tag}_ramb36.txt select -list t:RAMB36E1; \
        tee -q -o $out/xc7-${tag}_ramb18.txt select -list t:RAMB18E1" >/dev/null
    echo $((SECONDS - start)) > "$out/xc7-${tag}_seconds.txt"
fi
secs=$(cat "$out/xc7-${tag}_seconds.txt" 2>/dev/null || echo "?")

# The counts of the whole design: stat's one module (flattened after synthesis, for the instance
# paths below), or an unflattened stat's "design hierarchy" totals.
stat_total() { awk '{ l[n++] = $0 } /=== design hierarchy ===/ { s = n } END { for (i = s; i < n; i++) print l[i] }' "$out/xc7-${tag}_stat.txt"; }
# The RAM size synthesised, from the log's name of the soc_ram it elaborated (RAM_BYTES in binary).
ram_bin=$(grep -o "soc_ram.RAM_BYTES=s32'[01]*" "$out/xc7-$tag.log" | tail -n 1 | sed "s/.*'//")   # the last: the one used
[ -n "${RAM_BYTES:-}" ] || [ -z "$ram_bin" ] || ram_desc="$(( 2#$ram_bin / 1024 )) KiB$([ -n "${RAM_BYTES:-}" ] || echo ", the top's default")"
count() { stat_total | awk -v pat="$1" '$1 ~ pat && $2 ~ /^[0-9]+$/ { n += $2 } END { print n + 0 }'; }
luts=$(count '^(LUT[1-6]|INV)$')             # yosys' INV cells become LUT1s in Vivado
ffs=$(count '^FD[RSCP]E$')
b36=$(count '^RAMB36E1$')
b18=$(count '^RAMB18E1$')
dsp=$(count '^DSP48E1$')
# LUT RAM: the cells, and the LUTs (of SLICEM) each occupies.
lutram_cells=$(count '^RAM(32M|64M|32M16|16X1D|32X1D|64X1D|128X1D|256X1D|16X1S|32X1S|64X1S|128X1S|256X1S|512X1S)$')
lutram_luts=$(awk '$2 ~ /^[0-9]+$/ {
        w = 0
        if ($1 == "RAM32M" || $1 == "RAM64M" || $1 == "RAM128X1D" || $1 == "RAM256X1S") w = 4
        else if ($1 == "RAM32M16") w = 8
        else if ($1 == "RAM256X1D" || $1 == "RAM512X1S") w = 8
        else if ($1 == "RAM16X1D" || $1 == "RAM32X1D" || $1 == "RAM64X1D" || $1 == "RAM128X1S") w = 2
        else if ($1 == "RAM16X1S" || $1 == "RAM32X1S" || $1 == "RAM64X1S") w = 1
        n += w * $2 } END { print n + 0 }' <(stat_total))
bram_x2=$((2 * b36 + b18))                     # in RAMB18 halves
bram=$((bram_x2 / 2)); [ $((bram_x2 % 2)) -eq 0 ] || bram="$bram.5"
fits() { [ "$1" -le "$2" ] && echo yes || echo "**no**"; }
lut_all=$((luts + lutram_luts))
f_lut=$(fits "$lut_all" "$cap_lut")
f_ff=$(fits "$ffs" "$cap_ff")
f_bram=$(fits "$bram_x2" $((2 * cap_bram)))
f_dsp=$(fits "$dsp" "$cap_dsp")
f_lutram=$(fits "$lutram_luts" "$cap_lutram")
all=yes; for f in $f_lut $f_ff $f_bram $f_dsp $f_lutram; do [ "$f" = yes ] || all="**no**"; done

echo "| board (part), RAM | LUT | FF | BRAM (RAMB36 eq.) | DSP48E1 | LUT RAM cells (LUTs / SLICEM LUTs) | fits? | yosys time |"
echo "|---|---:|---:|---:|---:|---:|---|---:|"
echo "| $board ($part), RAM $ram_desc | $luts + $lutram_luts LUT RAM = $lut_all / $cap_lut ($f_lut) | $ffs / $cap_ff ($f_ff) | $bram / $cap_bram ($f_bram; $b36 RAMB36E1 + $b18 RAMB18E1) | $dsp / $cap_dsp ($f_dsp) | $lutram_cells ($lutram_luts / $cap_lutram, $f_lutram) | $all | ${secs} s |"
echo
# Block RAM per memory: memory_libmap names each block <memory>.<row>.<column>.
per_mem() { sed -n "s:^$top/::p" "$1" | sed -E 's/\.[0-9]+\.[0-9]+$//' | sort | uniq -c | awk '{ print $2, $1 }'; }
per_mem "$out/xc7-${tag}_ramb36.txt" > "$out/xc7-${tag}_ramb36_per_mem.txt"
per_mem "$out/xc7-${tag}_ramb18.txt" > "$out/xc7-${tag}_ramb18_per_mem.txt"
echo "| memory | RAMB36E1 | RAMB18E1 |"
echo "|---|---:|---:|"
join -a 1 -a 2 -e 0 -o 0,1.2,2.2 "$out/xc7-${tag}_ramb36_per_mem.txt" "$out/xc7-${tag}_ramb18_per_mem.txt" |
    awk '{ printf "| %s | %d | %d |\n", $1, $2, $3 }'
exit
}
