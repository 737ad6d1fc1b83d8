#!/usr/bin/env bash
# soc_proj_unit, the SoC's projection unit, against the firmware's fixed-point projection compiled
# from its own sources (tests/rtl/proj_unit_tb.cpp, proj_unit_ref.c): every answer word for word
# over random set-ups, transforms and vertices, and the custom-function handshake; its seed table
# entry by entry (--public-flat-rw: the testbench reads the ROM).
set -euo pipefail
: "${BUILD:?}" "${VERILATOR_RT:?}"
dir="$BUILD/tests/proj-unit"
mkdir -p "$dir"
fw_flags="-std=c11 -O2 -Wall -Wextra -Werror -Ifirmware -Icontract -Itests/rtl"
objs=""
for src in tests/rtl/proj_unit_ref.c firmware/render/proj.c firmware/math/fixed.c firmware/math/vec.c; do
    obj="$dir/$(basename "${src%.c}").o"
    cc $fw_flags -c "$src" -o "$obj"
    objs="$objs $PWD/$obj"
done
verilator --cc --exe --build -j 2 -O3 --assert --public-flat-rw --top-module soc_proj_unit soc_rtl/soc_pkg.sv soc_rtl/soc_proj_unit.v \
    "$PWD/tests/rtl/proj_unit_tb.cpp" -CFLAGS "-O2 -std=c++17 -I$PWD/tests/rtl -I$PWD/contract" \
    -LDFLAGS "$objs $VERILATOR_RT" --MAKEFLAGS "VM_GLOBAL_FAST= VM_GLOBAL_SLOW=" --Mdir "$dir/obj" \
    -o "$PWD/$dir/proj_unit_tb" >"$dir/verilator.log" 2>&1 || { tail -20 "$dir/verilator.log"; exit 1; }
"$dir/proj_unit_tb" "${PROJ_UNIT_VERTICES:-200000}"
