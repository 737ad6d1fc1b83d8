// ulx3s_sdram_sim: socsim's ULX3S build with SDRAM — boards/ulx3s/ulx3s_system on its three clocks
// (the TMDS pairs out, as socsim's plain board build) with its SDRAM, GPU frame and flash ports on
// soc_sdram (LiteDRAM's generated controller), wired as boards/ulx3s/ulx3s_sdram_top wires them
// (LiteDRAM reset by ulx3s_system's sdram_rst), and the chip's and the flash's pins out to socsim,
// which plays both (cosim/sdram/sdram_chip.h, cosim/flash/spi_flash.h). Left out are the vendor
// primitives a simulation cannot run: the PLLs (socsim makes the clocks, clk_sys2x among them), the
// ODDRX1Fs (socsim reads their input pairs) and the SDRAM clock's output register (the chip model is
// clocked at clk_sys2x's rate a whole period behind it, the phase docs/sdram.md argues).
//
// The controller and the chip's pins as in soc_sdram_sim (cosim/soc/soc_sdram_chip_model.vh).
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_gpu_mem.vh"
`include "soc_rtl/soc_sdram_bus.vh"
`include "cosim/soc/soc_sdram_chip_model.vh"
`default_nettype none

module ulx3s_sdram_sim #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_BOOT_BYTES,        // the boot program's on-chip RAM
    parameter integer SDRAM_BYTES = soc_pkg::SOC_SDRAM_DEFAULT_BYTES,
    parameter integer BAUD = soc_pkg::SOC_UART_BAUD,                  // the SoC's UART (ulx3s_system)
    parameter integer USB_HOST = 0,                                    // the keyboard host on US2 (ulx3s_system)
    `GPU_BUILD_PARAMS
) (
    // ---- the PLL's clocks, made by socsim
    input  wire        clk_sys,
    input  wire        clk_sys2x,       // 2 x clk_sys, rising edges aligned: the SDRAM PHY's
    input  wire        clk_pix,         // 25 MHz
    input  wire        clk_tmds,        // 125 MHz
    input  wire        pll_locked,
    // ---- board
    input  wire        btn_reset,
    input  wire        uart_rx,
    output wire        uart_tx,
    output wire [7:0]  led,
    output wire [3:0]  tmds_d0,         // the ODDRX1F inputs (ulx3s_system)
    output wire [3:0]  tmds_d1,
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
    output wire        sdram_busy,      // a request on the CPU's SDRAM port (waiting or answered)
    // ---- the SPI flash's pins, for socsim's flash model
    output wire        flash_cs_n,
    output wire        flash_sck,
    output wire        flash_mosi,
    input  wire        flash_miso,
    // ---- US2 (USB_HOST), for socsim's keyboard model
    input  wire        usb_dp_in,
    input  wire        usb_dn_in,
    output wire        usb_dp_out,
    output wire        usb_dn_out,
    output wire        usb_oe
);

    wire               sdram_rst;
    `SOC_SDRAM_BUS_WIRES  // soc_top's SDRAM ports to soc_sdram (soc_rtl/soc_sdram_bus.vh)
    `SOC_GPU_MEM_WIRES   // the GPU's frames (FRAME_DRAM): ulx3s_system to LiteDRAM (soc_rtl/soc_gpu_mem.vh)

    ulx3s_system #(
        .SYS_HZ      (SYS_HZ),
        .RAM_BYTES   (RAM_BYTES),
        .SDRAM_BYTES (SDRAM_BYTES),
        .BAUD        (BAUD),
        .USB_HOST    (USB_HOST),
        `GPU_BUILD_PARAMS_PASS
    ) u_system (
        .clk_sys (clk_sys), .clk_pix (clk_pix), .clk_tmds (clk_tmds), .pll_locked (pll_locked),
        .btn_reset (btn_reset), .uart_rx (uart_rx), .uart_tx (uart_tx), .led (led),
        .tmds_d0 (tmds_d0), .tmds_d1 (tmds_d1),
        .sdram_rst (sdram_rst),
        `SOC_SDRAM_BUS_PORTS,
        .flash_cs_n (flash_cs_n), .flash_sck (flash_sck), .flash_mosi (flash_mosi), .flash_miso (flash_miso),
        .usb_dp_in (usb_dp_in), .usb_dn_in (usb_dn_in), .usb_dp_out (usb_dp_out), .usb_dn_out (usb_dn_out),
        .usb_oe (usb_oe),
        `SOC_GPU_MEM_PORTS,
        .exit_valid (exit_valid), .exit_code (exit_code)
    );

    `SOC_SDRAM_FOR_CHIP_MODEL(clk_sys, clk_sys2x, sdram_rst)   // LiteDRAM, its pins to socsim (cosim/soc/soc_sdram_chip_model.vh)
endmodule

`default_nettype wire
