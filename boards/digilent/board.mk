# boards/digilent/board.mk — the Digilent Artix-7 boards (Basys3, Nexys A7-100T): tops and
# constraints for Vivado users; included by the top-level Makefile.
#   synth-board BOARD=basys3|nexys_a7   yosys synth_xilinx resource counts against the part
#                                       (synth/synth_xilinx.sh, about 4½ minutes; RAM_BYTES=…)
#   bitstream BOARD=basys3|nexys_a7     not here: Vivado's (boards/digilent/build.tcl)
#   lint-board                          also lints these tops (boards/digilent/lint.sh)
DIGILENT_BOARDS := basys3 nexys_a7

ifneq ($(filter $(DIGILENT_BOARDS),$(BOARD)),)
synth-board: $(SOC_VENV)
	@bash tools/setup.sh packages-synth.txt
	$(Q)$(call say,SYNTH,$(BOARD))bash synth/synth_xilinx.sh $(BOARD) $(BUILD)

bitstream flash load:
	@echo "$@ BOARD=$(BOARD): needs Vivado, which is not part of this project's set-up:"
	@echo "  vivado -mode batch -source boards/digilent/build.tcl -tclargs $(BOARD)   (see boards/$(BOARD)/README.md)"
	@exit 1
endif
