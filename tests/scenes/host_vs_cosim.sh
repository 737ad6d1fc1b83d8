#!/usr/bin/env bash
# The firmware rendered two ways must give byte-identical frames:
#   co-simulation: the ELF in QEMU, the Verilated GPU, each frame captured from the VGA pins (and
#                  checked against the golden model by the harness);
#   host build:    the same sources compiled for Linux, the golden model as the GPU (bsp/host).
# Each scene runs with a key script (same --keys-at rule on both sides) that exercises camera
# modes, wireframe, anaglyph stereo and voxel place/break. The per-frame statistics lines must
# agree too, except the two fields only the co-simulation can measure (instructions, GPU cycles).
# Uses the FW_TEST_FRAMES-frame builds of `make fw-test-deps` in $BUILD/fw-test.
set -euo pipefail
: "${GPUSIM:?}" "${BUILD:?}"
dir="$BUILD/fw-test"
work="$BUILD/test-scenes/host-vs-cosim"
rm -rf "$work" && mkdir -p "$work"

check_case() {
    local name=$1 variant=$2
    shift 2
    local args=()
    for k in "$@"; do
        args+=(--keys-at "$k")
    done
    [ -x "$dir/host-$variant" ] && [ -f "$dir/$variant.elf" ] || { echo "missing $dir/$variant builds (make fw-test-deps)"; exit 1; }
    if ! "$GPUSIM" cosim --fw "$dir/$variant.elf" --frames "$work/$name-cosim" \
         --uart-log "$work/$name-cosim.uart" "${args[@]}" >"$work/$name-cosim.out" 2>&1; then
        echo "$name: co-simulation failed"; tail -n 5 "$work/$name-cosim.out"; exit 1
    fi
    if ! "$dir/host-$variant" --frames "$work/$name-host" "${args[@]}" >"$work/$name-host.uart" 2>&1; then
        echo "$name: host build failed"; tail -n 5 "$work/$name-host.uart"; exit 1
    fi
    local n_cosim n_host n_model
    n_cosim=$(ls "$work/$name-cosim" | wc -l)
    n_host=$(ls "$work/$name-host" | wc -l)
    n_model=$(grep -c "equals golden model" "$work/$name-cosim.out" || true)
    [ "$n_cosim" -ge 4 ] || { echo "$name: only $n_cosim frames"; exit 1; }
    [ "$n_cosim" -eq "$n_host" ] || { echo "$name: $n_cosim co-simulated frames, $n_host host frames"; exit 1; }
    [ "$n_model" -eq "$n_cosim" ] || { echo "$name: the harness checked $n_model of $n_cosim frames"; exit 1; }
    for f in "$work/$name-cosim"/*.png; do
        cmp -s "$f" "$work/$name-host/$(basename "$f")" || { echo "$name: $(basename "$f") differs"; exit 1; }
    done
    # Frame lines: identical but for the co-simulation-only fields.
    strip() { grep '^frame ' "$1" | sed -E 's/fw instr [0-9]+/fw instr -/; s/gpu cycles [0-9]+/gpu cycles -/'; }
    if ! diff <(strip "$work/$name-cosim.uart") <(strip "$work/$name-host.uart") >"$work/$name.diff"; then
        echo "$name: frame statistics differ:"; head -n 6 "$work/$name.diff"; exit 1
    fi
    # Consecutive frames differ (the keys or the animation moved something).
    local distinct
    distinct=$(md5sum "$work/$name-cosim"/*.png | awk '{print $1}' | sort -u | wc -l)
    [ "$distinct" -ge 3 ] || { echo "$name: only $distinct distinct frames: nothing moved"; exit 1; }
    echo "$name: $n_cosim frames identical (keys: $*)"
}

check_case tetra        tetra        2:f 3:g
check_case cubes        cubes        2:jjjkk 3:m 4:lll
check_case landscape    landscape    2:wwwwdd 6:kk 10:f
check_case voxel        voxel        2:b 5:p 8:np
check_case knot         knot         2:uoo 3:g
check_case tetra-float  tetra-float  2:iif
check_case voxel-float  voxel-float  2:bbj 5:k 8:dd
echo "host-vs-cosim: 7 runs, every frame byte-identical between the host build and co-simulation"
