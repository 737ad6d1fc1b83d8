#!/usr/bin/env bash
# The watchdog's bound on the SoC: tests/soc/poll_cycles.c times the GPU driver's DONE_SEQ polling
# (gpu_wait, one uncached bus read and the loop per poll) with mcycle. The soc platform's default
# FW_MAX_POLLS (bsp/soc/bsp.mk) must then be about one second at 50 MHz: between 0.5 and 2 s.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test poll_cycles soc-poll-cycles

run_socsim 60 --max-cycles 5e6
cat "$work/out"
expect_status 0 "socsim"
line=$(grep '^poll_cycles: ' "$work/uart.log") || fail "no poll_cycles line"
per_poll=$(echo "$line" | sed -n 's/.*: \([0-9.]*\) cycles per poll.*/\1/p')
polls=$(sed -n 's/^FW_MAX_POLLS := //p' bsp/soc/bsp.mk)
clk=$(sed -n 's/^#define SOC_CLK_HZ_DEFAULT *\([0-9]*\)u.*/\1/p' contract/soc_map.h)
ms=$(awk -v n="$polls" -v c="$per_poll" -v f="$clk" 'BEGIN { printf "%d", n * c / f * 1000 }')
[ "$ms" -ge 500 ] && [ "$ms" -le 2000 ] ||
    fail "FW_MAX_POLLS=$polls at $per_poll cycles per poll is $ms ms at $clk Hz, not about a second"
pass "soc-poll-cycles: $per_poll cycles per DONE_SEQ poll; FW_MAX_POLLS $polls = $ms ms at 50 MHz"
