# tests/soc/tests.mk — the soc test programs, built by a recursive make for FW_PLATFORM=soc
# (`make soc-test-deps`, cosim/soc/socsim.mk: `$(MAKE) FW_PLATFORM=soc -f Makefile -f
# tests/soc/tests.mk soc-test-elfs`), so that the platform's flags and objects are firmware.mk's:
#   $(SOC_TEST_DIR)/<scene>.elf            the FW_TEST_FRAMES builds (firmware.mk's) of every scene
#   $(SOC_TEST_DIR)/<scene>-2f.elf         the same with SOC_SHORT_FRAMES (2) frames: a scene whose
#                                          start-up costs millions of simulated cycles (landscape
#                                          builds its terrain) is compared on fewer frames
#   $(SOC_TEST_DIR)/tetra-watchdog-tiny.elf  tetra, 5 frames, a watchdog of SOC_TINY_POLLS DONE_SEQ
#                                          reads: every batch outlasts it (tests/soc/watchdog.sh)
#   $(SOC_TEST_DIR)/model-upload.elf       the model scene, SOC_UPLOAD_FRAMES (10) frames: a model is
#                                          uploaded into it over the UART line (tests/soc/upload.sh)
#   $(SOC_TEST_DIR)/tetra-window.elf       tetra until Q (FRAMES 0): only closing socsim's window
#                                          ends it (tests/window/window.sh)
#   $(SOC_TEST_DIR)/bus_error.elf          tests/soc/bus_error.c with the soc BSP
#   $(SOC_TEST_DIR)/poll_cycles.elf        tests/soc/poll_cycles.c with the GPU driver and the BSP
ifneq ($(FW_PLATFORM),soc)
$(error tests/soc/tests.mk is for FW_PLATFORM=soc)
endif

SOC_TEST_DIR   := $(FW_TEST_DIR)
SOC_TINY_POLLS := 16
SOC_SHORT_FRAMES := 2
$(foreach s,$(FW_SCENES),$(eval $(call FW_ELF_RULES,$(SOC_TEST_DIR)/$(s)-2f.elf,$(s),fixed,$(SOC_SHORT_FRAMES),)))
$(eval $(call FW_ELF_RULES,$(SOC_TEST_DIR)/tetra-watchdog-tiny.elf,tetra,fixed,5,$(SOC_TINY_POLLS)))
SOC_UPLOAD_FRAMES := 10
$(eval $(call FW_ELF_RULES,$(SOC_TEST_DIR)/model-upload.elf,model,fixed,$(SOC_UPLOAD_FRAMES),))
$(eval $(call FW_ELF_RULES,$(SOC_TEST_DIR)/tetra-window.elf,tetra,fixed,0,))

SOC_BSP_OBJS := $(patsubst %.c,$(FW_OBJ_DIR_fixed)/%.o,$(FW_BSP_SRCS))
SOC_DRIVER_OBJ := $(FW_OBJ_DIR_fixed)/$(FW_DRIVER_SRC:.c=.o)

$(SOC_TEST_DIR)/%.o: tests/soc/%.c $(FW_OBJ_DIR_fixed)/cflags.txt
	@mkdir -p $(@D)
	$(Q)$(call say,CC,$<)$(FW_CC) $(FW_CFLAGS_fixed) -MMD -MP -c $< -o $@

# $(1) = program name, $(2) = further objects
define SOC_TEST_PROGRAM
$(SOC_TEST_DIR)/$(1).elf: $(SOC_TEST_DIR)/$(1).o $(2) $(SOC_BSP_OBJS) $(FW_LDSCRIPT)
	$$(Q)$$(call say,LD,$$@)$$(FW_CC) $$(FW_LDFLAGS_BASE) -o $$@ $(SOC_TEST_DIR)/$(1).o $(2) $(SOC_BSP_OBJS)
	$$(if $$(FW_POSTLINK),$$(Q)$$(call say,POSTLINK,$$@)$$(FW_POSTLINK) $$@)

-include $(SOC_TEST_DIR)/$(1).d
endef
$(eval $(call SOC_TEST_PROGRAM,bus_error,))
$(eval $(call SOC_TEST_PROGRAM,poll_cycles,$(SOC_DRIVER_OBJ)))

.PHONY: soc-test-elfs
# Every scene's one-scene build fits the default 192 KiB (`make fw-size`, suite fw-fit).
soc-test-elfs: $(foreach s,$(FW_SCENES),$(SOC_TEST_DIR)/$(s).elf $(SOC_TEST_DIR)/$(s)-2f.elf) \
               $(SOC_TEST_DIR)/tetra-watchdog-tiny.elf $(SOC_TEST_DIR)/model-upload.elf $(SOC_TEST_DIR)/tetra-window.elf \
               $(SOC_TEST_DIR)/bus_error.elf $(SOC_TEST_DIR)/poll_cycles.elf
