#!/usr/bin/env bash
# The SoC with SDRAM on socsim (socsim-sdram: soc_top, LiteDRAM's generated controller, the chip
# model on its pins): tests/soc/sdram_test.c from the on-chip RAM — SYS SDRAM_BYTES, a load before the
# power-up sequence refused, the sequence, the quick memory test over the whole chip, the CPU's cycles
# a word, code run from the SDRAM; the chip model sees no violation. Then the memory test program,
# and the same on a chip whose address pin A2 is stuck low (socsim --sdram-fault-a 2): it must name
# the address line and exit with 0xE1 on the LEDs. (The boot program's own faults: boot_faults.sh.)
#   usage: sdram.sh SOCSIM_SDRAM   (the suite passes {socsim-sdram-<RAM>k})
source "$(dirname "$0")/../lib.sh"
need BUILD
socsim=${1:?usage: sdram.sh SOCSIM_SDRAM}
hex="$BUILD/soc/sdram_test.elf.hex"
need_file "$socsim" "$hex"
work=$(fresh_dir soc-sdram)

run_to "$work/out.txt" 300 "$socsim" --hex "$hex" --frames "$work/frames" --uart-log "$work/uart.txt" \
    --summary "$work/summary.txt"
cat "$work/uart.txt"
expect_status 0 "socsim with SDRAM (log: $work/out.txt)"
expect_line '^sdram_test: ok' "$work/uart.txt"
expect_line '^memtest: quick ok' "$work/uart.txt"
expect_eq "$(summary sdram_violations "$work/summary.txt")" 0 "chip model violations"
expect_eq "$(summary sdram_init_done "$work/summary.txt")" 1 "LiteDRAM's init_done"
refreshes=$(summary sdram_refreshes "$work/summary.txt")
[ "$refreshes" -gt 0 ] || fail "no refresh reached the chip"

# The memory test program (bsp/soc/boot/memtest_main.c; socsim's build: one full pass over 16 KiB):
# the CPU's bandwidth, a full pass; then on a chip whose address pin A2 is stuck low it must name a
# bit that pin carries, show 0xE1 and exit with it. A2 is column bit 2 (byte-address bit 3) and row
# bit 2 (byte-address bit 12: rows above 9 column bits and the 16-bit word's byte bit); both are
# inside the 16 KiB, and which the address test meets first depends on what its write-through data
# cache still holds of the first line (a hit there hides the column alias; the row alias misses).
memtest="$BUILD/soc/memtest.elf.hex"
need_file "$memtest"
run_to "$work/memtest.txt" 300 "$socsim" --hex "$memtest" --frames "$work/frames-memtest" --uart-log "$work/uart-memtest.txt" \
    --summary "$work/summary-memtest.txt"
cat "$work/uart-memtest.txt"
expect_status 0 "the memory test program (log: $work/memtest.txt)"
expect_line '^memtest: CPU stores, one word each: [0-9.]+ cycles a word \([0-9.]+ MB/s\)$' "$work/uart-memtest.txt"
expect_line '^memtest: CPU loads, 8-word line refills: [0-9.]+ cycles a word \([0-9.]+ MB/s\)$' "$work/uart-memtest.txt"
expect_line '^pass 1: memtest: full ok \(16 KiB at 0x40000000, 5 tests' "$work/uart-memtest.txt"
expect_eq "$(summary sdram_violations "$work/summary-memtest.txt")" 0 "chip model violations (memory test program)"

run_to "$work/fault.txt" 300 "$socsim" --hex "$memtest" --frames "$work/frames-fault" --uart-log "$work/uart-fault.txt" \
    --summary "$work/summary-fault.txt" --sdram-fault-a 2
cat "$work/uart-fault.txt"
[ "$status" -eq 225 ] || fail "with A2 stuck low socsim ended with status $status, not the program's 0xE1 (log: $work/fault.txt)"
expect_line '^pass 1: memtest: address bus FAILED .*address bit (3|12) stuck' "$work/uart-fault.txt"
bit=$(sed -n 's/^pass 1: memtest: address bus FAILED .*address bit \([0-9]*\) stuck.*/\1/p' "$work/uart-fault.txt")
[ "$(summary leds "$work/summary-fault.txt")" = 0xe1 ] || fail "the LEDs after a failed memory test: $(summary leds "$work/summary-fault.txt"), not 0xe1"
pass "soc-sdram: $(grep -o 'quick ok.*' "$work/uart.txt" | head -c 80)...; $refreshes refreshes, 0 violations; the memory test program: $(grep -o 'stores.*' "$work/uart-memtest.txt" | head -c 60), $(grep -o 'loads.*' "$work/uart-memtest.txt" | head -c 60), a full pass; A2 stuck low caught as address bit $bit"
