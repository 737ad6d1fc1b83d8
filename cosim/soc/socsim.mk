# cosim/soc/socsim.mk — the SoC simulator, `make run PLATFORM=soc`, `make bench-soc` and the soc
# firmware builds; included by the top-level Makefile (paths relative to the repository root).
#
#   $(SOCSIM)      = $(BUILD)/socsim-<SOC_RAM_KIB>k[-w<SPAN_W>]/socsim: soc_top Verilated with
#                    RAM_BYTES = SOC_RAM_KIB KiB (the size the soc firmware is linked for,
#                    bsp/soc/soc_ram.mk) and the GPU's SPAN_W; the program is loaded at run time
#   $(SOCSIM_ULX3S) = $(BUILD)/socsim-ulx3s-<SOC_RAM_KIB>k/socsim: the same harness on the ULX3S
#                    build (boards/ulx3s/ulx3s_system: three clocks, the video decoded from the
#                    TMDS pairs of the DVI connector), -DSOCSIM_BOARD_ULX3S
#   run-soc        `make run PLATFORM=soc [SCENE=… FRAMES=…]`: the soc firmware of SCENE (a
#                  recursive make with FW_PLATFORM=soc) on socsim -> $(OUT)/frames, $(OUT)/uart.log,
#                  or a window where the Makefile's WINDOW says so (a display, not CI). USB=1: the
#                  SoC with its keyboard host (USB_HOST) and socsim's keyboard on its pins, the
#                  firmware with FW_USB_KEYBOARD, the window's keys typed on that keyboard;
#                  USB_KEYS=TEXT (USB=1 implied) types TEXT on it once it is enumerated (socsim
#                  --usb-keys-at 1:TEXT: {UP} {DOWN} {LEFT} {RIGHT} {ESC}... name keys, docs/usb.md)
#   soc-fw         that firmware only; soc-fw-test: the FW_TEST_FRAMES builds of every scene
#   bench-soc      per scene: instructions, cycles, CPI, refills, GPU cycles, fps (bench/bench_soc.py)
#   profile-soc    one scene's clocks by function on socsim (firmware/tools/profile_soc.py)
#   soc-smoke      the bare-metal smoke program (tests/soc/smoke.c, soc_rtl/soc.mk) on socsim
#
# The RTL's sources and flags come from soc_rtl/soc.mk (SOC_VFLAGS: gpu_rtl/files.f, the core from
# the venv, soc_rtl/files.f, their lint waivers), included before this file.

include bsp/soc/soc_ram.mk

# ZBUF=1 (outside a manifest build, whose mk/manifest.mk sets both itself): the GPU with its depth
# buffer, in a folder of its own (-z), as bench-error's depth-tested configurations run it.
# FB=<the largest frame>: its GPU (the Makefile's FB_TAG), in a folder of its own (-f<width>).
SOCSIM_GPU_GFLAGS ?= $(if $(filter 1,$(ZBUF)), -GENABLE_ZBUF=1)$(if $(FB_GFLAGS), $(FB_GFLAGS))
# USB=1 or USB_KEYS=TEXT: the keyboard host and socsim's keyboard (-usb). A socsim build with them
# (this make's own, or mk/builds.toml's usb = true) adds these parameters and definitions.
SOC_USB      := $(if $(or $(filter 1,$(USB)),$(USB_KEYS)),1)
SOCSIM_USB_PARAMS := -GUSB_HOST=1
SOCSIM_USB_CFLAGS := -DSOCSIM_USB=1
SOCSIM_DIR   := $(BUILD)/socsim$(SOC_MEM_SUFFIX)$(if $(SOC_USB),-usb)-$(SOC_RAM_KIB)k$(if $(filter 1,$(ZBUF)),-z)$(if $(FB_TAG),-$(FB_TAG))$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W))
SOCSIM       := $(SOCSIM_DIR)/socsim
# Each build compiles socsim.cpp, which includes its Verilated model and reads the build's
# definitions; the rest of its C++ is the same in every build, compiled once: the co-simulator's
# library (harness, model check, UART pump, terminal and pty, window: COSIM_CXX_LIB) and socsim's
# own (the UART line, the SDRAM chip and flash models, the TMDS decoder, the USB keyboard:
# SOCSIM_LIB). Six builds
# compiled those six to nine files each, about 6 s of CPU a build.
SOCSIM_SRC   := cosim/soc/socsim.cpp
SOCSIM_LIB_SRC := cosim/soc/uart_line.cpp cosim/soc/tmds_decoder.cpp cosim/sdram/sdram_chip.cpp cosim/flash/spi_flash.cpp \
                  cosim/usb/usb_kbd_device.cpp
SOCSIM_LIB   := $(BUILD)/host/libsocsim.a
SOCSIM_SV    := cosim/soc/socsim_taps.sv
# soc firmware: the same sources as `make run`, built by a recursive make for FW_PLATFORM=soc.
SOC_FW_DIR   := $(BUILD)/firmware-soc$(SOC_MEM_SUFFIX)
SOC_FW_ELF   := $(SOC_FW_DIR)/$(SCENE)$(if $(filter float,$(FW_BACKEND)),-float)$(if $(SOC_USB),-usb).elf
SOC_FW_MAKE   = $(MAKE) --no-print-directory FW_PLATFORM=soc BUILD=$(BUILD) SOC_RAM_KIB=$(SOC_RAM_KIB) \
                SOC_MEM=$(SOC_MEM) FW_DIR=$(SOC_FW_DIR)

SOCSIM_DEPS := $(SOC_VENV) $(SOC_FILES) $(SOC_RTL_V) $(SOC_RTL_VH) $(SOC_LINT) $(RTL_V) $(RTL_FILES) contract/gpu_regs.vh \
               contract/soc_map.vh contract/soc_map.h $(SOCSIM_SRC) $(SOCSIM_SV) $(wildcard cosim/soc/*.h) \
               $(wildcard cosim/*.h) $(SOCSIM_LIB) $(COSIM_CXX_LIB) $(COSIM_C_LIB) $(GPU_MODEL_LIB) $(VERILATOR_RT)

$(SOCSIM_LIB): $(patsubst %.cpp,$(BUILD)/host/%.o,$(SOCSIM_LIB_SRC))
	@rm -f $@
	$(Q)$(call say,AR,$@)ar rcs $@ $^

# The Verilator command of a socsim build, recorded in <dir>/cmd.txt (rewritten only when it changes)
# so that a change of parameters or flags rebuilds, and an edit elsewhere in this file does not.
# $(1) = the build's directory, $(2) = its top module and parameters, $(3) = the RAM's bytes,
# $(4) = the GPU's -G parameters (SPAN_W first), $(5) = further sources, $(6) = -CFLAGS definitions.
socsim_cmd = $(VERILATOR) --cc --exe --build -j $(VERILATOR_JOBS) -O3 --x-assign fast --x-initial fast \
  --top-module $(2) -GRAM_BYTES=$(3) $(4) \
  $(SOC_VFLAGS) $(SOCSIM_SV) $(abspath $(SOCSIM_SRC)) $(5) \
  -CFLAGS "-O2 -march=native -std=c++17 -ffunction-sections $(call gpu_build_defs,$(4)) -DSOCSIM_RAM_BYTES=$(3)u \
           $(6) $(addprefix -I$(CURDIR)/,cosim cosim/soc cosim/usb gpu_model contract) $$(pkg-config --cflags sdl2)" \
  -LDFLAGS "-Wl,--gc-sections $(abspath $(SOCSIM_LIB) $(COSIM_CXX_LIB) $(COSIM_C_LIB) $(GPU_MODEL_LIB)) $$(pkg-config --libs libpng sdl2) $(abspath $(VERILATOR_RT))" \
  --MAKEFLAGS "OPT_FAST=-O3 OPT_SLOW=-O1 CXX=$(SIM_CXX) LINK=$(SIM_CXX) $(VERILATOR_RT_MAKE) $(VERILATOR_ONE_UNIT)" --Mdir $(1)/obj -o $(abspath $(1))/socsim
# The systems a socsim build Verilates: soc_top (the pixel clock tied to the system clock), the
# ULX3S's (boards/ulx3s/ulx3s_system on its three clocks, the monitor on the TMDS pairs), each with
# the SDRAM too (below: sdram, ulx3s-sdram, the board's default build's memory system).
# Each system's top and parameters, further sources, -CFLAGS definitions and prerequisites (the
# names mk/gen_builds.py's rules use for a table build of that system).
SOCSIM_SYSTEM_soc         = soc_top $(SOC_SIM_TIED)
SOCSIM_SOURCES_soc       :=
SOCSIM_CFLAGS_soc        :=
SOCSIM_PREREQS_soc       :=
SOCSIM_SYSTEM_ulx3s       = ulx3s_system
ULX3S_SIM_FILES          := boards/ulx3s/files.f
SOCSIM_SOURCES_ulx3s      = -f $(ULX3S_SIM_FILES)
SOCSIM_CFLAGS_ulx3s      := -DSOCSIM_BOARD_ULX3S
SOCSIM_PREREQS_ulx3s     := $(ULX3S_SIM_FILES) $(shell sed -e 's://.*::' $(ULX3S_SIM_FILES))
# With SDRAM (cosim/soc/soc_sdram_sim.sv): soc_top and LiteDRAM's controller generated at the
# simulated clock for the contract's SDRAM size (soc_rtl/litedram), the chip played by socsim
# (cosim/sdram/sdram_chip.h), -DSOCSIM_SDRAM.
# The controller is generated once per system clock: $(call litedram_dir,HZ) holds it for HZ, shared
# by every build at that clock (socsim's at SOC_SIM_CLK_HZ; the ULX3S build's at SYS_MHZ,
# boards/ulx3s/board.mk). The "sim-" of the name is from when socsim was its only user.
litedram_dir              = $(BUILD)/litedram/sim-$(1)
LITEDRAM_SIM_DIR         := $(call litedram_dir,$(SOC_SIM_CLK_HZ))
LITEDRAM_SIM_V           := $(LITEDRAM_SIM_DIR)/litedram_core.v
SOCSIM_SYSTEM_sdram       = soc_sdram_sim -GPIX_CLK_HZ=$(SOC_SIM_CLK_HZ) -GSDRAM_BYTES=$(SOC_SDRAM_BYTES) --timescale 1ns/1ps
SOCSIM_SOURCES_sdram      = soc_rtl/litedram/lint.vlt soc_rtl/litedram/sdram_wb_burst.v soc_rtl/litedram/soc_sdram.v cosim/soc/soc_sdram_sim.sv \
                            $(LITEDRAM_SIM_V) $(wildcard cosim/sdram/ecp5/*.v)
SOCSIM_CFLAGS_sdram      := -DSOCSIM_SDRAM -I$(CURDIR)/cosim/sdram -I$(CURDIR)/cosim/flash
SOCSIM_PREREQS_sdram     := $(LITEDRAM_SIM_V) soc_rtl/litedram/lint.vlt soc_rtl/litedram/sdram_wb_burst.v soc_rtl/litedram/soc_sdram.v \
                            cosim/soc/soc_sdram_sim.sv cosim/soc/soc_sdram_chip_model.vh $(wildcard cosim/sdram/ecp5/*.v) \
                            cosim/sdram/sdram_chip.h cosim/sdram/sdram_pins.h cosim/flash/spi_flash.h
# The ULX3S build with SDRAM (cosim/soc/ulx3s_sdram_sim.sv): ulx3s_system on its three clocks with
# the same controller and chip on its SDRAM ports, the flash on its flash pins, the board's DVI
# decoded; the system with SDRAM's sources and the board's.
SOCSIM_SYSTEM_ulx3s-sdram   = ulx3s_sdram_sim -GSDRAM_BYTES=$(SOC_SDRAM_BYTES) --timescale 1ns/1ps
SOCSIM_SOURCES_ulx3s-sdram  = $(filter-out cosim/soc/soc_sdram_sim.sv,$(SOCSIM_SOURCES_sdram)) -f $(ULX3S_SIM_FILES) \
                              cosim/soc/ulx3s_sdram_sim.sv
SOCSIM_CFLAGS_ulx3s-sdram  := $(SOCSIM_CFLAGS_sdram) $(SOCSIM_CFLAGS_ulx3s)
SOCSIM_PREREQS_ulx3s-sdram := $(filter-out cosim/soc/soc_sdram_sim.sv,$(SOCSIM_PREREQS_sdram)) $(SOCSIM_PREREQS_ulx3s) \
                              cosim/soc/ulx3s_sdram_sim.sv
$(call litedram_dir,%)/litedram_core.v: soc_rtl/litedram/gen_litedram.py soc_rtl/litedram/ulx3s_sdram.yml contract/soc_map.h $(SOC_VENV)
	@mkdir -p $(@D)
	$(Q)$(call say,GEN,$@).venv/bin/python soc_rtl/litedram/gen_litedram.py soc_rtl/litedram/ulx3s_sdram.yml \
	  $(@D) --sys-clk-hz $* --expect-bytes $(SOC_SDRAM_BYTES) >$(@D)/gen.log 2>&1 \
	  || { tail -20 $(@D)/gen.log; exit 1; }
# Bare-metal programs of the system with SDRAM, built against the LiteDRAM headers of its controller
# ($(LITEDRAM_SIM_DIR)/include: the register offsets of the power-up sequence; HZ given: the
# controller generated for that system clock) and laid out in the on-chip RAM by linker/soc.ld (the
# stack above .bss): $(call SOC_SDRAM_PROGRAM,ELF,SOURCES[,FLAGS[,HZ]]).
# postlink checks each against the boot build's RAM (SOC_RAM_BOOT_BYTES) and writes ELF.hex; the
# link, that its image ends within SOC_RAM_BOOT_IMAGE_BYTES (above is the firmware's fast RAM once it
# runs: a reset finds the boot program whole).
SOC_RAM_BOOT_IMAGE_BYTES := $(call soc_map_value,SOC_RAM_BOOT_IMAGE_BYTES)
SOC_SDRAM_PROGRAM_SRC := bsp/soc/boot/say.c bsp/soc/sdram/sdram_init.c bsp/soc/sdram/memtest.c
SOC_SDRAM_PROGRAM_HDRS = $(wildcard bsp/soc/boot/*.h bsp/soc/sdram/*.h bsp/soc/sdram/include/*.h bsp/soc/sdram/include/hw/*.h)
define SOC_SDRAM_PROGRAM
$(1): $(2) $(SOC_SDRAM_PROGRAM_SRC) $$(SOC_SDRAM_PROGRAM_HDRS) linker/soc.ld contract/soc_map.h $(call litedram_dir,$(or $(4),$(SOC_SIM_CLK_HZ)))/litedram_core.v bsp/soc/postlink.py
	@mkdir -p $$(dir $$@)
	$$(Q)$$(call say,LD,$$@)$(RV_CC) $(SOC_RV_FLAGS) --specs=picolibc.specs -Os -g -std=c11 -ffreestanding -nostartfiles \
	  -Wall -Wextra -Werror -Icontract -Ifirmware -Ibsp/soc/boot -Ibsp/soc/sdram -Ibsp/soc/sdram/include \
	  -I$(call litedram_dir,$(or $(4),$(SOC_SIM_CLK_HZ)))/include -T linker/soc.ld -Wl,--defsym=__stack_size=2048 \
	  -Wl,--defsym=__image_limit=$(SOC_RAM_BOOT_IMAGE_BYTES) -Wl,--gc-sections \
	  -Wl,--no-warn-rwx-segments $(3) $(2) $(SOC_SDRAM_PROGRAM_SRC) -lgcc -o $$@
	$$(Q)$$(PYTHON) bsp/soc/postlink.py --ram-bytes $$$$(( $(SOC_RAM_BOOT_KIB) * 1024 )) \
	  --size $(patsubst %gcc,%size,$(RV_CC)) --nm $(patsubst %gcc,%nm,$(RV_CC)) $$@ >/dev/null
endef
# The boot program (bsp/soc/boot, docs/boot.md): the on-chip RAM's image of a build whose firmware
# runs from the SDRAM. $(call soc_boot_elf,HZ): the one for a system clock of HZ (a board's), the
# same as socsim's at socsim's clock; soc_boot_rules makes the rules of another clock's.
SOC_BOOT_ELF := $(BUILD)/soc/boot.elf
SOC_BOOT_HEX := $(SOC_BOOT_ELF).hex
SOC_BOOT_SRC := bsp/soc/boot/boot_crt0.S bsp/soc/boot/boot.c bsp/soc/boot/boot_image.c firmware/model/crc32.c
$(SOC_BOOT_HEX): $(SOC_BOOT_ELF)
$(eval $(call SOC_SDRAM_PROGRAM,$(SOC_BOOT_ELF),$(SOC_BOOT_SRC),-DCRC32_SLICE_TABLES=1))
# make test's scene runs from the SDRAM (soc-sdram-scenes, boards-ulx3s-dvi) boot with a random fill
# of 16 KiB instead of 256: 3.3 M cycles less a boot; the boot as built for boards runs in
# soc-boot-faults.
SOC_BOOT_FAST_ELF := $(BUILD)/soc/boot-fast.elf
SOC_BOOT_FAST_HEX := $(SOC_BOOT_FAST_ELF).hex
$(SOC_BOOT_FAST_HEX): $(SOC_BOOT_FAST_ELF)
$(eval $(call SOC_SDRAM_PROGRAM,$(SOC_BOOT_FAST_ELF),$(SOC_BOOT_SRC),-DCRC32_SLICE_TABLES=1 -DMEMTEST_QUICK_RANDOM_BYTES=16384u))
soc_boot_elf = $(if $(filter $(SOC_SIM_CLK_HZ),$(1)),$(SOC_BOOT_ELF),$(BUILD)/soc/boot-$(1).elf)
soc_boot_rules = $(if $(filter $(SOC_SIM_CLK_HZ),$(1)),,$(eval $(call soc_boot_elf,$(1)).hex: $(call soc_boot_elf,$(1))) \
  $(eval $(call SOC_SDRAM_PROGRAM,$(call soc_boot_elf,$(1)),$(SOC_BOOT_SRC),-DCRC32_SLICE_TABLES=1,$(1))))
# The full memory test as a program (bsp/soc/boot/memtest_main.c): socsim's over the first 16 KiB,
# one pass (a pass over the whole chip is 570 M accesses); a board's tests the whole SDRAM for ever.
SOC_MEMTEST_ELF := $(BUILD)/soc/memtest.elf
SOC_MEMTEST_HEX := $(SOC_MEMTEST_ELF).hex
$(SOC_MEMTEST_HEX): $(SOC_MEMTEST_ELF)
$(eval $(call SOC_SDRAM_PROGRAM,$(SOC_MEMTEST_ELF),tests/soc/smoke_crt0.S bsp/soc/boot/memtest_main.c,-DMEMTEST_PROGRAM_BYTES=16384u -DMEMTEST_PROGRAM_PASSES=1u))
# The SDRAM's test program (tests/soc/sdram_test.c, suite soc-sdram).
SOC_SDRAM_TEST_ELF := $(BUILD)/soc/sdram_test.elf
SOC_SDRAM_TEST_HEX := $(SOC_SDRAM_TEST_ELF).hex
$(SOC_SDRAM_TEST_HEX): $(SOC_SDRAM_TEST_ELF)
$(eval $(call SOC_SDRAM_PROGRAM,$(SOC_SDRAM_TEST_ELF),tests/soc/smoke_crt0.S tests/soc/sdram_test.c))

SOCSIM_GPU_FLAGS          = -GSPAN_W=$(SPAN_W)$(SOCSIM_GPU_GFLAGS)
# make's own socsim: soc_top, or with SOC_MEM=sdram the system with SDRAM (its RAM the boot program's).
SOCSIM_SYSTEM := $(if $(SOC_MEM_SUFFIX),sdram,soc)
SOCSIM_CMD = $(call socsim_cmd,$(SOCSIM_DIR),$(SOCSIM_SYSTEM_$(SOCSIM_SYSTEM))$(if $(SOC_USB), $(SOCSIM_USB_PARAMS)),$(SOC_RAM_BYTES),\
  $(SOCSIM_GPU_FLAGS),$(SOCSIM_SOURCES_$(SOCSIM_SYSTEM)),$(SOCSIM_CFLAGS_$(SOCSIM_SYSTEM))$(if $(SOC_USB), $(SOCSIM_USB_CFLAGS)))

# The board build.
SOCSIM_ULX3S_DIR := $(BUILD)/socsim-ulx3s-$(SOC_RAM_KIB)k
SOCSIM_ULX3S     := $(SOCSIM_ULX3S_DIR)/socsim
SOCSIM_ULX3S_CMD  = $(call socsim_cmd,$(SOCSIM_ULX3S_DIR),$(SOCSIM_SYSTEM_ulx3s),$(SOC_RAM_BYTES),$(SOCSIM_GPU_FLAGS),\
  $(SOCSIM_SOURCES_ulx3s),$(SOCSIM_CFLAGS_ulx3s))

# The rules of one socsim build: its recorded command (without the job count: make test builds with
# VERILATOR_JOBS=1, then runs with the default) and the simulator. $(1) = directory, $(2) = the name
# of its command variable, $(3) = further prerequisites.
define SOCSIM_BUILD_RULES
$(1)/cmd.txt: fw-force
	$$(call fw_flags_file,$$@,$$(subst -j $$(VERILATOR_JOBS) ,,$$($(2))))

$(1)/socsim: $$(SOCSIM_DEPS) $(1)/cmd.txt $(3)
	@mkdir -p $(1)
	$$(Q)$$(call say,VERILATE,$(notdir $(1)))$$($(2)) >$(1)/verilator.log 2>&1 || { tail -40 $(1)/verilator.log; exit 1; }
endef
# The table's builds (mk/builds.toml [socsim]: make test's, the benchmarks'), then this make's own
# (SOC_RAM_KIB, ZBUF, SPAN_W, a manifest's GPU) where the table has no build of that name.
ifneq ($(GEN_READ),)
include $(GEN_DIR)/socsim.mk
endif
socsim_rules_unless_listed = $(if $(filter $(notdir $(1)),$(SOCSIM_IDS)),,$(eval $(call SOCSIM_BUILD_RULES,$(1),$(2),$(3))))
$(call socsim_rules_unless_listed,$(SOCSIM_DIR),SOCSIM_CMD,$(SOCSIM_PREREQS_$(SOCSIM_SYSTEM)))
$(call socsim_rules_unless_listed,$(SOCSIM_ULX3S_DIR),SOCSIM_ULX3S_CMD,$(SOCSIM_PREREQS_ulx3s))

.PHONY: socsim socsim-ulx3s run-soc soc-fw soc-test-deps soc-sdram-test-deps bench-soc profile-soc bench-cpu \
        soc-smoke
soc-fw:
	+@$(SOC_FW_MAKE) SCENE=$(SCENE) FRAMES=$(FRAMES) FW_BACKEND=$(FW_BACKEND) $(SOC_FW_ELF)

# SOC_MEM=sdram: the boot program in the RAM, the firmware's image in the flash.
SOCSIM_BOOT := $(if $(SOC_MEM_SUFFIX),$(SOC_BOOT_HEX))

ifeq ($(SOC_RAM_KIB),auto)
# The RAM is the firmware's (bsp/soc/soc_ram.mk): the firmware first, then these goals again on a
# RAM of the size it needs.
socsim socsim-ulx3s run-soc: soc-fw
	$(call soc_ram_again,$(SOC_FW_ELF))
else
socsim: $(SOCSIM)
socsim-ulx3s: $(SOCSIM_ULX3S)

# With a display (the Makefile's WINDOW), the frames go to a window instead of $(OUT)/frames.
run-soc: $(SOCSIM) soc-fw $(SOCSIM_BOOT)
	@rm -rf $(OUT)/frames && mkdir -p $(OUT)/frames
	$(Q)$(call say,RUN,socsim $(SOC_FW_ELF))$(SOCSIM) $(if $(SOCSIM_BOOT),--boot $(SOCSIM_BOOT)) --fw $(SOC_FW_ELF) $(if $(WINDOW),--window,--frames $(OUT)/frames) --uart-log $(OUT)/uart.log \
	  $(if $(UART_PTY),--uart-pty $(UART_PTY)) $(if $(SOC_USB),$(if $(WINDOW),--usb-window) \
	  $(if $(USB_KEYS),--usb-keys-at '1:$(subst ','\'',$(USB_KEYS))'))
endif

# The soc test programs (tests/soc/tests.mk), for the suites that need soc-programs
# (tests/suites.toml).
soc-test-deps:
	+@$(SOC_FW_MAKE) soc-test-elfs
# The same programs run from the SDRAM (SOC_MEM=sdram: $(BUILD)/fw-test-soc-sdram/*.elf.img).
# The model scene at the host builds' capacities (firmware.mk's defaults), so that its frames compare
# with theirs byte for byte (the SDRAM's own capacities: docs/boot.md).
soc-sdram-test-deps:
	+@$(MAKE) --no-print-directory FW_PLATFORM=soc BUILD=$(BUILD) SOC_MEM=sdram FW_DIR=$(BUILD)/firmware-soc-sdram \
	  FW_MODEL_MAX_VERTS=$(FW_MODEL_MAX_VERTS) FW_MODEL_MAX_FACES=$(FW_MODEL_MAX_FACES) soc-test-elfs

# The smoke program's RAM image on socsim, answering its UART prompts (tests/soc/smoke.sh; suite
# rtl-soc-smoke).
soc-smoke: $(SOCSIM) $(SOC_SMOKE_HEX)
	@BUILD=$(BUILD) SOCSIM=$(SOCSIM) SOC_SMOKE_HEX=$(SOC_SMOKE_HEX) bash tests/soc/smoke.sh

# What the core's pipeline charges for each hazard (bench/bench_cpu.py, tests/soc/pipeline_cycles.c):
# the weights of `make profile-fw PROFILE_HAZARDS=1`.
bench-cpu: $(SOCSIM)
	+@$(SOC_FW_MAKE) $(BUILD)/fw-test-soc/pipeline_cycles.elf
	@$(PYTHON) bench/bench_cpu.py $(SOCSIM) $(BUILD)/fw-test-soc/pipeline_cycles.elf

# The benchmark builds (firmware.mk's FW_BENCH_FRAMES frames) of every scene, each on socsim, one
# table (bench/bench_soc.py).
# SOC_MEM=sdram: the same from the SDRAM (the boot program first; its cycles are not the frames').
# One make a scene: the program's boot scene decides the model scene's capacities (bsp/soc/bsp.mk).
# FRAME_DRAM=1 (with SOC_MEM=sdram): the board's default memory system, the GPU's 640x480 frames in
# the SDRAM too, drawn in strips of 16 rows with the firmware's binning (mk/builds.toml's
# socsim-sdram-dram; the same programs, which read the GPU's frame and strips at start-up).
SOC_BENCH_DIR  := $(BUILD)/fw-bench-soc$(SOC_MEM_SUFFIX)
SOC_BENCH_ELFS := $(foreach s,$(FW_SCENES),$(s)=$(SOC_BENCH_DIR)/$(s).elf)
ifeq ($(FRAME_DRAM),1)
ifneq ($(SOC_MEM),sdram)
bench-soc profile-soc: SOC_BENCH_SOCSIM = $(error FRAME_DRAM=1 is the system with SDRAM's: add SOC_MEM=sdram)
else
SOC_BENCH_SOCSIM := $(BUILD)/socsim-sdram-dram-$(SOC_RAM_KIB)k/socsim
endif
else
SOC_BENCH_SOCSIM := $(SOCSIM)
endif
bench-soc: $(SOC_BENCH_SOCSIM) $(SOCSIM_BOOT)
	+@$(foreach s,$(FW_SCENES),$(SOC_FW_MAKE) SCENE=$(s) $(SOC_BENCH_DIR)/$(s).elf &&) true
	@$(PYTHON) bench/bench_soc.py --socsim $(SOC_BENCH_SOCSIM) $(if $(SOCSIM_BOOT),--boot $(SOCSIM_BOOT)) \
	  --out $(BUILD)/bench-soc$(SOC_MEM_SUFFIX)$(if $(filter 1,$(FRAME_DRAM)),-dram) $(SOC_BENCH_ELFS)

# One scene's benchmark build on socsim, its clocks, instructions and refills by function (and with
# PROFILE_LINES=N by source line): firmware/tools/profile_soc.py, socsim's --profile.
profile-soc: $(SOC_BENCH_SOCSIM) $(SOCSIM_BOOT)
	+@$(SOC_FW_MAKE) SCENE=$(SCENE) $(SOC_BENCH_DIR)/$(SCENE).elf
	@$(PYTHON) firmware/tools/profile_soc.py $(SOC_BENCH_SOCSIM) $(SOC_BENCH_DIR)/$(SCENE).elf \
	  $(if $(SOCSIM_BOOT),--boot $(SOCSIM_BOOT)) $(if $(PROFILE_LINES),--lines $(PROFILE_LINES))
