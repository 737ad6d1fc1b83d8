// usb_ls_packet_rx: the USB low-speed host's packet checker: the bytes usb_ls_rx delivers, checked
// as a packet (8.3, 8.4): the PID's check nibble, its type's length, a token's CRC5, a data
// packet's CRC16; the payload passed on as it arrives, the verdict at the end.
//
// Contract (in): usb_ls_rx's rx_start, rx_valid/rx_data, rx_end and its four error flags, as that
// module gives them (every rx_start followed by one rx_end, bytes only between them).
// Contract (payload): a data packet's payload bytes come out on dat_valid/dat_data (one clock
// each, no backpressure: usb_ls_rx gives a byte at most every 8 bit times), two bytes behind the
// line (the last two bytes are the CRC16 field, known only at the end, and never come out): a
// byte comes out in the clock after the second byte after it arrived, so the first payload byte
// with the packet's 4th byte. Bytes of packets of other types never come out. The consumer keeps them
// until pkt_valid says whether the packet was good (a data packet with errors may have put out
// some of its bytes).
// Contract (verdict): pkt_valid pulses one clock after usb_ls_rx's rx_end, once per packet, with:
//   pkt_pid    the PID's code (the first byte's low nibble; 0 for an empty packet);
//   pkt_len    the payload bytes put out (data packets; 0 otherwise);
//   pkt_ok     none of the errors below;
//   err_line   the line layer's error (usb_ls_rx: stuffing, alignment, SE0, over MAX_BYTES);
//   err_pid    no byte, or the check nibble is not the complement of the PID (8.3.1);
//   err_len    a handshake not 1 byte, a token not 3, a data packet under 3 (PID and CRC16);
//   err_crc    a token's 16 bits after the PID not at the CRC5 residual 01100, a data packet's
//              bytes after the PID not at the CRC16 residual 0x800D (8.3.5).
// Several flags may be set together. The host ignores a packet with an error (no handshake).
`default_nettype none

module usb_ls_packet_rx #(
    parameter integer MAX_BYTES = usb_pkg::LS_MAX_PACKET_BYTES,   // as usb_ls_rx's
    localparam integer N_W = $clog2(MAX_BYTES + 1)
) (
    input  wire           clk,
    input  wire           rst,          // synchronous, active high
    // from usb_ls_rx
    input  wire           rx_start,
    input  wire           rx_valid,
    input  wire [7:0]     rx_data,
    input  wire           rx_end,
    input  wire           rx_err_stuff,
    input  wire           rx_err_align,
    input  wire           rx_err_se0,
    input  wire           rx_err_long,
    // payload (data packets)
    output reg            dat_valid,
    output reg  [7:0]     dat_data,
    // verdict
    output reg            pkt_valid,
    output reg  [3:0]     pkt_pid,
    output reg  [N_W-1:0] pkt_len,
    output reg            pkt_ok,
    output reg            err_line,
    output reg            err_pid,
    output reg            err_len,
    output reg            err_crc
);
    reg [N_W-1:0] n_q;              // bytes of the packet so far
    reg [7:0]     pid_q;            // the first byte
    reg [7:0]     b1_q, b2_q;       // the last two bytes (b2_q the latest)
    reg [15:0]    crc16_q;          // the CRC16 register over the bytes after the PID
    reg [N_W-1:0] out_q;            // payload bytes put out
    wire [1:0] kind = pid_q[1:0];

    // The verdict, from the packet's state in rx_end's clock.
    wire       v_pid = n_q != 0 && usb_pkg::pid_ok(pid_q);
    wire       v_len = kind == 2'b01 ? n_q == 3 : kind == 2'b11 ? n_q >= 3 : n_q == 1;
    wire [4:0] crc5 = usb_pkg::crc5_check({b2_q, b1_q});
    wire       v_crc = kind == 2'b01 ? crc5 == usb_pkg::CRC5_RESIDUAL
                     : kind == 2'b11 ? crc16_q == usb_pkg::CRC16_RESIDUAL : 1'b1;
    wire       v_line = rx_err_stuff || rx_err_align || rx_err_se0 || rx_err_long;

    always @(posedge clk) begin
        if (rst) begin
            n_q <= '0;
            pid_q <= 8'd0;
            b1_q <= 8'd0;
            b2_q <= 8'd0;
            crc16_q <= 16'hFFFF;
            out_q <= '0;
            dat_valid <= 1'b0;
            dat_data <= 8'd0;
            pkt_valid <= 1'b0;
            pkt_pid <= 4'd0;
            pkt_len <= '0;
            pkt_ok <= 1'b0;
            err_line <= 1'b0;
            err_pid <= 1'b0;
            err_len <= 1'b0;
            err_crc <= 1'b0;
        end else begin
            dat_valid <= 1'b0;
            pkt_valid <= 1'b0;
            if (rx_start) begin
                n_q <= '0;
                pid_q <= 8'd0;
                crc16_q <= 16'hFFFF;
                out_q <= '0;
            end
            if (rx_valid) begin
                if (n_q != {N_W{1'b1}}) n_q <= n_q + 1'b1;
                if (n_q == 0) begin
                    pid_q <= rx_data;
                end else begin
                    crc16_q <= usb_pkg::crc16_byte(crc16_q, rx_data);
                    b1_q <= b2_q;
                    b2_q <= rx_data;
                    // a data packet's byte two places back is payload, not CRC
                    if (kind == 2'b11 && usb_pkg::pid_ok(pid_q) && n_q >= 3) begin
                        dat_valid <= 1'b1;
                        dat_data <= b1_q;
                        out_q <= out_q + 1'b1;
                    end
                end
            end
            if (rx_end) begin
                pkt_valid <= 1'b1;
                pkt_pid <= n_q != 0 ? pid_q[3:0] : 4'd0;
                pkt_len <= out_q;
                err_line <= v_line;
                err_pid <= !v_pid;
                err_len <= !v_len;
                err_crc <= !v_crc;
                pkt_ok <= !v_line && v_pid && v_len && v_crc;
            end
        end
    end
endmodule

`default_nettype wire
