// tiny_tb: the placed-and-routed netlist of tests/boards/netlist_routed/tiny.v (nextpnr-ecp5's
// --write JSON through cosim/netlist/routed_json.py and yosys' write_verilog, module tiny_routed; its
// cells simulated by cosim/netlist/ecp5_routed) against the RTL itself (module tiny, its ODDRX1F by
// cosim/netlist/ecp5/ODDRX1F.v), driven alike. Run by tests/boards/netlist_routed_cells.sh.
// Every output pin of both is compared in both halves of each 25 MHz clock period (the ODDRX1F
// outputs send one bit in each), from the start (the flip-flops' and RAM's initial values) over
// CYCLES periods of seeded random input: the reset button pressed at the start and now and then, the
// serial input random. Prints "netlist_routed: ok ..." or stops at the first differences with $fatal;
// also fails when an output never toggles (the comparison would prove little).
`timescale 1ps / 1ps
`default_nettype none

module tiny_tb;
`ifndef CYCLES
    localparam int CYCLES = 20000;
`else
    localparam int CYCLES = `CYCLES;
`endif
    localparam int HALF = 20000;    // ps: 25 MHz

    reg clk = 1'b0, btn = 1'b1, txd = 1'b0;
    wire [7:0] led_r, led_n;
    wire [1:0] dp_r, dp_n;
    wire rxd_r, rxd_n, gpio_r, gpio_n;

    tiny u_rtl (.clk_25mhz(clk), .btn_fire1(btn), .ftdi_txd(txd), .led(led_r), .ftdi_rxd(rxd_r),
                .wifi_gpio0(gpio_r), .gpdi_dp(dp_r));
    tiny_routed u_net (.clk_25mhz(clk), .btn_fire1(btn), .ftdi_txd(txd), .led(led_n), .ftdi_rxd(rxd_n),
                       .wifi_gpio0(gpio_n), .gpdi_dp(dp_n));

    wire [11:0] pins_r = {led_r, rxd_r, gpio_r, dp_r};
    wire [11:0] pins_n = {led_n, rxd_n, gpio_n, dp_n};

    always #(HALF) clk = ~clk;

    int unsigned seed = 32'h1234_5678;
    int compared = 0, differed = 0;
    reg [11:0] first, toggled = 12'd0;

    task automatic compare(input string phase, input int cycle);
        compared++;
        if (compared == 1)
            first = pins_r;
        toggled |= pins_r ^ first;
        if (pins_r !== pins_n) begin
            differed++;
            $display("netlist_routed: cycle %0d (%s half): RTL led %02h rxd %b gpio %b dp %b, netlist led %02h rxd %b gpio %b dp %b",
                     cycle, phase, led_r, rxd_r, gpio_r, dp_r, led_n, rxd_n, gpio_n, dp_n);
            if (differed >= 5)
                $fatal(1, "netlist_routed: the routed netlist differs from the RTL");
        end
    endtask

    initial begin : run
        int cycle;
        #(HALF / 2) compare("low", -1);     // the initial values, before the first edge
        for (cycle = 0; cycle < CYCLES; cycle++) begin
            @(posedge clk);
            #(HALF / 2) compare("high", cycle);
            @(negedge clk);
            // new inputs in the low half, well away from the rising edge that registers them
            btn = cycle < 4 || ($urandom(seed) % 211 == 0);
            seed = seed * 1103515245 + 12345;
            txd = seed[17];
            #(HALF / 2) compare("low", cycle);
        end
        if (differed != 0)
            $fatal(1, "netlist_routed: the routed netlist differs from the RTL");
        if (toggled != 12'hfff)
            $fatal(1, "netlist_routed: pins that never toggled: %b (led, rxd, gpio, dp)", ~toggled);
        $display("netlist_routed: ok: %0d cycles, %0d comparisons of 12 pins, all equal; every pin toggled",
                 CYCLES, compared);
        $finish;
    end
endmodule

`default_nettype wire
