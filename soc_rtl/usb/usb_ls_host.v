// usb_ls_host: a USB 1.1 low-speed host for one HID boot keyboard on one port (issue #28): the
// port (attach, reset, keep-alive, detach, babble), the frame schedule, enumeration, the interrupt
// endpoint's polling, and the key events; on the line layer (usb_ls_tx, usb_ls_rx), the packet
// layer (usb_ls_packet_tx, usb_ls_packet_rx), the transaction layer (usb_ls_xfer) and the report
// decoder (usb_hid_keys). One clock, clk at SYS_HZ. docs/usb.md has the argument and the sources.
//
// Contract (port): enable low: nothing driven, the host held in reset (the counters kept). With
// enable: detached until the line is J (a low-speed device's pull-up on D-); J steady for TATTDB
// (100 ms: 101 frame ticks) is an attach (cnt_attach); then a bus reset (SE0 for RESET_MS, 20 ms:
// TDRST >= 10 ms), then keep-alives and the reset recovery (TRSTRCY 10 ms: 11 ticks), then
// enumeration. Detach: SE0 for more than 2.5 us (TDETRST) while the host does not drive (a device's
// EOP has 1.33 us): cnt_detach, back to detached, the keys held are released. Babble (usb_ls_rx's
// rx_babble: the device still talking BABBLE_BITS after its SOP) disables the port: nothing driven
// until a detach, then a re-attach as above. A detach and not a re-enumeration, because a babbling
// device would babble again, and keep-alives sent over it could collide with it; a disabled port
// waits for the user to replug it, as a hub's port does.
// Contract (frames): a keep-alive (a bare EOP) every FRAME_CLKS = SYS_HZ / 1000 clocks (1 ms, exact
// at 50 MHz: TFRAME's +-0.05 % holds for any SYS_HZ above 2 MHz) while the port is enabled; a
// transaction attempt starts only before the frame's last ATTEMPT_BITS bit times, so it
// ends before the next keep-alive (usb_ls_xfer's worst attempt: a token, 2 bit times, an 8-byte
// DATA, the 160-bit wait, the handshake: under ATTEMPT_BITS = 340 bit times, 231 us at 50 MHz).
// Contract (enumeration): a ROM of control requests, in order (the argument for a ROM over an FSM:
// the steps differ only in their 8 SETUP bytes and in what is kept from the answer): GET_DESCRIPTOR
// (device, 8) at address 0; SET_ADDRESS(DEV_ADDR) then 2 ms (3 ticks); GET_DESCRIPTOR(device, 18);
// GET_DESCRIPTOR(configuration, 9) for wTotalLength; GET_DESCRIPTOR(configuration, min(wTotalLength,
// CFG_MAX)) parsed as it arrives for the first interface of class 3, subclass 1, protocol 1 and its
// first interrupt IN endpoint (address, wMaxPacketSize, bInterval); none: state S_NOKBD until a
// detach (keep-alives go on); SET_CONFIGURATION(bConfigurationValue); SET_PROTOCOL(boot) and SET_IDLE(0) to that
// interface, each of these two tolerating a STALL. A control transfer: SETUP (DATA0), the data
// stage IN from DATA1 until wLength bytes or a short packet, the status stage (OUT or IN, DATA1).
// A NAK is retried in the next frame. A failed transaction (usb_ls_xfer's retries spent) or any
// other STALL: a bus reset and the enumeration again.
// Contract (polling): IN to the keyboard's endpoint every max(bInterval, 8) frames, from DATA0 after
// SET_CONFIGURATION; a new DATA goes to usb_hid_keys (rpt_*), a repeated one is dropped; NAK: the
// next interval; STALL: CLEAR_FEATURE(ENDPOINT_HALT) and the toggle back to DATA0; a failure: reset
// and enumeration.
// Contract (status): state (S_*), dev_addr, and saturating 16-bit counters (cnt_*), from rst.
`default_nettype none

module usb_ls_host #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // clk's frequency, Hz
    parameter [6:0]   DEV_ADDR = 7'd1,       // the address given to the keyboard
    parameter integer CFG_MAX = 128,         // configuration bytes read at most (the rest ignored)
    parameter integer FIFO_DEPTH = 16,       // key events buffered (usb_hid_keys)
    parameter integer ATTACH_MS = 101,       // TATTDB 100 ms, whole frame ticks after the first J
    parameter integer RESET_MS = 20,         // bus reset SE0 (TDRST >= 10 ms)
    parameter integer RECOVERY_MS = 11,      // TRSTRCY 10 ms in ticks
    parameter integer ADDR_RECOVERY_MS = 3,  // SET_ADDRESS recovery 2 ms in ticks
    parameter integer ATTEMPT_BITS = 340,    // the longest transaction attempt (see above)
    localparam integer FRAME_CLKS = SYS_HZ / 1000,
    localparam integer FR_W = $clog2(FRAME_CLKS),
    localparam integer BIT_CLKS = (SYS_HZ + usb_pkg::USB_LS_BIT_HZ - 1) / usb_pkg::USB_LS_BIT_HZ,
    localparam integer SLOT_END = FRAME_CLKS - ATTEMPT_BITS * BIT_CLKS,
    localparam integer RESET_CLKS = RESET_MS * FRAME_CLKS,
    localparam integer DETACH_CLKS = (SYS_HZ / 400_000) + 2,   // 2.5 us and a synchroniser's margin
    localparam integer DT_W = $clog2(DETACH_CLKS + 1)
) (
    input  wire        clk,
    input  wire        rst,            // synchronous, active high
    input  wire        enable,         // 0: the port left alone (nothing driven), the host reset
    // the bus
    input  wire        usb_dp_in,      // asynchronous
    input  wire        usb_dn_in,
    output wire        usb_dp_out,
    output wire        usb_dn_out,
    output wire        usb_oe,
    // key events
    output wire        ev_valid,
    input  wire        ev_ready,
    output wire        ev_press,       // 1 press, 0 release
    output wire [7:0]  ev_usage,       // Keyboard/Keypad usage; 0xE0..0xE7 the modifiers
    // status
    output reg  [2:0]  state,          // S_DETACHED .. S_BABBLE
    output reg  [6:0]  dev_addr,       // the keyboard's address (0 until SET_ADDRESS)
    output reg  [15:0] cnt_crc,        // corrupted answers (CRC, PID, length, line errors)
    output reg  [15:0] cnt_timeout,    // no answer (turnaround timeout)
    output reg  [15:0] cnt_retry,
    output reg  [15:0] cnt_nak,
    output reg  [15:0] cnt_stall,
    output reg  [15:0] cnt_attach,
    output reg  [15:0] cnt_detach,
    output reg  [15:0] cnt_wrong_len,  // reports not 8 bytes
    output reg  [15:0] cnt_overflow,   // key events lost to a full FIFO
    output reg  [15:0] cnt_reenum,     // resets after a failed transfer or an unexpected STALL
    output reg  [15:0] cnt_rollover,   // ErrorRollOver reports ignored
    output wire [7:0]  kbd_ep,         // the keyboard's interrupt IN endpoint (bEndpointAddress)
    output wire [7:0]  kbd_mps,        // its wMaxPacketSize (low byte)
    output wire [7:0]  kbd_interval    // its bInterval (ms; polled every max(bInterval, 8))
);
    localparam [2:0] S_DETACHED = 3'd0, S_ATTACHED = 3'd1, S_RESETTING = 3'd2, S_ENUM = 3'd3,
                     S_RUNNING = 3'd4, S_NOKBD = 3'd5, S_BABBLE = 3'd6;
    localparam [1:0] K_SETUP = 2'd0, K_IN = 2'd1, K_OUT = 2'd2;
    localparam [2:0] R_ACK = 3'd0, R_DATA = 3'd1, R_DUP = 3'd2, R_NAK = 3'd3, R_STALL = 3'd4,
                     R_FAIL = 3'd5;
    // enumeration steps (the ROM's index)
    localparam [3:0] E_DEV8 = 4'd0, E_ADDR = 4'd1, E_DEV18 = 4'd2, E_CFG9 = 4'd3, E_CFG = 4'd4,
                     E_SETCFG = 4'd5, E_PROTO = 4'd6, E_IDLE = 4'd7, E_CLRHALT = 4'd8;
    // control transfer stages
    localparam [2:0] C_SETUP = 3'd0, C_DIN = 3'd1, C_SOUT = 3'd2, C_SIN = 3'd3, C_NEXT = 3'd4,
                     C_POLL = 3'd5, C_WAIT = 3'd6;
    localparam [FR_W-1:0] FRAME_LAST = FRAME_CLKS[FR_W-1:0] - 1'b1;
    localparam [FR_W-1:0] SLOT_LAST = SLOT_END[FR_W-1:0];
    localparam [DT_W-1:0] DETACH_MAX = DETACH_CLKS[DT_W-1:0];
    localparam [7:0] CFG_LIMIT = CFG_MAX[7:0];
    localparam [6:0] T_ATTACH = ATTACH_MS[6:0], T_RECOVERY = RECOVERY_MS[6:0],
                     T_ADDR = ADDR_RECOVERY_MS[6:0];

    wire hrst = rst || !enable;

    // ---- the line and packet layers ----
    wire        tx_valid, tx_ready, tx_last, tx_idle, tx_done, tx_underrun;
    wire [7:0]  tx_data;
    reg         eop_start, reset_start;
    wire        cmd_valid, cmd_ready, pkt_busy, pl_valid, pl_ready;
    wire [3:0]  cmd_pid, cmd_endp, cmd_len;
    wire [6:0]  cmd_addr;
    wire [7:0]  pl_data;
    usb_ls_packet_tx #(.LEN_W(4)) u_ptx (
        .clk(clk), .rst(hrst),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_pid(cmd_pid), .cmd_addr(cmd_addr),
        .cmd_endp(cmd_endp), .cmd_len(cmd_len), .pkt_busy(pkt_busy),
        .pl_valid(pl_valid), .pl_ready(pl_ready), .pl_data(pl_data),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last)
    );
    localparam [23:0] RESET_CLKS_V = RESET_CLKS[23:0];
    usb_ls_tx #(.SYS_HZ(SYS_HZ)) u_tx (
        .clk(clk), .rst(hrst),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last),
        .eop_start(eop_start), .reset_start(reset_start), .reset_clks(RESET_CLKS_V),
        .tx_idle(tx_idle), .tx_done(tx_done), .tx_underrun(tx_underrun),
        .usb_dp_out(usb_dp_out), .usb_dn_out(usb_dn_out), .usb_oe(usb_oe)
    );
    wire       rx_start, rx_valid, rx_end, rx_err_stuff, rx_err_align, rx_err_se0, rx_err_long;
    wire       rx_timeout, rx_babble;
    wire [1:0] rx_line;
    wire [7:0] rx_data, rx_idle_bits;
    usb_ls_rx #(.SYS_HZ(SYS_HZ)) u_rx (
        .clk(clk), .rst(hrst),
        .usb_dp_in(usb_dp_in), .usb_dn_in(usb_dn_in), .tx_active(usb_oe),
        .rx_line(rx_line), .rx_idle_bits(rx_idle_bits), .rx_timeout(rx_timeout), .rx_babble(rx_babble),
        .rx_start(rx_start), .rx_valid(rx_valid), .rx_data(rx_data), .rx_end(rx_end),
        .rx_err_stuff(rx_err_stuff), .rx_err_align(rx_err_align), .rx_err_se0(rx_err_se0),
        .rx_err_long(rx_err_long)
    );
    wire       dat_valid, pkt_valid, pkt_ok, err_line, err_pid, err_len, err_crc;
    wire [7:0] dat_data;
    wire [3:0] pkt_pid, pkt_len;
    usb_ls_packet_rx u_prx (
        .clk(clk), .rst(hrst),
        .rx_start(rx_start), .rx_valid(rx_valid), .rx_data(rx_data), .rx_end(rx_end),
        .rx_err_stuff(rx_err_stuff), .rx_err_align(rx_err_align), .rx_err_se0(rx_err_se0),
        .rx_err_long(rx_err_long),
        .dat_valid(dat_valid), .dat_data(dat_data),
        .pkt_valid(pkt_valid), .pkt_pid(pkt_pid), .pkt_len(pkt_len), .pkt_ok(pkt_ok),
        .err_line(err_line), .err_pid(err_pid), .err_len(err_len), .err_crc(err_crc)
    );

    // ---- the transaction layer ----
    reg         xrst;               // abandon the transaction (not running, detach, babble)
    reg         req_valid;
    wire        req_ready;
    reg  [1:0]  req_kind;
    reg  [3:0]  req_endp;
    reg         req_toggle;
    reg  [3:0]  req_len;
    reg  [63:0] req_data;
    wire        slot_ok, x_busy, res_valid, ev_timeout, ev_bad, ev_retry;
    wire [2:0]  res_code;
    wire [3:0]  res_len;
    wire [63:0] res_data;
    usb_ls_xfer #(.SYS_HZ(SYS_HZ)) u_xfer (
        .clk(clk), .rst(hrst || xrst),
        .req_valid(req_valid), .req_ready(req_ready), .req_kind(req_kind), .req_addr(dev_addr),
        .req_endp(req_endp), .req_toggle(req_toggle), .req_len(req_len), .req_data(req_data),
        .slot_ok(slot_ok), .busy(x_busy),
        .res_valid(res_valid), .res_code(res_code), .res_len(res_len), .res_data(res_data),
        .ev_timeout(ev_timeout), .ev_bad(ev_bad), .ev_retry(ev_retry),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_pid(cmd_pid), .cmd_addr(cmd_addr),
        .cmd_endp(cmd_endp), .cmd_len(cmd_len), .pkt_busy(pkt_busy),
        .pl_valid(pl_valid), .pl_ready(pl_ready), .pl_data(pl_data),
        .tx_idle(tx_idle), .rx_line(rx_line), .rx_idle_bits(rx_idle_bits), .rx_timeout(rx_timeout),
        .rx_start(rx_start),
        .dat_valid(dat_valid), .dat_data(dat_data),
        .pkt_valid(pkt_valid), .pkt_pid(pkt_pid), .pkt_len(pkt_len), .pkt_ok(pkt_ok)
    );

    // ---- reports to keys ----
    reg         rpt_valid, rpt_clear;
    wire        rpt_ready, k_wrong_len, k_rollover, k_overflow;
    usb_hid_keys #(.FIFO_DEPTH(FIFO_DEPTH)) u_keys (
        .clk(clk), .rst(rst),
        .rpt_valid(rpt_valid), .rpt_ready(rpt_ready), .rpt_len(res_len), .rpt_data(res_data),
        .rpt_clear(rpt_clear || !enable),     // the keys held are released when the port is let go
        .ev_valid(ev_valid), .ev_ready(ev_ready), .ev_press(ev_press), .ev_usage(ev_usage),
        .ev_wrong_len(k_wrong_len), .ev_rollover(k_rollover), .ev_overflow(k_overflow)
    );

    // ---- frames ----
    reg [FR_W-1:0] frame_q;
    reg            ka_pend_q;       // a keep-alive is due
    wire           tick = frame_q == FRAME_LAST;
    wire           port_on = state == S_RESETTING && !rst_phase_q || state == S_ENUM
                          || state == S_RUNNING || state == S_NOKBD;
    assign slot_ok = port_on && !ka_pend_q && !eop_start && frame_q <= SLOT_LAST;

    // ---- port and sequencer state ----
    reg            rst_phase_q;     // S_RESETTING: the reset itself (1) or the recovery (0)
    reg            rst_sent_q;
    reg [6:0]      ms_q;            // frame ticks in the current wait
    reg [DT_W-1:0] se0_q;           // clocks of SE0 while the host does not drive
    reg [2:0]      oe_d_q;          // usb_oe delayed: the synchroniser's view of the host's drive
    reg [3:0]      step_q;          // enumeration step
    reg [2:0]      cst_q;           // control stage
    reg            tog_q;           // control data stage toggle
    reg [7:0]      got_q;           // data stage bytes received
    reg [7:0]      want_q;          // data stage bytes wanted (wLength)
    reg            nak_wait_q;      // a NAK: the next try after the next tick
    reg            req_sent_q;      // the current request has been handed to usb_ls_xfer
    reg [7:0]      total_q;         // configuration bytes to read
    // the configuration parser
    reg [7:0]      d_pos_q, d_len_q, d_type_q;
    reg            d_stop_q;
    reg [7:0]      cfg_val_q, if_num_q, if_class_q, if_sub_q, ep_addr_q;
    reg [1:0]      ep_attr_q;      // bmAttributes' transfer type
    reg            in_kbd_q, found_q;
    reg [7:0]      kbd_if_q, kbd_ep_q, kbd_mps_q, kbd_int_q, cur_if_q;
    reg [3:0]      walk_q;          // the received packet's bytes parsed so far
    reg            walking_q;
    reg [3:0]      walk_len_q;
    // polling
    reg            ep_tog_q;
    reg [7:0]      poll_q;          // frame ticks since the last poll
    assign kbd_ep = kbd_ep_q;
    assign kbd_mps = kbd_mps_q;
    assign kbd_interval = kbd_int_q;
    wire [7:0]     poll_int = kbd_int_q < 8'd8 ? 8'd8 : kbd_int_q;

    // The SETUP bytes of a step: {wLength, wIndex, wValue, bRequest, bmRequestType}, byte 0 first.
    function automatic [63:0] setup_bytes(input [7:0] bm, input [7:0] req, input [15:0] val,
                                          input [15:0] idx, input [15:0] len);
        setup_bytes = {len, idx, val, req, bm};
    endfunction
    reg [63:0] step_setup;
    always @(*) begin
        case (step_q)
            E_DEV8:    step_setup = setup_bytes(8'h80, 8'h06, 16'h0100, 16'h0000, 16'd8);
            E_ADDR:    step_setup = setup_bytes(8'h00, 8'h05, {9'd0, DEV_ADDR}, 16'h0000, 16'd0);
            E_DEV18:   step_setup = setup_bytes(8'h80, 8'h06, 16'h0100, 16'h0000, 16'd18);
            E_CFG9:    step_setup = setup_bytes(8'h80, 8'h06, 16'h0200, 16'h0000, 16'd9);
            E_CFG:     step_setup = setup_bytes(8'h80, 8'h06, 16'h0200, 16'h0000, {8'd0, total_q});
            E_SETCFG:  step_setup = setup_bytes(8'h00, 8'h09, {8'd0, cfg_val_q}, 16'h0000, 16'd0);
            E_PROTO:   step_setup = setup_bytes(8'h21, 8'h0B, 16'h0000, {8'd0, kbd_if_q}, 16'd0);
            E_IDLE:    step_setup = setup_bytes(8'h21, 8'h0A, 16'h0000, {8'd0, kbd_if_q}, 16'd0);
            default:   step_setup = setup_bytes(8'h02, 8'h01, 16'h0000, {8'd0, kbd_ep_q}, 16'd0);
        endcase
    end
    wire stall_ok = step_q == E_PROTO || step_q == E_IDLE;

    // The parser's view of one byte (walk_q-th of the packet).
    wire [7:0] wb = res_data[walk_q * 8 +: 8];   // usb_ls_xfer holds it: no request while walking
    wire [7:0] len_eff = d_pos_q == 8'd0 ? wb : d_len_q;

    function automatic [15:0] sat_inc(input [15:0] c, input en);
        sat_inc = (en && c != 16'hFFFF) ? c + 16'd1 : c;
    endfunction

    task automatic go_reset;   // a bus reset and the enumeration from the start
        begin
            state <= S_RESETTING;
            rst_phase_q <= 1'b1;
            rst_sent_q <= 1'b0;
            xrst <= 1'b1;
            rpt_clear <= 1'b1;
        end
    endtask
    task automatic next_step(input [3:0] s);
        begin
            step_q <= s;
            cst_q <= C_SETUP;
            req_sent_q <= 1'b0;
            nak_wait_q <= 1'b0;
        end
    endtask

    always @(posedge clk) begin
        if (hrst) begin
            frame_q <= '0;
            ka_pend_q <= 1'b0;
            eop_start <= 1'b0;
            reset_start <= 1'b0;
            state <= S_DETACHED;
            dev_addr <= 7'd0;
            rst_phase_q <= 1'b0;
            rst_sent_q <= 1'b0;
            ms_q <= 7'd0;
            se0_q <= '0;
            oe_d_q <= 3'd0;
            step_q <= E_DEV8;
            cst_q <= C_SETUP;
            tog_q <= 1'b0;
            got_q <= 8'd0;
            want_q <= 8'd0;
            nak_wait_q <= 1'b0;
            req_sent_q <= 1'b0;
            total_q <= 8'd9;
            xrst <= 1'b1;
            req_valid <= 1'b0;
            req_kind <= K_SETUP;
            req_endp <= 4'd0;
            req_toggle <= 1'b0;
            req_len <= 4'd0;
            req_data <= 64'd0;
            rpt_valid <= 1'b0;
            rpt_clear <= 1'b0;
            d_pos_q <= 8'd0;
            d_len_q <= 8'd0;
            d_type_q <= 8'd0;
            d_stop_q <= 1'b0;
            cfg_val_q <= 8'd1;
            if_num_q <= 8'd0;
            if_class_q <= 8'd0;
            if_sub_q <= 8'd0;
            ep_addr_q <= 8'd0;
            ep_attr_q <= 2'd0;
            in_kbd_q <= 1'b0;
            found_q <= 1'b0;
            kbd_if_q <= 8'd0;
            kbd_ep_q <= 8'd0;
            kbd_mps_q <= 8'd0;
            kbd_int_q <= 8'd10;
            cur_if_q <= 8'd0;
            walk_q <= 4'd0;
            walking_q <= 1'b0;
            walk_len_q <= 4'd0;
            ep_tog_q <= 1'b0;
            poll_q <= 8'd0;
        end else begin
            eop_start <= 1'b0;
            reset_start <= 1'b0;
            req_valid <= 1'b0;
            rpt_valid <= 1'b0;
            rpt_clear <= 1'b0;
            xrst <= 1'b0;
            oe_d_q <= {oe_d_q[1:0], usb_oe};

            // frames and keep-alives
            frame_q <= tick ? '0 : frame_q + 1'b1;
            if (tick && port_on) ka_pend_q <= 1'b1;
            if (!port_on) ka_pend_q <= 1'b0;
            else if (ka_pend_q && tx_idle && !x_busy && !eop_start) begin
                eop_start <= 1'b1;
                ka_pend_q <= 1'b0;
            end
            if (tick && ms_q != 7'h7F) ms_q <= ms_q + 1'b1;

            // detach: SE0 on a line the host does not drive
            if (rx_line == 2'b00 && !usb_oe && oe_d_q == 3'd0) begin
                if (se0_q != DETACH_MAX) se0_q <= se0_q + 1'b1;
            end else begin
                se0_q <= '0;
            end

            case (state)
                S_DETACHED: begin
                    xrst <= 1'b1;
                    dev_addr <= 7'd0;
                    if (rx_line == 2'b01) begin
                        state <= S_ATTACHED;
                        ms_q <= 7'd0;
                    end
                end
                S_ATTACHED: begin
                    xrst <= 1'b1;
                    if (rx_line != 2'b01) state <= S_DETACHED;
                    else if (ms_q == T_ATTACH) go_reset();
                end
                S_RESETTING: begin
                    xrst <= 1'b1;
                    dev_addr <= 7'd0;
                    if (rst_phase_q) begin
                        if (!rst_sent_q && tx_idle) begin
                            reset_start <= 1'b1;
                            rst_sent_q <= 1'b1;
                        end else if (rst_sent_q && tx_done) begin
                            rst_phase_q <= 1'b0;
                            ms_q <= 7'd0;
                        end
                    end else if (ms_q == T_RECOVERY) begin
                        state <= S_ENUM;
                        next_step(E_DEV8);
                        found_q <= 1'b0;
                        in_kbd_q <= 1'b0;
                        total_q <= 8'd9;
                    end
                end
                S_ENUM, S_RUNNING: begin
                    // the parser walks a received packet, one byte a clock
                    if (walking_q) begin
                        if (walk_q == walk_len_q || d_stop_q) begin
                            walking_q <= 1'b0;
                        end else begin
                            walk_q <= walk_q + 1'b1;
                            d_pos_q <= d_pos_q + 8'd1 == len_eff ? 8'd0 : d_pos_q + 8'd1;
                            if (d_pos_q == 8'd0) begin
                                d_len_q <= wb;
                                if (wb < 8'd2) d_stop_q <= 1'b1;    // malformed: parse no further
                            end
                            if (d_pos_q == 8'd1) d_type_q <= wb;
                            if (d_pos_q >= 8'd2) begin
                                case (d_type_q)
                                    8'd2: begin
                                        if (d_pos_q == 8'd2) total_q <= wb > CFG_LIMIT ? CFG_LIMIT : wb;
                                        if (d_pos_q == 8'd3 && wb != 8'd0) total_q <= CFG_LIMIT;
                                        if (d_pos_q == 8'd5) cfg_val_q <= wb;
                                    end
                                    8'd4: begin
                                        if (d_pos_q == 8'd2) if_num_q <= wb;
                                        if (d_pos_q == 8'd5) if_class_q <= wb;
                                        if (d_pos_q == 8'd6) if_sub_q <= wb;
                                        if (d_pos_q == 8'd7) begin
                                            in_kbd_q <= if_class_q == 8'd3 && if_sub_q == 8'd1 && wb == 8'd1;
                                            cur_if_q <= if_num_q;
                                        end
                                    end
                                    8'd5: begin
                                        if (d_pos_q == 8'd2) ep_addr_q <= wb;
                                        if (d_pos_q == 8'd3) ep_attr_q <= wb[1:0];
                                        if (d_pos_q == 8'd4) kbd_mps_q <= found_q ? kbd_mps_q : wb;
                                        if (d_pos_q == 8'd6 && in_kbd_q && !found_q && ep_addr_q[7]
                                            && ep_attr_q == 2'b11) begin
                                            found_q <= 1'b1;
                                            kbd_if_q <= cur_if_q;
                                            kbd_ep_q <= ep_addr_q;
                                            kbd_int_q <= wb;
                                        end
                                    end
                                    default: ;
                                endcase
                            end
                        end
                    end

                    // the control transfer of the current step, or the poll
                    case (cst_q)
                        C_SETUP: begin
                            if (!req_sent_q && req_ready && !walking_q && (!nak_wait_q || tick)) begin
                                req_valid <= 1'b1;
                                req_sent_q <= 1'b1;
                                nak_wait_q <= 1'b0;
                                req_kind <= K_SETUP;
                                req_endp <= 4'd0;
                                req_toggle <= 1'b0;
                                req_len <= 4'd8;
                                req_data <= step_setup;
                                want_q <= step_setup[55:48];
                                got_q <= 8'd0;
                                tog_q <= 1'b1;
                                if (step_q == E_CFG9 || step_q == E_CFG) begin
                                    d_pos_q <= 8'd0;
                                    d_stop_q <= 1'b0;
                                end
                            end
                            if (res_valid) begin
                                req_sent_q <= 1'b0;
                                if (res_code == R_ACK) cst_q <= want_q != 8'd0 ? C_DIN : C_SIN;
                                else if (res_code == R_NAK) nak_wait_q <= 1'b1;
                                else if (res_code == R_STALL && stall_ok) cst_q <= C_NEXT;
                                else go_reset();
                            end
                        end
                        C_DIN, C_SIN, C_SOUT: begin
                            if (!req_sent_q && req_ready && !walking_q && (!nak_wait_q || tick)) begin
                                req_valid <= 1'b1;
                                req_sent_q <= 1'b1;
                                nak_wait_q <= 1'b0;
                                req_kind <= cst_q == C_SOUT ? K_OUT : K_IN;
                                req_endp <= 4'd0;
                                req_toggle <= cst_q == C_DIN ? tog_q : 1'b1;
                                req_len <= 4'd0;
                            end
                            if (res_valid) begin
                                req_sent_q <= 1'b0;
                                if (res_code == R_DATA && cst_q == C_DIN) begin
                                    tog_q <= !tog_q;
                                    got_q <= got_q + {4'd0, res_len};
                                    walk_len_q <= res_len;
                                    walk_q <= 4'd0;
                                    walking_q <= 1'b1;
                                    if (res_len != 4'd8 || got_q + {4'd0, res_len} >= want_q) cst_q <= C_SOUT;
                                end else if (res_code == R_DUP && cst_q == C_DIN) begin
                                    // acknowledged and dropped: ask again
                                end else if ((res_code == R_ACK && cst_q == C_SOUT)
                                             || (res_code == R_DATA && cst_q == C_SIN)) begin
                                    cst_q <= C_NEXT;
                                end else if (res_code == R_NAK) begin
                                    nak_wait_q <= 1'b1;
                                end else if (res_code == R_STALL && stall_ok) begin
                                    cst_q <= C_NEXT;
                                end else begin
                                    go_reset();
                                end
                            end
                        end
                        C_NEXT: if (!walking_q) begin
                            // the step is done: what it leaves behind
                            case (step_q)
                                E_ADDR: begin
                                    ms_q <= 7'd0;
                                    cst_q <= C_WAIT;
                                end
                                E_CFG: if (found_q) next_step(E_SETCFG);
                                       else state <= S_NOKBD;
                                E_SETCFG: begin
                                    ep_tog_q <= 1'b0;
                                    next_step(E_PROTO);
                                end
                                E_IDLE, E_CLRHALT: begin
                                    ep_tog_q <= 1'b0;
                                    state <= S_RUNNING;
                                    poll_q <= 8'd0;
                                    cst_q <= C_POLL;
                                    req_sent_q <= 1'b0;
                                end
                                default: next_step(step_q + 4'd1);
                            endcase
                        end
                        C_WAIT: if (ms_q == T_ADDR) begin     // SET_ADDRESS recovery
                            dev_addr <= DEV_ADDR;
                            next_step(E_DEV18);
                        end
                        C_POLL: begin
                            if (tick && poll_q != 8'hFF) poll_q <= poll_q + 8'd1;
                            if (!req_sent_q && req_ready && rpt_ready && poll_q >= poll_int) begin
                                poll_q <= 8'd0;
                                req_valid <= 1'b1;
                                req_sent_q <= 1'b1;
                                req_kind <= K_IN;
                                req_endp <= kbd_ep_q[3:0];
                                req_toggle <= ep_tog_q;
                                req_len <= 4'd0;
                            end
                            if (res_valid) begin
                                req_sent_q <= 1'b0;
                                if (res_code == R_DATA) begin
                                    ep_tog_q <= !ep_tog_q;
                                    rpt_valid <= 1'b1;
                                end else if (res_code == R_STALL) begin
                                    state <= S_ENUM;
                                    next_step(E_CLRHALT);
                                end else if (res_code == R_FAIL) begin
                                    go_reset();
                                end
                            end
                        end
                        default: ;
                    endcase
                end
                S_NOKBD: xrst <= 1'b1;
                default: xrst <= 1'b1;                    // S_BABBLE: the port disabled
            endcase

            // babble and detach override everything else
            if (state != S_DETACHED && state != S_ATTACHED) begin
                if (se0_q == DETACH_MAX) begin
                    state <= S_DETACHED;
                    xrst <= 1'b1;
                    rpt_clear <= 1'b1;
                end else if (rx_babble && state != S_BABBLE) begin
                    state <= S_BABBLE;
                    xrst <= 1'b1;
                    rpt_clear <= 1'b1;
                end
            end
        end
    end

    // counters (kept over enable: cleared by rst only)
    always @(posedge clk) begin
        if (rst) begin
            cnt_crc <= 16'd0;
            cnt_timeout <= 16'd0;
            cnt_retry <= 16'd0;
            cnt_nak <= 16'd0;
            cnt_stall <= 16'd0;
            cnt_attach <= 16'd0;
            cnt_detach <= 16'd0;
            cnt_wrong_len <= 16'd0;
            cnt_overflow <= 16'd0;
            cnt_reenum <= 16'd0;
            cnt_rollover <= 16'd0;
        end else begin
            cnt_rollover <= sat_inc(cnt_rollover, k_rollover);
            cnt_crc <= sat_inc(cnt_crc, ev_bad);
            cnt_timeout <= sat_inc(cnt_timeout, ev_timeout);
            cnt_retry <= sat_inc(cnt_retry, ev_retry);
            cnt_nak <= sat_inc(cnt_nak, res_valid && res_code == R_NAK);
            cnt_stall <= sat_inc(cnt_stall, res_valid && res_code == R_STALL);
            cnt_attach <= sat_inc(cnt_attach, enable && state == S_ATTACHED && ms_q == T_ATTACH
                                              && rx_line == 2'b01);
            cnt_detach <= sat_inc(cnt_detach, enable && state != S_DETACHED && state != S_ATTACHED
                                              && se0_q == DETACH_MAX);
            cnt_wrong_len <= sat_inc(cnt_wrong_len, k_wrong_len);
            cnt_overflow <= sat_inc(cnt_overflow, k_overflow);
            cnt_reenum <= sat_inc(cnt_reenum, res_valid && (res_code == R_FAIL
                                  || (res_code == R_STALL && !stall_ok && state == S_ENUM)));
        end
    end
endmodule

`default_nettype wire
