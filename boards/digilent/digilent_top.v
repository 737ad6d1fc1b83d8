// digilent_top: what the Digilent Artix-7 board tops (basys3_top, nexys_a7_top) share — the clocks
// (digilent_clocks: one MMCM), the SoC, the registered 12-bit VGA outputs and the status LEDs. A
// board's top only names its pins and sets its reset polarity and RAM size; everything else, and
// the GPU's build parameters, is this.
//
// Contract: from the 100 MHz oscillator, digilent_clocks makes clk_sys (SYS_MHZ) and clk_pix
// (25 MHz); the SoC is held in reset until the MMCM locks and while btn_reset (active high,
// asynchronous) is pressed: soc_top synchronises ext_rst to clk_sys and gpu_top the reset of its
// scan-out to clk_pix. uart_rx / uart_tx are the USB-UART bridge's (115200 8N1).
// VGA: the GPU's 4:4:4 colours and syncs go to the boards' resistor-ladder VGA connector through one
// register in the clk_pix domain (loaded on vga_pix_stb, which with a 25 MHz clk_pix is every cycle),
// blanked outside the visible area; the syncs stay active low.
// LEDs: 0 heartbeat (about 0.7 s on, 0.7 s off at 50 MHz: the system clock runs), 1 frames (toggles
// every 16 buffer swaps: about 2 Hz at 60 fps), 2 GPU error (ERRORS non-zero), 3 the firmware has
// exited (SYS EXIT), 11:4 SYS LEDS 7:0 (the firmware's), 15:12 the exit code's low nibble. A board
// with 8 LEDs wires led[7:0].
// Clock domains: clk_sys and clk_pix; every crossing is soc_top's / gpu_top's own (gpu_cdc_sync,
// gpu_cdc_pulse). The only logic here on clk_pix is the output register, fed by gpu_top's clk_pix
// outputs. The lint (lint.sh) sees the MMCM and the BUFGs as its lint-only stand-ins (lint/).
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_top_no_sdram.vh"
`default_nettype none

module digilent_top #(
    parameter integer SYS_MHZ = 50,                                // a divisor of 8000 (digilent_clocks)
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // the firmware's SOC_RAM_KIB
    parameter RAM_INIT = "",                                       // the firmware's RAM image
    `GPU_BUILD_PARAMS,                                             // the GPU's (soc_top)
    localparam integer SYS_HZ = SYS_MHZ * 1000000                  // clk_sys: the SoC's CLK_HZ
) (
    input  wire        clk_100mhz,     // the board's oscillator
    // USB-UART
    input  wire        uart_rx,        // the FPGA receives
    output wire        uart_tx,        // the FPGA transmits
    // buttons and LEDs
    input  wire        btn_reset,      // active high, asynchronous
    output wire [15:0] led,
    // VGA connector (4:4:4 resistor ladder), clk_pix domain (registered)
    output reg  [3:0]  vga_r,
    output reg  [3:0]  vga_g,
    output reg  [3:0]  vga_b,
    output reg         vga_hs_n,
    output reg         vga_vs_n
);
    wire clk_sys, clk_pix, mmcm_locked;
    digilent_clocks #(.SYS_MHZ(SYS_MHZ)) u_clocks (
        .clk_100mhz (clk_100mhz),
        .clk_sys    (clk_sys),
        .clk_pix    (clk_pix),
        .locked     (mmcm_locked)
    );

    wire       pix_stb, de, hsync_n, vsync_n;
    wire [3:0] r, g, b;
    wire [7:0] sys_leds, exit_code;
    wire       frame_swapped, gpu_error, exit_valid;

    `SOC_TOP_NO_SDRAM_WIRES   // no SDRAM in this build (soc_rtl/soc_top_no_sdram.vh)
    wire [2:0] usb_idle;
    wire unused_usb = |usb_idle;

    soc_top #(
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        .CLK_HZ       (SYS_HZ),
        .PIX_CLK_HZ   (25000000),
        `GPU_BUILD_PARAMS_PASS
    ) u_soc (
        .clk               (clk_sys),
        .clk_pix           (clk_pix),
        .ext_rst           (!mmcm_locked || btn_reset),
        .uart_rx           (uart_rx),
        .uart_tx           (uart_tx),
        .vga_pix_stb       (pix_stb),
        .vga_de            (de),
        .vga_hsync_n       (hsync_n),
        .vga_vsync_n       (vsync_n),
        .vga_r             (r),
        .vga_g             (g),
        .vga_b             (b),
        `SOC_TOP_NO_SDRAM_PORTS,   // no SDRAM in this build (soc_rtl/soc_top_no_sdram.vh)
        .usb_dp_in         (1'b0),     // no USB host in this build (USB_HOST 0): the outputs stay low
        .usb_dn_in         (1'b0),
        .usb_dp_out        (usb_idle[0]),
        .usb_dn_out        (usb_idle[1]),
        .usb_oe            (usb_idle[2]),
        .leds              (sys_leds),
        .gpu_frame_swapped (frame_swapped),
        .gpu_error         (gpu_error),
        .exit_valid        (exit_valid),
        .exit_code         (exit_code)
    );

    // ---- VGA: one output register in the clk_pix domain ----
    initial begin
        vga_r = 4'd0;
        vga_g = 4'd0;
        vga_b = 4'd0;
        vga_hs_n = 1'b1;
        vga_vs_n = 1'b1;
    end
    always @(posedge clk_pix) begin
        if (pix_stb) begin
            vga_r    <= de ? r : 4'd0;
            vga_g    <= de ? g : 4'd0;
            vga_b    <= de ? b : 4'd0;
            vga_hs_n <= hsync_n;
            vga_vs_n <= vsync_n;
        end
    end

    // ---- LEDs (clk_sys) ----
    wire heartbeat, frames;
    board_status #(.SYS_HZ(SYS_HZ)) u_status (
        .clk_sys(clk_sys), .frame_swapped(frame_swapped), .heartbeat(heartbeat), .frames(frames)
    );
    assign led = {exit_code[3:0], sys_leds, exit_valid, gpu_error, frames, heartbeat};
    wire unused_exit = |exit_code[7:4];
endmodule

`default_nettype wire
