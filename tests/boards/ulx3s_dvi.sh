#!/usr/bin/env bash
# The ULX3S build's video, as the board's DVI connector carries it: socsim's board build
# (boards/ulx3s/ulx3s_system on its three clocks: system 50 MHz, pixel 25 MHz, TMDS 125 MHz, PLL
# unlocked for the first microsecond) decodes the four TMDS channels' bit pairs — every symbol
# checked against the DVI encoding and its DC balance, control periods, the clock channel — back
# into frames, each compared with the golden model; and the frames must be byte-identical to those
# of socsim's VGA build (soc_top's VGA pins) for the same firmware and keys, as must the firmware's
# frame lines. tetra (BOARD_SCENES='tetra cubes' adds cubes: 30 s more), make test's FW_TEST_FRAMES (4)
# soc build, the keys of soc-vs-cosim.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/../soc/soc_lib.sh"
need BUILD
board_sim=${SOCSIM_ULX3S:-$BUILD/socsim-ulx3s-192k/socsim}
need_file "$socsim" "$board_sim"
keys='1:jjjw'
work=$(fresh_dir boards-ulx3s-dvi)
scenes=${BOARD_SCENES:-tetra}

one_scene() {
    local s="$1" elf="$soc_test_dir/$1.elf" frames d
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
    # Blanking is sent as control symbols; the running disparity stays within the encoding's bound.
    [ "$(summary tmds_control_symbols "$work/$s.dvi.summary")" -gt 0 ] || fail "$s: no TMDS control period"
    for d in $(summary tmds_max_disparity "$work/$s.dvi.summary" | tr ',' ' '); do
        [ "$d" -le 8 ] || fail "$s: TMDS running disparity $d beyond the bound 8"
    done
    echo "$s: $frames frames decoded from TMDS, equal to the model and to the VGA build;" \
        "$(summary tmds_pixels "$work/$s.dvi.summary") pixels, max |disparity| $(summary tmds_max_disparity "$work/$s.dvi.summary")"
}

each_scene "$(echo $scenes | wc -w)" one_scene $scenes  # all at once
total=$(total_frames "$work/%.dvi.summary" $scenes)
pass "boards-ulx3s-dvi: $(echo $scenes | wc -w) scenes, $total frames decoded from the DVI pins, equal to the golden model and byte-identical to the VGA build"
