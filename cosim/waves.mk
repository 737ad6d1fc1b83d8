# cosim/waves.mk — `make waves`: an FST trace of one frame, with a GTKWave save file that opens on
# the GPU's (or the SoC's) interesting signals; included by the top-level Makefile.
#
#   $(GPUSIM_TRACE)   = $(BUILD)/sim-trace-w<SPAN_W>/gpusim: the pin path's simulator built with
#                       Verilator's --trace-fst and -DGPUSIM_TRACE=1 (GpuSim::trace_open, cosim
#                       --trace FILE --trace-frame N); sim-fast-trace-w<SPAN_W> the fast path's
#   $(SOCSIM_TRACE)   = $(BUILD)/socsim-trace-<SOC_RAM_KIB>k[-w<SPAN_W>]/socsim: socsim's, with
#                       -DSOCSIM_TRACE=1 (socsim --trace FILE --trace-frame N)
#   waves             `make waves [SCENE=… FRAME=N] [PLATFORM=soc | FAST=1]`: frame N (from 0,
#                     default 1) of SCENE traced on co-simulation's pin path, on socsim
#                     (PLATFORM=soc) or on co-simulation's fast display path (FAST=1: no scan-out)
#                     -> $(OUT)/waves/<scene>[-soc|-fast]-frame<N>.fst and a .gtkw beside it
#
# Tracing costs speed, so these builds have folders of their own; `make test` builds the pin path's
# for its suite cosim-waves (tests/cosim/waves.sh).

GPUSIM_TRACE      := $(BUILD)/sim-trace-w$(SPAN_W)/gpusim
GPUSIM_FAST_TRACE := $(BUILD)/sim-fast-trace-w$(SPAN_W)/gpusim

# (Both are simulators of mk/builds.toml: trace = true.)

# The SoC's: socsim's build (socsim.mk's socsim_cmd) with --trace-fst and -DSOCSIM_TRACE=1.
SOCSIM_TRACE_DIR := $(BUILD)/socsim-trace-$(SOC_RAM_KIB)k$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W))
SOCSIM_TRACE     := $(SOCSIM_TRACE_DIR)/socsim
SOCSIM_TRACE_CMD  = $(call socsim_cmd,$(SOCSIM_TRACE_DIR),$(SOCSIM_SYSTEM_soc) --trace-fst,$(SOC_RAM_BYTES),\
  $(SOCSIM_GPU_FLAGS),,-DSOCSIM_TRACE=1)
$(call socsim_rules_unless_listed,$(SOCSIM_TRACE_DIR),SOCSIM_TRACE_CMD,)

# The firmware: SCENE with FRAME + 1 frames, so the run ends soon after the traced frame (frames
# count from 0), under $(BUILD)/fw-waves[-soc]: the FRAMES builds of `make run` stay as they are.
FRAME          ?= 1
WAVES_FRAMES   := $(shell expr $(FRAME) + 1 2>/dev/null)
waves_fw        = $(BUILD)/fw-waves$(1)/$(call fw_name,$(SCENE),$(FW_BACKEND))-$(WAVES_FRAMES)f.elf
WAVES_FW_ELF    = $(call waves_fw,$(FW_PSUFFIX))
WAVES_SOC_FW_ELF = $(call waves_fw,-soc)
ifneq ($(WAVES_FRAMES),)
$(eval $(call FW_ELF_RULES,$(WAVES_FW_ELF),$(SCENE),$(FW_BACKEND),$(WAVES_FRAMES),$(FW_MAX_POLLS)))
endif

# The run: $(OUT)/waves/<scene>[-soc|-fast]-frame<N>.fst, its frames and UART log beside it, and a copy of
# the save file whose [dumpfile] is that trace.
WAVES_DIR  := $(OUT)/waves
WAVES_KIND  = $(if $(filter soc,$(PLATFORM)),soc,$(if $(FAST),fast,gpu))
WAVES_NAME  = $(SCENE)$(patsubst -gpu,,-$(WAVES_KIND))-frame$(FRAME)
WAVES_FST   = $(WAVES_DIR)/$(WAVES_NAME).fst
WAVES_GTKW  = $(if $(FAST),$(WAVES_DIR)/gpu-fast.gtkw,cosim/waves/$(WAVES_KIND).gtkw)
# The fast path's save file, from gpu.gtkw: gpu_core is the top, there is no gpu_vga.
WAVES_FAST_SED := -e '/TOP\.gpu_top\.\(u_vga\.\|vga_\)/d' -e '/^-Scan-out/d' \
  -e 's/TOP\.gpu_top\.vblank_start_sys/TOP.gpu_core.vblank_start/' -e 's/TOP\.gpu_top\.\(u_core\.\)\{0,1\}/TOP.gpu_core./'
WAVES_RUN   = @rm -rf $(WAVES_FST) $(WAVES_DIR)/$(WAVES_NAME)-frames && mkdir -p $(WAVES_DIR)/$(WAVES_NAME)-frames
define WAVES_DONE
	@sed -e 's|^\[dumpfile\] .*|[dumpfile] "$(abspath $(WAVES_FST))"|' $(WAVES_GTKW) >$(WAVES_DIR)/$(WAVES_NAME).gtkw
	@echo "waves: $(WAVES_FST) ($$(du -h $(WAVES_FST) | cut -f1)); open it with"
	@echo "  gtkwave $(WAVES_FST) $(WAVES_GTKW)"
endef

.PHONY: waves waves-gpu waves-soc socsim-trace
waves:
	@expr "$(FRAME)" : '[0-9][0-9]*$$' >/dev/null || { echo "waves: FRAME=N, a frame number from 0"; exit 2; }
	@bash tools/setup.sh
	@$(MAKE) --no-print-directory waves-$(if $(filter soc,$(PLATFORM)),soc,gpu)

waves-gpu: $(if $(FAST),$(GPUSIM_FAST_TRACE),$(GPUSIM_TRACE)) $(WAVES_FW_ELF)
	$(WAVES_RUN)
	$(if $(FAST),@sed $(WAVES_FAST_SED) cosim/waves/gpu.gtkw >$(WAVES_GTKW))
	$(Q)$(call say,TRACE,$(WAVES_FST))$(if $(FAST),$(GPUSIM_FAST_TRACE),$(GPUSIM_TRACE)) cosim --fw $(WAVES_FW_ELF) --frames $(WAVES_DIR)/$(WAVES_NAME)-frames \
	  --uart-log $(WAVES_DIR)/$(WAVES_NAME)-uart.log --trace $(WAVES_FST) --trace-frame $(FRAME)
	$(WAVES_DONE)

socsim-trace: $(SOCSIM_TRACE)

waves-soc: $(SOCSIM_TRACE)
	+@$(SOC_FW_MAKE) SCENE=$(SCENE) FRAME=$(FRAME) FW_BACKEND=$(FW_BACKEND) $(WAVES_SOC_FW_ELF)
	$(WAVES_RUN)
	$(Q)$(call say,TRACE,$(WAVES_FST))$(SOCSIM_TRACE) --fw $(WAVES_SOC_FW_ELF) --frames $(WAVES_DIR)/$(WAVES_NAME)-frames \
	  --uart-log $(WAVES_DIR)/$(WAVES_NAME)-uart.log --trace $(WAVES_FST) --trace-frame $(FRAME)
	$(WAVES_DONE)
