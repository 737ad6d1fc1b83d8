#!/usr/bin/env bash
# make bench-strips, second table: the firmware's binning measured (issue #26's "F"). Each scene's
# benchmark frames (FW_BENCH_FRAMES, default view, depth test on) at 640x480 in co-simulation, the
# frame sent whole against the frame in strips of 16 lines (FW_STRIP_ROWS=16: render/strips.h):
# the firmware's instructions a frame (QEMU -icount, exact) and the GPU's busy cycles a frame (its
# batches' PERF_BUSY_CYCLES), and the batches; then on STRIP_GPU, the same GPU with a strip buffer
# of 16 rows and buffers as large as their windows (STRIP_ROWS: the firmware sends that GPU its
# strips, every one, and the GPU draws each on chip and flushes it to the frame), the program built
# with the firmware's binning of every pass (FW_STRIP_WALK=0) and the default program, whose pass,
# one batch there, the GPU walks over every strip (CTRL.WALK). The golden model is not consulted
# (scene-strips checks the frames are the same).
#
# Usage: strips_measured.sh GPUSIM STRIP_GPU BENCH_DIR OUT_DIR SCENE...
set -euo pipefail
sim=${1:?}; strip_sim=${2:?}; dir=${3:?}; out=${4:?}; shift 4
source "$(dirname "$0")/frame_lines.sh"  # mean, commas
echo
echo "| scene | whole: fw instr | GPU cycles | batches | strips of 16: fw instr | GPU cycles | batches | binning, instructions | strip buffer of 16, the firmware's binning: fw instr | GPU cycles | batches | the GPU's walk: fw instr | GPU cycles | batches |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for scene in "$@"; do
    row="| $scene"
    whole_instr=0
    for v in z strips16-z bin-z walk; do
        log="$out/$scene-$v.uart"
        gpu=$sim elf="$dir/$scene-$v.elf"
        [ "$v" = bin-z ] && gpu=$strip_sim
        [ "$v" = walk ] && gpu=$strip_sim elf="$dir/$scene-z.elf"
        "$gpu" cosim --fw "$elf" --frames "$out/frames-$scene-$v" --no-model-check \
            --uart-log "$log" >"$out/$scene-$v.out" 2>&1 || { tail -n 5 "$out/$scene-$v.out" >&2; exit 1; }
        instr=$(mean "fw instr" "$log")
        [ "$v" = z ] && whole_instr=$instr
        [ "$v" = strips16-z ] && binning=$((instr - whole_instr))
        row="$row | $(commas "$instr") | $(commas "$(mean "gpu cycles" "$log")") | $(mean batches "$log")"
        [ "$v" = strips16-z ] && row="$row | +$(commas $binning)"
    done
    echo "$row |"
done
