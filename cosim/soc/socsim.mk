# cosim/soc/socsim.mk — the SoC simulator, `make run PLATFORM=soc`, `make bench-soc` and the soc
# firmware builds; included by the top-level Makefile (paths relative to the repository root).
#
#   $(SOCSIM)      = $(BUILD)/socsim-<SOC_RAM_KIB>k[-w<SPAN_W>]/socsim: soc_top Verilated with
#                    RAM_BYTES = SOC_RAM_KIB KiB (the size the soc firmware is linked for,
#                    bsp/soc/soc_ram.mk) and the GPU's SPAN_W; the program is loaded at run time
#   run-soc        `make run PLATFORM=soc [SCENE=… FRAMES=…]`: the soc firmware of SCENE (a
#                  recursive make with FW_PLATFORM=soc) on socsim -> $(OUT)/frames, $(OUT)/uart.log
#   soc-fw         that firmware only; soc-fw-test: the FW_TEST_FRAMES builds of every scene
#   bench-soc      per scene: instructions, cycles, CPI, refills, GPU cycles, fps (tools/bench_soc.py)
#
# The RTL's sources come from soc_rtl/soc.mk (SOC_RTL_V, SOC_CPU_V) and gpu_rtl/files.f.

include bsp/soc/soc_ram.mk
-include soc_rtl/soc.mk

SOCSIM_DIR   := $(BUILD)/socsim-$(SOC_RAM_KIB)k$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W))
SOCSIM       := $(SOCSIM_DIR)/socsim
SOCSIM_SRC   := $(wildcard cosim/soc/*.cpp) cosim/model_check.cpp cosim/uart_terminal.cpp
SOCSIM_SV    := cosim/soc/socsim_taps.sv
SOCSIM_VLT   := cosim/soc/socsim.vlt
# soc firmware: the same sources as `make run`, built by a recursive make for FW_PLATFORM=soc.
SOC_FW_DIR   := $(BUILD)/firmware-soc
SOC_FW_ELF   := $(SOC_FW_DIR)/$(SCENE)$(if $(filter float,$(FW_BACKEND)),-float).elf
SOC_FW_MAKE   = $(MAKE) --no-print-directory FW_PLATFORM=soc BUILD=$(BUILD) SOC_RAM_KIB=$(SOC_RAM_KIB)

SOCSIM_DEPS := $(SOC_RTL_V) $(SOC_CPU_V) $(RTL_V) $(RTL_FILES) contract/gpu_regs.vh contract/soc_map.h \
               $(SOCSIM_SRC) $(SOCSIM_SV) $(SOCSIM_VLT) $(wildcard cosim/soc/*.h) cosim/model_check.h \
               $(COSIM_C_LIB) $(GPU_MODEL_LIB) cosim/soc/socsim.mk

$(SOCSIM): $(SOCSIM_DEPS)
	@test -n "$(SOC_RTL_V)" || { echo "socsim: soc_rtl/soc.mk (SOC_RTL_V) not found"; exit 1; }
	@mkdir -p $(SOCSIM_DIR)
	$(VERILATOR) --cc --exe --build -j 2 -O3 --x-assign fast --x-initial fast -Wno-fatal -Wno-lint -Wno-style \
	  --top-module soc_top -GRAM_BYTES=$(SOC_RAM_BYTES) -GSPAN_W=$(SPAN_W) \
	  $(SOCSIM_VLT) -f $(RTL_FILES) $(SOC_CPU_V) $(SOC_RTL_V) $(SOCSIM_SV) $(abspath $(SOCSIM_SRC)) \
	  -CFLAGS "-O2 -std=c++17 -ffunction-sections -DSOCSIM_SPAN_W=$(SPAN_W)u \
	           $(addprefix -I$(CURDIR)/,cosim cosim/soc gpu_model contract)" \
	  -LDFLAGS "-Wl,--gc-sections $(abspath $(COSIM_C_LIB) $(GPU_MODEL_LIB)) $$(pkg-config --libs libpng)" \
	  --MAKEFLAGS "OPT_FAST=-O2 OPT_SLOW=-O1" --Mdir $(SOCSIM_DIR)/obj -o $(abspath $(SOCSIM)) \
	  >$(SOCSIM_DIR)/verilator.log 2>&1 || { tail -40 $(SOCSIM_DIR)/verilator.log; exit 1; }

.PHONY: socsim run-soc soc-fw soc-fw-test bench-soc
socsim: $(SOCSIM)

soc-fw:
	@$(SOC_FW_MAKE) SCENE=$(SCENE) FRAMES=$(FRAMES) $(SOC_FW_ELF)

run-soc: $(SOCSIM) soc-fw
	@rm -rf $(OUT)/frames && mkdir -p $(OUT)/frames
	$(SOCSIM) --fw $(SOC_FW_ELF) --frames $(OUT)/frames --uart-log $(OUT)/uart.log
