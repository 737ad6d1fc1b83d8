// soc_top_no_sdram.vh — soc_top in a system without SDRAM (SDRAM_BYTES 0, both SDRAM regions and
// the flash answer ERR): SOC_TOP_NO_SDRAM_WIRES declares what its SDRAM and flash ports' outputs
// drive (unused) — the GPU's frame memory port too — and SOC_TOP_NO_SDRAM_PORTS connects them and ties the answers off, in soc_top's
// port list — so each board says "no SDRAM" in two lines. Included from the repository root, as contract/ headers are.
`ifndef SOC_TOP_NO_SDRAM_VH
`define SOC_TOP_NO_SDRAM_VH

`define SOC_TOP_NO_SDRAM_WIRES \
    wire [8:0]  sdram_idle; \
    wire [$clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4)-1:0]      sdram_idle_adr; \
    wire [$clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4)-1:0] sdram_idle_ctrl_adr; \
    wire [31:0] sdram_idle_dat, sdram_idle_ctrl_dat; \
    wire [3:0]  sdram_idle_sel, sdram_idle_ctrl_sel; \
    wire [2:0]  sdram_idle_cti; \
    wire [3:0]  gpu_mem_idle; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_AW-1:0] gpu_mem_idle_addr; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0] gpu_mem_idle_data; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW/8-1:0] gpu_mem_idle_we; \
    wire unused_sdram = &{1'b0, sdram_idle, sdram_idle_adr, sdram_idle_ctrl_adr, sdram_idle_dat, \
                          sdram_idle_ctrl_dat, sdram_idle_sel, sdram_idle_ctrl_sel, sdram_idle_cti, \
                          gpu_mem_idle, gpu_mem_idle_addr, gpu_mem_idle_data, gpu_mem_idle_we};

`define SOC_TOP_NO_SDRAM_PORTS \
    .sdram_cyc        (sdram_idle[0]), \
    .sdram_stb        (sdram_idle[1]), \
    .sdram_we         (sdram_idle[2]), \
    .sdram_adr        (sdram_idle_adr), \
    .sdram_dat_w      (sdram_idle_dat), \
    .sdram_sel        (sdram_idle_sel), \
    .sdram_cti        (sdram_idle_cti), \
    .sdram_dat_r      (32'd0), \
    .sdram_ack        (1'b0), \
    .sdram_err        (1'b0), \
    .sdram_ctrl_cyc   (sdram_idle[3]), \
    .sdram_ctrl_stb   (sdram_idle[4]), \
    .sdram_ctrl_we    (sdram_idle[5]), \
    .sdram_ctrl_adr   (sdram_idle_ctrl_adr), \
    .sdram_ctrl_dat_w (sdram_idle_ctrl_dat), \
    .sdram_ctrl_sel   (sdram_idle_ctrl_sel), \
    .sdram_ctrl_dat_r (32'd0), \
    .sdram_ctrl_ack   (1'b0), \
    .sdram_ctrl_err   (1'b0), \
    .flash_cs_n       (sdram_idle[6]), \
    .flash_sck        (sdram_idle[7]), \
    .flash_mosi       (sdram_idle[8]), \
    .flash_miso       (1'b0), \
    .gpu_mem_cmd_valid   (gpu_mem_idle[0]), \
    .gpu_mem_cmd_ready   (1'b0), \
    .gpu_mem_cmd_we      (gpu_mem_idle[1]), \
    .gpu_mem_cmd_addr    (gpu_mem_idle_addr), \
    .gpu_mem_wdata_valid (gpu_mem_idle[2]), \
    .gpu_mem_wdata_ready (1'b0), \
    .gpu_mem_wdata_data  (gpu_mem_idle_data), \
    .gpu_mem_wdata_we    (gpu_mem_idle_we), \
    .gpu_mem_rdata_valid (1'b0), \
    .gpu_mem_rdata_ready (gpu_mem_idle[3]), \
    .gpu_mem_rdata_data  ({soc_pkg::SOC_SDRAM_NATIVE_DW{1'b0}})

`endif
