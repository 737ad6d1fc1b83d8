// ulx3s_sdram_top: the SoC on the Radiona ULX3S with its firmware in the SDRAM (SOC_MEM=sdram) —
// ulx3s_top's pins, PLL and DVI outputs, and the board's SDRAM and SPI flash.
//
// Contract: as ulx3s_top (clocks, DVI, UART, FIRE1, LEDs, wifi_gpio0), with soc_top's SDRAM_BYTES
// = SDRAM_BYTES and its on-chip RAM the boot program's (RAM_INIT, RAM_BYTES: docs/boot.md): the
// boot program powers the SDRAM up, tests it, copies the firmware's image from the flash into it
// and jumps there.
//   clocks  two PLLs: ulx3s_pll's clk_tmds and clk_pix (the DVI), ulx3s_sdram_pll's clk_sys,
//           clk_sys2x and clk_sdram; the system is held in reset until both have locked.
//   SDRAM   soc_sdram (LiteDRAM's controller with its half-rate PHY, generated for SYS_MHZ:
//           soc_rtl/litedram) on clk_sys, the pins on clk_sys2x, commands and data registered in the
//           I/O cells; sdram_clk is clk_sdram (2 x SYS_MHZ, SDRAM_PHASE_DEG after clk_sys2x: the
//           argument is in ulx3s_sdram_pll.v) leaving through an ODDRX1F (D0 1, D1 0), the same kind
//           of I/O register as the commands. Its reset is ulx3s_system's sdram_rst (PLL unlock or
//           FIRE1, synchronised to clk_sys).
//   flash   soc_top's SPI pins (mode 0, SCK = clk_sys / 2): CS#, MOSI, MISO on their balls; SCK
//           reaches the flash's clock ball (CCLK, a configuration pin) only through USRMCLK
//           (USRMCLKI = SCK, USRMCLKTS = 0: always driven, after configuration; the LPF's
//           MASTER_SPI_PORT=DISABLE leaves the pins to the design); WP# and HOLD# held high.
//   US2     with USB_HOST = 1 the keyboard host (soc_usb) on the second USB socket, as a host: both
//           lines' 15 kOhm pull-downs on (usb_fpga_pu_dp/dn low), D+ and D- driven and read single
//           ended on usb_fpga_bd_dp/dn (the line states need SE0, which the differential receiver
//           on usb_fpga_dp/dn cannot show). Without it (the default until the board build's cost and
//           timing with the host are measured: issue #28) the lines are released, the pull-downs on.
// Only the primitives live here; the logic is in ulx3s_system and soc_sdram. The GPU's build
// parameters (contract/gpu_build_params.vh) are passed through, as in ulx3s_top.
`include "contract/gpu_build_params.vh"
`include "soc_rtl/soc_gpu_mem.vh"
`include "soc_rtl/soc_sdram_bus.vh"
`default_nettype none

module ulx3s_sdram_top #(
    parameter integer SYS_MHZ = 50,                                   // 25 or 50 (ulx3s_sdram_pll)
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_BOOT_BYTES,        // the boot program's on-chip RAM
    parameter integer SDRAM_BYTES = soc_pkg::SOC_SDRAM_DEFAULT_BYTES, // the generated controller's chip
    parameter RAM_INIT = "",                                          // the boot program's RAM image
    parameter integer USB_HOST = 0,                                   // 1: the keyboard host on US2
    parameter integer PROJ_UNIT = 1,                                  // soc_top's: the projection unit
    `GPU_BUILD_PARAMS                                                 // the GPU's (ulx3s_system)
) (
    input  wire        clk_25mhz,      // G2
    // FT231X USB serial
    input  wire        ftdi_txd,       // the FPGA receives (M1)
    output wire        ftdi_rxd,       // the FPGA transmits (L4)
    // buttons and LEDs
    input  wire        btn_fire1,      // R1, active high: reset
    output wire [7:0]  led,
    // GPDI: blue, green, red, clock
    output wire [3:0]  gpdi_dp,
    // ESP32
    output wire        wifi_gpio0,     // held high
    // SDRAM (32 MB x16 SDR)
    output wire        sdram_clk,
    output wire        sdram_cke,
    output wire        sdram_csn,
    output wire        sdram_wen,
    output wire        sdram_rasn,
    output wire        sdram_casn,
    output wire [12:0] sdram_a,
    output wire [1:0]  sdram_ba,
    output wire [1:0]  sdram_dqm,
    inout  wire [15:0] sdram_d,
    // SPI configuration flash (its clock through USRMCLK)
    output wire        flash_csn,
    output wire        flash_mosi,
    input  wire        flash_miso,
    output wire        flash_wpn,      // held high
    output wire        flash_holdn,    // held high
    // US2, host mode
    inout  wire        usb_fpga_bd_dp,
    inout  wire        usb_fpga_bd_dn,
    output wire        usb_fpga_pu_dp, // 0: the 15 kOhm pull-down
    output wire        usb_fpga_pu_dn
);
    wire clk_tmds, clk_pix, clk_sys_off, video_locked;
    ulx3s_pll #(.SYS_CLK(0)) u_pll (
        .clk_25mhz (clk_25mhz),
        .clk_tmds  (clk_tmds),
        .clk_pix   (clk_pix),
        .clk_sys   (clk_sys_off),    // off: the system clock is ulx3s_sdram_pll's
        .locked    (video_locked)
    );
    wire unused_clk_sys = clk_sys_off;
    wire clk_sys, clk_sys2x, clk_sdram, sys_locked;
    ulx3s_sdram_pll #(.SYS_MHZ(SYS_MHZ)) u_sdram_pll (
        .clk_25mhz (clk_25mhz),
        .clk_sys   (clk_sys),
        .clk_sys2x (clk_sys2x),
        .clk_sdram (clk_sdram),
        .locked    (sys_locked)
    );
    wire pll_locked = video_locked && sys_locked;

    wire [3:0] tmds_d0, tmds_d1;
    wire       exit_valid;
    wire [7:0] exit_code;
    // soc_top's SDRAM ports, between ulx3s_system and soc_sdram (clk_sys)
    wire                     sdram_rst;
    `SOC_SDRAM_BUS_WIRES  // (soc_rtl/soc_sdram_bus.vh)
    wire                     flash_sck;
    `SOC_GPU_MEM_WIRES   // the GPU's frames (FRAME_DRAM): soc_top to LiteDRAM (soc_rtl/soc_gpu_mem.vh)
    wire                     usb_dp_out, usb_dn_out, usb_oe;
    ulx3s_system #(
        .SYS_HZ       (SYS_MHZ * 1000000),
        .RAM_BYTES    (RAM_BYTES),
        .SDRAM_BYTES  (SDRAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        .USB_HOST     (USB_HOST),
        .PROJ_UNIT    (PROJ_UNIT),
        `GPU_BUILD_PARAMS_PASS
    ) u_system (
        .clk_sys          (clk_sys),
        .clk_pix          (clk_pix),
        .clk_tmds         (clk_tmds),
        .pll_locked       (pll_locked),
        .btn_reset        (btn_fire1),
        .uart_rx          (ftdi_txd),
        .uart_tx          (ftdi_rxd),
        .led              (led),
        .tmds_d0          (tmds_d0),
        .tmds_d1          (tmds_d1),
        .sdram_rst        (sdram_rst),
        `SOC_SDRAM_BUS_PORTS,
        .flash_cs_n       (flash_csn),
        .flash_sck        (flash_sck),
        .flash_mosi       (flash_mosi),
        .flash_miso       (flash_miso),
        .usb_dp_in        (usb_fpga_bd_dp),
        .usb_dn_in        (usb_fpga_bd_dn),
        .usb_dp_out       (usb_dp_out),
        .usb_dn_out       (usb_dn_out),
        .usb_oe           (usb_oe),
        `SOC_GPU_MEM_PORTS,
        .exit_valid       (exit_valid),
        .exit_code        (exit_code)
    );
    wire unused_exit = exit_valid | (|exit_code);  // the board runs the firmware for ever

    // ---- US2: the host drives both lines or neither (soc_usb), the pull-downs always on ----
    assign usb_fpga_bd_dp = usb_oe ? usb_dp_out : 1'bz;
    assign usb_fpga_bd_dn = usb_oe ? usb_dn_out : 1'bz;
    assign usb_fpga_pu_dp = 1'b0;
    assign usb_fpga_pu_dn = 1'b0;

    // ---- the SDRAM: LiteDRAM on soc_top's ports, the chip's clock clk_sdram ----
    wire sdram_init_done;
    soc_sdram #(
        .SDRAM_BYTES (SDRAM_BYTES)
    ) u_sdram (
        .clk              (clk_sys),
        .clk2x            (clk_sys2x),
        .rst              (sdram_rst),
        .init_done        (sdram_init_done),
        `SOC_SDRAM_BUS_PORTS,
        `SOC_GPU_MEM_PORTS,
        .pin_a            (sdram_a),
        .pin_ba           (sdram_ba),
        .pin_cs_n         (sdram_csn),
        .pin_ras_n        (sdram_rasn),
        .pin_cas_n        (sdram_casn),
        .pin_we_n         (sdram_wen),
        .pin_cke          (sdram_cke),
        .pin_dqm          (sdram_dqm),
        .pin_dq           (sdram_d)
    );
    wire unused_init_done = sdram_init_done;   // the boot program reads it through the registers

    ODDRX1F u_sdram_clk (
        .SCLK (clk_sdram),
        .RST  (1'b0),
        .D0   (1'b1),       // high after clk_sdram's rising edge ...
        .D1   (1'b0),       // ... low after its falling one: clk_sdram at the pin
        .Q    (sdram_clk)
    );

    // ---- the flash's clock: the configuration clock pin, through USRMCLK ----
    USRMCLK u_flash_clk (
        .USRMCLKI  (flash_sck),
        .USRMCLKTS (1'b0)
    );
    assign flash_wpn   = 1'b1;
    assign flash_holdn = 1'b1;

    // ---- DVI, as ulx3s_top ----
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
