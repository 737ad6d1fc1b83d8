#!/usr/bin/env bash
# The firmware on a machine with no GPU (plain QEMU: the GPU window reads 0) must say so and exit
# with its "GPU init" status (2), not hang or draw into nothing.
set -uo pipefail
: "${FW_ELF:?}"
out=$(timeout 20 qemu-system-riscv32 -machine virt -bios none -display none -serial stdio -monitor none \
      -icount shift=0 -kernel "$FW_ELF" </dev/null)
status=$?
echo "$out"
[ "$status" -eq 2 ] || { echo "expected exit status 2, got $status"; exit 1; }
grep -q "GPU not found" <<<"$out" || { echo "no 'GPU not found' message"; exit 1; }
echo "no-gpu: reported and exited with status 2"
