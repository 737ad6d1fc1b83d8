// usb_line_top: the test harness's top for tests/usb/line_tb.cpp: usb_ls_tx and usb_ls_rx side by
// side, each with its own ports; the testbench connects the bus (the transmitter's pins, a pull-up,
// or its own reference waveform) to the receiver's inputs, so a test can loop one into the other
// or drive the receiver alone.
`default_nettype none

module usb_line_top #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT
) (
    input  wire        clk,
    input  wire        rst,
    // usb_ls_tx
    input  wire        tx_valid,
    output wire        tx_ready,
    input  wire [7:0]  tx_data,
    input  wire        tx_last,
    input  wire        eop_start,
    input  wire        reset_start,
    input  wire [23:0] reset_clks,
    output wire        tx_idle,
    output wire        tx_done,
    output wire        tx_underrun,
    output wire        usb_dp_out,
    output wire        usb_dn_out,
    output wire        usb_oe,
    // usb_ls_rx
    input  wire        usb_dp_in,
    input  wire        usb_dn_in,
    input  wire        tx_active,
    output wire [1:0]  rx_line,
    output wire [7:0]  rx_idle_bits,
    output wire        rx_timeout,
    output wire        rx_babble,
    output wire        rx_start,
    output wire        rx_valid,
    output wire [7:0]  rx_data,
    output wire        rx_end,
    output wire        rx_err_stuff,
    output wire        rx_err_align,
    output wire        rx_err_se0,
    output wire        rx_err_long
);
    usb_ls_tx #(.SYS_HZ(SYS_HZ), .RESET_W(24)) u_tx (
        .clk(clk), .rst(rst),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last),
        .eop_start(eop_start), .reset_start(reset_start), .reset_clks(reset_clks),
        .tx_idle(tx_idle), .tx_done(tx_done), .tx_underrun(tx_underrun),
        .usb_dp_out(usb_dp_out), .usb_dn_out(usb_dn_out), .usb_oe(usb_oe)
    );
    usb_ls_rx #(.SYS_HZ(SYS_HZ)) u_rx (
        .clk(clk), .rst(rst),
        .usb_dp_in(usb_dp_in), .usb_dn_in(usb_dn_in), .tx_active(tx_active),
        .rx_line(rx_line), .rx_idle_bits(rx_idle_bits), .rx_timeout(rx_timeout), .rx_babble(rx_babble),
        .rx_start(rx_start), .rx_valid(rx_valid), .rx_data(rx_data), .rx_end(rx_end),
        .rx_err_stuff(rx_err_stuff), .rx_err_align(rx_err_align), .rx_err_se0(rx_err_se0),
        .rx_err_long(rx_err_long)
    );
endmodule

`default_nettype wire
