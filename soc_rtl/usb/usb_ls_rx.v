// usb_ls_rx: the USB 1.1 low-speed host's receiver (the line layer): the bus's D+/D- in, the
// line state, and a packet's bytes out with its start, its end and its errors; the bit times since
// the last EOP, for the transaction layer's turnaround timeout. One clock (clk at SYS_HZ).
//
// Contract (line): usb_dp_in, usb_dn_in are asynchronous; each goes through two flops (rx_line is
// {D+, D-} after them: 2'b01 J, 2'b10 K, 2'b00 SE0, 2'b11 SE1). The bits are sampled by a digital
// PLL on the synchronised D+: every D+ transition restarts the bit timer so that the next sample
// falls half a bit later, then one every bit time (SYS_HZ / 1.5 MHz clocks, the same fractional
// step as usb_ls_tx). Between transitions there are at most 7 bit times (six 1s and a stuffed 0),
// so a device at +-1.5 % (TLSDRATE, 1.4775 to 1.5225 Mb/s) moves the 7th sample by 0.1 bit; the
// samples stay inside the bit for any transition displaced by less than about a third of a bit
// (the receiver jitter a host must take, TDJR1 +-152 ns, TDJR2 +-200 ns, is 0.23 and 0.30 bit).
// The SE0 that D+ and D- show during a differential transition (TLST, at most 210 ns) is never
// sampled (it is at the bit's edge, the sample in its middle); an SE0 counts for the EOP's end
// (rx_idle_bits) only when it has lasted half a bit (330 ns must be rejected as an EOP, 670 ns
// accepted: TLEOPR).
// Contract (packets): in idle, D+ rising (idle J to K) is a start of packet. The SYNC is decoded
// (NRZI: no transition is a 1): at least 3 0s, then a 1 (KJKJKJKK: seven 0s and a 1); rx_start
// pulses with its last bit, then the bits are destuffed (after six 1s, counted from the SYNC's
// last 1, a 0 is dropped) and assembled LSB first: each byte pulses rx_valid with rx_data. A
// packet's end pulses rx_end once for every rx_start (never without one), with the error flags
// valid in that clock (all clear: a good packet):
//   rx_err_stuff  a 1 where a stuffed 0 was due (seven 1s), or the EOP right after six 1s (the
//                 transmitter must stuff the last bit too, 7.1.9);
//   rx_err_align  the EOP (an SE0 sampled, then a J) after a number of bits that is not a
//                 multiple of 8 (the partial byte is dropped);
//   rx_err_se0    an SE0 not followed by J: a K after it, or SE0 for a fourth bit time (a reset or
//                 a detach, not an EOP), or the host starting to drive (tx_active) mid-packet;
//   rx_err_long   a byte beyond MAX_BYTES (it is not delivered; the packet ends there).
// After an error the receiver waits for the line to be idle (an EOP, or 8 bit times of J) before
// it looks for a start of packet again. A SYNC that is not one (a 1 too early, an SE0) is no
// packet: no rx_start, the receiver waits for idle. rx_babble is high while the line has not been
// idle for more than BABBLE_BITS bit times since a start of packet (a device talking past any
// legal packet, or a line stuck in K); it falls when the line is idle again.
// Contract (own transmission): the receiver is gated by the caller: tx_active (connect usb_ls_tx's
// usb_oe) high means the host drives the lines, and no start of packet is looked for (a packet in
// progress ends with rx_err_se0). The line state and rx_idle_bits keep running, so the host's own
// EOP restarts rx_idle_bits. The synchronisers delay the host's own drive by two clocks, which are
// J after its EOP: nothing is decoded from them.
// Contract (timing): rx_idle_bits counts the bit times since the last EOP's SE0-to-J transition (an
// SE0 of half a bit or more, then J), while the line has stayed J since (0 otherwise, saturating at
// 2^IDLE_W - 1; saturated after reset); it starts within 3 clocks of the transition on the pins (the
// synchroniser). rx_timeout pulses once when it reaches TIMEOUT_BITS: the host's turnaround
// timeout, which must be no less than 16 and no more than 18 bit times from the SE0-to-J of the
// EOP (8.7.2); the default 17 is 17 bit times plus at most 3 clocks (0.09 bit at 50 MHz). Latency:
// rx_start, rx_valid and rx_end come at the sample of the bit that completes them, half a bit
// (plus the synchroniser's 2 clocks) after that bit began on the pins.
`default_nettype none

module usb_ls_rx #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,       // clk's frequency, Hz
    parameter integer MAX_BYTES = usb_pkg::LS_MAX_PACKET_BYTES,    // longest packet delivered, PID and CRC included
    // rx_babble after this many bit times without idle from a start of packet: the longest packet
    // (SYNC, MAX_BYTES with every 7th bit stuffed, EOP) and a margin of 32
    parameter integer BABBLE_BITS = 8 + (MAX_BYTES * 8 * 7 + 5) / 6 + 3 + 32,
    parameter integer TIMEOUT_BITS = 17,                           // rx_timeout: 16 to 18 (8.7.2)
    parameter integer IDLE_W = 8,                                  // rx_idle_bits' width
    localparam integer G = usb_pkg::gcd(SYS_HZ, usb_pkg::USB_LS_BIT_HZ),
    localparam integer INC = usb_pkg::USB_LS_BIT_HZ / G,
    localparam integer MOD = SYS_HZ / G,
    localparam integer ACC_W = $clog2(2 * MOD + 2 * INC),
    localparam integer NB_W = $clog2(MAX_BYTES + 1),
    localparam integer BAB_W = $clog2(BABBLE_BITS + 2),
    localparam integer SE0_CLKS = (MOD + 2 * INC - 1) / (2 * INC),  // half a bit, rounded up
    localparam integer SE0_W = $clog2(SE0_CLKS + 1)
) (
    input  wire              clk,
    input  wire              rst,           // synchronous, active high
    // the bus (asynchronous)
    input  wire              usb_dp_in,
    input  wire              usb_dn_in,
    input  wire              tx_active,     // the host drives the lines (usb_ls_tx's usb_oe)
    // line state
    output wire [1:0]        rx_line,       // {D+, D-} synchronised: 01 J, 10 K, 00 SE0
    output reg  [IDLE_W-1:0] rx_idle_bits,  // bit times since the last EOP, the line J since
    output reg               rx_timeout,    // one clock: rx_idle_bits reached TIMEOUT_BITS
    output reg               rx_babble,     // no idle for BABBLE_BITS bit times since a SOP
    // packets
    output reg               rx_start,      // one clock: a SYNC was received
    output reg               rx_valid,      // one clock: rx_data is the packet's next byte
    output reg  [7:0]        rx_data,
    output reg               rx_end,        // one clock: the packet ended; the flags below valid
    output reg               rx_err_stuff,
    output reg               rx_err_align,
    output reg               rx_err_se0,
    output reg               rx_err_long
);
    generate if (!usb_pkg::ls_sys_hz_ok(SYS_HZ) || TIMEOUT_BITS < 1
                 || TIMEOUT_BITS >= (1 << IDLE_W) - 1) begin : g_bad
        $error("usb_ls_rx: SYS_HZ not accepted (usb_pkg::ls_sys_hz_ok), or TIMEOUT_BITS out of rx_idle_bits' range");
    end endgenerate

    localparam integer STEP_I = 2 * INC, WRAP_I = 2 * MOD;
    localparam [ACC_W-1:0] STEP = STEP_I[ACC_W-1:0];
    localparam [ACC_W-1:0] WRAP = WRAP_I[ACC_W-1:0];
    localparam [ACC_W-1:0] HALF = MOD[ACC_W-1:0];           // after a transition: the sample half a bit on
    localparam [IDLE_W-1:0] IDLE_MAX = {IDLE_W{1'b1}};
    localparam integer TIMEOUT_M1_I = TIMEOUT_BITS - 1, BAB_MAX_I = BABBLE_BITS + 1;
    localparam [IDLE_W-1:0] TIMEOUT_M1 = TIMEOUT_M1_I[IDLE_W-1:0];
    localparam [BAB_W-1:0] BAB_LIMIT = BABBLE_BITS[BAB_W-1:0], BAB_MAX = BAB_MAX_I[BAB_W-1:0];
    localparam [NB_W-1:0] NB_MAX = MAX_BYTES[NB_W-1:0];

    // ---- synchroniser and line state ----
    reg [1:0] dp_sync_q, dn_sync_q;     // [1]: the synchronous line
    reg       dp_prev_q;                // D+ one clock before: its transitions drive the PLL
    always @(posedge clk) begin
        if (rst) begin
            dp_sync_q <= 2'b00;
            dn_sync_q <= 2'b00;
            dp_prev_q <= 1'b0;
        end else begin
            dp_sync_q <= {dp_sync_q[0], usb_dp_in};
            dn_sync_q <= {dn_sync_q[0], usb_dn_in};
            dp_prev_q <= dp_sync_q[1];
        end
    end
    wire dp = dp_sync_q[1], dn = dn_sync_q[1];
    assign rx_line = {dp, dn};
    wire line_j = !dp && dn;
    wire line_se0 = !dp && !dn;
    wire dp_edge = dp != dp_prev_q;

    // ---- the DPLL: a sample in the middle of every bit ----
    reg [ACC_W-1:0] acc_q;
    wire [ACC_W-1:0] acc_sum = acc_q + STEP;
    wire sample = !dp_edge && acc_sum >= WRAP;
    always @(posedge clk) begin
        if (rst) acc_q <= '0;
        else if (dp_edge) acc_q <= HALF;
        else acc_q <= sample ? acc_sum - WRAP : acc_sum;
    end

    // ---- packets ----
    localparam [2:0] R_IDLE = 3'd0, R_SYNC = 3'd1, R_DATA = 3'd2, R_EOP = 3'd3, R_WAIT = 3'd4;
    reg [2:0]       st_q;
    reg             prev_k_q;       // the last sampled level, 1 K (for NRZI)
    reg [2:0]       zeros_q;        // SYNC 0s, saturating at 7
    reg [2:0]       ones_q;         // consecutive 1s, 0..6
    reg [2:0]       bitn_q;         // bits of the byte being assembled
    reg [6:0]       shift_q;        // the byte's bits so far, the latest in bit 6
    reg [NB_W-1:0]  nbytes_q;
    reg [1:0]       se0n_q;         // SE0 samples of the EOP
    reg             eop_stuff_q, eop_align_q;   // the EOP's flags, given with its J
    reg [3:0]       jn_q;           // J samples in a row while waiting for idle
    reg [BAB_W-1:0] busy_bits_q;    // bit times since the SOP without idle
    wire bit_k = dp;                // the sampled level (SE0 is tested apart)
    wire nrzi_one = bit_k == prev_k_q;
    wire [7:0] byte_now = {nrzi_one, shift_q};

    always @(posedge clk) begin
        if (rst) begin
            st_q <= R_IDLE;
            prev_k_q <= 1'b0;
            zeros_q <= 3'd0;
            ones_q <= 3'd0;
            bitn_q <= 3'd0;
            shift_q <= 7'd0;
            nbytes_q <= '0;
            se0n_q <= 2'd0;
            eop_stuff_q <= 1'b0;
            eop_align_q <= 1'b0;
            jn_q <= 4'd0;
            busy_bits_q <= '0;
            rx_babble <= 1'b0;
            rx_start <= 1'b0;
            rx_valid <= 1'b0;
            rx_data <= 8'd0;
            rx_end <= 1'b0;
            rx_err_stuff <= 1'b0;
            rx_err_align <= 1'b0;
            rx_err_se0 <= 1'b0;
            rx_err_long <= 1'b0;
        end else begin
            rx_start <= 1'b0;
            rx_valid <= 1'b0;
            rx_end <= 1'b0;
            rx_err_stuff <= 1'b0;
            rx_err_align <= 1'b0;
            rx_err_se0 <= 1'b0;
            rx_err_long <= 1'b0;
            // babble: bit times since the SOP while not back in idle
            if (st_q == R_IDLE) busy_bits_q <= '0;
            else if (sample && busy_bits_q != BAB_MAX) busy_bits_q <= busy_bits_q + 1'b1;
            rx_babble <= st_q != R_IDLE && busy_bits_q > BAB_LIMIT;
            if (tx_active) begin
                // the host drives: no SOP; a packet in progress ends
                st_q <= R_IDLE;
                if (st_q == R_DATA || st_q == R_EOP) begin
                    rx_end <= 1'b1;
                    rx_err_se0 <= 1'b1;
                end
            end else case (st_q)
                R_IDLE: begin
                    if (dp_edge && dp) begin           // idle J to K: a start of packet
                        st_q <= R_SYNC;
                        prev_k_q <= 1'b0;
                        zeros_q <= 3'd0;
                    end
                end
                R_SYNC: if (sample) begin
                    prev_k_q <= bit_k;
                    if (line_se0) begin
                        st_q <= R_WAIT;            // SE0: not a SYNC
                        jn_q <= 4'd0;
                        se0n_q <= 2'd1;
                    end else if (!nrzi_one) begin
                        if (zeros_q != 3'd7) zeros_q <= zeros_q + 1'b1;
                    end else if (zeros_q >= 3'd3) begin
                        st_q <= R_DATA;
                        rx_start <= 1'b1;
                        ones_q <= 3'd1;            // the SYNC's last 1 starts the count
                        bitn_q <= 3'd0;
                        nbytes_q <= '0;
                    end else begin
                        st_q <= R_WAIT;            // a 1 too early: not a SYNC
                        jn_q <= 4'd0;
                        se0n_q <= 2'd0;
                    end
                end
                R_DATA: if (sample) begin
                    prev_k_q <= bit_k;
                    if (line_se0) begin
                        st_q <= R_EOP;
                        se0n_q <= 2'd1;
                        eop_stuff_q <= ones_q == 3'd6;
                        eop_align_q <= bitn_q != 3'd0;
                    end else if (ones_q == 3'd6) begin
                        if (nrzi_one) begin        // seven 1s
                            st_q <= R_WAIT;
                            jn_q <= 4'd0;
                            se0n_q <= 2'd0;
                            rx_end <= 1'b1;
                            rx_err_stuff <= 1'b1;
                        end else begin
                            ones_q <= 3'd0;        // the stuffed 0, dropped
                        end
                    end else begin
                        ones_q <= nrzi_one ? ones_q + 1'b1 : 3'd0;
                        shift_q <= byte_now[7:1];
                        bitn_q <= bitn_q + 1'b1;
                        if (bitn_q == 3'd7) begin
                            if (nbytes_q == NB_MAX) begin
                                st_q <= R_WAIT;
                                jn_q <= 4'd0;
                                se0n_q <= 2'd0;
                                rx_end <= 1'b1;
                                rx_err_long <= 1'b1;
                            end else begin
                                nbytes_q <= nbytes_q + 1'b1;
                                rx_valid <= 1'b1;
                                rx_data <= byte_now;
                            end
                        end
                    end
                end
                R_EOP: if (sample) begin
                    prev_k_q <= bit_k;
                    if (line_j) begin              // SE0 then J: the EOP
                        st_q <= R_IDLE;
                        rx_end <= 1'b1;
                        rx_err_stuff <= eop_stuff_q;
                        rx_err_align <= eop_align_q;
                    end else if (!line_se0 || se0n_q == 2'd3) begin
                        st_q <= R_WAIT;            // SE0 then K, or SE0 too long
                        jn_q <= 4'd0;
                        se0n_q <= {1'b0, line_se0};   // waiting: the last sample was an SE0
                        rx_end <= 1'b1;
                        rx_err_se0 <= 1'b1;
                    end else begin
                        se0n_q <= se0n_q + 1'b1;
                    end
                end
                R_WAIT: if (sample) begin          // wait for idle: an SE0's J, or 8 bit times of J
                    // (se0n_q: the previous sample was an SE0)
                    prev_k_q <= bit_k;
                    if (line_j) begin
                        if (se0n_q != 2'd0 || jn_q == 4'd7) st_q <= R_IDLE;
                        else jn_q <= jn_q + 1'b1;
                    end else begin
                        jn_q <= 4'd0;
                    end
                    se0n_q <= line_se0 ? 2'd1 : 2'd0;
                end
                default: st_q <= R_IDLE;
            endcase
        end
    end

    // ---- bit times since the last EOP (the turnaround timer) ----
    reg [SE0_W-1:0] se0_run_q;      // clocks of SE0 so far, saturating at SE0_CLKS
    reg             counting_q;     // an EOP's J was seen and the line has stayed J since
    reg [ACC_W-1:0] idle_acc_q;
    wire [ACC_W-1:0] idle_sum = idle_acc_q + STEP;
    wire eop_j = line_j && se0_run_q == SE0_CLKS[SE0_W-1:0];
    always @(posedge clk) begin
        if (rst) begin
            se0_run_q <= '0;
            counting_q <= 1'b0;
            idle_acc_q <= '0;
            rx_idle_bits <= IDLE_MAX;
            rx_timeout <= 1'b0;
        end else begin
            rx_timeout <= 1'b0;
            if (line_se0) begin
                if (se0_run_q != SE0_CLKS[SE0_W-1:0]) se0_run_q <= se0_run_q + 1'b1;
            end else begin
                se0_run_q <= '0;
            end
            if (eop_j) begin
                counting_q <= 1'b1;
                idle_acc_q <= '0;
                rx_idle_bits <= '0;
            end else if (!line_j) begin
                counting_q <= 1'b0;
                rx_idle_bits <= '0;
            end else if (counting_q) begin
                idle_acc_q <= idle_sum >= WRAP ? idle_sum - WRAP : idle_sum;
                if (idle_sum >= WRAP && rx_idle_bits != IDLE_MAX) begin
                    rx_idle_bits <= rx_idle_bits + 1'b1;
                    if (rx_idle_bits == TIMEOUT_M1) rx_timeout <= 1'b1;
                end
            end
        end
    end
endmodule

`default_nettype wire
