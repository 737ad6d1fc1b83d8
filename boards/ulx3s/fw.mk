# boards/ulx3s/fw.mk — the board's firmware, built by a recursive make for FW_PLATFORM=soc
# (boards/ulx3s/board.mk: `$(MAKE) FW_PLATFORM=soc -f Makefile -f boards/ulx3s/fw.mk ulx3s-fw-elf`):
# SCENE's one-scene build that renders until Q (FRAMES 0), for the RAM of SOC_RAM_KIB, as
# BOARD_FW_ELF (board.mk names it), with BOARD_FW_DEFS' -D settings of app.c (USB=1's keyboard).
ifneq ($(FW_PLATFORM),soc)
$(error boards/ulx3s/fw.mk is for FW_PLATFORM=soc)
endif
ifeq ($(BOARD_FW_ELF),)
$(error boards/ulx3s/fw.mk needs BOARD_FW_ELF)
endif
$(eval $(call FW_ELF_RULES,$(BOARD_FW_ELF),$(SCENE),fixed,0,,$(BOARD_FW_DEFS)))

.PHONY: ulx3s-fw-elf
ulx3s-fw-elf: $(BOARD_FW_ELF)
