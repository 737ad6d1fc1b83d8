#!/usr/bin/env bash
# The SoC smoke test: tests/soc/smoke.c on the Verilated soc_top (socsim, cosim/soc/socsim.cpp, its
# RAM image loaded at run time with --hex). Checks the UART text decoded at the real baud rate, every
# "ok" line (registers, the GPU's ID, bus errors of each kind, timer, UART receive, overrun and
# framing error), the three prompts answered, no failure line, a VGA frame, the LEDs and SYS
# EXIT = 0. `make soc-smoke` builds both and runs it (with SOCSIM, SOC_SMOKE_HEX and BUILD set).
source "$(dirname "$0")/../lib.sh"
need SOCSIM SOC_SMOKE_HEX
need_file "$SOCSIM" "$SOC_SMOKE_HEX"
work=$(fresh_dir soc-smoke)

# The overrun burst (smoke.c's RX_BURST): the RX FIFO's depth from the contract and 4 bytes more,
# 'A' + i % 26 for byte i. At the real baud rate it is ~4,340 clocks a byte (~9 M clocks at depth
# 2048), most of the run: the line runs at the RTL's DIVIDER, as on a board.
depth=$(sed -n 's/^#define SOC_UART_RX_FIFO_DEPTH *\([0-9]*\)u.*/\1/p' contract/soc_map.h)
[ -n "$depth" ] || fail "no SOC_UART_RX_FIFO_DEPTH in contract/soc_map.h"
burst=$(awk -v n=$((depth + 4)) 'BEGIN { for (i = 0; i < n; i++) printf "%c", 65 + i % 26 }')

run_to "$work/out.txt" 240 "$SOCSIM" --hex "$SOC_SMOKE_HEX" --frames "$work/frames" --uart-log "$work/uart.txt" \
    --summary "$work/summary.txt" --max-cycles 30e6 --reply 'rx?\n=Z' --reply "burst?\\n=$burst" --reply 'break?\n=\f'
cat "$work/out.txt"
expect_status 0 "socsim (its status is the SoC's exit code; 1: a harness error or no exit in time)"
expect_no_line '^soc: FAIL' "$work/uart.txt"
for line in '^soc: hello$' '^soc: id 534f4330 clk 50000000 ram 196608 div 434$' '^soc: gpu id 47505530$' \
            '^soc: load fault ok' '^soc: store fault ok' '^soc: refill fault ok \(addr 00030000, 8 refused\)' \
            '^soc: SYS hole ok' '^soc: GPU byte store ok' '^soc: fetch fault ok' '^soc: timer ok$' '^soc: rx Z ok$' \
            '^soc: rx overrun ok \(4 dropped\)$' '^soc: rx framing ok$' '^soc: done$'; do
    expect_line "$line" "$work/uart.txt"
done
expect_eq "$(summary exit_valid "$work/summary.txt")" 1 "exit_valid"
expect_eq "$(summary firmware_status "$work/summary.txt")" 0 "SYS EXIT code in the summary"
expect_eq "$(summary uart_replies "$work/summary.txt")" 3 "prompts answered (rx?, burst?, break?)"
expect_eq "$(summary uart_framing_errors "$work/summary.txt")" 0 "UART framing errors seen by socsim's receiver"
[ "$(summary vga_vsyncs "$work/summary.txt")" -ge 1 ] || fail "no VGA vertical sync from the GPU"
[ "$(summary leds "$work/summary.txt")" = 0xa5 ] || fail "leds: $(summary leds "$work/summary.txt"), expected 0xa5"
pass "soc smoke: $(grep -c ' ok' "$work/uart.txt") checks ok, exit 0 after $(summary cycles "$work/summary.txt") cycles" \
     "($(grep -o '[0-9.]* M cycles/s$' "$work/out.txt"))"
