// EHXPLLL: the ECP5's PLL (Lattice FPGA-TN-02200, "ECP5 and ECP5-5G sysClock PLL/DLL Design and
// Usage Guide"; the ports and parameters of yosys' share/ecp5/cells_bb.v), for netlist simulation
// (make netlist-sim, cosim/netlist) — yosys ships only a black box. Needs Verilator's --timing.
//
// Contract: the output clocks follow from the netlist's own dividers and the input's measured period,
// so the simulation runs the clocks the board would, at their true ratios, and a wrong divider shows:
//   VCO period  = CLKI period x CLKI_DIV / (CLKFB_DIV x the feedback output's divider)
//   CLKOx period = VCO period x CLKOx_DIV          (x = P, S, S2, S3; an output not ENABLED stays low)
// The VCO must lie within 400..800 MHz (TN-02200), every half period must be a whole picosecond, and
// the phases must be 0 degrees (CLKOx_CPHASE = CLKOx_DIV, FPHASE 0, as ulx3s_pll sets them): the
// outputs start together at a rising edge of CLKI, the third one seen (two to measure the period).
// LOCK (and INTLOCK) rises LOCK_CYCLES input periods later: the real lock time (the datasheet's tLOCK,
// up to milliseconds) would only lengthen the simulation, and the design holds its clock domains in
// reset until LOCK whatever it is. Anything else (feedback from an internal path, dynamic phase,
// standby, the reset input enabled) is a clear error at elaboration, not a wrong model.
// Unit test: tests/boards/netlist_cells.sh (ulx3s_pll's dividers: periods, alignment, LOCK).
`default_nettype none
`timescale 1ps / 1ps

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// (the string parameters are compared with literals of other lengths, as Verilog pads them)
module EHXPLLL (
    input  wire CLKI, CLKFB,
    input  wire PHASESEL1, PHASESEL0, PHASEDIR, PHASESTEP, PHASELOADREG,
    input  wire STDBY, PLLWAKESYNC, RST,
    input  wire ENCLKOP, ENCLKOS, ENCLKOS2, ENCLKOS3,
    output reg  CLKOP, CLKOS, CLKOS2, CLKOS3,
    output wire LOCK, INTLOCK, REFCLK, CLKINTFB
);
    parameter CLKI_DIV = 1;
    parameter CLKFB_DIV = 1;
    parameter CLKOP_DIV = 8;
    parameter CLKOS_DIV = 8;
    parameter CLKOS2_DIV = 8;
    parameter CLKOS3_DIV = 8;
    parameter CLKOP_ENABLE = "ENABLED";
    parameter CLKOS_ENABLE = "DISABLED";
    parameter CLKOS2_ENABLE = "DISABLED";
    parameter CLKOS3_ENABLE = "DISABLED";
    parameter CLKOP_CPHASE = 0;
    parameter CLKOS_CPHASE = 0;
    parameter CLKOS2_CPHASE = 0;
    parameter CLKOS3_CPHASE = 0;
    parameter CLKOP_FPHASE = 0;
    parameter CLKOS_FPHASE = 0;
    parameter CLKOS2_FPHASE = 0;
    parameter CLKOS3_FPHASE = 0;
    parameter FEEDBK_PATH = "CLKOP";
    parameter CLKOP_TRIM_POL = "RISING";
    parameter CLKOP_TRIM_DELAY = 0;
    parameter CLKOS_TRIM_POL = "RISING";
    parameter CLKOS_TRIM_DELAY = 0;
    parameter OUTDIVIDER_MUXA = "DIVA";
    parameter OUTDIVIDER_MUXB = "DIVB";
    parameter OUTDIVIDER_MUXC = "DIVC";
    parameter OUTDIVIDER_MUXD = "DIVD";
    parameter PLL_LOCK_MODE = 0;
    parameter PLL_LOCK_DELAY = 200;
    parameter STDBY_ENABLE = "DISABLED";
    parameter REFIN_RESET = "DISABLED";
    parameter SYNC_ENABLE = "DISABLED";
    parameter INT_LOCK_STICKY = "ENABLED";
    parameter DPHASE_SOURCE = "DISABLED";
    parameter PLLRST_ENA = "DISABLED";
    parameter INTFB_WAKE = "DISABLED";

    localparam integer LOCK_CYCLES = 25;  // input periods from the first output edge to LOCK
    localparam integer FB_DIV = FEEDBK_PATH == "CLKOP" ? CLKOP_DIV : FEEDBK_PATH == "CLKOS" ? CLKOS_DIV
                              : FEEDBK_PATH == "CLKOS2" ? CLKOS2_DIV : FEEDBK_PATH == "CLKOS3" ? CLKOS3_DIV : 0;

    generate
        if (FB_DIV == 0) begin : g_bad_feedback
            $fatal(1, "EHXPLLL: FEEDBK_PATH %s is not modelled (an output's feedback only)", FEEDBK_PATH);
        end
        if (CLKOP_ENABLE == "ENABLED" && (CLKOP_CPHASE != CLKOP_DIV || CLKOP_FPHASE != 0)
            || CLKOS_ENABLE == "ENABLED" && (CLKOS_CPHASE != CLKOS_DIV || CLKOS_FPHASE != 0)
            || CLKOS2_ENABLE == "ENABLED" && (CLKOS2_CPHASE != CLKOS2_DIV || CLKOS2_FPHASE != 0)
            || CLKOS3_ENABLE == "ENABLED" && (CLKOS3_CPHASE != CLKOS3_DIV || CLKOS3_FPHASE != 0)) begin : g_bad_phase
            $fatal(1, "EHXPLLL: only 0-degree phases (CPHASE = DIV, FPHASE 0) are modelled");
        end
        if (STDBY_ENABLE != "DISABLED" || DPHASE_SOURCE != "DISABLED" || PLLRST_ENA != "DISABLED"
            || INTFB_WAKE != "DISABLED") begin : g_bad_mode
            $fatal(1, "EHXPLLL: standby, dynamic phase, the reset input and INTFB_WAKE are not modelled");
        end
    endgenerate

    // Half periods in ps, from the measured input period (a whole number of ps, checked).
    function automatic longint half_ps(input longint in_ps, input integer div);
        longint num;
        num = in_ps * CLKI_DIV * div;
        if (num % (2 * CLKFB_DIV * FB_DIV) != 0) begin
            $fatal(1, "EHXPLLL: an output's half period is no whole picosecond (input %0d ps, divider %0d)",
                   in_ps, div);
        end
        return num / (2 * CLKFB_DIV * FB_DIV);
    endfunction

    longint in_ps = 0, vco_ps_x1000 = 0;
    longint half_op = 0, half_os = 0, half_os2 = 0, half_os3 = 0;
    reg running = 1'b0, locked = 1'b0;

    initial begin : start
        longint t_first;
        {CLKOP, CLKOS, CLKOS2, CLKOS3} = 4'b0000;
        @(posedge CLKI);
        t_first = $time;
        @(posedge CLKI);
        in_ps = $time - t_first;
        vco_ps_x1000 = in_ps * CLKI_DIV * 1000 / (CLKFB_DIV * FB_DIV);
        if (vco_ps_x1000 < 1250000 || vco_ps_x1000 > 2500000) begin
            $fatal(1, "EHXPLLL: VCO at %0d.%03d ps is outside 400..800 MHz (input %0d ps)",
                   vco_ps_x1000 / 1000, vco_ps_x1000 % 1000, in_ps);
        end
        if (CLKOP_ENABLE == "ENABLED") half_op = half_ps(in_ps, CLKOP_DIV);
        if (CLKOS_ENABLE == "ENABLED") half_os = half_ps(in_ps, CLKOS_DIV);
        if (CLKOS2_ENABLE == "ENABLED") half_os2 = half_ps(in_ps, CLKOS2_DIV);
        if (CLKOS3_ENABLE == "ENABLED") half_os3 = half_ps(in_ps, CLKOS3_DIV);
        @(posedge CLKI);
        running = 1'b1;
        #(in_ps * LOCK_CYCLES);
        locked = 1'b1;
    end

    // Each output toggles every half period from the start (0 degrees: all rise together there).
    initial begin : run_op
        wait (running);
        if (CLKOP_ENABLE == "ENABLED") forever begin CLKOP = !CLKOP; #(half_op); end
    end
    initial begin : run_os
        wait (running);
        if (CLKOS_ENABLE == "ENABLED") forever begin CLKOS = !CLKOS; #(half_os); end
    end
    initial begin : run_os2
        wait (running);
        if (CLKOS2_ENABLE == "ENABLED") forever begin CLKOS2 = !CLKOS2; #(half_os2); end
    end
    initial begin : run_os3
        wait (running);
        if (CLKOS3_ENABLE == "ENABLED") forever begin CLKOS3 = !CLKOS3; #(half_os3); end
    end

    assign LOCK = locked;
    assign INTLOCK = locked;
    assign REFCLK = CLKI;
    assign CLKINTFB = CLKOP;
endmodule

`default_nettype wire
