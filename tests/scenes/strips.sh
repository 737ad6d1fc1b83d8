#!/usr/bin/env bash
# Frames drawn in strips (FW_STRIP_ROWS, render/strips.h, contract "Strips") are the frames drawn
# whole: every scene's host build in strips of 16 lines and of 1 line against the whole-frame
# build, byte for byte, at 320x240 (painter's order; wireframe with the anaglyph, so outlines,
# lines and the write mask's two passes) and at 640x480 with the depth test; then two scenes'
# ELFs in strips of 16 in co-simulation on a 640x480 GPU (sim-f640-w8: the RTL's STRIP, every
# frame checked against the golden model) against the host build's whole frames; then the
# whole-frame ELFs on GPUs with a strip buffer (contract "The strip buffer": STRIP_ROWS 16 for
# landscape and knot, 1, 4 and 64 for cubes, with depth and Gouraud; the firmware reads STRIP_ROWS
# and sends every strip: a pass that fits one batch once, which the GPU walks over the strips
# (CTRL.WALK: cubes; the knot on a GPU with buffers as large as their windows), the others binned
# by the firmware (landscape and knot on the contract's buffers; cubes built with FW_STRIP_WALK=0),
# each frame equal to the model and to the host's whole frames.
# Keys go in before the first doorbell (--keys-at 1:...): a frame in strips rings more doorbells,
# so a later doorbell would fall into another frame than in the whole build.
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
sim="$BUILD/sim-f640-w8/gpusim"
need_file "$sim"
work=$(fresh_dir scene-strips)
scenes=(tetra cubes landscape voxel knot model)
compared=0
for scene in "${scenes[@]}"; do
    need_file "$dir/host-$scene" "$dir/host-$scene-strips16" "$dir/host-$scene-strips1"
    for run in "plain" "wire:--keys-at 1:fg" "z640:--frame 640x480 --zbuf --keys-at 1:z"; do
        name=${run%%:*}
        args=()
        [ "$name" = plain ] || read -r -a args <<<"${run#*:}"
        "$dir/host-$scene" "${args[@]}" --frames "$work/$scene-$name-whole" >"$work/$scene-$name-whole.log" ||
            fail "$scene $name: the whole-frame build failed"
        for rows in 16 1; do
            "$dir/host-$scene-strips$rows" "${args[@]}" --frames "$work/$scene-$name-$rows" \
                >"$work/$scene-$name-$rows.log" || fail "$scene $name: the build in strips of $rows failed"
            same_pngs "$work/$scene-$name-whole" "$work/$scene-$name-$rows" "$scene $name: strips of $rows against the whole frame"
            compared=$((compared + $(ls "$work/$scene-$name-whole" | wc -l)))
        done
    done
    [ "$scene" = knot ] && expect_line '^depth buffer on' "$work/$scene-z640-16.log"
done
for scene in landscape knot; do
    need_file "$dir/$scene-strips16.elf"
    run_to "$work/$scene-cosim.out" 300 "$sim" cosim --fw "$dir/$scene-strips16.elf" --frames "$work/$scene-cosim" \
        --uart-log "$work/$scene-cosim.uart" --summary "$work/$scene.summary" --keys-at 1:z
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$scene-cosim.out"; fail "$scene: co-simulation in strips failed (status $status)"; }
    frames=$(summary frames "$work/$scene.summary")
    expect_eq "$(summary frames_model_checked "$work/$scene.summary")" "$frames" "$scene: frames checked against the model"
    same_pngs "$work/$scene-cosim" "$work/$scene-z640-whole" "$scene: co-simulated strips against the host's whole frames"
    batches=$(sed -nE 's/^frame 1: .*batches ([0-9]+).*/\1/p' "$work/$scene-cosim.uart")
    whole=$(sed -nE 's/^frame 1: .*batches ([0-9]+).*/\1/p' "$work/$scene-z640-whole.log")
    # 30 strips of 16 lines; those no primitive reaches are cleared with the next band drawn.
    [ "${batches:-0}" -ge 15 ] && [ "$batches" -gt "${whole:-0}" ] ||
        fail "$scene: frame 1 in ${batches:-no} batches (whole: ${whole:-?}): not drawn in strips"
    echo "$scene: frame 1 in $batches batches in strips, $whole whole"
done
# A GPU that draws in strips on chip: the firmware built for whole frames sends it its strips.
strip_gpu_runs=0
walked=0
# ELF:GPU:HOW, GPU sim-fast-s<rows>-f640-w8[-wide]; HOW bin (a batch or more a strip, the firmware's
# binning) or walk (the frame's pass one batch, CTRL.WALK).
for run in landscape:16:bin knot:16:bin cubes:1:walk cubes:4:walk cubes:64:walk cubes-bin:16:bin \
           knot:16-wide:walk; do
    IFS=: read -r elf gpu_tag how <<<"$run"
    rows=${gpu_tag%-wide}
    scene=${elf%-bin}
    gpu="$BUILD/sim-fast-s$rows-f640-w8${gpu_tag#"$rows"}/gpusim"
    need_file "$gpu" "$dir/$elf.elf"
    out="$work/$elf-gpu$gpu_tag"
    run_to "$out.out" 300 "$gpu" cosim --fw "$dir/$elf.elf" --frames "$out" --uart-log "$out.uart" \
        --summary "$out.summary" --keys-at 1:z
    [ "$status" -eq 0 ] || { tail -n 5 "$out.out"; fail "$scene: co-simulation on a GPU with strips of $rows failed (status $status)"; }
    expect_line "^strips: the GPU draws $rows rows at a time on chip" "$out.uart"
    expect_eq "$(summary frames_model_checked "$out.summary")" "$(summary frames "$out.summary")" \
        "$scene on strips of $rows: frames checked against the model"
    [ -d "$work/$scene-zg640-whole" ] ||
        "$dir/host-$scene" --frame 640x480 --zbuf --gouraud --keys-at 1:z --frames "$work/$scene-zg640-whole" \
            >"$work/$scene-zg640-whole.log" || fail "$scene: the host build with depth and Gouraud failed"
    same_pngs "$out" "$work/$scene-zg640-whole" "$scene: a GPU drawing strips of $rows rows against the host's whole frames"
    batches=$(sed -nE 's/^frame 1: .*batches ([0-9]+).*/\1/p' "$out.uart")
    if [ "$how" = walk ]; then
        expect_eq "${batches:-none}" 1 "$elf on strips of $rows ($gpu_tag): frame 1's batches, the GPU walking the strips"
        walked=$((walked + 1))
    else
        [ "${batches:-0}" -ge $(( (480 + rows - 1) / rows )) ] ||
            fail "$elf: frame 1 in ${batches:-no} batches on a GPU with $(( (480 + rows - 1) / rows )) strips"
    fi
    strip_gpu_runs=$((strip_gpu_runs + 1))
done
pass "strips: ${#scenes[@]} scenes, $compared frames in strips of 16 and 1 lines equal to the whole frames (320x240 painter's and wireframe anaglyph, 640x480 depth-tested); landscape and knot in strips co-simulated at 640x480, RTL = model = host; $strip_gpu_runs runs on GPUs with a strip buffer (strips of 1, 4, 16, 64 rows; $walked of them one batch the GPU walked) = model = host"
