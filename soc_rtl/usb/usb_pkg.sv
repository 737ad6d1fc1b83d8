// usb_pkg: the USB 1.1 low-speed host's constants and CRC functions, for soc_rtl/usb/, and nothing
// else: the bit rate, the PIDs, the CRC5 and CRC16 of the USB 1.1 specification, 8.3.5, and the
// bit timing's fractional step (usb_ls_tx, usb_ls_rx). Qualified names everywhere (usb_pkg::...):
// yosys 0.23 accepts no `import`. No logic here.
//
// Bit order. USB sends every field least significant bit first (8.1); a byte stream here is the
// bytes in the order sent, each LSB first. The CRCs are defined on the bits in that order (8.3.5):
// a 5-bit (16-bit) shift register preset to all ones; for each bit b, in the order sent, the
// register shifts one place towards its most significant end and is XORed with the polynomial's
// low terms (x^5+x^2+1: 5'b00101; x^16+x^15+x^2+1: 16'h8005) when b differs from the bit shifted
// out. The field sent is the register's ones' complement, most significant bit first. A receiver
// runs the same register over the protected bits and the CRC field; without errors it ends at the
// residual, 5'b01100 (x^4..x^0) or 16'h800D (1000000000001101).
`default_nettype none

package usb_pkg;
// Low speed: 1.5 Mb/s (7.1.11).
localparam integer USB_LS_BIT_HZ = 1_500_000;

// PIDs (8.3.1, Table 8-1): the 4-bit code; the byte on the wire is {~pid, pid} (check nibble).
localparam [3:0] PID_OUT   = 4'b0001;
localparam [3:0] PID_IN    = 4'b1001;
localparam [3:0] PID_SOF   = 4'b0101;
localparam [3:0] PID_SETUP = 4'b1101;
localparam [3:0] PID_DATA0 = 4'b0011;
localparam [3:0] PID_DATA1 = 4'b1011;
localparam [3:0] PID_ACK   = 4'b0010;
localparam [3:0] PID_NAK   = 4'b1010;
localparam [3:0] PID_STALL = 4'b1110;
localparam [3:0] PID_PRE   = 4'b1100;

// Field widths (8.3.2, 8.3.3, 8.4.4): device address, endpoint, the CRCs; the longest low-speed
// packet: PID, 8 data bytes (5.7.3, 5.5.3: low-speed maximum packet size), CRC16.
localparam integer ADDR_W = 7;
localparam integer ENDP_W = 4;
localparam integer CRC5_W = 5;
localparam integer CRC16_W = 16;
localparam integer LS_MAX_DATA_BYTES = 8;
localparam integer LS_MAX_PACKET_BYTES = 1 + LS_MAX_DATA_BYTES + 2;

localparam [4:0]  CRC5_POLY = 5'b00101;       // x^5 + x^2 + 1 without its x^5
localparam [15:0] CRC16_POLY = 16'h8005;      // x^16 + x^15 + x^2 + 1 without its x^16
localparam [4:0]  CRC5_RESIDUAL = 5'b01100;
localparam [15:0] CRC16_RESIDUAL = 16'h800D;

function automatic [7:0] pid_byte(input [3:0] pid);
    pid_byte = {~pid, pid};
endfunction

// The PID check (8.3.1): the high nibble is the ones' complement of the low one.
function automatic pid_ok(input [7:0] b);
    pid_ok = b[7:4] == ~b[3:0];
endfunction

// One bit through the CRC5 register (b: the next bit in the order sent).
function automatic [4:0] crc5_bit(input [4:0] r, input b);
    crc5_bit = {r[3:0], 1'b0} ^ ((r[4] ^ b) ? CRC5_POLY : 5'd0);
endfunction

// The CRC5 field of a token's or SOF's 11 bits (bit 0 sent first: a token's {endp, addr}): the
// value whose bit 4 is sent first (after field bit 10).
function automatic [4:0] crc5_of(input [10:0] field);
    integer i;
    reg [4:0] r;
    begin
        r = 5'b11111;
        for (i = 0; i < 11; i = i + 1) r = crc5_bit(r, field[i]);
        crc5_of = ~r;
    end
endfunction

// A token's two bytes after its PID (8.4.1): {endp, addr} bit 0 first, then the CRC5 field, its
// bit 4 first. Byte 2, LSB first: endp[3:1], then crc[4], crc[3], ..., crc[0].
function automatic [15:0] token_bytes(input [6:0] addr, input [3:0] endp);
    reg [10:0] f;
    reg [4:0] c;
    begin
        f = {endp, addr};
        c = crc5_of(f);
        token_bytes = {c[0], c[1], c[2], c[3], c[4], f[10:0]};   // {byte 2, byte 1}
    end
endfunction

// A received token's 16 bits after its PID ({byte 2, byte 1}, bit 0 received first) through the
// CRC5 register: CRC5_RESIDUAL when the field and its CRC agree.
function automatic [4:0] crc5_check(input [15:0] rx);
    integer i;
    reg [4:0] r;
    begin
        r = 5'b11111;
        for (i = 0; i < 16; i = i + 1) r = crc5_bit(r, rx[i]);
        crc5_check = r;
    end
endfunction

// One byte (sent LSB first) through the CRC16 register.
function automatic [15:0] crc16_byte(input [15:0] r, input [7:0] d);
    integer i;
    reg [15:0] x;
    begin
        x = r;
        for (i = 0; i < 8; i = i + 1) x = {x[14:0], 1'b0} ^ ((x[15] ^ d[i]) ? CRC16_POLY : 16'd0);
        crc16_byte = x;
    end
endfunction

// The CRC16 field's two bytes from the register after the data ({second, first}): the complement,
// its bit 15 sent first, so the first byte (LSB first) holds bits 15..8 reversed.
function automatic [15:0] crc16_field(input [15:0] r);
    integer i;
    reg [15:0] c, f;
    begin
        c = ~r;
        for (i = 0; i < 16; i = i + 1) f[i] = c[15 - i];
        crc16_field = f;
    end
endfunction

// Greatest common divisor, for the bit timing's reduced fraction SYS_HZ / USB_LS_BIT_HZ (an
// elaboration-time function: Euclid takes fewer than 48 steps on 32-bit operands).
function automatic integer gcd(input integer a, input integer b);
    integer x, y, t, i;
    begin
        x = a;
        y = b;
        for (i = 0; i < 48; i = i + 1) begin
            if (y != 0) begin
                t = x % y;
                x = y;
                y = t;
            end
        end
        gcd = x;
    end
endfunction

// The system clocks the line layer accepts (usb_ls_tx, usb_ls_rx refuse others at elaboration).
// The transmitter puts every bit boundary on the system clock nearest its ideal time (a
// fractional step of USB_LS_BIT_HZ / SYS_HZ): with SYS_HZ / USB_LS_BIT_HZ = n + p/q in lowest
// terms, the boundaries' errors take q values spread over (q-1)/q of a clock, so the time between
// any two transitions is off by at most (q-1)/(q * SYS_HZ) from its ideal N bit times. That must
// fit the low-speed source jitter of a host's (downstream) port, +-14 ns for paired transitions
// (TDDJ2; +-25 ns to the next transition, TDDJ1): LS_JITTER_PS. And the receiver wants at least
// 16 clocks a bit (LS_MIN_SYS_HZ): 24 MHz. 50 MHz (q = 3): 13.3 ns, accepted; 48, 60, 72, 96 MHz
// (q = 1): exact; 40 MHz (q = 3): 16.7 ns, refused; any SYS_HZ above 71.43 MHz: under a clock.
localparam integer LS_JITTER_PS = 14_000;
localparam integer LS_MIN_SYS_HZ = 24_000_000;
function automatic ls_sys_hz_ok(input integer sys_hz);
    reg [63:0] q, span_num, span_den;
    begin
        q = {32'd0, USB_LS_BIT_HZ} / {32'd0, gcd(sys_hz, USB_LS_BIT_HZ)};
        span_num = (q - 64'd1) * 64'd1_000_000_000_000;        // span = num / den ps
        span_den = q * {32'd0, sys_hz};
        ls_sys_hz_ok = sys_hz >= LS_MIN_SYS_HZ
                       && (span_num + span_den - 64'd1) / span_den <= {32'd0, LS_JITTER_PS};  // ceil
    end
endfunction
endpackage

`default_nettype wire
