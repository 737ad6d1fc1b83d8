// dvi_tx: DVI 1.0 (TMDS) transmitter for the ULX3S GPDI connector, up to the ODDRX1F inputs.
//
// Contract: three tmds_encoder channels in the pixel domain (0 blue with ctrl = {vsync, hsync},
// i.e. c0 = hsync and c1 = vsync as LEVELS, so active-low VGA syncs are passed unchanged; 1 green and
// 2 red with ctrl = 00) plus the clock channel, the constant word 10'b0000011111. The board top feeds
// ddr_d0[k]/ddr_d1[k] to the D0/D1 of four ODDRX1F (SCLK = clk_tmds): in each clk_tmds period D0 goes
// out after the rising edge and D1 after the falling one, so every symbol leaves LSB first (bit 0
// first) in 5 clk_tmds periods, and the clock channel's five ones start with the symbol's bit 0.
//
// Clocks: clk_tmds must be exactly 5x clk_pix from the same PLL (phase irrelevant, see below); each
// domain has its own synchronous reset. Release rst_tmds no later than rst_pix: the first symbol sent
// is then the first one encoded after rst_pix (running disparity 0); before it the outputs are 0.
//
// Latency: inputs at a clk_pix edge -> symbol register at that edge -> loaded into the TMDS shift
// registers 2 or 3 clk_tmds periods later (depending on the phase) -> first two bits on ddr_d0/d1 at
// that same load edge (registered outputs), last two 4 clk_tmds later.
//
// Pixel -> TMDS crossing. The pixel domain registers the three symbols together with a toggle
// (tog_pix) that flips at every clk_pix edge (held while rst_pix). The TMDS domain passes the toggle
// through two flops (tog_sync_tmds, ASYNC_REG) and loads its shift registers from the pixel-domain
// words (sym_*_pix, not synchronised) at the edge after the synchronised toggle differs from its
// previous value (tog_seen_tmds). Timing: the words and the toggle change together at a clk_pix edge
// T and then stay stable until T + 5 Ttmds. The first sync flop takes the new toggle at the first
// clk_tmds edge e0 in [T, T + Ttmds] (an edge coinciding with T samples the old value, then the next
// edge takes it), the second at e0 + Ttmds, and the load samples the words at e0 + 2 Ttmds, i.e. in
// [T + 2 Ttmds, T + 3 Ttmds]: at least 2 Ttmds after they changed and at least 2 Ttmds before they
// change again, whatever the phase. With the clocks from one PLL the phase is fixed, so a load comes
// exactly every 5 clk_tmds periods. For static timing the sym_*_pix -> shift-register paths are
// 2-period multicycle paths (or false paths); only tog_pix -> tog_sync_tmds[0] is asynchronous.
`default_nettype none

module dvi_tx (
    // pixel clock domain
    input  wire       clk_pix,
    input  wire       rst_pix,     // synchronous to clk_pix, active high
    // TMDS bit clock domain: exactly 5x clk_pix, same PLL
    input  wire       clk_tmds,
    input  wire       rst_tmds,    // synchronous to clk_tmds, active high
    // video in (pixel domain)
    input  wire       de,          // 1: r/g/b are visible pixels; 0: blanking, syncs are sent
    input  wire       hsync,       // line level (as on the VGA pin), sent as c0 of channel 0
    input  wire       vsync,       // line level, sent as c1 of channel 0
    input  wire [7:0] r,
    input  wire [7:0] g,
    input  wire [7:0] b,
    // to the ODDRX1F D0/D1 inputs (TMDS domain, registered); bit k: 0 blue, 1 green, 2 red, 3 clock
    output reg  [3:0] ddr_d0,      // sent in the first half of the clk_tmds period
    output reg  [3:0] ddr_d1       // sent in the second half
);
    localparam [9:0] CLK_WORD = 10'b0000011111;

    // ---- pixel domain: encoders and the toggle ----
    wire [9:0] sym_b_pix;
    wire [9:0] sym_g_pix;
    wire [9:0] sym_r_pix;

    tmds_encoder enc_b (
        .clk_pix(clk_pix), .rst_pix(rst_pix),
        .de(de), .ctrl({vsync, hsync}), .data(b),
        .symbol(sym_b_pix)
    );
    tmds_encoder enc_g (
        .clk_pix(clk_pix), .rst_pix(rst_pix),
        .de(de), .ctrl(2'b00), .data(g),
        .symbol(sym_g_pix)
    );
    tmds_encoder enc_r (
        .clk_pix(clk_pix), .rst_pix(rst_pix),
        .de(de), .ctrl(2'b00), .data(r),
        .symbol(sym_r_pix)
    );

    reg tog_pix;  // flips with every new set of symbols
    always @(posedge clk_pix) begin
        if (rst_pix) begin
            tog_pix <= 1'b0;
        end else begin
            tog_pix <= ~tog_pix;
        end
    end

    // The four words as one vector, channel k in bits 10k+9..10k (stable 5 clk_tmds per symbol).
    wire [39:0] words_pix = {CLK_WORD, sym_r_pix, sym_g_pix, sym_b_pix};

    // ---- TMDS domain: toggle synchroniser and 2-bit serialisers ----
    (* ASYNC_REG = "TRUE" *) reg [1:0] tog_sync_tmds;  // [0] may go metastable, [1] is clean
    reg tog_seen_tmds;                                  // tog_sync_tmds[1] one clk_tmds earlier
    wire load_tmds = tog_sync_tmds[1] ^ tog_seen_tmds;
    reg [31:0] shift_tmds;  // per channel the 8 bits still to send, next pair in bits 8k+1..8k

    always @(posedge clk_tmds) begin : serialise
        integer k;
        if (rst_tmds) begin
            tog_sync_tmds <= 2'b00;
            tog_seen_tmds <= 1'b0;
            shift_tmds <= 32'd0;
            ddr_d0 <= 4'd0;
            ddr_d1 <= 4'd0;
        end else begin
            tog_sync_tmds <= {tog_sync_tmds[0], tog_pix};
            tog_seen_tmds <= tog_sync_tmds[1];
            for (k = 0; k < 4; k = k + 1) begin
                if (load_tmds) begin
                    ddr_d0[k] <= words_pix[10*k];
                    ddr_d1[k] <= words_pix[10*k+1];
                    shift_tmds[8*k +: 8] <= words_pix[10*k+2 +: 8];
                end else begin
                    ddr_d0[k] <= shift_tmds[8*k];
                    ddr_d1[k] <= shift_tmds[8*k+1];
                    shift_tmds[8*k +: 8] <= {2'b00, shift_tmds[8*k+2 +: 6]};
                end
            end
        end
    end
`ifdef FORMAL
    // ---- formal properties of the crossing (tests/formal/dvi_tx.sby; the clocks at 5:1 from one
    // PLL, any phase, from dvi_tx_check.sv) ----
    // Each domain's properties hold once a reset has been seen in it (the registers have no initial
    // values).
    reg f_rst_pix_seen = 1'b0;   // clk_pix
    reg f_rst_tmds_seen = 1'b0;  // clk_tmds
    always @(posedge clk_pix) if (rst_pix) f_rst_pix_seen <= 1'b1;
    always @(posedge clk_tmds) if (rst_tmds) f_rst_tmds_seen <= 1'b1;
    wire f_valid = f_rst_pix_seen && f_rst_tmds_seen;
    // The contract's resets (dvi_tx_check.sv assumes them as ulx3s_system makes them): each held
    // from configuration until at least one edge of its clock, rst_tmds released only once the
    // pixel domain has been reset, and no later than rst_pix.
    always @(*) begin
        assert((f_rst_pix_seen || rst_pix) && (f_rst_tmds_seen || rst_tmds));
        if (!rst_pix) assert(!rst_tmds);
        if (!rst_tmds) assert(f_rst_pix_seen);
    end

    // The words presented, numbered in the pixel domain: word n is in sym_*_pix from the n-th
    // clk_pix edge after rst_pix (mod 8) until the next.
    reg [2:0] f_seq_pix = 3'd0;  // clk_pix
    always @(posedge clk_pix) f_seq_pix <= rst_pix ? 3'd0 : f_seq_pix + 3'd1;

    // TMDS domain: when the words last changed, as its edges see it (tog_pix at each edge), and
    // what each load took: the word, its number, the number of the load before.
    reg       f_tog_tmds = 1'b0;    // tog_pix as the last clk_tmds edge saw it (0 in rst_tmds)
    reg [1:0] f_since = 2'd3;       // clk_tmds edges since that changed, up to 3
    reg [1:0] f_loads = 2'd0;       // loads since rst_tmds, up to 2
    reg [2:0] f_pos = 3'd0;         // clk_tmds edges since the last load, up to 7
    reg [39:0] f_word = 40'd0;      // the words of the last load
    reg [2:0] f_seq = 3'd0;         // ... their number
    reg [2:0] f_seq_before = 3'd0;  // the number of the load before
    always @(posedge clk_tmds) begin
        if (rst_tmds) begin            // as tog_sync_tmds (rst_pix holds tog_pix at 0 meanwhile)
            f_tog_tmds <= 1'b0;
            f_since <= 2'd3;
            f_loads <= 2'd0;
            f_pos <= 3'd0;
        end else begin
            f_tog_tmds <= tog_pix;
            if (tog_pix != f_tog_tmds) f_since <= 2'd1;
            else if (f_since != 2'd3) f_since <= f_since + 2'd1;
            if (load_tmds) begin
                f_word <= words_pix;
                f_seq <= f_seq_pix;
                f_seq_before <= f_seq;
                f_pos <= 3'd0;
                if (f_loads != 2'd2) f_loads <= f_loads + 2'd1;
            end else if (f_pos != 3'd7) begin
                f_pos <= f_pos + 3'd1;
            end
        end
    end

    always @(*) begin
        if (f_valid && !rst_tmds) begin
            // The sample's margins: a load samples the words at the third clk_tmds edge after they
            // changed (the edge that coincides with the change sees the old toggle), so they have
            // been stable for at least two clk_tmds periods, and (5:1) stay so for two more.
            if (load_tmds) assert(tog_pix == f_tog_tmds && f_since == 2'd2);
            // Every word once, in order, from the first encoded after rst_pix.
            if (f_loads == 2'd1) assert(f_seq == 3'd1);
            if (f_loads == 2'd2) assert(f_seq == f_seq_before + 3'd1);
            // The load took the word still presented: the same word, the same number.
            if (f_loads != 2'd0 && f_pos <= 3'd1) assert(f_seq == f_seq_pix && f_word == words_pix);
            // Back to back: the next load comes at the fifth clk_tmds edge, no sooner, no later.
            if (f_loads != 2'd0) assert(f_pos <= 3'd4 && (!load_tmds || f_pos == 3'd4));
        end
    end

    // The serialisers: f_pos edges after a load, channel k has sent (or is sending) bit pairs
    // 0..f_pos of the word the load took, and holds the rest; before the first load, zeros.
    always @(*) begin : f_serial
        integer k;
        if (f_valid && !rst_tmds) begin
            for (k = 0; k < 4; k = k + 1) begin
                if (f_loads == 2'd0) begin
                    assert(ddr_d0[k] == 1'b0 && ddr_d1[k] == 1'b0 && shift_tmds[8*k +: 8] == 8'd0);
                end else begin
                    assert(ddr_d0[k] == f_word[10*k + 2*f_pos]);
                    assert(ddr_d1[k] == f_word[10*k + 2*f_pos + 1]);
                    assert(shift_tmds[8*k +: 8] == (f_word[10*k+2 +: 8] >> (2*f_pos)));
                    if (k == 3) assert(f_word[10*k +: 10] == CLK_WORD);
                end
            end
        end
    end

    // Invariants of the toggle's way (the induction's): it is the word number's parity; the first
    // sync flop is what the last edge saw, and the change is at the place f_since says.
    always @(*) begin
        if (f_valid) begin
            assert(tog_pix == f_seq_pix[0]);
            if (rst_pix) assert(f_seq_pix == 3'd0 && f_loads == 2'd0);
            // the word presented is the last one loaded, or the one after it still on its way
            if (!rst_tmds)
                assert(f_seq_pix == (f_loads == 2'd0 ? 3'd0 : f_seq)
                                    + {2'd0, tog_pix != tog_seen_tmds});
            // the cadence (5:1): the words change between the second and third edges after a load
            if (!rst_tmds && f_loads != 2'd0) begin
                case (f_pos)
                    3'd0, 3'd1: assert(f_since == 2'd3 && tog_pix == f_tog_tmds);
                    3'd2: assert(f_since == 2'd3);
                    3'd3: assert(f_since == 2'd1 && tog_pix == f_tog_tmds);
                    default: assert(f_since == 2'd2 && tog_pix == f_tog_tmds);
                endcase
            end
            if (!rst_tmds) begin
                assert(tog_sync_tmds[0] == f_tog_tmds);
                case (f_since)
                    2'd1: assert(tog_sync_tmds[1] != tog_sync_tmds[0]
                                 && tog_seen_tmds == tog_sync_tmds[1]);
                    2'd2: assert(tog_sync_tmds[1] == tog_sync_tmds[0]
                                 && tog_seen_tmds != tog_sync_tmds[1]);
                    2'd3: assert(tog_sync_tmds[1] == tog_sync_tmds[0]
                                 && tog_seen_tmds == tog_sync_tmds[1]);
                    default: ;
                endcase
            end
        end
    end
`endif
endmodule

`default_nettype wire
