# bsp/soc/bsp.mk — what firmware/firmware.mk needs to build for the FPGA SoC (soc_rtl/soc_top:
# VexRiscv_FullCfu with the projection unit, rv32im, on-chip RAM at 0). Set on the command line:
#   SOC_RAM_KIB   on-chip RAM in KiB (default: contract/soc_map.h SOC_RAM_DEFAULT_BYTES, or the
#                 image's own need in a scene's manifest build, mk/manifest.mk). The link does
#                 not depend on it (linker/soc.ld: the stack sits above .bss); postlink refuses an
#                 image that does not fit it and writes the image's need to <elf>.ramkib.
#   FW_MAX_POLLS  the watchdog's DONE_SEQ reads per batch (default: about one second at 50 MHz).

include bsp/soc/soc_ram.mk

# A chip build holds its boot scene only (firmware.mk FW_SCENE_SET): 192 KiB are not enough for all.
FW_SCENE_SET ?= one
# The SoC's GPU draws lines (CAPS_LINES, the contract's default): no room for emulated ones.
FW_LINE_EMULATION ?= 0
# Its GPU draws into its frame (STRIP_ROWS 0): with the firmware in the on-chip RAM there is no
# room for the strip binning (FW_WITH_STRIPS, about 4 KiB of code and list heads) either, unless
# FW_DEFS asks for it. With SOC_MEM=sdram it stays in.
ifneq ($(SOC_MEM),sdram)
ifeq ($(findstring FW_WITH_STRIPS,$(FW_DEFS)),)
FW_DEFS += -DFW_WITH_STRIPS=0
endif
endif

# The core's projection unit (soc_rtl/soc_proj_unit.v, firmware/render/proj_unit.h): every
# vertex through it, unless FW_DEFS says -DFW_PROJ_UNIT=0.
ifeq ($(findstring FW_PROJ_UNIT,$(FW_DEFS)),)
FW_DEFS += -DFW_PROJ_UNIT=1
endif

FW_CC         = $(RV_CC)
FW_OBJDUMP    = $(patsubst %gcc,%objdump,$(RV_CC))
FW_ARCH_FLAGS = -march=rv32im -misa-spec=2.2 -mabi=ilp32 -mcmodel=medlow --specs=picolibc.specs \
                -DPICOLIBC_INTEGER_PRINTF_SCANF
FW_BSP_SRCS   = $(wildcard bsp/soc/*.c) $(wildcard bsp/rv32/*.c)
FW_LDSCRIPT   = linker/soc.ld
# The start is the BSP's own (crt0.c: picolibc's crt0 "hosted" in its steps, without its relaxed load of
# an absolute symbol); it calls exit(main()), and the BSP's _exit() writes SYS EXIT.
FW_BSP_LDFLAGS = -nostartfiles -Wl,--no-warn-rwx-segments -Wl,--defsym=__stack_size=$(FW_STACK_BYTES)
# After linking: <elf>.hex (RAM_INIT, one 32-bit word per line) and <elf>.ramkib (the RAM it needs),
# or a build error with the sizes when the image, its bss and the stack do not fit the RAM the build
# checks against (SOC_FW_RAM_BYTES, bsp/soc/soc_ram.mk; the ELF is then deleted).
FW_POSTLINK   = $(or $(PYTHON),python3) bsp/soc/postlink.py --ram-bytes $(SOC_FW_RAM_BYTES) \
                --size $(patsubst %gcc,%size,$(RV_CC)) --nm $(patsubst %gcc,%nm,$(RV_CC))
# One DONE_SEQ poll is an uncached bus read plus the loop: 9.00 cycles, measured on socsim by
# tests/soc/poll_cycles.c (suite soc-poll-cycles), so 5,000,000 polls are 0.9 s at 50 MHz.
ifeq ($(strip $(FW_MAX_POLLS)),)
FW_MAX_POLLS := 5000000
endif

# SOC_MEM=sdram (bsp/soc/soc_ram.mk): linked at the SDRAM's base, checked against its size, and
# written as the boot image <elf>.img (bsp/soc/mkimage.py) for the flash instead of a RAM image.
ifeq ($(SOC_MEM),sdram)
# The model scene holds the SDRAM's capacities (firmware.mk's fw_sdram_model_cap) in a program that
# has it; firmware.mk decides by the scene set.
FW_MODEL_SDRAM_CAPS := 1
FW_BSP_LDFLAGS += -Wl,--defsym=__ram=$(SOC_SDRAM_BASE)
# The on-chip RAM above the boot program's image is the firmware's once it runs (linker/soc.ld's
# .fast): the stack at its top, the FW_FAST_DATA objects at its bottom; postlink checks they fit.
SOC_FAST_BASE := $(shell echo $$(( $(call soc_map_value,SOC_RAM_BASE) + $(call soc_map_value,SOC_RAM_BOOT_IMAGE_BYTES) )))
SOC_FAST_TOP  := $(shell echo $$(( $(call soc_map_value,SOC_RAM_BASE) + $(call soc_map_value,SOC_RAM_BOOT_BYTES) )))
FW_BSP_LDFLAGS += -Wl,--defsym=__fast=$(SOC_FAST_BASE) -Wl,--defsym=__stack=$(SOC_FAST_TOP)
FW_DEFS += -DFW_FAST_RAM=1
FW_POSTLINK   = $(or $(PYTHON),python3) bsp/soc/postlink.py --image --ram-bytes $(SOC_SDRAM_CPU_BYTES) \
                --size $(patsubst %gcc,%size,$(RV_CC)) --nm $(patsubst %gcc,%nm,$(RV_CC))
endif

# How to run an ELF: append `-kernel ELF` (the soc simulator, built for SOC_RAM_KIB; with SOC_MEM=sdram
# the system with SDRAM, its on-chip RAM holding the boot program, the ELF's image in the flash).
FW_RUN        = $(if $(filter sdram,$(SOC_MEM)),$(BUILD)/socsim-sdram-$(SOC_RAM_KIB)k/socsim --boot $(SOC_BOOT_HEX),$(BUILD)/socsim-$(SOC_RAM_KIB)k/socsim)
