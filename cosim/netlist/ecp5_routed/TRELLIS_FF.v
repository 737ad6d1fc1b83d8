// TRELLIS_FF: one flip-flop of an ECP5 SLICE as nextpnr-ecp5 packs it (the cell of its --write JSON,
// the placed-and-routed netlist), for netlist simulation of that netlist (cosim/netlist). It replaces
// yosys' TRELLIS_FF (share/ecp5/common_sim.vh), which disagrees with nextpnr's packed cells: yosys
// always registers DI (M only preloads, LSRMODE "PRLD"), while nextpnr's packer feeds half of the
// flip-flops from M: ecp5/pack.cc pack_ffs keeps DI (and sets SD "1") only when a LUT of the same
// slice drives it, and otherwise renames DI to M and sets SD "0" (the slice's M input, general
// routing), as the bitstream's REGn.SD mux then selects (ecp5/bitstream.cc write_ff).
//
// Contract: at each rising edge of CLK, Q takes
//   the set/reset value (REGSET "SET": 1, "RESET": 0)  when LSR is high (SRMODE "LSR_OVER_CE": a
//                                                       synchronous reset, ahead of the enable)
//   D = SD "1" ? DI : M                                 else when the enable is high:
//                                                       CEMUX "CE": CE; "INV": ~CE; "1": always
// and Q starts at the set/reset value (the configuration's global reset). LSRMUX "LSR", CLKMUX
// "CLK". An unconnected LSR means no reset: nextpnr's packer disconnects an LSR tied to its inactive
// level (pack.cc set_net_constant), so cosim/netlist/routed_json.py ties it back to that level (0 for
// LSRMUX "LSR"); an unconnected CE comes with CEMUX "1" (or "0", not modelled) and is then unused.
// GSR "ENABLED" or "DISABLED" alike: the netlist has no GSR cell to pulse the global reset (a GSR
// cell would have no model, and netlist_cells.py would say so).
// Refused at elaboration: SD absent or other than "0"/"1" (the cell is not a packed one), CEMUX
// "0", LSRMUX "INV", CLKMUX "INV", SRMODE "ASYNC", LSRMODE "PRLD", REGSET other than SET/RESET —
// none of which the board's netlist uses.
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// (string parameters compared with literals of other lengths, as Verilog pads them)
module TRELLIS_FF (
    input  wire CLK,    // the clock (rising edge)
    input  wire LSR,    // the synchronous set/reset (high)
    input  wire CE,     // the clock enable, as CEMUX says
    input  wire DI,     // data from the slice's own LUT (SD "1")
    input  wire M,      // data from general routing (SD "0")
    output reg  Q
);
    // The defaults are those of nextpnr's bitstream.cc write_ff for an absent parameter (SD aside).
    parameter GSR = "ENABLED";
    parameter CEMUX = "1";
    parameter CLKMUX = "CLK";
    parameter LSRMUX = "LSR";
    parameter SRMODE = "LSR_OVER_CE";
    parameter REGSET = "RESET";
    parameter LSRMODE = "LSR";
    parameter SD = "none";

    localparam SRVAL = REGSET == "SET";

    generate
        if (SD != "0" && SD != "1") begin : no_sd
            $fatal(1, "TRELLIS_FF: SD %s: nextpnr's packer sets SD 0 (data from M) or 1 (from DI); is this a placed-and-routed netlist?", SD);
        end
        if (CEMUX != "CE" && CEMUX != "INV" && CEMUX != "1") begin : bad_ce
            $fatal(1, "TRELLIS_FF: CEMUX %s is not modelled (CE, INV, 1)", CEMUX);
        end
        if (LSRMUX != "LSR" || CLKMUX != "CLK") begin : bad_mux
            $fatal(1, "TRELLIS_FF: LSRMUX %s, CLKMUX %s are not modelled (LSR, CLK only)", LSRMUX, CLKMUX);
        end
        if (SRMODE != "LSR_OVER_CE" || LSRMODE != "LSR") begin : bad_sr
            $fatal(1, "TRELLIS_FF: SRMODE %s, LSRMODE %s are not modelled (a synchronous reset only: LSR_OVER_CE, LSR)", SRMODE, LSRMODE);
        end
        if (REGSET != "SET" && REGSET != "RESET") begin : bad_regset
            $fatal(1, "TRELLIS_FF: REGSET %s is not modelled (SET, RESET)", REGSET);
        end
        if (GSR != "ENABLED" && GSR != "DISABLED") begin : bad_gsr
            $fatal(1, "TRELLIS_FF: GSR %s is not modelled (ENABLED, DISABLED)", GSR);
        end
    endgenerate

    wire d = SD == "1" ? DI : M;
    wire en = CEMUX == "CE" ? CE : CEMUX == "INV" ? ~CE : 1'b1;

    initial Q = SRVAL;
    always @(posedge CLK)
        if (LSR)
            Q <= SRVAL;
        else if (en)
            Q <= d;
endmodule

`default_nettype wire
