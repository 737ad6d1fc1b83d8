#!/usr/bin/env bash
# The SPI NOR flash model (cosim/flash/spi_flash.cpp, the ULX3S's ISSI IS25LP128) on its own, no
# Verilator: tests/flash/spi_flash_test.cpp bit-bangs SPI at its pins — RDID, READ (several addresses, a
# wrap at the end, a stream across pages), FAST READ with dummy clocks, mode 3, deep power-down and the
# release, page program and sector erase — and, for every check the model makes, a sequence that breaks
# exactly it and must be reported as exactly that.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir flash-model)

run_to "$work/build.log" 300 g++ -std=c++17 -O2 -Wall -Wextra -Werror -Icosim/flash \
    tests/flash/spi_flash_test.cpp cosim/flash/spi_flash.cpp -o "$work/spi_flash_test"
expect_status 0 "building the flash model's test (log: $work/build.log)"
[ -s "$work/build.log" ] && fail "the build printed warnings or notes (log: $work/build.log)"
run_to "$work/out" 60 "$work/spi_flash_test" -v
expect_status 0 "the flash model's test (log: $work/out)"
last=$(tail -n 1 "$work/out")
[[ "$last" =~ ^spi_flash:\ ok\ ([0-9]+)\ cases$ ]] || fail "the last line is '$last', not 'spi_flash: ok N cases' (log: $work/out)"
pass "flash-model: the IS25LP128 model passes ${BASH_REMATCH[1]} cases: reads, programs and erases answered bit by bit at the pins, each timing, power-down, busy, write-enable and framing violation reported as itself"
