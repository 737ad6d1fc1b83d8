#!/usr/bin/env bash
# Every scene at the contract's largest frame, 640x480 shown 1:1, with the depth buffer off and on:
# the firmware (the FW_TEST_FRAMES builds in $BUILD/fw-test, the very programs the 320x240 suites
# run: the firmware reads its frame from the GPU's FB_SIZE) in QEMU against a GPU built for the
# frame with the depth buffer (mk/builds.toml's sim-f640-w8), each frame from the VGA pins and
# checked against the golden model by the harness; the host build with the model at that frame
# (--frame 640x480 --zbuf) gives byte-identical frames. Z at the doorbell that starts frame 1
# (--keys-at f1:z, whatever its batches) turns the depth test on from frame 3 (keys typed at a
# frame's doorbells act from the frame after next: app.c): frames 0 to 2 in painter's order, the rest
# depth-tested.
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
sim="$BUILD/sim-f640-w8/gpusim"
need_file "$sim"
work=$(fresh_dir scene-640)
scenes=(tetra cubes landscape voxel knot model)
frames_total=0
for scene in "${scenes[@]}"; do
    need_file "$dir/$scene.elf" "$dir/host-$scene"
    run_to "$work/$scene-cosim.out" 300 "$sim" cosim --fw "$dir/$scene.elf" --frames "$work/$scene-cosim" \
        --uart-log "$work/$scene-cosim.uart" --summary "$work/$scene.summary" --keys-at f1:z
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$scene-cosim.out"; fail "$scene: co-simulation at 640x480 failed (status $status)"; }
    run_to "$work/$scene-host.uart" 300 "$dir/host-$scene" --frame 640x480 --zbuf --frames "$work/$scene-host" --keys-at f1:z
    [ "$status" -eq 0 ] || { tail -n 5 "$work/$scene-host.uart"; fail "$scene: host build at 640x480 failed (status $status)"; }
    expect_line 'fb 640x480' "$work/$scene-cosim.uart"
    expect_line '^depth buffer on' "$work/$scene-cosim.uart"
    [ "$(grep -B1 '^depth buffer on' "$work/$scene-cosim.uart" | head -n 1 | cut -d: -f1)" = "frame 2" ] ||
        fail "$scene: the depth test did not start after frame 2 ($work/$scene-cosim.uart)"
    frames=$(summary frames "$work/$scene.summary")
    [ "$frames" -ge 4 ] || fail "$scene: only $frames frames"
    expect_eq "$(summary frames_model_checked "$work/$scene.summary")" "$frames" "$scene: frames checked against the model"
    same_pngs "$work/$scene-cosim" "$work/$scene-host" "$scene at 640x480: co-simulation against host"
    size=$("$PYTHON" -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]))' \
           "$(ls "$work/$scene-cosim"/*.png | head -1)")
    [ "$size" = 640x480 ] || fail "$scene: frames of $size, not 640x480"
    frames_total=$((frames_total + frames))
done
pass "scene-640: ${#scenes[@]} scenes at 640x480, $frames_total frames (painter's order, then depth-tested), co-simulation = model = host build"
