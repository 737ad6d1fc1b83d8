// TRELLIS_IO: an ECP5 pad buffer, as LiteDRAM's generated core (soc_rtl/litedram) instantiates it
// for the SDRAM's DQ pins, for the RTL simulations (socsim, tests/sdram). yosys' own model
// (share/ecp5/common_sim.vh) tests `T === 1'bz`, which Verilator 5.006 refuses ("tristate in
// top-level IO"); this one is the same buffer in two-state logic.
//
// Contract:
//   DIR "INPUT"    O = B; B not driven
//   DIR "OUTPUT"   B = I while T is low, not driven while T is high; O = 0
//   DIR "BIDIR"    both: B = I while T is low (the FPGA drives the pad), O = B always
// T is the active-high tristate of Lattice's BB/OBZ buffers (FPGA Libraries Reference Guide).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off WIDTH
// (the DIR string compared with literals of other lengths, as Verilog pads them)
module TRELLIS_IO (
    inout  wire B,      // the pad
    input  wire I,      // output data from the fabric
    input  wire T,      // tristate: high = the pad is not driven
    output wire O       // input data to the fabric
);
    parameter DIR = "INPUT";

    generate
        if (DIR == "INPUT") begin : input_pad
            assign O = B;
        end else if (DIR == "OUTPUT") begin : output_pad
            assign B = T ? 1'bz : I;
            assign O = 1'b0;
        end else if (DIR == "BIDIR") begin : bidir_pad
            assign B = T ? 1'bz : I;
            assign O = B;
        end else begin : bad_dir
            $fatal(1, "TRELLIS_IO: DIR %s is not modelled (INPUT, OUTPUT, BIDIR)", DIR);
        end
    endgenerate
endmodule

`default_nettype wire
