// nexys_a7_top: the SoC on the Digilent Nexys A7-100T (XC7A100T-1CSG324C) — the board's pins
// (boards/nexys_a7/nexys_a7.xdc) on digilent_top (an MMCM's clocks, the SoC, the VGA register, the LEDs).
//
// Contract: from the 100 MHz oscillator, digilent_clocks makes the system clock (SYS_MHZ) and the
// 25 MHz pixel clock; the SoC is held in reset until the MMCM locks and while the red CPU RESET
// button (CPU_RESETN, active LOW) is pressed. The FT2232's UART channel carries the UART
// (UART_TXD_IN in, UART_RXD_OUT out: named from the bridge's side; 115200 8N1, no flow control).
// The 12-bit VGA connector shows the GPU's 640x480@60 picture. The 16 LEDs are digilent_top's
// (0 heartbeat, 1 frames, 2 GPU error, 3 exited, 11:4 SYS LEDS, 15:12 exit code).
// Only the pin names and the reset polarity live here; the rest is digilent_top's.
`include "contract/gpu_build_params.vh"
`default_nettype none

module nexys_a7_top #(
    parameter integer SYS_MHZ = 50,                                // a divisor of 8000 (digilent_clocks)
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // the firmware's SOC_RAM_KIB
    parameter RAM_INIT = "",                                       // the firmware's RAM image
    `GPU_BUILD_PARAMS                                              // the GPU's (digilent_top)
) (
    input  wire        CLK100MHZ,      // E3, 100 MHz
    // USB-UART (FT2232HQ)
    input  wire        UART_TXD_IN,    // C4, the FPGA receives
    output wire        UART_RXD_OUT,   // D4, the FPGA transmits
    // buttons and LEDs
    input  wire        CPU_RESETN,     // C12, active LOW: reset
    output wire [15:0] LED,
    // VGA connector (4:4:4 resistor ladder)
    output wire [3:0]  VGA_R,
    output wire [3:0]  VGA_G,
    output wire [3:0]  VGA_B,
    output wire        VGA_HS,         // active low
    output wire        VGA_VS          // active low
);
    digilent_top #(
        .SYS_MHZ      (SYS_MHZ),
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        `GPU_BUILD_PARAMS_PASS
    ) u_board (
        .clk_100mhz (CLK100MHZ),
        .uart_rx    (UART_TXD_IN),
        .uart_tx    (UART_RXD_OUT),
        .btn_reset  (!CPU_RESETN),
        .led        (LED),
        .vga_r      (VGA_R),
        .vga_g      (VGA_G),
        .vga_b      (VGA_B),
        .vga_hs_n   (VGA_HS),
        .vga_vs_n   (VGA_VS)
    );
endmodule

`default_nettype wire
