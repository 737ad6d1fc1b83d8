# bsp/soc/soc_ram.mk — the SoC's RAM size as make variables, one place for the two users that must
# agree: the firmware's link (bsp/soc/bsp.mk: --defsym=__ram_size) and the RTL (cosim/soc/socsim.mk:
# RAM_BYTES). Set SOC_RAM_KIB on the command line; the default and the limit come from
# contract/soc_map.h (SOC_RAM_DEFAULT_BYTES, SOC_RAM_WINDOW_BYTES).
ifndef SOC_RAM_MK_INCLUDED
SOC_RAM_MK_INCLUDED := 1
SOC_MAP_H           := contract/soc_map.h
soc_map_kib          = $(shell printf '%d' $$(( $$(sed -n 's/^\#define $(1) *\(0x[0-9A-Fa-f]*\).*/\1/p' $(SOC_MAP_H)) / 1024 )))
SOC_RAM_DEFAULT_KIB := $(call soc_map_kib,SOC_RAM_DEFAULT_BYTES)
SOC_RAM_WINDOW_KIB  := $(call soc_map_kib,SOC_RAM_WINDOW_BYTES)
SOC_RAM_KIB         ?= $(SOC_RAM_DEFAULT_KIB)
ifneq ($(shell test '$(SOC_RAM_KIB)' -ge 1 -a '$(SOC_RAM_KIB)' -le '$(SOC_RAM_WINDOW_KIB)' 2>/dev/null && echo ok),ok)
$(error SOC_RAM_KIB=$(SOC_RAM_KIB): the SoC's RAM window holds 1 to $(SOC_RAM_WINDOW_KIB) KiB (contract/soc_map.h))
endif
SOC_RAM_BYTES       := $(shell echo $$(( $(SOC_RAM_KIB) * 1024 )))
endif
