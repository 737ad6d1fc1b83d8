// MULT18X18D: the ECP5's 18x18 multiplier (Lattice FPGA-TN-02205, "ECP5 and ECP5-5G sysDSP Usage
// Guide"; the port and parameter list of yosys' share/ecp5/cells_bb.v), for netlist simulation
// (make netlist-sim, cosim/netlist) — yosys ships only a black box.
//
// Contract: the mode yosys' synth_ecp5 maps every multiplication to (share/lattice/dsp_map_18x18.v):
// no input, pipeline or output register (REG_*_CLK "NONE"), the multiplier not bypassed, operands
// from the A and B pins (SOURCEA = SOURCEB = 0). Then P = A x B, 36 bits, where SIGNEDA (SIGNEDB)
// reads A (B) as two's complement, else unsigned; SIGNEDP = SIGNEDA | SIGNEDB says the product is
// signed. The cascade outputs carry the operands as in that mode: ROA = SROA = A, ROB = SROB = B,
// ROC = C. Any other parameter value is a clear error at elaboration, never a silently wrong model:
// a netlist that uses the registers or the shift chains needs a model written for them.
// Unit test: tests/boards/netlist_cells.sh (against Verilog's own signed and unsigned products).
`default_nettype none

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
module MULT18X18D(
    A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0, B17, B16, B15,
    B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0, C17, C16, C15, C14, C13, C12,
    C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0,    SIGNEDA, SIGNEDB, SOURCEA, SOURCEB, CLK3,
    CLK2, CLK1, CLK0, CE3, CE2, CE1, CE0,    RST3, RST2, RST1, RST0, SRIA17, SRIA16, SRIA15, SRIA14,
    SRIA13, SRIA12, SRIA11, SRIA10, SRIA9, SRIA8, SRIA7, SRIA6, SRIA5, SRIA4, SRIA3, SRIA2, SRIA1,
    SRIA0, SRIB17, SRIB16, SRIB15, SRIB14, SRIB13, SRIB12, SRIB11, SRIB10, SRIB9, SRIB8, SRIB7,
    SRIB6, SRIB5, SRIB4, SRIB3, SRIB2, SRIB1, SRIB0,    SROA17, SROA16, SROA15, SROA14, SROA13,
    SROA12, SROA11, SROA10, SROA9, SROA8, SROA7, SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0,
    SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9, SROB8, SROB7, SROB6,
    SROB5, SROB4, SROB3, SROB2, SROB1, SROB0,    ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11,
    ROA10, ROA9, ROA8, ROA7, ROA6, ROA5, ROA4, ROA3, ROA2, ROA1, ROA0, ROB17, ROB16, ROB15, ROB14,
    ROB13, ROB12, ROB11, ROB10, ROB9, ROB8, ROB7, ROB6, ROB5, ROB4, ROB3, ROB2, ROB1, ROB0, ROC17,
    ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9, ROC8, ROC7, ROC6, ROC5, ROC4, ROC3, ROC2,
    ROC1, ROC0,    P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20,
    P19, P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0,
    SIGNEDP
);
    parameter REG_INPUTA_CLK = "NONE";
    parameter REG_INPUTA_CE = "CE0";
    parameter REG_INPUTA_RST = "RST0";
    parameter REG_INPUTB_CLK = "NONE";
    parameter REG_INPUTB_CE = "CE0";
    parameter REG_INPUTB_RST = "RST0";
    parameter REG_INPUTC_CLK = "NONE";
    parameter REG_INPUTC_CE = "CE0";
    parameter REG_INPUTC_RST = "RST0";
    parameter REG_PIPELINE_CLK = "NONE";
    parameter REG_PIPELINE_CE = "CE0";
    parameter REG_PIPELINE_RST = "RST0";
    parameter REG_OUTPUT_CLK = "NONE";
    parameter REG_OUTPUT_CE = "CE0";
    parameter REG_OUTPUT_RST = "RST0";
    parameter CLK0_DIV = "ENABLED";
    parameter CLK1_DIV = "ENABLED";
    parameter CLK2_DIV = "ENABLED";
    parameter CLK3_DIV = "ENABLED";
    parameter HIGHSPEED_CLK = "NONE";
    parameter GSR = "ENABLED";
    parameter CAS_MATCH_REG = "FALSE";
    parameter SOURCEB_MODE = "B_SHIFT";
    parameter MULT_BYPASS = "DISABLED";
    parameter RESETMODE = "SYNC";
    // nextpnr's placed cells name the constant of each unconnected operand pin here ("0"/"1");
    // cosim/netlist/routed_json.py puts that constant on the pin itself, so the model reads pins only.
    parameter A0MUX = "A0";
    parameter A1MUX = "A1";
    parameter A2MUX = "A2";
    parameter A3MUX = "A3";
    parameter A4MUX = "A4";
    parameter A5MUX = "A5";
    parameter A6MUX = "A6";
    parameter A7MUX = "A7";
    parameter A8MUX = "A8";
    parameter A9MUX = "A9";
    parameter A10MUX = "A10";
    parameter A11MUX = "A11";
    parameter A12MUX = "A12";
    parameter A13MUX = "A13";
    parameter A14MUX = "A14";
    parameter A15MUX = "A15";
    parameter A16MUX = "A16";
    parameter A17MUX = "A17";
    parameter B0MUX = "B0";
    parameter B1MUX = "B1";
    parameter B2MUX = "B2";
    parameter B3MUX = "B3";
    parameter B4MUX = "B4";
    parameter B5MUX = "B5";
    parameter B6MUX = "B6";
    parameter B7MUX = "B7";
    parameter B8MUX = "B8";
    parameter B9MUX = "B9";
    parameter B10MUX = "B10";
    parameter B11MUX = "B11";
    parameter B12MUX = "B12";
    parameter B13MUX = "B13";
    parameter B14MUX = "B14";
    parameter B15MUX = "B15";
    parameter B16MUX = "B16";
    parameter B17MUX = "B17";
    parameter C0MUX = "C0";
    parameter C1MUX = "C1";
    parameter C2MUX = "C2";
    parameter C3MUX = "C3";
    parameter C4MUX = "C4";
    parameter C5MUX = "C5";
    parameter C6MUX = "C6";
    parameter C7MUX = "C7";
    parameter C8MUX = "C8";
    parameter C9MUX = "C9";
    parameter C10MUX = "C10";
    parameter C11MUX = "C11";
    parameter C12MUX = "C12";
    parameter C13MUX = "C13";
    parameter C14MUX = "C14";
    parameter C15MUX = "C15";
    parameter C16MUX = "C16";
    parameter C17MUX = "C17";
    input  A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0;
    input  B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0;
    input  C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0;
    input  SRIA17, SRIA16, SRIA15, SRIA14, SRIA13, SRIA12, SRIA11, SRIA10, SRIA9, SRIA8, SRIA7,
           SRIA6, SRIA5, SRIA4, SRIA3, SRIA2, SRIA1, SRIA0;
    input  SRIB17, SRIB16, SRIB15, SRIB14, SRIB13, SRIB12, SRIB11, SRIB10, SRIB9, SRIB8, SRIB7,
           SRIB6, SRIB5, SRIB4, SRIB3, SRIB2, SRIB1, SRIB0;
    input  SIGNEDA, SIGNEDB, SOURCEA, SOURCEB, CLK3, CLK2, CLK1, CLK0, CE3, CE2, CE1, CE0;
    input  RST3, RST2, RST1, RST0;
    output SROA17, SROA16, SROA15, SROA14, SROA13, SROA12, SROA11, SROA10, SROA9, SROA8, SROA7,
           SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0;
    output SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9, SROB8, SROB7,
           SROB6, SROB5, SROB4, SROB3, SROB2, SROB1, SROB0;
    output ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11, ROA10, ROA9, ROA8, ROA7, ROA6, ROA5,
           ROA4, ROA3, ROA2, ROA1, ROA0;
    output ROB17, ROB16, ROB15, ROB14, ROB13, ROB12, ROB11, ROB10, ROB9, ROB8, ROB7, ROB6, ROB5,
           ROB4, ROB3, ROB2, ROB1, ROB0;
    output ROC17, ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9, ROC8, ROC7, ROC6, ROC5,
           ROC4, ROC3, ROC2, ROC1, ROC0;
    output P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19, P18,
           P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0;
    output SIGNEDP;

    wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
    wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};
    wire [17:0] c = {C17, C16, C15, C14, C13, C12, C11, C10, C9, C8, C7, C6, C5, C4, C3, C2, C1, C0};
    // Each operand widened to 36 bits as its sign pin says; the low 36 bits of the product are then
    // the product of the two readings (signed x unsigned included).
    wire [35:0] a_wide = {{18{SIGNEDA & a[17]}}, a};
    wire [35:0] b_wide = {{18{SIGNEDB & b[17]}}, b};
    wire [35:0] p = a_wide * b_wide;

    assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19, P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p;
    assign SIGNEDP = SIGNEDA | SIGNEDB;
    assign {ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11, ROA10, ROA9, ROA8, ROA7, ROA6, ROA5, ROA4, ROA3, ROA2, ROA1, ROA0} = a;
    assign {SROA17, SROA16, SROA15, SROA14, SROA13, SROA12, SROA11, SROA10, SROA9, SROA8, SROA7, SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0} = a;
    assign {ROB17, ROB16, ROB15, ROB14, ROB13, ROB12, ROB11, ROB10, ROB9, ROB8, ROB7, ROB6, ROB5, ROB4, ROB3, ROB2, ROB1, ROB0} = b;
    assign {SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9, SROB8, SROB7, SROB6, SROB5, SROB4, SROB3, SROB2, SROB1, SROB0} = b;
    assign {ROC17, ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9, ROC8, ROC7, ROC6, ROC5, ROC4, ROC3, ROC2, ROC1, ROC0} = c;

    generate
        if (REG_INPUTA_CLK != "NONE" || REG_INPUTB_CLK != "NONE" || REG_INPUTC_CLK != "NONE"
            || REG_PIPELINE_CLK != "NONE" || REG_OUTPUT_CLK != "NONE") begin : g_registered
            $fatal(1, "MULT18X18D: a registered mode (REG_*_CLK not NONE) is not modelled (cosim/netlist/ecp5)");
        end
        if (MULT_BYPASS != "DISABLED") begin : g_bypass
            $fatal(1, "MULT18X18D: MULT_BYPASS is not modelled (cosim/netlist/ecp5)");
        end
    endgenerate
    // The operand sources are pins: a netlist that selects the shift chains (SOURCEA/SOURCEB high)
    // is not modelled, which only the run can see.
    always @* begin
        if (SOURCEA | SOURCEB) begin
            $fatal(1, "MULT18X18D: SOURCEA/SOURCEB (the shift-chain operands) are not modelled");
        end
    end
endmodule

`default_nettype wire
