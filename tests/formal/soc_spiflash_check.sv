// soc_spiflash_check: formal properties of soc_spiflash (soc_rtl/soc_spiflash.v), a read-only SPI
// flash reader behind a Wishbone B4 classic slave, from its ports (tests/formal/soc_spiflash.sby;
// make formal).
//
// As gpu_wb_slave_check: a property module the slave instantiates in its `ifdef FORMAL block. It
// assumes the master's side and the flash's, asserts the slave's, and hands its models (the bus's
// and the flash's) to the slave's block, whose invariants tie its flops to them (yosys reads no
// hierarchical names). SOC_SPIFLASH defined (this proof): the partners' rules are assumed;
// undefined (a larger proof that includes the slave with its partners): they are asserted.
//
// The flash model is written from the data sheet's protocol, not from the slave: it watches CS#,
// SCK and MOSI (flops of the slave: a change seen in a clock happened at the clock edge that began
// it), counts the rising edges since CS# fell, takes the command byte and the 24-bit address MSB
// first, and after the address drives one data bit per falling edge, MSB first, the address
// counting up (wrapping at 16 MiB). One byte is tracked: an anyconst address and value; every other
// bit is any value, at any clock. A bit of the tracked byte is on MISO from the rising edge after
// the falling edge that began it until the next falling edge; while SCK is low after that edge
// MISO is any value (changing): see "MISO", below, for the clock edges and why.
// Master (assumed): reset in the first clock, then at any clock; Wishbone classic: wb_we, wb_adr,
//   wb_sel and wb_dat_w held while a request goes on; it may drop wb_cyc or wb_stb before the answer
//   (the request is abandoned), hold wb_stb into the next request, or raise wb_stb without wb_cyc.
// Slave (asserted), Wishbone: wb_ack and wb_err only during a request, never both, never in its
//   first clock (one answer per request); wb_err exactly in a write's second clock; wb_ack only for
//   reads; wb_dat_r 0 without wb_ack; a read of the word that holds the tracked byte returns it in
//   its byte lane; a read held is answered at most F_WAIT clocks after its first, whatever came
//   before (a READ under way for an abandoned request, the wake-up): the slave is never stuck.
// Slave (asserted), SPI: SCK low while CS# is high; SCK changes only with CS# low before and
//   after, CS# only with SCK low before and after (mode 0), except at a reset; MOSI changes only
//   into SCK low; each SCK level, and the low level after CS# falls, lasts at least SCK_DIV
//   clocks; CS# high at least CS_HIGH_CLKS clocks; every command is 0xAB (exactly 8 SCK cycles)
//   or 0x03; a 0x03 comes after a 0xAB and WAKE_CLKS clocks of CS# high since the last reset, its
//   CS# fell after a clock with a read request, and its address is that request's byte address;
//   no SCK rising edge and no CS# fall without a reason (the wake-up since the reset, a read
//   request now, or one of an earlier clock whose word the flash has not finished: a write never
//   starts anything); CS# rises only after the wake-up command or for a read of a word other than
//   the one the flash is at (a consecutive read streams), or at a reset.
// Covers (with a scripted master, below): a read answered; the next word streamed after it (SCK
// running again with CS# still low); a restart (CS# falling again after an answered read); a write
// refused; a read answered after an abandoned one.
`default_nettype none

`ifdef SOC_SPIFLASH
`define SOC_SPIFLASH_ASSUME assume
`else
`define SOC_SPIFLASH_ASSUME assert
`endif

module soc_spiflash_check #(
    parameter integer ADDR_BITS = 8,
    parameter integer SCK_DIV = 1,
    parameter integer CS_HIGH_CLKS = 2,
    parameter integer WAKE_CLKS = 4,
    localparam integer AW = ADDR_BITS - 2,
    localparam integer HIGH_MAX = WAKE_CLKS > CS_HIGH_CLKS ? WAKE_CLKS : CS_HIGH_CLKS,
    localparam integer HW = $clog2(HIGH_MAX + 1),
    localparam integer SW = $clog2(SCK_DIV + 1),
    // The longest wait of a read (clocks after its first, in which it is answered at the latest):
    // behind a READ just started for an abandoned request (64 SCK cycles), CS# high, its own READ;
    // or behind the wake-up after a reset.
    localparam integer WAIT_CMD = 256 * SCK_DIV + CS_HIGH_CLKS + 1,
    localparam integer WAIT_WAKE = CS_HIGH_CLKS + 144 * SCK_DIV + HIGH_MAX + 1,
    localparam integer F_WAIT = WAIT_CMD > WAIT_WAKE ? WAIT_CMD : WAIT_WAKE
) (
    input  wire          clk,
    input  wire          rst,
    // the slave's Wishbone port
    input  wire          wb_cyc,
    input  wire          wb_stb,
    input  wire          wb_we,
    input  wire [AW-1:0] wb_adr,
    input  wire [3:0]    wb_sel,
    input  wire [31:0]   wb_dat_w,
    input  wire [31:0]   wb_dat_r,
    input  wire          wb_ack,
    input  wire          wb_err,
    // its flash port
    input  wire          flash_cs_n,
    input  wire          flash_sck,
    input  wire          flash_mosi,
    input  wire          flash_miso,
    // the models, for the slave's invariants
    output reg           f_past_valid,  // not the first clock
    output reg           f_busy,        // last clock had a request not answered: this one continues it
    output reg           f_wr_due,      // last clock was a write's first: answered (err) now if held
    output reg  [5:0]    f_rx_n,        // the flash: bits received since CS# fell (0..32, then held)
    output reg  [31:0]   f_rx,          // ... those bits, the last in bit 0: command, address
    output reg           f_first,       // ... the address is in, no data bit driven yet
    output reg  [26:0]   f_pos,         // ... the data bit driven (byte address, bit 0 = MSB first)
    output reg           f_valid,       // ... the flash drives that bit (since its falling edge)
    output reg  [HW-1:0] f_high,        // clocks CS# had been high before this one (saturating)
    output reg  [SW-1:0] f_same,        // clocks SCK has had its level, this one included (saturating)
    output reg           f_woke,        // since reset: 0xAB sent and WAKE_CLKS of CS# high after it
    output reg           f_pend,        // since reset: 0xAB sent and CS# high since
    output reg           f_token,       // a read was requested whose word the flash has not finished
    output reg  [AW-1:0] f_cmd_adr,     // the read requested in the clock before CS# last fell
    output reg           f_cmd_rd,      // ... there was one
    output wire [23:0]   f_taddr,       // the tracked byte's address
    output wire [7:0]    f_tval,        // ... and value
    output reg  [15:0]   f_rdw,         // clocks the read held now has waited (0: its first)
    output wire [15:0]   f_wait         // F_WAIT: the most it may wait
);
    localparam [7:0] CMD_READ = 8'h03;
    localparam [7:0] CMD_RDP  = 8'hAB;
    localparam [SW-1:0] SAME_ONE = 1, SAME_MAX = SCK_DIV;
    localparam [HW-1:0] HIGH_TOP = HIGH_MAX, HIGH_MIN = CS_HIGH_CLKS, HIGH_WAKE = WAKE_CLKS;

    (* anyconst *) reg [23:0] f_track_addr;
    (* anyconst *) reg [7:0]  f_track_val;
    assign f_taddr = f_track_addr;
    assign f_tval = f_track_val;
    assign f_wait = F_WAIT[15:0];

    wire req = wb_cyc && wb_stb;
    wire rd_req = req && !wb_we;
    wire answer = wb_ack || wb_err;
    wire first = req && !f_busy;   // a request's first clock

    // ---- the bus model ----
    reg f_busy_rd;     // last clock's unanswered request was a read
    initial begin
        f_past_valid = 1'b0;
        f_busy = 1'b0;
        f_wr_due = 1'b0;
        f_busy_rd = 1'b0;
        f_rdw = 16'd0;
    end
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_busy <= !rst && req && !answer;
        f_busy_rd <= !rst && rd_req && !answer;
        f_rdw <= (rst || !rd_req || answer) ? 16'd0 : (f_rdw == f_wait ? f_rdw : f_rdw + 1'b1);
        f_wr_due <= !rst && first && wb_we;
    end

    // ---- the master ----
    always @(*) begin
        if (!f_past_valid) `SOC_SPIFLASH_ASSUME(rst);
    end
    always @(posedge clk) begin
        if (f_busy && req) begin
            `SOC_SPIFLASH_ASSUME(wb_we == $past(wb_we));
            `SOC_SPIFLASH_ASSUME(wb_adr == $past(wb_adr));
            `SOC_SPIFLASH_ASSUME(wb_sel == $past(wb_sel));
            `SOC_SPIFLASH_ASSUME(wb_dat_w == $past(wb_dat_w));
        end
    end

    // ---- the flash ----
    // The slave's outputs and the bus in the last clock; p_rst: the slave was reset at the edge
    // that began this clock (what changed at that edge is the reset's doing).
    reg p_cs_n = 1'b1, p_sck = 1'b0, p_mosi = 1'b0, p_rst = 1'b1, p_rd = 1'b0;
    reg [AW-1:0] p_adr = '0;
    always @(posedge clk) begin
        p_cs_n <= flash_cs_n;
        p_sck <= flash_sck;
        p_mosi <= flash_mosi;
        p_rst <= rst;
        p_rd <= rd_req;
        p_adr <= wb_adr;
    end
    wire cs_fell = p_cs_n && !flash_cs_n;
    wire cs_rose = !p_cs_n && flash_cs_n;
    wire sck_rose = !flash_cs_n && !p_sck && flash_sck;
    wire sck_fell = !flash_cs_n && p_sck && !flash_sck;

    // The model's state after the last clock's events (m_*), and after this clock's (f_*: what the
    // flash is doing now, from the changes at the edge that began this clock).
    reg [5:0]    m_rx_n = 6'd0;
    reg [31:0]   m_rx = 32'd0;
    reg          m_first = 1'b0, m_valid = 1'b0;
    reg [26:0]   m_pos = 27'd0;
    reg [HW-1:0] m_high = '0;
    reg [SW-1:0] m_same = '0;
    reg          m_woke = 1'b0, m_pend = 1'b0, m_token = 1'b0, m_cmd_rd = 1'b0;
    reg [AW-1:0] m_cmd_adr = '0;
    wire is_read = f_rx_n == 6'd32 && f_rx[31:24] == CMD_READ;
    // the flash finishes a word at this edge (its next bit is a word's first)
    wire word_end = sck_fell && m_rx_n == 6'd32 && !m_first && m_pos[4:0] == 5'd31;
    always @(*) begin
        f_rx_n = m_rx_n;
        f_rx = m_rx;
        f_first = m_first;
        f_pos = m_pos;
        f_valid = m_valid;
        if (flash_cs_n) begin   // deselected: the next command starts afresh
            f_rx_n = 6'd0;
            f_first = 1'b0;
            f_valid = 1'b0;
        end else if (sck_rose) begin
            if (m_rx_n != 6'd32) begin
                f_rx = {m_rx[30:0], p_mosi};   // MOSI as it was before the edge (and after: held)
                f_rx_n = m_rx_n + 1'b1;
                if (m_rx_n == 6'd31) begin
                    f_pos = {f_rx[23:0], 3'd0};
                    f_first = 1'b1;
                end
            end
        end else if (sck_fell && m_rx_n == 6'd32) begin
            if (!m_first) f_pos = m_pos + 1'b1;
            f_first = 1'b0;
            f_valid = 1'b1;
        end
        f_high = m_high;
        f_same = (flash_sck != p_sck || cs_fell) ? SAME_ONE : (m_same == SAME_MAX ? m_same : m_same + 1'b1);
        // the session (since reset): the wake-up, the tokens, the command's request
        f_woke = m_woke;
        f_pend = m_pend;
        f_token = m_token && !word_end;
        f_cmd_adr = m_cmd_adr;
        f_cmd_rd = m_cmd_rd;
        if (p_rst) begin
            f_woke = 1'b0;
            f_pend = 1'b0;
            f_token = 1'b0;
        end else if (cs_rose) begin
            if (m_rx_n == 6'd8 && m_rx[7:0] == CMD_RDP) f_pend = 1'b1;
        end else if (cs_fell) begin
            if (m_pend && m_high >= HIGH_WAKE) f_woke = 1'b1;
            f_pend = 1'b0;
            f_cmd_adr = p_adr;
            f_cmd_rd = p_rd;
        end
    end
    always @(posedge clk) begin
        m_rx_n <= f_rx_n;
        m_rx <= f_rx;
        m_first <= f_first;
        m_pos <= f_pos;
        m_valid <= f_valid;
        m_high <= !flash_cs_n ? '0 : (m_high == HIGH_TOP ? m_high : m_high + 1'b1);
        m_same <= f_same;
        m_woke <= !rst && f_woke;
        m_pend <= !rst && f_pend;
        m_token <= !rst && (f_token || rd_req);
        m_cmd_adr <= f_cmd_adr;
        m_cmd_rd <= f_cmd_rd;
    end

    // MISO: the tracked byte's bits, MSB first, each from the rising SCK edge after the falling
    // edge that began it to the next falling edge; any value while SCK is low.
    // The clock edges. The slave's flop that samples MISO takes, at a clock edge, flash_miso as it
    // is in the clock that edge ends. SCK is a flop of the slave: the edge that drops it begins the
    // first clock with flash_sck low, where this model sees sck_fell and moves to the next bit
    // (f_pos), so the bit the flash drove in the SCK period before is still flash_miso in the clock
    // that edge ends (SCK high): a flop sampling at the edge that drops SCK takes it, and the new
    // bit is seen at the earliest at the edge after (the flash cannot answer a fall before the edge
    // that makes it; a model whose MISO changed in the clock ending at that edge would have the
    // flash see the fall a clock early, and refuse the late sampling that is right on the board).
    // Why free while SCK is low: on the board the new bit reaches the flop 23-27 ns after the edge
    // that dropped SCK (SCK's route, the flash's tV, the MISO path: soc_spiflash.v's SPI timing),
    // past the half-period of 20 ns at SCK = clk / 2, so a sample at the edge that raises SCK (the
    // end of the last clock with SCK low) may catch MISO changing. A zero-delay flash holding the
    // bit the whole period could not tell that sample from a right one (early sampling is a matter
    // of the board's delays, not of the logic: with such a model the rising-edge copy of
    // soc_spiflash.broken passes even the proof, only the late one fails); this model leaves every
    // clock with SCK low free (the output still changing, at any SCK_DIV) and asks only that the
    // bit be there with SCK high, up to and including the clock the next falling edge ends (the
    // hold past that edge, tHO and the route delays, is the board's, not visible here). So a slave
    // that samples at the rising edge, or a clock after the falling edge, reads any value and fails
    // the tracked byte's property; one that samples at the edge that drops SCK reads the bit.
    always @(*) begin
        if (!flash_cs_n && flash_sck && f_valid && is_read && f_pos[26:3] == f_track_addr)
            `SOC_SPIFLASH_ASSUME(flash_miso == f_track_val[~f_pos[2:0]]);
    end

    // ---- the slave: Wishbone ----
    wire [23:0] req_byte = {wb_adr, 2'b00};       // zero-extended
    wire [21:0] req_word = wb_adr;
    wire [23:0] cmd_byte = {f_cmd_adr, 2'b00};
    always @(*) begin
        if (f_past_valid) begin
            if (wb_ack) assert(req);
            if (wb_err) assert(req);
            assert(!(wb_ack && wb_err));
            if (!wb_ack) assert(wb_dat_r == 32'd0);
            if (first) assert(!answer);
            assert(wb_err == (req && f_wr_due));
            if (wb_ack) assert(!wb_we);
            if (rd_req && f_rdw == f_wait) assert(wb_ack);   // never stuck, whatever came before
            if (wb_ack && req_byte[23:2] == f_track_addr[23:2])
                assert(wb_dat_r[8 * f_track_addr[1:0] +: 8] == f_track_val);
        end
    end

    // ---- the slave: SPI ----
    // Activity needs a reason: the wake-up (not done since reset), a read now, or a token.
    wire allow = !f_woke || rd_req || f_token;
    // CS# may rise after the wake-up command, or for a read of a word other than the flash's next
    // (its counter at a word's start, inside the window; not 0, where a 16 MiB flash wraps).
    wire [21:0] at_word = f_pos[26:5];
    wire at_start = !flash_cs_n && is_read && !f_first && f_pos[4:0] == 5'd0 && at_word != 22'd0
                    && (at_word >> AW) == 22'd0;
    wire may_close = (f_rx_n == 6'd8 && f_rx[7:0] == CMD_RDP)
                     || (rd_req && !(at_start && req_word == at_word));
    reg p_allow = 1'b0, p_may_close = 1'b0;
    always @(posedge clk) begin
        p_allow <= allow;
        p_may_close <= may_close;
    end
    always @(*) begin
        if (f_past_valid && flash_cs_n) assert(!flash_sck);
        if (f_past_valid && !p_rst) begin
            // mode 0
            if (flash_sck != p_sck) assert(!flash_cs_n && !p_cs_n);
            if (flash_cs_n != p_cs_n) assert(!flash_sck && !p_sck);
            if (flash_mosi != p_mosi) assert(!flash_sck);
            if (flash_sck != p_sck) assert(m_same >= SAME_MAX);
            // CS# high time, and a reason for every transfer and every CS# rise
            if (cs_fell) assert(m_high >= HIGH_MIN);
            if (cs_fell || sck_rose) assert(p_allow);
            if (cs_rose) assert(p_may_close);
            // the commands
            if (sck_rose && m_rx_n == 6'd7) begin
                assert(f_rx[7:0] == CMD_READ || f_rx[7:0] == CMD_RDP);
                if (f_rx[7:0] == CMD_READ) assert(f_woke && f_cmd_rd);
            end
            if (sck_rose && m_rx_n == 6'd8) assert(m_rx[7:0] != CMD_RDP);
            if (sck_rose && m_rx_n == 6'd31 && f_rx[31:24] == CMD_READ)
                assert(f_rx[23:0] == cmd_byte);
        end
    end

    // ---- covers ----
    // SOC_SPIFLASH_SCRIPT (the cover task): a scripted master, as z3 takes minutes a step to search
    // a free master's traces 150 clocks deep (a first read takes that long). No reset after the
    // first clock; one request at a time, an idle clock after each: a read abandoned in its second
    // clock, a read of an anyconst word, a write, a read of another anyconst word, each held until
    // its answer.
    // MISO, wb_sel and wb_dat_w are 0 (they steer nothing here, and z3 is faster without them).
`ifdef SOC_SPIFLASH_SCRIPT
    (* anyconst *) reg [AW-1:0] f_s_adr2, f_s_adr3;
    reg [1:0] f_s_n = 2'd0;   // the request: 0 the abandoned read, 1 a read, 2 the write, 3 a read
    reg       f_s_gap = 1'b1; // a clock without a request
    reg       f_s_done = 1'b0;
    reg       f_s_held = 1'b0; // the request's first clock is over
    wire      f_s_req = !f_s_gap && !f_s_done && !(f_s_n == 2'd0 && f_s_held);
    always @(posedge clk) begin
        if (rst) begin
            f_s_n <= 2'd0;
            f_s_gap <= 1'b1;
            f_s_done <= 1'b0;
            f_s_held <= 1'b0;
        end else if (f_s_gap || f_s_done) begin
            f_s_gap <= 1'b0;
        end else if (!f_s_req || answer) begin   // abandoned (the first read) or answered
            f_s_n <= f_s_n + 1'b1;
            f_s_gap <= 1'b1;
            f_s_done <= f_s_n == 2'd3;
            f_s_held <= 1'b0;
        end else begin
            f_s_held <= 1'b1;
        end
    end
    always @(*) begin
        if (f_past_valid) assume(!rst);
        assume(wb_cyc == f_s_req && wb_stb == f_s_req);
        assume(!flash_miso && wb_sel == 4'd0 && wb_dat_w == 32'd0);
        if (f_s_req) begin
            assume(wb_we == (f_s_n == 2'd2));
            if (f_s_n == 2'd1) assume(wb_adr == f_s_adr2);
            if (f_s_n == 2'd3) assume(wb_adr == f_s_adr3);
        end
    end
`endif
    reg [1:0] f_acks = 2'd0;      // reads answered since reset
    reg [1:0] f_acks_low = 2'd0;  // ... since CS# last fell
    reg       f_abandoned = 1'b0; // a read dropped before its answer since reset
    always @(posedge clk) begin
        if (rst) f_acks <= 2'd0;
        else if (wb_ack && f_acks != 2'd3) f_acks <= f_acks + 1'b1;
        if (rst || flash_cs_n) f_acks_low <= 2'd0;
        else if (wb_ack && f_acks_low != 2'd3) f_acks_low <= f_acks_low + 1'b1;
        f_abandoned <= !rst && (f_abandoned || (f_busy_rd && !req));
    end
    always @(*) begin
        if (f_past_valid && !rst && !p_rst) begin
            cover(wb_ack);                                   // a read answered
            cover(sck_rose && f_acks_low != 2'd0);           // the next word streamed after it
            cover(cs_fell && f_acks != 2'd0);                // a new command after it (restart)
            cover(wb_err);                                   // a write refused
            cover(wb_ack && f_abandoned);                    // a read answered after an abandoned one
        end
    end
endmodule

`undef SOC_SPIFLASH_ASSUME
`default_nettype wire
