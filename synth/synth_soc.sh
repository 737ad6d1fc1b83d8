#!/usr/bin/env bash
# `make synth-soc`: yosys synth_ecp5 of soc_top (VexRiscv_FullCfu + the projection unit + RAM + GPU + UART + SYS), default
# parameters (192 KiB RAM, SPAN_W 8, lines, no depth buffer), no place and route (Debian has no
# nextpnr-ecp5). Prints a Markdown table: LUT4, flip-flops, carry cells, LUT RAM, DP16KD (EBR) per
# memory and in total, MULT18X18D; checks the RAM's EBR count against RAM_BYTES / 2 KiB.
# Usage: [ZBUF=1 [ZBUF_BITS=B]] SOC_CPU_V=path/VexRiscv_FullCfu.v synth_soc.sh BUILD_DIR (ZBUF=1: the GPU
# with its depth buffer, keeping ZBUF_BITS bits, default 16). Logs in BUILD_DIR/synth-soc[-zB]/.
set -euo pipefail
cd "$(dirname "$0")/.."
zbuf=${ZBUF:-0}
zbits=${ZBUF_BITS:-16}
out="${1:-build}/synth-soc$([ "$zbuf" = 1 ] && echo "-z$zbits")"
mkdir -p "$out"
: "${SOC_CPU_V:?SOC_CPU_V must name VexRiscv_FullCfu.v (soc_rtl/soc.mk sets it)}"
# The sources in compilation order, from the lists (`//` starts a comment) and the packaged core.
rtl="$(sed -e 's://.*::' gpu_rtl/files.f | tr '\n' ' ') $SOC_CPU_V $(sed -e 's://.*::' soc_rtl/files.f | tr '\n' ' ')"
ram_bytes=$(sed -n 's/^#define SOC_RAM_DEFAULT_BYTES *\(0x[0-9A-Fa-f]*\)u.*/\1/p' contract/soc_map.h)

echo "synth-soc: yosys synth_ecp5 on soc_top (takes minutes) ..." >&2
start=$SECONDS
yosys -q -l "$out/ecp5.log" 2>"$out/ecp5.warnings" -p "read_verilog -sv $rtl; \
    chparam -set ENABLE_ZBUF $zbuf -set ZBUF_BITS $zbits soc_top; synth_ecp5 -top soc_top; tee -q -o $out/ecp5_stat.txt stat; tee -q -o $out/ebr_cells.txt select -list t:DP16KD" >/dev/null
secs=$((SECONDS - start))

count() { awk -v pat="$1" '$1 ~ pat && $2 ~ /^[0-9]+$/ { n += $2 } END { print n + 0 }' "$out/ecp5_stat.txt"; }
luts=$(count '^LUT4$')
ffs=$(count '^TRELLIS_FF$')
ccu=$(count '^CCU2C$')
dpr=$(count '^TRELLIS_DPR16X4$')
ebr=$(count '^DP16KD$')
mult=$(count '^MULT18X18D$')

# EBR per memory: memory_libmap names each block it makes <memory>.<row>.<column>, so the DP16KD
# cells (the pseudo-dual-port PDPW16KD ones included) grouped by <memory> are each memory's count.
per_mem=$(sed -n 's:^soc_top/::p' "$out/ebr_cells.txt" | sed -E 's/\.[0-9]+\.[0-9]+$//' | sort | uniq -c)
ram_ebr=$(echo "$per_mem" | awk '$2 == "u_ram.mem" { print $1 }')
fb_ebr=$(echo "$per_mem" | awk '$2 ~ /^u_gpu\.u_core\.g_frame_bram\.u_framebuffer\./ { n += $1 } END { print n + 0 }')
ram_want=$((ram_bytes / 2048))

echo "| design | LUT4 | FF | CCU2C | LUT RAM (DPR16X4) | DP16KD (EBR) | MULT18X18D | yosys time |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
echo "| soc_top (ECP5, synth_ecp5; ENABLE_ZBUF=$zbuf, ZBUF_BITS=$zbits) | $luts | $ffs | $ccu | $dpr | $ebr | $mult | ${secs} s |"
echo
echo "| memory | DP16KD |"
echo "|---|---:|"
echo "$per_mem" | awk '{ printf "| %s | %d |\n", $2, $1 }'
echo "| (framebuffers, both banks) | $fb_ebr |"
[ "${ram_ebr:-0}" -eq "$ram_want" ] || { echo "synth-soc: the RAM took ${ram_ebr:-0} EBR, expected $ram_want (RAM_BYTES / 2 KiB)" >&2; exit 1; }
echo
echo "synth-soc: RAM $ram_ebr EBR = $ram_bytes bytes / 2 KiB, as expected" >&2
