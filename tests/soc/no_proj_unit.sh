#!/usr/bin/env bash
# A SoC built without its projection unit (soc_top PROJ_UNIT = 0, the small parts' board build):
# its custom-function port answers every instruction with all ones, so a program built for the
# unit (every bsp/soc program by default) finds it missing at start-up and stops with its error
# and FW_EXIT_CONFIG (1) instead of drawing every vertex wrong; a program that uses no custom
# instruction (the pipeline timings) runs as on the SoC with the unit.
#     no_proj_unit.sh SOCSIM      (SOCSIM: mk/builds.toml's socsim-nopu)
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
socsim="$1"
soc_test tetra soc-no-proj-unit

run_socsim 60 --summary "$work/summary" --max-cycles 20e6
expect_status 1 "socsim (the firmware's FW_EXIT_CONFIG)"
expect_line "^error: this program projects its vertices with the SoC's projection unit, and this SoC has none \\(soc_top PROJ_UNIT = 0\\): build it with FW_DEFS=-DFW_PROJ_UNIT=0$" "$work/uart.log"
expect_eq "$(count '^frame ' "$work/uart.log")" 0 "frames drawn"

elf="$soc_test_dir/pipeline_cycles.elf"
need_file "$elf.hex"
run_to "$work/out-plain" 60 "$socsim" --fw "$elf" --uart-log "$work/uart-plain.log" --max-cycles 1e7
expect_status 0 "socsim (a program without custom instructions)"
expect_line 'pipeline: done' "$work/uart-plain.log"
pass "soc-no-proj-unit: tetra built for the unit stops with its error (exit 1, no frame); a program without custom instructions runs"
