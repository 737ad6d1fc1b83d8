#!/usr/bin/env bash
# What of the ULX3S flow can be checked without a board: the constraints cover every pin of
# ulx3s_top (and name no other), the oscillator is constrained; openFPGALoader knows the board;
# `make flash`/`make load` refuse without a bitstream and say what to do; boards/board_load.sh, with no
# board on USB, fails with openFPGALoader's "device not found" and says what to check;
# boards/board_term.sh (make term) refuses a missing serial port clearly.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir boards-ulx3s-tools)
lpf=boards/ulx3s/ulx3s.lpf

# The ports of ulx3s_top, buses expanded to bits: name[i].
ports=$(sed -n '/^module ulx3s_top/,/^);/p' boards/ulx3s/ulx3s_top.v |
    sed -n 's/^ *\(input\|output\) *wire *\(\[\([0-9]*\):0\]\)\? *\([a-z_0-9]*\).*/\3:\4/p' |
    while IFS=: read -r msb name; do
        if [ -z "$msb" ]; then echo "$name"; else for ((i = 0; i <= msb; i++)); do echo "$name[$i]"; done; fi
    done | sort)
[ "$(echo "$ports" | wc -l)" -ge 10 ] || fail "could not read the ports of ulx3s_top: $ports"
located=$(sed -n 's/^LOCATE COMP "\([^"]*\)".*/\1/p' "$lpf" | sort)
iobuf=$(sed -n 's/^IOBUF PORT "\([^"]*\)".*/\1/p' "$lpf" | sort)
[ "$ports" = "$located" ] || fail "LOCATE COMP in $lpf against the ports of ulx3s_top: $(diff <(echo "$ports") <(echo "$located") | grep '^[<>]' | tr '\n' ' ')"
[ "$ports" = "$iobuf" ] || fail "IOBUF PORT in $lpf against the ports of ulx3s_top: $(diff <(echo "$ports") <(echo "$iobuf") | grep '^[<>]' | tr '\n' ' ')"
grep -q '^FREQUENCY PORT "clk_25mhz" 25 MHZ;' "$lpf" || fail "$lpf does not constrain clk_25mhz to 25 MHz"
sites=$(sed -n 's/^LOCATE COMP "[^"]*" SITE "\([^"]*\)".*/\1/p' "$lpf" | sort)
[ -z "$(echo "$sites" | uniq -d)" ] || fail "$lpf puts two ports on one site: $(echo "$sites" | uniq -d | tr '\n' ' ')"

# (to a file first: grep -q would close the pipe early, and pipefail would count openFPGALoader's SIGPIPE)
openFPGALoader --list-boards >"$work/boards.txt" 2>&1 </dev/null || true
grep -q '^ulx3s ' "$work/boards.txt" || fail "openFPGALoader does not know the board ulx3s: $(head -c 300 "$work/boards.txt")"

run_to "$work/flash.out" 60 make --no-print-directory flash BOARD=ulx3s BUILD="$work/empty-build"
[ "$status" -ne 0 ] || fail "make flash without a bitstream succeeded"
expect_line "make bitstream BOARD=ulx3s first" "$work/flash.out"

head -c 4096 /dev/urandom >"$work/not-a-board.bit"
run_to "$work/load.out" 60 bash boards/board_load.sh ulx3s sram "$work/not-a-board.bit"
if [ "$status" -eq 0 ]; then
    echo "a ULX3S is attached: loading random bytes succeeded?"; cat "$work/load.out"; fail "board_load.sh accepted garbage"
fi
expect_line "device not found" "$work/load.out"
expect_line "board_load: openFPGALoader could not load" "$work/load.out"

run_to "$work/term.out" 10 env TERM_PORT="$work/ttyUSB-none" bash boards/board_term.sh "$work/ttyUSB-none"
[ "$status" -ne 0 ] || fail "board_term.sh started on a missing port"
expect_line "term: no serial port" "$work/term.out"

# The frames' options: in the SDRAM only with the firmware there, 640x480 only in the SDRAM, and the
# build's directory names the part and the frames. The board's default build (boards/ulx3s/defaults.mk):
# everything in the SDRAM at 640x480 with the depth buffer; SOC_MEM=ram the on-chip build.
ulx3s_dir() {  # NAME ARGS...: make ulx3s-dir's answer for ARGS, into $work/NAME.out
    local name="$1"
    shift
    run_to "$work/$name.out" 60 make --no-print-directory ulx3s-dir BOARD=ulx3s "$@" BUILD="$work/empty-build"
}
ulx3s_dir dram-ram SOC_MEM=ram FRAME_DRAM=1
[ "$status" -ne 0 ] || fail "FRAME_DRAM=1 with the firmware on chip was accepted"
expect_line "FRAME_DRAM=1 keeps the frames in the SDRAM: it needs SOC_MEM=sdram" "$work/dram-ram.out"
ulx3s_dir fb640 SOC_MEM=sdram FRAME_DRAM=0 FB=640x480
[ "$status" -ne 0 ] || fail "FB=640x480 with the frames on chip was accepted"
expect_line "FB=640x480 on the board: .*FRAME_DRAM=1 SOC_MEM=sdram" "$work/fb640.out"
ulx3s_dir part SOC_MEM=sdram FRAME_DRAM=1 FB=640x480 ZBUF=1 FPGA=12F
expect_status 0 "make ulx3s-dir with the frames in the SDRAM"
# (the 12F leaves the projection unit out by default: PROJ_UNIT=0)
expect_line "/board-ulx3s/tetra-16k-50mhz-z-sdram-dram-s16-f640-12f-nopu$" "$work/part.out"
ulx3s_dir part-pu SOC_MEM=sdram FRAME_DRAM=1 FB=640x480 ZBUF=1 FPGA=12F PROJ_UNIT=1
expect_status 0 "make ulx3s-dir on the 12F with the projection unit"
expect_line "/board-ulx3s/tetra-16k-50mhz-z-sdram-dram-s16-f640-12f$" "$work/part-pu.out"
ulx3s_dir default
expect_status 0 "make ulx3s-dir (the default build)"
# (the 85F's buffers as large as their windows by default: WIDE_BUF=1)
expect_line "/board-ulx3s/tetra-16k-50mhz-z-sdram-dram-s16-f640-wide$" "$work/default.out"
ulx3s_dir narrow WIDE_BUF=0
expect_status 0 "make ulx3s-dir WIDE_BUF=0"
expect_line "/board-ulx3s/tetra-16k-50mhz-z-sdram-dram-s16-f640$" "$work/narrow.out"
ulx3s_dir on-chip SOC_MEM=ram
expect_status 0 "make ulx3s-dir SOC_MEM=ram"
expect_line "/board-ulx3s/tetra-192k-50mhz$" "$work/on-chip.out"
ulx3s_dir sdram-only SOC_MEM=sdram FRAME_DRAM=0
expect_status 0 "make ulx3s-dir SOC_MEM=sdram FRAME_DRAM=0"
expect_line "/board-ulx3s/tetra-16k-50mhz-sdram$" "$work/sdram-only.out"
# Every other goal keeps the Makefile's defaults (the contract's frame, no depth buffer, the
# firmware on chip) whatever the board's are.
run_to "$work/defaults.out" 60 make -s --no-print-directory BOARD=ulx3s BUILD="$work/empty-build" \
    --eval 'show-defaults: ; @echo "defaults: $(FB) $(ZBUF) $(SOC_MEM)"' show-defaults
expect_status 0 "make show-defaults"
expect_line "^defaults: 320x240 0 ram$" "$work/defaults.out"

pass "boards-ulx3s-tools: $(echo "$ports" | wc -l) pins of ulx3s_top constrained once each; flash/load/term refuse clearly without a board; the frames' options and the board's defaults checked"
