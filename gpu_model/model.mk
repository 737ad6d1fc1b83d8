# gpu_model/model.mk - make fragment for the golden C model and its unit tests.
# Included by the top-level Makefile after it defines BUILD, HOST_CC and
# HOST_CFLAGS (the defaults below only apply if it does not).

HOST_CC     ?= gcc
HOST_CFLAGS ?= -std=c11 -O2 -Wall -Wextra -Werror

GPU_MODEL_SRC      := gpu_model/gpu_model.c
GPU_MODEL_HDR      := gpu_model/gpu_model.h firmware/include/gpu_regs.h
GPU_MODEL_TEST_SRC := $(wildcard tests/model/*.c)
GPU_MODEL_TEST_HDR := $(wildcard tests/model/*.h)
GPU_MODEL_UNIT     := $(BUILD)/tests/model_unit

# The unit-test runner: prints one line per failed check, then
# "N passed, N failed"; exits non-zero on any failure.  No libraries needed.
$(GPU_MODEL_UNIT): $(GPU_MODEL_SRC) $(GPU_MODEL_HDR) $(GPU_MODEL_TEST_SRC) $(GPU_MODEL_TEST_HDR)
	@mkdir -p $(dir $@)
	$(HOST_CC) $(HOST_CFLAGS) -Igpu_model -Ifirmware/include \
		$(GPU_MODEL_SRC) $(GPU_MODEL_TEST_SRC) -o $@
