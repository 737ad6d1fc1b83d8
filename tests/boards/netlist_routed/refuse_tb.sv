// refuse_tb: the run-time refusals of cosim/netlist/ecp5_routed, for
// tests/boards/netlist_routed_cells.sh: a DCCA whose CE goes low (clock gating: not modelled) and
// an output TRELLIS_IO whose T goes high (a tristate output: not modelled) must stop the simulation
// with their error; with +case=none neither happens and the run ends normally.
`timescale 1ps / 1ps
`default_nettype none

module refuse_tb;
    reg clk = 1'b0, ce = 1'b1, t = 1'b0;
    wire gclk, pad;
    DCCA u_dcc (.CLKI(clk), .CE(ce), .CLKO(gclk));
    TRELLIS_IO #(.DIR("OUTPUT")) u_io (.B(pad), .I(gclk), .T(t));

    initial begin : run
        string which;
        if (!$value$plusargs("case=%s", which))
            which = "none";
        repeat (3) begin
            #5 clk = 1'b1;
            #5 clk = 1'b0;
        end
        if (pad !== gclk)
            $fatal(1, "refuse_tb: the pad does not follow the global clock");
        if (which == "dcca")
            ce = 1'b0;
        if (which == "tristate")
            t = 1'b1;
        repeat (3) begin
            #5 clk = 1'b1;
            #5 clk = 1'b0;
        end
        $display("refuse_tb: no error (%s)", which);
        $finish;
    end
endmodule

`default_nettype wire
