# The SoC in RTL (soc_rtl/): the CPU core from the project's venv, lint, synthesis and the smoke test.
# Included by the top-level Makefile. Targets: lint-soc, synth-soc, soc-smoke; the simulator
# $(SOC_SIM) and the smoke program's image $(SOC_SMOKE_HEX).

# The core: VexRiscv_Full.v of the pinned pythondata-cpu-vexriscv (tools/requirements.txt), found
# through the package in .venv/ (tools/setup.sh makes it). Deferred (=): evaluated in the recipes,
# after $(SOC_VENV) has been brought up to date.
SOC_VENV      := .venv/.requirements.sha256
SOC_CPU_V      = $(shell .venv/bin/python -c 'import os, pythondata_cpu_vexriscv as p; print(os.path.join(p.data_location, "VexRiscv_Full.v"))')
SOC_FILES     := soc_rtl/files.f
SOC_RTL_V     := $(shell sed -e 's://.*::' $(SOC_FILES))
SOC_LINT      := soc_rtl/lint.vlt
# Everything under soc_top, in compilation order: the GPU's list, the core, the SoC's list.
SOC_VFLAGS     = $(RTL_LINT) $(SOC_LINT) -f $(RTL_FILES) $(SOC_CPU_V) -f $(SOC_FILES)
# The simulators (the smoke testbench, socsim) run soc_top at the contract's default clock and tie
# the GPU's scan-out clock to it; a board gives a separate 25 MHz one (boards/).
SOC_SIM_CLK_HZ := $(shell sed -n 's/^clk_hz_default *= *\([0-9]*\).*/\1/p' contract/soc_map.toml)
SOC_SIM_TIED   := -GPIX_CLK_HZ=$(SOC_SIM_CLK_HZ)

$(SOC_VENV): tools/requirements.txt
	@bash tools/setup.sh
	@touch $@

.PHONY: lint-soc synth-soc soc-smoke

# files.f is the one list: a soc_rtl source left out of it is refused, as in `make lint`.
SOC_UNLISTED = $(filter-out $(SOC_RTL_V),$(wildcard soc_rtl/*.v soc_rtl/*.sv))
lint-soc: $(SOC_VENV)
	@test -z "$(SOC_UNLISTED)" || { echo "lint-soc: not in $(SOC_FILES): $(SOC_UNLISTED)"; exit 1; }
	$(VERILATOR) --lint-only -Wall --top-module soc_top $(SOC_VFLAGS)
	@echo "lint-soc: $(words $(SOC_RTL_V)) files of $(SOC_FILES) clean under -Wall (with the GPU and $(notdir $(SOC_CPU_V)))"

# yosys synth_ecp5 of soc_top: LUT4, FF, EBR per memory, MULT18X18D (installs yosys).
synth-soc: $(SOC_VENV)
	@bash tools/setup.sh packages-synth.txt
	@SOC_CPU_V=$(SOC_CPU_V) bash synth/synth_soc.sh $(BUILD)

# ---- the smoke test: a bare-metal program on the Verilated soc_top ----
SOC_SIM        := $(BUILD)/soc/sim/soc_sim
SOC_SMOKE_ELF  := $(BUILD)/soc/smoke.elf
SOC_SMOKE_HEX  := $(BUILD)/soc/smoke.hex
# The testbench and the UART line codec it shares with socsim (cosim/soc/uart_line).
SOC_TB_CPP     := tests/soc/soc_tb.cpp cosim/soc/uart_line.cpp
RV_CC          ?= riscv64-unknown-elf-gcc
# Flags the SoC's firmware needs (docs: /work/shared PLATFORM-NOTES): RV32IM, CSR instructions.
SOC_RV_FLAGS   := -march=rv32im -misa-spec=2.2 -mabi=ilp32 -mcmodel=medany
SOC_SMOKE_SRC  := tests/soc/smoke_crt0.S tests/soc/smoke.c

$(SOC_SMOKE_ELF): $(SOC_SMOKE_SRC) tests/soc/smoke.ld contract/soc_map.h contract/gpu_regs.h
	@mkdir -p $(dir $@)
	$(RV_CC) $(SOC_RV_FLAGS) -Os -g -ffreestanding -nostdlib -nostartfiles -Wall -Wextra -Werror \
	  -Icontract -T tests/soc/smoke.ld -Wl,--no-warn-rwx-segments $(SOC_SMOKE_SRC) -o $@

$(SOC_SMOKE_HEX): $(SOC_SMOKE_ELF) tools/elf_to_hex.py
	$(PYTHON) tools/elf_to_hex.py $< $@

# One model runs any program: the RAM image is loaded at run time (+ram_init=FILE).
$(SOC_SIM): $(SOC_VENV) $(RTL_FILES) $(RTL_V) $(SOC_FILES) $(SOC_RTL_V) $(SOC_LINT) contract/gpu_regs.vh \
            contract/soc_map.vh contract/soc_map.h $(SOC_TB_CPP) cosim/soc/uart_line.h
	@mkdir -p $(dir $@)
	$(VERILATOR) --cc --exe --build -j $(VERILATOR_JOBS) -O3 --x-assign fast --x-initial fast \
	  --top-module soc_top $(SOC_SIM_TIED) $(SOC_VFLAGS) $(abspath $(SOC_TB_CPP)) \
	  -CFLAGS "-O2 -std=c++17 -I$(CURDIR)/contract -I$(CURDIR)/cosim/soc" \
	  --MAKEFLAGS "OPT_FAST=-O2 OPT_SLOW=-O1" --Mdir $(dir $@)obj -o $(abspath $@) \
	  >$(dir $@)verilator.log 2>&1 || { tail -40 $(dir $@)verilator.log; exit 1; }

soc-smoke: $(SOC_SIM) $(SOC_SMOKE_HEX)
	@BUILD=$(BUILD) SOC_SIM=$(SOC_SIM) SOC_SMOKE_HEX=$(SOC_SMOKE_HEX) bash tests/soc/smoke.sh

# make test's suite rtl-soc-smoke runs the smoke program: built in make test's build phase.
test-quick: $(SOC_SIM) $(SOC_SMOKE_HEX)
