// soc_sdram_sim: socsim's system with SDRAM — soc_top (the pixel clock tied to the system clock, as
// socsim's plain build) with its SDRAM ports on soc_sdram (LiteDRAM's generated controller), the
// chip's pins out to socsim, which plays the chip (cosim/sdram/sdram_chip.h) on them, and soc_top's
// flash pins likewise (cosim/flash/spi_flash.h).
//
// The ports are soc_top's but the SDRAM's, so socsim drives either system with the same code; the
// controller and its pins as cosim/soc/soc_sdram_chip_model.vh makes them (DQ split for the chip
// model).
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_gpu_mem.vh"
`include "soc_rtl/soc_sdram_bus.vh"
`include "cosim/soc/soc_sdram_chip_model.vh"
`default_nettype none

module soc_sdram_sim #(
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,
    parameter integer SDRAM_BYTES = soc_pkg::SOC_SDRAM_DEFAULT_BYTES,
    parameter integer PIX_CLK_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,   // tied to clk, as socsim's soc_top
    parameter integer BAUD = soc_pkg::SOC_UART_BAUD,              // soc_top's UART
    parameter integer USB_HOST = 0,                                // soc_top's USB keyboard host
    `GPU_BUILD_PARAMS
) (
    input  wire        clk,
    input  wire        clk2x,           // 2 x clk, rising edges aligned: the SDRAM PHY's
    input  wire        clk_pix,
    // verilator lint_off SYNCASYNCNET
    input  wire        ext_rst,         // soc_top synchronises it; LiteDRAM's reset flops take it asynchronously
    // verilator lint_on SYNCASYNCNET
    input  wire        uart_rx,
    output wire        uart_tx,
    output wire        vga_pix_stb,
    output wire        vga_de,
    output wire        vga_hsync_n,
    output wire        vga_vsync_n,
    output wire [3:0]  vga_r,
    output wire [3:0]  vga_g,
    output wire [3:0]  vga_b,
    output wire [7:0]  leds,
    output wire        gpu_frame_swapped,
    output wire        gpu_error,
    output wire        exit_valid,
    output wire [7:0]  exit_code,
    // ---- the SDRAM chip's pins, for socsim's chip model
    output wire [12:0] sdram_a,
    output wire [1:0]  sdram_ba,
    output wire        sdram_cs_n,
    output wire        sdram_ras_n,
    output wire        sdram_cas_n,
    output wire        sdram_we_n,
    output wire        sdram_cke,
    output wire [1:0]  sdram_dqm,
    output wire [15:0] sdram_dq_pins,   // the DQ bus as resolved
    output wire        ctrl_dq_oe,      // the controller drives DQ
    input  wire [15:0] chip_dq,         // the chip's drive ...
    input  wire        chip_dq_oe,      // ... while this is high
    output wire        sdram_init_done,
    output wire        sdram_busy,      // a request to the SDRAM is on soc_top's port (waiting or answered)
    // ---- the SPI flash's pins, for socsim's flash model
    output wire        flash_cs_n,
    output wire        flash_sck,
    output wire        flash_mosi,
    input  wire        flash_miso,
    // ---- the USB port (USB_HOST), for socsim's keyboard model
    input  wire        usb_dp_in,
    input  wire        usb_dn_in,
    output wire        usb_dp_out,
    output wire        usb_dn_out,
    output wire        usb_oe
);

    `SOC_SDRAM_BUS_WIRES  // soc_top's SDRAM ports to soc_sdram (soc_rtl/soc_sdram_bus.vh)
    `SOC_GPU_MEM_WIRES   // the GPU's frames (FRAME_DRAM): soc_top to LiteDRAM (soc_rtl/soc_gpu_mem.vh)

    soc_top #(
        .RAM_BYTES   (RAM_BYTES),
        .SDRAM_BYTES (SDRAM_BYTES),
        .PIX_CLK_HZ  (PIX_CLK_HZ),
        .BAUD        (BAUD),
        .USB_HOST    (USB_HOST),
        `GPU_BUILD_PARAMS_PASS
    ) u_soc (
        .clk (clk), .clk_pix (clk_pix), .ext_rst (ext_rst), .uart_rx (uart_rx), .uart_tx (uart_tx),
        .vga_pix_stb (vga_pix_stb), .vga_de (vga_de), .vga_hsync_n (vga_hsync_n),
        .vga_vsync_n (vga_vsync_n), .vga_r (vga_r), .vga_g (vga_g), .vga_b (vga_b),
        `SOC_SDRAM_BUS_PORTS,
        .flash_cs_n (flash_cs_n), .flash_sck (flash_sck), .flash_mosi (flash_mosi), .flash_miso (flash_miso),
        .usb_dp_in (usb_dp_in), .usb_dn_in (usb_dn_in), .usb_dp_out (usb_dp_out), .usb_dn_out (usb_dn_out),
        .usb_oe (usb_oe),
        `SOC_GPU_MEM_PORTS,
        .leds (leds), .gpu_frame_swapped (gpu_frame_swapped), .gpu_error (gpu_error),
        .exit_valid (exit_valid), .exit_code (exit_code)
    );

    `SOC_SDRAM_FOR_CHIP_MODEL(clk, clk2x, ext_rst)   // LiteDRAM, its pins to socsim (cosim/soc/soc_sdram_chip_model.vh)
endmodule

`default_nettype wire
