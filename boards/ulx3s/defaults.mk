# boards/ulx3s/defaults.mk — the ULX3S build's defaults, read by the Makefile before its own (FB,
# ZBUF) and bsp/soc/soc_ram.mk's (SOC_MEM) are set, so that only the goals that build for the board
# change them (make run and the simulators keep theirs).
#
# The board's default build keeps everything it can in the SDRAM: the firmware (SOC_MEM=sdram, booted
# from the flash), the GPU's two frames (FRAME_DRAM=1) at the contract's largest frame, 640x480 shown
# 1:1, drawn in strips whose colour and depth stay on chip — so the depth buffer costs no frame
# (ZBUF=1: a strip's depths, 12 EBR). It fits the 25F as well as the 85F (docs/board-ulx3s.md).
# Each default follows the one before it, unless given: SOC_MEM=ram (the on-chip build, netlist-sim's
# and crossings') leaves the frames on chip at 320x240 without a depth buffer, as before;
# SOC_MEM=sdram FRAME_DRAM=0 the firmware alone in the SDRAM.
ULX3S_DEFAULT_GOALS := bitstream synth-board ulx3s-dir flash load board-fw timing-groups
ifeq ($(or $(BOARD),ulx3s),ulx3s)
ifneq ($(filter $(ULX3S_DEFAULT_GOALS),$(MAKECMDGOALS)),)
SOC_MEM    ?= sdram
FRAME_DRAM ?= $(if $(filter sdram,$(SOC_MEM)),1,0)
ifeq ($(FRAME_DRAM),1)
FB         ?= $(CONTRACT_FB_MAX)
ZBUF       ?= 1
endif
endif
endif
