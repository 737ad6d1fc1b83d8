// netlist_cells_tb: the ECP5 cell models that yosys does not ship (cosim/netlist/ecp5: MULT18X18D,
// ODDRX1F, EHXPLLL), each against a behavioural reference written here another way. Run by
// tests/boards/netlist_cells.sh (Verilator --binary --timing); prints "netlist_cells: ok ..." or
// stops at the first difference with $fatal.
//   MULT18X18D  every sign mode on the corner operands (0, 1, -1, the extremes) and on seeded random
//               ones: P against a 64-bit product of the operands read as the sign pins say
//   ODDRX1F     seeded random bit pairs: Q sampled in each half period is D0 then D1 of the pair
//               registered at that period's rising edge; RST clears it
//   EHXPLLL     boards/ulx3s/ulx3s_pll as the board builds it (SYS_MHZ from the script): from a
//               25 MHz input, the TMDS, pixel and system clocks at the periods the script expects,
//               rising together at an input edge, LOCK after they start
`timescale 1ps / 1ps
`default_nettype none

module netlist_cells_tb;
    // ---- MULT18X18D -------------------------------------------------------------------------------
    reg  [17:0] a = 0, b = 0;
    reg         sa = 0, sb = 0;
    wire [35:0] p;
    wire        signedp;
    MULT18X18D u_mul (
        .A17(a[17]), .A16(a[16]), .A15(a[15]), .A14(a[14]), .A13(a[13]), .A12(a[12]), .A11(a[11]),
        .A10(a[10]), .A9(a[9]), .A8(a[8]), .A7(a[7]), .A6(a[6]), .A5(a[5]), .A4(a[4]), .A3(a[3]),
        .A2(a[2]), .A1(a[1]), .A0(a[0]),
        .B17(b[17]), .B16(b[16]), .B15(b[15]), .B14(b[14]), .B13(b[13]), .B12(b[12]), .B11(b[11]),
        .B10(b[10]), .B9(b[9]), .B8(b[8]), .B7(b[7]), .B6(b[6]), .B5(b[5]), .B4(b[4]), .B3(b[3]),
        .B2(b[2]), .B1(b[1]), .B0(b[0]),
        .C17(1'b0), .C16(1'b0), .C15(1'b0), .C14(1'b0), .C13(1'b0), .C12(1'b0), .C11(1'b0),
        .C10(1'b0), .C9(1'b0), .C8(1'b0), .C7(1'b0), .C6(1'b0), .C5(1'b0), .C4(1'b0), .C3(1'b0),
        .C2(1'b0), .C1(1'b0), .C0(1'b0),
        .SIGNEDA(sa), .SIGNEDB(sb), .SOURCEA(1'b0), .SOURCEB(1'b0),
        .CLK3(1'b0), .CLK2(1'b0), .CLK1(1'b0), .CLK0(1'b0), .CE3(1'b0), .CE2(1'b0), .CE1(1'b0),
        .CE0(1'b0), .RST3(1'b0), .RST2(1'b0), .RST1(1'b0), .RST0(1'b0),
        .SRIA17(1'b0), .SRIA16(1'b0), .SRIA15(1'b0), .SRIA14(1'b0), .SRIA13(1'b0), .SRIA12(1'b0),
        .SRIA11(1'b0), .SRIA10(1'b0), .SRIA9(1'b0), .SRIA8(1'b0), .SRIA7(1'b0), .SRIA6(1'b0),
        .SRIA5(1'b0), .SRIA4(1'b0), .SRIA3(1'b0), .SRIA2(1'b0), .SRIA1(1'b0), .SRIA0(1'b0),
        .SRIB17(1'b0), .SRIB16(1'b0), .SRIB15(1'b0), .SRIB14(1'b0), .SRIB13(1'b0), .SRIB12(1'b0),
        .SRIB11(1'b0), .SRIB10(1'b0), .SRIB9(1'b0), .SRIB8(1'b0), .SRIB7(1'b0), .SRIB6(1'b0),
        .SRIB5(1'b0), .SRIB4(1'b0), .SRIB3(1'b0), .SRIB2(1'b0), .SRIB1(1'b0), .SRIB0(1'b0),
        .SROA17(), .SROA16(), .SROA15(), .SROA14(), .SROA13(), .SROA12(), .SROA11(), .SROA10(),
        .SROA9(), .SROA8(), .SROA7(), .SROA6(), .SROA5(), .SROA4(), .SROA3(), .SROA2(), .SROA1(),
        .SROA0(),
        .SROB17(), .SROB16(), .SROB15(), .SROB14(), .SROB13(), .SROB12(), .SROB11(), .SROB10(),
        .SROB9(), .SROB8(), .SROB7(), .SROB6(), .SROB5(), .SROB4(), .SROB3(), .SROB2(), .SROB1(),
        .SROB0(),
        .ROA17(), .ROA16(), .ROA15(), .ROA14(), .ROA13(), .ROA12(), .ROA11(), .ROA10(), .ROA9(),
        .ROA8(), .ROA7(), .ROA6(), .ROA5(), .ROA4(), .ROA3(), .ROA2(), .ROA1(), .ROA0(),
        .ROB17(), .ROB16(), .ROB15(), .ROB14(), .ROB13(), .ROB12(), .ROB11(), .ROB10(), .ROB9(),
        .ROB8(), .ROB7(), .ROB6(), .ROB5(), .ROB4(), .ROB3(), .ROB2(), .ROB1(), .ROB0(),
        .ROC17(), .ROC16(), .ROC15(), .ROC14(), .ROC13(), .ROC12(), .ROC11(), .ROC10(), .ROC9(),
        .ROC8(), .ROC7(), .ROC6(), .ROC5(), .ROC4(), .ROC3(), .ROC2(), .ROC1(), .ROC0(),
        .P35(p[35]), .P34(p[34]), .P33(p[33]), .P32(p[32]), .P31(p[31]), .P30(p[30]), .P29(p[29]),
        .P28(p[28]), .P27(p[27]), .P26(p[26]), .P25(p[25]), .P24(p[24]), .P23(p[23]), .P22(p[22]),
        .P21(p[21]), .P20(p[20]), .P19(p[19]), .P18(p[18]), .P17(p[17]), .P16(p[16]), .P15(p[15]),
        .P14(p[14]), .P13(p[13]), .P12(p[12]), .P11(p[11]), .P10(p[10]), .P9(p[9]), .P8(p[8]),
        .P7(p[7]), .P6(p[6]), .P5(p[5]), .P4(p[4]), .P3(p[3]), .P2(p[2]), .P1(p[1]), .P0(p[0]),
        .SIGNEDP(signedp)
    );

    // The reference: each operand as a 64-bit integer (negative when its sign pin says two's
    // complement and its top bit is set), their exact product, its low 36 bits.
    function automatic longint operand(input [17:0] v, input bit is_signed);
        return is_signed && v[17] ? longint'(v) - (longint'(1) << 18) : longint'(v);
    endfunction

    int mul_checks = 0;
    task automatic mul_check(input [17:0] x, input [17:0] y, input bit sx, input bit sy);
        longint want;
        a = x; b = y; sa = sx; sb = sy;
        #1;
        want = operand(x, sx) * operand(y, sy);
        if (p !== want[35:0] || signedp !== (sx | sy)) begin
            $fatal(1, "MULT18X18D: %0s%h x %0s%h: P %h, want %h (SIGNEDP %b)", sx ? "s" : "u", x,
                   sy ? "s" : "u", y, p, want[35:0], signedp);
        end
        mul_checks++;
    endtask

    // ---- ODDRX1F ----------------------------------------------------------------------------------
    reg  sclk = 0, rst = 0, d0 = 0, d1 = 0;
    wire q;
    ODDRX1F u_ddr (.SCLK(sclk), .RST(rst), .D0(d0), .D1(d1), .Q(q));

    // ---- EHXPLLL through the board's ulx3s_pll ----------------------------------------------------
    reg  clk_25mhz = 0;
    wire clk_tmds, clk_pix, clk_sys, locked;
    ulx3s_pll #(.SYS_MHZ(`PLL_SYS_MHZ)) u_pll (
        .clk_25mhz (clk_25mhz),
        .clk_tmds  (clk_tmds),
        .clk_pix   (clk_pix),
        .clk_sys   (clk_sys),
        .locked    (locked)
    );
    always #20000 clk_25mhz = !clk_25mhz;

    // Rising edges of each output after LOCK: the last time and the period seen.
    longint last_tmds = -1, last_pix = -1, last_sys = -1, per_tmds = 0, per_pix = 0, per_sys = 0;
    longint start_tmds = -1, start_pix = -1, start_sys = -1, lock_time = -1;
    always @(posedge clk_tmds) begin
        if (start_tmds < 0) start_tmds = $time;
        if (last_tmds >= 0) begin
            if (per_tmds != 0 && $time - last_tmds != per_tmds) $fatal(1, "EHXPLLL: clk_tmds period changed");
            per_tmds = $time - last_tmds;
        end
        last_tmds = $time;
    end
    always @(posedge clk_pix) begin
        if (start_pix < 0) start_pix = $time;
        if (last_pix >= 0) begin
            if (per_pix != 0 && $time - last_pix != per_pix) $fatal(1, "EHXPLLL: clk_pix period changed");
            per_pix = $time - last_pix;
        end
        last_pix = $time;
    end
    always @(posedge clk_sys) begin
        if (start_sys < 0) start_sys = $time;
        if (last_sys >= 0) begin
            if (per_sys != 0 && $time - last_sys != per_sys) $fatal(1, "EHXPLLL: clk_sys period changed");
            per_sys = $time - last_sys;
        end
        last_sys = $time;
    end
    always @(posedge locked) lock_time = $time;

    int ddr_checks = 0;
    initial begin : run
        int seed;
        bit want0, want1;
        seed = `SEED;
        // MULT18X18D: corners in every sign mode, then random operands.
        begin
            reg [17:0] corners [0:6];
            corners[0] = 18'h00000; corners[1] = 18'h00001; corners[2] = 18'h3ffff; corners[3] = 18'h1ffff;
            corners[4] = 18'h20000; corners[5] = 18'h20001; corners[6] = 18'h15555;
            for (int m = 0; m < 4; m++) begin
                for (int i = 0; i < 7; i++) begin
                    for (int j = 0; j < 7; j++) begin
                        mul_check(corners[i], corners[j], m[0], m[1]);
                    end
                end
                for (int k = 0; k < 20000; k++) begin
                    mul_check(18'($urandom(seed)), 18'($urandom(seed)), m[0], m[1]);
                    seed = seed + 1;
                end
            end
        end
        // ODDRX1F: a pair set before each rising edge; Q a quarter period after each edge.
        for (int k = 0; k < 4000; k++) begin
            d0 = 1'($urandom(seed)); seed = seed + 1;
            d1 = 1'($urandom(seed)); seed = seed + 1;
            want0 = d0; want1 = d1;
            #1000 sclk = 1;
            #250 d0 = !d0; d1 = !d1;  // the inputs move after the edge: the register holds what it took
            #250 if (q !== want0) $fatal(1, "ODDRX1F: pair %0d: Q %b in the high half, want D0 %b", k, q, want0);
            #500 sclk = 0;
            #500 if (q !== want1) $fatal(1, "ODDRX1F: pair %0d: Q %b in the low half, want D1 %b", k, q, want1);
            #500;
            ddr_checks++;
        end
        rst = 1;
        #10 if (q !== 1'b0) $fatal(1, "ODDRX1F: Q %b under RST", q);
        rst = 0;
        // EHXPLLL: let it lock and run.
        #5000000;
        if (lock_time < 0) $fatal(1, "EHXPLLL: LOCK never rose");
        if (per_tmds != `WANT_TMDS_PS || per_pix != `WANT_PIX_PS || per_sys != `WANT_SYS_PS) begin
            $fatal(1, "EHXPLLL: periods tmds %0d pix %0d sys %0d ps, want %0d %0d %0d", per_tmds, per_pix,
                   per_sys, `WANT_TMDS_PS, `WANT_PIX_PS, `WANT_SYS_PS);
        end
        if (start_tmds != start_pix || start_pix != start_sys) begin
            $fatal(1, "EHXPLLL: outputs start at %0d, %0d, %0d ps, not together", start_tmds, start_pix, start_sys);
        end
        if (start_tmds % 40000 != 20000 || lock_time <= start_tmds) begin
            $fatal(1, "EHXPLLL: outputs start at %0d ps (not an input rising edge) or LOCK at %0d before", start_tmds, lock_time);
        end
        $display("netlist_cells: ok: MULT18X18D %0d products in 4 sign modes, ODDRX1F %0d bit pairs, EHXPLLL (SYS_MHZ %0d) tmds %0d, pix %0d, sys %0d ps from a 40000 ps input, LOCK at %0d ps",
                 mul_checks, ddr_checks, `PLL_SYS_MHZ, per_tmds, per_pix, per_sys, lock_time);
        $finish;
    end
endmodule

`default_nettype wire
