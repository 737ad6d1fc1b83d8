# The SoC in RTL (soc_rtl/): the CPU core from the project's venv, lint, synthesis and the smoke test.
# Included by the top-level Makefile. Targets: lint-soc, synth-soc; the smoke program's image
# $(SOC_SMOKE_HEX), which `make soc-smoke` runs on socsim (cosim/soc/socsim.mk).

# The core: VexRiscv_FullCfu.v of the pinned pythondata-cpu-vexriscv (tools/requirements.txt), found
# through the package in .venv/ (tools/setup.sh makes it). Deferred (=): evaluated in the recipes,
# after $(SOC_VENV) has been brought up to date.
SOC_VENV      := .venv/.requirements.sha256
SOC_CPU_V      = $(shell .venv/bin/python -c 'import os, pythondata_cpu_vexriscv as p; print(os.path.join(p.data_location, "VexRiscv_FullCfu.v"))')
SOC_FILES     := soc_rtl/files.f
SOC_RTL_V     := $(shell sed -e 's://.*::' $(SOC_FILES))
# The headers its systems include (the SDRAM's and the GPU frames' port bundles, the no-SDRAM ties).
SOC_RTL_VH    := $(wildcard soc_rtl/*.vh)
SOC_LINT      := soc_rtl/lint.vlt soc_rtl/usb/lint.vlt
# Everything under soc_top, in compilation order: the GPU's list, the core, the SoC's list.
SOC_VFLAGS     = $(RTL_LINT) $(SOC_LINT) -f $(RTL_FILES) $(SOC_CPU_V) -f $(SOC_FILES)
# The simulator (socsim) runs soc_top at the contract's default clock and tie
# the GPU's scan-out clock to it; a board gives a separate 25 MHz one (boards/).
SOC_SIM_CLK_HZ := $(shell sed -n 's/^clk_hz_default *= *\([0-9]*\).*/\1/p' contract/soc_map.toml)
SOC_SIM_TIED   := -GPIX_CLK_HZ=$(SOC_SIM_CLK_HZ)

$(SOC_VENV): tools/requirements.txt
	@bash tools/setup.sh
	@touch $@

.PHONY: lint-soc synth-soc

# files.f is the one list: a soc_rtl source left out of it is refused, as in `make lint`.
SOC_UNLISTED = $(filter-out $(SOC_RTL_V),$(wildcard soc_rtl/*.v soc_rtl/*.sv soc_rtl/usb/*.v soc_rtl/usb/*.sv))
lint-soc: $(SOC_VENV)
	@test -z "$(SOC_UNLISTED)" || { echo "lint-soc: not in $(SOC_FILES): $(SOC_UNLISTED)"; exit 1; }
	$(Q)$(call say,LINT,soc_top)$(VERILATOR) --lint-only -Wall --top-module soc_top $(SOC_VFLAGS)
	@echo "lint-soc: $(words $(SOC_RTL_V)) files of $(SOC_FILES) clean under -Wall (with the GPU and $(notdir $(SOC_CPU_V)))"

# yosys synth_ecp5 of soc_top: LUT4, FF, EBR per memory, MULT18X18D (installs yosys). ZBUF=1
# [ZBUF_BITS=B]: with the GPU's depth buffer, keeping B bits (default 16).
synth-soc: $(SOC_VENV)
	@bash tools/setup.sh packages-synth.txt
	@ZBUF=$(ZBUF) $(if $(ZBUF_BITS),ZBUF_BITS=$(ZBUF_BITS)) SOC_CPU_V=$(SOC_CPU_V) bash synth/synth_soc.sh $(BUILD)

# ---- the smoke test: a bare-metal program on the Verilated soc_top (socsim, a RAM image) ----
SOC_SMOKE_ELF  := $(BUILD)/soc/smoke.elf
SOC_SMOKE_HEX  := $(BUILD)/soc/smoke.hex
RV_CC          ?= riscv64-unknown-elf-gcc
# Flags the SoC's firmware needs (docs: /work/shared PLATFORM-NOTES): RV32IM, CSR instructions.
SOC_RV_FLAGS   := -march=rv32im -misa-spec=2.2 -mabi=ilp32 -mcmodel=medany
SOC_SMOKE_SRC  := tests/soc/smoke_crt0.S tests/soc/smoke.c

$(SOC_SMOKE_ELF): $(SOC_SMOKE_SRC) tests/soc/smoke.ld contract/soc_map.h contract/gpu_regs.h
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(RV_CC) $(SOC_RV_FLAGS) -Os -g -ffreestanding -nostdlib -nostartfiles -Wall -Wextra -Werror \
	  -Icontract -T tests/soc/smoke.ld -Wl,--no-warn-rwx-segments $(SOC_SMOKE_SRC) -o $@

$(SOC_SMOKE_HEX): $(SOC_SMOKE_ELF) bsp/soc/elf_to_hex.py
	$(Q)$(call say,GEN,$@)$(PYTHON) bsp/soc/elf_to_hex.py $< $@
