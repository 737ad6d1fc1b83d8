// basys3_top: the SoC on the Digilent Basys3 (XC7A35T-1CPG236C) — the board's pins
// (boards/basys3/basys3.xdc) on digilent_top (an MMCM's clocks, the SoC, the VGA register, the LEDs).
//
// Contract: from the 100 MHz oscillator, digilent_clocks makes the system clock (SYS_MHZ) and the
// 25 MHz pixel clock; the SoC is held in reset until the MMCM locks and while the centre button
// (btnC, active high) is pressed. The FT2232's second channel carries the UART (RsRx in, RsTx out,
// 115200 8N1). The 12-bit VGA connector shows the GPU's 640x480@60 picture. The 16 LEDs are
// digilent_top's (0 heartbeat, 1 frames, 2 GPU error, 3 exited, 11:4 SYS LEDS, 15:12 exit code).
// Block RAM: the XC7A35T has 50 RAMB36. The two framebuffers take 38 of them (19 a bank), the CPU's
// caches and register file 5 (1 RAMB36 + 8 RAMB18), the GPU's vertex and index RAMs 2: 45 before
// the SoC's RAM (8 KiB a RAMB36). So RAM_BYTES defaults to 16 KiB here, the largest that fits (49
// of 50; 24 KiB needs 51, the SoC's default 192 KiB 93): too small for any scene (tetra needs
// 57.5 KiB), enough for small test programs. yosys synth_xilinx counts: boards/basys3/README.md.
// Only the pin names, the reset polarity and the RAM size live here; the rest is digilent_top's.
`include "contract/gpu_build_params.vh"
`default_nettype none

module basys3_top #(
    parameter integer SYS_MHZ = 50,                    // a divisor of 8000 (digilent_clocks)
    parameter integer RAM_BYTES = 16 * 1024,           // the firmware's SOC_RAM_KIB (see above)
    parameter RAM_INIT = "",                           // the firmware's RAM image
    `GPU_BUILD_PARAMS                                  // the GPU's (digilent_top)
) (
    input  wire        clk,            // W5, 100 MHz
    // USB-UART (FT2232HQ channel B)
    input  wire        RsRx,           // B18, the FPGA receives
    output wire        RsTx,           // A18, the FPGA transmits
    // buttons and LEDs
    input  wire        btnC,           // U18, active high: reset
    output wire [15:0] led,
    // VGA connector (4:4:4 resistor ladder)
    output wire [3:0]  vgaRed,
    output wire [3:0]  vgaGreen,
    output wire [3:0]  vgaBlue,
    output wire        Hsync,          // active low
    output wire        Vsync           // active low
);
    digilent_top #(
        .SYS_MHZ      (SYS_MHZ),
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        `GPU_BUILD_PARAMS_PASS
    ) u_board (
        .clk_100mhz (clk),
        .uart_rx    (RsRx),
        .uart_tx    (RsTx),
        .btn_reset  (btnC),
        .led        (led),
        .vga_r      (vgaRed),
        .vga_g      (vgaGreen),
        .vga_b      (vgaBlue),
        .vga_hs_n   (Hsync),
        .vga_vs_n   (Vsync)
    );
endmodule

`default_nettype wire
