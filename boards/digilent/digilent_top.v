// digilent_top: what the Digilent Artix-7 board tops (basys3_top, nexys_a7_top) share — the clocks
// (digilent_clocks: one MMCM) around digilent_system. A board's top only names its pins and sets
// its reset polarity and RAM size; everything else, and the GPU's build parameters, is this.
//
// Contract: from the 100 MHz oscillator, digilent_clocks makes the system clock (SYS_MHZ) and the
// 25 MHz pixel clock; the SoC is held in reset until the MMCM locks and while btn_reset (active
// high, asynchronous) is pressed. uart_rx / uart_tx are the USB-UART bridge's (115200 8N1). The
// VGA outputs are digilent_system's registered 4:4:4 colours and active-low syncs; the 16 LEDs are
// digilent_system's (0 heartbeat, 1 frames, 2 GPU error, 3 exited, 11:4 SYS LEDS, 15:12 exit code).
`include "contract/gpu_build_params.vh"
`default_nettype none

module digilent_top #(
    parameter integer SYS_MHZ = 50,                                // a divisor of 8000 (digilent_clocks)
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // the firmware's SOC_RAM_KIB
    parameter RAM_INIT = "",                                       // the firmware's RAM image
    `GPU_BUILD_PARAMS                                              // the GPU's (digilent_system)
) (
    input  wire        clk_100mhz,     // the board's oscillator
    // USB-UART
    input  wire        uart_rx,        // the FPGA receives
    output wire        uart_tx,        // the FPGA transmits
    // buttons and LEDs
    input  wire        btn_reset,      // active high, asynchronous
    output wire [15:0] led,
    // VGA connector (4:4:4 resistor ladder)
    output wire [3:0]  vga_r,
    output wire [3:0]  vga_g,
    output wire [3:0]  vga_b,
    output wire        vga_hs_n,
    output wire        vga_vs_n
);
    wire clk_sys, clk_pix, mmcm_locked;
    digilent_clocks #(.SYS_MHZ(SYS_MHZ)) u_clocks (
        .clk_100mhz (clk_100mhz),
        .clk_sys    (clk_sys),
        .clk_pix    (clk_pix),
        .locked     (mmcm_locked)
    );

    digilent_system #(
        .SYS_HZ       (SYS_MHZ * 1000000),
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        `GPU_BUILD_PARAMS_PASS
    ) u_system (
        .clk_sys     (clk_sys),
        .clk_pix     (clk_pix),
        .mmcm_locked (mmcm_locked),
        .btn_reset   (btn_reset),
        .uart_rx     (uart_rx),
        .uart_tx     (uart_tx),
        .led         (led),
        .vga_r       (vga_r),
        .vga_g       (vga_g),
        .vga_b       (vga_b),
        .vga_hs_n    (vga_hs_n),
        .vga_vs_n    (vga_vs_n)
    );
endmodule

`default_nettype wire
