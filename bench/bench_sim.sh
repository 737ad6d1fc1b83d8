#!/usr/bin/env bash
# make bench-sim: how fast the co-simulation runs, per scene and display path, as a Markdown table.
#   pins  gpusim (gpu_top): every frame a VGA scan, captured from the pins — make test's path
#   fast  gpusim on the fast display path (gpu_core, the harness as display) — the window's path
# Both run the same firmware (FRAMES=0 builds, SIM_BENCH_DIR) with the golden-model check on, as
# the window runs, and write no PNG files; --stop-after-frames ends each run. From the run's
# summary: simulated GPU clocks per wall second and frames per wall second, both between the first
# and the last frame (start-up left out), and the fast path's frames/s as a multiple of the pins'
# measured in this same run. Wall time on a shared machine varies: the ratio is the robust figure.
#   bench_sim.sh PINS_SIM FAST_SIM ELF_DIR SCENE...
set -euo pipefail
pins_sim=$1 fast_sim=$2 dir=$3
shift 3
: "${PINS_FRAMES:=5}" "${FAST_FRAMES:=120}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

field() { sed -n "s/^$1=//p" "$2"; }

# run SIM ELF FRAMES SUMMARY: prints "frames cycles_per_s fps"
run() {
    "$1" cosim --fw "$2" --frames '' --stop-after-frames "$3" --summary "$4" >"$4.out" 2>&1 </dev/null ||
        { tail -n 5 "$4.out" >&2; echo "bench-sim: $1 on $2 failed" >&2; exit 1; }
    awk -v n="$(field frames "$4")" -v t0="$(field frame_wall_first_s "$4")" -v t1="$(field frame_wall_last_s "$4")" \
        -v c0="$(field frame_cycles_first "$4")" -v c1="$(field frame_cycles_last "$4")" \
        'BEGIN { dt = t1 - t0; printf "%d %.0f %.2f\n", n, (c1 - c0) / dt, (n - 1) / dt }'
}

echo "| scene | path | frames | simulated cycles/s | frames/s | frames/s against pins |"
echo "|---|---|---:|---:|---:|---:|"
for scene in "$@"; do
    echo "bench-sim: $scene ..." >&2
    read -r pn pc pf < <(run "$pins_sim" "$dir/$scene.elf" "$PINS_FRAMES" "$work/$scene-pins")
    read -r fn fc ff < <(run "$fast_sim" "$dir/$scene.elf" "$FAST_FRAMES" "$work/$scene-fast")
    printf '| %s | pins | %d | %s | %.2f | 1 |\n' "$scene" "$pn" "$pc" "$pf"
    printf '| %s | fast | %d | %s | %.1f | %.0f× |\n' "$scene" "$fn" "$fc" "$ff" \
        "$(awk -v a="$ff" -v b="$pf" 'BEGIN { print a / b }')"
done
