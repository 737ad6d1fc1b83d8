#!/usr/bin/env bash
# The SDRAM memory test's pure core (bsp/soc/sdram/memtest.c) on the host, against a fake memory with
# injected faults (tests/sdram/memtest_test.c): a good memory passes the quick and the full test; each
# data-bus, address-bus, byte-lane and cell fault is caught by the test meant for it at the first
# failing address (and address bit); the quick test misses a bad cell beyond its 256 KiB random fill,
# as documented; bad arguments are refused untouched; memtest_format() never overruns its buffer.
# Then memtest.c alone through the firmware's cross compiler, freestanding, with no undefined symbol:
# it must build for the SoC without a C library.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir sdram-memtest)
rv_cc=${RV_CC:-riscv64-unknown-elf-gcc}  # the firmware's cross compiler (soc_rtl/soc.mk's RV_CC)
command -v "$rv_cc" >/dev/null || fail "no $rv_cc on the PATH: the freestanding build of bsp/soc/sdram/memtest.c needs the firmware's cross compiler (tools/setup.sh installs it)"

run_to "$work/build.log" 120 gcc -std=c11 -O2 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
    -Ibsp/soc/sdram tests/sdram/memtest_test.c -o "$work/memtest_test"
expect_status 0 "building the memory test's host test (log: $work/build.log)"

run_to "$work/rv32.log" 120 "$rv_cc" -march=rv32im -mabi=ilp32 -O2 -std=c11 -Wall -Wextra -Werror -ffreestanding \
    -c bsp/soc/sdram/memtest.c -o "$work/memtest.rv32.o"
expect_status 0 "compiling bsp/soc/sdram/memtest.c for rv32im, freestanding (log: $work/rv32.log)"
undefined=$("${rv_cc%gcc}nm" -u "$work/memtest.rv32.o")
[ -z "$undefined" ] || fail "memtest.rv32.o needs symbols from outside (a library call crept in): $undefined"

run_to "$work/out" 60 "$work/memtest_test" -v
expect_status 0 "the memory test's host test (log: $work/out)"
last=$(tail -n 1 "$work/out")
[[ "$last" =~ ^memtest_test:\ ok\ ([0-9]+)\ cases$ ]] || fail "the last line is '$last', not 'memtest_test: ok N cases' (log: $work/out)"
pass "sdram-memtest: the memory test passes ${BASH_REMATCH[1]} cases: a good memory passes, each injected bus, byte-lane and cell fault is caught by its own test at its first failing address; memtest.c builds freestanding for rv32im"
