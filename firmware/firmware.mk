# firmware/firmware.mk — firmware build, included by the top-level Makefile (paths are relative
# to the repository root, where that Makefile lives).
#
# Inputs (set before or on the command line):
#   BUILD          output directory                                  (default build)
#   SCENE          scene shown at boot, one of the scene table's (firmware/scenes/scene_list.h:
#                  tetra cubes landscape voxel knot)                  (default tetra)
#   FW_BACKEND     arithmetic of the pipeline: fixed or float          (default fixed)
#   FRAMES         frames the firmware renders, -DFW_FRAMES; 0 = until Q (default 24)
#   RV_CC          cross compiler                         (default riscv64-unknown-elf-gcc)
#   HOST_CC        host compiler for the host build and the unit tests (default gcc)
#   HOST_CFLAGS    host flags, extended by the firmware's warnings and include paths
#   FW_PLATFORM    bsp/<platform>/ to build for           (default qemu_virt); another platform's
#                  objects and ELFs go to $(BUILD)/firmware-<p>/, fw-test-<p>/, ... so that both
#                  coexist in one tree
#   FW_SCENE_SET   one: an ELF holds only its boot scene SCENE (code, data, and memory sized for
#                  it: scenes/scene_set.h); all: every scene of the table, keys 1..N switch
#                  (default all; a platform's bsp.mk may set another default: FW_SCENE_SET ?= one)
#   FW_STACK_BYTES the stack a chip build reserves, for `make fw-size` (default 4096: the deepest
#                  call chain of every scene's image, trap handler on top, is 1664 bytes by
#                  firmware/tools/stack_depth.py, and fw-size fails if one reaches the reserve)
#   FW_MAX_POLLS   optional -DFW_GPU_MAX_POLLS override (the watchdog: DONE_SEQ reads per batch)
#   FW_PROFILE     1: every frame also prints where its instructions went (app.c)
#   FW_SUBPIXEL_BITS  fraction bits kept in projected vertices, 0..4 (default: 4, the contract's
#                  Q12.4); an accuracy knob (proj.h), measured by `make bench-error`
#   FW_LINE_EMULATION  1: the wireframe on a GPU without line primitives draws each edge as two
#                  triangles, and every frame reserves room for that (the wireframe columns of
#                  scenes/scene_list.h); 0: it does not (the F key then says so on such a GPU) and
#                  the frame needs only the filled columns: -DFW_WITH_LINE_EMULATION (default 1;
#                  a platform whose GPU has CAPS_LINES may set FW_LINE_EMULATION ?= 0 in bsp.mk)
#   FW_DEFS        further -D settings of every object, e.g. "-DFW_WITH_LIGHTING=0" (config/build_options.h:
#                  the FW_WITH_* features a scene may not need)
#   GPUSIM         the co-simulator (set by the top-level Makefile), for bench-fw
#
# From bsp/<platform>/bsp.mk: FW_CC FW_OBJDUMP FW_ARCH_FLAGS FW_BSP_SRCS FW_LDSCRIPT FW_BSP_LDFLAGS
# FW_RUN, and optionally FW_POSTLINK (a command run as `$(FW_POSTLINK) <elf>` after every link,
# e.g. to make a memory image and refuse one larger than the chip's RAM), FW_SCENE_SET and
# FW_LINE_EMULATION.
#
# Outputs:
#   $(FW_ELF)       = $(FW_DIR)/$(SCENE)[-float].elf (+ .map; its .lst from make fw or make
#                     <elf without .elf>.lst): what `make run` runs;
#                     FW_DIR = $(BUILD)/firmware, or $(BUILD)/firmware-<p> for FW_PLATFORM=<p>
#   $(FW_HOST)      = $(BUILD)/fw-host/$(SCENE)[-float]: the same firmware on the host, rendering
#                     through the golden model (bsp/host)
#   $(FW_UNIT)      = $(BUILD)/tests/fw_unit, host unit tests of the pure code (fixed backend)
#   $(FW_UNIT_FLOAT)= $(BUILD)/tests/fw_unit_float, the same tests on the float backend
#   $(FW_UNIT_WIDE) = $(BUILD)/tests/fw_unit_wide, the same tests (fixed) at the SDRAM builds'
#                     model capacities: the render frame's 32-bit indices
#   the programs of mk/builds.toml's [fw.*] families (make test's FW_TEST_FRAMES builds under
#                   $(BUILD)/fw-test[-<p>], bench-fw's, bench-error's fixed, float, depth-tested,
#                   sub-pixel, Newton-step and sine-table builds and camera paths, fw-size's):
#                   their rules are generated from that table (docs/build.md)
#   fw-size         the memory table of every scene's one-scene build (and the all-scene one):
#                   text, data, bss, stack against the chip targets (firmware/tools/fw_size.sh)
# Convenience targets: fw, fw-all (every scene, both backends), fw-host, fw-unit, fw-smoke,
# bench-fw (the instruction-count table of every scene and backend, measured in co-simulation),
# profile-fw (one scene's instructions per function and frame; PROFILE_LINES=N: and its N hottest
# source lines; PROFILE_HAZARDS=1: and the pipeline's hazards, weighted with make bench-cpu's charges).
#
# Objects are shared by every program of the same variant and flags (mk/builds.toml's
# [fw_variant]; $(BUILD)/fw-obj[-<p>|-host]/<variant>-<checksum of the flags>/); only app.c, which
# carries the scene name, the frame count, the watchdog bound and the scene set (FW_BUILT_SCENES:
# which descriptors the table references, and the memory sized for them), is compiled per ELF; an
# ELF links the objects of its scenes only.
# A change of flags rebuilds by itself (cflags.txt).

BUILD       ?= build
SCENE       ?= tetra
FW_BACKEND  ?= fixed
FRAMES      ?= 24
RV_CC       ?= riscv64-unknown-elf-gcc
HOST_CC     ?= gcc
HOST_CFLAGS ?= -std=c11 -O2 -g -Wall -Wextra -Werror
FW_PLATFORM ?= qemu_virt
FW_MAX_POLLS ?=
FW_PROFILE  ?=
FW_SUBPIXEL_BITS ?=
FW_DEFS     ?=
GPUSIM      ?= $(BUILD)/sim/gpusim
FW_STACK_BYTES ?= 4096

# The model scene's capacities with the firmware in an SDRAM ($(1): verts or faces): its manifest's
# sdram_max_* (the SDRAM builds' default, bsp/soc/bsp.mk, and the wide unit tests', below).
fw_sdram_model_cap = $(shell sed -n 's/^sdram_max_$(1) *= *\([0-9]*\).*/\1/p' firmware/scenes/model.manifest.toml)
include bsp/$(FW_PLATFORM)/bsp.mk

# After bsp.mk, which may choose another default for its platform.
FW_SCENE_SET ?= all
FW_LINE_EMULATION ?= 1
ifeq ($(filter $(FW_LINE_EMULATION),0 1),)
$(error FW_LINE_EMULATION=$(FW_LINE_EMULATION) is not 0 or 1)
endif
FW_POSTLINK  ?=
ifeq ($(filter $(FW_SCENE_SET),one all),)
$(error FW_SCENE_SET=$(FW_SCENE_SET) is not one of: one all)
endif

# Where this platform's firmware goes: qemu_virt (the co-simulated default) keeps the historical
# folders; any other platform gets its own, so both platforms' builds coexist in one tree.
FW_PSUFFIX   := $(if $(filter qemu_virt,$(FW_PLATFORM)),,-$(FW_PLATFORM))
FW_DIR       := $(BUILD)/firmware$(FW_PSUFFIX)$(SOC_MEM_SUFFIX)

# The scenes: the names of the scene table's SCENE(name) lines, in its order (keys 1..9 follow
# it). A scene's sources are firmware/scenes/<name>.c, or every .c file of firmware/scenes/<name>/.
FW_SCENE_TABLE := firmware/scenes/scene_list.h
FW_SCENES   := $(shell sed -n 's/^SCENE(\([A-Za-z0-9_]*\)[,)].*/\1/p' $(FW_SCENE_TABLE))
# The scenes of scene set $(1) with boot scene $(2): one (only its boot scene), all (every scene of
# the table) or a list joined by + (mk/builds.toml's set = [...]).
fw_set_scenes = $(if $(filter one,$(1)),$(2),$(if $(findstring +,$(1)),$(subst +, ,$(1)),$(FW_SCENES)))
FW_BACKENDS := fixed float
fw_scene_srcs = $(wildcard firmware/scenes/$(1).c firmware/scenes/$(1)/*.c)
FW_ALL_SCENE_SRCS = $(foreach s,$(FW_SCENES),$(call fw_scene_srcs,$(s)))
$(foreach s,$(FW_SCENES),$(if $(call fw_scene_srcs,$(s)),,\
  $(error scene '$(s)' of $(FW_SCENE_TABLE) has no firmware/scenes/$(s).c nor firmware/scenes/$(s)/*.c)))

ifeq ($(filter $(SCENE),$(FW_SCENES)),)
$(error SCENE=$(SCENE) is not one of: $(FW_SCENES))
endif
ifeq ($(filter $(FW_BACKEND),$(FW_BACKENDS)),)
$(error FW_BACKEND=$(FW_BACKEND) is not one of: $(FW_BACKENDS))
endif
ifneq ($(filter-out 0 1 2 3 4,$(FW_SUBPIXEL_BITS)),)
$(error FW_SUBPIXEL_BITS=$(FW_SUBPIXEL_BITS) is not one of: 0 1 2 3 4)
endif

# name of a (scene, backend) build: tetra, tetra-float
fw_name = $(1)$(if $(filter float,$(2)),-float)

FW_ELF        := $(FW_DIR)/$(call fw_name,$(SCENE),$(FW_BACKEND)).elf
FW_HOST       := $(BUILD)/fw-host/$(call fw_name,$(SCENE),$(FW_BACKEND))
FW_UNIT       := $(BUILD)/tests/fw_unit
FW_UNIT_FLOAT := $(BUILD)/tests/fw_unit_float
FW_UNIT_WIDE  := $(BUILD)/tests/fw_unit_wide

# Pure sources (no hardware access: built for the target, the host build and the unit tests),
# the driver edge, the frame loop (per ELF), the target's main.
# The folders follow the data path (firmware/README.md): math/, input/, camera/, render/ (the
# pipeline stages), gpu/ (batching and the driver), scenes/, app/ (the loop, main, settings).
FW_PURE_SRCS := firmware/math/fixed.c firmware/math/vec.c firmware/camera/camera.c \
                firmware/input/input.c firmware/input/usb_keys.c \
                $(addprefix firmware/render/,palette.c mesh.c proj.c clip.c sort.c render.c strips.c) \
                firmware/gpu/batch.c firmware/scenes/scene.c \
                $(addprefix firmware/model/,crc32.c meshfile.c upload.c) \
                $(FW_ALL_SCENE_SRCS)
FW_DRIVER_SRC := firmware/gpu/gpu.c
FW_APP_SRC    := firmware/app/app.c
FW_MAIN_SRC   := firmware/app/main.c
# The host build's own sources: its BSP and command line, the frames' output, the scene's export
# for --dump-scene, and the same main() as the target's (the stress test links the rest without
# these).
FW_HOST_SRCS  := bsp/host/bsp_host.c bsp/host/host_main.c bsp/host/scene_dump.c \
                 bsp/host/frame_out_png.c firmware/scenes/scene_export.c $(FW_MAIN_SRC)
# Other components in the host build come as their own libraries, built once by their own rules
# (the golden model, gpu_model/model.mk; the PNG writer, the top-level Makefile). Their headers:
# the golden model's everywhere in the host build (the BSP is built on it); the PNG writer's
# (cosim/) only where frame_out_png.c, the one file that calls it, is compiled.
FW_HOST_LIBS  := $(COSIM_C_LIB) $(GPU_MODEL_LIB)
FW_HOST_PNG_OBJ_CFLAGS = -Icosim $(FW_PNG_CFLAGS)

FW_PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)
FW_PNG_LIBS   := $(or $(shell pkg-config --libs libpng 2>/dev/null),-lpng)

# ---- the model scene's built-in model -----------------------------------------------------------
# MODEL (any file assimp reads, or a .gmsh) converted by tools/meshconv to the build's capacity
# (FW_MODEL_MAX_VERTS, FW_MODEL_MAX_FACES: every object sees them, scenes/model/model.h), simplified
# to it where larger, then assembled into an object of its own (.incbin) that an ELF links where
# its scene set has the model scene.
MODEL              ?= /usr/share/assimp/models/OBJ/spider.obj
# A platform whose model scene holds more (FW_MODEL_SDRAM_CAPS: bsp/soc/bsp.mk with SOC_MEM=sdram)
# gives it the SDRAM's capacities where this make's scene set has the model scene. They size every
# object's frame, and past 65,535 vertices or primitives its indices, primitives and sort items
# double (config/build_options.h FW_RENDER_WIDE_INDEX), so a program without the model keeps the
# defaults below and the narrow frame (the landscape from the SDRAM: 442,348 -> 435,467
# instructions and 5,901 -> 4,938 data-cache refills a frame, docs/soc.md).
ifneq ($(and $(FW_MODEL_SDRAM_CAPS),$(filter model,$(call fw_set_scenes,$(FW_SCENE_SET),$(SCENE)))),)
FW_MODEL_MAX_VERTS ?= $(call fw_sdram_model_cap,verts)
FW_MODEL_MAX_FACES ?= $(call fw_sdram_model_cap,faces)
endif
FW_MODEL_MAX_VERTS ?= 1024
FW_MODEL_MAX_FACES ?= 1024
FW_MODEL_DEFS      := -DFW_MODEL_MAX_VERTS=$(FW_MODEL_MAX_VERTS)u -DFW_MODEL_MAX_FACES=$(FW_MODEL_MAX_FACES)u
# The name carries the file's, a checksum of its full path (two models of one name in different
# folders are two files here, never one stale conversion) and the capacity.
FW_MODEL_TAG       := $(basename $(notdir $(MODEL)))-$(shell printf '%s' '$(abspath $(MODEL))' | cksum | cut -d' ' -f1)-v$(FW_MODEL_MAX_VERTS)f$(FW_MODEL_MAX_FACES)
FW_MODEL_GMSH      := $(BUILD)/model/$(FW_MODEL_TAG).gmsh
FW_MODEL_OBJ       := $(FW_DIR)/model-blob/$(FW_MODEL_TAG).o
FW_MODEL_HOST_OBJ  := $(BUILD)/fw-host/model-blob/$(FW_MODEL_TAG).o

# A .gmsh MODEL is taken as it is once the validator accepts it at this capacity.
$(FW_MODEL_GMSH): $(MODEL) $(MESHCONV)
	@mkdir -p $(@D)
	$(Q)$(call say,MESHCONV,$(MODEL))$(if $(filter .gmsh,$(suffix $(MODEL))),\
	  $(MESHCONV) --check $(MODEL) --max-verts $(FW_MODEL_MAX_VERTS) --max-faces $(FW_MODEL_MAX_FACES) && cp $(MODEL) $@,\
	  $(MESHCONV) $(MODEL) $@ --max-verts $(FW_MODEL_MAX_VERTS) --max-faces $(FW_MODEL_MAX_FACES))

# The blob's assembly: the file between two symbols (scenes/model/model.c reads them).
$(BUILD)/model/$(FW_MODEL_TAG).S: $(FW_MODEL_GMSH)
	@printf '\t.section .rodata.model_builtin,"a"\n\t.balign 4\n\t.globl model_builtin\nmodel_builtin:\n\t.incbin "%s"\n\t.globl model_builtin_end\nmodel_builtin_end:\n\t.section .note.GNU-stack,"",@progbits\n' \
	  '$(abspath $(FW_MODEL_GMSH))' > $@

$(FW_MODEL_OBJ): $(BUILD)/model/$(FW_MODEL_TAG).S
	@mkdir -p $(@D)
	$(Q)$(call say,CC,$<)$(FW_CC) $(FW_ARCH_FLAGS) -c $< -o $@

$(FW_MODEL_HOST_OBJ): $(BUILD)/model/$(FW_MODEL_TAG).S
	@mkdir -p $(@D)
	$(Q)$(call say,CC,$<)$(HOST_CC) -c $< -o $@

# The built-in model's object where scene set $(1) with boot scene $(2) has the model scene;
# $(3) = the object of the platform (FW_MODEL_OBJ or FW_MODEL_HOST_OBJ).
fw_model_obj = $(if $(filter model,$(call fw_set_scenes,$(1),$(2))),$(3))

FW_WARN := -std=c11 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes
# The object variants (mk/builds.toml [fw_variant]: a backend and its -D settings; the table's
# fixed and float take the command line's settings below) and the programs built from them
# ([fw.<family>]) come from the generated $(GEN_DIR)/firmware.mk, read further down.
FW_BACKEND_DEFS_fixed_BASE :=
FW_BACKEND_DEFS_float_BASE := -DFW_BACKEND_FLOAT=1
FW_COMMAND_LINE_DEFS := $(if $(FW_SUBPIXEL_BITS),-DFW_SUBPIXEL_BITS=$(FW_SUBPIXEL_BITS)) \
                        -DFW_WITH_LINE_EMULATION=$(FW_LINE_EMULATION) $(FW_DEFS)
# -ffp-contract=off: no fused multiply-adds, so the float backend rounds identically on the host
# and on rv32 (C11 mode already implies it for GCC; stated for other compilers).
# -fno-tree-loop-distribute-patterns: GCC would turn the pipeline's clearing loops (the sort's
# histograms, 2 KiB a frame) into memset calls, and picolibc's rv32 memset stores a byte at a time:
# measured on a cubes frame, the sort fell from 25,059 to 17,869 instructions without the call.
FW_CFLAGS_BASE := $(FW_ARCH_FLAGS) -O2 -g $(FW_WARN) -ffp-contract=off -ffunction-sections \
                  -fdata-sections -fno-tree-loop-distribute-patterns \
                  -Ibsp/$(FW_PLATFORM) -Ibsp -Icontract -Ifirmware $(FW_MODEL_DEFS)
FW_HOST_CFLAGS_BASE = $(HOST_CFLAGS) $(FW_WARN) -ffp-contract=off -Ibsp/host -Ibsp -Icontract \
                      -Ifirmware -Igpu_model $(FW_MODEL_DEFS)
FW_LDFLAGS_BASE := $(FW_ARCH_FLAGS) $(FW_BSP_LDFLAGS) -T$(FW_LDSCRIPT) -Wl,--gc-sections

# Record a command line in a file, rewriting it only when it changed: objects depend on it.
# $(1) = file, $(2) = text
define fw_flags_file
	@mkdir -p $(dir $(1))
	@echo '$(2)' | cmp -s - $(1) || echo '$(2)' > $(1)
endef

# ---- per variant: shared objects, target and host ---------------------------------------------
# An object folder is named by the variant and a checksum of its compiler and flags, so every build
# with the same flags shares its objects, whichever make or folder of programs asks for them (make
# test's, `make run`'s, a scene's manifest build with the same features); cflags.txt in it says
# what they are. An object is written under a temporary name and renamed: two makes side by side
# (suites that run make) never leave one half-written.
fw_flags_sum = $(shell printf '%s' '$(subst ','\'',$(1))' | cksum | cut -d' ' -f1)
# $(1) = the variant (mk/builds.toml [fw_variant]: its backend and -D settings)
define FW_BACKEND_RULES
FW_CFLAGS_$(1)    := $(FW_CFLAGS_BASE) $(FW_BACKEND_DEFS_$(1)) $(FW_VARIANT_DEFS_$(1))
FW_OBJ_DIR_$(1)   := $(BUILD)/fw-obj$(FW_PSUFFIX)/$(1)-$$(call fw_flags_sum,$(FW_CC) $$(FW_CFLAGS_$(1)))
FW_OBJS_$(1)      := $$(patsubst %.c,$$(FW_OBJ_DIR_$(1))/%.o,$(FW_PURE_SRCS) $(FW_DRIVER_SRC) \
                     $(FW_MAIN_SRC) $(FW_BSP_SRCS))
# ... without the scenes' objects: an ELF adds those of the scenes it is built with.
FW_CORE_OBJS_$(1) := $$(filter-out $$(patsubst %.c,$$(FW_OBJ_DIR_$(1))/%.o,$(FW_ALL_SCENE_SRCS)),\
                     $$(FW_OBJS_$(1)))
FW_HOST_CFLAGS_$(1) = $(FW_HOST_CFLAGS_BASE) $(FW_BACKEND_DEFS_$(1)) $(FW_VARIANT_DEFS_$(1))
HOST_OBJ_DIR_$(1) := $(BUILD)/fw-obj-host/$(1)-$$(call fw_flags_sum,$(HOST_CC) $$(FW_HOST_CFLAGS_$(1)))
FW_HOST_OBJS_$(1) := $$(patsubst %.c,$$(HOST_OBJ_DIR_$(1))/%.o,$(FW_PURE_SRCS) $(FW_DRIVER_SRC) \
                     $(FW_HOST_SRCS))
FW_HOST_CORE_OBJS_$(1) := $$(filter-out \
                     $$(patsubst %.c,$$(HOST_OBJ_DIR_$(1))/%.o,$(FW_ALL_SCENE_SRCS)),$$(FW_HOST_OBJS_$(1)))

$$(FW_OBJ_DIR_$(1))/cflags.txt: fw-force
	$$(call fw_flags_file,$$@,$$(FW_CC) $$(FW_CFLAGS_$(1)))

$$(FW_OBJ_DIR_$(1))/%.o: %.c $$(FW_OBJ_DIR_$(1))/cflags.txt
	@mkdir -p $$(@D)
	$$(Q)$$(call say,CC,$$<)$$(FW_CC) $$(FW_CFLAGS_$(1)) -MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.$$$$$$$$ \
	  && mv -f $$@.$$$$$$$$ $$@

$$(HOST_OBJ_DIR_$(1))/cflags.txt: fw-force
	$$(call fw_flags_file,$$@,$$(HOST_CC) $$(FW_HOST_CFLAGS_$(1)))

$$(HOST_OBJ_DIR_$(1))/%.o: %.c $$(HOST_OBJ_DIR_$(1))/cflags.txt
	@mkdir -p $$(@D)
	$$(Q)$$(call say,CC,$$<)$$(HOST_CC) $$(FW_HOST_CFLAGS_$(1)) $$(if $$(filter %/frame_out_png.o,$$@),$$(FW_HOST_PNG_OBJ_CFLAGS)) \
	  -MMD -MP -MF $$(@:.o=.d) -MT $$@ -c $$< -o $$@.$$$$$$$$ && mv -f $$@.$$$$$$$$ $$@

FW_DEP_FILES += $$(FW_OBJS_$(1):.o=.d) $$(FW_HOST_OBJS_$(1):.o=.d)
endef

# ---- per program: app.c with its settings, linked with a backend's objects ---------------------
# A program's scene set (fw_set_scenes, above; a list's keys 1..N in its order): fw_set_defs =
# app.c's -DFW_BUILT_SCENES (none: scene_set.h's default, the whole table). $(1) = set, $(2) = boot
# scene.
fw_set_defs   = $(if $(filter one,$(1)),-DFW_BUILT_SCENES='SCENE($(2))',$(if $(findstring +,$(1)),\
                -DFW_BUILT_SCENES='$(foreach s,$(subst +, ,$(1)),SCENE($(s)))'))
fw_set_objs   = $(patsubst %.c,$(3)/%.o,$(foreach s,$(call fw_set_scenes,$(1),$(2)),$(call fw_scene_srcs,$(s))))

# $(1) = ELF path, $(2) = scene, $(3) = backend, $(4) = frames, $(5) = max polls (may be empty),
# $(6) = further -D settings of app.c (may be empty), $(7) = scene set (default FW_SCENE_SET)
define FW_ELF_RULES
$(1:.elf=)/app.o: $(FW_APP_SRC) $(1:.elf=)/cflags.txt
	$$(Q)$$(call say,CC,$$<)$$(FW_CC) $$(FW_CFLAGS_$(3)) -DFW_SCENE='"$(2)"' -DFW_FRAMES=$(4) \
	  $(if $(5),-DFW_GPU_MAX_POLLS=$(5)) $(if $(FW_PROFILE),-DFW_PROFILE=$(FW_PROFILE)) $(6) \
	  $(call fw_set_defs,$(or $(7),$(FW_SCENE_SET)),$(2)) \
	  $(if $(call fw_model_obj,$(or $(7),$(FW_SCENE_SET)),$(2),1),-DFW_MODEL_SCENE_BUILT=1) \
	  -MMD -MP -c $$< -o $$@

$(1:.elf=)/cflags.txt: fw-force
	$$(call fw_flags_file,$$@,$$(FW_CC) $$(FW_CFLAGS_$(3)) $(2) $(4) $(5) $(FW_PROFILE) $(6) \
	  $(or $(7),$(FW_SCENE_SET)) $(FW_POSTLINK))

$(1): $$(FW_CORE_OBJS_$(3)) $(call fw_set_objs,$(or $(7),$(FW_SCENE_SET)),$(2),$$(FW_OBJ_DIR_$(3))) \
      $(call fw_model_obj,$(or $(7),$(FW_SCENE_SET)),$(2),$(FW_MODEL_OBJ)) $(1:.elf=)/app.o $(FW_LDSCRIPT)
	$$(Q)$$(call say,LD,$$@)$$(FW_CC) $$(FW_LDFLAGS_BASE) -Wl,-Map=$(1:.elf=.map) -o $$@ $$(FW_CORE_OBJS_$(3)) \
	  $(call fw_set_objs,$(or $(7),$(FW_SCENE_SET)),$(2),$$(FW_OBJ_DIR_$(3))) \
	  $(call fw_model_obj,$(or $(7),$(FW_SCENE_SET)),$(2),$(FW_MODEL_OBJ)) $(1:.elf=)/app.o -lm
	$(if $(FW_POSTLINK),$$(Q)$$(call say,POSTLINK,$$@)$(FW_POSTLINK) $$@)

FW_DEP_FILES += $(1:.elf=)/app.d
endef

# $(1) = host program path, $(2) = scene, $(3) = backend, $(4) = frames (the scene set is
# FW_SCENE_SET's, as the ELFs'), $(5) = further -D settings of app.c (may be empty)
define FW_HOST_RULES
$(1).obj/app.o: $(FW_APP_SRC) $(1).obj/cflags.txt
	@mkdir -p $$(@D)
	$$(Q)$$(call say,CC,$$<)$$(HOST_CC) $$(FW_HOST_CFLAGS_$(3)) -DFW_SCENE='"$(2)"' -DFW_FRAMES=$(4) $(5) \
	  $(call fw_set_defs,$(FW_SCENE_SET),$(2)) \
	  $(if $(call fw_model_obj,$(FW_SCENE_SET),$(2),1),-DFW_MODEL_SCENE_BUILT=1) -MMD -MP -c $$< -o $$@

$(1).obj/cflags.txt: fw-force
	$$(call fw_flags_file,$$@,$$(HOST_CC) $$(FW_HOST_CFLAGS_$(3)) $(2) $(4) $(5) $(FW_SCENE_SET))

$(1): $$(FW_HOST_CORE_OBJS_$(3)) $(call fw_set_objs,$(FW_SCENE_SET),$(2),$$(HOST_OBJ_DIR_$(3))) \
      $(call fw_model_obj,$(FW_SCENE_SET),$(2),$(FW_MODEL_HOST_OBJ)) $(1).obj/app.o $(FW_HOST_LIBS)
	$$(Q)$$(call say,LD,$$@)$$(HOST_CC) -o $$@ $$(FW_HOST_CORE_OBJS_$(3)) \
	  $(call fw_set_objs,$(FW_SCENE_SET),$(2),$$(HOST_OBJ_DIR_$(3))) \
	  $(call fw_model_obj,$(FW_SCENE_SET),$(2),$(FW_MODEL_HOST_OBJ)) $(1).obj/app.o \
	  $(FW_HOST_LIBS) $(FW_PNG_LIBS) -lm

FW_DEP_FILES += $(1).obj/app.d
endef

# The programs' folders and settings, which mk/builds.toml's [fw.<family>] tables use:
# make test's (few frames, independent of FRAMES, so `make test` does not depend on what the last
# `make run` asked for), the benchmarks' (bench-fw, bench-soc: FW_BENCH_FRAMES; bench-sim: until
# stopped), bench-error's (FW_ERR_FRAMES frames; its camera paths: FW_PATH_VIEWS views of the seeded
# path of app/cam_path.h, one a frame, and on the SoC only the first FW_PATH_SOC_VIEWS, since socsim
# simulates about 0.6 M CPU cycles a second), fw-size's.
FW_TEST_FRAMES := 4
FW_TEST_DIR    := $(BUILD)/fw-test$(FW_PSUFFIX)$(SOC_MEM_SUFFIX)
# The upload test's frames: its uploads are paced by the wall clock (the tool's acknowledgements and
# retransmissions) while the co-simulation draws frames, and the good file committed anywhere from
# frame 10 to after frame 15 of 16 on a 2-core machine (the run then fails): 32 leave the margin.
FW_UPLOAD_TEST_FRAMES := 32
SOC_UPLOAD_FRAMES := 12
# The tour (soc-sdram-scenes: every scene in one program from the SDRAM, tests/soc/sdram_tour.sh):
# two frames a scene, painter's order then depth-tested, and one more painter's frame first (keys
# typed at a frame's doorbell act from the frame after next: the first frame's keys reach the third).
FW_TOUR_FRAMES = $(words first $(FW_SCENES) $(FW_SCENES))
FW_BENCH_FRAMES := 8
FW_BENCH_DIR    := $(BUILD)/fw-bench$(FW_PSUFFIX)$(SOC_MEM_SUFFIX)
FW_SIMBENCH_DIR := $(BUILD)/fw-simbench$(FW_PSUFFIX)
FW_ERR_FRAMES := 3
FW_ERR_DIR    := $(BUILD)/fw-error$(FW_PSUFFIX)
FW_PATH_VIEWS := 52
FW_PATH_SEED  := 1
FW_PATH_DIR   := $(BUILD)/fw-path$(FW_PSUFFIX)
FW_PATH_DEFS  := -DFW_CAMERA_PATH=$(FW_PATH_VIEWS) -DFW_CAMERA_PATH_SEED=$(FW_PATH_SEED)u
FW_PATH_SOC_VIEWS := 1
FW_SIZE_DIR    := $(BUILD)/fw-size$(FW_PSUFFIX)
ifneq ($(GEN_READ),)
include $(GEN_DIR)/firmware.mk
endif

# Memory per scene (`make fw-size`, tests/firmware/fit.sh: mk/builds.toml's fw.fw-size builds).
# The targets of issue #9: the default scene's image in 64 KiB, every other scene's in 192 KiB.
FW_SIZE_TARGET_DEFAULT := 65536
FW_SIZE_TARGET_OTHER   := 196608
FW_SIZE_ENV = SIZE=$(patsubst %gcc,%size,$(FW_CC)) NM=$(patsubst %gcc,%nm,$(FW_CC)) \
              OBJDUMP=$(FW_OBJDUMP) STACK_BYTES=$(FW_STACK_BYTES) DEFAULT_SCENE=tetra \
              TARGET_DEFAULT=$(FW_SIZE_TARGET_DEFAULT) TARGET_OTHER=$(FW_SIZE_TARGET_OTHER) \
              PLATFORM=$(FW_PLATFORM)

# ---- host unit tests -------------------------------------------------------------------------
# The pure sources and gpu.c, built against tests/firmware/fake_bsp/bsp_platform.h (the GPU aperture is an
# array), once per backend. Test files that only make sense for one backend say so themselves.

FW_UNIT_TEST_SRCS := $(wildcard tests/firmware/*.c)
FW_UNIT_CFLAGS     = $(HOST_CFLAGS) $(FW_WARN) -ffp-contract=off -Itests/firmware/fake_bsp -Ibsp \
                     -Itests/firmware -Itests -Icontract -Ifirmware -DSORT_COUNT_WORK
# The wide build's model capacities: the SDRAM builds', whose frames need 32-bit indices
# (config/build_options.h FW_RENDER_WIDE_INDEX).
FW_UNIT_WIDE_DEFS := -DFW_MODEL_MAX_VERTS=$(call fw_sdram_model_cap,verts)u \
                     -DFW_MODEL_MAX_FACES=$(call fw_sdram_model_cap,faces)u

# $(1) = binary, $(2) = backend, $(3) = the model scene's capacities (-D flags)
define FW_UNIT_RULES
$(1)_OBJ  := $(1).obj
$(1)_OBJS := $$(patsubst %.c,$$($(1)_OBJ)/%.o,$(FW_UNIT_TEST_SRCS) $(FW_PURE_SRCS) $(FW_DRIVER_SRC))

$$($(1)_OBJ)/cflags.txt: fw-force
	$$(call fw_flags_file,$$@,$$(HOST_CC) $$(FW_UNIT_CFLAGS) $(3) $$(FW_BACKEND_DEFS_$(2)))

$$($(1)_OBJ)/%.o: %.c $$($(1)_OBJ)/cflags.txt
	@mkdir -p $$(@D)
	$$(Q)$$(call say,CC,$$<)$$(HOST_CC) $$(FW_UNIT_CFLAGS) $(3) $$(FW_BACKEND_DEFS_$(2)) -MMD -MP -c $$< -o $$@

$(1): $$($(1)_OBJS) $(FW_MODEL_HOST_OBJ)
	$$(Q)$$(call say,LD,$$@)$$(HOST_CC) -o $$@ $$($(1)_OBJS) $(FW_MODEL_HOST_OBJ) -lm

FW_DEP_FILES += $$($(1)_OBJS:.o=.d)
endef

$(eval $(call FW_UNIT_RULES,$(FW_UNIT),fixed,$(FW_MODEL_DEFS)))
$(eval $(call FW_UNIT_RULES,$(FW_UNIT_FLOAT),float,$(FW_MODEL_DEFS)))
$(eval $(call FW_UNIT_RULES,$(FW_UNIT_WIDE),fixed,$(FW_UNIT_WIDE_DEFS)))

-include $(FW_DEP_FILES)

# ---- convenience ----------------------------------------------------------------------------

# Fake GPU registers for fw-smoke: ID, VERSION, VTX_CAP, TRI_CAP, FB_SIZE as the contract says,
# preloaded by QEMU's generic loader; nothing answers DOORBELL, so frame 0 must time out.
FW_FAKE_GPU_REGS := \
  -device loader,addr=0x87000000,data=0x47505530,data-len=4 \
  -device loader,addr=0x87000004,data=0x00010001,data-len=4 \
  -device loader,addr=0x8700000c,data=1024,data-len=4 \
  -device loader,addr=0x87000010,data=512,data-len=4 \
  -device loader,addr=0x87000014,data=0x00f00140,data-len=4

.PHONY: fw fw-all fw-host fw-unit fw-smoke bench-fw profile-fw fw-force fw-size \
        fw-size-deps
fw: $(FW_ELF) $(FW_ELF:.elf=.lst)

# An ELF's disassembly with its source lines, on demand (make fw writes make run's): not for every
# one of the hundreds of test and benchmark ELFs.
%.lst: %.elf
	$(Q)$(call say,OBJDUMP,$<)$(FW_OBJDUMP) -d -S $< > $@.$$$$ && mv $@.$$$$ $@

fw-all: $(FW_ALL_ELFS) $(FW_ALL_HOSTS)

fw-host: $(FW_HOST)

fw-unit: $(FW_UNIT) $(FW_UNIT_FLOAT) $(FW_UNIT_WIDE)
	$(Q)$(call say,RUN,$(FW_UNIT))$(FW_UNIT)
	$(Q)$(call say,RUN,$(FW_UNIT_FLOAT))$(FW_UNIT_FLOAT)
	$(Q)$(call say,RUN,$(FW_UNIT_WIDE))$(FW_UNIT_WIDE)


# The memory table (Markdown) of every scene; fails if a one-scene build misses its target.
fw-size: $(FW_SIZE_ELFS)
	@$(FW_SIZE_ENV) bash firmware/tools/fw_size.sh $(FW_SIZE_DIR) $(FW_SCENES)

fw-size-deps: $(FW_SIZE_ELFS)

# Boots the short-watchdog ELF without a GPU: "GPU not found" (status 2); then with the identity
# registers preloaded and nothing answering: FW_WATCHDOG_GIVE_UP watchdog resets, then status 4.
fw-smoke: $(FW_TEST_DIR)/tetra-watchdog.elf
	@echo "fw-smoke: no GPU -> expect 'GPU not found' and exit status 2"
	@timeout 20 $(FW_RUN) -kernel $< > $(FW_TEST_DIR)/smoke-nogpu.log; rc=$$?; \
	  cat $(FW_TEST_DIR)/smoke-nogpu.log; \
	  grep -q '^tetra fw' $(FW_TEST_DIR)/smoke-nogpu.log && \
	  grep -q 'GPU not found' $(FW_TEST_DIR)/smoke-nogpu.log && test $$rc -eq 2 || \
	  { echo "fw-smoke: FAILED (status $$rc)"; exit 1; }
	@echo "fw-smoke: silent GPU -> expect watchdog resets, then exit status 4"
	@timeout 60 $(FW_RUN) $(FW_FAKE_GPU_REGS) -kernel $< > $(FW_TEST_DIR)/smoke-timeout.log; \
	  rc=$$?; cat $(FW_TEST_DIR)/smoke-timeout.log; \
	  test "$$(grep -c '^watchdog: frame' $(FW_TEST_DIR)/smoke-timeout.log)" -eq 3 && \
	  grep -q 'still hung' $(FW_TEST_DIR)/smoke-timeout.log && test $$rc -eq 4 || \
	  { echo "fw-smoke: FAILED (status $$rc)"; exit 1; }
	@echo "fw-smoke: passed"

# The instruction-count table of issue #4, measured in co-simulation (no model check: faster).
bench-fw: $(FW_BENCH_ELFS) $(GPUSIM)
	@GPUSIM=$(GPUSIM) BENCH_DIR=$(FW_BENCH_DIR) bash firmware/tools/bench_fw.sh $(FW_SCENES)

# Instructions per function and frame of one scene's benchmark build (SCENE, FW_BACKEND).
profile-fw: $(FW_BENCH_DIR)/$(call fw_name,$(SCENE),$(FW_BACKEND)).elf $(GPUSIM)
	@$(or $(PYTHON),python3) firmware/tools/profile_fw.py $(GPUSIM) $< $(if $(PROFILE_LINES),--lines $(PROFILE_LINES)) \
	  $(if $(filter 1,$(PROFILE_HAZARDS)),--hazards)

fw-force:

# ---- the upload receiver on a pty, for tools/mesh_upload.py's tests (tests/upload/) -------------
UPLOAD_PEER := $(BUILD)/tests/upload_peer
UPLOAD_PEER_SRCS := tests/upload/upload_peer.c $(addprefix firmware/model/,crc32.c meshfile.c upload.c) \
                    firmware/render/mesh.c firmware/math/vec.c firmware/math/fixed.c
$(UPLOAD_PEER): $(UPLOAD_PEER_SRCS) $(wildcard firmware/model/*.h)
	@mkdir -p $(@D)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(HOST_CFLAGS) -Ifirmware -Icontract $(FW_MODEL_DEFS) $(filter %.c,$^) -o $@ -lm

# The same at a 2,048-face capacity, for `make bench-upload`'s larger model.
UPLOAD_PEER_2048 := $(BUILD)/tests/upload_peer-2048
$(UPLOAD_PEER_2048): $(filter-out %.h,$(UPLOAD_PEER_SRCS)) $(wildcard firmware/model/*.h)
	@mkdir -p $(@D)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(HOST_CFLAGS) -Ifirmware -Icontract -DFW_MODEL_MAX_VERTS=2048u -DFW_MODEL_MAX_FACES=2048u \
	  $(filter %.c,$^) -o $@ -lm

.PHONY: bench-upload
bench-upload: $(UPLOAD_PEER) $(UPLOAD_PEER_2048) $(MESHCONV)
	@bash bench/bench_upload.sh $(BUILD) $(UPLOAD_PEER) $(UPLOAD_PEER_2048) $(MESHCONV)
