#!/usr/bin/env bash
# The SoC with SDRAM on socsim (socsim-sdram: soc_top, LiteDRAM's generated controller, the chip
# model on its pins): tests/soc/sdram_test.c from the on-chip RAM — SYS SDRAM_BYTES, a load before the
# power-up sequence refused, the sequence, the quick memory test over the whole chip, the CPU's cycles
# a word, code run from the SDRAM; the chip model sees no violation. Then the same program on a chip
# whose address pin A11 is stuck low (socsim --sdram-fault-a 11): the memory test must name the
# address line, the program exit 1 with the LEDs showing it.
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

run_to "$work/fault.txt" 300 "$socsim" --hex "$hex" --frames "$work/frames-fault" --uart-log "$work/uart-fault.txt" \
    --summary "$work/summary-fault.txt" --sdram-fault-a 11
cat "$work/uart-fault.txt"
[ "$status" -eq 1 ] || fail "with A11 stuck low socsim ended with status $status, not the firmware's 1 (log: $work/fault.txt)"
expect_line '^memtest: address bus FAILED .*address bit 23' "$work/uart-fault.txt"
expect_line '^sdram_test: FAILED: the quick memory test' "$work/uart-fault.txt"
[ "$(summary leds "$work/summary-fault.txt")" = 0xe1 ] || fail "the LEDs after a failed memory test: $(summary leds "$work/summary-fault.txt"), not 0xe1"
pass "soc-sdram: $(grep -o 'quick ok.*' "$work/uart.txt" | head -c 80)...; $(grep -o 'store.*a word' "$work/uart.txt"); $refreshes refreshes, 0 violations; A11 stuck low caught as address bit 23"
