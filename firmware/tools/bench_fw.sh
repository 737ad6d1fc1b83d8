#!/usr/bin/env bash
# make bench-fw — the firmware's cost per scene and arithmetic backend, as a Markdown table.
#
# Each scene's benchmark ELF (FW_BENCH_FRAMES frames, default view, no keys) runs in co-simulation
# without the golden-model check (the counts do not depend on it); QEMU runs with -icount, so the
# firmware's per-frame "fw instr" (minstret delta of the frame's CPU work, DONE_SEQ polling and
# printing excluded; see firmware/app/app.c) is exact and reproducible. The table gives the mean
# over the frames. "triangles drawn" is the GPU's PERF_TRIS_DRAWN summed over the frame's batches.
# The 60 fps budget: 100 MHz / 1.3 cycles per instruction / 60 = 1,282,051 instructions per frame.
#
# Usage (from the repository root): GPUSIM=... BENCH_DIR=... firmware/tools/bench_fw.sh SCENE...
set -euo pipefail
: "${GPUSIM:?}" "${BENCH_DIR:?}"
budget=1282051

echo "| scene | backend | triangles submitted | triangles drawn | instructions/frame | instructions/triangle | 60 fps budget used |"
echo "|---|---|---:|---:|---:|---:|---:|"
for scene in "$@"; do
    for backend in fixed float; do
        name="$scene"
        [ "$backend" = float ] && name="$scene-float"
        elf="$BENCH_DIR/$name.elf"
        log="$BENCH_DIR/$name.uart"
        rm -rf "$BENCH_DIR/frames-$name"
        if ! "$GPUSIM" cosim --fw "$elf" --frames "$BENCH_DIR/frames-$name" --no-model-check \
             --uart-log "$log" >"$BENCH_DIR/$name.out" 2>&1; then
            echo "bench-fw: $name failed:" >&2
            tail -n 5 "$BENCH_DIR/$name.out" >&2
            exit 1
        fi
        grep '^frame ' "$log" | awk -v scene="$scene" -v backend="$backend" -v budget="$budget" '
            {
                for (i = 1; i <= NF; i++) {
                    if ($i == "submitted") { sub_ += $(i + 1) }
                    if ($i == "drawn") { drawn += $(i + 1) }
                    if ($i == "instr") { instr += $(i + 1) }
                }
                n++
            }
            END {
                if (n == 0) { exit 1 }
                s = sub_ / n; d = drawn / n; f = instr / n
                printf "| %s | %s | %d | %d | %d | %d | %.0f%% |\n", scene, backend, s, d, f, f / s, 100 * f / budget
            }'
    done
done
echo
echo "Mean of $(grep -c '^frame ' "$BENCH_DIR/$1.uart") frames per row, QEMU -icount instruction counts; budget = 100 MHz / 1.3 CPI / 60 fps = $budget instructions per frame."
