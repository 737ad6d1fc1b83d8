#!/usr/bin/env bash
# verilator --lint-only -Wall of the Digilent board tops (basys3_top, nexys_a7_top) with the whole
# SoC under them; the Xilinx primitives from the lint-only stand-ins in boards/digilent/lint/; the
# waivers of gpu_rtl/lint.vlt, soc_rtl/lint.vlt, soc_rtl/usb/lint.vlt and boards/digilent/lint.vlt.
# Usage, from anywhere: [VENV=path/.venv] boards/digilent/lint.sh [basys3|nexys_a7 ...]
set -euo pipefail
cd "$(dirname "$0")/../.."
venv="${VENV:-.venv}"
cpu_v="$("$venv/bin/python" -c 'import os, pythondata_cpu_vexriscv as p; print(os.path.join(p.data_location, "VexRiscv_FullCfu.v"))')"
for board in "${@:-basys3 nexys_a7}"; do
    for b in $board; do
        verilator --lint-only -Wall --top-module "${b}_top" gpu_rtl/lint.vlt soc_rtl/lint.vlt soc_rtl/usb/lint.vlt \
            boards/digilent/lint.vlt -f gpu_rtl/files.f "$cpu_v" -f soc_rtl/files.f \
            -f boards/digilent/files.f boards/digilent/lint/BUFG.v boards/digilent/lint/MMCME2_BASE.v \
            "boards/$b/${b}_top.v"
        echo "lint: ${b}_top clean under -Wall"
    done
done
