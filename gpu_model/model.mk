# gpu_model/model.mk - make fragment for the golden C model and its unit tests.
# Included by the top-level Makefile after it defines BUILD, HOST_CC and
# HOST_CFLAGS (the defaults below only apply if it does not).
#
# The model is built once, as $(GPU_MODEL_LIB), and linked by everything that runs it on the
# host: its unit tests, the co-simulator and the firmware's host build. (The fuzzers build their
# own instrumented copy: sanitizer and coverage flags are a different program.)

HOST_CC     ?= gcc
HOST_CFLAGS ?= -std=c11 -O2 -Wall -Wextra -Werror

GPU_MODEL_SRC      := gpu_model/gpu_model.c
GPU_MODEL_HDR      := gpu_model/gpu_model.h contract/gpu_regs.h
GPU_MODEL_INC      := -Igpu_model -Icontract
GPU_MODEL_LIB      := $(BUILD)/gpu_model/libgpu_model.a
GPU_MODEL_TEST_SRC := $(wildcard tests/model/*.c)
GPU_MODEL_TEST_HDR := $(wildcard tests/model/*.h)
GPU_MODEL_UNIT     := $(BUILD)/tests/model_unit

$(BUILD)/gpu_model/gpu_model.o: $(GPU_MODEL_SRC) $(GPU_MODEL_HDR)
	@mkdir -p $(dir $@)
	$(Q)$(call say,CC,$<)$(HOST_CC) $(HOST_CFLAGS) $(GPU_MODEL_INC) -c $< -o $@

$(GPU_MODEL_LIB): $(BUILD)/gpu_model/gpu_model.o
	@rm -f $@
	$(Q)$(call say,AR,$@)ar rcs $@ $^

# The unit-test runner: prints one line per failed check, then
# "N passed, N failed"; exits non-zero on any failure. Needs only the model's library.
$(GPU_MODEL_UNIT): $(GPU_MODEL_TEST_SRC) $(GPU_MODEL_TEST_HDR) $(GPU_MODEL_LIB)
	@mkdir -p $(dir $@)
	$(Q)$(call say,LD,$@)$(HOST_CC) $(HOST_CFLAGS) $(GPU_MODEL_INC) $(GPU_MODEL_TEST_SRC) $(GPU_MODEL_LIB) -o $@
