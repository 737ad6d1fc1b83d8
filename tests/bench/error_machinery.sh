#!/usr/bin/env bash
# The machinery of `make bench-error` (which is too long for `make test`), on tiny inputs:
#  1. the metric (tools/png_diff through bench/bench_error.py): 0 for identical images, the known
#     count and sum for two changed pixels, one pixel per block with --block, box means with
#     --box (changes in two boxes add, changes in one box cancel), sizes checked;
#  2. FW_SUBPIXEL_BITS=4 builds the same program as the default build (tetra, fixed point: the
#     loaded bytes of the two ELFs are equal);
#  3. FW_SUBPIXEL_BITS outside 0..4 is refused by the build.
source "$(dirname "$0")/../lib.sh"
need BUILD PYTHON
work=$(fresh_dir bench-error-machinery)

# 1.
"$PYTHON" bench/bench_error.py --check-metric "$BUILD/tools/png_diff" "$work"

# 2.
objcopy=riscv64-unknown-elf-objcopy
"$objcopy" -O binary "$BUILD/fw-test/tetra.elf" "$work/default.bin"
"$objcopy" -O binary "$BUILD/fw-test/tetra-fixed-sp4.elf" "$work/sp4.bin"
[ -s "$work/default.bin" ] || fail "empty image from tetra.elf"
cmp -s "$work/default.bin" "$work/sp4.bin" || fail "FW_SUBPIXEL_BITS=4 is not the default program"
echo "sub-pixel: FW_SUBPIXEL_BITS=4 gives the default program ($(stat -c %s "$work/sp4.bin") bytes, equal)"

# 3.
if make --no-print-directory -n BUILD="$work/b" FW_SUBPIXEL_BITS=5 fw >"$work/sp5.log" 2>&1; then
    fail "FW_SUBPIXEL_BITS=5 was accepted"
fi
expect_line "FW_SUBPIXEL_BITS=5 is not one of" "$work/sp5.log"
pass "bench-error machinery: metric exact on known images, FW_SUBPIXEL_BITS=4 = default build, 5 refused"
