// netlist_cells_tb: the ECP5 cell models that yosys does not ship (cosim/netlist/ecp5: MULT18X18D,
// ODDRX1F, EHXPLLL), each against a behavioural reference written here another way. Run by
// tests/boards/netlist_cells.sh (Verilator --binary --timing); prints "netlist_cells: ok ..." or
// stops at the first difference with $fatal.
//   MULT18X18D  every sign mode on the corner operands (0, 1, -1, the extremes) and on seeded random
//               ones: P against a 64-bit product of the operands read as the sign pins say
//   ODDRX1F     seeded random bit pairs: Q sampled in each half period is D0 then D1 of the pair
//               registered at that period's rising edge; RST clears it
//   DP16KD      seeded random writes on port A (18 bits with byte enables; 36 as a pair) and reads
//               on port B (9, 4, 36 bits), against a flat array of the block's 18,432 bits indexed
//               as the contract says; INITVAL's layout; the write modes; the asynchronous reset
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

    // ---- DP16KD -----------------------------------------------------------------------------------
    reg         bclk = 0, bwe = 0, brst = 0;
    int         phase = 0;  // the block being written: 0 x18/x9, 1 x4, 2 x36
    reg  [13:0] bad_a = 0, bad_b = 0;
    reg  [17:0] bdi_a = 0, bdi_b = 0;
    wire [17:0] bdo_a18_9, bdo_b18_9, bdo_a4, bdo_b4, bdo_a36, bdo_b36;
    `define DP16KD_PINS(WE, DOA, DOB) \
        .DIA17(bdi_a[17]), .DIA16(bdi_a[16]), .DIA15(bdi_a[15]), .DIA14(bdi_a[14]), .DIA13(bdi_a[13]), \
        .DIA12(bdi_a[12]), .DIA11(bdi_a[11]), .DIA10(bdi_a[10]), .DIA9(bdi_a[9]), .DIA8(bdi_a[8]), \
        .DIA7(bdi_a[7]), .DIA6(bdi_a[6]), .DIA5(bdi_a[5]), .DIA4(bdi_a[4]), .DIA3(bdi_a[3]), \
        .DIA2(bdi_a[2]), .DIA1(bdi_a[1]), .DIA0(bdi_a[0]), \
        .ADA13(bad_a[13]), .ADA12(bad_a[12]), .ADA11(bad_a[11]), .ADA10(bad_a[10]), .ADA9(bad_a[9]), \
        .ADA8(bad_a[8]), .ADA7(bad_a[7]), .ADA6(bad_a[6]), .ADA5(bad_a[5]), .ADA4(bad_a[4]), \
        .ADA3(bad_a[3]), .ADA2(bad_a[2]), .ADA1(bad_a[1]), .ADA0(bad_a[0]), \
        .CEA(1'b1), .OCEA(1'b1), .CLKA(bclk), .WEA(WE), .RSTA(1'b0), .CSA2(1'b0), .CSA1(1'b0), .CSA0(1'b0), \
        .DOA17(DOA[17]), .DOA16(DOA[16]), .DOA15(DOA[15]), .DOA14(DOA[14]), .DOA13(DOA[13]), \
        .DOA12(DOA[12]), .DOA11(DOA[11]), .DOA10(DOA[10]), .DOA9(DOA[9]), .DOA8(DOA[8]), .DOA7(DOA[7]), \
        .DOA6(DOA[6]), .DOA5(DOA[5]), .DOA4(DOA[4]), .DOA3(DOA[3]), .DOA2(DOA[2]), .DOA1(DOA[1]), \
        .DOA0(DOA[0]), \
        .DIB17(bdi_b[17]), .DIB16(bdi_b[16]), .DIB15(bdi_b[15]), .DIB14(bdi_b[14]), .DIB13(bdi_b[13]), \
        .DIB12(bdi_b[12]), .DIB11(bdi_b[11]), .DIB10(bdi_b[10]), .DIB9(bdi_b[9]), .DIB8(bdi_b[8]), \
        .DIB7(bdi_b[7]), .DIB6(bdi_b[6]), .DIB5(bdi_b[5]), .DIB4(bdi_b[4]), .DIB3(bdi_b[3]), \
        .DIB2(bdi_b[2]), .DIB1(bdi_b[1]), .DIB0(bdi_b[0]), \
        .ADB13(bad_b[13]), .ADB12(bad_b[12]), .ADB11(bad_b[11]), .ADB10(bad_b[10]), .ADB9(bad_b[9]), \
        .ADB8(bad_b[8]), .ADB7(bad_b[7]), .ADB6(bad_b[6]), .ADB5(bad_b[5]), .ADB4(bad_b[4]), \
        .ADB3(bad_b[3]), .ADB2(bad_b[2]), .ADB1(bad_b[1]), .ADB0(bad_b[0]), \
        .CEB(1'b1), .OCEB(1'b1), .CLKB(bclk), .WEB(1'b0), .RSTB(brst), .CSB2(1'b0), .CSB1(1'b0), .CSB0(1'b0), \
        .DOB17(DOB[17]), .DOB16(DOB[16]), .DOB15(DOB[15]), .DOB14(DOB[14]), .DOB13(DOB[13]), \
        .DOB12(DOB[12]), .DOB11(DOB[11]), .DOB10(DOB[10]), .DOB9(DOB[9]), .DOB8(DOB[8]), .DOB7(DOB[7]), \
        .DOB6(DOB[6]), .DOB5(DOB[5]), .DOB4(DOB[4]), .DOB3(DOB[3]), .DOB2(DOB[2]), .DOB1(DOB[1]), \
        .DOB0(DOB[0])
    // Word 17 of the initial contents: INITVAL_01, slot 1 (bits 20..37) holds 18'h2_5a3c.
    localparam [319:0] INIT_ROW1 = 320'h2_5a3c << 20;
    DP16KD #(.DATA_WIDTH_A(18), .DATA_WIDTH_B(9), .WRITEMODE_A("READBEFOREWRITE"), .RESETMODE("ASYNC"),
             .INITVAL_01(INIT_ROW1))
        u_ram18_9 (`DP16KD_PINS(bwe & phase == 0, bdo_a18_9, bdo_b18_9));
    DP16KD #(.DATA_WIDTH_A(4), .DATA_WIDTH_B(4), .WRITEMODE_A("WRITETHROUGH"))
        u_ram4 (`DP16KD_PINS(bwe & phase == 1, bdo_a4, bdo_b4));
    DP16KD #(.DATA_WIDTH_A(36), .DATA_WIDTH_B(36))
        u_ram36 (`DP16KD_PINS(bwe & phase == 2, bdo_a36, bdo_b36));

    // The references: each block's 18,432 bits, word w's bit b at w * 18 + b.
    bit ref18 [0:18431];
    bit ref4 [0:18431];
    bit ref36 [0:18431];
    function automatic int phys(input int data_bit16);  // 16 data bits of a word: 8 and 17 skipped
        return data_bit16 + (data_bit16 >= 8);
    endfunction
    int ram_checks = 0;

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
        // DP16KD: the initial word, then random writes on A and reads on B.
        foreach (ref18[i]) begin ref18[i] = 0; ref4[i] = 0; ref36[i] = 0; end
        for (int b = 0; b < 18; b++) ref18[17 * 18 + b] = (18'h2_5a3c >> b) & 1;
        for (int k = 0; k < 6000; k++) begin
            int word, sub, a_item, b_item;
            bit [3:0] be;
            reg [35:0] data;
            reg [17:0] want_a18, want_b9, want_a4, want_b4, want_a36, want_b36;
            word = k < 20 ? 17 : $urandom(seed) % 1024; seed++;
            data = {$urandom(seed), $urandom(seed + 1)}; seed += 2;
            be = 4'($urandom(seed)); seed++;
            bwe = k >= 20 && ($urandom(seed) % 3 != 0); seed++;
            b_item = word * 2 + ($urandom(seed) % 2); seed++;   // a 9-bit item of the same word
            a_item = word * 4 + ($urandom(seed) % 4); seed++;   // a 4-bit item of it
            // what each port must show after this edge (READBEFOREWRITE, WRITETHROUGH, NORMAL)
            for (int b = 0; b < 18; b++) want_a18[b] = ref18[word * 18 + b];
            // x18 / x9 block: A writes word at AD[13:4] with byte enables AD[1:0]; B reads AD[13:3]
            bad_a = {4'(word >> 6), 6'(word), 2'b00, be[1:0]};
            bad_a[13:4] = 10'(word);
            bdi_a = data[17:0];
            bdi_b = data[35:18];
            bad_b = {10'(b_item >> 1), b_item[0], 3'b000};
            phase = 0;
            #500 bclk = 1;
            #500;
            if (bwe) begin
                for (int b = 0; b < 9; b++) if (be[0]) ref18[word * 18 + b] = data[b];
                for (int b = 9; b < 18; b++) if (be[1]) ref18[word * 18 + b] = data[b];
            end
            // B's read and A's write at the same edge: B reads the word before the write
            want_b9 = 0;
            if (k < 20 || !bwe) for (int b = 0; b < 9; b++) want_b9[b] = ref18[(b_item >> 1) * 18 + (b_item & 1) * 9 + b];
            if (bdo_a18_9 !== want_a18) $fatal(1, "DP16KD x18: word %0d: DOA %h, want the old word %h", word, bdo_a18_9, want_a18);
            if ((k < 20 || !bwe) && bdo_b18_9 !== want_b9) $fatal(1, "DP16KD x9: item %0d: DOB %h, want %h", b_item, bdo_b18_9, want_b9);
            bclk = 0;
            // x4 block: A writes 4-bit item a_item (WRITETHROUGH), B reads it back the next edge
            bad_a = {12'(a_item), 2'b00};
            bad_b = {12'(a_item), 2'b00};
            phase = 1;
            #500 bclk = 1;
            #500;
            if (bwe) for (int b = 0; b < 4; b++) ref4[(a_item >> 2) * 18 + phys((a_item & 3) * 4 + b)] = data[b];
            want_a4 = 0;
            for (int b = 0; b < 4; b++) want_a4[b] = ref4[(a_item >> 2) * 18 + phys((a_item & 3) * 4 + b)];
            if (bdo_a4 !== want_a4) $fatal(1, "DP16KD x4: item %0d: DOA %h, want %h (written through)", a_item, bdo_a4, want_a4);
            bclk = 0;
            bwe = 0;
            #500 bclk = 1;
            #500;
            if (bdo_b4 !== want_a4) $fatal(1, "DP16KD x4: item %0d: DOB %h, want %h", a_item, bdo_b4, want_a4);
            bclk = 0;
            // x36 pair: A writes pair word / 2 with four byte enables, B reads it the next edge
            bwe = 1;
            bad_a = {9'(word >> 1), 1'b0, be};
            bad_b = {9'(word >> 1), 5'b0};
            phase = 2;
            bdi_a = data[17:0];
            bdi_b = data[35:18];
            #500 bclk = 1;
            #500 bclk = 0;
            for (int q = 0; q < 4; q++) if (be[q]) for (int b = 0; b < 9; b++)
                ref36[((word >> 1) * 2 + q / 2) * 18 + (q % 2) * 9 + b] = data[q * 9 + b];
            bwe = 0;
            #500 bclk = 1;
            #500 bclk = 0;
            for (int b = 0; b < 18; b++) begin
                want_a36[b] = ref36[((word >> 1) * 2) * 18 + b];
                want_b36[b] = ref36[((word >> 1) * 2 + 1) * 18 + b];
            end
            if (bdo_a36 !== want_a36 || bdo_b36 !== want_b36) begin
                $fatal(1, "DP16KD x36: pair %0d: %h %h, want %h %h", word >> 1, bdo_b36, bdo_a36, want_b36, want_a36);
            end
            ram_checks++;
        end
        brst = 1;
        #10 if (bdo_b18_9 !== 18'h0) $fatal(1, "DP16KD: DOB %h under the asynchronous RST", bdo_b18_9);
        brst = 0;
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
        $display("netlist_cells: ok: MULT18X18D %0d products in 4 sign modes, ODDRX1F %0d bit pairs, DP16KD %0d rounds of x18/x9, x4, x36, EHXPLLL (SYS_MHZ %0d) tmds %0d, pix %0d, sys %0d ps from a 40000 ps input, LOCK at %0d ps",
                 mul_checks, ddr_checks, ram_checks, `PLL_SYS_MHZ, per_tmds, per_pix, per_sys, lock_time);
        $finish;
    end
endmodule

`default_nettype wire
