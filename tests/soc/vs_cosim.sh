#!/usr/bin/env bash
# The SoC against co-simulation: every scene runs on socsim (the whole SoC: VexRiscv, caches,
# Wishbone bus, RAM, UART, the GPU and its VGA pins) and on the firmware's host build (the golden
# model as the GPU; suite scene-host-vs-cosim holds it byte-identical to `gpusim cosim`, QEMU and
# the Verilated GPU, and it takes a second where co-simulation takes twenty), with the same
# scripted keys at the same doorbell. Both must end with status 0; socsim checks every frame and the
# registers the firmware reads after each batch against the golden model; its PNG files must be
# byte-identical to the host build's of the same names, its frame lines the same triangle counts,
# and the keys must have arrived whole before the firmware read them (keys_late 0).
#
# Every scene: their one-scene chip builds fit the SoC's 192 KiB (`make fw-size`, suite fw-fit).
# The host side runs make test's FW_TEST_FRAMES (4) builds (all scenes in one image, line emulation
# compiled in: neither changes a frame, as no scene or wireframe key is pressed); on socsim every
# scene runs its 2-frame build (tests/soc/tests.mk): a SoC frame is seconds of simulation (the
# start-up of landscape, voxel and knot alone is millions of cycles: terrain, chunk meshes, the
# knot's grid), and frames 0-1 already cover the keys (read at frame 1). Two scenes run at a time.
# SOC_SCENES='tetra cubes' limits the scenes.
#
#   vs_cosim.sh sdram SOCSIM_SDRAM   (suite soc-sdram-scenes) the same with the firmware in the
#   SDRAM: the system with LiteDRAM and the chip and flash models (socsim-sdram-<boot RAM>k), its
#   RAM holding the boot program, which powers the SDRAM up, runs the quick memory test (its random
#   fill cut to 16 KiB: boot-fast; the boards' boot runs in soc-boot-faults) and copies each scene's
#   image (the SOC_MEM=sdram builds; the model scene at the host build's capacities) from the flash
#   (docs/boot.md). The frames must be the same bytes, with no SDRAM or flash violation, the image
#   loaded and started. A short run a scene: the first frame (--stop-frames 1; the keys, read at
#   frame 1, are the on-chip runs' subject).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
memory=on-chip
boot=()
short=()
image=hex
if [ "${1:-}" = sdram ]; then
    memory=SDRAM
    socsim=${2:?usage: vs_cosim.sh sdram SOCSIM_SDRAM}
    soc_test_dir=$BUILD/fw-test-soc-sdram
    boot=(--boot "$BUILD/soc/boot-fast.elf.hex")  # its random fill 16 KiB: the scenes are the subject here
    short=(--stop-frames 1)
    need_file "${boot[1]}"
    image=img
fi
need_file "$socsim"
# J J J W at doorbell 1 (frame 0's first batch): look or swing left three times and move forward or
# zoom in, in every camera mode; the firmware reads them at frame 1 in both worlds. No scene key.
keys='1:jjjw'
work=$(fresh_dir "soc-vs-cosim${1:+-$1}")
# The slowest first, so that it overlaps the others.
# From the SDRAM the model scene too: its capacities are the SDRAM build's.
scenes=${SOC_SCENES:-knot voxel landscape cubes tetra${1:+ model}}

one_scene() {
    local s="$1" host="$BUILD/fw-test/host-$1" soc_elf frames printed f
    soc_elf="$soc_test_dir/$s-2f.elf"
    need_file "$host" "$soc_elf.$image"
    run_to "$work/$s.host.uart" 300 "$host" --frames "$work/$s-host" --keys-at "$keys"
    expect_status 0 "host build of $s"
    run_to "$work/$s.soc.out" 600 "$socsim" "${boot[@]}" "${short[@]}" --fw "$soc_elf" --frames "$work/$s-soc" \
        --uart-log "$work/$s.soc.uart" --keys-at "$keys" --summary "$work/$s.soc.summary"
    expect_status 0 "socsim of $s (log: $work/$s.soc.out)"
    frames=$(summary frames "$work/$s.soc.summary")
    [ "$frames" -ge $((${#short[@]} ? 1 : 2)) ] || fail "$s: only $frames frames on socsim"
    expect_eq "$(png_count "$work/$s-soc")" "$frames" "$s: PNG files written by socsim"
    expect_eq "$(summary frames_model_checked "$work/$s.soc.summary")" "$frames" "$s: socsim frames equal to the model"
    expect_eq "$(summary keys_late "$work/$s.soc.summary")" 0 "$s: keys still on the line when read"
    [ "$(summary registers_model_checked "$work/$s.soc.summary")" -gt 0 ] ||
        fail "$s: no register read compared with the model"
    for f in "$work/$s-soc"/*.png; do
        [ -f "$work/$s-host/$(basename "$f")" ] || fail "$s: the host build has no $(basename "$f")"
        cmp -s "$f" "$work/$s-host/$(basename "$f")" || fail "$s: $(basename "$f") differs from the host build's"
    done
    # Both worlds read the keys at the same frame: the same triangles submitted and drawn per frame
    # (a short run may stop before its frame's line is out on the UART: the lines it has).
    printed=$(frame_lines "$work/$s.soc.uart" | wc -l)
    [ "$printed" -le "$frames" ] || fail "$s: $printed frame lines for $frames frames"
    diff <(frame_lines "$work/$s.soc.uart") <(frame_lines "$work/$s.host.uart" | head -n "$printed") >/dev/null ||
        fail "$s: the firmware's triangle counts differ between socsim and the host build"
    if [ "$memory" = SDRAM ]; then
        expect_eq "$(summary sdram_violations "$work/$s.soc.summary")" 0 "$s: SDRAM chip model violations"
        expect_eq "$(summary flash_violations "$work/$s.soc.summary")" 0 "$s: flash model violations"
        grep -q "^boot: image of [0-9]* bytes from flash .* starting at 0x40000000" "$work/$s.soc.uart" ||
            fail "$s: the boot program did not load and start the image (log: $work/$s.soc.uart)"
    fi
    echo "$s: $frames frames identical to the host build's, $(summary cycles "$work/$s.soc.summary") SoC cycles ($memory)"
}

each_scene 2 one_scene $scenes
total=$(total_frames "$work/%.soc.summary" $scenes)
pass "soc-vs-cosim${1:+ ($1)}: $(echo $scenes | wc -w) scenes from the $memory, $total socsim frames byte-identical to the host build's (= co-simulation's), all equal to the model"
