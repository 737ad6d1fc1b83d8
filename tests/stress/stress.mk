# tests/stress/stress.mk — `make stress` (issue #13): the named stiff and extreme cases
# (tests/stress/stress.c), one Markdown row each, on both arithmetic backends. Included by the
# top-level Makefile after firmware/firmware.mk, whose host objects it links: the firmware's pure
# core and driver as the host build compiles them (the fixed and float variants' objects under $(BUILD)/fw-obj-host), every
# scene, the built-in model, and the golden model as the GPU (tests/stress/stress_bsp.c in place
# of bsp/host's BSP and main).
#
#   make stress                 the full run: STRESS_ARGS (default: 10^4 soak frames per scene
#                               and run, the look key held 10^6 frames), both backends, at each
#                               of STRESS_FRAMES (the contract's frame and its largest)
#   make stress STRESS_ARGS=--short    the make-test form (tests/stress/run.sh: the same cases,
#                               fewer frames, and a sample co-simulated)
#   make stress-san             the same under ASan and UBSan (any report fails; not in make test)
#   STRESS_TIMEOUT              seconds per backend before a run counts as hung (default 900)
#
# Outputs: $(STRESS) = $(BUILD)/tests/stress, $(STRESS_FLOAT) = $(BUILD)/tests/stress_float (the
# suite fw-stress needs both: mk/builds.toml's [target] stress).

STRESS         := $(BUILD)/tests/stress
STRESS_FLOAT   := $(BUILD)/tests/stress_float
STRESS_ARGS    ?=
STRESS_TIMEOUT ?= 900
STRESS_FRAMES  ?= $(CONTRACT_FB) $(CONTRACT_FB_MAX)
STRESS_SRCS    := tests/stress/stress.c tests/stress/stress_bsp.c

# $(1) = binary, $(2) = backend
define STRESS_RULES
$(1)_OBJ  := $(1).obj
$(1)_OBJS := $$(patsubst %.c,$$($(1)_OBJ)/%.o,$(STRESS_SRCS))
# The host build's objects of that backend, without its BSP and main; with every scene.
$(1)_FW_OBJS := $$(filter-out $$(patsubst %.c,$$(HOST_OBJ_DIR_$(2))/%.o,$(FW_HOST_SRCS)),\
                $$(FW_HOST_CORE_OBJS_$(2))) \
                $$(call fw_set_objs,all,$(SCENE),$$(HOST_OBJ_DIR_$(2)))

$$($(1)_OBJ)/%.o: %.c $$(HOST_OBJ_DIR_$(2))/cflags.txt
	@mkdir -p $$(@D)
	$$(Q)$$(call say,CC,$$<)$$(HOST_CC) $$(FW_HOST_CFLAGS_$(2)) -Itests/stress -Itests/firmware -MMD -MP -c $$< -o $$@

$(1): $$($(1)_OBJS) $$($(1)_FW_OBJS) $(FW_MODEL_HOST_OBJ) $(GPU_MODEL_LIB)
	$$(Q)$$(call say,LD,$$@)$$(HOST_CC) -o $$@ $$($(1)_OBJS) $$($(1)_FW_OBJS) $(FW_MODEL_HOST_OBJ) $(GPU_MODEL_LIB) -lm

-include $$($(1)_OBJS:.o=.d)
endef

$(eval $(call STRESS_RULES,$(STRESS),fixed))
$(eval $(call STRESS_RULES,$(STRESS_FLOAT),float))

.PHONY: stress
stress: $(STRESS) $(STRESS_FLOAT)
	@rc=0; for f in $(STRESS_FRAMES); do for s in $(STRESS) $(STRESS_FLOAT); do \
	  timeout $(STRESS_TIMEOUT) $$s $(STRESS_ARGS) --frame $$f; a=$$?; \
	  if [ $$a -eq 124 ]; then echo "stress: HUNG (timeout $(STRESS_TIMEOUT) s)"; fi; \
	  [ $$a -eq 0 ] || rc=1; done; done; exit $$rc

# `make stress-san`: the same cases with AddressSanitizer and UndefinedBehaviorSanitizer, both
# backends, every source compiled in one command (not in make test: a minute of compiling). Any
# report stops the run (-fno-sanitize-recover), so a pass means no UB and no bad access.
STRESS_SAN       := $(BUILD)/tests/stress-san
STRESS_SAN_FLOAT := $(BUILD)/tests/stress-san-float
STRESS_SAN_SRCS   = $(STRESS_SRCS) $(FW_PURE_SRCS) $(FW_DRIVER_SRC) $(GPU_MODEL_SRC)
STRESS_SAN_FLAGS := -std=c11 -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined \
                    -ffp-contract=off -Ibsp/host -Ibsp -Icontract -Ifirmware -Igpu_model -Icosim \
                    -Itests/stress -Itests/firmware $(FW_MODEL_DEFS) -DFW_WITH_LINE_EMULATION=$(FW_LINE_EMULATION)

$(STRESS_SAN) $(STRESS_SAN_FLOAT): $(STRESS_SAN_SRCS) $(FW_MODEL_HOST_OBJ) $(wildcard firmware/*/*.h \
                                   firmware/scenes/*/*.h gpu_model/*.h tests/stress/*.h)
	@mkdir -p $(@D)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(STRESS_SAN_FLAGS) $(if $(filter %-float,$@),-DFW_BACKEND_FLOAT=1) \
	  $(STRESS_SAN_SRCS) $(FW_MODEL_HOST_OBJ) -o $@ -lm

.PHONY: stress-san
stress-san: $(STRESS_SAN) $(STRESS_SAN_FLOAT)
	@timeout $(STRESS_TIMEOUT) $(STRESS_SAN) $(STRESS_ARGS) && \
	  timeout $(STRESS_TIMEOUT) $(STRESS_SAN_FLOAT) $(STRESS_ARGS)
