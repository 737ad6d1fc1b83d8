#!/usr/bin/env bash
# The firmware rendered three ways must give byte-identical frames:
#   co-simulation: the ELF in QEMU, the Verilated GPU, each frame captured from the VGA pins (and
#                  checked against the golden model by the harness);
#   fast path:     the same, on the fast display path (GPUSIM_FAST: gpu_core with the harness as
#                  its display, the RTL's front bank through the RTL's palette, no VGA scan) — what
#                  the window shows, held to the pins frame for frame on every scene;
#   host build:    the same sources compiled for Linux, the golden model as the GPU (bsp/host).
# Each scene runs with a key script (same --keys-at rule on both sides) that exercises camera
# modes, wireframe, anaglyph stereo and voxel place/break. The per-frame statistics lines must
# agree too, except the two fields only the co-simulation can measure (instructions, GPU cycles).
# Uses the FW_TEST_FRAMES-frame builds in $BUILD/fw-test (mk/builds.toml's fw.fw-test).
source "$(dirname "$0")/../lib.sh"
need GPUSIM GPUSIM_FAST BUILD
dir="$BUILD/fw-test"
work=$(fresh_dir scene-host-vs-cosim)

check_case() {
    local name=$1 variant=$2
    shift 2
    local args=()
    for k in "$@"; do
        args+=(--keys-at "$k")
    done
    need_file "$dir/host-$variant" "$dir/$variant.elf"
    run_to "$work/$name-cosim.out" 300 "$GPUSIM" cosim --fw "$dir/$variant.elf" --frames "$work/$name-cosim" \
        --uart-log "$work/$name-cosim.uart" --summary "$work/$name.summary" "${args[@]}"
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$name-cosim.out"; fail "$name: co-simulation failed (status $status)"; }
    run_to "$work/$name-fast.out" 300 "$GPUSIM_FAST" cosim --fw "$dir/$variant.elf" --frames "$work/$name-fast" \
        --uart-log "$work/$name-fast.uart" --summary "$work/$name-fast.summary" "${args[@]}"
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$name-fast.out"; fail "$name: fast path failed (status $status)"; }
    run_to "$work/$name-host.uart" 300 "$dir/host-$variant" --frames "$work/$name-host" "${args[@]}"
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$name-host.uart"; fail "$name: host build failed (status $status)"; }
    local frames
    frames=$(summary frames "$work/$name.summary")
    [ "$frames" -ge 4 ] || fail "$name: only $frames frames"
    expect_eq "$(summary frames_model_checked "$work/$name.summary")" "$frames" "$name: frames checked against the model"
    same_pngs "$work/$name-cosim" "$work/$name-host" "$name: co-simulation against host"
    same_pngs "$work/$name-cosim" "$work/$name-fast" "$name: the VGA pins against the fast path"
    expect_eq "$(summary frames_model_checked "$work/$name-fast.summary")" "$frames" "$name: fast-path frames checked against the model"
    # Frame lines: identical but for the co-simulation-only fields.
    strip() { grep '^frame ' "$1" | sed -E 's/fw instr [0-9]+/fw instr -/; s/gpu cycles [0-9]+/gpu cycles -/; s/cpu cycles [0-9]+/cpu cycles -/'; }
    local other
    for other in host fast; do
        if ! diff <(strip "$work/$name-cosim.uart") <(strip "$work/$name-$other.uart") >"$work/$name.diff"; then
            head -n 6 "$work/$name.diff"; fail "$name: frame statistics differ ($other)"
        fi
    done
    # Consecutive frames differ (the keys or the animation moved something).
    local distinct
    distinct=$(md5sum "$work/$name-cosim"/*.png | awk '{print $1}' | sort -u | wc -l)
    [ "$distinct" -ge 3 ] || fail "$name: only $distinct distinct frames: nothing moved"
    echo "$name: $frames frames identical, pins, fast path and host (keys: $*)"
}

check_case tetra        tetra        2:f 3:g
check_case cubes        cubes        2:jjjkk 3:m 4:lll
check_case landscape    landscape    2:wwwwdd 6:kk 10:f
check_case voxel        voxel        2:b 5:p 8:np
check_case knot         knot         2:uoo 3:g
check_case model        model        2:jjf 3:uu
check_case tetra-float  tetra-float  2:iif
check_case voxel-float  voxel-float  2:bbj 5:k 8:dd
pass "host-vs-cosim: 8 runs (every scene), every frame byte-identical between the VGA pins, the fast display path and the host build"
