// DP16KD: the ECP5's 18-Kbit true dual-port block RAM (Lattice FPGA-TN-02204, "ECP5 and ECP5-5G
// Memory Usage Guide"; ports and parameters as yosys' share/ecp5/cells_sim.v declares them, where it
// is only a black box), for netlist simulation (make netlist-sim, cosim/netlist).
//
// Contract: 1,024 words of 18 bits, seen by each port at its DATA_WIDTH:
//   18  address AD[13:4]; AD[1:0] enable the write of bits [8:0] and [17:9] (byte enables)
//    9  AD[13:3]: bits [8:0] or [17:9] of word AD[13:4] as AD[3] says
//  4, 2, 1  AD[13:2], AD[13:1], AD[13:0]: the nibble, pair or bit of word AD[13:4] within its 16 data
//       bits (bits 8 and 17, the parity positions, are not addressed in these modes)
//   36  pseudo dual port (as yosys maps 36-bit memories): port A writes and port B reads words
//       2n (bits [17:0], the DIA/DOA pins) and 2n + 1 ([35:18], DIB/DOB) for n = AD[13:5]; AD[3:0]
//       enable the writes of the four 9-bit bytes
// INITVAL_00..3F hold the words as yosys writes them: word w in INITVAL_<w / 16>, bits
// [(w % 16) * 20 +: 18]. A port acts at the rising edge of its clock when CE is high and its chip
// selects CS[2:0] equal CSDECODE: it writes when WE is high (WRITEMODE NORMAL: the output keeps its
// value; WRITETHROUGH: it shows the new data; READBEFOREWRITE: the old), and reads otherwise. The
// output is the read register (REGMODE "NOREG"); RST clears it, at the clock edge (RESETMODE SYNC)
// or at once (ASYNC). A *MUX parameter selects what drives its input: the pin of that name, "INV"
// the pin inverted, or a constant "0"/"1" (nextpnr's packed cells write these).
// Anything else — REGMODE "OUTREG", a width outside 1, 2, 4, 9, 18, 36, 36 on one port only — is a
// clear error at elaboration, never a silently wrong model.
// Unit test: tests/boards/netlist_cells.sh (the widths the board uses, 18/9, 4 and 36, and the three
// write modes, against a flat array of the block's bits; widths 1 and 2 are not exercised).
`default_nettype none
`timescale 1ps / 1ps

// verilator lint_off DECLFILENAME
// verilator lint_off UNUSEDSIGNAL
// verilator lint_off UNUSEDPARAM
// verilator lint_off WIDTH
// verilator lint_off BLKSEQ
// (string parameters compared with literals of other lengths; the memory array is written at once
// by the port that writes, so that the other port of another clock reads it as the RAM would)
module DP16KD (
    input  wire DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7, DIA6,
    DIA5, DIA4, DIA3, DIA2, DIA1, DIA0,
    input  wire ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2, ADA1,
    ADA0,
    input  wire CEA, OCEA, CLKA, WEA, RSTA, CSA2, CSA1, CSA0,
    output wire DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6,
    DOA5, DOA4, DOA3, DOA2, DOA1, DOA0,
    input  wire DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6,
    DIB5, DIB4, DIB3, DIB2, DIB1, DIB0,
    input  wire ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2, ADB1,
    ADB0,
    input  wire CEB, OCEB, CLKB, WEB, RSTB, CSB2, CSB1, CSB0,
    output wire DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6,
    DOB5, DOB4, DOB3, DOB2, DOB1, DOB0
);
    parameter DATA_WIDTH_A = 18;
    parameter DATA_WIDTH_B = 18;
    parameter REGMODE_A = "NOREG";
    parameter REGMODE_B = "NOREG";
    parameter RESETMODE = "SYNC";
    parameter ASYNC_RESET_RELEASE = "SYNC";
    parameter CSDECODE_A = "0b000";
    parameter CSDECODE_B = "0b000";
    parameter WRITEMODE_A = "NORMAL";
    parameter WRITEMODE_B = "NORMAL";
    parameter GSR = "ENABLED";
    parameter INIT_DATA = "STATIC";
    parameter WID = 0;
    parameter DIA17MUX = "DIA17";
    parameter DIA16MUX = "DIA16";
    parameter DIA15MUX = "DIA15";
    parameter DIA14MUX = "DIA14";
    parameter DIA13MUX = "DIA13";
    parameter DIA12MUX = "DIA12";
    parameter DIA11MUX = "DIA11";
    parameter DIA10MUX = "DIA10";
    parameter DIA9MUX = "DIA9";
    parameter DIA8MUX = "DIA8";
    parameter DIA7MUX = "DIA7";
    parameter DIA6MUX = "DIA6";
    parameter DIA5MUX = "DIA5";
    parameter DIA4MUX = "DIA4";
    parameter DIA3MUX = "DIA3";
    parameter DIA2MUX = "DIA2";
    parameter DIA1MUX = "DIA1";
    parameter DIA0MUX = "DIA0";
    parameter ADA13MUX = "ADA13";
    parameter ADA12MUX = "ADA12";
    parameter ADA11MUX = "ADA11";
    parameter ADA10MUX = "ADA10";
    parameter ADA9MUX = "ADA9";
    parameter ADA8MUX = "ADA8";
    parameter ADA7MUX = "ADA7";
    parameter ADA6MUX = "ADA6";
    parameter ADA5MUX = "ADA5";
    parameter ADA4MUX = "ADA4";
    parameter ADA3MUX = "ADA3";
    parameter ADA2MUX = "ADA2";
    parameter ADA1MUX = "ADA1";
    parameter ADA0MUX = "ADA0";
    parameter CEAMUX = "CEA";
    parameter OCEAMUX = "OCEA";
    parameter CLKAMUX = "CLKA";
    parameter WEAMUX = "WEA";
    parameter RSTAMUX = "RSTA";
    parameter CSA2MUX = "CSA2";
    parameter CSA1MUX = "CSA1";
    parameter CSA0MUX = "CSA0";
    parameter DOA17MUX = "DOA17";
    parameter DOA16MUX = "DOA16";
    parameter DOA15MUX = "DOA15";
    parameter DOA14MUX = "DOA14";
    parameter DOA13MUX = "DOA13";
    parameter DOA12MUX = "DOA12";
    parameter DOA11MUX = "DOA11";
    parameter DOA10MUX = "DOA10";
    parameter DOA9MUX = "DOA9";
    parameter DOA8MUX = "DOA8";
    parameter DOA7MUX = "DOA7";
    parameter DOA6MUX = "DOA6";
    parameter DOA5MUX = "DOA5";
    parameter DOA4MUX = "DOA4";
    parameter DOA3MUX = "DOA3";
    parameter DOA2MUX = "DOA2";
    parameter DOA1MUX = "DOA1";
    parameter DOA0MUX = "DOA0";
    parameter DIB17MUX = "DIB17";
    parameter DIB16MUX = "DIB16";
    parameter DIB15MUX = "DIB15";
    parameter DIB14MUX = "DIB14";
    parameter DIB13MUX = "DIB13";
    parameter DIB12MUX = "DIB12";
    parameter DIB11MUX = "DIB11";
    parameter DIB10MUX = "DIB10";
    parameter DIB9MUX = "DIB9";
    parameter DIB8MUX = "DIB8";
    parameter DIB7MUX = "DIB7";
    parameter DIB6MUX = "DIB6";
    parameter DIB5MUX = "DIB5";
    parameter DIB4MUX = "DIB4";
    parameter DIB3MUX = "DIB3";
    parameter DIB2MUX = "DIB2";
    parameter DIB1MUX = "DIB1";
    parameter DIB0MUX = "DIB0";
    parameter ADB13MUX = "ADB13";
    parameter ADB12MUX = "ADB12";
    parameter ADB11MUX = "ADB11";
    parameter ADB10MUX = "ADB10";
    parameter ADB9MUX = "ADB9";
    parameter ADB8MUX = "ADB8";
    parameter ADB7MUX = "ADB7";
    parameter ADB6MUX = "ADB6";
    parameter ADB5MUX = "ADB5";
    parameter ADB4MUX = "ADB4";
    parameter ADB3MUX = "ADB3";
    parameter ADB2MUX = "ADB2";
    parameter ADB1MUX = "ADB1";
    parameter ADB0MUX = "ADB0";
    parameter CEBMUX = "CEB";
    parameter OCEBMUX = "OCEB";
    parameter CLKBMUX = "CLKB";
    parameter WEBMUX = "WEB";
    parameter RSTBMUX = "RSTB";
    parameter CSB2MUX = "CSB2";
    parameter CSB1MUX = "CSB1";
    parameter CSB0MUX = "CSB0";
    parameter DOB17MUX = "DOB17";
    parameter DOB16MUX = "DOB16";
    parameter DOB15MUX = "DOB15";
    parameter DOB14MUX = "DOB14";
    parameter DOB13MUX = "DOB13";
    parameter DOB12MUX = "DOB12";
    parameter DOB11MUX = "DOB11";
    parameter DOB10MUX = "DOB10";
    parameter DOB9MUX = "DOB9";
    parameter DOB8MUX = "DOB8";
    parameter DOB7MUX = "DOB7";
    parameter DOB6MUX = "DOB6";
    parameter DOB5MUX = "DOB5";
    parameter DOB4MUX = "DOB4";
    parameter DOB3MUX = "DOB3";
    parameter DOB2MUX = "DOB2";
    parameter DOB1MUX = "DOB1";
    parameter DOB0MUX = "DOB0";
    parameter [319:0] INITVAL_00 = 320'h0;
    parameter [319:0] INITVAL_01 = 320'h0;
    parameter [319:0] INITVAL_02 = 320'h0;
    parameter [319:0] INITVAL_03 = 320'h0;
    parameter [319:0] INITVAL_04 = 320'h0;
    parameter [319:0] INITVAL_05 = 320'h0;
    parameter [319:0] INITVAL_06 = 320'h0;
    parameter [319:0] INITVAL_07 = 320'h0;
    parameter [319:0] INITVAL_08 = 320'h0;
    parameter [319:0] INITVAL_09 = 320'h0;
    parameter [319:0] INITVAL_0A = 320'h0;
    parameter [319:0] INITVAL_0B = 320'h0;
    parameter [319:0] INITVAL_0C = 320'h0;
    parameter [319:0] INITVAL_0D = 320'h0;
    parameter [319:0] INITVAL_0E = 320'h0;
    parameter [319:0] INITVAL_0F = 320'h0;
    parameter [319:0] INITVAL_10 = 320'h0;
    parameter [319:0] INITVAL_11 = 320'h0;
    parameter [319:0] INITVAL_12 = 320'h0;
    parameter [319:0] INITVAL_13 = 320'h0;
    parameter [319:0] INITVAL_14 = 320'h0;
    parameter [319:0] INITVAL_15 = 320'h0;
    parameter [319:0] INITVAL_16 = 320'h0;
    parameter [319:0] INITVAL_17 = 320'h0;
    parameter [319:0] INITVAL_18 = 320'h0;
    parameter [319:0] INITVAL_19 = 320'h0;
    parameter [319:0] INITVAL_1A = 320'h0;
    parameter [319:0] INITVAL_1B = 320'h0;
    parameter [319:0] INITVAL_1C = 320'h0;
    parameter [319:0] INITVAL_1D = 320'h0;
    parameter [319:0] INITVAL_1E = 320'h0;
    parameter [319:0] INITVAL_1F = 320'h0;
    parameter [319:0] INITVAL_20 = 320'h0;
    parameter [319:0] INITVAL_21 = 320'h0;
    parameter [319:0] INITVAL_22 = 320'h0;
    parameter [319:0] INITVAL_23 = 320'h0;
    parameter [319:0] INITVAL_24 = 320'h0;
    parameter [319:0] INITVAL_25 = 320'h0;
    parameter [319:0] INITVAL_26 = 320'h0;
    parameter [319:0] INITVAL_27 = 320'h0;
    parameter [319:0] INITVAL_28 = 320'h0;
    parameter [319:0] INITVAL_29 = 320'h0;
    parameter [319:0] INITVAL_2A = 320'h0;
    parameter [319:0] INITVAL_2B = 320'h0;
    parameter [319:0] INITVAL_2C = 320'h0;
    parameter [319:0] INITVAL_2D = 320'h0;
    parameter [319:0] INITVAL_2E = 320'h0;
    parameter [319:0] INITVAL_2F = 320'h0;
    parameter [319:0] INITVAL_30 = 320'h0;
    parameter [319:0] INITVAL_31 = 320'h0;
    parameter [319:0] INITVAL_32 = 320'h0;
    parameter [319:0] INITVAL_33 = 320'h0;
    parameter [319:0] INITVAL_34 = 320'h0;
    parameter [319:0] INITVAL_35 = 320'h0;
    parameter [319:0] INITVAL_36 = 320'h0;
    parameter [319:0] INITVAL_37 = 320'h0;
    parameter [319:0] INITVAL_38 = 320'h0;
    parameter [319:0] INITVAL_39 = 320'h0;
    parameter [319:0] INITVAL_3A = 320'h0;
    parameter [319:0] INITVAL_3B = 320'h0;
    parameter [319:0] INITVAL_3C = 320'h0;
    parameter [319:0] INITVAL_3D = 320'h0;
    parameter [319:0] INITVAL_3E = 320'h0;
    parameter [319:0] INITVAL_3F = 320'h0;

    // An input as its *MUX parameter selects it (see the contract).
    function automatic bit muxed(input bit pin, input [8*8-1:0] sel);
        if (sel == "INV") return !pin;
        if (sel == "0" || sel == "0 ") return 1'b0;
        if (sel == "1" || sel == "1 ") return 1'b1;
        return pin;
    endfunction

    wire [17:0] di_a =
        {muxed(DIA17, DIA17MUX), muxed(DIA16, DIA16MUX), muxed(DIA15, DIA15MUX), muxed(DIA14,
        DIA14MUX), muxed(DIA13, DIA13MUX), muxed(DIA12, DIA12MUX), muxed(DIA11, DIA11MUX),
        muxed(DIA10, DIA10MUX), muxed(DIA9, DIA9MUX), muxed(DIA8, DIA8MUX), muxed(DIA7, DIA7MUX),
        muxed(DIA6, DIA6MUX), muxed(DIA5, DIA5MUX), muxed(DIA4, DIA4MUX), muxed(DIA3, DIA3MUX),
        muxed(DIA2, DIA2MUX), muxed(DIA1, DIA1MUX), muxed(DIA0, DIA0MUX)};
    wire [13:0] ad_a =
        {muxed(ADA13, ADA13MUX), muxed(ADA12, ADA12MUX), muxed(ADA11, ADA11MUX), muxed(ADA10,
        ADA10MUX), muxed(ADA9, ADA9MUX), muxed(ADA8, ADA8MUX), muxed(ADA7, ADA7MUX), muxed(ADA6,
        ADA6MUX), muxed(ADA5, ADA5MUX), muxed(ADA4, ADA4MUX), muxed(ADA3, ADA3MUX), muxed(ADA2,
        ADA2MUX), muxed(ADA1, ADA1MUX), muxed(ADA0, ADA0MUX)};
    wire ce_a = muxed(CEA, CEAMUX), we_a = muxed(WEA, WEAMUX), rst_a = muxed(RSTA, RSTAMUX);
    wire clk_a = muxed(CLKA, CLKAMUX);
    wire [2:0] cs_a = {muxed(CSA2, CSA2MUX), muxed(CSA1, CSA1MUX), muxed(CSA0, CSA0MUX)};
    wire [17:0] di_b =
        {muxed(DIB17, DIB17MUX), muxed(DIB16, DIB16MUX), muxed(DIB15, DIB15MUX), muxed(DIB14,
        DIB14MUX), muxed(DIB13, DIB13MUX), muxed(DIB12, DIB12MUX), muxed(DIB11, DIB11MUX),
        muxed(DIB10, DIB10MUX), muxed(DIB9, DIB9MUX), muxed(DIB8, DIB8MUX), muxed(DIB7, DIB7MUX),
        muxed(DIB6, DIB6MUX), muxed(DIB5, DIB5MUX), muxed(DIB4, DIB4MUX), muxed(DIB3, DIB3MUX),
        muxed(DIB2, DIB2MUX), muxed(DIB1, DIB1MUX), muxed(DIB0, DIB0MUX)};
    wire [13:0] ad_b =
        {muxed(ADB13, ADB13MUX), muxed(ADB12, ADB12MUX), muxed(ADB11, ADB11MUX), muxed(ADB10,
        ADB10MUX), muxed(ADB9, ADB9MUX), muxed(ADB8, ADB8MUX), muxed(ADB7, ADB7MUX), muxed(ADB6,
        ADB6MUX), muxed(ADB5, ADB5MUX), muxed(ADB4, ADB4MUX), muxed(ADB3, ADB3MUX), muxed(ADB2,
        ADB2MUX), muxed(ADB1, ADB1MUX), muxed(ADB0, ADB0MUX)};
    wire ce_b = muxed(CEB, CEBMUX), we_b = muxed(WEB, WEBMUX), rst_b = muxed(RSTB, RSTBMUX);
    wire clk_b = muxed(CLKB, CLKBMUX);
    wire [2:0] cs_b = {muxed(CSB2, CSB2MUX), muxed(CSB1, CSB1MUX), muxed(CSB0, CSB0MUX)};

    // "0b101" -> 3'b101
    function automatic [2:0] decode(input [8*5-1:0] text);
        return {text[23:16] == "1", text[15:8] == "1", text[7:0] == "1"};
    endfunction
    localparam [2:0] CS_A = decode(CSDECODE_A), CS_B = decode(CSDECODE_B);
    localparam bit PDP = DATA_WIDTH_A == 36;

    generate
        if (REGMODE_A != "NOREG" || REGMODE_B != "NOREG") begin : g_bad_reg
            $fatal(1, "DP16KD: REGMODE OUTREG is not modelled (cosim/netlist/ecp5)");
        end
        if ((DATA_WIDTH_A == 36) != (DATA_WIDTH_B == 36)) begin : g_bad_pdp
            $fatal(1, "DP16KD: DATA_WIDTH 36 on one port only is not modelled");
        end
        if (!(DATA_WIDTH_A inside {1, 2, 4, 9, 18, 36}) || !(DATA_WIDTH_B inside {1, 2, 4, 9, 18, 36})) begin : g_bad_width
            $fatal(1, "DP16KD: DATA_WIDTH %0d / %0d is no width of the block RAM", DATA_WIDTH_A, DATA_WIDTH_B);
        end
    endgenerate

    reg [17:0] mem [0:1023];
    function automatic [319:0] init_row(input integer r);
        case (r)
            0: return INITVAL_00;
            1: return INITVAL_01;
            2: return INITVAL_02;
            3: return INITVAL_03;
            4: return INITVAL_04;
            5: return INITVAL_05;
            6: return INITVAL_06;
            7: return INITVAL_07;
            8: return INITVAL_08;
            9: return INITVAL_09;
            10: return INITVAL_0A;
            11: return INITVAL_0B;
            12: return INITVAL_0C;
            13: return INITVAL_0D;
            14: return INITVAL_0E;
            15: return INITVAL_0F;
            16: return INITVAL_10;
            17: return INITVAL_11;
            18: return INITVAL_12;
            19: return INITVAL_13;
            20: return INITVAL_14;
            21: return INITVAL_15;
            22: return INITVAL_16;
            23: return INITVAL_17;
            24: return INITVAL_18;
            25: return INITVAL_19;
            26: return INITVAL_1A;
            27: return INITVAL_1B;
            28: return INITVAL_1C;
            29: return INITVAL_1D;
            30: return INITVAL_1E;
            31: return INITVAL_1F;
            32: return INITVAL_20;
            33: return INITVAL_21;
            34: return INITVAL_22;
            35: return INITVAL_23;
            36: return INITVAL_24;
            37: return INITVAL_25;
            38: return INITVAL_26;
            39: return INITVAL_27;
            40: return INITVAL_28;
            41: return INITVAL_29;
            42: return INITVAL_2A;
            43: return INITVAL_2B;
            44: return INITVAL_2C;
            45: return INITVAL_2D;
            46: return INITVAL_2E;
            47: return INITVAL_2F;
            48: return INITVAL_30;
            49: return INITVAL_31;
            50: return INITVAL_32;
            51: return INITVAL_33;
            52: return INITVAL_34;
            53: return INITVAL_35;
            54: return INITVAL_36;
            55: return INITVAL_37;
            56: return INITVAL_38;
            57: return INITVAL_39;
            58: return INITVAL_3A;
            59: return INITVAL_3B;
            60: return INITVAL_3C;
            61: return INITVAL_3D;
            62: return INITVAL_3E;
            63: return INITVAL_3F;
            default: return 320'h0;
        endcase
    endfunction
    initial begin : load
        reg [319:0] row;
        for (int r = 0; r < 64; r++) begin
            row = init_row(r);
            for (int s = 0; s < 16; s++) mem[r * 16 + s] = row[s * 20 +: 18];
        end
    end

    // The physical bit of a narrow port's data bit k (widths 1, 2, 4): the 16 data bits skip 8 and 17.
    function automatic integer data_bit(input integer k);
        return k < 8 ? k : k + 1;
    endfunction

    // One port's access at its clock edge: word w (and w + 1, the high half, for 36 bits) read, then
    // written where WE and the byte enables say; returns the output register's next value.
    function automatic [17:0] port_access(input integer width, input [13:0] ad, input [17:0] di, input bit we,
                                          input bit hi, input bit through);
        integer w, sub;
        reg [17:0] old, next, q;
        w = width == 36 ? {ad[13:5], hi} : ad[13:4];
        old = mem[w];
        next = old;
        q = 18'h0;
        sub = 0;
        case (width)
            36, 18: begin
                if (we && (width == 36 ? ad[{hi, 1'b0}] : ad[0])) next[8:0] = di[8:0];
                if (we && (width == 36 ? ad[{hi, 1'b1}] : ad[1])) next[17:9] = di[17:9];
            end
            9: begin
                sub = ad[3] * 9;
                if (we) next[sub +: 9] = di[8:0];
            end
            default: begin  // 4, 2, 1: the item's place among the word's 16 data bits
                sub = (ad[3:0] >> $clog2(width)) * width;
                if (we) for (int k = 0; k < width; k++) next[data_bit(sub + k)] = di[k];
            end
        endcase
        mem[w] = next;
        begin : shown
            reg [17:0] src;
            src = we && through ? next : old;
            case (width)
                36, 18: q = src;
                9: q[8:0] = src[sub +: 9];
                default: for (int k = 0; k < width; k++) q[k] = src[data_bit(sub + k)];
            endcase
        end
        return q;
    endfunction

    // The output registers. A 36-bit pair: port A writes both halves, port B reads both, the low
    // half leaving on the DOA pins (do_a36), the high on DOB.
    reg [17:0] do_a = 18'h0, do_b = 18'h0, do_a36 = 18'h0;
    wire sel_a = ce_a && cs_a == CS_A, sel_b = ce_b && cs_b == CS_B;

    task automatic port_a_edge();
        if (sel_a) begin
            if (DATA_WIDTH_A == 36) begin
                do_a <= port_access(36, ad_a, di_a, we_a, 1'b0, 1'b0);
                void'(port_access(36, ad_a, di_b, we_a, 1'b1, 1'b0));
            end else if (!(we_a && WRITEMODE_A == "NORMAL")) begin
                do_a <= port_access(DATA_WIDTH_A, ad_a, di_a, we_a, 1'b0, WRITEMODE_A == "WRITETHROUGH");
            end else begin
                void'(port_access(DATA_WIDTH_A, ad_a, di_a, we_a, 1'b0, 1'b0));
            end
        end
    endtask
    task automatic port_b_edge();
        if (sel_b) begin
            if (DATA_WIDTH_B == 36) begin
                do_b <= port_access(36, ad_b, 18'h0, 1'b0, 1'b1, 1'b0);
                do_a36 <= port_access(36, ad_b, 18'h0, 1'b0, 1'b0, 1'b0);
            end else if (!(we_b && WRITEMODE_B == "NORMAL")) begin
                do_b <= port_access(DATA_WIDTH_B, ad_b, di_b, we_b, 1'b0, WRITEMODE_B == "WRITETHROUGH");
            end else begin
                void'(port_access(DATA_WIDTH_B, ad_b, di_b, we_b, 1'b0, 1'b0));
            end
        end
    endtask

    // RST clears the output register at the clock edge (SYNC), or at once (ASYNC: the reset is
    // also an edge the block waits for).
    wire arst_a = RESETMODE == "ASYNC" && rst_a, arst_b = RESETMODE == "ASYNC" && rst_b;
    always @(posedge clk_a or posedge arst_a) begin
        if (rst_a) do_a <= 18'h0;
        else port_a_edge();
    end
    always @(posedge clk_b or posedge arst_b) begin
        if (rst_b) begin
            do_b <= 18'h0;
            do_a36 <= 18'h0;
        end else begin
            port_b_edge();
        end
    end
    wire [17:0] out_a = DATA_WIDTH_A == 36 ? do_a36 : do_a;
    assign {DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5,
            DOA4, DOA3, DOA2, DOA1, DOA0} = out_a;
    assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5,
            DOB4, DOB3, DOB2, DOB1, DOB0} = do_b;
endmodule

`default_nettype wire
