#!/usr/bin/env bash
# The SoC against co-simulation: the scenes run on socsim (the whole SoC: VexRiscv, caches,
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
# scene runs its 3-frame build (mk/builds.toml fw.soc-test): a SoC frame is seconds of simulation (the
# start-up of landscape, voxel and knot alone is millions of cycles: terrain, chunk meshes, the
# knot's grid), and frames 0-2 already cover the keys (read at frame 2). Two scenes run at a time.
# On chip three scenes run, one per camera mode (voxel fly, cubes orbit, tetra object): the knot's
# and the landscape's start-ups are most of a run's cycles, and every scene runs on socsim from the
# SDRAM in soc-sdram-scenes (tests/soc/sdram_tour.sh; their on-chip images' fit, stack included, is
# fw-fit's). SOC_SCENES='…' picks others.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
# J J J W at doorbell 1 (frame 0's first batch): look or swing left three times and move forward or
# zoom in, in every camera mode; the firmware reads them at frame 2 in both worlds (keys typed at a
# frame's doorbells act from the frame after next, app.c). No scene key.
keys='1:jjjw'
need_file "$socsim"
work=$(fresh_dir soc-vs-cosim)
scenes=${SOC_SCENES:-voxel cubes tetra}

one_scene() {
    local s="$1" host="$BUILD/fw-test/host-$1" soc_elf frames printed f
    soc_elf="$soc_test_dir/$s-3f.elf"
    need_file "$host" "$soc_elf.hex"
    run_to "$work/$s.host.uart" 300 "$host" --frames "$work/$s-host" --keys-at "$keys"
    expect_status 0 "host build of $s"
    run_to "$work/$s.soc.out" 600 "$socsim" --fw "$soc_elf" --frames "$work/$s-soc" \
        --uart-log "$work/$s.soc.uart" --keys-at "$keys" --summary "$work/$s.soc.summary"
    expect_status 0 "socsim of $s (log: $work/$s.soc.out)"
    frames=$(summary frames "$work/$s.soc.summary")
    [ "$frames" -ge 3 ] || fail "$s: only $frames frames on socsim"
    expect_eq "$(png_count "$work/$s-soc")" "$frames" "$s: PNG files written by socsim"
    expect_eq "$(summary frames_model_checked "$work/$s.soc.summary")" "$frames" "$s: socsim frames equal to the model"
    expect_eq "$(summary keys_late "$work/$s.soc.summary")" 0 "$s: keys still on the line when read"
    [ "$(summary registers_model_checked "$work/$s.soc.summary")" -gt 0 ] ||
        fail "$s: no register read compared with the model"
    for f in "$work/$s-soc"/*.png; do
        [ -f "$work/$s-host/$(basename "$f")" ] || fail "$s: the host build has no $(basename "$f")"
        cmp -s "$f" "$work/$s-host/$(basename "$f")" || fail "$s: $(basename "$f") differs from the host build's"
    done
    # Both worlds read the keys at the same frame: the same triangles submitted and drawn per frame.
    printed=$(frame_lines "$work/$s.soc.uart" | wc -l)
    [ "$printed" -le "$frames" ] || fail "$s: $printed frame lines for $frames frames"
    diff <(frame_lines "$work/$s.soc.uart") <(frame_lines "$work/$s.host.uart" | head -n "$printed") >/dev/null ||
        fail "$s: the firmware's triangle counts differ between socsim and the host build"
    echo "$s: $frames frames identical to the host build's, $(summary cycles "$work/$s.soc.summary") SoC cycles"
}

each_scene 2 one_scene $scenes
total=$(total_frames "$work/%.soc.summary" $scenes)
pass "soc-vs-cosim: $(echo $scenes | wc -w) scenes, $total socsim frames byte-identical to the host build's (= co-simulation's), all equal to the model"
