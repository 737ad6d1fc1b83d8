// SIOLOGIC: the I/O logic of an ECP5 top/bottom PIO as nextpnr-ecp5 packs it (the cell of its --write
// JSON, the placed-and-routed netlist), for netlist simulation of that netlist (cosim/netlist); yosys
// has no model of it. nextpnr's packer turns each ODDRX1F into the SIOLOGIC of its pad (ecp5/pack.cc
// pack_iologic): MODE "IDDRX1_ODDRX1", the ODDRX1F's D0/D1 on TXDATA0/TXDATA1, SCLK on CLK
// (CLKOMUX "CLK"), RST on LSR (LSROMUX "LSRMUX"; "0" when RST had no net), Q on IOLDO, which feeds
// the pad's TRELLIS_IO (its DATAMUX_ODDR "IOLDO").
//
// Contract (MODE "IDDRX1_ODDRX1", its output half — the ODDRX1F of cosim/netlist/ecp5/ODDRX1F.v,
// Lattice FPGA-TN-02035): at each rising edge of CLK, TXDATA0 and TXDATA1 are registered; IOLDO
// carries that TXDATA0 while CLK is high and that TXDATA1 while it is low. The reset, LSR through
// LSRMUX "LSR", clears both registers (asynchronously, as ODDRX1F.v models the primitive's RST).
// The input half (IDDRX1F: PADDI -> RXDATA0/1) is unused: its outputs are 0, and routed_json.py
// refuses a SIOLOGIC whose input half, tristate or delay pins have a net.
// GSR "ENABLED" or "DISABLED" alike: the netlist has no GSR cell.
// Refused at elaboration: any other MODE (IREG_OREG, NONE), CLKOMUX other than CLK, LSROMUX other
// than LSRMUX, LSRMUX other than LSR, an output delay (DELAY.OUTDEL ENABLED, DELAY.DEL_VALUE not 0,
// DELAY.WAIT_FOR_EDGE ENABLED) — none of which the board's netlist uses.
// Unit test: tests/boards/netlist_routed_cells.sh (a placed-and-routed design against its RTL).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// (string parameters compared with literals of other lengths, as Verilog pads them)
module SIOLOGIC (
    input  wire CLK,                    // the ODDR's bit-pair clock
    input  wire LSR,                    // the ODDR's reset (through LSRMUX)
    input  wire CE,
    input  wire TXDATA0,                // sent first, while CLK is high
    input  wire TXDATA1,                // sent second, while CLK is low
    input  wire TSDATA0,
    input  wire PADDI, DI,              // the input half: unused
    input  wire IOLDOI, LOADN, MOVE, DIRECTION,
    output wire IOLDO,                  // to the pad's TRELLIS_IO
    output wire IOLTO,
    output wire RXDATA0, RXDATA1, INFF, INDD, IOLDOD, CFLAG
);
    // The parameters nextpnr's packer may write on a SIOLOGIC (cells.cc create_ecp5_cell, pack.cc).
    parameter MODE = "NONE";
    parameter GSR = "DISABLED";
    parameter CLKIMUX = "CLK";
    parameter CLKOMUX = "CLK";
    parameter LSRIMUX = "0";
    parameter LSROMUX = "0";
    parameter LSRMUX = "LSR";
    parameter CEIMUX = "1";
    parameter CEOMUX = "1";
    parameter CEMUX = "CE";
    parameter SRMODE = "ASYNC";
    parameter \DELAY.OUTDEL = "DISABLED";
    parameter \DELAY.DEL_VALUE = 0;
    parameter \DELAY.WAIT_FOR_EDGE = "DISABLED";
    parameter \FF.INREGMODE = "BYPASS";
    parameter \FF.REGSET = "RESET";
    parameter \OUTREG.OUTREGMODE = "BYPASS";
    parameter \OUTREG.REGSET = "RESET";
    parameter \TSREG.OUTREGMODE = "BYPASS";
    parameter \TSREG.REGSET = "RESET";

    generate
        if (MODE != "IDDRX1_ODDRX1") begin : bad_mode
            $fatal(1, "SIOLOGIC: MODE %s is not modelled (IDDRX1_ODDRX1, an ODDRX1F, only)", MODE);
        end
        if (CLKOMUX != "CLK" || LSROMUX != "LSRMUX" || LSRMUX != "LSR") begin : bad_mux
            $fatal(1, "SIOLOGIC: CLKOMUX %s, LSROMUX %s, LSRMUX %s are not modelled (CLK, LSRMUX, LSR)",
                   CLKOMUX, LSROMUX, LSRMUX);
        end
        if (\DELAY.OUTDEL != "DISABLED" || \DELAY.DEL_VALUE != 0 || \DELAY.WAIT_FOR_EDGE != "DISABLED") begin : bad_delay
            $fatal(1, "SIOLOGIC: an output delay (DELAY.*) is not modelled");
        end
        if (GSR != "ENABLED" && GSR != "DISABLED") begin : bad_gsr
            $fatal(1, "SIOLOGIC: GSR %s is not modelled (ENABLED, DISABLED)", GSR);
        end
    endgenerate

    reg d0_q = 1'b0, d1_q = 1'b0;
    always @(posedge CLK or posedge LSR) begin
        if (LSR) begin
            d0_q <= 1'b0;
            d1_q <= 1'b0;
        end else begin
            d0_q <= TXDATA0;
            d1_q <= TXDATA1;
        end
    end
    assign IOLDO = CLK ? d0_q : d1_q;

    assign IOLTO = 1'b0;
    assign {RXDATA0, RXDATA1, INFF, INDD, IOLDOD, CFLAG} = 6'b0;
endmodule

`default_nettype wire
