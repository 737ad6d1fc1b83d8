# mk/manifest.mk — scene manifests: `make run SCENE=x`, `make run PLATFORM=soc SCENE=x` and
# `make bitstream SCENE=x` build what firmware/scenes/x.manifest.toml says the scene needs (the
# firmware's switches, the GPU's parameters and the RAM from that one file, mk/manifest.py);
# FULL=1 builds the default, every feature, as before. Included by the top-level Makefile before
# every other fragment (the manifest's values must be in place when they read SPAN_W, FW_DEFS ...).
#
# A manifest build happens where all of these hold:
#   - SCENE is given on the command line (the default scene without it is the full build),
#   - FULL is not 1,
#   - the scene has a manifest (every scene of the table has one; the model scene's also sets its
#     capacities and the UART upload, so `make run SCENE=model MODEL=x` simplifies x to them,
#     while `make run MODEL=x` without SCENE is the full build),
#   - a goal is one of MANIFEST_GOALS: what runs or builds one scene (make test, fw-size, bench-*,
#     board-fit, fw-all ... keep their own builds whatever SCENE says).
# The decision is exported as LEAN_SCENE, so that the recursive makes (run -> run-built, soc-fw,
# board-fw) build the same. Its outputs have their own folders, so nothing make test uses is
# rebuilt differently: firmware under $(LEAN_ROOT)/<scene>/ (firmware/, firmware-soc/, board-fw/,
# board-ulx3s/), the SoC's RAM sized to the linked image (SOC_RAM_KIB=auto, bsp/soc/soc_ram.mk);
# simulators per parameter set: the default ones where the manifest's GPU is the
# default (SPAN_W aside), else $(BUILD)/sim-cfg-w<N>-<tag>/, sim-fast-cfg-w<N>-<tag>/ and
# socsim-<RAM>k-w<N>-<tag>/ (tag: z1 depth buffer, l0 no lines, m0 no framebuffer write mask: a scene
# without the anaglyph, v<N> t<N> capacities, g1 Gouraud, f<width> the largest frame), shared by
# every scene with that set.
#
#   manifest-show [SCENE=x] [FULL=1]   what such a build uses: its ELFs, simulators, RTL parameters
#   manifest-check                      every manifest valid (mk/manifest.py --check)
#   lean-report                         full against lean per scene (bench/lean_report.py)
FULL       ?=
LEAN_ROOT  ?= $(BUILD)/lean
MANIFEST_GOALS := run run-built run-soc soc-fw fw bitstream synth-board board-fw flash load \
                  ulx3s-dir socsim manifest-show

ifeq ($(origin LEAN_SCENE),undefined)
ifneq ($(and $(filter command line,$(origin SCENE)),$(if $(filter 1,$(FULL)),,1),\
             $(wildcard firmware/scenes/$(SCENE).manifest.toml),$(filter $(MANIFEST_GOALS),$(MAKECMDGOALS))),)
LEAN_SCENE := $(SCENE)
endif
endif

ifneq ($(LEAN_SCENE),)
export LEAN_SCENE
ifneq ($(LEAN_SCENE),$(SCENE))
$(error manifest build of $(LEAN_SCENE), but SCENE=$(SCENE))
endif
MANIFEST_MK := $(BUILD)/manifest/$(LEAN_SCENE).mk
include $(MANIFEST_MK)
LEAN_DIR    := $(LEAN_ROOT)/$(LEAN_SCENE)
# The SoC's RAM: what the linked image needs (bsp/soc/soc_ram.mk), unless the command line says.
SOC_RAM_KIB ?= auto
# GOURAUD=1: the manifest's GPU with Gouraud triangles too (tag g1), for the scenes that carry
# vertex normals (the firmware's FW_WITH_GOURAUD is on in every build unless FW_DEFS says not).
ifeq ($(GOURAUD),1)
MANIFEST_GPU_TAG    := $(if $(MANIFEST_GPU_TAG),$(MANIFEST_GPU_TAG)-g1,g1)
MANIFEST_GPU_GFLAGS := $(strip $(MANIFEST_GPU_GFLAGS) -GENABLE_GOURAUD=1)
endif
# FB=<the contract's largest frame> (the Makefile's FB_TAG): the manifest's GPU built for it (tag
# f<width>).
ifneq ($(FB_TAG),)
MANIFEST_GPU_TAG    := $(if $(MANIFEST_GPU_TAG),$(MANIFEST_GPU_TAG)-$(FB_TAG),$(FB_TAG))
MANIFEST_GPU_GFLAGS := $(strip $(MANIFEST_GPU_GFLAGS) $(FB_GFLAGS))
endif
MANIFEST_SIM_NAME := $(if $(MANIFEST_GPU_TAG),cfg-w$(SPAN_W)-$(MANIFEST_GPU_TAG),w$(SPAN_W))
# Firmware: firmware.mk's FW_DIR (QEMU and soc platforms), socsim.mk's run-soc ELF, board.mk's.
override FW_DIR        = $(LEAN_DIR)/firmware$(FW_PSUFFIX)$(SOC_MEM_SUFFIX)
override SOC_FW_DIR    = $(LEAN_DIR)/firmware-soc$(SOC_MEM_SUFFIX)
override ULX3S_FW_ELF  = $(LEAN_DIR)/board-fw/$(SCENE).elf
override ULX3S_DIR     = $(LEAN_DIR)/board-ulx3s/$(ULX3S_NAME)$(if $(MANIFEST_GPU_TAG),-$(MANIFEST_GPU_TAG))
# The GPU: the co-simulators, socsim (its -G flags after -GSPAN_W) and the board's --param list.
override GPUSIM       := $(BUILD)/sim-$(MANIFEST_SIM_NAME)/gpusim
override GPUSIM_FAST  := $(BUILD)/sim-fast-$(MANIFEST_SIM_NAME)/gpusim
override SOCSIM_DIR    = $(BUILD)/socsim$(SOC_MEM_SUFFIX)$(if $(SOC_USB),-usb)-$(SOC_RAM_KIB)k$(if $(MANIFEST_GPU_TAG),-w$(SPAN_W)-$(MANIFEST_GPU_TAG),$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W)))
SOCSIM_GPU_GFLAGS     := $(if $(MANIFEST_GPU_GFLAGS), $(MANIFEST_GPU_GFLAGS))$(if $(filter 1,$(ZBUF)), -GENABLE_ZBUF=1)
ULX3S_GPU_PARAMS      := $(patsubst -G%,--param %,$(MANIFEST_GPU_GFLAGS))
# Every manifest GPU, capacities included, runs with the model check: the golden model takes the
# simulator's own -G parameters (gpu_build_defs below, cosim/gpu_build.h).
endif

# The fragment: regenerated when the manifest, the generator or the scene table change (make then
# reads it again before building anything).
$(BUILD)/manifest/%.mk: firmware/scenes/%.manifest.toml mk/manifest.py firmware/scenes/scene_list.h \
                        contract/gpu_contract.toml contract/soc_map.h
	@$(PYTHON) mk/manifest.py $* --out $@

# The GPU parameters of a list of Verilator flags, as C definitions for the harness's per-simulator
# sources (cosim/gpu_build.h): -GVTX_CAP=32 -> -DGPU_BUILD_VTX_CAP=32. Made from the same flags the
# RTL is Verilated with, so the golden model beside a simulator has that simulator's sizes. (Here,
# the first fragment the Makefile reads, so that every later one can use it at parse time.)
# The names are the contract's (contract/gpu_build_params.vh, generated from its build table).
GPU_BUILD_PARAMS := $(shell sed -n 's/^ *parameter integer \([A-Z_]*\) .*/\1/p' contract/gpu_build_params.vh)
gpu_build_defs = $(patsubst -G%,-DGPU_BUILD_%,$(filter $(foreach p,$(GPU_BUILD_PARAMS),-G$(p)=%),$(1)))

.PHONY: manifest-show manifest-check lean-report
manifest-show:
	@echo "scene=$(SCENE) manifest=$(if $(LEAN_SCENE),firmware/scenes/$(SCENE).manifest.toml,none (full build))"
	@echo "FW_ELF=$(FW_ELF)"
	@echo "SOC_FW_ELF=$(SOC_FW_ELF)"
	@echo "GPUSIM=$(GPUSIM)"
	@echo "GPUSIM_FAST=$(GPUSIM_FAST)"
	@echo "SOCSIM=$(SOCSIM)"
	@echo "ULX3S_DIR=$(ULX3S_DIR)"
	@echo "ULX3S_FW_ELF=$(ULX3S_FW_ELF)"
	@echo "SOC_RAM_KIB=$(SOC_RAM_KIB)"
	@echo "SOC_FW_RAM_BYTES=$(SOC_FW_RAM_BYTES)"
	@echo "FW_DEFS=$(FW_DEFS) FW_SCENE_SET=$(FW_SCENE_SET) FW_LINE_EMULATION=$(FW_LINE_EMULATION)"
	@echo "GPU=-GSPAN_W=$(SPAN_W) -GENABLE_ZBUF=$(ZBUF) $(MANIFEST_GPU_GFLAGS)"

manifest-check:
	@$(PYTHON) mk/manifest.py --check

# Full against lean per scene (LEAN_SCENES, default every scene with a manifest): ECP5 synthesis
# JOBS at a time, firmware sizes, socsim's instructions and cycles per frame, frames compared.
LEAN_SCENES ?= $(filter $(patsubst firmware/scenes/%.manifest.toml,%,$(wildcard firmware/scenes/*.manifest.toml)),$(FW_SCENES))
# (The make it calls through a variable of its own: a recipe naming $$(MAKE) would run under -n.)
LEAN_REPORT_MAKE := $(MAKE)
# LEAN_SYNTH=0 leaves the ECP5 synthesis columns out; LEAN_FRAMES: socsim's frames per build (4).
LEAN_SYNTH  ?= 1
LEAN_FRAMES ?= 4
lean-report:
	@bash tools/setup.sh
	$(Q)$(call say,RUN,lean_report.py $(LEAN_SCENES))$(PYTHON) bench/lean_report.py --build $(BUILD) --make $(LEAN_REPORT_MAKE) $(if $(JOBS),--jobs $(JOBS)) \
	  --frames $(LEAN_FRAMES) $(if $(filter 0,$(LEAN_SYNTH)),--no-synth) $(LEAN_SCENES)

# make test's manifest build (tests/manifest/manifest.sh): cubes as its manifest says, the test
# builds' FW_TEST_FRAMES frames, under $(BUILD)/lean-test (apart from `make run SCENE=cubes`'s).
# It runs on make test's GPUSIM_FAST: that GPU holds everything the manifest's (no write mask) has.
# (Inside that make, a manifest build, firmware.mk's own rule makes the ELF.)
MANIFEST_TEST_ELF := $(BUILD)/lean-test/cubes/firmware/cubes.elf
ifeq ($(LEAN_SCENE),)
$(MANIFEST_TEST_ELF): fw-force
	+@$(MAKE) --no-print-directory SCENE=cubes FULL= FRAMES=$(FW_TEST_FRAMES) LEAN_ROOT=$(BUILD)/lean-test fw
endif
