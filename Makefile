# Top-level build. `make run` and `make test` install what is missing first (tools/setup.sh).
# Every other target is listed in README.md and the pages of docs/.

# Quiet builds, as Kbuild's: one short line a step (`CC firmware/render/clip.c`, `VERILATE sim-w8`),
# the full commands with V=1. A recipe line starts with $(Q)$(call say,STEP,WHAT).
V           ?= 0
Q           := $(if $(filter 1,$(V)),,@)
say          = $(if $(filter 1,$(V)),,printf '  %-8s %s\n' '$(1)' '$(2)';)

BUILD       ?= build
OUT         ?= out
FRAMES      ?= 24
# MODEL=path (a model file, firmware/firmware.mk) alone shows that model: the model scene.
SCENE       ?= $(if $(filter command line environment,$(origin MODEL)),model,tetra)
HOST_CC     ?= gcc
HOST_CFLAGS ?= -std=c11 -O2 -g -Wall -Wextra -Werror
PYTHON      ?= python3
VERILATOR   ?= verilator
# Verilator's runtime (verilated.cpp, its threads, DPI and FST writer), compiled once by Verilator's
# own make fragment with its own flags into an archive that every simulator links (VERILATOR_RT_MAKE:
# the runtime left out of a simulator's build), instead of once per simulator: 7 s of CPU a build.
VERILATOR_RT_DIR   := $(BUILD)/verilator-rt
VERILATOR_RT       := $(VERILATOR_RT_DIR)/libverilated-rt.a
VERILATOR_RT_NAMES := verilated verilated_threads verilated_dpi verilated_fst_c
VERILATOR_RT_MAKE  := VM_GLOBAL_FAST= VM_GLOBAL_SLOW=
# A model's C++ compiled as one unit (Verilator's "all .cpp files in one fell swoop"), also where
# Verilator splits a large design into files (the SDRAM and USB socsims: 24 to 34 of them), each of
# which would parse the model's headers again: 22 s of CPU for socsim-sdram-dram-16k against 7 s,
# less wall time even beside a second compiler, and the simulator as fast.
VERILATOR_ONE_UNIT := VM_PARALLEL_BUILDS=0
# The builds as data (mk/builds.toml, tests/suites.toml): mk/gen_builds.py writes $(BUILD)/gen/,
# the lists read here and the rules read below, by cosim/soc/socsim.mk and by firmware/firmware.mk
# (mk/gen.mk); the contract's frames (CONTRACT_FB, CONTRACT_FB_MAX) with them.
include mk/gen.mk
# The ULX3S build's defaults (everything in the SDRAM, 640x480, depth), for the board's goals only.
include boards/ulx3s/defaults.mk
# FB=WxH: the frame of the GPU that run, run-soc and the window simulate: the contract's default
# ($(CONTRACT_FB), shown 2x2) or its largest ($(CONTRACT_FB_MAX), shown 1:1; the simulators'
# names then carry f<width>, a manifest build's tag too). The firmware reads the frame from the
# GPU (FB_SIZE): one program draws either.
FB          ?= $(CONTRACT_FB)
FB_MAX_GFLAGS := -GFB_WIDTH=$(word 1,$(subst x, ,$(CONTRACT_FB_MAX))) -GFB_HEIGHT=$(word 2,$(subst x, ,$(CONTRACT_FB_MAX)))
ifeq ($(FB),$(CONTRACT_FB))
FB_TAG      :=
FB_GFLAGS   :=
else ifeq ($(FB),$(CONTRACT_FB_MAX))
FB_TAG      := f$(word 1,$(subst x, ,$(FB)))
FB_GFLAGS   := $(FB_MAX_GFLAGS)
else ifneq ($(GEN_READ),)
$(error FB=$(FB): $(CONTRACT_FB) or $(CONTRACT_FB_MAX))
endif
# SCENE=x on the command line of run, bitstream ...: the scene's manifest build; FULL=1: the full one.
include mk/manifest.mk

SPAN_W      ?= 8
ZBUF        ?= 0
# GOURAUD=1: run on a GPU built with Gouraud triangles (ENABLE_GOURAUD, with the depth buffer):
# sim-g-w<SPAN_W> and sim-fast-g-w<SPAN_W>; the scenes with vertex normals are then shaded.
GOURAUD     ?= 0
GPUSIM_G    := $(if $(filter 1,$(GOURAUD)),g-)
GPUSIM_F    := $(if $(FB_TAG),$(FB_TAG)-)
GPUSIM      := $(BUILD)/sim-$(GPUSIM_F)$(GPUSIM_G)w$(SPAN_W)/gpusim
ZBUF_SIM    := $(BUILD)/sim-z-w8/gpusim
GOURAUD_SIM := $(BUILD)/sim-g-w8/gpusim
GOURAUD_SIM_FAST := $(BUILD)/sim-fast-g-w8/gpusim
GPUSIM_W8   := $(BUILD)/sim-w8/gpusim
GPUSIM_FAST := $(BUILD)/sim-fast-$(GPUSIM_F)$(GPUSIM_G)w$(SPAN_W)/gpusim
PNG_DIFF    := $(BUILD)/tools/png_diff
# Defined up here: bench-error-path-run's prerequisites are expanded where that rule is read.
EXACT_REF   := $(BUILD)/tools/exact_ref

# The harness's C parts (VGA monitor model, PNG writer), built once: the co-simulator and the
# firmware's host build link them.
COSIM_C_SRC := cosim/vga_monitor.c cosim/png_write.c
COSIM_C_LIB := $(BUILD)/host/libcosim.a
# The co-simulators' C++ library (its rules below), gpusim's and socsim's.
COSIM_CXX_LIB := $(BUILD)/host/libcosim_sim.a

# Golden model (GPU_MODEL_LIB, model_unit), firmware (FW_ELF, fw_unit) rules.
include gpu_model/model.mk
# The model converter (MESHCONV, meshconv, meshconv-sweep): before the firmware, which converts MODEL=.
include tools/meshconv/meshconv.mk
include firmware/firmware.mk
ifeq ($(FW_PLATFORM),soc)
include tests/soc/tests.mk
endif
include tests/stress/stress.mk
# libFuzzer targets (FUZZ_BINS, fuzz-build) and `make fuzz`.
include tests/fuzz/fuzz.mk
# Formal checks of the RTL: make formal, make formal-broken.
include tests/formal/formal.mk

# The RTL, in compilation order: gpu_rtl/files.f is the one list (lint, simulators, synth/synth.sh).
RTL_FILES  := gpu_rtl/files.f
RTL_V      := $(shell sed -e 's://.*::' $(RTL_FILES))
RTL_LINT   := gpu_rtl/lint.vlt
# The SoC in RTL (soc_rtl/): lint-soc, synth-soc, the smoke program (run by soc-smoke, socsim.mk).
include soc_rtl/soc.mk
COSIM_CPP  := $(sort $(wildcard cosim/*.cpp))
HOST_INC   := -Icosim -Igpu_model -Icontract -Ibsp/qemu_virt
# The SoC simulator (socsim), run-soc, bench-soc, soc-smoke and the soc firmware builds.
include cosim/soc/socsim.mk
# `make debug`: the firmware under gdb-multiarch, the GPU co-simulated (needs GPUSIM, FW_ELF).
include cosim/debug.mk
# Boards: bitstream, synth-board, flash, load, term, lint-board (boards/<board>/board.mk).
BOARD      ?= ulx3s
include boards/ulx3s/board.mk
include boards/digilent/board.mk

.PHONY: all setup run run-built test test-quick test-list lint check-contract contract random-long raster \
        bench-gpu bench-sim bench-strips bench-error bench-error-run bench-error-path bench-error-path-run \
        bench-error-shading bench-error-shading-run synth clean

all: $(FW_ELF) $(GPUSIM)

setup:
	@bash tools/setup.sh

# ---- run: the default scene, in a window or headless (frames as PNG files) ----
# The window (cosim/sdl_window.h): where there is a display ($DISPLAY) and it is neither CI nor
# HEADLESS=1, `make run` shows the frames in a window on the fast display path (cosim/gpu_sim.h) and
# runs until Q or the window closes (FRAMES=0 unless given). Otherwise the frames come from the VGA
# pins, FRAMES of them, into $(OUT)/frames.
WINDOW := $(if $(and $(DISPLAY),$(if $(CI)$(HEADLESS),,1)),1)
run: setup
	@$(MAKE) --no-print-directory run-built \
	  $(if $(and $(WINDOW),$(filter-out command line,$(origin FRAMES))),FRAMES=0)

# PLATFORM=soc: the whole SoC in socsim instead of QEMU + the GPU (cosim/soc/socsim.mk); USB=1 and
# USB_KEYS=TEXT its USB keyboard.
# UART_PTY=LINK: the firmware's UART also on a pseudo-terminal, for tools/mesh_upload.py.
ifeq ($(PLATFORM),soc)
run-built: run-soc
else ifneq ($(filter-out 0,$(USB))$(USB_KEYS),)
run-built:
	@echo "run: USB=1 and USB_KEYS are socsim's USB keyboard: PLATFORM=soc"; exit 2
else ifneq ($(WINDOW),)
run-built: $(FW_ELF) $(GPUSIM_FAST)
	@mkdir -p $(OUT)
	$(Q)$(call say,RUN,gpusim cosim $(FW_ELF))$(GPUSIM_FAST) cosim --fw $(FW_ELF) --window --uart-log $(OUT)/uart.log $(if $(UART_PTY),--uart-pty $(UART_PTY))
else
run-built: $(FW_ELF) $(GPUSIM)
	@rm -rf $(OUT)/frames && mkdir -p $(OUT)/frames
	$(Q)$(call say,RUN,gpusim cosim $(FW_ELF))$(GPUSIM) cosim --fw $(FW_ELF) --frames $(OUT)/frames --uart-log $(OUT)/uart.log \
	  $(if $(UART_PTY),--uart-pty $(UART_PTY))
endif

# ---- test: every suite (or those matching SUITE, e.g. SUITE='rtl-* fw-unit'), with a summary line ----
# `make test` builds what the selected suites need (their `needs` in tests/suites.toml, by the ids
# of mk/builds.toml) BUILD_JOBS recipes at a time (default: the cores), then tests/run_all.sh runs
# the suites TEST_JOBS at a time (default: the cores). `make test-quick` builds as the command line
# says (-j) and runs the suites; TEST_BUILD_ONLY=1 only builds.
SUITE ?= *
BUILD_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
TEST_ENV = GPUSIM=$(GPUSIM) GPUSIM_FAST=$(GPUSIM_FAST) GPUSIM_TRACE=$(GPUSIM_TRACE) SOCSIM=$(SOCSIM) \
           SOCSIM_ULX3S=$(SOCSIM_ULX3S) VERILATOR_RT=$(abspath $(VERILATOR_RT)) FW_ELF=$(FW_ELF) BUILD=$(BUILD) \
           PYTHON=$(PYTHON) SUITE='$(SUITE)' \
           $(if $(TEST_JOBS),TEST_JOBS=$(TEST_JOBS))
test: setup
	@$(MAKE) --no-print-directory -j$(BUILD_JOBS) VERILATOR_JOBS=1 TEST_BUILD_ONLY=1 test-quick
	@$(MAKE) --no-print-directory test-quick

# test-quick's prerequisites (what the selected suites need) are derived at the end of this file.

test-list:
	@$(TEST_ENV) bash tests/run_all.sh --list

# ---- the contract: regenerate, or check that the generated files are current ----
contract:
	$(Q)$(call say,GEN,contract)$(PYTHON) contract/gen_contract.py

check-contract:
	$(Q)$(call say,CHECK,contract)$(PYTHON) contract/gen_contract.py --check

# files.f is the one list, so a source left out of it would be neither linted nor built: refused.
RTL_BUS_SLAVES := gpu_wb_slave gpu_axil_slave
RTL_UNLISTED = $(filter-out $(RTL_V),$(wildcard gpu_rtl/*.v gpu_rtl/*.sv))
lint:
	@test -z "$(RTL_UNLISTED)" || { echo "lint: not in $(RTL_FILES): $(RTL_UNLISTED)"; exit 1; }
	$(Q)$(call say,LINT,gpu_top)$(VERILATOR) --lint-only -Wall --top-module gpu_top $(RTL_LINT) -f $(RTL_FILES)
	$(Q)$(call say,LINT,gpu_top 640x480 depth)$(VERILATOR) --lint-only -Wall --top-module gpu_top $(RTL_LINT) \
	  $(FB_MAX_GFLAGS) -GENABLE_ZBUF=1 -f $(RTL_FILES)
	$(Q)$(call say,LINT,gpu_top 640x480 depth strips of 16)$(VERILATOR) --lint-only -Wall --top-module gpu_top \
	  $(RTL_LINT) $(FB_MAX_GFLAGS) -GENABLE_ZBUF=1 -GSTRIP_ROWS=16 -f $(RTL_FILES)
	$(Q)$(call say,LINT,gpu_top 640x480 depth strips of 16 frames in SDRAM)$(VERILATOR) --lint-only -Wall \
	  --top-module gpu_top $(RTL_LINT) $(FB_MAX_GFLAGS) -GENABLE_ZBUF=1 -GSTRIP_ROWS=16 -GFRAME_DRAM=1 -f $(RTL_FILES)
	$(Q)$(call say,LINT,gpu_top 320x240 strips of 4 frames in SDRAM)$(VERILATOR) --lint-only -Wall \
	  --top-module gpu_top $(RTL_LINT) -GSTRIP_ROWS=4 -GFRAME_DRAM=1 -f $(RTL_FILES)
	@# The bus slaves are not under gpu_top (a SoC puts one in front of it): each is its own top.
	$(Q)$(call say,LINT,$(RTL_BUS_SLAVES))$(foreach m,$(RTL_BUS_SLAVES),$(VERILATOR) --lint-only -Wall --top-module $(m) $(RTL_LINT) gpu_rtl/$(m).v &&) true
	@echo "lint: $(words $(RTL_V)) files of $(RTL_FILES) clean under -Wall"

# ---- longer randomized RTL-vs-model run ----
random-long: $(GPUSIM) $(GOURAUD_SIM_FAST)
	$(Q)$(call say,RUN,gpusim random: seeds 101-110)for seed in 101 102 103 104 105 106 107 108 109 110; do \
	  $(GPUSIM) random --seed $$seed --batches 500 --tris 500 --swap-percent 10 --min-prims 100000 || exit 1; done
	@# Gouraud triangles (40 % of the primitives there, random intensities, extremes, slow gradients).
	$(Q)$(call say,RUN,gpusim random: Gouraud seeds 111-113)for seed in 111 112 113; do \
	  $(GOURAUD_SIM_FAST) random --seed $$seed --batches 500 --tris 500 --swap-percent 10 --min-prims 100000 || exit 1; done

# ---- the GPU without firmware: a primitive list through RTL and model ----
raster: $(GPUSIM)
	@test -n "$(IN)" -a -n "$(OUT)" || { echo "usage: make raster IN=<list> OUT=<dir>"; exit 2; }
	$(Q)$(call say,RUN,gpusim raster $(IN))$(GPUSIM) raster --in $(IN) --out $(OUT)

# ---- GPU performance, counted in simulated cycles, for each span width ----
# Then the frames in external memory, every scene at 640x480 (bench/frame_dram_measured.sh).
BENCH_DRAM_SIMS = $(BUILD)/sim-s16-f640-w8/gpusim $(BUILD)/sim-dram-s16-f640-w8/gpusim
BENCH_SYS_HZ    = $(call soc_map_value,SOC_CLK_HZ_DEFAULT)
bench-gpu: $(BENCH_SIMS) $(ZBUF_SIM) $(GOURAUD_SIM) $(FW_ELF) $(BENCH_DRAM_SIMS) $(BUILD)/sim-f640-w8/gpusim $(FW_BENCH_STRIPS_ELFS)
	@rm -rf $(BUILD)/bench-gpu/scene-lists && mkdir -p $(BUILD)/bench-gpu/scene-lists
	@$(GPUSIM) cosim --fw $(FW_ELF) --frames $(BUILD)/bench-gpu/scene-frames --no-model-check \
	  --dump-lists $(BUILD)/bench-gpu/scene-lists >/dev/null
	@$(PYTHON) bench/bench_gpu.py $(BUILD) $(BUILD)/bench-gpu/scene-lists
	@rm -rf $(BUILD)/bench-gpu/dram && mkdir -p $(BUILD)/bench-gpu/dram
	@bash bench/frame_dram_measured.sh $(BENCH_SYS_HZ) $(BENCH_DRAM_SIMS) $(FW_BENCH_DIR) $(BUILD)/bench-gpu/dram $(FW_SCENES)

# ---- the strip renderer's binning workload per scene and strip height (bench/strip_bins.py):
# each scene's benchmark frames as primitive lists, counted at 640x480 ----
STRIP_HEIGHTS ?= 1 8 16 32 60
bench-strips: $(FW_BENCH_ELFS) $(FW_BENCH_STRIPS_ELFS) $(GPUSIM_FAST) $(BUILD)/sim-f640-w8/gpusim \
              $(BUILD)/sim-s16-f640-w8/gpusim
	@rm -rf $(BUILD)/bench-strips && mkdir -p $(BUILD)/bench-strips
	@for s in $(FW_SCENES); do mkdir -p $(BUILD)/bench-strips/$$s; \
	  $(GPUSIM_FAST) cosim --fw $(FW_BENCH_DIR)/$$s.elf --frames $(BUILD)/bench-strips/frames-$$s \
	    --no-model-check --dump-lists $(BUILD)/bench-strips/$$s >/dev/null || exit 1; done
	@$(PYTHON) bench/strip_bins.py 2 $(STRIP_HEIGHTS) -- $(foreach s,$(FW_SCENES),$(s)=$(BUILD)/bench-strips/$(s))
	@bash bench/strips_measured.sh $(BUILD)/sim-f640-w8/gpusim $(BUILD)/sim-s16-f640-w8/gpusim $(FW_BENCH_DIR) \
	  $(BUILD)/bench-strips $(FW_SCENES)

# ---- pixel error against counted cost, for every accuracy/speed knob (bench/bench_error.py) ----
# Installs matplotlib for the plot (tools/packages-plot.txt), then runs the table and the plot with
# the interpreter Debian's python3-matplotlib belongs to (PYTHON may be another one, e.g. pyenv's).
PLOT_PYTHON ?= $(or $(wildcard /usr/bin/python3),$(PYTHON))
BENCH_ERROR_CHECK = $(if $(FW_SUBPIXEL_BITS),@echo "bench-error sets FW_SUBPIXEL_BITS itself: run it without" && exit 2)
# The co-simulation's speed per scene on both display paths, the pins and the fast one (window).
bench-sim: $(FW_SIMBENCH_ELFS) $(GPUSIM) $(GPUSIM_FAST)
	@bash bench/bench_sim.sh $(GPUSIM) $(GPUSIM_FAST) $(FW_SIMBENCH_DIR) $(FW_SCENES)

bench-error:
	$(BENCH_ERROR_CHECK)
	@bash tools/setup.sh packages-plot.txt
	@$(MAKE) --no-print-directory bench-error-run

bench-error-run: $(FW_ERR_ELFS) $(GPUSIM_W8) $(ZBUF_SIMS) $(ZBITS_SIMS) $(PNG_DIFF) $(FW_PATH_HOSTS) bench-error-soc
	$(BENCH_ERROR_CHECK)
	@$(PLOT_PYTHON) bench/bench_error.py --build $(BUILD) --frames $(FW_ERR_FRAMES) $(BENCH_SOC_ARGS) $(FW_SCENES)
	@$(MAKE) --no-print-directory bench-error-path-run
	@$(MAKE) --no-print-directory bench-error-shading-run

# Both halves' CPU cycles on the SoC (bench/bench_error.py --socsim): the path ELFs of the first
# FW_PATH_SOC_VIEWS views built for bsp/soc (firmware.mk FW_PATH_SOC_ELFS, $(BUILD)/fw-path-soc/),
# on socsim with and without the depth buffer, and R's on a SPAN_W 1 GPU (the span-width check):
# mk/builds.toml's socsim-bench, -z and -z-w1 (why the whole RAM window: there). Measured once per
# configuration (the results are cached in $(BUILD)/bench-error/soc/).
BENCH_SOCSIM      := socsim-bench
BENCH_SOC_RAM_KIB := $(SOCSIM_RAM_KIB_$(BENCH_SOCSIM))
BENCH_SOC_ARGS    = --socsim sim-w8=$(BUILD)/$(BENCH_SOCSIM)/socsim --socsim sim-z-w8=$(BUILD)/$(BENCH_SOCSIM)-z/socsim \
                    --socsim sim-z-w1=$(BUILD)/$(BENCH_SOCSIM)-z-w1/socsim --soc-views $(FW_PATH_SOC_VIEWS)
.PHONY: bench-error-soc
bench-error-soc: $(foreach s,$(BENCH_SOCSIM) $(BENCH_SOCSIM)-z $(BENCH_SOCSIM)-z-w1,$(BUILD)/$(s)/socsim)
	+@$(SOC_FW_MAKE) SOC_RAM_KIB=$(BENCH_SOC_RAM_KIB) $(patsubst $(BUILD)/fw-path/%,$(BUILD)/fw-path-soc/%,$(FW_PATH_SOC_ELFS))

# The camera paths against the exact reference (bench/bench_error.py --path): FW_PATH_VIEWS views
# per scene of BENCH_PATH_SCENES, the costs co-simulated on the first BENCH_COST_VIEWS of them.
# `make bench-error-path` runs only these (BENCH_PATH_SCENES="tetra cubes" for a reduced run).
BENCH_PATH_SCENES ?= $(FW_SCENES)
BENCH_COST_VIEWS  ?= 8
bench-error-path:
	$(BENCH_ERROR_CHECK)
	@bash tools/setup.sh packages-plot.txt
	@$(MAKE) --no-print-directory bench-error-path-run

bench-error-path-run: $(FW_PATH_HOSTS) $(FW_PATH_ELFS) $(GPUSIM_W8) $(ZBUF_SIMS) $(ZBITS_SIMS) $(PNG_DIFF) $(EXACT_REF) bench-error-soc
	$(BENCH_ERROR_CHECK)
	@$(PLOT_PYTHON) bench/bench_error.py --build $(BUILD) --path $(FW_PATH_VIEWS) \
	  --cost-views $(BENCH_COST_VIEWS) $(BENCH_SOC_ARGS) $(BENCH_PATH_SCENES)

# The shading knobs (bench/bench_shading.py): flat, Gouraud and Gouraud dithered on the scenes with
# vertex normals (FW_SHADING_SCENES), against the undithered reference, on the same camera path;
# `make bench-error-shading` runs only these.
bench-error-shading:
	$(BENCH_ERROR_CHECK)
	@bash tools/setup.sh packages-plot.txt
	@$(MAKE) --no-print-directory bench-error-shading-run

bench-error-shading-run: $(FW_SHADING_HOSTS) $(FW_SHADING_ELFS) $(GOURAUD_SIM) $(PNG_DIFF)
	$(BENCH_ERROR_CHECK)
	@$(PLOT_PYTHON) bench/bench_shading.py --build $(BUILD) --views $(FW_PATH_VIEWS) \
	  --cost-views $(BENCH_COST_VIEWS) $(FW_SHADING_SCENES)

# The exact reference of bench-error's camera paths (double precision, the pipeline's definitions
# written anew: bench/exact_ref/exact_ref.c), and its self-test on known polygons.
$(EXACT_REF): bench/exact_ref/exact_ref.c cosim/png_write.c cosim/png_write.h
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(HOST_CFLAGS) -Icosim $$(pkg-config --cflags libpng) bench/exact_ref/exact_ref.c \
	  cosim/png_write.c -o $@ $$(pkg-config --libs libpng) -lm

$(PNG_DIFF): tools/png_diff.c
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(HOST_CFLAGS) $$(pkg-config --cflags libpng) $< -o $@ $$(pkg-config --libs libpng)

# ---- synthesis: yosys for 7-series (resource counts) and iCE40 place-and-route (fmax) ----
synth:
	@bash tools/setup.sh packages-synth.txt
	@ZBUF=$(ZBUF) GOURAUD=$(GOURAUD) bash synth/synth.sh $(BUILD)

# ---- the README's two commands on a fresh Debian 12: a debootstrap chroot in $(BUILD)/fresh (root) ----
.PHONY: fresh-check
fresh-check:
	@BUILD=$(BUILD) bash mk/fresh_check.sh

# ---- host-side simulator: Verilated GPU + co-simulation bridge + golden model ----
HOST_OBJ := $(patsubst %.c,$(BUILD)/host/%.o,$(COSIM_C_SRC))

$(BUILD)/host/%.o: %.c
	@mkdir -p $(dir $@)
	$(Q)$(call say,CC,$<)$(HOST_CC) $(HOST_CFLAGS) -MMD -MP $(HOST_INC) $$(pkg-config --cflags libpng) -c $< -o $@

$(COSIM_C_LIB): $(HOST_OBJ)
	@rm -f $@
	$(Q)$(call say,AR,$@)ar rcs $@ $^

# SIM_CXX compiles the simulators' C++ (gpusim's and socsim's): clang's code of the Verilated model
# runs faster than GCC 12's (rtl-vs-model-seed1: 10.0 s of CPU against 10.9 s; socsim, knot's two
# frames: 22.2 s against 28.4 s); socsim's clang build took 13.4 s of CPU (with the shared runtime).
SIM_CXX        ?= clang++-14

# The co-simulator's C++ apart from the Verilated model's two neighbours (gpu_sim.cpp includes the
# model's headers, main.cpp Verilator's): the same in every configuration, so compiled once for all
# the simulators, with the code-generation flags Verilator's make gives its user files. A function
# a section: socsim links the library too, and its --gc-sections drops what needs gpusim's GpuSim.
COSIM_CXXFLAGS := -O2 -std=c++17 -faligned-new -fcf-protection=none -ffunction-sections
COSIM_CPP_SIM  := cosim/gpu_sim.cpp cosim/main.cpp
COSIM_CPP_LIB  := $(filter-out $(COSIM_CPP_SIM),$(COSIM_CPP))
COSIM_CXX_OBJ  := $(patsubst %.cpp,$(BUILD)/host/%.o,$(COSIM_CPP_LIB))

# The compiler and flags recorded (rewritten only when they change): a change recompiles the objects.
COSIM_CXX_FLAGS_FILE := $(BUILD)/host/cxxflags.txt
$(COSIM_CXX_FLAGS_FILE): fw-force
	$(call fw_flags_file,$@,$(SIM_CXX) $(COSIM_CXXFLAGS) $(HOST_INC))

$(BUILD)/host/%.o: %.cpp $(COSIM_CXX_FLAGS_FILE)
	@mkdir -p $(dir $@)
	$(Q)$(call say,CXX,$<)$(SIM_CXX) $(COSIM_CXXFLAGS) -MMD -MP $(HOST_INC) $$(pkg-config --cflags sdl2) -c $< -o $@

$(COSIM_CXX_LIB): $(COSIM_CXX_OBJ)
	@rm -f $@
	$(Q)$(call say,AR,$@)ar rcs $@ $^

# Verilator's runtime (VERILATOR_RT, near the top), rebuilt when Verilator's version changes
# (version.txt is rewritten only then).
$(VERILATOR_RT_DIR)/version.txt: fw-force
	@mkdir -p $(@D) && v=$$($(VERILATOR) --version) && { echo "$$v" | cmp -s - $@ || echo "$$v" > $@; }
$(VERILATOR_RT): $(VERILATOR_RT_DIR)/version.txt
	@touch $(VERILATOR_RT_DIR)/rt.mk
	$(Q)$(call say,CXX,verilator-rt)root=$$($(VERILATOR) --getenv VERILATOR_ROOT) && \
	  $(MAKE) -s --no-print-directory -C $(VERILATOR_RT_DIR) -f $$root/include/verilated.mk VERILATOR_ROOT=$$root \
	    VM_PREFIX=rt VM_GLOBAL_FAST="$(VERILATOR_RT_NAMES)" VM_GLOBAL_SLOW= VM_COVERAGE=0 VM_SC=0 VM_TRACE=1 \
	    VM_TRACE_FST=1 VM_TRACE_VCD=0 $(VERILATOR_RT_NAMES:=.o) && \
	  rm -f $@ && ar rcs $@ $(VERILATOR_RT_NAMES:%=$(VERILATOR_RT_DIR)/%.o)

# One simulator per configuration: $(BUILD)/sim-w<SPAN_W>/gpusim, sim-z-w<SPAN_W> with the depth
# buffer built in, and sim-fast-w<SPAN_W> on the fast display path (gpu_core with the harness as its
# display: cosim/gpu_sim.h). $(call verilate,OUTPUT,VERILATOR PARAMETER FLAGS[,TOP MODULE,CFLAGS]):
# the flags may be any of Verilator's besides -G (the table's trace builds add --trace-fst).
# VERILATOR_JOBS: compilers each build runs at once (its own make, outside this make's -j); `make
# test` sets 1, since it builds the simulators side by side already. The old program is removed
# first: Verilator's make relinks only for its own objects, not for a changed library.
VERILATOR_JOBS ?= 2
define verilate
	@mkdir -p $(dir $(1))
	@rm -f $(1)
	$(Q)$(call say,VERILATE,$(patsubst $(BUILD)/%/,%,$(dir $(1))))$(VERILATOR) --cc --exe --build -j $(VERILATOR_JOBS) --assert -O3 --x-assign fast --x-initial fast \
	  --top-module $(or $(3),gpu_top) $(2) -f $(RTL_FILES) $(abspath $(COSIM_CPP_SIM)) \
	  -CFLAGS "-O2 -std=c++17 $(call gpu_build_defs,$(2)) $(4) $(addprefix -I$(CURDIR)/,$(patsubst -I%,%,$(HOST_INC)))" \
	  -LDFLAGS "$(abspath $(COSIM_CXX_LIB) $(COSIM_C_LIB) $(GPU_MODEL_LIB)) $$(pkg-config --libs libpng sdl2) $(abspath $(VERILATOR_RT))" \
	  --MAKEFLAGS "OPT_FAST=-O2 OPT_SLOW=-O1 CXX=$(SIM_CXX) LINK=$(SIM_CXX) $(VERILATOR_RT_MAKE) $(VERILATOR_ONE_UNIT)" --Mdir $(dir $(1))obj -o $(abspath $(1)) \
	  >$(dir $(1))verilator.log 2>&1 || { tail -40 $(dir $(1))verilator.log; exit 1; }
endef
SIM_DEPS := $(RTL_FILES) $(RTL_V) contract/gpu_regs.vh $(COSIM_CPP) $(wildcard cosim/*.h) bsp/qemu_virt/platform.h $(COSIM_CXX_LIB) $(COSIM_C_LIB) $(GPU_MODEL_LIB) \
            $(VERILATOR_RT)

# Every simulator of mk/builds.toml: $(BUILD)/<id>/gpusim, $(call verilate,...) with its parameters.
ifneq ($(GEN_READ),)
include $(GEN_DIR)/gpusim.mk
# (In a manifest build, once make has read the manifest's fragment: it makes it first.)
ifneq ($(if $(LEAN_SCENE),$(MANIFEST_SCENE),1),)
ifneq ($(filter-out $(GPUSIM_IDS),$(patsubst $(BUILD)/%/gpusim,%,$(GPUSIM) $(GPUSIM_FAST))),)
$(error SPAN_W=$(SPAN_W) GOURAUD=$(GOURAUD): $(GPUSIM) is not a simulator of mk/builds.toml (SPAN_W: 1 4 8 16))
endif
endif
endif

# `make waves` (its simulators are the table's trace = true rows).
include cosim/waves.mk

clean:
	$(Q)$(call say,CLEAN,$(BUILD) $(OUT))rm -rf $(BUILD) $(OUT)

-include $(HOST_OBJ:.o=.d) $(COSIM_CXX_OBJ:.o=.d)

# make test's builds: what the selected suites need (mk/gen_builds.py --needs), read last, when
# every fragment has named its targets.
ifneq ($(filter test-quick test-needs,$(MAKECMDGOALS)),)
$(eval TEST_DEPS := $(shell $(PYTHON) mk/gen_builds.py --needs '$(SUITE)'))
endif
.PHONY: test-needs
test-quick: $(TEST_DEPS)
	@$(if $(TEST_BUILD_ONLY),:,$(TEST_ENV) bash tests/run_all.sh)

test-needs:
	@echo $(TEST_DEPS)
