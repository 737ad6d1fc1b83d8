// usb_ls_tx: the USB 1.1 low-speed host's transmitter (the line layer): a packet's bytes in, the
// bus's D+/D- out as SYNC, NRZI, bit stuffing and EOP; also a bare EOP (the low-speed keep-alive)
// and a bus reset. One clock (clk at SYS_HZ); the bit boundaries are placed by a fractional step.
//
// Contract (stream): a packet is the bytes of one valid/ready stream up to the one with tx_last
// (tx_data sent LSB first; the first byte is the PID; at least one byte). A byte is taken in a
// clock with tx_valid && tx_ready. In idle (tx_idle), tx_ready is high and the first byte starts
// the packet: the SYNC's first K is on the pins from the next clock (outputs registered: one clock
// of latency). The byte waits in a holding register while the SYNC is sent, and each later byte is
// taken into it as soon as the previous one moves to the shifter: tx_ready rises in the clock
// after the shifter loads a byte and stays high until a byte arrives, so the source has a byte time
// less a clock (8 bit times, about 5.3 us, 266 clocks at 50 MHz) to present the next one. Throughput: one byte
// per 8 bit times plus stuffed bits (1.5 Mb/s on the wire). After the byte with tx_last, tx_ready
// stays low until tx_idle: the next packet cannot start before this one's EOP has been sent (the
// inter-packet gap, 2 bit times or more (7.1.18), is the caller's).
// Underrun (the source must not let it happen: a source holding the whole packet, as
// usb_ls_packet_tx, keeps tx_valid high from its first byte to its last): if the shifter needs the
// next byte and the holding register is empty before tx_last was seen, tx_underrun pulses for one
// clock and the packet is made invalid for every receiver: seven more 1 bits without a stuffed 0
// (a bit-stuff error, 7.1.9), then the EOP. The rest of that packet's bytes are then taken and
// dropped (tx_ready high) up to and including its tx_last, a byte offered in the very clock the
// shifter needed it among them; tx_idle stays low until then.
// Contract (line): low-speed J is D- high, D+ low; K is D+ high, D- low; SE0 both low. usb_oe is
// high while the host drives the lines: from the SYNC's first K (or the SE0 of a bare EOP or a
// reset) to the end of the J after the SE0, then the lines are released (the device's pull-up
// holds J). A packet: SYNC (KJKJKJKK), the bytes in NRZI (a 0 toggles the line, a 1 keeps it),
// with a 0 inserted after every six consecutive 1s, counting from the SYNC's last bit and across
// bytes, also after the last data bit if it ends a run of six (7.1.9); then the EOP: SE0 for two
// bit times (1.33 us: TLEOPT is 1.25 to 1.50 us) and J for one. eop_start (in idle): SE0 two bit
// times, J one, release: the keep-alive a low-speed port gets instead of a SOF (11.8.4.1).
// reset_start (in idle): SE0 for reset_clks clocks (at least 1; 10 ms or more for a bus reset,
// TDRST, 7.1.7.3), then J for one bit time, then release. Priority when several arrive in one idle
// clock: reset, EOP, packet (tx_ready is low in a clock with reset_start or eop_start); a request
// outside tx_idle is ignored. tx_done pulses in the clock the lines are released.
// Contract (timing): bit boundaries at the system clock nearest their ideal time k * SYS_HZ /
// 1.5 MHz from the SOP (ties to the earlier clock), so the average rate is exactly 1.5 Mb/s of
// clk, and each transition is within half a clock of its ideal time: at 50 MHz (33 1/3 clocks a
// bit) the bits last 33 or 34 clocks and any interval between transitions is within 2/3 of a clock
// (13.3 ns) of its ideal length, inside the host's low-speed source jitter (TDDJ1 +-25 ns to the
// next transition, TDDJ2 +-14 ns for paired transitions; docs/usb.md has the sources and the
// stricter +-10 ns of 7.1.13's text). usb_pkg::ls_sys_hz_ok says which SYS_HZ meet that; the module
// refuses the others at elaboration. The rate's accuracy is clk's (a host's: +-0.05 %).
// Formal: tests/formal/usb_ls_tx.sby (the `ifdef FORMAL block at the end).
`default_nettype none

module usb_ls_tx #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // clk's frequency, Hz
    parameter integer RESET_W = 24,                          // width of reset_clks (2^24 clocks: 335 ms at 50 MHz)
    // the bit timing's fraction in lowest terms: a bit is MOD / INC clocks
    localparam integer G = usb_pkg::gcd(SYS_HZ, usb_pkg::USB_LS_BIT_HZ),
    localparam integer INC = usb_pkg::USB_LS_BIT_HZ / G,
    localparam integer MOD = SYS_HZ / G,
    localparam integer ACC_W = $clog2(2 * MOD + 2 * INC)   // holds 2 * (MOD + INC): half-clock units
) (
    input  wire               clk,
    input  wire               rst,          // synchronous, active high
    // packet stream (bytes in the order sent, each LSB first)
    input  wire               tx_valid,
    output reg                tx_ready,
    input  wire [7:0]         tx_data,
    input  wire               tx_last,      // this byte ends the packet
    // line requests (taken only while tx_idle)
    input  wire               eop_start,    // a bare EOP: the low-speed keep-alive
    input  wire               reset_start,  // SE0 for reset_clks clocks (a bus reset)
    input  wire [RESET_W-1:0] reset_clks,   // with reset_start, at least 1
    // status
    output wire               tx_idle,      // not driving, nothing in progress: a packet or request may start
    output reg                tx_done,      // one clock: the lines have just been released
    output reg                tx_underrun,  // one clock: the stream ran dry mid-packet (see above)
    // the bus (registered)
    output reg                usb_dp_out,
    output reg                usb_dn_out,
    output reg                usb_oe        // the host drives both lines while high
);
`ifndef FORMAL  // the proof (tests/formal/usb_ls_tx.sby) runs at 3 1/3 clocks a bit: short traces
    generate if (!usb_pkg::ls_sys_hz_ok(SYS_HZ)) begin : g_bad
        $error("usb_ls_tx: SYS_HZ gives bit edges outside the low-speed source jitter (usb_pkg::ls_sys_hz_ok)");
    end endgenerate
`endif

    // The fractional bit timer, in half-clock units: acc_q is 2 * INC * (clocks since the SOP) + INC
    // modulo 2 * MOD, so the k-th boundary falls on the first clock c with c >= k * MOD / INC - 1/2.
    localparam integer STEP_I = 2 * INC, WRAP_I = 2 * MOD;
    localparam [ACC_W-1:0] STEP = STEP_I[ACC_W-1:0];
    localparam [ACC_W-1:0] WRAP = WRAP_I[ACC_W-1:0];
    localparam [ACC_W-1:0] ACC0 = INC[ACC_W-1:0];

    localparam [2:0] S_IDLE = 3'd0, S_DATA = 3'd1, S_ABORT = 3'd2, S_EOP = 3'd3, S_EOPJ = 3'd4,
                     S_RESET = 3'd5;
    reg [2:0]         st_q;
    reg [ACC_W-1:0]   acc_q;
    reg [7:0]         shift_q;       // the byte being sent (the SYNC's 8'h80 first)
    reg [3:0]         bitn_q;        // its bits sent, 0..8
    reg               cur_last_q;    // it ends the packet
    reg [7:0]         hold_q;        // the next byte
    reg               hold_valid_q, hold_last_q;
    reg [2:0]         ones_q;        // consecutive 1s sent, 0..6
    reg               level_q;       // the NRZI line level: 1 K, 0 J
    reg               flush_q;       // after an underrun: drop the packet's remaining bytes
    reg [RESET_W-1:0] cnt_q;         // reset clocks left; abort 1s left; EOP SE0 bits left

    wire [ACC_W-1:0] acc_sum = acc_q + STEP;
    wire tick = st_q != S_IDLE && st_q != S_RESET && acc_sum >= WRAP;   // a bit boundary at the next edge
    wire idle = st_q == S_IDLE && !flush_q;
    assign tx_idle = idle;
    always @(*) begin
        if (flush_q) tx_ready = 1'b1;
        else if (st_q == S_IDLE) tx_ready = !reset_start && !eop_start;
        else tx_ready = st_q == S_DATA && !hold_valid_q && !cur_last_q;
    end
    wire take = tx_valid && tx_ready;
    wire start_reset = idle && reset_start;
    wire start_eop = idle && !reset_start && eop_start;
    wire start_pkt = idle && take;
    wire stuff = ones_q == 3'd6;           // the next bit is a stuffed 0
    wire [7:0] next_byte = hold_q;

    // Line symbols on the registered outputs.
    task automatic drive_level(input k);
        begin
            usb_dp_out <= k;
            usb_dn_out <= !k;
            usb_oe <= 1'b1;
        end
    endtask
    task automatic drive_se0;
        begin
            usb_dp_out <= 1'b0;
            usb_dn_out <= 1'b0;
            usb_oe <= 1'b1;
        end
    endtask

    always @(posedge clk) begin
        if (rst) begin
            st_q <= S_IDLE;
            acc_q <= ACC0;
            shift_q <= 8'd0;
            bitn_q <= 4'd0;
            cur_last_q <= 1'b0;
            hold_q <= 8'd0;
            hold_valid_q <= 1'b0;
            hold_last_q <= 1'b0;
            ones_q <= 3'd0;
            level_q <= 1'b0;
            flush_q <= 1'b0;
            cnt_q <= '0;
            tx_done <= 1'b0;
            tx_underrun <= 1'b0;
            usb_dp_out <= 1'b0;
            usb_dn_out <= 1'b1;
            usb_oe <= 1'b0;
        end else begin
            tx_done <= 1'b0;
            tx_underrun <= 1'b0;
            acc_q <= tick ? acc_sum - WRAP : acc_sum;
            if (flush_q && take && tx_last) flush_q <= 1'b0;
            // the holding register: filled by the stream while the packet is being sent
            if (take && !flush_q && st_q == S_DATA) begin
                hold_q <= tx_data;
                hold_valid_q <= 1'b1;
                hold_last_q <= tx_last;
            end
            case (st_q)
                S_IDLE: begin
                    acc_q <= ACC0;     // the SOP is boundary 0
                    if (start_reset) begin
                        st_q <= S_RESET;
                        cnt_q <= reset_clks;
                        drive_se0();
                    end else if (start_eop) begin
                        st_q <= S_EOP;
                        cnt_q <= 1;
                        drive_se0();
                    end else if (start_pkt) begin
                        // the SYNC is the byte 8'h80 (seven 0s, then a 1); its bit 0 goes out now
                        st_q <= S_DATA;
                        shift_q <= 8'h80;
                        bitn_q <= 4'd1;
                        cur_last_q <= 1'b0;
                        hold_q <= tx_data;
                        hold_valid_q <= 1'b1;
                        hold_last_q <= tx_last;
                        ones_q <= 3'd0;
                        level_q <= 1'b1;
                        drive_level(1'b1);
                    end
                end
                S_DATA: if (tick) begin
                    if (stuff) begin
                        level_q <= !level_q;
                        ones_q <= 3'd0;
                        drive_level(!level_q);
                    end else if (bitn_q == 4'd8) begin
                        if (cur_last_q) begin
                            st_q <= S_EOP;
                            cnt_q <= 1;
                            drive_se0();
                        end else if (hold_valid_q) begin
                            shift_q <= next_byte;
                            cur_last_q <= hold_last_q;
                            hold_valid_q <= 1'b0;
                            bitn_q <= 4'd1;
                            if (next_byte[0]) begin
                                ones_q <= ones_q + 1'b1;
                            end else begin
                                ones_q <= 3'd0;
                                level_q <= !level_q;
                            end
                            drive_level(next_byte[0] ? level_q : !level_q);
                        end else begin
                            // underrun: a 1 now and six more, with no stuffed 0 between; a
                            // byte arriving in this very clock is too late: the flush drops it
                            st_q <= S_ABORT;
                            cnt_q <= 6;
                            hold_valid_q <= 1'b0;
                            flush_q <= !(take && tx_last);
                            tx_underrun <= 1'b1;
                            drive_level(level_q);
                        end
                    end else begin
                        bitn_q <= bitn_q + 1'b1;
                        if (shift_q[bitn_q[2:0]]) begin
                            ones_q <= ones_q + 1'b1;
                        end else begin
                            ones_q <= 3'd0;
                            level_q <= !level_q;
                        end
                        drive_level(shift_q[bitn_q[2:0]] ? level_q : !level_q);
                    end
                end
                S_ABORT: if (tick) begin
                    if (cnt_q == 0) begin
                        st_q <= S_EOP;
                        cnt_q <= 1;
                        drive_se0();
                    end else begin
                        cnt_q <= cnt_q - 1'b1;
                        drive_level(level_q);
                    end
                end
                S_EOP: if (tick) begin     // SE0 for two bit times, then J
                    if (cnt_q != 0) begin
                        cnt_q <= cnt_q - 1'b1;
                        drive_se0();
                    end else begin
                        st_q <= S_EOPJ;
                        drive_level(1'b0);
                    end
                end
                S_EOPJ: if (tick) begin    // J for one bit time, then release
                    st_q <= S_IDLE;
                    hold_valid_q <= 1'b0;
                    tx_done <= 1'b1;
                    usb_dp_out <= 1'b0;
                    usb_dn_out <= 1'b1;
                    usb_oe <= 1'b0;
                end
                S_RESET: begin             // counted in clocks; then a J bit on a fresh bit timer
                    acc_q <= ACC0;
                    if (cnt_q <= 1) begin
                        st_q <= S_EOPJ;
                        drive_level(1'b0);
                    end else begin
                        cnt_q <= cnt_q - 1'b1;
                    end
                end
                default: st_q <= S_IDLE;
            endcase
        end
    end
`ifdef FORMAL
    // ---- formal properties (tests/formal/usb_ls_tx.sby, with the stream's rules in
    // usb_ls_tx_check.sv). An observer rebuilds what the line must carry from the stream's
    // handshakes alone (the bytes taken, in order) and the outputs (the symbol after each bit
    // boundary), and checks it: the SYNC, each data bit in NRZI, a stuffed 0 after six 1s and only
    // there, the EOP's two bit times of SE0 and one of J, the release; each bit floor or ceil of
    // SYS_HZ / 1.5 MHz clocks. The invariants tie the observer to the module's registers. ----
    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;
    wire f_se0 = usb_oe && !usb_dp_out && !usb_dn_out;
    wire f_k = usb_oe && usb_dp_out && !usb_dn_out;
    wire f_j = usb_oe && !usb_dp_out && usb_dn_out;
    localparam integer F_LO = MOD / INC, F_HI = (MOD + INC - 1) / INC;   // a bit's clocks

    // clocks since the last bit boundary (or the first symbol)
    reg [7:0] f_clks = 8'd0;
    always @(posedge clk) f_clks <= (rst || st_q == S_IDLE || st_q == S_RESET || tick) ? 8'd0 : f_clks + 1'b1;

    // a reset: the clocks asked for, the clocks of SE0 so far
    reg [RESET_W-1:0] f_rst_len = '0, f_rst_clks = '0;
    always @(posedge clk) begin
        if (start_reset) begin
            f_rst_len <= reset_clks;
            f_rst_clks <= '0;
        end else if (st_q == S_RESET) begin
            f_rst_clks <= f_rst_clks + 1'b1;
        end
    end
    always @(*) if (f_past_valid && !rst && st_q == S_RESET) assert(f_rst_clks + cnt_q == f_rst_len && cnt_q != 0);

    // the observer: bytes taken (the SYNC's 8'h80 first), bits sent, 1s in a row, the line level
    reg [7:0] f_cur = 8'd0, f_next = 8'd0;
    reg       f_cur_last = 1'b0, f_next_valid = 1'b0, f_next_last = 1'b0;
    reg [3:0] f_bit = 4'd0;
    reg [2:0] f_run = 3'd0;
    reg       f_level = 1'b0;
    reg       f_data_tick = 1'b0;      // the previous clock was a bit boundary in S_DATA
    reg [1:0] f_se0_bits = 2'd0;       // bit boundaries in S_EOP so far
    always @(posedge clk) f_data_tick <= !rst && tick && st_q == S_DATA;
    wire f_line_bit = usb_dp_out == f_level;     // NRZI: no change is a 1
    // the observer moves to the next byte (it takes the first bit of f_next in)
    wire f_consume = f_data_tick && !f_se0 && st_q == S_DATA && f_run != 3'd6 && f_bit == 4'd8;
    always @(posedge clk) begin
        if (rst) begin
            f_next_valid <= 1'b0;
        end else begin
            if (start_pkt) begin
                f_cur <= 8'h80;
                f_bit <= 4'd1;
                f_run <= 3'd0;
                f_level <= 1'b1;
                f_cur_last <= 1'b0;
                f_next <= tx_data;
                f_next_last <= tx_last;
                f_next_valid <= 1'b1;
            end
            if (f_data_tick && !f_se0 && st_q == S_DATA) begin
                f_level <= usb_dp_out;
                if (f_run == 3'd6) begin
                    f_run <= 3'd0;                         // the stuffed 0
                end else begin
                    f_run <= f_line_bit ? f_run + 1'b1 : 3'd0;
                    if (f_bit == 4'd8) begin
                        f_cur <= f_next;
                        f_cur_last <= f_next_last;
                        f_bit <= 4'd1;
                    end else begin
                        f_bit <= f_bit + 1'b1;
                    end
                end
            end
            // a byte taken while the one before moves on (f_consume) waits in its place
            if (!start_pkt && take && !flush_q && st_q == S_DATA) begin
                f_next <= tx_data;
                f_next_last <= tx_last;
                f_next_valid <= 1'b1;
            end else if (f_consume) begin
                f_next_valid <= 1'b0;
            end
            if (st_q != S_EOP) f_se0_bits <= 2'd0;
            else if (tick) f_se0_bits <= f_se0_bits + 1'b1;
        end
    end
    wire [7:0] f_byte = f_bit == 4'd8 ? f_next : f_cur;          // the byte of the bit just sent
    wire [2:0] f_idx = f_bit == 4'd8 ? 3'd0 : f_bit[2:0];

    always @(*) begin
        if (f_past_valid && !rst) begin
            // the outputs by state: released in idle, a data level in a packet, SE0, J
            case (st_q)
                S_IDLE:          begin assert(!usb_oe && !hold_valid_q); end
                S_DATA, S_ABORT: begin assert((f_k || f_j) && usb_dp_out == level_q); end
                S_EOP, S_RESET:  begin assert(f_se0); end
                S_EOPJ:          begin assert(f_j); end
                default:         begin assert(1'b0); end
            endcase
            assert(acc_q < WRAP && ones_q <= 3'd6);
            if (st_q == S_DATA) assert(bitn_q >= 4'd1 && bitn_q <= 4'd8);
            // the bit timer: acc_q is f_clks steps past the last boundary's remainder (< STEP)
            if (st_q != S_IDLE && st_q != S_RESET)
                assert({8'd0, acc_q} >= {{ACC_W{1'b0}}, f_clks} * STEP
                       && {8'd0, acc_q} - {{ACC_W{1'b0}}, f_clks} * STEP < {8'd0, STEP});
            // the observer and the registers agree while a packet's data goes out (but in the
            // clock after a bit boundary, when the observer takes the new symbol in)
            if (st_q == S_DATA && !f_data_tick) begin
                assert(f_cur == shift_q && f_bit == bitn_q && f_run == ones_q && f_level == level_q
                       && f_cur_last == cur_last_q && f_next_valid == hold_valid_q);
                if (hold_valid_q) assert(f_next == hold_q && f_next_last == hold_last_q && !cur_last_q);
            end
            if (st_q != S_DATA) assert(!hold_valid_q);
            if (st_q == S_EOP) assert(cnt_q <= 1 && {1'b0, f_se0_bits} + cnt_q[1:0] == 2'd1);
            if (st_q == S_ABORT) assert(cnt_q <= 6);
            if (flush_q) assert(st_q == S_IDLE || st_q == S_ABORT || st_q == S_EOP || st_q == S_EOPJ);
            // the stream: one byte ahead at most, none after the packet's last
            if (take && !flush_q && st_q == S_DATA)
                assert((!f_next_valid || (f_consume && !f_next_last)) && !f_cur_last);
        end
    end
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst) && !rst) begin
            // each bit lasts floor or ceil of MOD / INC clocks
            if ($past(tick)) assert($past(f_clks) + 1 >= F_LO && $past(f_clks) + 1 <= F_HI);
            // a packet starts with the SYNC's first K
            if ($past(start_pkt)) assert(f_k);
            // after a data bit boundary: a stuffed 0 after six 1s, else the next data bit, or the
            // EOP's SE0 once the last byte is out (and its run of six 1s stuffed), or an underrun
            if ($past(tick && st_q == S_DATA)) begin
                if ($past(ones_q) == 3'd6) assert(!f_se0 && !f_line_bit);
                else if ($past(bitn_q == 4'd8 && cur_last_q)) assert(f_se0);
                else if (!tx_underrun) assert(!f_se0 && f_line_bit == f_byte[f_idx]);
            end
            // the EOP: SE0 for two bit boundaries, then J for one, then released
            if ($past(st_q == S_EOP && tick)) assert($past(f_se0_bits) == 2'd1 ? f_j : f_se0);
            if ($past(st_q == S_EOPJ && tick)) assert(!usb_oe && tx_done);
            // a reset's SE0: reset_clks clocks, then the J
            if ($past(st_q == S_RESET) && st_q != S_RESET) assert(f_rst_clks == f_rst_len && f_j);
        end
    end

    // Covers: a stuffed bit at a byte boundary, a packet's end, an underrun, a reset's end.
    always @(posedge clk) begin
        cover(f_past_valid && st_q == S_DATA && tick && stuff && bitn_q == 4'd8);
        cover(f_past_valid && tx_done && !flush_q && cur_last_q);
        cover(f_past_valid && tx_underrun);
        cover(f_past_valid && st_q == S_RESET && cnt_q == 1);
    end
`endif
endmodule

`default_nettype wire
