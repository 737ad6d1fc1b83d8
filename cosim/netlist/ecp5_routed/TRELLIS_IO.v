// TRELLIS_IO: an ECP5 PIO (the pad's buffer) as nextpnr-ecp5 packs it (the cell of its --write JSON,
// the placed-and-routed netlist), for netlist simulation of that netlist (cosim/netlist). It replaces
// yosys' TRELLIS_IO (share/ecp5/common_sim.vh), whose ports are B, I, T, O only: nextpnr's packer
// moves an output driven by an IOLOGIC (ODDRX1F and the like) from I to IOLDO and selects it with
// DATAMUX_ODDR "IOLDO" (ecp5/pack.cc pack_iologic; ecp5/cells.cc create_ecp5_cell declares IOLDO
// and IOLTO on every TRELLIS_IO).
//
// Contract:
//   DIR "INPUT"    O = B (the pad); B is not driven
//   DIR "OUTPUT"   B = DATAMUX_ODDR "IOLDO" ? IOLDO : I (PADDO, the default: the fabric's I); O = 0.
//                  The output is always enabled: nextpnr ties an unconnected T low for an output
//                  (ecp5/bitstream.cc write_io), and cosim/netlist/routed_json.py ties it to 0 in
//                  the JSON; T high (a tristate output) stops the simulation with an error.
// The pad's electrical attributes (IO_TYPE, DRIVE, PULLMODE, ...) change nothing here.
// B is an inout, as nextpnr declares it; on an input pad it is wired to a top-level input, and the
// simulator's lint takes that for an assignment to an input (ASSIGNIN, an error by default): build
// with -Wno-ASSIGNIN (the model never drives B there, and it simulates as written).
// Refused at elaboration: DIR "BIDIR", DATAMUX_ODDR other than PADDO/IOLDO (or IOLDO on an input),
// DATAMUX_MDDR / DATAMUX_OREG other than PADDO, TRIMUX_TSREG other than PADDT — none of which the
// board's netlist uses.
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// (string parameters compared with literals of other lengths, as Verilog pads them)
module TRELLIS_IO (
    inout  wire B,      // the pad (the top-level port)
    input  wire I,      // output data from the fabric (DATAMUX_ODDR "PADDO")
    input  wire T,      // tristate (high: not driven); tied 0 when unconnected
    input  wire IOLDO,  // output data from the IOLOGIC (DATAMUX_ODDR "IOLDO")
    input  wire IOLTO,  // tristate from the IOLOGIC: not modelled
    output wire O       // input data to the fabric
);
    // The defaults are those of nextpnr's bitstream.cc write_io for an absent parameter.
    parameter DIR = "INPUT";
    parameter DATAMUX_ODDR = "PADDO";
    parameter DATAMUX_MDDR = "PADDO";
    parameter DATAMUX_OREG = "PADDO";
    parameter TRIMUX_TSREG = "PADDT";

    generate
        if (DATAMUX_MDDR != "PADDO" || DATAMUX_OREG != "PADDO" || TRIMUX_TSREG != "PADDT") begin : bad_mux
            $fatal(1, "TRELLIS_IO: DATAMUX_MDDR %s, DATAMUX_OREG %s, TRIMUX_TSREG %s are not modelled (PADDO, PADDO, PADDT)",
                   DATAMUX_MDDR, DATAMUX_OREG, TRIMUX_TSREG);
        end
        if (DIR == "INPUT") begin : input_pad
            if (DATAMUX_ODDR != "PADDO") begin : bad_oddr
                $fatal(1, "TRELLIS_IO: an input with DATAMUX_ODDR %s is not modelled", DATAMUX_ODDR);
            end
            assign O = B;
        end else if (DIR == "OUTPUT") begin : output_pad
            if (DATAMUX_ODDR == "IOLDO") begin : from_iologic
                assign B = IOLDO;
            end else if (DATAMUX_ODDR == "PADDO") begin : from_fabric
                assign B = I;
            end else begin : bad_oddr
                $fatal(1, "TRELLIS_IO: DATAMUX_ODDR %s is not modelled (PADDO, IOLDO)", DATAMUX_ODDR);
            end
            assign O = 1'b0;
            always @(T)
                if (T)
                    $fatal(1, "TRELLIS_IO: T high (a tristate output) is not modelled");
        end else begin : bad_dir
            $fatal(1, "TRELLIS_IO: DIR %s is not modelled (INPUT, OUTPUT)", DIR);
        end
    endgenerate
endmodule

`default_nettype wire
