// soc_sdram_bus.vh — soc_top's two Wishbone ports to the SDRAM (sdram_*: the memory window, with
// CTI for bursts; sdram_ctrl_*: LiteDRAM's control registers) between soc_top (or ulx3s_system,
// which passes them through) and soc_sdram, one name on both sides: SOC_SDRAM_BUS_WIRES declares the
// wires a system connects them with, SOC_SDRAM_BUS_PORTS connects a module's ports of those names to
// them. Widths from soc_pkg (the memory map). Included from the repository root, as contract/
// headers are; soc_top_no_sdram.vh ties the same ports off in a system without SDRAM.
`ifndef SOC_SDRAM_BUS_VH
`define SOC_SDRAM_BUS_VH

`define SOC_SDRAM_BUS_WIRES \
    wire        sdram_wb_cyc, sdram_wb_stb, sdram_wb_we, sdram_wb_ack, sdram_wb_err; \
    wire [$clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4)-1:0] sdram_wb_adr; \
    wire [31:0] sdram_wb_dat_w, sdram_wb_dat_r; \
    wire [3:0]  sdram_wb_sel; \
    wire [2:0]  sdram_wb_cti; \
    wire        sdram_ctrl_wb_cyc, sdram_ctrl_wb_stb, sdram_ctrl_wb_we, sdram_ctrl_wb_ack, sdram_ctrl_wb_err; \
    wire [$clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4)-1:0] sdram_ctrl_wb_adr; \
    wire [31:0] sdram_ctrl_wb_dat_w, sdram_ctrl_wb_dat_r; \
    wire [3:0]  sdram_ctrl_wb_sel;

`define SOC_SDRAM_BUS_PORTS \
    .sdram_cyc        (sdram_wb_cyc), \
    .sdram_stb        (sdram_wb_stb), \
    .sdram_we         (sdram_wb_we), \
    .sdram_adr        (sdram_wb_adr), \
    .sdram_dat_w      (sdram_wb_dat_w), \
    .sdram_sel        (sdram_wb_sel), \
    .sdram_cti        (sdram_wb_cti), \
    .sdram_dat_r      (sdram_wb_dat_r), \
    .sdram_ack        (sdram_wb_ack), \
    .sdram_err        (sdram_wb_err), \
    .sdram_ctrl_cyc   (sdram_ctrl_wb_cyc), \
    .sdram_ctrl_stb   (sdram_ctrl_wb_stb), \
    .sdram_ctrl_we    (sdram_ctrl_wb_we), \
    .sdram_ctrl_adr   (sdram_ctrl_wb_adr), \
    .sdram_ctrl_dat_w (sdram_ctrl_wb_dat_w), \
    .sdram_ctrl_sel   (sdram_ctrl_wb_sel), \
    .sdram_ctrl_dat_r (sdram_ctrl_wb_dat_r), \
    .sdram_ctrl_ack   (sdram_ctrl_wb_ack), \
    .sdram_ctrl_err   (sdram_ctrl_wb_err)

`endif
