#!/usr/bin/env bash
# The SDRAM chip model (cosim/sdram/sdram_chip.cpp) on its own, no Verilator: tests/sdram/chip_model_test.cpp
# drives it with hand-written controller sequences — the power-up, bursts at CL 2/3 and BL 1/2/4/8 with
# each read word on its exact edge, DQM both ways, auto precharge, 8,192 refreshes in 64 ms — and, for
# every check the model makes, a sequence that breaks exactly it and must be reported as exactly that.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir sdram-chip-model)

run_to "$work/build.log" 300 g++ -std=c++17 -O2 -Wall -Wextra -Werror -Icosim/sdram \
    tests/sdram/chip_model_test.cpp cosim/sdram/sdram_chip.cpp -o "$work/chip_model_test"
expect_status 0 "building the chip model's test (log: $work/build.log)"
run_to "$work/out" 60 "$work/chip_model_test" -v
expect_status 0 "the chip model's test (log: $work/out)"
last=$(tail -n 1 "$work/out")
[[ "$last" =~ ^chip_model:\ ok\ ([0-9]+)\ cases$ ]] || fail "the last line is '$last', not 'chip_model: ok N cases' (log: $work/out)"
pass "sdram-chip-model: the IS42S16160G model passes ${BASH_REMATCH[1]} cases: legal sequences read back on the exact edge, each timing, state, refresh and bus violation reported as itself"
