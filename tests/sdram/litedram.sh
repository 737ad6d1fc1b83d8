#!/usr/bin/env bash
# LiteDRAM's generated controller (soc_rtl/litedram, inside the SoC's SDRAM block soc_sdram.v, behind
# our Wishbone port sdram_wb_burst.v) against the SDRAM chip model (cosim/sdram) at the chip's pins
# (tests/sdram/litedram_tb.cpp):
#   1. the board's configuration, our power-up sequence (bsp/soc/sdram/sdram_init.c): random words over
#      the whole chip and a block of consecutive ones read back equal; 8-word read and write bursts
#      (clocks a word, a line's first-beat latency) and 2,000 burst cases mixed at random against a
#      reference memory (line reads and writes, single words, bursts abandoned early, unaligned,
#      wrap-8, across the chip's top) all read back right; then more than 64 ms with the
#      controller's refresh alone — no violation of any command, timing or the refresh budget;
#   2. the same core with the chip's clock half a PHY clock (clk2x) behind instead of a whole one:
#      the reads come back a beat early, so the board's SDRAM clock must lag clk2x by more (PLL);
#   3. LiteDRAM's own generated init_sequence(): the chip model refuses its first mode register
#      write (A8 set, reserved in an SDR chip's mode register);
#   4. a controller generated with a refresh interval ten times too long: the chip model stops the
#      run, naming the refresh.
# LITEDRAM_TB_IDLE_US (default 70000) sets how long case 1 idles.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(realpath "$(fresh_dir sdram-litedram)")
python=.venv/bin/python
sys_hz=50000000
[ -x "$python" ] || fail "no .venv (make setup makes it)"

# build NAME [--set T=NS ...]: generate the core into $work/NAME/gen and Verilate the bench.
build() {
    local name=$1
    shift
    mkdir -p "$work/$name"
    run_to "$work/$name/gen.log" 300 "$python" soc_rtl/litedram/gen_litedram.py soc_rtl/litedram/ulx3s_sdram.yml \
        "$work/$name/gen" --sys-clk-hz $sys_hz "$@"
    expect_status 0 "generating the controller $name (log: $work/$name/gen.log)"
    local inc="-I$PWD/tests/sdram/stub -I$work/$name/gen/include -I$PWD/bsp/soc/sdram"
    for c in bsp/soc/sdram/sdram_init.c tests/sdram/litedram_init.c; do
        run_to "$work/$name/cc.log" 60 gcc -std=c11 -O2 -Wall -Wextra -Werror $inc -c "$c" \
            -o "$work/$name/$(basename "$c" .c).o"
        expect_status 0 "compiling $c (log: $work/$name/cc.log)"
    done
    run_to "$work/$name/verilator.log" 600 verilator --cc --exe --build -j 2 -O2 -Wno-fatal -Wno-lint -Wno-style \
        --top-module litedram_tb_top --Mdir "$work/$name/obj" -o litedram_tb \
        --timescale 1ns/1ps -I"$PWD" soc_rtl/soc_pkg.sv soc_rtl/soc_stream_slice.v soc_rtl/litedram/sdram_wb_burst.v soc_rtl/litedram/soc_sdram.v \
        tests/sdram/litedram_tb_top.sv \
        "$work/$name/gen/litedram_core.v" cosim/sdram/ecp5/*.v \
        "$PWD/tests/sdram/litedram_tb.cpp" "$PWD/cosim/sdram/sdram_chip.cpp" \
        "$work/$name/sdram_init.o" "$work/$name/litedram_init.o" \
        -CFLAGS "-std=c++17 -I$PWD/cosim/sdram $inc -DLITEDRAM_TB_SYS_CLK_HZ=$sys_hz"
    expect_status 0 "building the bench $name (log: $work/$name/verilator.log)"
}

# run NAME LOG ARG...: the bench, output to $work/LOG
run() {
    local name=$1 log=$2
    shift 2
    run_to "$work/$log" 300 "$work/$name/obj/litedram_tb" "$@"
    cat "$work/$log"
}

build board
grep -E '^(tRCD|tRP|tRAS|tRFC|tRRD|tWR|tREFI|cl) ' "$work/board/gen/settings.txt" | tr '\n' ' '; echo

run board ok.log --init ours --words 3000 --bursts 2000 --seed 7 --grade 6 --idle-us "${LITEDRAM_TB_IDLE_US:-70000}"
expect_status 0 "the board's controller against the chip model, grade -6 (log: $work/ok.log)"
expect_line '^litedram_tb: ok ' "$work/ok.log"
expect_line '^litedram_tb: burst cases: [0-9]+ read beats checked .*, 0 wrong$' "$work/ok.log"
run board ok7.log --init ours --words 3000 --bursts 2000 --seed 8 --grade 7 --idle-us 1000
expect_status 0 "the board's controller against the chip model, grade -7 (log: $work/ok7.log)"
expect_line '^litedram_tb: ok ' "$work/ok7.log"
expect_line '^litedram_tb: burst cases: [0-9]+ read beats checked .*, 0 wrong$' "$work/ok7.log"

run board lag-half.log --init ours --words 200 --lag half
[ "$status" -ne 0 ] || fail "the chip clocked half a clk2x period behind read back right: the phase argument of docs/sdram.md is wrong"
expect_line 'read 0x' "$work/lag-half.log"

run board litedram-init.log --init litedram --words 10 --expect-error 'reserved'
expect_status 0 "LiteDRAM's init_sequence() against the chip model (log: $work/litedram-init.log)"

build refresh10x --set tREFI=78125
run refresh10x refresh.log --init ours --words 100 --idle-us 2000 --expect-error 'refresh'
expect_status 0 "a controller refreshing ten times too seldom (log: $work/refresh.log)"

line_clocks=$(sed -n 's/^litedram_tb: 8-word read bursts: first beat [0-9.]* clocks, \([0-9.]*\) a line.*/\1/p' "$work/ok.log")
pass "sdram-litedram: LiteDRAM's controller and the chip model agree on $(sed -n 's/^litedram_tb: ok \([0-9]*\) random.*/\1/p' "$work/ok.log") random words, $(sed -n 's/^litedram_tb: ok .* \([0-9]*\) burst beats.*/\1/p' "$work/ok.log") burst beats (a line in $line_clocks clocks) and 70 ms of refresh; an early chip clock, LiteDRAM's init and a 10x refresh interval each caught"
