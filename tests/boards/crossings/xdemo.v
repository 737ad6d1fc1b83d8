// xdemo: the fixture of tests/boards/crossings.sh — a small design on two clocks of one EHXPLLL
// (a = CLKOP, b = CLKOS) with one crossing of each sort synth/crossings.py tells apart:
//   sync_b      a toggle of domain a through two flops (declared: sync2)
//   rst_sync_b  the PLL's LOCK through two flops (declared: reset, from async)
//   ram         a block RAM written on a, read on b (declared: dual-clock-ram)
//   lram        a LUT RAM written on a, read asynchronously into lram_b on b (declared: accepted)
//   raw_b       a register of domain a sampled directly on b: the undeclared crossing
`default_nettype none

module xdemo (
    input  wire       clk_in,   // the oscillator, into the PLL only
    output wire [7:0] led
);
    wire clk_a, clk_b, locked;
    EHXPLLL #(
        .CLKI_DIV(1), .CLKFB_DIV(4), .FEEDBK_PATH("CLKOP"),
        .CLKOP_ENABLE("ENABLED"), .CLKOP_DIV(6), .CLKOP_CPHASE(6),
        .CLKOS_ENABLE("ENABLED"), .CLKOS_DIV(12), .CLKOS_CPHASE(12)
    ) u_pll (
        .CLKI(clk_in), .CLKFB(clk_a), .CLKOP(clk_a), .CLKOS(clk_b), .LOCK(locked),
        .RST(1'b0), .STDBY(1'b0), .PHASESEL0(1'b0), .PHASESEL1(1'b0), .PHASEDIR(1'b0),
        .PHASESTEP(1'b0), .PHASELOADREG(1'b0), .PLLWAKESYNC(1'b0),
        .ENCLKOP(1'b0), .ENCLKOS(1'b0), .ENCLKOS2(1'b0), .ENCLKOS3(1'b0)
    );

    // ---- domain a: a counter that writes both memories ----
    reg [9:0] cnt_a = 10'd0;
    reg toggle_a = 1'b0;
    reg [7:0] ram [0:1023];
    (* ram_style = "distributed" *) reg [3:0] lram [0:15];
    always @(posedge clk_a) begin
        cnt_a <= cnt_a + 10'd1;
        if (cnt_a == 10'd0) toggle_a <= ~toggle_a;
        ram[cnt_a] <= cnt_a[9:2];
        lram[cnt_a[3:0]] <= cnt_a[7:4];
    end

    // ---- domain b ----
    (* ASYNC_REG = "TRUE" *) reg [1:0] rst_sync_b = 2'b11;
    (* ASYNC_REG = "TRUE" *) reg [1:0] sync_b = 2'b00;
    reg raw_b = 1'b0;
    reg [9:0] addr_b = 10'd0;
    reg [7:0] rd_b = 8'd0;
    reg [3:0] lram_b = 4'd0;
    wire rst_b = rst_sync_b[1];
    always @(posedge clk_b) begin
        rst_sync_b <= {rst_sync_b[0], !locked};
        sync_b <= {sync_b[0], toggle_a};
        raw_b <= cnt_a[9];
        addr_b <= rst_b ? 10'd0 : addr_b + 10'd1;
        rd_b <= ram[addr_b];
        lram_b <= lram[addr_b[3:0]];
    end

    assign led = {rd_b[7:4] ^ lram_b, rd_b[3:2], sync_b[1], raw_b};
endmodule

`default_nettype wire
