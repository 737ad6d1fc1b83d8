// usb_ls_xfer: the USB low-speed host's transaction layer: one SETUP, IN or OUT transaction (8.4,
// 8.5) on the packet layer (usb_ls_packet_tx/_rx), with the turnaround timeout, the inter-packet
// gap, the handshake and up to MAX_RETRIES retries; the caller (usb_ls_host) schedules them.
//
// Contract (request): req_valid/req_ready; req_ready is high in idle. req_kind (K_SETUP, K_IN,
// K_OUT), req_addr, req_endp, req_toggle (SETUP/OUT: the DATA PID sent, 0 DATA0, 1 DATA1; IN: the
// DATA PID expected), req_len and req_data (SETUP/OUT payload, byte 0 in [7:0]; SETUP always 8).
// Each attempt starts only while slot_ok (the caller's frame schedule: an attempt lasts at most
// ATTEMPT_BITS bit times, so it ends before the next keep-alive) and the bus has been idle for
// GAP_BITS after the last EOP (TIPD, 7.1.18.1), or J for DRAIN_BITS (a line that went idle without
// an EOP). An attempt: the token; for SETUP/OUT, GAP_BITS after its EOP, the DATA packet; then the
// answer. SETUP/OUT: ACK, NAK or STALL ends it. IN: DATA0/DATA1 with a good CRC is acknowledged
// (ACK GAP_BITS after the device's EOP) and ends it as R_DATA when its PID is req_toggle, as R_DUP
// when not (a repeated packet whose ACK the device missed, 8.6.4: acknowledged and dropped); NAK or
// STALL end it. Errors: rx_timeout (16-18 bit times of idle after the host's EOP, usb_ls_rx) or no
// verdict within WAIT_BITS of the host's EOP (a line that never went idle after it) is a timeout
// (ev_timeout); a packet with pkt_ok low or an unexpected PID is corrupted (ev_bad: not
// acknowledged). After a corrupted packet the layer waits until the line has been J for DRAIN_BITS
// (past the device's own 16-18-bit wait for a handshake), after a timeout not at all (the device has
// been silent for the whole timeout: the retry's token follows it, 16-18 bit times after the EOP),
// and retries (ev_retry), at most MAX_RETRIES times; then R_FAIL.
// Contract (result): res_valid pulses once per request with res_code; R_DATA/R_DUP carry res_len
// and res_data (the payload, byte 0 in [7:0]; the bytes come from usb_ls_packet_rx's dat_* into a
// register that holds them from the result to the next request: no device packet comes between). busy: an attempt is on the bus (the caller sends
// no keep-alive then). rst (the caller's) abandons a transaction at once.
`default_nettype none

module usb_ls_xfer #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // clk's frequency, Hz
    parameter integer MAX_RETRIES = 3,      // retries after a timeout or a corrupted packet (then R_FAIL)
    parameter integer GAP_BITS = 2,         // idle bit times before the host's packet (TIPD >= 2)
    parameter integer WAIT_BITS = 160,      // after the host's EOP: the turnaround (18) + the longest packet (114) + margin
    parameter integer DRAIN_BITS = 20,      // J before a retry: past the device's 16-18 bit handshake wait
    localparam integer BIT_CLKS = (SYS_HZ + usb_pkg::USB_LS_BIT_HZ - 1) / usb_pkg::USB_LS_BIT_HZ,
    localparam integer WAIT_CLKS = WAIT_BITS * BIT_CLKS,
    localparam integer DRAIN_CLKS = DRAIN_BITS * BIT_CLKS,
    localparam integer W_W = $clog2(WAIT_CLKS + 1),
    localparam integer D_W = $clog2(DRAIN_CLKS + 1),
    localparam integer R_W = $clog2(MAX_RETRIES + 1)
) (
    input  wire        clk,
    input  wire        rst,            // synchronous, active high: abandons the transaction
    // request
    input  wire        req_valid,
    output wire        req_ready,
    input  wire [1:0]  req_kind,       // K_SETUP, K_IN, K_OUT
    input  wire [6:0]  req_addr,
    input  wire [3:0]  req_endp,
    input  wire        req_toggle,     // SETUP/OUT: DATA1 sent; IN: DATA1 expected
    input  wire [3:0]  req_len,        // SETUP/OUT payload bytes (0..8)
    input  wire [63:0] req_data,       // SETUP/OUT payload, byte 0 in [7:0]
    input  wire        slot_ok,        // the frame schedule allows an attempt to start
    output wire        busy,           // an attempt is on the bus
    // result
    output reg         res_valid,
    output reg  [2:0]  res_code,       // R_ACK, R_DATA, R_DUP, R_NAK, R_STALL, R_FAIL
    output reg  [3:0]  res_len,        // R_DATA/R_DUP: payload bytes
    output wire [63:0] res_data,       // R_DATA/R_DUP: payload, byte 0 in [7:0]; held until the next request
    // events (one clock each, for the counters)
    output reg         ev_timeout,
    output reg         ev_bad,
    output reg         ev_retry,
    // usb_ls_packet_tx
    output reg         cmd_valid,
    input  wire        cmd_ready,
    output reg  [3:0]  cmd_pid,
    output wire [6:0]  cmd_addr,
    output wire [3:0]  cmd_endp,
    output reg  [3:0]  cmd_len,
    input  wire        pkt_busy,
    output wire        pl_valid,
    input  wire        pl_ready,
    output wire [7:0]  pl_data,
    // usb_ls_tx, usb_ls_rx
    input  wire        tx_idle,
    input  wire [1:0]  rx_line,
    input  wire [7:0]  rx_idle_bits,
    input  wire        rx_timeout,
    input  wire        rx_start,
    // usb_ls_packet_rx
    input  wire        dat_valid,
    input  wire [7:0]  dat_data,
    input  wire        pkt_valid,
    input  wire [3:0]  pkt_pid,
    input  wire [3:0]  pkt_len,
    input  wire        pkt_ok
);
    localparam [1:0] K_SETUP = 2'd0, K_IN = 2'd1, K_OUT = 2'd2;
    localparam [2:0] R_ACK = 3'd0, R_DATA = 3'd1, R_DUP = 3'd2, R_NAK = 3'd3, R_STALL = 3'd4,
                     R_FAIL = 3'd5;
    localparam [2:0] X_IDLE = 3'd0, X_SLOT = 3'd1, X_TOK = 3'd2, X_GAP = 3'd3, X_DAT = 3'd4,
                     X_WAIT = 3'd5, X_ACK = 3'd6, X_DRAIN = 3'd7;
    localparam [7:0] GAP = GAP_BITS[7:0];
    localparam [W_W-1:0] WAIT_MAX = WAIT_CLKS[W_W-1:0];
    localparam [D_W-1:0] DRAIN_MAX = DRAIN_CLKS[D_W-1:0];
    localparam [R_W-1:0] RETRY_MAX = MAX_RETRIES[R_W-1:0];

    reg [2:0]     st_q;
    reg [1:0]     kind_q;
    reg [6:0]     addr_q;
    reg [3:0]     endp_q;
    reg           tog_q;
    reg [3:0]     len_q;
    reg [63:0]    txb_q;        // payload to send, shifted out byte 0 first
    reg [63:0]    rxb_q;        // payload being received, then the result's
    reg [3:0]     rxn_q;
    reg [R_W-1:0] retry_q;
    reg [W_W-1:0] wait_q;       // clocks since the host's EOP (X_WAIT)
    reg [D_W-1:0] jrun_q;       // clocks the line has been J
    reg           cmd_sent_q;   // X_TOK/X_DAT/X_ACK: the command was taken
    reg [2:0]     pend_q;       // X_ACK: the result after the handshake
    reg           quiet_q;      // X_DRAIN after a timeout: the line is idle already, retry at once

    wire line_j = rx_line == 2'b01;
    wire bus_quiet = (rx_idle_bits >= GAP || jrun_q == DRAIN_MAX) && line_j;
    wire sent = cmd_sent_q && !pkt_busy && tx_idle;    // the host's packet has been sent (EOP done)
    assign req_ready = st_q == X_IDLE;
    assign busy = st_q != X_IDLE && st_q != X_SLOT && st_q != X_DRAIN;
    assign cmd_addr = addr_q;
    assign cmd_endp = endp_q;
    assign pl_valid = 1'b1;                             // the payload is in txb_q: never a gap
    assign pl_data = txb_q[7:0];
    assign res_data = rxb_q;

    always @(*) begin
        cmd_valid = 1'b0;
        cmd_pid = 4'd0;
        cmd_len = 4'd0;
        case (st_q)
            X_SLOT: begin
                cmd_valid = slot_ok && bus_quiet && tx_idle;
                cmd_pid = kind_q == K_OUT ? usb_pkg::PID_OUT
                        : kind_q == K_IN ? usb_pkg::PID_IN : usb_pkg::PID_SETUP;
            end
            X_GAP: begin
                cmd_valid = rx_idle_bits >= GAP && line_j;
                cmd_pid = tog_q ? usb_pkg::PID_DATA1 : usb_pkg::PID_DATA0;
                cmd_len = len_q;
            end
            X_ACK: begin
                cmd_valid = !cmd_sent_q && rx_idle_bits >= GAP && line_j;
                cmd_pid = usb_pkg::PID_ACK;
            end
            default: ;
        endcase
    end
    wire cmd_take = cmd_valid && cmd_ready;

    // The answer's verdict (X_WAIT, pkt_valid).
    wire is_data = pkt_pid == usb_pkg::PID_DATA0 || pkt_pid == usb_pkg::PID_DATA1;
    wire ans_ack = pkt_ok && pkt_pid == usb_pkg::PID_ACK && kind_q != K_IN;
    wire ans_nak = pkt_ok && pkt_pid == usb_pkg::PID_NAK;
    wire ans_stall = pkt_ok && pkt_pid == usb_pkg::PID_STALL;
    wire ans_data = pkt_ok && is_data && kind_q == K_IN;

    task automatic finish(input [2:0] code);
        begin
            res_valid <= 1'b1;
            res_code <= code;
            st_q <= X_IDLE;
        end
    endtask

    task automatic error_retry(input timed_out);
        begin
            st_q <= X_DRAIN;
            quiet_q <= timed_out;
        end
    endtask

    always @(posedge clk) begin
        if (rst) begin
            st_q <= X_IDLE;
            kind_q <= K_SETUP;
            addr_q <= 7'd0;
            endp_q <= 4'd0;
            tog_q <= 1'b0;
            len_q <= 4'd0;
            txb_q <= 64'd0;
            rxb_q <= 64'd0;
            rxn_q <= 4'd0;
            retry_q <= '0;
            wait_q <= '0;
            jrun_q <= '0;
            cmd_sent_q <= 1'b0;
            pend_q <= R_ACK;
            quiet_q <= 1'b0;
            res_valid <= 1'b0;
            res_code <= R_ACK;
            res_len <= 4'd0;
            ev_timeout <= 1'b0;
            ev_bad <= 1'b0;
            ev_retry <= 1'b0;
        end else begin
            res_valid <= 1'b0;
            ev_timeout <= 1'b0;
            ev_bad <= 1'b0;
            ev_retry <= 1'b0;
            if (!line_j) jrun_q <= '0;
            else if (jrun_q != DRAIN_MAX) jrun_q <= jrun_q + 1'b1;
            // the payload being received, kept until the verdict
            if (rx_start) rxn_q <= 4'd0;
            if (dat_valid && rxn_q < 4'd8) begin
                rxb_q[rxn_q * 8 +: 8] <= dat_data;
                rxn_q <= rxn_q + 1'b1;
            end
            if (cmd_take) cmd_sent_q <= 1'b1;
            if (pl_ready) txb_q <= {8'd0, txb_q[63:8]};
            case (st_q)
                X_IDLE: if (req_valid) begin
                    kind_q <= req_kind;
                    addr_q <= req_addr;
                    endp_q <= req_endp;
                    tog_q <= req_toggle;
                    len_q <= req_len;
                    txb_q <= req_data;
                    retry_q <= '0;
                    st_q <= X_SLOT;
                end
                X_SLOT: if (cmd_take) begin
                    cmd_sent_q <= 1'b1;
                    st_q <= X_TOK;
                end
                X_TOK: if (sent) begin
                    cmd_sent_q <= 1'b0;
                    wait_q <= '0;
                    st_q <= kind_q == K_IN ? X_WAIT : X_GAP;
                end
                X_GAP: if (cmd_take) begin
                    cmd_sent_q <= 1'b1;
                    st_q <= X_DAT;
                end
                X_DAT: if (sent) begin
                    cmd_sent_q <= 1'b0;
                    wait_q <= '0;
                    st_q <= X_WAIT;
                end
                X_WAIT: begin
                    if (wait_q != WAIT_MAX) wait_q <= wait_q + 1'b1;
                    if (pkt_valid) begin
                        if (ans_ack) finish(R_ACK);
                        else if (ans_nak) finish(R_NAK);
                        else if (ans_stall) finish(R_STALL);
                        else if (ans_data) begin
                            // the DATA PID's bit 3 is the toggle (DATA0 0011, DATA1 1011)
                            pend_q <= pkt_pid[3] == tog_q ? R_DATA : R_DUP;
                            res_len <= pkt_len;
                            cmd_sent_q <= 1'b0;
                            st_q <= X_ACK;
                        end else begin
                            ev_bad <= 1'b1;
                            error_retry(1'b0);
                        end
                    end else if (rx_timeout || wait_q == WAIT_MAX) begin
                        ev_timeout <= 1'b1;
                        error_retry(1'b1);
                    end
                end
                X_ACK: if (sent) begin
                    cmd_sent_q <= 1'b0;
                    finish(pend_q);
                end
                X_DRAIN: if (jrun_q == DRAIN_MAX || quiet_q) begin
                    if (retry_q == RETRY_MAX) begin
                        finish(R_FAIL);
                    end else begin
                        retry_q <= retry_q + 1'b1;
                        ev_retry <= 1'b1;
                        st_q <= X_SLOT;
                    end
                end
                default: st_q <= X_IDLE;
            endcase
        end
    end
endmodule

`default_nettype wire
