// soc_wb_decoder: the SoC's address decoder (contract/soc-memory-map.md), one Wishbone bus onto the
// RAM, the SDRAM, its controller's registers and the flash (when the build has SDRAM, whose
// firmware the boot program copies from the flash), the GPU, the UART, SYS and the USB host (when the
// build has one), with the error responder for every other address.
//
// Contract: combinational select, no added latency. A slave's *_stb is cyc && stb && (the address is
// in its region); the shared request signals (we, adr, dat_w, sel, cti) go to every slave unchanged
// (wired in soc_top). ack/err/dat_r come from the selected slave; the slaves answer only while
// selected, so ack and err are ORed and dat_r is multiplexed by the region. The RAM region answers
// only below RAM_BYTES, the SDRAM region only below SDRAM_BYTES, the SDRAM_CTRL and FLASH regions
// only when SDRAM_BYTES is not 0, the USB region only when USB_HOST is not 0; the rest of those windows, and every address outside the regions, is
// answered by the error responder: err one clock after the request, once per request (so a burst
// there gets one err per beat, two clocks each), dat_r = 0. Offsets inside UART, SYS and USB that
// name no register are refused by those slaves themselves (they answer err).
`default_nettype none

module soc_wb_decoder #(
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // the RAM's size: above it, err
    parameter integer SDRAM_BYTES = 0,      // the SDRAM's size: above it, err; 0: no SDRAM, no SDRAM_CTRL
    parameter integer USB_HOST = 0          // 1: the USB region is decoded; 0: it answers err
) (
    input  wire        clk,
    input  wire        rst,         // synchronous, active high
    // the bus, from the arbiter
    input  wire        cyc,
    input  wire        stb,
    input  wire [29:0] adr,         // word address (byte address [31:2])
    output wire [31:0] dat_r,
    output wire        ack,
    output wire        err,
    // RAM
    output wire        ram_stb,
    input  wire [31:0] ram_dat_r,
    input  wire        ram_ack,
    // SDRAM (its controller's user port) and its controller's registers
    output wire        sdram_stb,
    input  wire [31:0] sdram_dat_r,
    input  wire        sdram_ack,
    input  wire        sdram_err,
    output wire        sdram_ctrl_stb,
    input  wire [31:0] sdram_ctrl_dat_r,
    input  wire        sdram_ctrl_ack,
    input  wire        sdram_ctrl_err,
    // the flash (soc_spiflash; it refuses writes with err)
    output wire        flash_stb,
    input  wire [31:0] flash_dat_r,
    input  wire        flash_ack,
    input  wire        flash_err,
    // GPU (gpu_wb_slave; it refuses partial writes with err)
    output wire        gpu_stb,
    input  wire [31:0] gpu_dat_r,
    input  wire        gpu_ack,
    input  wire        gpu_err,
    // UART
    output wire        uart_stb,
    input  wire [31:0] uart_dat_r,
    input  wire        uart_ack,
    input  wire        uart_err,
    // SYS
    output wire        sys_stb,
    input  wire [31:0] sys_dat_r,
    input  wire        sys_ack,
    input  wire        sys_err,
    // the USB host's registers (soc_usb)
    output wire        usb_stb,
    input  wire [31:0] usb_dat_r,
    input  wire        usb_ack,
    input  wire        usb_err
);
    // Each region is a power-of-two window aligned to its size (checked by contract/gen_contract.py):
    // it is selected by the byte address bits above the window.
    localparam integer RAM_WB  = $clog2(soc_pkg::SOC_RAM_WINDOW_BYTES);
    localparam integer SDRAM_WB = $clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES);
    localparam integer SDRAM_CTRL_WB = $clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES);
    localparam integer FLASH_WB = $clog2(soc_pkg::SOC_FLASH_WINDOW_BYTES);
    localparam integer GPU_WB  = $clog2(soc_pkg::SOC_GPU_WINDOW_BYTES);
    localparam integer UART_WB = $clog2(soc_pkg::SOC_UART_WINDOW_BYTES);
    localparam integer SYS_WB  = $clog2(soc_pkg::SOC_SYS_WINDOW_BYTES);
    localparam integer USB_WB  = $clog2(soc_pkg::SOC_USB_WINDOW_BYTES);
    localparam [31:0] RAM_BASE  = soc_pkg::SOC_RAM_BASE;
    localparam [31:0] SDRAM_BASE = soc_pkg::SOC_SDRAM_BASE;
    localparam [31:0] SDRAM_CTRL_BASE = soc_pkg::SOC_SDRAM_CTRL_BASE;
    localparam [31:0] FLASH_BASE = soc_pkg::SOC_FLASH_BASE;
    localparam [31:0] GPU_BASE  = soc_pkg::SOC_GPU_BASE;
    localparam [31:0] UART_BASE = soc_pkg::SOC_UART_BASE;
    localparam [31:0] SYS_BASE  = soc_pkg::SOC_SYS_BASE;
    localparam [31:0] USB_BASE  = soc_pkg::SOC_USB_BASE;
    localparam [31:0] RAM_LIMIT = RAM_BYTES;   // bytes of the RAM window that hold RAM
    localparam [31:0] SDRAM_LIMIT = SDRAM_BYTES;  // bytes of the SDRAM window that hold SDRAM

    generate if (RAM_BYTES < 4 || RAM_BYTES % 4 != 0 || RAM_BYTES > soc_pkg::SOC_RAM_WINDOW_BYTES) begin : g_bad_ram
        $error("soc_wb_decoder: RAM_BYTES must be a multiple of 4 within SOC_RAM_WINDOW_BYTES");
    end endgenerate
    generate if (SDRAM_BYTES < 0 || SDRAM_BYTES % 4 != 0 || SDRAM_BYTES > soc_pkg::SOC_SDRAM_WINDOW_BYTES) begin : g_bad_sdram
        $error("soc_wb_decoder: SDRAM_BYTES must be 0 or a multiple of 4 within SOC_SDRAM_WINDOW_BYTES");
    end endgenerate

    wire [31:0] byte_adr = {adr, 2'b00};
    // Inside its window a region's offset is the address's bits below the window (the base is
    // aligned to the window's size): no 32-bit subtract before the compare, and none at all where
    // the memory fills its window (these compares sit on the CPU's refill path to the SDRAM port).
    wire ram_in_size;     // below RAM_BYTES
    generate if (RAM_BYTES == soc_pkg::SOC_RAM_WINDOW_BYTES) begin : g_ram_whole
        assign ram_in_size = 1'b1;
    end else begin : g_ram_part
        assign ram_in_size = byte_adr[RAM_WB-1:0] < RAM_LIMIT[RAM_WB-1:0];
    end endgenerate
    wire hit_ram  = (byte_adr >> RAM_WB) == (RAM_BASE >> RAM_WB) && ram_in_size;
    wire sdram_in_size;   // below SDRAM_BYTES (a build without SDRAM has no such address)
    generate if (SDRAM_BYTES == 0) begin : g_no_sdram
        assign sdram_in_size = 1'b0;
    end else if (SDRAM_BYTES == soc_pkg::SOC_SDRAM_WINDOW_BYTES) begin : g_sdram_whole
        assign sdram_in_size = 1'b1;
    end else begin : g_sdram
        assign sdram_in_size = byte_adr[SDRAM_WB-1:0] < SDRAM_LIMIT[SDRAM_WB-1:0];
    end endgenerate
    wire hit_sdram = (byte_adr >> SDRAM_WB) == (SDRAM_BASE >> SDRAM_WB) && sdram_in_size;
    wire hit_sdram_ctrl = SDRAM_BYTES != 0 && (byte_adr >> SDRAM_CTRL_WB) == (SDRAM_CTRL_BASE >> SDRAM_CTRL_WB);
    wire hit_flash = SDRAM_BYTES != 0 && (byte_adr >> FLASH_WB) == (FLASH_BASE >> FLASH_WB);
    wire hit_gpu  = (byte_adr >> GPU_WB) == (GPU_BASE >> GPU_WB);
    wire hit_uart = (byte_adr >> UART_WB) == (UART_BASE >> UART_WB);
    wire hit_sys  = (byte_adr >> SYS_WB) == (SYS_BASE >> SYS_WB);
    wire hit_usb  = USB_HOST != 0 && (byte_adr >> USB_WB) == (USB_BASE >> USB_WB);
    wire hit_none = !(hit_ram || hit_sdram || hit_sdram_ctrl || hit_flash || hit_gpu || hit_uart || hit_sys
                      || hit_usb);

    wire req = cyc && stb;
    assign ram_stb  = req && hit_ram;
    assign sdram_stb = req && hit_sdram;
    assign sdram_ctrl_stb = req && hit_sdram_ctrl;
    assign flash_stb = req && hit_flash;
    assign gpu_stb  = req && hit_gpu;
    assign uart_stb = req && hit_uart;
    assign sys_stb  = req && hit_sys;
    assign usb_stb  = req && hit_usb;

    // The error responder: answers a request to no region in the next clock, then lets it go (the
    // master moves on after err), so a request held on is answered again every other clock.
    reg none_err_q;
    always @(posedge clk) begin
        if (rst) none_err_q <= 1'b0;
        else     none_err_q <= req && hit_none && !none_err_q;
    end
    wire none_err = none_err_q && req && hit_none;

    assign ack   = ram_ack || sdram_ack || sdram_ctrl_ack || flash_ack || gpu_ack || uart_ack || sys_ack
                   || usb_ack;
    assign err   = none_err || sdram_err || sdram_ctrl_err || flash_err || gpu_err || uart_err || sys_err
                   || usb_err;
    assign dat_r = hit_ram  ? ram_dat_r  :
                   hit_sdram ? sdram_dat_r :
                   hit_sdram_ctrl ? sdram_ctrl_dat_r :
                   hit_flash ? flash_dat_r :
                   hit_gpu  ? gpu_dat_r  :
                   hit_uart ? uart_dat_r :
                   hit_sys  ? sys_dat_r  :
                   hit_usb  ? usb_dat_r  : 32'd0;
endmodule

`default_nettype wire
