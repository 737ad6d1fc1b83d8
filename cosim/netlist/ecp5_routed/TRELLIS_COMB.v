// TRELLIS_COMB: one LUT4 of an ECP5 SLICE as nextpnr-ecp5 packs it (the cell of its --write JSON,
// the placed-and-routed netlist), for netlist simulation of that netlist (cosim/netlist). It replaces
// yosys' TRELLIS_COMB (share/ecp5/common_sim.vh), which disagrees with nextpnr's packed cells: its
// CCU2 mode declares FCO again inside the generate block, so the port FCO is never driven (every
// carry chain breaks); its DPRAM mode loads INITVAL in address order while nextpnr stores it in
// LUT-input order; and its OFX follows a parameter IS_Z1 that nextpnr never writes.
//
// Contract (the semantics of nextpnr's ecp5/cells.cc lut_to_comb, ccu2_to_comb, dram_to_comb and
// ecp5/pack.cc, read with ecp5/bitstream.cc write_comb and yosys' ccu2c_sim.vh for the carry):
//   LUT   L = INITVAL[{D, C, B, A}] in every mode (A the index's bit 0, as yosys' LUT4 reads INIT)
//   MODE "LOGIC" (the default)  F = L
//   MODE "CCU2"  one half of a CCU2C: F = L ^ cin, FCO = (~L & g) | (L & FCI), where
//                g = INITVAL[{B, A}] (the half's LUT2) and cin = FCI, both forced to 0 when
//                CCU2_INJECT1 is "YES"; the carry passes through the FCO -> FCI nets
//   MODE "DPRAM" one bit of a 16x4 distributed RAM (TRELLIS_DPR16X4 split by dram_to_comb): F = the
//                stored LUT at {D, C, B, A}, the read address RAD[0..3] on D, B, C, A; it starts as
//                INITVAL, which dram_to_comb has already permuted into that LUT order. At a rising
//                edge of WCK, when WRE is high, WD is written at write address WAD0..3 (from the
//                TRELLIS_RAMW's WADO0..3, the RAM's WAD[0..3]), which lands on the LUT index that the
//                same read address selects: WAD0 on D, WAD1 on B, WAD2 on C, WAD3 on A
//   MODE "RAMW_BLOCK"  nextpnr's placeholder for the LUTs that the slice's TRELLIS_RAMW takes over
//                (bitstream.cc write_comb writes nothing for it): no function, outputs 0
//   OFX          the slice's wide-function mux, which one depending on the LUT's place (IS_Z1):
//                IS_Z1 = 0 (the slice's K0 LUT): the PFUMX of a LUT5, OFX = M ? F1 : F
//                IS_Z1 = 1 (its K1 LUT): the L6MUX21 of a LUT6/7, OFX = M ? FXB : FXA
//                (pack.cc pack_lut5xs: a PFUMX's ALUT/BLUT/C0/Z become F1/F/M/OFX of the BLUT's comb;
//                an L6MUX21's D0/D1/SD/Z become FXA/FXB/M/OFX of a second LUT). nextpnr's JSON has no
//                IS_Z1: cosim/netlist/routed_json.py writes it from the placement (NEXTPNR_BEL ".K0"
//                or ".K1"); a cell without it is refused. OFX is 0 in the other modes.
// A LUT input that nextpnr left unconnected reads 1 in the fabric (bitstream.cc write_comb sets the
// unrouted input's mux to "1"; pack.cc relies on it for CCU2 inputs tied high and for the carry
// feed-in's LUT4 = 0): routed_json.py ties such inputs to 1 in the JSON, since an unconnected
// Verilog input reads 0. Refused at elaboration: any other MODE, CCU2_INJECT1, WREMUX or WCKMUX.
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// (string parameters compared with literals of other lengths, as Verilog pads them)
module TRELLIS_COMB (
    input  wire A, B, C, D,             // the LUT's inputs (the read address in DPRAM mode)
    input  wire M,                      // the OFX mux's select
    input  wire F1, FXA, FXB,           // the OFX mux's data (PFUMX: F1; L6MUX21: FXA, FXB)
    input  wire FCI,                    // carry in (CCU2)
    input  wire DI0, DI1,               // nextpnr declares them; nothing drives them in a packed cell
    input  wire WD, WAD0, WAD1, WAD2, WAD3, WRE, WCK,  // the DPRAM write port
    output wire F,                      // the LUT (CCU2: the sum)
    output wire FCO,                    // carry out (CCU2)
    output wire OFX                     // the wide-function mux
);
    parameter MODE = "LOGIC";
    parameter [15:0] INITVAL = 16'h0000;
    parameter CCU2_INJECT1 = "YES";     // bitstream.cc's default when absent
    parameter WREMUX = "WRE";
    parameter WCKMUX = "WCK";
    parameter IS_Z1 = -1;               // written by routed_json.py: 0 for a K0 LUT, 1 for K1

    wire lut = INITVAL[{D, C, B, A}];
    wire mux = IS_Z1 == 1 ? (M ? FXB : FXA) : (M ? F1 : F);

    generate
        if (IS_Z1 != 0 && IS_Z1 != 1) begin : no_place
            $fatal(1, "TRELLIS_COMB: no IS_Z1 (0 for a K0 LUT, 1 for K1): pass nextpnr's JSON through cosim/netlist/routed_json.py first");
        end
        if (MODE == "LOGIC") begin : logic_mode
            assign F = lut;
            assign FCO = 1'b0;
            assign OFX = mux;
        end else if (MODE == "CCU2") begin : ccu2_mode
            if (CCU2_INJECT1 != "YES" && CCU2_INJECT1 != "NO") begin : bad_inject
                $fatal(1, "TRELLIS_COMB: CCU2_INJECT1 %s is not modelled (YES or NO)", CCU2_INJECT1);
            end
            wire inject = CCU2_INJECT1 == "YES";
            wire gen = inject ? 1'b0 : INITVAL[{B, A}];
            assign F = lut ^ (inject ? 1'b0 : FCI);
            assign FCO = (~lut & gen) | (lut & FCI);
            assign OFX = 1'b0;
        end else if (MODE == "DPRAM") begin : dpram_mode
            if (WREMUX != "WRE" || WCKMUX != "WCK") begin : bad_mux
                $fatal(1, "TRELLIS_COMB: DPRAM with WREMUX %s, WCKMUX %s is not modelled (WRE, WCK only)", WREMUX, WCKMUX);
            end
            reg [15:0] ram = INITVAL;   // LUT order, as F reads it
            always @(posedge WCK)
                if (WRE)
                    ram[{WAD0, WAD2, WAD1, WAD3}] <= WD;
            assign F = ram[{D, C, B, A}];
            assign FCO = 1'b0;
            assign OFX = 1'b0;
        end else if (MODE == "RAMW_BLOCK") begin : ramw_block
            assign F = 1'b0;
            assign FCO = 1'b0;
            assign OFX = 1'b0;
        end else begin : bad_mode
            $fatal(1, "TRELLIS_COMB: MODE %s is not modelled (LOGIC, CCU2, DPRAM, RAMW_BLOCK)", MODE);
        end
    endgenerate
endmodule

`default_nettype wire
