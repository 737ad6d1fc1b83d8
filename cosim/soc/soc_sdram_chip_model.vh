// soc_sdram_chip_model.vh — socsim's systems with SDRAM (soc_sdram_sim, ulx3s_sdram_sim): soc_sdram
// (LiteDRAM) on the system's SDRAM bus and GPU frame port (soc_rtl/soc_sdram_bus.vh,
// soc_rtl/soc_gpu_mem.vh), its pins out to socsim's chip model as cosim/sdram/sdram_pins.h names
// them. DQ is split as tests/sdram/litedram_tb_top.sv splits it: the controller's drive through its
// TRELLIS_IO buffers, the chip's through chip_dq/chip_dq_oe (in), the resolved bus (sdram_dq_pins)
// and which side the controller is on (ctrl_dq_oe: the tristate of DQ bit 0, all 16 share one
// registered enable in LiteDRAM's PHY) out. sdram_busy: a request on the CPU's SDRAM port.
// SOC_SDRAM_FOR_CHIP_MODEL(CLK, CLK2X, RST): the system's clock, the PHY's (twice it, rising edges
// aligned) and LiteDRAM's reset. Needs the
// SOC_SDRAM_BUS_WIRES and SOC_GPU_MEM_WIRES, SDRAM_BYTES and the chip pins as the system's ports.
`ifndef SOC_SDRAM_CHIP_MODEL_VH
`define SOC_SDRAM_CHIP_MODEL_VH

`define SOC_SDRAM_FOR_CHIP_MODEL(CLK, CLK2X, RST) \
    assign sdram_busy = sdram_wb_cyc && sdram_wb_stb; \
    wire [15:0] dq; \
    assign dq = chip_dq_oe ? chip_dq : 16'bz; \
    assign sdram_dq_pins = dq; \
    assign ctrl_dq_oe = !u_sdram.u_core.TRELLIS_IO.T; \
    soc_sdram #( \
        .SDRAM_BYTES (SDRAM_BYTES) \
    ) u_sdram ( \
        .clk (CLK), .clk2x (CLK2X), .rst (RST), .init_done (sdram_init_done), \
        `SOC_SDRAM_BUS_PORTS, \
        `SOC_GPU_MEM_PORTS, \
        .pin_a (sdram_a), .pin_ba (sdram_ba), .pin_cs_n (sdram_cs_n), .pin_ras_n (sdram_ras_n), \
        .pin_cas_n (sdram_cas_n), .pin_we_n (sdram_we_n), .pin_cke (sdram_cke), .pin_dqm (sdram_dqm), \
        .pin_dq (dq) \
    );

`endif
