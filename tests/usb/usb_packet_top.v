// usb_packet_top: the test harness's top for tests/usb/packet_tb.cpp: usb_ls_packet_tx into
// usb_ls_tx, and usb_ls_rx into usb_ls_packet_rx; the testbench connects the bus (the
// transmitter's pins with the pull-up's J, or its own reference waveform) to the receiver.
`default_nettype none

module usb_packet_top #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT
) (
    input  wire       clk,
    input  wire       rst,
    // usb_ls_packet_tx
    input  wire       cmd_valid,
    output wire       cmd_ready,
    input  wire [3:0] cmd_pid,
    input  wire [6:0] cmd_addr,
    input  wire [3:0] cmd_endp,
    input  wire [3:0] cmd_len,
    output wire       pkt_busy,
    input  wire       pl_valid,
    output wire       pl_ready,
    input  wire [7:0] pl_data,
    // usb_ls_tx
    output wire       tx_idle,
    output wire       tx_underrun,
    output wire       usb_dp_out,
    output wire       usb_dn_out,
    output wire       usb_oe,
    // usb_ls_rx
    input  wire       usb_dp_in,
    input  wire       usb_dn_in,
    input  wire       tx_active,
    // usb_ls_packet_rx
    output wire       dat_valid,
    output wire [7:0] dat_data,
    output wire       pkt_valid,
    output wire [3:0] pkt_pid,
    output wire [3:0] pkt_len,
    output wire       pkt_ok,
    output wire       err_line,
    output wire       err_pid,
    output wire       err_len,
    output wire       err_crc
);
    wire       tx_valid, tx_ready, tx_last, tx_done;
    wire [7:0] tx_data;
    usb_ls_packet_tx #(.LEN_W(4)) u_ptx (
        .clk(clk), .rst(rst),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_pid(cmd_pid), .cmd_addr(cmd_addr),
        .cmd_endp(cmd_endp), .cmd_len(cmd_len), .pkt_busy(pkt_busy),
        .pl_valid(pl_valid), .pl_ready(pl_ready), .pl_data(pl_data),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last)
    );
    usb_ls_tx #(.SYS_HZ(SYS_HZ)) u_tx (
        .clk(clk), .rst(rst),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last),
        .eop_start(1'b0), .reset_start(1'b0), .reset_clks(24'd0),
        .tx_idle(tx_idle), .tx_done(tx_done), .tx_underrun(tx_underrun),
        .usb_dp_out(usb_dp_out), .usb_dn_out(usb_dn_out), .usb_oe(usb_oe)
    );
    wire       rx_start, rx_valid, rx_end, rx_err_stuff, rx_err_align, rx_err_se0, rx_err_long;
    wire       rx_timeout, rx_babble;
    wire [1:0] rx_line;
    wire [7:0] rx_data, rx_idle_bits;
    usb_ls_rx #(.SYS_HZ(SYS_HZ)) u_rx (
        .clk(clk), .rst(rst),
        .usb_dp_in(usb_dp_in), .usb_dn_in(usb_dn_in), .tx_active(tx_active),
        .rx_line(rx_line), .rx_idle_bits(rx_idle_bits), .rx_timeout(rx_timeout), .rx_babble(rx_babble),
        .rx_start(rx_start), .rx_valid(rx_valid), .rx_data(rx_data), .rx_end(rx_end),
        .rx_err_stuff(rx_err_stuff), .rx_err_align(rx_err_align), .rx_err_se0(rx_err_se0),
        .rx_err_long(rx_err_long)
    );
    usb_ls_packet_rx u_prx (
        .clk(clk), .rst(rst),
        .rx_start(rx_start), .rx_valid(rx_valid), .rx_data(rx_data), .rx_end(rx_end),
        .rx_err_stuff(rx_err_stuff), .rx_err_align(rx_err_align), .rx_err_se0(rx_err_se0),
        .rx_err_long(rx_err_long),
        .dat_valid(dat_valid), .dat_data(dat_data),
        .pkt_valid(pkt_valid), .pkt_pid(pkt_pid), .pkt_len(pkt_len), .pkt_ok(pkt_ok),
        .err_line(err_line), .err_pid(err_pid), .err_len(err_len), .err_crc(err_crc)
    );
endmodule

`default_nettype wire
