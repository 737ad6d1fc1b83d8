# firmware/firmware.mk — firmware build, included by the top-level Makefile (paths are relative
# to the repository root, where that Makefile lives).
#
# Inputs (set before or on the command line):
#   BUILD          output directory                       (default build)
#   FRAMES         frames the firmware renders, -DFW_FRAMES (default 24)
#   RV_CC          cross compiler                         (default riscv64-unknown-elf-gcc)
#   HOST_CC        host compiler for the unit tests       (default gcc)
#   HOST_CFLAGS    host flags, extended by the firmware's warnings and include paths
#   FW_PLATFORM    bsp/<platform>/ to build for           (default qemu_virt)
#   FW_MAX_POLLS   optional -DFW_GPU_MAX_POLLS override (DONE_SEQ reads before a timeout)
#
# Outputs:
#   $(FW_ELF)                  = $(BUILD)/firmware/tetra.elf (+ .map, .lst next to it)
#   $(FW_UNIT)                 = $(BUILD)/tests/fw_unit, host unit tests of the pure code
# Convenience targets: fw (the ELF), fw-unit (build and run the unit tests), fw-smoke (boot the ELF
# in QEMU without a GPU and check the two failure paths: "GPU not found", and a bounded timeout when
# the GPU's ID registers are present but nothing answers the doorbell).

BUILD       ?= build
FRAMES      ?= 24
RV_CC       ?= riscv64-unknown-elf-gcc
HOST_CC     ?= gcc
HOST_CFLAGS ?= -std=c11 -O2 -g -Wall -Wextra -Werror
FW_PLATFORM ?= qemu_virt
FW_MAX_POLLS ?=

include bsp/$(FW_PLATFORM)/bsp.mk

FW_ELF  := $(BUILD)/firmware/tetra.elf
FW_UNIT := $(BUILD)/tests/fw_unit
FW_OBJ  := $(BUILD)/firmware/obj

# Pure sources (no hardware access: built for the target and for the host tests), and the
# hardware edge (target only).
FW_PURE_SRCS := firmware/src/fixed.c firmware/src/xform.c firmware/src/render.c \
                firmware/src/scene.c
FW_EDGE_SRCS := firmware/src/gpu.c firmware/src/main.c
FW_SRCS      := $(FW_PURE_SRCS) $(FW_EDGE_SRCS) $(FW_BSP_SRCS)

FW_WARN   := -std=c11 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes
FW_DEFS   := -DFW_FRAMES=$(FRAMES) $(if $(FW_MAX_POLLS),-DFW_GPU_MAX_POLLS=$(FW_MAX_POLLS))
FW_CFLAGS := $(FW_ARCH_FLAGS) -O2 -g $(FW_WARN) -ffunction-sections -fdata-sections \
             -Ibsp/$(FW_PLATFORM) -Ifirmware/include -Ifirmware/src $(FW_DEFS)
FW_LDFLAGS := $(FW_ARCH_FLAGS) $(FW_BSP_LDFLAGS) -T$(FW_LDSCRIPT) -Wl,--gc-sections \
              -Wl,-Map=$(FW_ELF:.elf=.map)

FW_OBJS := $(patsubst %.c,$(FW_OBJ)/%.o,$(FW_SRCS))

# Rebuild when the flags change (FRAMES=…), not only when sources do.
$(FW_OBJ)/cflags.txt: fw-force
	@mkdir -p $(@D)
	@echo '$(FW_CC) $(FW_CFLAGS)' | cmp -s - $@ || echo '$(FW_CC) $(FW_CFLAGS)' > $@

$(FW_OBJ)/%.o: %.c $(FW_OBJ)/cflags.txt
	@mkdir -p $(@D)
	$(FW_CC) $(FW_CFLAGS) -MMD -MP -c $< -o $@

$(FW_ELF): $(FW_OBJS) $(FW_LDSCRIPT)
	$(FW_CC) $(FW_LDFLAGS) -o $@ $(FW_OBJS)
	$(FW_OBJDUMP) -d -S $@ > $(@:.elf=.lst)

# ---- host unit tests -------------------------------------------------------------------------
# gpu.c is built against tests/firmware/fake_bsp/bsp.h (the GPU aperture is an array).

FW_UNIT_OBJ    := $(BUILD)/tests/fw_unit_obj
FW_UNIT_SRCS   := $(wildcard tests/firmware/*.c) $(FW_PURE_SRCS) firmware/src/gpu.c
FW_UNIT_CFLAGS  = $(HOST_CFLAGS) $(FW_WARN) -Itests/firmware/fake_bsp -Itests/firmware \
                  -Ifirmware/include -Ifirmware/src
FW_UNIT_OBJS   := $(patsubst %.c,$(FW_UNIT_OBJ)/%.o,$(FW_UNIT_SRCS))

$(FW_UNIT_OBJ)/cflags.txt: fw-force
	@mkdir -p $(@D)
	@echo '$(HOST_CC) $(FW_UNIT_CFLAGS)' | cmp -s - $@ || echo '$(HOST_CC) $(FW_UNIT_CFLAGS)' > $@

$(FW_UNIT_OBJ)/%.o: %.c $(FW_UNIT_OBJ)/cflags.txt
	@mkdir -p $(@D)
	$(HOST_CC) $(FW_UNIT_CFLAGS) -MMD -MP -c $< -o $@

$(FW_UNIT): $(FW_UNIT_OBJS)
	$(HOST_CC) -o $@ $(FW_UNIT_OBJS) -lm

-include $(FW_OBJS:.o=.d) $(FW_UNIT_OBJS:.o=.d)

# ---- convenience ----------------------------------------------------------------------------

# Fake GPU registers for fw-smoke: ID, VERSION, VTX_CAP, TRI_CAP, FB_SIZE as the contract says,
# preloaded by QEMU's generic loader; nothing answers DOORBELL, so frame 0 must time out.
FW_FAKE_GPU_REGS := \
  -device loader,addr=0x87000000,data=0x47505530,data-len=4 \
  -device loader,addr=0x87000004,data=0x00010000,data-len=4 \
  -device loader,addr=0x8700000c,data=1024,data-len=4 \
  -device loader,addr=0x87000010,data=1024,data-len=4 \
  -device loader,addr=0x87000014,data=0x00f00140,data-len=4

.PHONY: fw fw-unit fw-smoke fw-force
fw: $(FW_ELF)

fw-unit: $(FW_UNIT)
	$(FW_UNIT)

fw-smoke: $(FW_ELF)
	@echo "fw-smoke: no GPU -> expect 'GPU not found' and exit status 2"
	@timeout 20 $(FW_RUN) -kernel $(FW_ELF) > $(BUILD)/firmware/smoke-nogpu.log; rc=$$?; \
	  cat $(BUILD)/firmware/smoke-nogpu.log; \
	  grep -q '^tetra fw' $(BUILD)/firmware/smoke-nogpu.log && \
	  grep -q 'GPU not found' $(BUILD)/firmware/smoke-nogpu.log && test $$rc -eq 2 || \
	  { echo "fw-smoke: FAILED (status $$rc)"; exit 1; }
	@echo "fw-smoke: silent GPU -> expect a bounded timeout and exit status 4"
	@timeout 60 $(FW_RUN) $(FW_FAKE_GPU_REGS) -kernel $(FW_ELF) > $(BUILD)/firmware/smoke-timeout.log; \
	  rc=$$?; cat $(BUILD)/firmware/smoke-timeout.log; \
	  grep -q 'GPU timeout' $(BUILD)/firmware/smoke-timeout.log && test $$rc -eq 4 || \
	  { echo "fw-smoke: FAILED (status $$rc)"; exit 1; }
	@echo "fw-smoke: passed"

fw-force:
