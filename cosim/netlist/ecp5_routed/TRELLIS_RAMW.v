// TRELLIS_RAMW: the write half of an ECP5 distributed RAM as nextpnr-ecp5 packs it (SLICEC in RAMW
// mode: the LUT inputs of that slice carry a 16x4 RAM's write address and data to the DPRAM LUTs of
// SLICEA/B), for netlist simulation of the placed-and-routed netlist (cosim/netlist); yosys has no
// model of it.
//
// Contract: outputs follow inputs at once, one wire each:
//   WADO0 = D0, WADO1 = B0, WADO2 = C0, WADO3 = A0   (the RAM's write address WAD[0..3])
//   WDO0  = C1, WDO1  = A1, WDO2  = D1, WDO3  = B1   (its write data DI[0..3])
// Source: nextpnr ecp5/arch.cc getCellDelay (the TRELLIS_RAMW's only timing arcs, A0 -> WADO3,
// B0 -> WADO1, C0 -> WADO2, D0 -> WADO0, A1 -> WDO1, B1 -> WDO3, C1 -> WDO0, D1 -> WDO2, zero delay),
// with ecp5/cells.cc dram_to_ramw_split (WAD[0..3] onto D0, B0, C0, A0; DI[0..3] onto C1, A1, D1, B1)
// and dram_to_comb (WADOi -> the DPRAM LUT's WADi, WDOi -> WD of the LUT of data bit i): WADOi is
// the RAM's WAD[i] and WDOi its DI[i]. The write itself (at WCK, when WRE) happens in the DPRAM
// TRELLIS_COMB. routed_json.py refuses a TRELLIS_RAMW with an unconnected input (nextpnr ties none).
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
module TRELLIS_RAMW (
    input  wire A0, B0, C0, D0,     // the write address: WAD[3], WAD[1], WAD[2], WAD[0]
    input  wire A1, B1, C1, D1,     // the write data: DI[1], DI[3], DI[0], DI[2]
    output wire WADO0, WADO1, WADO2, WADO3,
    output wire WDO0, WDO1, WDO2, WDO3
);
    assign WADO0 = D0;
    assign WADO1 = B0;
    assign WADO2 = C0;
    assign WADO3 = A0;
    assign WDO0 = C1;
    assign WDO1 = A1;
    assign WDO2 = D1;
    assign WDO3 = B1;
endmodule

`default_nettype wire
