// ulx3s_top: the SoC on the Radiona ULX3S (LFE5U-85F) — the board's pins (boards/ulx3s/ulx3s.lpf),
// its one PLL and the four DDR output registers of the GPDI (DVI) connector around ulx3s_system.
//
// Contract: from the 25 MHz oscillator, ulx3s_pll makes the system clock (SYS_MHZ), the 25 MHz
// pixel clock and the 125 MHz TMDS clock; each TMDS channel leaves through an ODDRX1F (D0 after the
// rising edge, D1 after the falling one: 250 Mbit/s = 10 bits per 25 MHz pixel) on a gpdi_dp pin,
// whose complement the LVCMOS33D standard drives on the paired dn pin. The FT231X carries the
// UART (keys in, the firmware's text out). FIRE1 resets. wifi_gpio0 stays high so the ESP32 does
// not reset the FPGA. Only the primitives live here; the logic is in ulx3s_system. The GPU's build
// parameters (contract/gpu_build_params.vh) are passed through: a scene's manifest may size the
// buffers (VTX_CAP, TRI_CAP); ENABLE_WMASK costs 4 EBR, board.mk turns it off beside a depth buffer.
// This is the build without SDRAM (SOC_MEM=ram): the firmware in on-chip RAM, the SDRAM and flash
// ports of ulx3s_system idle; ulx3s_sdram_top is the build with them.
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_top_no_sdram.vh"
`default_nettype none

module ulx3s_top #(
    parameter integer SYS_MHZ = 50,                                // a divisor of 750 (ulx3s_pll)
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // the firmware's SOC_RAM_KIB
    parameter RAM_INIT = "",                                       // the firmware's RAM image
    parameter integer PROJ_UNIT = 1,                               // soc_top's: 1 = the projection unit
    `GPU_BUILD_PARAMS                                              // the GPU's (ulx3s_system)
) (
    input  wire       clk_25mhz,      // G2
    // FT231X USB serial
    input  wire       ftdi_txd,       // the FPGA receives (M1)
    output wire       ftdi_rxd,       // the FPGA transmits (L4)
    // buttons and LEDs
    input  wire       btn_fire1,      // R1, active high: reset
    output wire [7:0] led,
    // GPDI: blue, green, red, clock
    output wire [3:0] gpdi_dp,
    // ESP32
    output wire       wifi_gpio0      // held high
);
    wire clk_tmds, clk_pix, clk_sys, pll_locked;
    ulx3s_pll #(.SYS_MHZ(SYS_MHZ)) u_pll (
        .clk_25mhz (clk_25mhz),
        .clk_tmds  (clk_tmds),
        .clk_pix   (clk_pix),
        .clk_sys   (clk_sys),
        .locked    (pll_locked)
    );

    wire [3:0] tmds_d0, tmds_d1;
    wire       exit_valid;
    wire [7:0] exit_code;
    `SOC_TOP_NO_SDRAM_WIRES   // no SDRAM: ulx3s_system's SDRAM and flash ports (soc_rtl/soc_top_no_sdram.vh)
    wire       sdram_rst_idle;
    wire unused_sdram_rst = sdram_rst_idle;
    wire [2:0] usb_idle;
    wire unused_usb = |usb_idle;
    ulx3s_system #(
        .SYS_HZ       (SYS_MHZ * 1000000),
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        .PROJ_UNIT    (PROJ_UNIT),
        `GPU_BUILD_PARAMS_PASS
    ) u_system (
        .clk_sys    (clk_sys),
        .clk_pix    (clk_pix),
        .clk_tmds   (clk_tmds),
        .pll_locked (pll_locked),
        .btn_reset  (btn_fire1),
        .uart_rx    (ftdi_txd),
        .uart_tx    (ftdi_rxd),
        .led        (led),
        .tmds_d0    (tmds_d0),
        .tmds_d1    (tmds_d1),
        .sdram_rst  (sdram_rst_idle),
        `SOC_TOP_NO_SDRAM_PORTS,
        .usb_dp_in  (1'b0),       // no USB host in this build (USB_HOST 0): the outputs stay low
        .usb_dn_in  (1'b0),
        .usb_dp_out (usb_idle[0]),
        .usb_dn_out (usb_idle[1]),
        .usb_oe     (usb_idle[2]),
        .exit_valid (exit_valid),
        .exit_code  (exit_code)
    );
    wire unused_exit = exit_valid | (|exit_code);  // the board runs the firmware for ever

    genvar ch;
    generate
        for (ch = 0; ch < 4; ch = ch + 1) begin : g_tmds_out
            ODDRX1F u_ddr (
                .SCLK (clk_tmds),
                .RST  (1'b0),
                .D0   (tmds_d0[ch]),
                .D1   (tmds_d1[ch]),
                .Q    (gpdi_dp[ch])
            );
        end
    endgenerate

    assign wifi_gpio0 = 1'b1;
endmodule

`default_nettype wire
