// soc_uart_check: the harness of soc_uart's formal proof (soc_rtl/soc_uart.v, whose `ifdef FORMAL
// block holds the FIFO invariants and the two-tracked-bytes properties; tests/formal/soc_uart.sby).
//
// Small build: CLK_HZ 4, BAUD 1 (DIV 4 clocks a bit, the least soc_uart allows), RX_DEPTH and
// TX_DEPTH 4 (parameters). Environment (assumed): rst in the first clock, then at any clock; the
// Wishbone master (classic, one request at a time) holds cyc, stb, we, adr and dat_w from a
// request's first clock until its wb_ack or wb_err; the serial line uart_rx_async is free.
// Properties from the ports (asserted): wb_ack and wb_err never together; every request answered
// by exactly one of them in the clock after its first, and by nothing else (so each DATA write
// pushes once and each DATA read pops once); wb_err exactly for an offset outside DATA, STATUS,
// ERRORS, DIVIDER. Covers: a STATUS read that reports the TX FIFO full; a DATA read that returns a
// byte; an ERRORS read that shows an overrun.
`default_nettype none

module soc_uart_check #(
    parameter integer RX_DEPTH = 4,
    parameter integer TX_DEPTH = 4
) (
    input wire       clk,
    input wire       rst,
    input wire       wb_cyc,
    input wire       wb_stb,
    input wire       wb_we,
    input wire [7:2] wb_adr,
    input wire [7:0] wb_dat_w,
    input wire       uart_rx_async
);
    wire [31:0] wb_dat_r;
    wire        wb_ack, wb_err, uart_tx;
    soc_uart #(.CLK_HZ(4), .BAUD(1), .RX_DEPTH(RX_DEPTH), .TX_DEPTH(TX_DEPTH)) dut (
        .clk(clk), .rst(rst),
        .wb_cyc(wb_cyc), .wb_stb(wb_stb), .wb_we(wb_we), .wb_adr(wb_adr), .wb_dat_w(wb_dat_w),
        .wb_dat_r(wb_dat_r), .wb_ack(wb_ack), .wb_err(wb_err),
        .uart_rx_async(uart_rx_async), .uart_tx(uart_tx)
    );

    reg past_valid = 1'b0;
    always @(posedge clk) past_valid <= 1'b1;
    wire req = wb_cyc && wb_stb;
    wire [7:0] off = {wb_adr, 2'b00};
    wire known = off == soc_pkg::SOC_UART_REG_DATA || off == soc_pkg::SOC_UART_REG_STATUS
              || off == soc_pkg::SOC_UART_REG_ERRORS || off == soc_pkg::SOC_UART_REG_DIVIDER;

    // The bus rules: reset first; a request held until its answer.
    always @(*) if (!past_valid) assume(rst);
    always @(posedge clk) begin
        if (past_valid && !$past(rst) && $past(req && !wb_ack && !wb_err)) begin
            assume(req && wb_we == $past(wb_we) && wb_adr == $past(wb_adr)
                   && wb_dat_w == $past(wb_dat_w));
        end
    end

    // A request's first clock: a request, not the continuation of one still unanswered.
    reg pending = 1'b0;  // the previous clock had a request not yet answered
    always @(posedge clk) pending <= !rst && req && !wb_ack && !wb_err;
    wire first = req && !pending;
    always @(*) if (past_valid) assert(!(wb_ack && wb_err));
    always @(posedge clk) begin
        if (past_valid && !$past(rst)) begin
            assert(wb_ack == $past(first && known));
            assert(wb_err == $past(first && !known));
        end
    end

    // Covers, at the ports.
    reg [7:0] off_q = 8'd0;   // the offset of the request answered now
    reg       we_q = 1'b0;
    always @(posedge clk) begin
        off_q <= off;
        we_q <= wb_we;
    end
    always @(*) begin
        if (past_valid && wb_ack && !we_q) begin
            cover(off_q == soc_pkg::SOC_UART_REG_STATUS
                  && wb_dat_r[soc_pkg::SOC_UART_STATUS_TX_FULL_LSB]);
            cover(off_q == soc_pkg::SOC_UART_REG_DATA && wb_dat_r[soc_pkg::SOC_UART_DATA_VALID_LSB]);
            cover(off_q == soc_pkg::SOC_UART_REG_ERRORS
                  && wb_dat_r[soc_pkg::SOC_UART_ERRORS_OVERRUN_LSB +: 16] != 16'd0);
        end
    end
endmodule

`default_nettype wire
