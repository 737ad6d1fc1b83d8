#!/usr/bin/env bash
# A bus error on the SoC: tests/soc/bus_error.c loads from 0x90000000, which no device decodes. The
# bus answers ERR, soc_top records it (SYS BUS_ERR/BUS_ERR_ADDR) and raises the bus-error interrupt;
# the soc BSP's trap handler must name it with the address and end the run with BSP_EXIT_TRAP (126).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test bus_error soc-bus-error

run_socsim 60 --summary "$work/summary" --max-cycles 5e6
cat "$work/out"
expect_status 126 "socsim (BSP_EXIT_TRAP)"
expect_line '^bus_error: loading from 0x90000000' "$work/uart.log"
expect_line '^TRAP: mcause=0x8000000b mepc=0x[0-9a-f]{8} mtval=0x[0-9a-f]{8} \(bus error: load at 0x90000000\)$' \
    "$work/uart.log"
expect_no_line 'no trap after the load' "$work/uart.log"
expect_eq "$(summary firmware_status "$work/summary")" 126 "firmware status in the summary"
pass "soc-bus-error: $(grep -o 'bus error: load at 0x[0-9a-f]*' "$work/uart.log"), exit status 126"
