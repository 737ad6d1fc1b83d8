#!/usr/bin/env bash
# Every scene from the SDRAM, booted once: the system with LiteDRAM and the chip and flash models
# (socsim-sdram-dram-<boot RAM>k), its RAM holding the boot program, which powers the SDRAM up, runs
# the quick memory test (its random fill cut to 16 KiB: boot-fast; the boards' boot runs in
# soc-boot-faults) and copies the tour's image from the flash (docs/boot.md): every scene in one
# program (mk/builds.toml fw.soc-tour; the model scene at the host build's capacities), the GPU's
# two 640x480 frames in the SDRAM too (FRAME_DRAM, strips of 16 rows, depth buffer and Gouraud: the
# contract's "Frames in external memory"), on LiteDRAM's second port, the chip model serving the
# CPU's cache lines, the strips' flushes and the scan-out's rows.
#
# Two frames a scene, painter's order then depth-tested, after one more painter's frame of the first
# scene: keys typed at a frame's doorbell act from the frame after next (the firmware collects the
# next frame's keys before a frame's first doorbell, app.c), so Z typed at the doorbell that starts
# frame 2i is read at frame 2i + 2, scene i's second, and Z and the next scene's key at the one that
# starts frame 2i + 1 (--keys-at fF:TEXT: by frame, since a frame takes more batches on the SoC's
# GPU than on the model's). The host build (fw-test host-tour: the golden model as the GPU, at 640x480 with its
# depth buffer) gets the same keys at the same frames. Its frames must be the tour asked for (each
# scene's name, then depth off and on), socsim's the same bytes, all equal to the model, with no
# SDRAM or flash violation, no scan-out underflow, every row fetched within its display line, the
# image loaded and started, and the keys on time (keys_late 0). One boot for all the scenes: a boot
# is about 2.3 M of socsim's cycles (a second order of them for each scene run of its own).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
socsim=${1:?usage: sdram_tour.sh SOCSIM_SDRAM_DRAM}
host="$BUILD/fw-test/host-tour"
elf="$BUILD/fw-test-soc-sdram/tour.elf"
boot="$BUILD/soc/boot-fast.elf.hex"  # its random fill 16 KiB: the scenes are the subject here
need_file "$socsim" "$host" "$elf.img" "$boot"
work=$(fresh_dir soc-sdram-tour)

# The scenes in the table's order (their keys 1, 2, ...); the tour starts at knot, the program's
# boot scene, and visits the others in the table's order.
mapfile -t table < <(sed -n 's/^SCENE(\([A-Za-z0-9_]*\)[,)].*/\1/p' firmware/scenes/scene_list.h)
[ "${#table[@]}" -ge 2 ] || fail "no scene table in firmware/scenes/scene_list.h"
tour=(knot)
for s in "${table[@]}"; do
    [ "$s" = knot ] || tour+=("$s")
done
keys=()
for i in "${!tour[@]}"; do
    keys+=(--keys-at "f$((2 * i)):z")
    if [ $((i + 1)) -lt "${#tour[@]}" ]; then
        next=${tour[$((i + 1))]}
        for k in "${!table[@]}"; do
            [ "${table[$k]}" = "$next" ] && keys+=(--keys-at "f$((2 * i + 1)):z$((k + 1))")
        done
    fi
done
frames=$((2 * ${#tour[@]} + 1))

run_to "$work/host.uart" 300 "$host" "${dram_host_frame[@]}" --frames "$work/host" "${keys[@]}"
expect_status 0 "host build of the tour"
expect_eq "$(png_count "$work/host")" "$frames" "the host build's frames (its FW_TOUR_FRAMES)"
# The tour as a run took it (UART_LOG): each scene started, depth off and on, the frames.
tour_lines() {
    grep -E '^(scene [a-z]+:|depth buffer o|frame [0-9]+:)' "$1" | sed -E 's/^(scene [a-z]+):.*/\1/; s/^frame [0-9]+:.*/frame/'
}
want=""
for s in "${tour[@]}"; do
    if [ -z "$want" ]; then
        want="scene $s;frame;frame;depth buffer on;frame;"  # the extra painter's frame first
    else
        want+="scene $s;depth buffer off;frame;depth buffer on;frame;"
    fi
done
got=$(tour_lines "$work/host.uart" | tr '\n' ';')
[ "$got" = "$want" ] || fail "the host build's tour: got '$got', expected '$want' (scenes, depth off and on, frames)"

run_to "$work/soc.out" 900 "$socsim" --boot "$boot" --stop-frames "$frames" --fw "$elf" --frames "$work/soc" \
    --uart-log "$work/soc.uart" "${keys[@]}" --summary "$work/soc.summary"
expect_status 0 "socsim of the tour (log: $work/soc.out)"
expect_eq "$(summary frames "$work/soc.summary")" "$frames" "socsim's frames"
expect_eq "$(png_count "$work/soc")" "$frames" "PNG files written by socsim"
expect_eq "$(summary frames_model_checked "$work/soc.summary")" "$frames" "socsim frames equal to the model"
expect_eq "$(summary keys_late "$work/soc.summary")" 0 "keys still on the line when read"
[ "$(summary registers_model_checked "$work/soc.summary")" -gt 0 ] || fail "no register read compared with the model"
same_pngs "$work/soc" "$work/host" "socsim's frames against the host build's"
# The same triangles submitted per frame (drawn differs: in strips a triangle is drawn once for each
# strip it reaches), and the same tour.
diff <(frame_lines "$work/soc.uart" | sed 's/ drawn .*//') <(frame_lines "$work/host.uart" | sed 's/ drawn .*//') >/dev/null ||
    fail "the firmware's triangle counts differ between socsim and the host build"
diff <(tour_lines "$work/soc.uart") <(tour_lines "$work/host.uart") >/dev/null ||
    fail "the tour differs between socsim and the host build (scenes, depth off and on, frames)"
expect_eq "$(summary sdram_violations "$work/soc.summary")" 0 "SDRAM chip model violations"
expect_eq "$(summary flash_violations "$work/soc.summary")" 0 "flash model violations"
grep -q "^boot: image of [0-9]* bytes from flash .* starting at 0x40000000" "$work/soc.uart" ||
    fail "the boot program did not load and start the image (log: $work/soc.uart)"
expect_eq "$(summary scanout_underflows "$work/soc.summary")" 0 "SCANOUT_UNDERFLOWS"
worst=$(summary scanout_worst_row_clocks "$work/soc.summary")
# A row's deadline is one display line: 800 pixels of 2 system clocks (socsim's 50 MHz, the 25 MHz
# pixel rate).
[ "${worst:-0}" -gt 0 ] && [ "$worst" -lt 1600 ] || fail "the slowest row fetch took ${worst:-?} clocks (deadline 1,600)"
expect_line '^strips: the GPU draws 16 rows at a time on chip' "$work/soc.uart"
pass "soc-sdram-scenes: ${#tour[@]} scenes from the SDRAM in one boot (${tour[*]}), $frames frames at 640x480, painter's order then depth-tested, byte-identical to the host build's and equal to the model; $(summary cycles "$work/soc.summary") SoC cycles, the slowest row fetch $worst clocks, SDRAM words read $(summary sdram_words_read "$work/soc.summary"), written $(summary sdram_words_written "$work/soc.summary"), no underflow"
