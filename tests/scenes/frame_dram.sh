#!/usr/bin/env bash
# Frames in external memory (contract "Frames in external memory", FRAME_DRAM): the whole-frame
# firmware on 640x480 GPUs with strips of 16 rows whose frames live behind a memory port. landscape
# on the pin path (gpu_top: the flushes and the scan-out through gpu_frame_dram to a model of
# LiteDRAM's native port, every frame taken from the VGA pins through the line buffer), knot on
# the fast path (gpu_core's frame stream into the harness); each frame equal to the model and to the
# host build's whole frames, SCANOUT_UNDERFLOWS 0 after every batch (the model's, compared) and at
# the end, the port's traffic counted.
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
work=$(fresh_dir scene-dram)
for run in landscape:sim-dram-s16-f640-w8 knot:sim-fast-dram-s16-f640-w8; do
    scene=${run%%:*} id=${run#*:}
    gpu="$BUILD/$id/gpusim"
    need_file "$gpu" "$dir/$scene.elf" "$dir/host-$scene"
    out="$work/$scene-$id"
    run_to "$out.out" 300 "$gpu" cosim --fw "$dir/$scene.elf" --frames "$out" --uart-log "$out.uart" \
        --summary "$out.summary" --keys-at 1:z
    [ "$status" -eq 0 ] || { tail -n 5 "$out.out"; fail "$scene on $id: co-simulation failed (status $status)"; }
    expect_line '^strips: the GPU draws 16 rows at a time on chip' "$out.uart"
    expect_eq "$(summary frames_model_checked "$out.summary")" "$(summary frames "$out.summary")" \
        "$scene on $id: frames checked against the model"
    expect_eq "$(summary scanout_underflows "$out.summary")" 0 "$scene on $id: SCANOUT_UNDERFLOWS"
    "$dir/host-$scene" --frame 640x480 --zbuf --gouraud --keys-at 1:z --frames "$work/$scene-whole" \
        >"$work/$scene-whole.log" || fail "$scene: the host build with depth and Gouraud failed"
    same_pngs "$out" "$work/$scene-whole" "$scene on $id: frames in external memory against the host's whole frames"
    echo "$scene on $id: $(summary frames "$out.summary") frames;" \
        "port words written $(summary frame_memory_words_written "$out.summary")," \
        "read $(summary frame_memory_words_read "$out.summary")"
done
written=$(summary frame_memory_words_written "$work/landscape-sim-dram-s16-f640-w8.summary")
bytes=$(summary frame_memory_word_bytes "$work/landscape-sim-dram-s16-f640-w8.summary")
[ "${bytes:-0}" -gt 0 ] || fail "landscape: no native word width in the summary"
frame_words=$((640 * 480 / bytes))  # a frame in the port's native words (76,800 of 32 bits)
[ "${written:-0}" -ge "$frame_words" ] || fail "landscape: only ${written:-no} words written through the frames' port (a frame is $frame_words)"
pass "frames in external memory: landscape (pin path, through the port model and the line buffer) and knot (fast path) at 640x480 in strips of 16 = model = host, no underflow"
