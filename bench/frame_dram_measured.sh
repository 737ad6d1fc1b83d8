#!/usr/bin/env bash
# make bench-gpu, third table: the frames in external memory (FRAME_DRAM, contract "Frames in
# external memory"). Each scene's benchmark frames (FW_BENCH_FRAMES, default view, depth test on) at
# 640x480 on two GPUs with a strip buffer of 16 rows: the frame on chip (ON_CHIP_GPU) and the frames
# behind LiteDRAM's native port (DRAM_GPU, gpusim's model of the port, cosim/native_port_model.h,
# on the pin path: the strips' flushes and the scan-out's rows both through it). Per scene: the
# GPU's busy cycles a frame on each (the firmware's "gpu cycles"); the bytes the port wrote a frame
# drawn and read a frame shown (counted: the read words over the display scans the run simulated,
# its summary's scan_clocks each, cosim/gpu_sim.h); and what those bytes take
# of the board's port at 60 frames a second, one native word a clock at the system clock (SYS_HZ,
# contract/soc_map.toml's SOC_CLK_HZ_DEFAULT; the word's bytes from the summary's
# frame_memory_word_bytes: 4, the half-rate PHY's 32-bit port): each frame drawn once and shown
# once. The golden model is not consulted (scene-dram checks the frames).
#
# Usage: frame_dram_measured.sh SYS_HZ ON_CHIP_GPU DRAM_GPU BENCH_DIR OUT_DIR SCENE...
set -euo pipefail
sys_hz=${1:?}; on_chip=${2:?}; dram=${3:?}; dir=${4:?}; out=${5:?}; shift 5
source "$(dirname "$0")/frame_lines.sh"  # mean, commas
value() { sed -n "s/^$1=//p" "$2"; }  # value KEY SUMMARY: a key of a gpusim summary
echo
echo "| scene | GPU cycles a frame: frame on chip | frames in SDRAM | SDRAM bytes written a frame drawn | read a frame shown | the port at 60 frames/s, $((sys_hz / 1000000)) MHz | underflows |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for scene in "$@"; do
    elf="$dir/$scene-z.elf"
    for v in on-chip dram; do
        gpu=$on_chip
        [ "$v" = dram ] && gpu=$dram
        "$gpu" cosim --fw "$elf" --frames "$out/frames-$scene-$v" --no-model-check --uart-log "$out/$scene-$v.uart" \
            --summary "$out/$scene-$v.summary" >"$out/$scene-$v.out" 2>&1 || { tail -n 5 "$out/$scene-$v.out" >&2; exit 1; }
    done
    s="$out/$scene-dram.summary"
    frames=$(value frames "$s") written=$(value frame_memory_words_written "$s") read=$(value frame_memory_words_read "$s")
    clocks=$(value gpu_cycles "$s") scan=$(value scan_clocks "$s") bytes=$(value frame_memory_word_bytes "$s")
    [ "${frames:-0}" -gt 0 ] && [ "${clocks:-0}" -gt 0 ] && [ "${scan:-0}" -gt 0 ] && [ "${bytes:-0}" -gt 0 ] ||
        { echo "frame_dram_measured: $scene: no frames, no display scan or no port width in $s" >&2; exit 1; }
    on=$(mean "gpu cycles" "$out/$scene-on-chip.uart") off=$(mean "gpu cycles" "$out/$scene-dram.uart")
    wr=$((bytes * written / frames))
    rd=$(awk -v b="$bytes" -v r="$read" -v c="$clocks" -v d="$scan" 'BEGIN { printf "%.0f", b * r / (c / d) }')
    share=$(awk -v b="$bytes" -v w="$wr" -v r="$rd" -v hz="$sys_hz" 'BEGIN { printf "%.1f %%", 100 * (w + r) / b * 60 / hz }')
    echo "| $scene | $(commas "$on") | $(commas "$off") (+$(((off - on) * 100 / on)) %) | $(commas $wr) | $(commas "$rd") |" \
         "$share | $(value scanout_underflows "$s") |"
done
