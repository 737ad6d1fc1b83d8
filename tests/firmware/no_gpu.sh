#!/usr/bin/env bash
# The firmware on a machine with no GPU (plain QEMU: the GPU window reads 0) must say so and exit
# with its "GPU init" status (2), not hang or draw into nothing.
source "$(dirname "$0")/../lib.sh"
need FW_ELF BUILD
work=$(fresh_dir fw-no-gpu)
run_to "$work/uart" 20 qemu-system-riscv32 -machine virt -bios none -display none -serial stdio -monitor none \
    -icount shift=0 -kernel "$FW_ELF" </dev/null
cat "$work/uart"
expect_status 2 "the firmware without a GPU"
expect_line "GPU not found" "$work/uart"
pass "no-gpu: reported and exited with status 2"
