#!/usr/bin/env bash
# The ECP5 cell models of make netlist-sim (cosim/netlist/ecp5) against behavioural references
# (tests/boards/netlist_cells_tb.sv): MULT18X18D in every sign mode, ODDRX1F's bit order, DP16KD at
# the widths and write modes the board uses, EHXPLLL
# through the board's ulx3s_pll at SYS_MHZ 50 (NETLIST_CELLS_SYS_MHZ='50 25' adds 25: periods, alignment, LOCK); and the models
# refuse what they do not model with a clear error: a registered MULT18X18D, a PLL phase shift.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir boards-netlist-cells)
models=(cosim/netlist/ecp5/MULT18X18D.v cosim/netlist/ecp5/ODDRX1F.v cosim/netlist/ecp5/EHXPLLL.v cosim/netlist/ecp5/DP16KD.v)

# build NAME TOP ARG...: Verilator --binary --timing of TOP with the models, into $work/NAME; sets $status
build() {
    local name=$1 top=$2
    shift 2
    run_to "$work/$name.build.log" 600 verilator --binary --timing --timescale 1ps/1ps -Wno-fatal -Wno-lint -Wno-style -Werror-USERFATAL \
        --top-module "$top" --Mdir "$work/$name" -o "$name" "$@"
}

for sys_mhz in ${NETLIST_CELLS_SYS_MHZ:-50}; do
    build "cells$sys_mhz" netlist_cells_tb "${models[@]}" boards/ulx3s/ulx3s_pll.v tests/boards/netlist_cells_tb.sv \
        -DPLL_SYS_MHZ=$sys_mhz -DSEED=$sys_mhz -DWANT_TMDS_PS=8000 -DWANT_PIX_PS=40000 -DWANT_SYS_PS=$((1000000 / sys_mhz))
    expect_status 0 "building the cell models' test at SYS_MHZ $sys_mhz (log: $work/cells$sys_mhz.build.log)"
    run_to "$work/cells$sys_mhz.out" 120 "$work/cells$sys_mhz/cells$sys_mhz"
    expect_status 0 "the cell models' test at SYS_MHZ $sys_mhz (log: $work/cells$sys_mhz.out)"
    expect_line '^netlist_cells: ok' "$work/cells$sys_mhz.out"
    grep '^netlist_cells: ok' "$work/cells$sys_mhz.out"
done

# What the models do not model is refused at elaboration, naming the cell.
cat >"$work/bad_mult.v" <<'V'
module bad_mult(input wire [17:0] a, output wire p0);
    MULT18X18D #(.REG_OUTPUT_CLK("CLK0")) u (.A0(a[0]), .B0(a[1]), .P0(p0));
endmodule
V
cat >"$work/bad_pll.v" <<'V'
module bad_pll(input wire clk, output wire o);
    EHXPLLL #(.CLKOP_DIV(6), .CLKOP_CPHASE(3), .CLKFB_DIV(5)) u (.CLKI(clk), .CLKFB(o), .CLKOP(o));
endmodule
V
build bad_mult bad_mult --lint-only "${models[0]}" "$work/bad_mult.v"
[ "$status" -ne 0 ] || fail "a registered MULT18X18D was accepted"
expect_line 'MULT18X18D: a registered mode' "$work/bad_mult.build.log"
build bad_pll bad_pll --lint-only "${models[2]}" "$work/bad_pll.v"
[ "$status" -ne 0 ] || fail "a PLL output with a phase shift was accepted"
expect_line 'EHXPLLL: only 0-degree phases' "$work/bad_pll.build.log"
pass "boards-netlist-cells: MULT18X18D, ODDRX1F, DP16KD and EHXPLLL (SYS_MHZ ${NETLIST_CELLS_SYS_MHZ:-50}) equal their references; unmodelled modes refused"
