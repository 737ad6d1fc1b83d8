# tests/soc/tests.mk — the soc test programs, read by the Makefile when the firmware is built for
# FW_PLATFORM=soc (`make soc-test-deps`, cosim/soc/socsim.mk, runs `$(MAKE) FW_PLATFORM=soc
# soc-test-elfs`), so that the platform's flags and objects are firmware.mk's:
#   $(SOC_TEST_DIR)/<scene>.elf     make test's programs (mk/builds.toml fw.fw-test) of every scene
#   $(SOC_TEST)                     mk/builds.toml's fw.soc-test: 2 frames of every scene, a tiny
#                                   watchdog, the model scene for an upload, tetra and cubes with the
#                                   USB keyboard (tetra also until Q, for the window); with
#                                   SOC_MEM=sdram fw.soc-tour's program too
#   $(SOC_TEST_DIR)/bus_error.elf   tests/soc/bus_error.c with the soc BSP
#   $(SOC_TEST_DIR)/poll_cycles.elf tests/soc/poll_cycles.c with the GPU driver and the BSP
#   $(SOC_TEST_DIR)/pipeline_cycles.elf tests/soc/pipeline_cycles.c with the BSP (`make bench-cpu`)
SOC_TEST_DIR   := $(FW_TEST_DIR)

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
$(eval $(call SOC_TEST_PROGRAM,pipeline_cycles,))

.PHONY: soc-test-elfs
# Every scene's one-scene build fits the default 192 KiB (`make fw-size`, suite fw-fit).
soc-test-elfs: $(foreach s,$(FW_SCENES),$(SOC_TEST_DIR)/$(s).elf) $(SOC_TEST) \
               $(SOC_TEST_DIR)/bus_error.elf $(SOC_TEST_DIR)/poll_cycles.elf \
               $(SOC_TEST_DIR)/pipeline_cycles.elf
