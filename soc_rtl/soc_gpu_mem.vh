// soc_gpu_mem.vh — the GPU's frame memory port between soc_top (gpu_mem_*, a GPU built with
// FRAME_DRAM) and the SDRAM controller's second user port (soc_sdram's gpu_mem_*), one name on both
// sides: SOC_GPU_MEM_WIRES declares the wires a system connects them with, SOC_GPU_MEM_PORTS
// connects a module's ports of those names to them (soc_top's, ulx3s_system's, soc_sdram's).
// Included from the repository root, as contract/ headers are.
`ifndef SOC_GPU_MEM_VH
`define SOC_GPU_MEM_VH

`define SOC_GPU_MEM_WIRES \
    wire        gpu_mem_cmd_valid, gpu_mem_cmd_ready, gpu_mem_cmd_we; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_AW-1:0] gpu_mem_cmd_addr; \
    wire        gpu_mem_wdata_valid, gpu_mem_wdata_ready; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0] gpu_mem_wdata_data; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW/8-1:0] gpu_mem_wdata_we; \
    wire        gpu_mem_rdata_valid, gpu_mem_rdata_ready; \
    wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0] gpu_mem_rdata_data;

`define SOC_GPU_MEM_PORTS \
    .gpu_mem_cmd_valid   (gpu_mem_cmd_valid), \
    .gpu_mem_cmd_ready   (gpu_mem_cmd_ready), \
    .gpu_mem_cmd_we      (gpu_mem_cmd_we), \
    .gpu_mem_cmd_addr    (gpu_mem_cmd_addr), \
    .gpu_mem_wdata_valid (gpu_mem_wdata_valid), \
    .gpu_mem_wdata_ready (gpu_mem_wdata_ready), \
    .gpu_mem_wdata_data  (gpu_mem_wdata_data), \
    .gpu_mem_wdata_we    (gpu_mem_wdata_we), \
    .gpu_mem_rdata_valid (gpu_mem_rdata_valid), \
    .gpu_mem_rdata_ready (gpu_mem_rdata_ready), \
    .gpu_mem_rdata_data  (gpu_mem_rdata_data)

`endif
