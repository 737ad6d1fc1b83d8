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
# scene runs its 2-frame build (tests/soc/tests.mk): a SoC frame is seconds of simulation (the
# start-up of landscape, voxel and knot alone is millions of cycles: terrain, chunk meshes, the
# knot's grid), and frames 0-1 already cover the keys (read at frame 1). Two scenes run at a time.
# On chip three scenes run, one per camera mode (voxel fly, cubes orbit, tetra object): the knot's
# and the landscape's start-ups are most of a run's cycles, and both scenes run on socsim from the
# SDRAM below (their on-chip images' fit, stack included, is fw-fit's). SOC_SCENES='…' picks others.
#
#   vs_cosim.sh sdram SOCSIM_SDRAM_DRAM   (suite soc-sdram-scenes) the same with everything in the
#   SDRAM: the system with LiteDRAM and the chip and flash models (socsim-sdram-dram-<boot RAM>k),
#   its RAM holding the boot program, which powers the SDRAM up, runs the quick memory test (its
#   random fill cut to 16 KiB: boot-fast; the boards' boot runs in soc-boot-faults) and copies each
#   scene's image (the SOC_MEM=sdram builds; the model scene at the host build's capacities) from
#   the flash (docs/boot.md); and the GPU's two 640x480 frames in the SDRAM too (FRAME_DRAM, strips
#   of 16 rows, depth buffer and Gouraud: the contract's "Frames in external memory"), on
#   LiteDRAM's second port, the chip model serving the CPU's cache lines, the strips' flushes and
#   the scan-out's rows. Two frames a scene: painter's order, then depth-tested (Z at doorbell 1,
#   read at frame 1; the camera keys are the on-chip runs' subject), against the host build at
#   640x480 with its depth buffer. The frames must be the same bytes, with no SDRAM or flash
#   violation, no scan-out underflow, every row fetched within its display line, the image loaded
#   and started.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
memory=on-chip
boot=()
short=()
host_frame=()
counts='s/$//'   # the frame lines' counts compared: all of them
image=hex
# J J J W at doorbell 1 (frame 0's first batch): look or swing left three times and move forward or
# zoom in, in every camera mode; the firmware reads them at frame 1 in both worlds. No scene key.
keys='1:jjjw'
if [ "${1:-}" = sdram ]; then
    memory=SDRAM
    socsim=${2:?usage: vs_cosim.sh sdram SOCSIM_SDRAM_DRAM}
    soc_test_dir=$BUILD/fw-test-soc-sdram
    boot=(--boot "$BUILD/soc/boot-fast.elf.hex")  # its random fill 16 KiB: the scenes are the subject here
    short=(--stop-frames 2)
    host_frame=("${dram_host_frame[@]}")
    keys='1:z'
    counts='s/ drawn .*//'
    need_file "${boot[1]}"
    image=img
fi
need_file "$socsim"
work=$(fresh_dir "soc-vs-cosim${1:+-$1}")
# The slowest first, so that it overlaps the others.
# From the SDRAM the model scene too: its capacities are the SDRAM build's.
scenes=${SOC_SCENES:-${1:+knot landscape model }voxel cubes tetra}

one_scene() {
    local s="$1" host="$BUILD/fw-test/host-$1" soc_elf frames printed f worst detail=""
    soc_elf="$soc_test_dir/$s-2f.elf"
    need_file "$host" "$soc_elf.$image"
    run_to "$work/$s.host.uart" 300 "$host" "${host_frame[@]}" --frames "$work/$s-host" --keys-at "$keys"
    expect_status 0 "host build of $s"
    run_to "$work/$s.soc.out" 600 "$socsim" "${boot[@]}" "${short[@]}" --fw "$soc_elf" --frames "$work/$s-soc" \
        --uart-log "$work/$s.soc.uart" --keys-at "$keys" --summary "$work/$s.soc.summary"
    expect_status 0 "socsim of $s (log: $work/$s.soc.out)"
    frames=$(summary frames "$work/$s.soc.summary")
    [ "$frames" -ge 2 ] || fail "$s: only $frames frames on socsim"
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
    # (a short run may stop before its frame's line is out on the UART: the lines it has). In
    # strips a triangle is drawn once for each strip it reaches: there the triangles submitted.
    printed=$(frame_lines "$work/$s.soc.uart" | wc -l)
    [ "$printed" -le "$frames" ] || fail "$s: $printed frame lines for $frames frames"
    diff <(frame_lines "$work/$s.soc.uart" | sed "$counts") <(frame_lines "$work/$s.host.uart" | head -n "$printed" | sed "$counts") >/dev/null ||
        fail "$s: the firmware's triangle counts differ between socsim and the host build"
    if [ "$memory" = SDRAM ]; then
        expect_eq "$(summary sdram_violations "$work/$s.soc.summary")" 0 "$s: SDRAM chip model violations"
        expect_eq "$(summary flash_violations "$work/$s.soc.summary")" 0 "$s: flash model violations"
        grep -q "^boot: image of [0-9]* bytes from flash .* starting at 0x40000000" "$work/$s.soc.uart" ||
            fail "$s: the boot program did not load and start the image (log: $work/$s.soc.uart)"
        expect_eq "$(summary scanout_underflows "$work/$s.soc.summary")" 0 "$s: SCANOUT_UNDERFLOWS"
        worst=$(summary scanout_worst_row_clocks "$work/$s.soc.summary")
        # A row's deadline is one display line: 800 pixels of 2 system clocks (socsim's 50 MHz, the
        # 25 MHz pixel rate).
        [ "${worst:-0}" -gt 0 ] && [ "$worst" -lt 1600 ] ||
            fail "$s: the slowest row fetch took ${worst:-?} clocks (deadline 1,600)"
        expect_line '^strips: the GPU draws 16 rows at a time on chip' "$work/$s.soc.uart"
        expect_line '^depth buffer on' "$work/$s.soc.uart"
        detail=", the slowest row fetch $worst clocks, SDRAM words read $(summary sdram_words_read "$work/$s.soc.summary"), written $(summary sdram_words_written "$work/$s.soc.summary")"
    fi
    echo "$s: $frames frames identical to the host build's, $(summary cycles "$work/$s.soc.summary") SoC cycles ($memory)$detail"
}

each_scene 2 one_scene $scenes
total=$(total_frames "$work/%.soc.summary" $scenes)
what=""
[ "$memory" = SDRAM ] && what=" (the frames too: 640x480, painter's order then depth-tested, no underflow)"
pass "soc-vs-cosim${1:+ ($1)}: $(echo $scenes | wc -w) scenes from the $memory$what, $total socsim frames byte-identical to the host build's (= co-simulation's), all equal to the model"
