// usb_ls_tx_check: the harness of usb_ls_tx's formal proof (soc_rtl/usb/usb_ls_tx.v, whose
// `ifdef FORMAL block holds the observer of the line and the invariants; tests/formal/usb_ls_tx.sby).
//
// Small build: SYS_HZ 5 MHz (10/3 clocks a bit: bits of 3 and 4 clocks, the fractional step's three
// phases; below the SYS_HZ the module accepts, whose elaboration check is left out under FORMAL;
// the covers at 3 MHz, 2 clocks a bit, for short traces), RESET_W 3. Environment (assumed): rst in the first clock, then at any clock; the stream holds
// tx_valid, tx_data and tx_last from a clock with tx_valid until the byte is taken (valid/ready);
// reset_clks at least 1 with reset_start; eop_start, reset_start and the stream otherwise free.
`default_nettype none

module usb_ls_tx_check #(
    parameter integer SYS_HZ = 5_000_000
) (
    input wire       clk,
    input wire       rst,
    input wire       tx_valid,
    input wire [7:0] tx_data,
    input wire       tx_last,
    input wire       eop_start,
    input wire       reset_start,
    input wire [2:0] reset_clks
);
    wire tx_ready, tx_idle, tx_done, tx_underrun, usb_dp_out, usb_dn_out, usb_oe;
    usb_ls_tx #(.SYS_HZ(SYS_HZ), .RESET_W(3)) dut (
        .clk(clk), .rst(rst),
        .tx_valid(tx_valid), .tx_ready(tx_ready), .tx_data(tx_data), .tx_last(tx_last),
        .eop_start(eop_start), .reset_start(reset_start), .reset_clks(reset_clks),
        .tx_idle(tx_idle), .tx_done(tx_done), .tx_underrun(tx_underrun),
        .usb_dp_out(usb_dp_out), .usb_dn_out(usb_dn_out), .usb_oe(usb_oe)
    );

    reg past_valid = 1'b0;
    always @(posedge clk) past_valid <= 1'b1;
    always @(*) if (!past_valid) assume(rst);
    always @(*) if (reset_start) assume(reset_clks != 3'd0);
    always @(posedge clk) begin
        if (past_valid && !$past(rst) && $past(tx_valid && !tx_ready))
            assume(tx_valid && tx_data == $past(tx_data) && tx_last == $past(tx_last));
    end
    // Never both lines high (SE1), and the lines released exactly when idle or flushing in idle.
    always @(*) begin
        if (past_valid && !rst) begin
            assert(!(usb_oe && usb_dp_out && usb_dn_out));
            if (tx_idle) assert(!usb_oe);
        end
    end
endmodule

`default_nettype wire
