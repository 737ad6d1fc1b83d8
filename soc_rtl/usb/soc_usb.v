// soc_usb: the USB low-speed host's register block (USB in contract/soc-memory-map.md), a Wishbone
// B4 slave over usb_ls_host (docs/usb.md, "The register block"), in soc_top when USB_HOST = 1;
// tested alone (tests/usb/regs.sh) and in the SoC (tests/soc/usb_keys.sh).
//
// Contract (bus): every request is answered in the next clock, once: wb_ack for the registers of the
// map (CTRL, STATUS, KEY, KBD and the counters), wb_err for any other offset of the window. Writes
// honour wb_sel on CTRL (ENABLE's byte lane); writes to the ro registers are ignored (acked). Effects
// happen in a request's first clock.
//   CTRL: ENABLE, 0 after reset; drives usb_ls_host's enable (low: nothing driven, the host held in
//         reset, the keys held released as events, the counters kept).
//   KEY: a read returns the oldest key event ({PRESS, VALID, USAGE}) and pops it (usb_ls_host's
//        ev_ready high for that one clock), or 0 when none is held. One pop per request: the
//        request's later clocks (the ack's) are not accepted.
//   STATUS, KBD, the counters: usb_ls_host's outputs as they are in the request's first clock.
// Contract (pins): usb_ls_host's, passed through (usb_dp_in/usb_dn_in asynchronous).
`default_nettype none

module soc_usb #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // clk's frequency, Hz
    parameter [6:0]   DEV_ADDR = 7'd1,       // usb_ls_host's parameters, passed through
    parameter integer CFG_MAX = 128,
    parameter integer FIFO_DEPTH = 16,       // key events held (a power of 2)
    parameter integer ATTACH_MS = 101,
    parameter integer RESET_MS = 20,
    parameter integer RECOVERY_MS = 11,
    parameter integer ADDR_RECOVERY_MS = 3,
    parameter integer ATTEMPT_BITS = 340
) (
    input  wire        clk,
    input  wire        rst,           // synchronous, active high
    // Wishbone B4 slave (the USB window)
    input  wire        wb_cyc,
    input  wire        wb_stb,        // selected by the decoder
    input  wire        wb_we,
    input  wire [7:2]  wb_adr,        // word offset in the window
    input  wire [31:0] wb_dat_w,
    input  wire [3:0]  wb_sel,        // byte lanes of a write
    output reg  [31:0] wb_dat_r,      // valid with wb_ack
    output wire        wb_ack,
    output wire        wb_err,
    // the USB port
    input  wire        usb_dp_in,     // asynchronous
    input  wire        usb_dn_in,
    output wire        usb_dp_out,
    output wire        usb_dn_out,
    output wire        usb_oe
);
    localparam [7:0] OFF_CTRL       = soc_pkg::SOC_USB_REG_CTRL;
    localparam [7:0] OFF_STATUS     = soc_pkg::SOC_USB_REG_STATUS;
    localparam [7:0] OFF_KEY        = soc_pkg::SOC_USB_REG_KEY;
    localparam [7:0] OFF_KBD        = soc_pkg::SOC_USB_REG_KBD;
    localparam [7:0] OFF_CRC_ERRORS = soc_pkg::SOC_USB_REG_CRC_ERRORS;
    localparam [7:0] OFF_TIMEOUTS   = soc_pkg::SOC_USB_REG_TIMEOUTS;
    localparam [7:0] OFF_RETRIES    = soc_pkg::SOC_USB_REG_RETRIES;
    localparam [7:0] OFF_NAKS       = soc_pkg::SOC_USB_REG_NAKS;
    localparam [7:0] OFF_STALLS     = soc_pkg::SOC_USB_REG_STALLS;
    localparam [7:0] OFF_ATTACHES   = soc_pkg::SOC_USB_REG_ATTACHES;
    localparam [7:0] OFF_DETACHES   = soc_pkg::SOC_USB_REG_DETACHES;
    localparam [7:0] OFF_WRONG_LEN  = soc_pkg::SOC_USB_REG_WRONG_LEN;
    localparam [7:0] OFF_OVERFLOWS  = soc_pkg::SOC_USB_REG_OVERFLOWS;
    localparam [7:0] OFF_REENUMS    = soc_pkg::SOC_USB_REG_REENUMS;
    localparam [7:0] OFF_ROLLOVERS  = soc_pkg::SOC_USB_REG_ROLLOVERS;
    localparam integer ENABLE_LSB   = soc_pkg::SOC_USB_CTRL_ENABLE_LSB;
    localparam integer ENABLE_LANE  = ENABLE_LSB / 8;

    // The field widths the host's outputs have (checked): the contract's fields must hold them.
    generate if (soc_pkg::SOC_USB_CTRL_ENABLE_WIDTH != 1 || soc_pkg::SOC_USB_STATUS_STATE_WIDTH != 3
                 || soc_pkg::SOC_USB_STATUS_ADDR_WIDTH != 7 || soc_pkg::SOC_USB_KEY_USAGE_WIDTH != 8
                 || soc_pkg::SOC_USB_KEY_VALID_WIDTH != 1 || soc_pkg::SOC_USB_KEY_PRESS_WIDTH != 1
                 || soc_pkg::SOC_USB_KBD_EP_WIDTH != 8 || soc_pkg::SOC_USB_KBD_MPS_WIDTH != 8
                 || soc_pkg::SOC_USB_KBD_INTERVAL_WIDTH != 8
                 || soc_pkg::SOC_USB_CRC_ERRORS_COUNT_WIDTH != 16 || soc_pkg::SOC_USB_TIMEOUTS_COUNT_WIDTH != 16
                 || soc_pkg::SOC_USB_RETRIES_COUNT_WIDTH != 16 || soc_pkg::SOC_USB_NAKS_COUNT_WIDTH != 16
                 || soc_pkg::SOC_USB_STALLS_COUNT_WIDTH != 16 || soc_pkg::SOC_USB_ATTACHES_COUNT_WIDTH != 16
                 || soc_pkg::SOC_USB_DETACHES_COUNT_WIDTH != 16 || soc_pkg::SOC_USB_WRONG_LEN_COUNT_WIDTH != 16
                 || soc_pkg::SOC_USB_OVERFLOWS_COUNT_WIDTH != 16 || soc_pkg::SOC_USB_REENUMS_COUNT_WIDTH != 16
                 || soc_pkg::SOC_USB_ROLLOVERS_COUNT_WIDTH != 16) begin : g_bad_fields
        $error("soc_usb: the USB fields of contract/soc_map.toml differ from usb_ls_host's widths");
    end endgenerate

    // ---- bus: registered answer, one clock after the request ----
    reg  ack_q, err_q;
    wire req = wb_cyc && wb_stb;
    wire accept = req && !ack_q && !err_q;   // a request's first clock: its effects happen here
    wire [7:0] off = {wb_adr, 2'b00};
    wire known = off == OFF_CTRL || off == OFF_STATUS || off == OFF_KEY || off == OFF_KBD
              || off == OFF_CRC_ERRORS || off == OFF_TIMEOUTS || off == OFF_RETRIES || off == OFF_NAKS
              || off == OFF_STALLS || off == OFF_ATTACHES || off == OFF_DETACHES || off == OFF_WRONG_LEN
              || off == OFF_OVERFLOWS || off == OFF_REENUMS || off == OFF_ROLLOVERS;
    wire wr = accept && wb_we;
    wire rd = accept && !wb_we;
    assign wb_ack = ack_q && req;
    assign wb_err = err_q && req;

    // ---- the host ----
    reg         enable_q;
    wire        ev_valid, ev_press;
    wire [7:0]  ev_usage;
    wire [2:0]  state;
    wire [6:0]  dev_addr;
    wire [15:0] cnt_crc, cnt_timeout, cnt_retry, cnt_nak, cnt_stall, cnt_attach, cnt_detach;
    wire [15:0] cnt_wrong_len, cnt_overflow, cnt_reenum, cnt_rollover;
    wire [7:0]  kbd_ep, kbd_mps, kbd_interval;
    wire        pop = rd && off == OFF_KEY && ev_valid;   // one clock per KEY read
    usb_ls_host #(
        .SYS_HZ(SYS_HZ), .DEV_ADDR(DEV_ADDR), .CFG_MAX(CFG_MAX), .FIFO_DEPTH(FIFO_DEPTH),
        .ATTACH_MS(ATTACH_MS), .RESET_MS(RESET_MS), .RECOVERY_MS(RECOVERY_MS),
        .ADDR_RECOVERY_MS(ADDR_RECOVERY_MS), .ATTEMPT_BITS(ATTEMPT_BITS)
    ) u_host (
        .clk(clk), .rst(rst), .enable(enable_q),
        .usb_dp_in(usb_dp_in), .usb_dn_in(usb_dn_in),
        .usb_dp_out(usb_dp_out), .usb_dn_out(usb_dn_out), .usb_oe(usb_oe),
        .ev_valid(ev_valid), .ev_ready(pop), .ev_press(ev_press), .ev_usage(ev_usage),
        .state(state), .dev_addr(dev_addr),
        .cnt_crc(cnt_crc), .cnt_timeout(cnt_timeout), .cnt_retry(cnt_retry), .cnt_nak(cnt_nak),
        .cnt_stall(cnt_stall), .cnt_attach(cnt_attach), .cnt_detach(cnt_detach),
        .cnt_wrong_len(cnt_wrong_len), .cnt_overflow(cnt_overflow), .cnt_reenum(cnt_reenum),
        .cnt_rollover(cnt_rollover),
        .kbd_ep(kbd_ep), .kbd_mps(kbd_mps), .kbd_interval(kbd_interval)
    );

    // The registers' words, fields placed by the contract's positions.
    wire [31:0] ctrl_word   = {31'd0, enable_q} << ENABLE_LSB;
    wire [31:0] status_word = ({29'd0, state} << soc_pkg::SOC_USB_STATUS_STATE_LSB)
                            | ({25'd0, dev_addr} << soc_pkg::SOC_USB_STATUS_ADDR_LSB);
    wire [31:0] key_word    = ev_valid ? (({24'd0, ev_usage} << soc_pkg::SOC_USB_KEY_USAGE_LSB)
                                        | (32'd1 << soc_pkg::SOC_USB_KEY_VALID_LSB)
                                        | ({31'd0, ev_press} << soc_pkg::SOC_USB_KEY_PRESS_LSB)) : 32'd0;
    wire [31:0] kbd_word    = ({24'd0, kbd_ep} << soc_pkg::SOC_USB_KBD_EP_LSB)
                            | ({24'd0, kbd_mps} << soc_pkg::SOC_USB_KBD_MPS_LSB)
                            | ({24'd0, kbd_interval} << soc_pkg::SOC_USB_KBD_INTERVAL_LSB);
    function automatic [31:0] count(input [15:0] c, input integer lsb);
        count = {16'd0, c} << lsb;
    endfunction

    // Of a write, only ENABLE's bit and lane are used.
    wire unused_dat_w = &{1'b0, wb_dat_w, wb_sel};

    always @(posedge clk) begin
        if (rst) begin
            ack_q <= 1'b0;
            err_q <= 1'b0;
            wb_dat_r <= 32'd0;
            enable_q <= 1'b0;
        end else begin
            ack_q <= accept && known;
            err_q <= accept && !known;
            if (rd) begin
                case (off)
                    OFF_CTRL:       wb_dat_r <= ctrl_word;
                    OFF_STATUS:     wb_dat_r <= status_word;
                    OFF_KEY:        wb_dat_r <= key_word;
                    OFF_KBD:        wb_dat_r <= kbd_word;
                    OFF_CRC_ERRORS: wb_dat_r <= count(cnt_crc, soc_pkg::SOC_USB_CRC_ERRORS_COUNT_LSB);
                    OFF_TIMEOUTS:   wb_dat_r <= count(cnt_timeout, soc_pkg::SOC_USB_TIMEOUTS_COUNT_LSB);
                    OFF_RETRIES:    wb_dat_r <= count(cnt_retry, soc_pkg::SOC_USB_RETRIES_COUNT_LSB);
                    OFF_NAKS:       wb_dat_r <= count(cnt_nak, soc_pkg::SOC_USB_NAKS_COUNT_LSB);
                    OFF_STALLS:     wb_dat_r <= count(cnt_stall, soc_pkg::SOC_USB_STALLS_COUNT_LSB);
                    OFF_ATTACHES:   wb_dat_r <= count(cnt_attach, soc_pkg::SOC_USB_ATTACHES_COUNT_LSB);
                    OFF_DETACHES:   wb_dat_r <= count(cnt_detach, soc_pkg::SOC_USB_DETACHES_COUNT_LSB);
                    OFF_WRONG_LEN:  wb_dat_r <= count(cnt_wrong_len, soc_pkg::SOC_USB_WRONG_LEN_COUNT_LSB);
                    OFF_OVERFLOWS:  wb_dat_r <= count(cnt_overflow, soc_pkg::SOC_USB_OVERFLOWS_COUNT_LSB);
                    OFF_REENUMS:    wb_dat_r <= count(cnt_reenum, soc_pkg::SOC_USB_REENUMS_COUNT_LSB);
                    OFF_ROLLOVERS:  wb_dat_r <= count(cnt_rollover, soc_pkg::SOC_USB_ROLLOVERS_COUNT_LSB);
                    default:        wb_dat_r <= 32'd0;   // refused offsets
                endcase
            end
            if (wr && off == OFF_CTRL && wb_sel[ENABLE_LANE]) enable_q <= wb_dat_w[ENABLE_LSB];
        end
    end
endmodule

`default_nettype wire
