// ulx3s_system: everything of the ULX3S build between the PLL and the pins — the SoC, its DVI
// transmitter, the resets of every clock domain and the status LEDs — without a vendor primitive,
// so that Verilator runs it as it is (cosim/soc/socsim.mk's board build drives its three clocks).
// With SDRAM_BYTES > 0 (ulx3s_sdram_top) soc_top's SDRAM, GPU frame memory and flash ports pass through to the top,
// whose LiteDRAM core (soc_rtl/litedram/soc_sdram) and I/O primitives live there; sdram_rst is its
// reset. With SDRAM_BYTES = 0 (ulx3s_top, socsim's board build) those answers are tied to 0 here,
// whatever drives the ports (soc_top asks for 0; a Verilated top leaves its inputs undriven).
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
// to pixel clock) and dvi_tx's (pixel to TMDS clock). Everything on the SDRAM and flash ports is on
// clk_sys.
// The GPU's build parameters (contract/gpu_build_params.vh) are passed through to soc_top.
`include "contract/gpu_build_params.vh"
`default_nettype none

module ulx3s_system #(
    parameter integer SYS_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,        // clk_sys: the SoC's CLK_HZ
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // on-chip RAM (soc_top)
    parameter integer SDRAM_BYTES = 0,                             // soc_top's: 0 = no SDRAM, no flash
    parameter RAM_INIT = "",                                       // the firmware image (soc_top)
    parameter integer BAUD = soc_pkg::SOC_UART_BAUD,               // the UART's bits per second (soc_top)
    parameter integer USB_HOST = 0,                                // soc_top's: 1 = the keyboard host on US2
    parameter integer PROJ_UNIT = 1,                               // soc_top's: 1 = the projection unit
    `GPU_BUILD_PARAMS,                                             // the GPU's (soc_top)
    localparam integer SDRAM_AW = $clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4),      // soc_top's
    localparam integer SDRAM_CTRL_AW = $clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4),
    localparam integer GPU_MEM_AW = soc_pkg::SOC_SDRAM_NATIVE_AW     // soc_top's
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
    // US2 (USB_HOST = 1): soc_top's USB pins; the top puts them on usb_fpga_bd_dp/dn
    input  wire       usb_dp_in,      // asynchronous
    input  wire       usb_dn_in,
    output wire       usb_dp_out,
    output wire       usb_dn_out,
    output wire       usb_oe,
    // DVI: the ODDRX1F inputs, clk_tmds domain
    output wire [3:0] tmds_d0,        // sent first (after the rising edge)
    output wire [3:0] tmds_d1,
    // SDRAM (SDRAM_BYTES > 0): LiteDRAM's reset, and soc_top's two Wishbone ports as soc_top names them
    output wire                     sdram_rst,        // pll unlocked or FIRE1, synchronised to clk_sys
    output wire                     sdram_cyc,
    output wire                     sdram_stb,
    output wire                     sdram_we,
    output wire [SDRAM_AW-1:0]      sdram_adr,
    output wire [31:0]              sdram_dat_w,
    output wire [3:0]               sdram_sel,
    output wire [2:0]               sdram_cti,
    input  wire [31:0]              sdram_dat_r,
    input  wire                     sdram_ack,
    input  wire                     sdram_err,
    output wire                     sdram_ctrl_cyc,
    output wire                     sdram_ctrl_stb,
    output wire                     sdram_ctrl_we,
    output wire [SDRAM_CTRL_AW-1:0] sdram_ctrl_adr,
    output wire [31:0]              sdram_ctrl_dat_w,
    output wire [3:0]               sdram_ctrl_sel,
    input  wire [31:0]              sdram_ctrl_dat_r,
    input  wire                     sdram_ctrl_ack,
    input  wire                     sdram_ctrl_err,
    // SPI flash (SDRAM_BYTES > 0), soc_top's pins (flash_sck to USRMCLK in the top)
    output wire                     flash_cs_n,
    output wire                     flash_sck,
    output wire                     flash_mosi,
    input  wire                     flash_miso,
    // the GPU's frames in the SDRAM (FRAME_DRAM): soc_top's gpu_mem_* port
    output wire                     gpu_mem_cmd_valid,
    input  wire                     gpu_mem_cmd_ready,
    output wire                     gpu_mem_cmd_we,
    output wire [GPU_MEM_AW-1:0]    gpu_mem_cmd_addr,
    output wire                     gpu_mem_wdata_valid,
    input  wire                     gpu_mem_wdata_ready,
    output wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0]   gpu_mem_wdata_data,
    output wire [soc_pkg::SOC_SDRAM_NATIVE_DW/8-1:0] gpu_mem_wdata_we,
    input  wire                     gpu_mem_rdata_valid,
    output wire                     gpu_mem_rdata_ready,
    input  wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0]   gpu_mem_rdata_data,
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

    // soc_top's answers from the SDRAM and the flash: the ports' with SDRAM, else 0.
    wire [31:0] soc_sdram_dat_r, soc_sdram_ctrl_dat_r;
    wire        soc_sdram_ack, soc_sdram_err, soc_sdram_ctrl_ack, soc_sdram_ctrl_err, soc_flash_miso;
    wire        soc_gpu_mem_cmd_ready, soc_gpu_mem_wdata_ready, soc_gpu_mem_rdata_valid;
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0] soc_gpu_mem_rdata_data;
    generate if (SDRAM_BYTES != 0) begin : g_sdram
        assign soc_gpu_mem_cmd_ready   = gpu_mem_cmd_ready;
        assign soc_gpu_mem_wdata_ready = gpu_mem_wdata_ready;
        assign soc_gpu_mem_rdata_valid = gpu_mem_rdata_valid;
        assign soc_gpu_mem_rdata_data  = gpu_mem_rdata_data;
        assign soc_sdram_dat_r      = sdram_dat_r;
        assign soc_sdram_ack        = sdram_ack;
        assign soc_sdram_err        = sdram_err;
        assign soc_sdram_ctrl_dat_r = sdram_ctrl_dat_r;
        assign soc_sdram_ctrl_ack   = sdram_ctrl_ack;
        assign soc_sdram_ctrl_err   = sdram_ctrl_err;
        assign soc_flash_miso       = flash_miso;
    end else begin : g_no_sdram
        assign soc_gpu_mem_cmd_ready   = 1'b0;
        assign soc_gpu_mem_wdata_ready = 1'b0;
        assign soc_gpu_mem_rdata_valid = 1'b0;
        assign soc_gpu_mem_rdata_data  = {soc_pkg::SOC_SDRAM_NATIVE_DW{1'b0}};
        assign soc_sdram_dat_r      = 32'd0;
        assign soc_sdram_ack        = 1'b0;
        assign soc_sdram_err        = 1'b0;
        assign soc_sdram_ctrl_dat_r = 32'd0;
        assign soc_sdram_ctrl_ack   = 1'b0;
        assign soc_sdram_ctrl_err   = 1'b0;
        assign soc_flash_miso       = 1'b0;
        wire unused_sdram_in = &{1'b0, sdram_dat_r, sdram_ack, sdram_err, sdram_ctrl_dat_r, sdram_ctrl_ack,
                                 sdram_ctrl_err, flash_miso, gpu_mem_cmd_ready, gpu_mem_wdata_ready,
                                 gpu_mem_rdata_valid, gpu_mem_rdata_data};
    end endgenerate

    soc_top #(
        .RAM_BYTES    (RAM_BYTES),
        .SDRAM_BYTES  (SDRAM_BYTES),
        .RAM_INIT     (RAM_INIT),
        .CLK_HZ       (SYS_HZ),
        .PIX_CLK_HZ   (25000000),
        .BAUD         (BAUD),
        .USB_HOST     (USB_HOST),
        .PROJ_UNIT    (PROJ_UNIT),
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
        .sdram_cyc         (sdram_cyc),
        .sdram_stb         (sdram_stb),
        .sdram_we          (sdram_we),
        .sdram_adr         (sdram_adr),
        .sdram_dat_w       (sdram_dat_w),
        .sdram_sel         (sdram_sel),
        .sdram_cti         (sdram_cti),
        .sdram_dat_r       (soc_sdram_dat_r),
        .sdram_ack         (soc_sdram_ack),
        .sdram_err         (soc_sdram_err),
        .sdram_ctrl_cyc    (sdram_ctrl_cyc),
        .sdram_ctrl_stb    (sdram_ctrl_stb),
        .sdram_ctrl_we     (sdram_ctrl_we),
        .sdram_ctrl_adr    (sdram_ctrl_adr),
        .sdram_ctrl_dat_w  (sdram_ctrl_dat_w),
        .sdram_ctrl_sel    (sdram_ctrl_sel),
        .sdram_ctrl_dat_r  (soc_sdram_ctrl_dat_r),
        .sdram_ctrl_ack    (soc_sdram_ctrl_ack),
        .sdram_ctrl_err    (soc_sdram_ctrl_err),
        .flash_cs_n        (flash_cs_n),
        .flash_sck         (flash_sck),
        .flash_mosi        (flash_mosi),
        .flash_miso        (soc_flash_miso),
        .usb_dp_in         (usb_dp_in),
        .usb_dn_in         (usb_dn_in),
        .usb_dp_out        (usb_dp_out),
        .usb_dn_out        (usb_dn_out),
        .usb_oe            (usb_oe),
        .gpu_mem_cmd_valid   (gpu_mem_cmd_valid),
        .gpu_mem_cmd_ready   (soc_gpu_mem_cmd_ready),
        .gpu_mem_cmd_we      (gpu_mem_cmd_we),
        .gpu_mem_cmd_addr    (gpu_mem_cmd_addr),
        .gpu_mem_wdata_valid (gpu_mem_wdata_valid),
        .gpu_mem_wdata_ready (soc_gpu_mem_wdata_ready),
        .gpu_mem_wdata_data  (gpu_mem_wdata_data),
        .gpu_mem_wdata_we    (gpu_mem_wdata_we),
        .gpu_mem_rdata_valid (soc_gpu_mem_rdata_valid),
        .gpu_mem_rdata_ready (gpu_mem_rdata_ready),
        .gpu_mem_rdata_data  (soc_gpu_mem_rdata_data),
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
    // LiteDRAM's reset (its own two flops follow): the SoC's reset request, as soc_top takes it,
    // synchronised here so that nothing of the SDRAM side sees an asynchronous level. Without SDRAM
    // nothing reads it and synthesis drops it.
    gpu_cdc_sync #(.RESET_VALUE(1'b1)) u_rst_sdram_sync (.clk(clk_sys), .in(unlocked || btn_reset), .out(sdram_rst));

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
