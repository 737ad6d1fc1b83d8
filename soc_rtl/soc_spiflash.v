// soc_spiflash: the board's SPI configuration flash as a read-only, memory-mapped Wishbone B4 slave
// (the boot program copies the firmware image from it into SDRAM, one uncached word at a time).
//
// Contract (bus): a read of word address wb_adr returns the 32-bit little-endian word at flash byte
// address {wb_adr, 2'b00}: byte A in wb_dat_r[7:0], A+1 in [15:8], A+2 in [23:16], A+3 in [31:24];
// wb_sel is ignored (the whole word is read). A write is refused: wb_err in the request's second
// clock, no SPI activity, the stream below left as it was. Each request is answered once, by wb_ack
// (reads) or wb_err (writes), only while it is held (wb_cyc && wb_stb), never in its first clock.
// wb_dat_r is 0 except with wb_ack. A master that drops wb_cyc or wb_stb before the answer abandons
// the request: a transfer already started runs to its end (the flash is left after that word) and
// its answer is swallowed; a later request is served after it, never answered with its data.
// Contract (flash): SPI mode 0, READ (0x03): CS# low, the command and the 24-bit byte address MSB
// first on MOSI, then the data bytes, each MSB first, on MISO (64 SCK cycles for the first word).
// CS# then stays low with SCK low: the flash's address counter points at the next word, and a read
// of exactly that word (the usual copy loop) just clocks 32 more bits out (streaming). Any other
// address raises CS# for CS_HIGH_CLKS clocks and sends a new command; nothing else raises it (no
// idle timeout: nothing else uses the flash, and a READ may pause for any time with SCK low). The
// stream also restarts at the top of the window (after word 2^(ADDR_BITS-2) - 1), so a flash larger
// than the window is read correctly too.
// Contract (wake-up): after reset CS# is high and SCK low; CS# stays high CS_HIGH_CLKS clocks, then
// Release from Deep Power-down (0xAB, 8 SCK cycles), then CS# high for WAKE_CLKS clocks (tRES1) before
// the first READ, so a flash left in deep power-down by an earlier design answers. The wake-up
// happens once after every reset, whether or not a read is waiting. A reset in the middle of a
// transfer raises CS# and drops SCK at once (a READ may be cut anywhere).
// Timing, in clk cycles, D = SCK_DIV, H = CS_HIGH_CLKS, counting the request's first clock as 1:
// a streamed word is acked in clock 64*D + 2 (32 SCK cycles); a new command with CS# already high
// long enough in clock 128*D + 2 (64 SCK cycles); one that first closes a stream in H + 128*D + 2; a
// write's err in clock 2. The wake-up takes H + 16*D + 1 + max(WAKE_CLKS, H) clocks after reset.
// Whatever came before (a READ under way for an abandoned request, the wake-up), a read is acked
// by clock max(256*D + H + 2, 144*D + H + max(WAKE_CLKS, H) + 2) (proved). With the defaults
// (50 MHz, SCK 25 MHz): 66 clocks (1.32 us) a streamed word, 3 MB/s; 130 (2.6 us) a first word;
// the wake-up 169 clocks (3.4 us); at most 298 clocks (6 us) for any read.
//
// SPI timing (D = 1: SCK = clk / 2; every SCK half-period is D clocks, the first one after CS# falls
// included): MOSI (the shift register's top bit) and SCK are flops; MOSI changes only at the clock
// edge that drops SCK (or with SCK low), so the flash's setup and hold around the rising edge are a
// half-period each. MISO is sampled late: one input flop (miso_q) takes it at the clock edge that
// next drops SCK, a whole SCK period (2 * D clocks: 40 ns at D = 1 and 50 MHz) after the falling edge
// that made the flash change it. That path is SCK's route to USRMCLK and the CCLK pad (4-7.5 ns),
// the flash's output valid time (tV, 6-8 ns) and the MISO pad and its route to the flop (4-7 ns):
// 23-27 ns in routed ULX3S builds, past the half-period (20 ns) a sample at the rising edge would
// have, well inside the 40 ns. Hold: the edge that samples is the one that drops SCK again, and the
// flash changes its output only after it sees that fall (tHO >= 0) through the same SCK route, then
// the MISO path: the bit stays at the flop at least ~8 ns past the sampling edge, far above the
// flop's hold time. A word's last bit is taken at its last falling edge, which ends the transfer,
// and goes to wb_dat_r from miso_q, so late sampling costs no clock (the counts above include it);
// a streamed word's first bit is the one the flash put out at that edge and holds while SCK stays
// low, however long. CS# falls with SCK low a half-period before the first rising edge (tSLCH),
// and rises with SCK low at least a clock after the last falling edge (tCHSH). CS_HIGH_CLKS (2:
// 40 ns) covers the CS# high time between reads (tSHSL / tCEH, 7-10 ns in the data sheets).
// The board top instantiates USRMCLK for SCK on ECP5, and ties the flash's WP# and HOLD# high.
`default_nettype none

module soc_spiflash #(
    parameter integer CLK_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // system clock, Hz: WAKE_CLKS's default
    parameter integer ADDR_BITS = 24,      // flash byte-address bits of the window (24: 16 MiB, READ's 3 bytes)
    parameter integer SCK_DIV = 1,         // clk cycles per SCK half-period, >= 1 (1: SCK = clk / 2)
    parameter integer CS_HIGH_CLKS = 2,    // least clocks CS# stays high between commands, >= 1
    // clocks CS# stays high after 0xAB before the first READ: tRES1 = 3 us, rounded up (150 at 50 MHz)
    parameter integer WAKE_CLKS = (CLK_HZ / 1000 * 3 + 999) / 1000,
    localparam integer AW = ADDR_BITS - 2,  // word-address bits
    localparam integer WAIT_CLKS = WAKE_CLKS > CS_HIGH_CLKS ? WAKE_CLKS : CS_HIGH_CLKS,
    localparam integer CW = $clog2(WAIT_CLKS + 1),  // CS# high timer width
    localparam integer DW = $clog2(SCK_DIV + 1)     // SCK half-period timer width
) (
    input  wire          clk,
    input  wire          rst,           // synchronous, active high
    // Wishbone B4 classic slave (the flash window, read-only)
    input  wire          wb_cyc,
    input  wire          wb_stb,        // selected by the decoder
    input  wire          wb_we,         // a write: refused
    input  wire [AW-1:0] wb_adr,        // word address in the window
    input  wire [3:0]    wb_sel,        // ignored: a read returns the whole word
    input  wire [31:0]   wb_dat_w,      // ignored: writes are refused
    output wire [31:0]   wb_dat_r,      // the word with wb_ack, else 0
    output wire          wb_ack,
    output wire          wb_err,
    // SPI flash, mode 0
    output reg           flash_cs_n,    // chip select, active low
    output reg           flash_sck,     // serial clock (to USRMCLK on ECP5), low when idle
    output wire          flash_mosi,    // to the flash's DI (IO0)
    input  wire          flash_miso     // from the flash's DO (IO1)
);
    generate if (ADDR_BITS < 3 || ADDR_BITS > 24 || SCK_DIV < 1 || CS_HIGH_CLKS < 1 || WAKE_CLKS < 1
                 || CLK_HZ < 1) begin : g_bad
        $error("soc_spiflash: ADDR_BITS 3..24; SCK_DIV, CS_HIGH_CLKS, WAKE_CLKS and CLK_HZ at least 1");
    end endgenerate

    localparam [7:0] CMD_READ = 8'h03;   // READ: 24-bit address, no dummy cycles
    localparam [7:0] CMD_RDP  = 8'hAB;   // Release from Deep Power-down
    localparam [DW-1:0] DIV_LAST = SCK_DIV[DW-1:0] - 1'b1;
    localparam [CW-1:0] HIGH_LAST = CS_HIGH_CLKS[CW-1:0] - 1'b1;   // CS# high HIGH_LAST + 1 clocks
    localparam [CW-1:0] WAKE_LAST = WAIT_CLKS[CW-1:0] - 1'b1;      // ... after the wake-up command
    localparam [1:0] ST_HIGH = 2'd0,     // CS# high: its least time (cnt_q), then idle
                     ST_XFER = 2'd1,     // CS# low, SCK running: bits_q SCK cycles left
                     ST_OPEN = 2'd2;     // CS# low, SCK low, stopped after a word (or the wake-up)

    wire unused_ok = &{1'b0, wb_sel, wb_dat_w};

    reg [1:0]    state_q;
    reg [CW-1:0] cnt_q;        // ST_HIGH: clocks left before CS# may fall
    reg          woke_q;       // the wake-up command has been sent since reset
    reg [DW-1:0] div_q;        // ST_XFER: clocks left in this SCK half-period
    reg [6:0]    bits_q;       // ST_XFER: SCK cycles left (8, 64 or 32 at the start)
    reg [31:0]   sr_q;         // out: command and address from bit 31 (MOSI); in: miso_q into bit 0
    reg          miso_q;       // MISO sampled at the last falling SCK edge: the word's newest bit
    reg [AW-1:0] next_q;       // the word after the last one read: where the flash's counter is
    reg          stream_ok_q;  // ... and next_q did not wrap past the top of the window
    reg          pending_q;    // the transfer under way answers a request held since it started
    reg          ack_q, err_q;

    assign flash_mosi = sr_q[31];

    // ---- bus ----
    wire req = wb_cyc && wb_stb;
    wire accept = req && !ack_q && !err_q;   // a request, not in its answer's clock
    wire rd = accept && !wb_we;              // a read waiting to be served (or being served)
    wire [AW:0] adr_inc = {1'b0, wb_adr} + 1'b1;   // the word after it, with the wrap in the top bit
    wire seq = stream_ok_q && wb_adr == next_q;     // the flash's counter is at this word
    wire [31:0] rd_cmd = {CMD_READ, 24'd0} | {{(32 - ADDR_BITS){1'b0}}, wb_adr, 2'b00};
    assign wb_ack = ack_q && req;
    assign wb_err = err_q && req;
    // the last 32 bits in, the newest (in miso_q) in bit 0: flash byte A (the first in) is rx[31:24]
    wire [31:0] rx = {sr_q[30:0], miso_q};
    assign wb_dat_r = wb_ack ? {rx[7:0], rx[15:8], rx[23:16], rx[31:24]} : 32'd0;

    // ---- sequencer ----
    wire high_done    = state_q == ST_HIGH && cnt_q == 0;   // CS# has been high long enough
    wire start_wake   = high_done && !woke_q;
    wire start_cmd    = high_done && woke_q && rd;
    wire start_stream = state_q == ST_OPEN && woke_q && rd && seq;
    wire close        = state_q == ST_OPEN && (!woke_q || (rd && !seq));
    wire tick         = div_q == 0;                          // this SCK half-period ends
    wire fall         = state_q == ST_XFER && tick && flash_sck;    // SCK falls at this clock's end
    wire last         = fall && bits_q == 7'd1;              // the transfer's last falling edge

    always @(posedge clk) begin
        if (rst) begin
            state_q <= ST_HIGH;
            flash_cs_n <= 1'b1;
            flash_sck <= 1'b0;
            cnt_q <= HIGH_LAST;
            woke_q <= 1'b0;
            div_q <= '0;
            bits_q <= 7'd0;
            stream_ok_q <= 1'b0;
            pending_q <= 1'b0;
            ack_q <= 1'b0;
            err_q <= 1'b0;
        end else begin
            err_q <= accept && wb_we;
            ack_q <= last && pending_q && req;
            if (!req || last) pending_q <= 1'b0;   // abandoned, or answered now
            case (state_q)
                ST_HIGH: begin
                    if (cnt_q != 0) cnt_q <= cnt_q - 1'b1;
                    if (start_wake) bits_q <= 7'd8;
                    if (start_cmd) bits_q <= 7'd64;
                end
                ST_XFER: begin
                    if (!tick) div_q <= div_q - 1'b1;
                    else begin
                        div_q <= DIV_LAST;
                        flash_sck <= !flash_sck;
                        if (flash_sck) begin
                            bits_q <= bits_q - 1'b1;
                            if (bits_q == 7'd1) state_q <= ST_OPEN;
                        end
                    end
                end
                default: begin   // ST_OPEN
                    if (start_stream) bits_q <= 7'd32;
                    if (close) begin
                        flash_cs_n <= 1'b1;
                        state_q <= ST_HIGH;
                        cnt_q <= woke_q ? HIGH_LAST : WAKE_LAST;
                        woke_q <= 1'b1;
                    end
                end
            endcase
            if (start_wake || start_cmd || start_stream) begin
                state_q <= ST_XFER;
                flash_cs_n <= 1'b0;
                div_q <= DIV_LAST;
            end
            if (start_cmd || start_stream) begin
                pending_q <= 1'b1;
                stream_ok_q <= !adr_inc[AW];
            end
        end
    end

    // The data path, without reset (what it holds matters only once a transfer has set it): the
    // shift register, loaded with a command, shifted at each falling SCK edge; MISO's input flop,
    // at each falling edge too (the bit the flash drove in the SCK period before: late sampling,
    // see SPI timing), shifted on into sr_q at the next one; the word after the one a transfer reads.
    always @(posedge clk) begin
        if (start_wake) sr_q <= {CMD_RDP, 24'd0};
        else if (start_cmd) sr_q <= rd_cmd;
        else if (fall) sr_q <= {sr_q[30:0], miso_q};
        if (fall) miso_q <= flash_miso;
        if (start_cmd || start_stream) next_q <= adr_inc[AW-1:0];
    end

`ifdef FORMAL
    // ---- formal properties (tests/formal/soc_spiflash.sby: proved by induction) ----
    // The bus rules and the flash, assumed, and the slave's properties, asserted, are in
    // tests/formal/soc_spiflash_check.sv (a model of the bus and one of the flash, written from the
    // data sheet's protocol); here, the invariants that tie the flops to those models.
    wire          f_past_valid, f_busy, f_wr_due, f_first, f_valid, f_woke, f_pend, f_token;
    wire          f_cmd_rd;
    wire [5:0]    f_rx_n;
    wire [31:0]   f_rx;
    wire [26:0]   f_pos;
    wire [CW-1:0] f_high;
    wire [DW-1:0] f_same;
    wire [AW-1:0] f_cmd_adr;
    wire [23:0]   f_taddr;
    wire [7:0]    f_tval;
    wire [15:0]   f_rdw, f_wait;
    soc_spiflash_check #(
        .ADDR_BITS(ADDR_BITS), .SCK_DIV(SCK_DIV), .CS_HIGH_CLKS(CS_HIGH_CLKS), .WAKE_CLKS(WAKE_CLKS)
    ) f_check (
        .clk(clk), .rst(rst),
        .wb_cyc(wb_cyc), .wb_stb(wb_stb), .wb_we(wb_we), .wb_adr(wb_adr), .wb_sel(wb_sel),
        .wb_dat_w(wb_dat_w), .wb_dat_r(wb_dat_r), .wb_ack(wb_ack), .wb_err(wb_err),
        .flash_cs_n(flash_cs_n), .flash_sck(flash_sck), .flash_mosi(flash_mosi),
        .flash_miso(flash_miso),
        .f_past_valid(f_past_valid), .f_busy(f_busy), .f_wr_due(f_wr_due), .f_rx_n(f_rx_n),
        .f_rx(f_rx), .f_first(f_first), .f_pos(f_pos), .f_valid(f_valid), .f_high(f_high),
        .f_same(f_same), .f_woke(f_woke), .f_pend(f_pend), .f_token(f_token),
        .f_cmd_adr(f_cmd_adr), .f_cmd_rd(f_cmd_rd), .f_taddr(f_taddr), .f_tval(f_tval),
        .f_rdw(f_rdw), .f_wait(f_wait)
    );

    // What the transfer under way (or the last one) is, and last clock's request.
    localparam [1:0] F_WAKE = 2'd0, F_CMD = 2'd1, F_STREAM = 2'd2;
    reg [1:0]    f_kind_q = F_WAKE;
    reg          f_rd_q = 1'b0, f_wr_q = 1'b0;
    reg [AW-1:0] f_adr_q = '0;
    always @(posedge clk) begin
        if (!rst && start_wake) f_kind_q <= F_WAKE;
        if (!rst && start_cmd) f_kind_q <= F_CMD;
        if (!rst && start_stream) f_kind_q <= F_STREAM;
        f_rd_q <= req && !wb_we;
        f_wr_q <= req && wb_we;
        f_adr_q <= wb_adr;
    end
    wire [6:0]    f_total = f_kind_q == F_WAKE ? 7'd8 : f_kind_q == F_CMD ? 7'd64 : 7'd32;
    wire [6:0]    f_falls = f_total - bits_q;                 // SCK falling edges so far
    wire [6:0]    f_rises = f_falls + {6'd0, flash_sck};     // ... rising edges
    wire [AW-1:0] f_w = next_q - 1'b1;                        // the word read
    wire [26:0]   f_wpos = {f_w, 5'd0};                       // its first bit in the flash's count
    wire [31:0]   f_cmd = f_kind_q == F_WAKE ? {CMD_RDP, 24'd0} : {CMD_READ, f_wpos[26:3]};
    // the command phase (wake-up or READ, up to the address's last falling edge) ...
    wire f_cmd_phase = state_q != ST_HIGH && (f_kind_q == F_WAKE || (f_kind_q == F_CMD && f_falls < 7'd32));
    // ... and the data phase: the flash drives the word's bits, which shift into sr_q
    wire f_data = state_q != ST_HIGH && woke_q && (f_kind_q == F_STREAM || f_falls >= 7'd32);
    wire [6:0]    f_have = f_kind_q == F_STREAM ? f_falls : f_falls - 7'd32;   // data bits of the word
    wire [26:0]   f_dpos = f_wpos + {20'd0, f_have};             // the flash's bit now
    // The clocks from this one to the answer of a read held from now on (0: answered now): the
    // edges to the last falling edge of the transfer under way, then what follows it.
    localparam integer F_CMD_CLKS = 128 * SCK_DIV;   // a READ's 64 SCK cycles
    wire [15:0]   f_xfer = div_q + (2 * bits_q - flash_sck - 1) * SCK_DIV;
    wire [15:0]   f_left = ack_q ? 0
                         : state_q == ST_XFER ? (pending_q ? f_xfer + 1
                                                 : f_xfer + 1 + (woke_q ? CS_HIGH_CLKS : WAIT_CLKS) + F_CMD_CLKS + 1)
                         : state_q == ST_OPEN ? (!woke_q ? WAIT_CLKS + F_CMD_CLKS + 1
                                                 : seq ? 64 * SCK_DIV + 1 : CS_HIGH_CLKS + F_CMD_CLKS + 1)
                         : woke_q ? cnt_q + F_CMD_CLKS + 1 : cnt_q + 144 * SCK_DIV + WAIT_CLKS + 2;

    always @(*) begin
        if (f_past_valid) begin
            assert(state_q != 2'd3 && f_kind_q != 2'd3 && div_q <= DIV_LAST);
            // a read's wait: at most f_wait clocks after its first
            assert(f_left <= f_wait && f_rdw <= f_wait);
            if (req && !wb_we) assert({1'b0, f_rdw} + {1'b0, f_left} <= {1'b0, f_wait});
            // the bus: each answer owed to the request of the last clock, still held
            assert(!(ack_q && err_q));
            assert(err_q == f_wr_due);
            if (ack_q || err_q) assert(f_busy);
            if (f_busy && f_wr_q) assert(err_q);
            if (ack_q) assert(state_q == ST_OPEN && woke_q && f_kind_q != F_WAKE && f_busy && f_rd_q
                              && f_adr_q == f_w);
            if (pending_q) assert(state_q == ST_XFER && woke_q && f_kind_q != F_WAKE && f_busy
                                  && f_rd_q && f_adr_q == f_w && !ack_q && !err_q);
            // the wake-up
            if (!woke_q) assert(!f_woke);
            if (state_q != ST_HIGH) assert(!flash_cs_n && (woke_q ? f_woke && f_kind_q != F_WAKE
                                                                  : f_kind_q == F_WAKE && !f_pend));
            if (state_q != ST_HIGH && woke_q) assert(stream_ok_q == (next_q != '0));
            // CS# high
            if (state_q == ST_HIGH) begin
                assert(flash_cs_n && !flash_sck && bits_q == 7'd0);
                assert(cnt_q <= WAKE_LAST && f_high + 1 + cnt_q >= CS_HIGH_CLKS);
                if (!woke_q) assert(!f_pend && cnt_q <= HIGH_LAST);
                else assert(f_woke || (f_pend && f_high + 1 + cnt_q >= WAKE_CLKS));
            end
            if (state_q == ST_OPEN) assert(!flash_sck && bits_q == 7'd0);
            // SCK running: its level's time, and a read's token
            if (state_q == ST_XFER) begin
                assert(bits_q != 7'd0 && bits_q <= f_total && !ack_q);
                assert(f_same + div_q >= SCK_DIV);
                if (woke_q) assert(f_token);
            end
            // the command phase: the bits the flash has, and those left in sr_q
            if (f_cmd_phase) begin
                assert(f_rx_n == f_rises[5:0]);
                assert((f_rx & ~(32'hFFFFFFFF << f_rises)) == f_cmd >> (7'd32 - f_rises));
                assert((sr_q >> f_falls) == ((f_cmd << f_falls) >> f_falls));
                if (f_kind_q == F_CMD) assert(f_cmd_rd && f_cmd_adr == f_w);
                if (f_rises == 7'd32) assert(f_first && f_pos == f_wpos && !f_valid);
                else assert(!f_valid);
            end
            // the data phase: where the flash is (the bit it has driven since the last falling
            // edge), and the tracked bits received
            if (f_data) begin
                assert(f_rx_n == 6'd32 && f_rx[31:24] == CMD_READ && !f_first);
                if (f_kind_q == F_CMD) assert(f_rx == f_cmd);
                assert(f_pos == f_dpos && f_valid);
            end
        end
    end
    // The tracked byte, if it is in this word: its bits are data bits 8 * lane .. 8 * lane + 7, MSB
    // first; data bit j (of f_have received) is in rx[f_have - 1 - j]. The one sampled last, at
    // the falling edge that began the flash's present bit (f_pos), is rx[0] = miso_q: data bit
    // f_have - 1, the bit the flash drove in the SCK period before that edge, never the one it
    // drives after it (late sampling, at the edge that drops SCK, not at the one that raised it).
    wire       f_tw = f_taddr[23:2] == f_wpos[26:5];
    wire [5:0] f_tj = {1'b0, f_taddr[1:0], 3'd0};
    genvar f_b;
    generate for (f_b = 0; f_b < 8; f_b = f_b + 1) begin : g_f_byte
        wire [5:0] f_j = f_tj + f_b;
        wire [5:0] f_at = f_have[5:0] - 6'd1 - f_j;
        always @(*) begin
            if (f_past_valid && f_data && f_tw) begin
                if (f_j < f_have[5:0]) assert(rx[f_at[4:0]] == f_tval[7 - f_b]);
            end
        end
    end endgenerate
`endif
endmodule

`default_nettype wire
