# tests/fuzz/fuzz.mk - make fragment: the libFuzzer targets (clang 14, ASan + UBSan), `make fuzz`
# and the short deterministic run of `make test`. Included by the top-level Makefile after it
# defines BUILD; FW_PURE_SRCS comes from firmware/firmware.mk.
#
#   make fuzz                   every target for FUZZ_SECONDS (60) seconds, corpus kept in
#                               $(BUILD)/fuzz/corpus-<name>, crashes in $(BUILD)/fuzz/artifacts/
#   make fuzz FUZZ_TARGETS=input FUZZ_SECONDS=600
#   make fuzz-build             build only
#
# Every target is built with -fsanitize=fuzzer,address,undefined and -fno-sanitize-recover, so
# any sanitizer report stops it like a failed property check. The golden model is compiled without
# comparison tracing (-fno-sanitize-coverage=trace-cmp): its pixel loops would otherwise dominate
# the time, and its branches are reached by the harnesses' own choice of values. Warnings are not
# errors here: the sources are other owners', built by their own rules with -Werror already, and a
# new clang warning must not break `make test`.

FUZZ_CC      ?= clang-14
FUZZ_CXX     ?= clang++-14
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= prim_list input gpu_model gpu_driver upload meshfile meshconv
FUZZ_DIR     := $(BUILD)/fuzz
FUZZ_SAN     := -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
FUZZ_CFLAGS  := -std=c11 -g -O1 -Wall -Wextra $(FUZZ_SAN)
FUZZ_CXXFLAGS := -std=c++17 -g -O1 -Wall -Wextra $(FUZZ_SAN)
FUZZ_BINS    := $(foreach t,$(FUZZ_TARGETS),$(FUZZ_DIR)/fuzz_$(t))

FUZZ_FW_HDRS := $(wildcard firmware/*/*.h firmware/scenes/*/*.h bsp/bsp.h contract/gpu_regs.h)

# The golden model, instrumented for ASan/UBSan and coverage but not comparison tracing.
$(FUZZ_DIR)/gpu_model.o: gpu_model/gpu_model.c $(GPU_MODEL_HDR)
	@mkdir -p $(dir $@)
	$(Q)$(call say,CC,$<)$(FUZZ_CC) $(filter-out $(FUZZ_SAN),$(FUZZ_CFLAGS)) \
	  -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
	  -fno-sanitize-coverage=trace-cmp -Igpu_model -Icontract -c $< -o $@

$(FUZZ_DIR)/fuzz_prim_list: tests/fuzz/fuzz_prim_list.cpp cosim/prim_list.cpp cosim/prim_list.h \
                            contract/gpu_regs.h
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CXX) $(FUZZ_CXXFLAGS) -Icosim -Icontract $(filter %.cpp,$^) -o $@

$(FUZZ_DIR)/fuzz_input: tests/fuzz/fuzz_input.c tests/fuzz/fuzz_common.h $(FW_PURE_SRCS) $(FUZZ_FW_HDRS)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Icontract -Ifirmware $(filter %.c,$^) -lm -o $@

$(FUZZ_DIR)/fuzz_gpu_model: tests/fuzz/fuzz_gpu_model.c tests/fuzz/fuzz_common.h $(FUZZ_DIR)/gpu_model.o $(GPU_MODEL_HDR)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Igpu_model -Icontract $(filter %.c %.o,$^) -o $@

$(FUZZ_DIR)/fuzz_gpu_driver: tests/fuzz/fuzz_gpu_driver.c tests/fuzz/fuzz_common.h firmware/gpu/gpu.c firmware/gpu/batch.c \
                             $(FUZZ_DIR)/gpu_model.o tests/fuzz/driver_bsp/bsp_platform.h tests/firmware/fake_bsp/bsp_idle.h \
                             $(FUZZ_FW_HDRS) \
                             $(GPU_MODEL_HDR)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Itests/fuzz/driver_bsp -Ibsp -Igpu_model -Icontract \
	  -Ifirmware $(filter %.c %.o,$^) -o $@

# The upload's receiver and the mesh file's validator, with the pieces of the pipeline they use.
# fuzz_upload ends every input with the abandon timeout's silence: a fifth of the firmware's (the
# same code, five times the executions a second).
FUZZ_MODEL_SRCS := $(addprefix firmware/model/,crc32.c meshfile.c upload.c) firmware/render/mesh.c \
                   firmware/math/vec.c firmware/math/fixed.c
$(FUZZ_DIR)/fuzz_upload: tests/fuzz/fuzz_upload.c tests/fuzz/fuzz_common.h tests/upload/test_files.h \
                         $(FUZZ_MODEL_SRCS) $(FUZZ_FW_HDRS)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Icontract -Ifirmware -Itests -DUPLOAD_TIMEOUT_FRAMES=180u \
	  $(filter %.c,$^) -lm -o $@

$(FUZZ_DIR)/fuzz_meshfile: tests/fuzz/fuzz_meshfile.c tests/fuzz/fuzz_common.h $(FUZZ_MODEL_SRCS) $(FUZZ_FW_HDRS)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Icontract -Ifirmware $(filter %.c,$^) -lm -o $@

# The converter's path (tools/meshconv) on assimp and meshoptimizer, which are not instrumented.
# Its seeds are generated into the build directory (meshconv_seeds.py: our own small models).
FUZZ_MESHCONV_SRCS := tests/fuzz/fuzz_meshconv.c tools/meshconv/meshconv_core.c \
                      tools/meshconv/meshconv_scene.c firmware/render/palette.c $(FUZZ_MODEL_SRCS)
$(FUZZ_DIR)/fuzz_meshconv: $(FUZZ_MESHCONV_SRCS) tests/fuzz/fuzz_common.h $(wildcard tools/meshconv/*.h) \
                           $(FUZZ_FW_HDRS) | $(FUZZ_DIR)/seeds-meshconv
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(FUZZ_CC) $(FUZZ_CFLAGS) -Itools/meshconv -Ifirmware -Icontract $$(pkg-config --cflags assimp) \
	  $(filter %.c,$^) -o $@ $$(pkg-config --libs assimp) -lmeshoptimizer -lstdc++ -lm

$(FUZZ_DIR)/seeds-meshconv: tests/fuzz/meshconv_seeds.py
	@rm -rf $@
	$(Q)$(call say,GEN,$@)$(PYTHON) $< $@

.PHONY: fuzz fuzz-build
fuzz-build: $(FUZZ_BINS)

fuzz: setup
	@$(MAKE) --no-print-directory fuzz-build
	@FUZZ_DIR=$(FUZZ_DIR) FUZZ_SECONDS=$(FUZZ_SECONDS) bash tests/fuzz/run_fuzz.sh long $(FUZZ_TARGETS)
