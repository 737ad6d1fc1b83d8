// DCCA: the ECP5's global clock buffer (a DCC in the clock spines; Lattice FPGA-TN-02200, "ECP5 and
// ECP5-5G sysClock PLL/DLL Design and Usage Guide": CLKO follows CLKI while CE is high), as
// nextpnr-ecp5 inserts one for each clock it promotes to a global net (ecp5/globals.cc), for netlist
// simulation of the placed-and-routed netlist (cosim/netlist); yosys ships only a black box.
//
// Contract: CLKO = CLKI, no delay. nextpnr leaves CE unconnected on the buffers it inserts, and then
// configures no gating at all (ecp5/bitstream.cc write_dcc sets the DCC's DCCA mode only when CE has
// a net): the clock passes. cosim/netlist/routed_json.py ties such a CE to 1. Clock gating (CE low)
// is not modelled: CE low at a clock edge stops the simulation with an error (also the sign that the
// JSON did not pass through routed_json.py, since an unconnected Verilog input reads 0).
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
module DCCA (
    input  wire CLKI,   // the clock
    input  wire CE,     // 1: pass (tied by routed_json.py when unconnected)
    output wire CLKO    // the global clock
);
    assign CLKO = CLKI;
    always @(posedge CLKI)
        if (!CE)
            $fatal(1, "DCCA: CE low: clock gating is not modelled (or the JSON skipped cosim/netlist/routed_json.py)");
endmodule

`default_nettype wire
