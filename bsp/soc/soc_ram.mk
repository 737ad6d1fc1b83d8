# bsp/soc/soc_ram.mk — the SoC's RAM size as make variables, one place for its users: the RTL
# (cosim/soc/socsim.mk, boards/ulx3s/board.mk: RAM_BYTES) and the firmware's fit check
# (bsp/soc/bsp.mk: postlink --ram-bytes). Set SOC_RAM_KIB on the command line; the default and the
# limit come from contract/soc_map.h (SOC_RAM_DEFAULT_BYTES, SOC_RAM_WINDOW_BYTES).
#
# SOC_RAM_KIB=auto (a scene's manifest build, mk/manifest.mk): the RAM is what the linked image
# needs. The link does not depend on the RAM (linker/soc.ld), so the firmware is linked first and
# checked against the whole window (SOC_FW_RAM_BYTES), postlink writes its need to <elf>.ramkib, and
# the goals that build hardware run again with SOC_RAM_KIB=<that need> (soc_ram_again below).
ifndef SOC_RAM_MK_INCLUDED
SOC_RAM_MK_INCLUDED := 1
SOC_MAP_H           := contract/soc_map.h
# A constant of contract/soc_map.h, hexadecimal or decimal, as a decimal number (in KiB: soc_map_kib).
soc_map_value        = $(shell printf '%d' $$(sed -n 's/^\#define $(1) *\(0x[0-9A-Fa-f]*\|[0-9][0-9]*\).*/\1/p' $(SOC_MAP_H)))
soc_map_kib          = $(shell echo $$(( $(call soc_map_value,$(1)) / 1024 )))
# SOC_MEM: where the firmware runs. ram: the on-chip RAM (loaded with the bitstream, or by socsim);
# sdram: the SDRAM, linked at its base and copied there from the flash by the boot program
# (docs/boot.md), the on-chip RAM then the boot program's (SOC_RAM_BOOT_BYTES).
SOC_MEM             ?= ram
ifeq ($(filter $(SOC_MEM),ram sdram),)
$(error SOC_MEM=$(SOC_MEM): ram (the on-chip RAM) or sdram (the SDRAM, booted from the flash))
endif
SOC_SDRAM_BASE      := $(call soc_map_value,SOC_SDRAM_BASE)
SOC_SDRAM_BYTES     := $(call soc_map_value,SOC_SDRAM_DEFAULT_BYTES)
# The firmware's share of it: below the GPU's frames (contract/soc_map.toml gpu_frames_offset).
SOC_SDRAM_CPU_BYTES := $(call soc_map_value,SOC_SDRAM_GPU_FRAMES_OFFSET)
SOC_RAM_BOOT_KIB    := $(call soc_map_kib,SOC_RAM_BOOT_BYTES)
ifeq ($(SOC_MEM),sdram)
SOC_RAM_KIB         := $(SOC_RAM_BOOT_KIB)
endif
# The folders of an SDRAM build's firmware and simulator carry it in their names.
SOC_MEM_SUFFIX      := $(if $(filter sdram,$(SOC_MEM)),-sdram)
SOC_RAM_DEFAULT_KIB := $(call soc_map_kib,SOC_RAM_DEFAULT_BYTES)
SOC_RAM_WINDOW_KIB  := $(call soc_map_kib,SOC_RAM_WINDOW_BYTES)
SOC_RAM_KIB         ?= $(SOC_RAM_DEFAULT_KIB)
ifeq ($(SOC_RAM_KIB),auto)
SOC_FW_RAM_BYTES    ?= $(shell echo $$(( $(SOC_RAM_WINDOW_KIB) * 1024 )))
SOC_RAM_BYTES        = $(error SOC_RAM_KIB=auto: the RAM's size is known only after the link (soc_ram_again))
else
ifneq ($(shell test '$(SOC_RAM_KIB)' -ge 1 -a '$(SOC_RAM_KIB)' -le '$(SOC_RAM_WINDOW_KIB)' 2>/dev/null && echo ok),ok)
$(error SOC_RAM_KIB=$(SOC_RAM_KIB): the SoC's RAM window holds 1 to $(SOC_RAM_WINDOW_KIB) KiB (contract/soc_map.h))
endif
SOC_RAM_BYTES       := $(shell echo $$(( $(SOC_RAM_KIB) * 1024 )))
SOC_FW_RAM_BYTES    ?= $(SOC_RAM_BYTES)
endif
# $(call soc_ram_again,ELF): a recipe line running this make's goal again for the RAM that ELF
# needs; the firmware keeps the window as its fit check, so its flags, and so the ELF, stay as built.
soc_ram_again = +@$(MAKE) --no-print-directory $@ SOC_RAM_KIB=$$(cat $(1).ramkib) SOC_FW_RAM_BYTES=$(SOC_FW_RAM_BYTES)
endif
