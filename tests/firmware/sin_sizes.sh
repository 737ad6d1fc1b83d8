#!/usr/bin/env bash
# The sine table's sizes (FW_SIN_TABLE_BITS = 6, 8, 10; math/fixed.h): each built on the host with
# the sine cases of the unit tests (sin_sizes/main.c), each within its own error bound, its table
# exact to its own rounding, and the camera path's sine the same at every size. About 1 s of CPU.
source "$(dirname "$0")/../lib.sh"
need BUILD
CC=${HOST_CC:-gcc}
out=$(fresh_dir fw-sin-sizes)
for bits in 6 8 10; do
    "$CC" -std=c11 -O2 -Wall -Wextra -Werror -ffp-contract=off -Itests/firmware -Ifirmware \
        -DFW_SIN_TABLE_BITS=$bits tests/firmware/sin_sizes/main.c tests/firmware/unit_rand.c \
        tests/firmware/test_fixed.c tests/firmware/test_cam_path.c firmware/math/fixed.c -o "$out/sin$bits" -lm
    "$out/sin$bits" || fail "FW_SIN_TABLE_BITS=$bits"
done
# A size the table does not have is refused at compile time.
if "$CC" -std=c11 -Ifirmware -DFW_SIN_TABLE_BITS=7 -c firmware/math/fixed.c -o "$out/bad.o" 2>"$out/bad.err"; then
    fail "FW_SIN_TABLE_BITS=7 compiled"
fi
grep -q "FW_SIN_TABLE_BITS must be 6, 8 or 10" "$out/bad.err" || fail "FW_SIN_TABLE_BITS=7: no clear error"
pass "sine table: 64, 256 and 1024 entries each within its bound and exact to its rounding; the path's sine unchanged"
