// ulx3s_system: everything of the ULX3S build between the PLL and the pins — the SoC, its DVI
// transmitter, the resets of every clock domain and the status LEDs — without a vendor primitive,
// so that Verilator runs it as it is (cosim/soc/socsim.mk's board build drives its three clocks).
//
// Contract: clk_sys, clk_pix (25 MHz) and clk_tmds (5 x clk_pix, the same PLL) come from
// ulx3s_pll; until pll_locked every domain is held in reset, and the SoC while btn_reset is pressed.
// tmds_d0/tmds_d1 are, per TMDS channel (0 blue, 1 green, 2 red, 3 clock), the bit pair an
// ODDRX1F sends in one clk_tmds period (dvi_tx). The SoC's 4-bit VGA colours go out as 8-bit DVI
// colours by repeating the nibble (0xF -> 0xFF), so white stays white.
// LEDs: 0 heartbeat (about 0.7 s on, 0.7 s off at 50 MHz: the system clock runs), 1 frames
// (toggles every 16 buffer swaps: about 2 Hz at 60 fps), 2 GPU error (ERRORS non-zero), 3 the
// firmware has exited (SYS EXIT), 7:4 SYS LEDS 3:0 (the firmware's).
// Clock domains: each reset crosses through gpu_cdc_sync; the video crossings are gpu_top's (system
// to pixel clock) and dvi_tx's (pixel to TMDS clock).
// The GPU's build parameters (contract/gpu_build_params.vh) are passed through to soc_top.
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_top_no_sdram.vh"
`default_nettype none

module ulx3s_system #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,        // clk_sys: the SoC's CLK_HZ
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // on-chip RAM (soc_top)
    parameter RAM_INIT = "",                                       // the firmware image (soc_top)
    `GPU_BUILD_PARAMS                                              // the GPU's (soc_top)
) (
    // clocks (ulx3s_pll)
    input  wire       clk_sys,
    input  wire       clk_pix,        // 25 MHz
    input  wire       clk_tmds,       // 125 MHz, 5 x clk_pix
    input  wire       pll_locked,     // asynchronous
    // board
    input  wire       btn_reset,      // FIRE1, active high, asynchronous
    input  wire       uart_rx,        // from the FT231X (ftdi_txd)
    output wire       uart_tx,        // to the FT231X (ftdi_rxd)
    output wire [7:0] led,
    // DVI: the ODDRX1F inputs, clk_tmds domain
    output wire [3:0] tmds_d0,        // sent first (after the rising edge)
    output wire [3:0] tmds_d1,
    // for a simulation: the firmware's SYS EXIT
    output wire       exit_valid,
    output wire [7:0] exit_code
);
    wire unlocked = !pll_locked;

    // ---- the SoC: the system clock, and the GPU's scan-out on the pixel clock ----
    wire       vga_pix_stb, vga_de, vga_hsync_n, vga_vsync_n;
    wire [3:0] vga_r, vga_g, vga_b;
    wire [7:0] soc_leds;
    wire       gpu_frame_swapped, gpu_error;

    `SOC_TOP_NO_SDRAM_WIRES   // no SDRAM in this build (soc_rtl/soc_top_no_sdram.vh)

    soc_top #(
        .RAM_BYTES    (RAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        .CLK_HZ       (SYS_HZ),
        .PIX_CLK_HZ   (25000000),
        `GPU_BUILD_PARAMS_PASS
    ) u_soc (
        .clk               (clk_sys),
        .clk_pix           (clk_pix),
        .ext_rst           (unlocked || btn_reset),   // soc_top synchronises it
        .uart_rx           (uart_rx),
        .uart_tx           (uart_tx),
        .vga_pix_stb       (vga_pix_stb),
        .vga_de            (vga_de),
        .vga_hsync_n       (vga_hsync_n),
        .vga_vsync_n       (vga_vsync_n),
        .vga_r             (vga_r),
        .vga_g             (vga_g),
        .vga_b             (vga_b),
        `SOC_TOP_NO_SDRAM_PORTS,   // no SDRAM in this build (soc_rtl/soc_top_no_sdram.vh)
        .leds              (soc_leds),
        .gpu_frame_swapped (gpu_frame_swapped),
        .gpu_error         (gpu_error),
        .exit_valid        (exit_valid),
        .exit_code         (exit_code)
    );
    // A 25 MHz pixel clock: a new pixel on every clk_pix edge (PIX_DIV 1), so no strobe is needed.
    wire unused_pix_stb = vga_pix_stb;

    // ---- DVI: pixel clock to TMDS clock, serialised by the ODDRX1Fs of ulx3s_top ----
    wire rst_pix, rst_tmds;
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_pix_sync (.clk(clk_pix), .in(unlocked), .out(rst_pix));
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_tmds_sync (.clk(clk_tmds), .in(unlocked), .out(rst_tmds));

    dvi_tx u_dvi (
        .clk_pix  (clk_pix),
        .rst_pix  (rst_pix),
        .clk_tmds (clk_tmds),
        .rst_tmds (rst_tmds),
        .de       (vga_de),
        .hsync    (vga_hsync_n),    // 640x480: negative syncs, sent as the line levels
        .vsync    (vga_vsync_n),
        .r        ({vga_r, vga_r}),
        .g        ({vga_g, vga_g}),
        .b        ({vga_b, vga_b}),
        .ddr_d0   (tmds_d0),
        .ddr_d1   (tmds_d1)
    );

    // ---- status LEDs, system clock ----
    wire heartbeat, frames;
    board_status #(.SYS_HZ(SYS_HZ)) u_status (
        .clk_sys(clk_sys), .frame_swapped(gpu_frame_swapped), .heartbeat(heartbeat), .frames(frames)
    );
    assign led = {soc_leds[3:0], exit_valid, gpu_error, frames, heartbeat};
    wire unused_leds = |soc_leds[7:4];
endmodule

`default_nettype wire
