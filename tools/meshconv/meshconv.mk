# tools/meshconv/meshconv.mk — the model converter (tools/meshconv/README.md), included by the
# top-level Makefile after BUILD and HOST_CFLAGS.
#
#   make meshconv          $(MESHCONV) = $(BUILD)/tools/meshconv
#   make meshconv-sweep    every model under MESHCONV_MODELS converted (MESHCONV_TIMEOUT seconds
#                          each) as the firmware build converts MODEL= (to its capacity, simplifying:
#                          MESHCONV_SWEEP_ARGS): a Markdown table and the totals; a crash or a
#                          timeout fails it

MESHCONV         := $(BUILD)/tools/meshconv
MESHCONV_MODELS  ?= /usr/share/assimp/models
MESHCONV_TIMEOUT ?= 30
MESHCONV_SWEEP_ARGS ?= --max-verts $(FW_MODEL_MAX_VERTS) --max-faces $(FW_MODEL_MAX_FACES)
# The firmware's pure code it links: the validator it checks its output with (the loader in the
# same file brings mesh.c and the arithmetic), the CRC, and the palette it maps colours to (so
# that the converter and the screen agree by construction).
MESHCONV_FW_SRCS ?= firmware/model/meshfile.c firmware/model/crc32.c firmware/render/mesh.c \
                    firmware/math/fixed.c firmware/math/vec.c
MESHCONV_SRCS    := tools/meshconv/meshconv.c tools/meshconv/meshconv_scene.c tools/meshconv/meshconv_core.c \
                    firmware/render/palette.c $(MESHCONV_FW_SRCS)
MESHCONV_CFLAGS  := $(HOST_CFLAGS) -Itools/meshconv -Ifirmware -Icontract $(MESHCONV_EXTRA_CFLAGS) \
                    $$(pkg-config --cflags assimp)
MESHCONV_LIBS    := $$(pkg-config --libs assimp) -lmeshoptimizer -lstdc++ -lm

.PHONY: meshconv meshconv-sweep
meshconv: $(MESHCONV)

$(MESHCONV): $(MESHCONV_SRCS) $(wildcard tools/meshconv/*.h firmware/model/*.h firmware/render/palette.h)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(MESHCONV_CFLAGS) $(filter %.c,$^) -o $@ $(MESHCONV_LIBS)

meshconv-sweep: $(MESHCONV)
	@MESHCONV=$(MESHCONV) BUILD=$(BUILD) MESHCONV_TIMEOUT=$(MESHCONV_TIMEOUT) \
	  MESHCONV_ARGS='$(MESHCONV_SWEEP_ARGS)' bash tools/meshconv/sweep.sh $(MESHCONV_MODELS)
