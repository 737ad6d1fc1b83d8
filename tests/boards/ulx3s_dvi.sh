#!/usr/bin/env bash
# The ULX3S build's video, as the board's DVI connector carries it: socsim's board build
# (boards/ulx3s/ulx3s_system on its three clocks: system 50 MHz, pixel 25 MHz, TMDS 125 MHz, PLL
# unlocked for the first microsecond) decodes the four TMDS channels' bit pairs — every symbol
# checked against the DVI encoding and its DC balance, control periods, the clock channel — back
# into frames, each compared with the golden model; and the frames must be byte-identical to those
# of socsim's VGA build (soc_top's VGA pins) for the same firmware and keys, as must the firmware's
# frame lines. tetra (BOARD_SCENES='tetra cubes' adds cubes: 30 s more), make test's FW_TEST_FRAMES (4)
# soc build, the keys of soc-vs-cosim.
#
# Then the board's build with everything in the SDRAM (socsim-ulx3s-sdram-dram: the system with
# LiteDRAM, the chip and flash models on ulx3s_system's ports; the GPU's two 640x480 frames in the
# SDRAM, strips of 16 rows, depth buffer): the boot program loads the firmware from the flash, and
# the frames decoded from the DVI pins at 640x480, 1:1, painter's order and then depth-tested (Z at
# doorbell 1, read by the third frame), must equal the model and the host build's at 640x480, byte for byte, with no SDRAM
# or flash violation and no scan-out underflow. tetra (BOARD_DRAM_SCENES adds others: the rest of
# the scenes run from the SDRAM on soc_top's VGA pins in soc-sdram-scenes).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/../soc/soc_lib.sh"
need BUILD
board_sim=${SOCSIM_ULX3S:-$BUILD/socsim-ulx3s-192k/socsim}
need_file "$socsim" "$board_sim"
keys='1:jjjw'
work=$(fresh_dir boards-ulx3s-dvi)
scenes=${BOARD_SCENES:-tetra}

one_scene() {
    local s="$1" elf="$soc_test_dir/$1.elf" frames
    need_file "$elf.hex"
    run_to "$work/$s.vga.out" 300 "$socsim" --fw "$elf" --frames "$work/$s-vga" --uart-log "$work/$s.vga.uart" \
        --keys-at "$keys" --summary "$work/$s.vga.summary"
    expect_status 0 "socsim (VGA) of $s"
    run_to "$work/$s.dvi.out" 300 "$board_sim" --fw "$elf" --frames "$work/$s-dvi" --uart-log "$work/$s.dvi.uart" \
        --keys-at "$keys" --summary "$work/$s.dvi.summary"
    expect_status 0 "socsim (ULX3S, DVI) of $s (log: $work/$s.dvi.out)"
    frames=$(summary frames "$work/$s.dvi.summary")
    [ "$frames" -ge 4 ] || fail "$s: only $frames frames decoded from the DVI pins"
    expect_eq "$frames" "$(summary frames "$work/$s.vga.summary")" "$s: frames, DVI against VGA"
    expect_eq "$(summary frames_model_checked "$work/$s.dvi.summary")" "$frames" "$s: DVI frames equal to the model"
    expect_eq "$(summary keys_late "$work/$s.dvi.summary")" 0 "$s: keys still on the line when read"
    same_pngs "$work/$s-dvi" "$work/$s-vga" "$s: the frames from the DVI pins against the VGA build's"
    diff <(frame_lines "$work/$s.dvi.uart") <(frame_lines "$work/$s.vga.uart") >/dev/null ||
        fail "$s: the firmware's frame lines differ between the DVI and the VGA build"
    check_tmds "$s" "$work/$s.dvi.summary"
    echo "$s: $frames frames decoded from TMDS, equal to the model and to the VGA build;" \
        "$(summary tmds_pixels "$work/$s.dvi.summary") pixels, max |disparity| $(summary tmds_max_disparity "$work/$s.dvi.summary")"
}

check_tmds() {
    local s="$1" summary_file="$2" d
    # Blanking is sent as control symbols; the running disparity stays within the encoding's bound.
    [ "$(summary tmds_control_symbols "$summary_file")" -gt 0 ] || fail "$s: no TMDS control period"
    for d in $(summary tmds_max_disparity "$summary_file" | tr ',' ' '); do
        [ "$d" -le 8 ] || fail "$s: TMDS running disparity $d beyond the bound 8"
    done
}

dram_scene() {
    local s="$1" elf="$BUILD/fw-test-soc-sdram/$1-3f.elf" host="$BUILD/fw-test/host-$1" f sum
    sum="$work/$s.dram.summary"
    need_file "$elf.img" "$host"
    run_to "$work/$s.dram-host.uart" 300 "$host" "${dram_host_frame[@]}" --keys-at 1:z --frames "$work/$s-dram-host"
    expect_status 0 "host build of $s at 640x480"
    run_to "$work/$s.dram.out" 600 "$dram_sim" --boot "$boot" --stop-frames 3 --fw "$elf" --frames "$work/$s-dram" \
        --uart-log "$work/$s.dram.uart" --keys-at 1:z --summary "$sum"
    expect_status 0 "socsim (ULX3S, SDRAM, DVI) of $s (log: $work/$s.dram.out)"
    expect_eq "$(summary frames "$sum")" 3 "$s: frames decoded from the DVI pins at 640x480"
    expect_eq "$(summary frames_model_checked "$sum")" 3 "$s: those frames equal to the model"
    expect_eq "$(summary sdram_violations "$sum")" 0 "$s: SDRAM chip model violations"
    expect_eq "$(summary flash_violations "$sum")" 0 "$s: flash model violations"
    expect_eq "$(summary scanout_underflows "$sum")" 0 "$s: SCANOUT_UNDERFLOWS"
    expect_line '^depth buffer on' "$work/$s.dram.uart"
    for f in "$work/$s-dram"/*.png; do   # the host build runs more frames: the first three are compared
        cmp -s "$f" "$work/$s-dram-host/$(basename "$f")" || fail "$s: $(basename "$f") from the DVI pins differs from the host build's"
    done
    check_tmds "$s" "$sum"
    echo "$s: 3 frames at 640x480 from the DVI pins, frames in the SDRAM, equal to the model and to the host build;" \
        "the slowest row fetch $(summary scanout_worst_row_clocks "$sum") clocks"
}

each_scene "$(echo $scenes | wc -w)" one_scene $scenes  # all at once
total=$(total_frames "$work/%.dvi.summary" $scenes)

dram_sim=${1:?usage: ulx3s_dvi.sh SOCSIM_ULX3S_SDRAM_DRAM}
boot="$BUILD/soc/boot-fast.elf.hex"
need_file "$dram_sim" "$boot"
dram_scenes=${BOARD_DRAM_SCENES:-tetra}
each_scene 2 dram_scene $dram_scenes
dram_total=$(total_frames "$work/%.dram.summary" $dram_scenes)
pass "boards-ulx3s-dvi: $(echo $scenes | wc -w) scenes, $total frames decoded from the DVI pins, equal to the golden model and byte-identical to the VGA build; with the frames in the SDRAM at 640x480, $dram_total frames (painter's, depth-tested) = model = host build"
