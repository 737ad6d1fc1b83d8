// usb_ls_packet_tx: the USB low-speed host's packet builder: a token (PID, address, endpoint,
// CRC5), a data packet (PID, payload, CRC16) or a handshake (PID) from one command, as the byte
// stream usb_ls_tx sends (8.4).
//
// Contract (command): cmd_valid/cmd_ready; cmd_ready is high while no packet is being built
// (pkt_busy low). The PID's type says the packet (8.3.1): xx01 a token (cmd_addr, cmd_endp; 3
// bytes: PID, {endp, addr} LSB first, the CRC5 field), xx11 data (DATA0/DATA1: PID, cmd_len
// payload bytes from the pl_* stream, the CRC16 field; 3 + cmd_len bytes), xx10 a handshake (the
// PID alone). A special PID (xx00: PRE) is sent as a lone PID byte too; this host never sends one.
// Contract (payload): a data packet takes cmd_len bytes (0 .. 2^LEN_W - 1) from pl_valid/pl_ready/
// pl_data, each in the clock usb_ls_tx takes it (pl_ready = the line's tx_ready in the payload):
// the payload must be ready from the command on (a byte time between bytes at most: usb_ls_tx's
// underrun contract, its tx_underrun); a buffer that holds the payload meets it.
// Contract (stream to usb_ls_tx): tx_valid is high from the command to the packet's last byte
// except while a payload byte is not valid; the bytes are computed from registers (token and CRC)
// or passed through (payload) in the clock they are taken: no added latency, the line's throughput.
// CRC: usb_pkg (USB 1.1 8.3.5): the CRC5 over the 11 bits of {endp, addr}, the CRC16 over the
// payload's bits, each field complemented, most significant bit first.
`default_nettype none

module usb_ls_packet_tx #(
    parameter integer LEN_W = 4        // cmd_len's width: low-speed payloads are 0..8 bytes
) (
    input  wire             clk,
    input  wire             rst,        // synchronous, active high
    // command
    input  wire             cmd_valid,
    output wire             cmd_ready,
    input  wire [3:0]       cmd_pid,
    input  wire [6:0]       cmd_addr,   // tokens
    input  wire [3:0]       cmd_endp,   // tokens
    input  wire [LEN_W-1:0] cmd_len,    // data packets: payload bytes
    output wire             pkt_busy,   // a packet is being handed to usb_ls_tx
    // payload (data packets)
    input  wire             pl_valid,
    output wire             pl_ready,
    input  wire [7:0]       pl_data,
    // to usb_ls_tx
    output reg              tx_valid,
    input  wire             tx_ready,
    output reg  [7:0]       tx_data,
    output reg              tx_last
);
    localparam [2:0] P_IDLE = 3'd0, P_PID = 3'd1, P_TOK1 = 3'd2, P_TOK2 = 3'd3, P_DATA = 3'd4,
                     P_CRC1 = 3'd5, P_CRC2 = 3'd6;
    reg [2:0]       st_q;
    reg [3:0]       pid_q;
    reg [15:0]      tok_q;          // a token's two bytes after its PID, {byte 2, byte 1}
    reg [LEN_W-1:0] left_q;         // payload bytes still to send
    reg [15:0]      crc_q;          // the CRC16 register over the payload so far
    wire [1:0] kind = pid_q[1:0];   // 01 token, 11 data, 10 handshake, 00 special
    wire [15:0] crc_field = usb_pkg::crc16_field(crc_q);

    assign cmd_ready = st_q == P_IDLE;
    assign pkt_busy = st_q != P_IDLE;
    assign pl_ready = st_q == P_DATA && tx_ready;

    always @(*) begin
        tx_valid = 1'b0;
        tx_data = 8'd0;
        tx_last = 1'b0;
        case (st_q)
            P_PID: begin
                tx_valid = 1'b1;
                tx_data = usb_pkg::pid_byte(pid_q);
                tx_last = kind[0] == 1'b0;    // a handshake or a special PID: the PID alone
            end
            P_TOK1: begin
                tx_valid = 1'b1;
                tx_data = tok_q[7:0];
            end
            P_TOK2: begin
                tx_valid = 1'b1;
                tx_data = tok_q[15:8];
                tx_last = 1'b1;
            end
            P_DATA: begin
                tx_valid = pl_valid;
                tx_data = pl_data;
            end
            P_CRC1: begin
                tx_valid = 1'b1;
                tx_data = crc_field[7:0];
            end
            P_CRC2: begin
                tx_valid = 1'b1;
                tx_data = crc_field[15:8];
                tx_last = 1'b1;
            end
            default: ;
        endcase
    end
    wire take = tx_valid && tx_ready;

    always @(posedge clk) begin
        if (rst) begin
            st_q <= P_IDLE;
            pid_q <= 4'd0;
            tok_q <= 16'd0;
            left_q <= '0;
            crc_q <= 16'hFFFF;
        end else begin
            case (st_q)
                P_IDLE: if (cmd_valid) begin
                    st_q <= P_PID;
                    pid_q <= cmd_pid;
                    tok_q <= usb_pkg::token_bytes(cmd_addr, cmd_endp);
                    left_q <= cmd_len;
                    crc_q <= 16'hFFFF;
                end
                P_PID: if (take) begin
                    if (kind == 2'b01) st_q <= P_TOK1;
                    else if (kind == 2'b11) st_q <= left_q == 0 ? P_CRC1 : P_DATA;
                    else st_q <= P_IDLE;
                end
                P_TOK1: if (take) st_q <= P_TOK2;
                P_TOK2: if (take) st_q <= P_IDLE;
                P_DATA: if (take) begin
                    crc_q <= usb_pkg::crc16_byte(crc_q, pl_data);
                    left_q <= left_q - 1'b1;
                    if (left_q == 1) st_q <= P_CRC1;
                end
                P_CRC1: if (take) st_q <= P_CRC2;
                P_CRC2: if (take) st_q <= P_IDLE;
                default: st_q <= P_IDLE;
            endcase
        end
    end
endmodule

`default_nettype wire
