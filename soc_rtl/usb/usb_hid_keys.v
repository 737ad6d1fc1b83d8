// usb_hid_keys: HID boot keyboard reports (HID 1.11 Appendix B.1: a modifier byte, a reserved
// byte, 6 key usages) to key events: each report is compared with the previous one.
//
// Contract (reports): rpt_valid with rpt_len and rpt_data (byte 0 in [7:0]), taken only while
// rpt_ready (idle; a report takes SCAN_STEPS + 1 clocks, and reports come bInterval >= 8 ms apart).
// A report of another length than 8 is ignored and pulses ev_wrong_len. A report with a key byte
// 0x01..0x03 (ErrorRollOver, POSTFail, ErrorUndefined: the keyboard's phantom state, HID Usage
// Tables 10) is ignored (no release storm), pulsing ev_rollover. rpt_clear (any time) is an
// all-keys-up report taken as soon as the scanner is idle: the releases of every key still held
// (the keyboard was detached or re-enumerated) so that the consumer never keeps a stuck key.
// Contract (events): per report, in this order: the releases (modifier bits 0..7 as usages
// 0xE0..0xE7 cleared, then the previous report's key usages absent from the new one, in their slot
// order), then the presses (modifier bits set, then the new report's key usages absent from the
// previous one, in slot order); one candidate per clock. Each event goes into a FIFO of FIFO_DEPTH
// entries read on ev_valid/ev_ready ({ev_press, ev_usage}); an event that finds it full is dropped
// and pulses ev_overflow (the caller counts it: nothing is dropped silently).
`default_nettype none

module usb_hid_keys #(
    parameter integer FIFO_DEPTH = 16,     // events buffered for a slow consumer (a power of 2)
    localparam integer A_W = $clog2(FIFO_DEPTH)
) (
    input  wire        clk,
    input  wire        rst,            // synchronous, active high
    // reports
    input  wire        rpt_valid,
    output wire        rpt_ready,
    input  wire [3:0]  rpt_len,
    input  wire [63:0] rpt_data,
    input  wire        rpt_clear,      // release every key held (kept until the scanner is idle)
    // events
    output wire        ev_valid,
    input  wire        ev_ready,
    output wire        ev_press,       // 1 press, 0 release
    output wire [7:0]  ev_usage,       // Keyboard/Keypad page usage (0xE0..0xE7: modifiers)
    // counters' pulses
    output reg         ev_wrong_len,
    output reg         ev_rollover,
    output reg         ev_overflow
);
    localparam integer SCAN_STEPS = 28;    // 8 modifier releases, 6 key releases, 8 + 6 presses
    reg [63:0] old_q, new_q;
    reg        scanning_q;
    reg [4:0]  step_q;
    reg        clear_q;

    assign rpt_ready = !scanning_q && !clear_q;

    function automatic in_keys(input [7:0] k, input [63:16] r);   // the 6 key bytes
        in_keys = k == r[23:16] || k == r[31:24] || k == r[39:32] || k == r[47:40]
               || k == r[55:48] || k == r[63:56];
    endfunction
    wire rollover = (rpt_data[23:16] != 0 && rpt_data[23:16] < 4) || (rpt_data[31:24] != 0 && rpt_data[31:24] < 4)
                 || (rpt_data[39:32] != 0 && rpt_data[39:32] < 4) || (rpt_data[47:40] != 0 && rpt_data[47:40] < 4)
                 || (rpt_data[55:48] != 0 && rpt_data[55:48] < 4) || (rpt_data[63:56] != 0 && rpt_data[63:56] < 4);

    // This step's candidate event.
    reg       c_valid, c_press;
    reg [7:0] c_usage;
    reg [2:0] m;
    reg [2:0] kslot;
    always @(*) begin
        c_valid = 1'b0;
        c_press = 1'b0;
        c_usage = 8'd0;
        m = step_q[2:0];
        kslot = 3'd0;
        if (step_q < 5'd8) begin
            c_valid = old_q[{3'd0, m}] && !new_q[{3'd0, m}];
            c_usage = {5'b11100, m};
        end else if (step_q < 5'd14) begin
            kslot = step_q[2:0];          // 8..13 -> slots 0..5
            c_usage = old_q[16 + kslot * 8 +: 8];
            c_valid = c_usage >= 8'd4 && !in_keys(c_usage, new_q[63:16]);
        end else if (step_q < 5'd22) begin
            m = step_q[2:0] - 3'd6;       // 14..21 -> bits 0..7
            c_press = 1'b1;
            c_valid = new_q[{3'd0, m}] && !old_q[{3'd0, m}];
            c_usage = {5'b11100, m};
        end else begin
            kslot = step_q[2:0] - 3'd6;   // 22..27 -> slots 0..5
            c_press = 1'b1;
            c_usage = new_q[16 + kslot * 8 +: 8];
            c_valid = c_usage >= 8'd4 && !in_keys(c_usage, old_q[63:16]);
        end
        c_valid = c_valid && scanning_q;
    end

    // The event FIFO.
    reg [8:0]   fifo_q [0:FIFO_DEPTH-1];
    reg [A_W:0] wr_q, rd_q;
    wire full = (wr_q - rd_q) == FIFO_DEPTH[A_W:0];
    assign ev_valid = wr_q != rd_q;
    assign {ev_press, ev_usage} = fifo_q[rd_q[A_W-1:0]];

    always @(posedge clk) begin
        if (c_valid && !full) fifo_q[wr_q[A_W-1:0]] <= {c_press, c_usage};
    end

    always @(posedge clk) begin
        if (rst) begin
            old_q <= 64'd0;
            new_q <= 64'd0;
            scanning_q <= 1'b0;
            step_q <= 5'd0;
            clear_q <= 1'b0;
            wr_q <= '0;
            rd_q <= '0;
            ev_wrong_len <= 1'b0;
            ev_rollover <= 1'b0;
            ev_overflow <= 1'b0;
        end else begin
            ev_wrong_len <= 1'b0;
            ev_rollover <= 1'b0;
            ev_overflow <= 1'b0;
            if (ev_valid && ev_ready) rd_q <= rd_q + 1'b1;
            if (c_valid) begin
                if (full) ev_overflow <= 1'b1;
                else wr_q <= wr_q + 1'b1;
            end
            if (rpt_clear) clear_q <= 1'b1;
            if (scanning_q) begin
                if (step_q == SCAN_STEPS[4:0] - 5'd1) begin
                    scanning_q <= 1'b0;
                    old_q <= new_q;
                end
                step_q <= step_q + 1'b1;
            end else if (clear_q) begin
                clear_q <= 1'b0;
                new_q <= 64'd0;
                step_q <= 5'd0;
                scanning_q <= 1'b1;
            end else if (rpt_valid) begin
                if (rpt_len != 4'd8) ev_wrong_len <= 1'b1;
                else if (rollover) ev_rollover <= 1'b1;
                else begin
                    new_q <= rpt_data;
                    step_q <= 5'd0;
                    scanning_q <= 1'b1;
                end
            end
        end
    end
endmodule

`default_nettype wire
