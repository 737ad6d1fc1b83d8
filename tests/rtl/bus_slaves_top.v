// bus_slaves_top: test-only top for tests/rtl/bus_slaves_tb.cpp — one gpu_top (default build) behind
// either gpu_wb_slave (sel = 0) or gpu_axil_slave (sel = 1). The native bus between the chosen slave
// and the GPU is brought out (mon_*) so that the testbench can check every access a slave makes.
// The slave not chosen sees bus_rvalid = 0 and its native-bus outputs are ignored; the testbench keeps
// its inputs idle.
`default_nettype none

module bus_slaves_top (
    input  wire        clk,
    input  wire        rst,
    input  wire        sel,            // 0: Wishbone slave drives the GPU, 1: AXI4-Lite slave
    // Wishbone
    input  wire        wb_cyc,
    input  wire        wb_stb,
    input  wire        wb_we,
    input  wire [16:2] wb_adr,
    input  wire [31:0] wb_dat_w,
    input  wire [3:0]  wb_sel,
    output wire [31:0] wb_dat_r,
    output wire        wb_ack,
    output wire        wb_err,
    // AXI4-Lite
    input  wire        s_axi_awvalid,
    output wire        s_axi_awready,
    input  wire [16:0] s_axi_awaddr,
    input  wire        s_axi_wvalid,
    output wire        s_axi_wready,
    input  wire [31:0] s_axi_wdata,
    input  wire [3:0]  s_axi_wstrb,
    output wire        s_axi_bvalid,
    input  wire        s_axi_bready,
    output wire [1:0]  s_axi_bresp,
    input  wire        s_axi_arvalid,
    output wire        s_axi_arready,
    input  wire [16:0] s_axi_araddr,
    output wire        s_axi_rvalid,
    input  wire        s_axi_rready,
    output wire [31:0] s_axi_rdata,
    output wire [1:0]  s_axi_rresp,
    // the native bus, observed
    output wire        mon_valid,
    output wire        mon_write,
    output wire [16:2] mon_addr,
    output wire [31:0] mon_wdata,
    output wire [31:0] mon_rdata,
    output wire        mon_rvalid
);
    wire        wb_bus_valid, wb_bus_write, ax_bus_valid, ax_bus_write;
    wire [16:2] wb_bus_addr, ax_bus_addr;
    wire [31:0] wb_bus_wdata, ax_bus_wdata;

    gpu_wb_slave u_wb (
        .clk(clk), .rst(rst),
        .wb_cyc(wb_cyc), .wb_stb(wb_stb), .wb_we(wb_we), .wb_adr(wb_adr), .wb_dat_w(wb_dat_w),
        .wb_sel(wb_sel), .wb_dat_r(wb_dat_r), .wb_ack(wb_ack), .wb_err(wb_err),
        .bus_valid(wb_bus_valid), .bus_write(wb_bus_write), .bus_addr(wb_bus_addr),
        .bus_wdata(wb_bus_wdata), .bus_rdata(mon_rdata), .bus_rvalid(mon_rvalid && !sel)
    );

    gpu_axil_slave u_axil (
        .clk(clk), .rst(rst),
        .s_axi_awvalid(s_axi_awvalid), .s_axi_awready(s_axi_awready), .s_axi_awaddr(s_axi_awaddr),
        .s_axi_awprot(3'b000),
        .s_axi_wvalid(s_axi_wvalid), .s_axi_wready(s_axi_wready), .s_axi_wdata(s_axi_wdata),
        .s_axi_wstrb(s_axi_wstrb),
        .s_axi_bvalid(s_axi_bvalid), .s_axi_bready(s_axi_bready), .s_axi_bresp(s_axi_bresp),
        .s_axi_arvalid(s_axi_arvalid), .s_axi_arready(s_axi_arready), .s_axi_araddr(s_axi_araddr),
        .s_axi_arprot(3'b000),
        .s_axi_rvalid(s_axi_rvalid), .s_axi_rready(s_axi_rready), .s_axi_rdata(s_axi_rdata),
        .s_axi_rresp(s_axi_rresp),
        .bus_valid(ax_bus_valid), .bus_write(ax_bus_write), .bus_addr(ax_bus_addr),
        .bus_wdata(ax_bus_wdata), .bus_rdata(mon_rdata), .bus_rvalid(mon_rvalid && sel)
    );

    assign mon_valid = sel ? ax_bus_valid : wb_bus_valid;
    assign mon_write = sel ? ax_bus_write : wb_bus_write;
    assign mon_addr  = sel ? ax_bus_addr : wb_bus_addr;
    assign mon_wdata = sel ? ax_bus_wdata : wb_bus_wdata;

    wire vga_pix_stb, vga_de, vga_hsync_n, vga_vsync_n, frame_swapped, error;
    wire [3:0] vga_r, vga_g, vga_b;
    wire [3:0] mem_out;
    wire [23:0] mem_addr;
    wire [31:0] mem_data;  // gpu_top's default MEM_DW, the SoC's SDRAM port's
    wire [3:0] mem_we;
    gpu_top u_gpu (
        .clk(clk), .rst(rst), .clk_pix(clk),
        .bus_valid(mon_valid), .bus_write(mon_write), .bus_addr(mon_addr), .bus_wdata(mon_wdata),
        .bus_rdata(mon_rdata), .bus_rvalid(mon_rvalid),
        .frame_swapped(frame_swapped), .error(error),
        .vga_pix_stb(vga_pix_stb), .vga_de(vga_de), .vga_hsync_n(vga_hsync_n), .vga_vsync_n(vga_vsync_n),
        .vga_r(vga_r), .vga_g(vga_g), .vga_b(vga_b),
        // the frames are the GPU's block RAM (FRAME_DRAM 0): its memory port is idle
        .mem_cmd_valid(mem_out[0]), .mem_cmd_ready(1'b0), .mem_cmd_we(mem_out[1]), .mem_cmd_addr(mem_addr),
        .mem_wdata_valid(mem_out[2]), .mem_wdata_ready(1'b0), .mem_wdata_data(mem_data),
        .mem_wdata_we(mem_we), .mem_rdata_valid(1'b0), .mem_rdata_ready(mem_out[3]), .mem_rdata_data(32'd0)
    );
    wire unused_vga = vga_pix_stb | vga_de | vga_hsync_n | vga_vsync_n | (|vga_r) | (|vga_g) | (|vga_b)
                    | frame_swapped | error | (|mem_out) | (|mem_addr) | (|mem_data) | (|mem_we);
endmodule

`default_nettype wire
