# boards/ulx3s/fw.mk — the board's firmware, built by a recursive make for FW_PLATFORM=soc
# (boards/ulx3s/board.mk: `$(MAKE) FW_PLATFORM=soc -f Makefile -f boards/ulx3s/fw.mk board-fw`):
# SCENE's one-scene build that renders until Q (FRAMES 0), for the RAM of SOC_RAM_KIB.
ifneq ($(FW_PLATFORM),soc)
$(error boards/ulx3s/fw.mk is for FW_PLATFORM=soc)
endif
BOARD_FW_ELF ?= $(BUILD)/board-fw/$(SCENE)-$(SOC_RAM_KIB)k.elf
$(eval $(call FW_ELF_RULES,$(BOARD_FW_ELF),$(SCENE),fixed,0,))

.PHONY: board-fw
board-fw: $(BOARD_FW_ELF)
