// soc_top: the whole SoC on its system clock — VexRiscv (RV32IM, 4 KiB I$ and D$, its custom-function
// port to the projection unit soc_proj_unit), on-chip RAM, the GPU,
// a UART and the system registers, on one Wishbone bus. Memory map: contract/soc-memory-map.md.
// With SDRAM_BYTES > 0 the SDRAM region and its controller's registers leave soc_top as two Wishbone
// master ports (sdram_*, sdram_ctrl_*): the controller (LiteDRAM, generated at build time, and the
// chip's pins) belongs to the system around soc_top (soc_rtl/litedram, docs/sdram.md). Such a build
// also reads the board's SPI flash (soc_spiflash, region FLASH: the boot program copies the
// firmware from it into the SDRAM, docs/boot.md); its pins leave soc_top as flash_* (on ECP5 the
// board's top sends flash_sck through USRMCLK). Without SDRAM the three regions answer ERR and the
// ports stay idle (tie their inputs to 0: soc_rtl/soc_top_no_sdram.vh). A GPU built with FRAME_DRAM
// keeps its frames in the SDRAM: its memory port leaves soc_top as gpu_mem_* for the controller's
// second user port (soc_sdram); otherwise that port is idle. With USB_HOST = 1 the USB low-speed
// host for a boot keyboard (soc_usb, region USB, docs/usb.md) drives the usb_* pins; without it the
// region answers ERR and the pins stay released (usb_oe low; tie the inputs to 0).
//
//   VexRiscv iBus ─┐                      ┌─ soc_ram (RAM_BYTES, RAM_INIT)
//                  ├─ soc_wb_arbiter ─ soc_wb_decoder ─┼─ gpu_wb_slave ─ gpu_top ─ VGA pins
//   VexRiscv dBus ─┘   (round robin,      (regions,    ├─ (the SDRAM port)
//                       per CYC)           err for     └─ soc_wb_stage ─┬─ soc_uart ─ uart_rx / uart_tx
//                                          the rest)      (a clock)     ├─ soc_sys ─ leds, exit, timer, bus errors
//                                                                       └─ flash, SDRAM registers, USB host
//
// The slow slaves (the UART, SYS, the flash, the SDRAM controller's registers, the USB host) take
// their requests from soc_wb_stage's flops, a clock after the bus: the bus's paths from the CPU
// end there instead of in their logic, some by the pins (issue #27); none of them is on a frame's
// hot path (the RAM, the SDRAM and the GPU are reached directly).
//
// Reset: a power-on counter holds everything in reset for POR_CLKS clocks after configuration (the
// FPGA's flops start at their initial values), and again after ext_rst (a button; two-flop
// synchronised). The core starts at SOC_RAM_BASE.
// Bus errors: the packaged VexRiscv ignores Wishbone ERR (its bridges tie the response error to 0),
// so here a refused beat is answered to the core as an ACK with data 0 (a load reads 0, a fetch
// reads 0x00000000 = illegal instruction, a store is dropped) and reported to soc_sys, which records
// it (BUS_ERR, BUS_ERR_ADDR) and raises external interrupt SOC_IRQ_BUS_ERROR: no hang, no silence.
// Clocks: clk runs everything but the GPU's scan-out, which runs on clk_pix (gpu_top crosses between
// them): a board gives a 25 MHz pixel clock; a simulation may tie clk_pix to clk and say so with
// PIX_CLK_HZ = CLK_HZ. PIX_CLK_HZ must be a multiple of the 25 MHz VGA pixel rate.
// The GPU's build parameters (contract/gpu_build_params.vh) are passed through to gpu_top; a scene's
// manifest may size the buffers (VTX_CAP, TRI_CAP) to it; ENABLE_WMASK costs 4 EBR on ECP5 (README).
`include "contract/gpu_build_params.vh"
`default_nettype none

module soc_top #(
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // on-chip RAM; 192 KiB = 96 ECP5 EBR
    parameter integer SDRAM_BYTES = 0,          // the SDRAM behind the sdram_* port; 0: none
    parameter RAM_INIT = "",                   // $readmemh image of the RAM (one 32-bit word a line)
    parameter integer CLK_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,  // clk's frequency: UART divider, SYS CLK_HZ
    parameter integer PIX_CLK_HZ = 25000000,   // clk_pix's frequency: 25 MHz, or CLK_HZ when tied to clk
    parameter integer BAUD = soc_pkg::SOC_UART_BAUD,         // UART bits per second
    parameter integer USB_HOST = 0,            // 1: the USB keyboard host (soc_usb); 0: none
    parameter integer PROJ_UNIT = 1,           // 1: the projection unit (soc_proj_unit); 0: none
    `GPU_BUILD_PARAMS,                         // the GPU's (gpu_top), passed through
    localparam integer PIX_HZ = 25000000,      // VGA 640x480@60 pixel rate
    localparam integer PIX_DIV = PIX_CLK_HZ / PIX_HZ,
    localparam integer RAM_AW = $clog2(RAM_BYTES / 4),
    localparam integer SDRAM_AW = $clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4),        // word address bits
    localparam integer SDRAM_CTRL_AW = $clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4),
    localparam integer GPU_MEM_AW = soc_pkg::SOC_SDRAM_NATIVE_AW,    // native words
    localparam integer GPU_MEM_DW = soc_pkg::SOC_SDRAM_NATIVE_DW,
    localparam integer POR_CLKS = 16           // reset length after power-on or ext_rst
) (
    input  wire       clk,            // the system clock, CLK_HZ
    input  wire       clk_pix,        // the GPU's scan-out clock, PIX_CLK_HZ (may be clk)
    input  wire       ext_rst,        // board reset button, active high, asynchronous (tie 0 if none)
    // UART (8N1, BAUD)
    input  wire       uart_rx,        // the FPGA receives; asynchronous, idle high
    output wire       uart_tx,        // the FPGA transmits; idle high
    // VGA 640x480@60 (gpu_top's pins), clk_pix domain
    output wire       vga_pix_stb,    // the outputs change on the clk_pix edge where this is high
    output wire       vga_de,         // visible area (for a DVI encoder)
    output wire       vga_hsync_n,
    output wire       vga_vsync_n,
    output wire [3:0] vga_r,
    output wire [3:0] vga_g,
    output wire [3:0] vga_b,
    // SDRAM (SDRAM_BYTES > 0): Wishbone B4 classic masters; cyc is the bus's, stb this region's
    output wire                      sdram_cyc,
    output wire                      sdram_stb,
    output wire                      sdram_we,
    output wire [SDRAM_AW-1:0]       sdram_adr,       // word address from SOC_SDRAM_BASE
    output wire [31:0]               sdram_dat_w,
    output wire [3:0]                sdram_sel,
    output wire [2:0]                sdram_cti,
    input  wire [31:0]               sdram_dat_r,
    input  wire                      sdram_ack,
    input  wire                      sdram_err,
    // the controller's registers: from soc_wb_stage's flops (cyc and stb together)
    output wire                      sdram_ctrl_cyc,
    output wire                      sdram_ctrl_stb,
    output wire                      sdram_ctrl_we,
    output wire [SDRAM_CTRL_AW-1:0]  sdram_ctrl_adr,  // word address from SOC_SDRAM_CTRL_BASE
    output wire [31:0]               sdram_ctrl_dat_w,
    output wire [3:0]                sdram_ctrl_sel,
    input  wire [31:0]               sdram_ctrl_dat_r,
    input  wire                      sdram_ctrl_ack,
    input  wire                      sdram_ctrl_err,
    // the GPU's frames in the SDRAM (FRAME_DRAM, SDRAM_BYTES > 0): LiteDRAM's native user port
    // protocol, 16-bit words from SOC_SDRAM_BASE (the frames from SOC_SDRAM_GPU_FRAMES_OFFSET on);
    // idle (valid low) in a build whose frames are the GPU's block RAM
    output wire                      gpu_mem_cmd_valid,
    input  wire                      gpu_mem_cmd_ready,
    output wire                      gpu_mem_cmd_we,
    output wire [GPU_MEM_AW-1:0]     gpu_mem_cmd_addr,
    output wire                      gpu_mem_wdata_valid,
    input  wire                      gpu_mem_wdata_ready,
    output wire [GPU_MEM_DW-1:0]     gpu_mem_wdata_data,
    output wire [GPU_MEM_DW/8-1:0]   gpu_mem_wdata_we,
    input  wire                      gpu_mem_rdata_valid,
    output wire                      gpu_mem_rdata_ready,
    input  wire [GPU_MEM_DW-1:0]     gpu_mem_rdata_data,
    // SPI flash (SDRAM_BYTES > 0), SPI mode 0; idle: cs_n high, sck low
    output wire       flash_cs_n,
    output wire       flash_sck,
    output wire       flash_mosi,
    input  wire       flash_miso,     // registered inside (soc_spiflash)
    // USB low-speed host (USB_HOST = 1): D+ and D- as the host sees and drives them; the board
    // keeps both lines' pull-downs on (host mode)
    input  wire       usb_dp_in,      // asynchronous (synchronised inside)
    input  wire       usb_dn_in,
    output wire       usb_dp_out,     // driven while usb_oe
    output wire       usb_dn_out,
    output wire       usb_oe,
    // board
    output wire [7:0] leds,           // SYS LEDS
    output wire       gpu_frame_swapped,  // one clk cycle at each GPU buffer swap
    output wire       gpu_error,      // the GPU's ERRORS register is non-zero
    output wire       exit_valid,     // SYS EXIT was written (held until reset): a simulator ends
    output wire [7:0] exit_code       // its status, 0 = success
);
    generate if (PIX_DIV < 1 || PIX_DIV * PIX_HZ != PIX_CLK_HZ) begin : g_bad_clk
        $error("soc_top: PIX_CLK_HZ must be a multiple of 25 MHz (the GPU's VGA pixel rate)");
    end endgenerate

    // ---- reset: power-on counter, restarted by the (synchronised) button ----
    reg [1:0] ext_rst_sync_q = 2'b00;
    localparam integer POR_W = $clog2(POR_CLKS) + 1;
    localparam [POR_W-1:0] POR_END = POR_W'(POR_CLKS);
    reg [POR_W-1:0] por_q = '0;             // counts up to POR_END; in reset until then
    reg rst = 1'b1;                          // synchronous, active high, for everything
    always @(posedge clk) begin
        ext_rst_sync_q <= {ext_rst_sync_q[0], ext_rst};
        if (ext_rst_sync_q[1]) por_q <= '0;
        else if (rst) por_q <= por_q + 1'b1;
        rst <= ext_rst_sync_q[1] || por_q < POR_END;
    end

    // ---- the core ----
    wire        ibus_cyc, ibus_stb, ibus_we, ibus_ack, ibus_err;
    wire [29:0] ibus_adr;
    wire [31:0] ibus_dat_w, ibus_dat_r;
    wire [3:0]  ibus_sel;
    wire [2:0]  ibus_cti;
    wire [1:0]  ibus_bte;
    wire        dbus_cyc, dbus_stb, dbus_we, dbus_ack, dbus_err;
    wire [29:0] dbus_adr;
    wire [31:0] dbus_dat_w, dbus_dat_r;
    wire [3:0]  dbus_sel;
    wire [2:0]  dbus_cti;
    wire [1:0]  dbus_bte;
    wire        timer_irq, buserr_irq;
    wire        cfu_cmd_valid, cfu_cmd_ready, cfu_rsp_valid, cfu_rsp_ready;
    wire [9:0]  cfu_function_id;
    wire [31:0] cfu_in0, cfu_in1, cfu_out;

    localparam [31:0] RESET_VECTOR = soc_pkg::SOC_RAM_BASE;
    wire [31:0] ext_irqs = {31'd0, buserr_irq} << soc_pkg::SOC_IRQ_BUS_ERROR;

    VexRiscv u_cpu (
        .clk                    (clk),
        .reset                  (rst),
        .externalResetVector    (RESET_VECTOR),
        .timerInterrupt         (timer_irq),
        .softwareInterrupt      (1'b0),
        .externalInterruptArray (ext_irqs),
        .iBusWishbone_CYC       (ibus_cyc),
        .iBusWishbone_STB       (ibus_stb),
        .iBusWishbone_ACK       (ibus_ack || ibus_err),        // a refused beat completes (see header)
        .iBusWishbone_WE        (ibus_we),
        .iBusWishbone_ADR       (ibus_adr),
        .iBusWishbone_DAT_MISO  (ibus_err ? 32'd0 : ibus_dat_r),
        .iBusWishbone_DAT_MOSI  (ibus_dat_w),
        .iBusWishbone_SEL       (ibus_sel),
        .iBusWishbone_ERR       (1'b0),                        // ignored by the core
        .iBusWishbone_CTI       (ibus_cti),
        .iBusWishbone_BTE       (ibus_bte),
        .dBusWishbone_CYC       (dbus_cyc),
        .dBusWishbone_STB       (dbus_stb),
        .dBusWishbone_ACK       (dbus_ack || dbus_err),
        .dBusWishbone_WE        (dbus_we),
        .dBusWishbone_ADR       (dbus_adr),
        .dBusWishbone_DAT_MISO  (dbus_err ? 32'd0 : dbus_dat_r),
        .dBusWishbone_DAT_MOSI  (dbus_dat_w),
        .dBusWishbone_SEL       (dbus_sel),
        .dBusWishbone_ERR       (1'b0),
        .dBusWishbone_CTI       (dbus_cti),
        .dBusWishbone_BTE       (dbus_bte),
        .CfuPlugin_bus_cmd_valid              (cfu_cmd_valid),
        .CfuPlugin_bus_cmd_ready              (cfu_cmd_ready),
        .CfuPlugin_bus_cmd_payload_function_id(cfu_function_id),
        .CfuPlugin_bus_cmd_payload_inputs_0   (cfu_in0),
        .CfuPlugin_bus_cmd_payload_inputs_1   (cfu_in1),
        .CfuPlugin_bus_rsp_valid              (cfu_rsp_valid),
        .CfuPlugin_bus_rsp_ready              (cfu_rsp_ready),
        .CfuPlugin_bus_rsp_payload_outputs_0  (cfu_out)
    );

    // ---- the projection unit on the core's custom-function port (custom-0 instructions) ----
    // Without it (PROJ_UNIT = 0: a small part's build) the port answers every instruction with
    // all ones, which no command of the unit answers to the firmware's probe (a SET of no
    // register: 0), so a program built for the unit stops with an error instead of drawing wrong.
    generate
        if (PROJ_UNIT != 0) begin : g_proj_unit
            soc_proj_unit u_proj_unit (
                .clk             (clk),
                .rst             (rst),
                .cmd_valid       (cfu_cmd_valid),
                .cmd_ready       (cfu_cmd_ready),
                .cmd_function_id (cfu_function_id),
                .cmd_in0         (cfu_in0),
                .cmd_in1         (cfu_in1),
                .rsp_valid       (cfu_rsp_valid),
                .rsp_ready       (cfu_rsp_ready),
                .rsp_out         (cfu_out)
            );
        end else begin : g_no_proj_unit
            reg answered;                       // an answer offered, not yet taken
            always @(posedge clk)
                if (rst) answered <= 1'b0;
                else     answered <= answered ? !cfu_rsp_ready : cfu_cmd_valid;
            assign cfu_cmd_ready = !answered;
            assign cfu_rsp_valid = answered;
            assign cfu_out = 32'hFFFF_FFFF;
        end
    endgenerate

    // ---- the bus: arbiter, decoder ----
    wire        bus_cyc, bus_stb, bus_we, bus_ack, bus_err;
    wire [29:0] bus_adr;
    wire [31:0] bus_dat_w, bus_dat_r;
    wire [3:0]  bus_sel;
    wire [2:0]  bus_cti;

    soc_wb_arbiter u_arbiter (
        .clk      (clk),
        .rst      (rst),
        .m0_cyc   (ibus_cyc),
        .m0_stb   (ibus_stb),
        .m0_we    (ibus_we),
        .m0_adr   (ibus_adr),
        .m0_dat_w (ibus_dat_w),
        .m0_sel   (ibus_sel),
        .m0_cti   (ibus_cti),
        .m0_dat_r (ibus_dat_r),
        .m0_ack   (ibus_ack),
        .m0_err   (ibus_err),
        .m1_cyc   (dbus_cyc),
        .m1_stb   (dbus_stb),
        .m1_we    (dbus_we),
        .m1_adr   (dbus_adr),
        .m1_dat_w (dbus_dat_w),
        .m1_sel   (dbus_sel),
        .m1_cti   (dbus_cti),
        .m1_dat_r (dbus_dat_r),
        .m1_ack   (dbus_ack),
        .m1_err   (dbus_err),
        .s_cyc    (bus_cyc),
        .s_stb    (bus_stb),
        .s_we     (bus_we),
        .s_adr    (bus_adr),
        .s_dat_w  (bus_dat_w),
        .s_sel    (bus_sel),
        .s_cti    (bus_cti),
        .s_dat_r  (bus_dat_r),
        .s_ack    (bus_ack),
        .s_err    (bus_err)
    );

    wire        ram_stb, ram_ack;
    wire [31:0] ram_dat_r;
    wire        gpu_stb, gpu_ack, gpu_err;
    wire [31:0] gpu_dat_r;
    wire        uart_stb, uart_ack, uart_err;
    wire [31:0] uart_dat_r;
    wire        sys_stb, sys_ack, sys_err;
    wire [31:0] sys_dat_r;
    wire        flash_stb, flash_ack, flash_err;
    wire [31:0] flash_dat_r;
    wire        usb_stb, usb_ack, usb_err;
    // the decoder's selects of the slow slaves (soc_wb_stage takes them; *_stb are its outputs)
    wire        flash_req, sdram_ctrl_req, uart_req, sys_req, usb_req;
    wire [31:0] usb_dat_r;

    soc_wb_decoder #(
        .RAM_BYTES   (RAM_BYTES),
        .SDRAM_BYTES (SDRAM_BYTES),
        .USB_HOST    (USB_HOST)
    ) u_decoder (
        .clk        (clk),
        .rst        (rst),
        .cyc        (bus_cyc),
        .stb        (bus_stb),
        .adr        (bus_adr),
        .dat_r      (bus_dat_r),
        .ack        (bus_ack),
        .err        (bus_err),
        .ram_stb    (ram_stb),
        .ram_dat_r  (ram_dat_r),
        .ram_ack    (ram_ack),
        .sdram_stb  (sdram_stb),
        .sdram_dat_r(sdram_dat_r),
        .sdram_ack  (sdram_ack),
        .sdram_err  (sdram_err),
        .sdram_ctrl_stb  (sdram_ctrl_req),
        .sdram_ctrl_dat_r(sdram_ctrl_dat_r),
        .sdram_ctrl_ack  (sdram_ctrl_ack),
        .sdram_ctrl_err  (sdram_ctrl_err),
        .flash_stb  (flash_req),
        .flash_dat_r(flash_dat_r),
        .flash_ack  (flash_ack),
        .flash_err  (flash_err),
        .gpu_stb    (gpu_stb),
        .gpu_dat_r  (gpu_dat_r),
        .gpu_ack    (gpu_ack),
        .gpu_err    (gpu_err),
        .uart_stb   (uart_req),
        .uart_dat_r (uart_dat_r),
        .uart_ack   (uart_ack),
        .uart_err   (uart_err),
        .sys_stb    (sys_req),
        .sys_dat_r  (sys_dat_r),
        .sys_ack    (sys_ack),
        .sys_err    (sys_err),
        .usb_stb    (usb_req),
        .usb_dat_r  (usb_dat_r),
        .usb_ack    (usb_ack),
        .usb_err    (usb_err)
    );

    // ---- slaves ----
    // The SDRAM's two ports: the bus's request, this region's stb (from the decoder).
    assign sdram_cyc        = bus_cyc;
    assign sdram_we         = bus_we;
    assign sdram_adr        = bus_adr[SDRAM_AW-1:0];
    assign sdram_dat_w      = bus_dat_w;
    assign sdram_sel        = bus_sel;
    assign sdram_cti        = bus_cti;

    // ---- the slow slaves, behind one register stage: their requests from its flops ----
    localparam integer SLOW_N = 5;
    localparam integer SLOW_FLASH = 0, SLOW_SDRAM_CTRL = 1, SLOW_UART = 2, SLOW_SYS = 3, SLOW_USB = 4;
    localparam integer FLASH_AW = $clog2(soc_pkg::SOC_FLASH_WINDOW_BYTES / 4);
    localparam integer UART_AW = $clog2(soc_pkg::SOC_UART_WINDOW_BYTES / 4);
    localparam integer SYS_AW = $clog2(soc_pkg::SOC_SYS_WINDOW_BYTES / 4);
    localparam integer USB_AW = $clog2(soc_pkg::SOC_USB_WINDOW_BYTES / 4);
    // the word address bits they need: their widest window's
    localparam integer SLOW_AW = max_of(max_of(FLASH_AW, SDRAM_CTRL_AW), max_of(max_of(UART_AW, SYS_AW), USB_AW));
    function automatic integer max_of(input integer a, input integer b);
        max_of = a > b ? a : b;
    endfunction
    wire [SLOW_N-1:0] slow_stb;
    wire        slow_cyc, slow_we;
    wire [SLOW_AW-1:0] slow_adr;
    wire [31:0] slow_dat_w;
    wire [3:0]  slow_sel;
    soc_wb_stage #(
        .N  (SLOW_N),
        .AW (SLOW_AW)
    ) u_slow (
        .clk      (clk),
        .rst      (rst),
        .cyc      (bus_cyc),
        .m_stb    ({usb_req, sys_req, uart_req, sdram_ctrl_req, flash_req}),
        .we       (bus_we),
        .adr      (bus_adr[SLOW_AW-1:0]),
        .dat_w    (bus_dat_w),
        .sel      (bus_sel),
        .s_cyc    (slow_cyc),
        .s_stb    (slow_stb),
        .s_we     (slow_we),
        .s_adr    (slow_adr),
        .s_dat_w  (slow_dat_w),
        .s_sel    (slow_sel),
        .s_answer ({usb_ack || usb_err, sys_ack || sys_err, uart_ack || uart_err,
                    sdram_ctrl_ack || sdram_ctrl_err, flash_ack || flash_err})
    );
    assign flash_stb        = slow_stb[SLOW_FLASH];
    assign uart_stb         = slow_stb[SLOW_UART];
    assign sys_stb          = slow_stb[SLOW_SYS];
    assign usb_stb          = slow_stb[SLOW_USB];
    assign sdram_ctrl_cyc   = slow_cyc;
    assign sdram_ctrl_stb   = slow_stb[SLOW_SDRAM_CTRL];
    assign sdram_ctrl_we    = slow_we;
    assign sdram_ctrl_adr   = slow_adr[SDRAM_CTRL_AW-1:0];
    assign sdram_ctrl_dat_w = slow_dat_w;
    assign sdram_ctrl_sel   = slow_sel;

    generate if (SDRAM_BYTES != 0) begin : g_flash
        soc_spiflash #(
            .CLK_HZ    (CLK_HZ),
            .ADDR_BITS (FLASH_AW + 2)
        ) u_flash (
            .clk        (clk),
            .rst        (rst),
            .wb_cyc     (slow_cyc),
            .wb_stb     (flash_stb),
            .wb_we      (slow_we),
            .wb_adr     (slow_adr[FLASH_AW-1:0]),
            .wb_sel     (slow_sel),
            .wb_dat_w   (slow_dat_w),
            .wb_dat_r   (flash_dat_r),
            .wb_ack     (flash_ack),
            .wb_err     (flash_err),
            .flash_cs_n (flash_cs_n),
            .flash_sck  (flash_sck),
            .flash_mosi (flash_mosi),
            .flash_miso (flash_miso)
        );
    end else begin : g_no_flash
        // the decoder never selects the FLASH region without SDRAM
        assign flash_dat_r = 32'd0;
        assign flash_ack   = 1'b0;
        assign flash_err   = 1'b0;
        assign flash_cs_n  = 1'b1;
        assign flash_sck   = 1'b0;
        assign flash_mosi  = 1'b0;
        wire unused_flash = &{1'b0, flash_stb, flash_miso, slow_adr};  // (the flash's address bits)
    end endgenerate

    soc_ram #(
        .RAM_BYTES (RAM_BYTES),
        .RAM_INIT  (RAM_INIT)
    ) u_ram (
        .clk      (clk),
        .rst      (rst),
        .wb_cyc   (bus_cyc),
        .wb_stb   (ram_stb),
        .wb_we    (bus_we),
        .wb_adr   (bus_adr[RAM_AW-1:0]),
        .wb_dat_w (bus_dat_w),
        .wb_sel   (bus_sel),
        .wb_cti   (bus_cti),
        .wb_dat_r (ram_dat_r),
        .wb_ack   (ram_ack)
    );

    wire        gpu_bus_valid, gpu_bus_write, gpu_bus_rvalid;
    wire [16:2] gpu_bus_addr;
    wire [31:0] gpu_bus_wdata, gpu_bus_rdata;

    gpu_wb_slave u_gpu_wb (
        .clk        (clk),
        .rst        (rst),
        .wb_cyc     (bus_cyc),
        .wb_stb     (gpu_stb),
        .wb_we      (bus_we),
        .wb_adr     (bus_adr[14:0]),
        .wb_dat_w   (bus_dat_w),
        .wb_sel     (bus_sel),
        .wb_dat_r   (gpu_dat_r),
        .wb_ack     (gpu_ack),
        .wb_err     (gpu_err),
        .bus_valid  (gpu_bus_valid),
        .bus_write  (gpu_bus_write),
        .bus_addr   (gpu_bus_addr),
        .bus_wdata  (gpu_bus_wdata),
        .bus_rdata  (gpu_bus_rdata),
        .bus_rvalid (gpu_bus_rvalid)
    );

    gpu_top #(
        `GPU_BUILD_PARAMS_PASS,
        .PIX_DIV      (PIX_DIV),
        .MEM_AW       (GPU_MEM_AW),
        .MEM_DW       (GPU_MEM_DW),
        .FRAME_BASE   (soc_pkg::SOC_SDRAM_GPU_FRAMES_OFFSET / (GPU_MEM_DW / 8))
    ) u_gpu (
        .clk         (clk),
        .rst         (rst),
        .clk_pix     (clk_pix),
        .bus_valid   (gpu_bus_valid),
        .bus_write   (gpu_bus_write),
        .bus_addr    (gpu_bus_addr),
        .bus_wdata   (gpu_bus_wdata),
        .bus_rdata   (gpu_bus_rdata),
        .bus_rvalid  (gpu_bus_rvalid),
        .frame_swapped (gpu_frame_swapped),
        .error       (gpu_error),
        .vga_pix_stb (vga_pix_stb),
        .vga_de      (vga_de),
        .vga_hsync_n (vga_hsync_n),
        .vga_vsync_n (vga_vsync_n),
        .vga_r       (vga_r),
        .vga_g       (vga_g),
        .vga_b       (vga_b),
        .mem_cmd_valid   (gpu_mem_cmd_valid),
        .mem_cmd_ready   (gpu_mem_cmd_ready),
        .mem_cmd_we      (gpu_mem_cmd_we),
        .mem_cmd_addr    (gpu_mem_cmd_addr),
        .mem_wdata_valid (gpu_mem_wdata_valid),
        .mem_wdata_ready (gpu_mem_wdata_ready),
        .mem_wdata_data  (gpu_mem_wdata_data),
        .mem_wdata_we    (gpu_mem_wdata_we),
        .mem_rdata_valid (gpu_mem_rdata_valid),
        .mem_rdata_ready (gpu_mem_rdata_ready),
        .mem_rdata_data  (gpu_mem_rdata_data)
    );
    generate if (FRAME_DRAM != 0 && (SDRAM_BYTES == 0
                 || soc_pkg::SOC_SDRAM_GPU_FRAMES_OFFSET + 2 * FB_WIDTH * FB_HEIGHT > SDRAM_BYTES)) begin : g_bad_frames
        $error("soc_top: the GPU's frames in SDRAM (FRAME_DRAM) need an SDRAM that holds them (SDRAM_BYTES)");
    end endgenerate

    soc_uart #(
        .CLK_HZ (CLK_HZ),
        .BAUD   (BAUD)
    ) u_uart (
        .clk           (clk),
        .rst           (rst),
        .wb_cyc        (slow_cyc),
        .wb_stb        (uart_stb),
        .wb_we         (slow_we),
        .wb_adr        (slow_adr[UART_AW-1:0]),
        .wb_dat_w      (slow_dat_w[7:0]),
        .wb_dat_r      (uart_dat_r),
        .wb_ack        (uart_ack),
        .wb_err        (uart_err),
        .uart_rx_async (uart_rx),
        .uart_tx       (uart_tx)
    );

    generate if (USB_HOST != 0) begin : g_usb
        soc_usb #(
            .SYS_HZ (CLK_HZ)
        ) u_usb (
            .clk        (clk),
            .rst        (rst),
            .wb_cyc     (slow_cyc),
            .wb_stb     (usb_stb),
            .wb_we      (slow_we),
            .wb_adr     (slow_adr[USB_AW-1:0]),
            .wb_dat_w   (slow_dat_w),
            .wb_sel     (slow_sel),
            .wb_dat_r   (usb_dat_r),
            .wb_ack     (usb_ack),
            .wb_err     (usb_err),
            .usb_dp_in  (usb_dp_in),
            .usb_dn_in  (usb_dn_in),
            .usb_dp_out (usb_dp_out),
            .usb_dn_out (usb_dn_out),
            .usb_oe     (usb_oe)
        );
    end else begin : g_no_usb
        // the decoder never selects the USB region without the host
        assign usb_dat_r  = 32'd0;
        assign usb_ack    = 1'b0;
        assign usb_err    = 1'b0;
        assign usb_dp_out = 1'b0;
        assign usb_dn_out = 1'b0;
        assign usb_oe     = 1'b0;
        wire unused_usb = &{1'b0, usb_stb, usb_dp_in, usb_dn_in};
    end endgenerate

    // The refused beats of either bus, for the SYS record (one clock each).
    wire        buserr_stb   = ibus_err || dbus_err;
    wire [31:0] buserr_addr  = {ibus_err ? ibus_adr : dbus_adr, 2'b00};
    wire        buserr_write = dbus_err && dbus_we;

    soc_sys #(
        .CLK_HZ      (CLK_HZ),
        .RAM_BYTES   (RAM_BYTES),
        .SDRAM_BYTES (SDRAM_BYTES)
    ) u_sys (
        .clk          (clk),
        .rst          (rst),
        .wb_cyc       (slow_cyc),
        .wb_stb       (sys_stb),
        .wb_we        (slow_we),
        .wb_adr       (slow_adr[SYS_AW-1:0]),
        .wb_dat_w     (slow_dat_w),
        .wb_sel       (slow_sel),
        .wb_dat_r     (sys_dat_r),
        .wb_ack       (sys_ack),
        .wb_err       (sys_err),
        .buserr_stb   (buserr_stb),
        .buserr_addr  (buserr_addr),
        .buserr_write (buserr_write),
        .buserr_fetch (ibus_err),
        .timer_irq    (timer_irq),
        .buserr_irq   (buserr_irq),
        .leds         (leds),
        .exit_valid   (exit_valid),
        .exit_code    (exit_code)
    );
endmodule

`default_nettype wire
