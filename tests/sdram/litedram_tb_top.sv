// litedram_tb_top: the SoC's SDRAM block (soc_rtl/litedram/soc_sdram.v: LiteDRAM's generated
// controller, behind sdram_wb_burst on soc_top's SDRAM port and its control registers on the other)
// alone, for tests/sdram/litedram_tb.cpp, which plays a Wishbone master on those ports and the chip
// (cosim/sdram/sdram_chip.h) on the pins. The GPU's frame memory port (gpu_mem_*) is a port of this
// top so that the bench can drive it; it leaves it idle (no command), as a GPU without FRAME_DRAM.
//
// The pins' names are those of socsim's system (cosim/soc/soc_sdram_sim.sv), so both harnesses read
// them with cosim/sdram/sdram_pins.h. DQ is split the same way: the controller drives it through
// its TRELLIS_IO buffers (cosim/sdram/ecp5/TRELLIS_IO.v), the chip through chip_dq/chip_dq_oe;
// ctrl_dq_oe is the tristate of DQ bit 0 (all 16 share one registered enable in the PHY).
`default_nettype none
`include "soc_rtl/soc_gpu_mem.vh"

module litedram_tb_top #(
    localparam integer AW = $clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4),
    localparam integer CTRL_AW = $clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4)
) (
    // ---- clock and reset
    input  wire               clk,
    input  wire               clk2x,           // 2 x clk, rising edges aligned: the PHY's
    input  wire               rst,
    output wire               init_done,
    // ---- the SDRAM's pins as the chip sees them
    output wire [12:0]        sdram_a,
    output wire [1:0]         sdram_ba,
    output wire               sdram_cs_n,
    output wire               sdram_ras_n,
    output wire               sdram_cas_n,
    output wire               sdram_we_n,
    output wire               sdram_cke,
    output wire [1:0]         sdram_dqm,
    output wire [15:0]        sdram_dq_pins,   // the DQ bus as resolved (either side's drive)
    output wire               ctrl_dq_oe,      // the controller drives DQ
    input  wire [15:0]        chip_dq,         // the chip's drive ...
    input  wire               chip_dq_oe,      // ... while this is high
    // ---- the control registers (csr.csv; word addresses from SOC_SDRAM_CTRL_BASE)
    input  wire [CTRL_AW-1:0] ctrl_adr,
    input  wire [31:0]        ctrl_dat_w,
    output wire [31:0]        ctrl_dat_r,
    input  wire [3:0]         ctrl_sel,
    input  wire               ctrl_cyc,
    input  wire               ctrl_stb,
    input  wire               ctrl_we,
    output wire               ctrl_ack,
    output wire               ctrl_err,
    // ---- the SDRAM: 32-bit words (word addresses from SOC_SDRAM_BASE)
    input  wire [AW-1:0]      wb_adr,
    input  wire [31:0]        wb_dat_w,
    output wire [31:0]        wb_dat_r,
    input  wire [3:0]         wb_sel,
    input  wire [2:0]         wb_cti,          // 3'b010: another beat follows at wb_adr + 1
    input  wire               wb_cyc,
    input  wire               wb_stb,
    input  wire               wb_we,
    output wire               wb_ack,
    output wire               wb_err,
    // ---- the GPU's frame memory port (LiteDRAM's native protocol, 32-bit words from SOC_SDRAM_BASE)
    input  wire               gpu_mem_cmd_valid,
    output wire               gpu_mem_cmd_ready,
    input  wire               gpu_mem_cmd_we,
    input  wire [soc_pkg::SOC_SDRAM_NATIVE_AW-1:0] gpu_mem_cmd_addr,
    input  wire               gpu_mem_wdata_valid,
    output wire               gpu_mem_wdata_ready,
    input  wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0]   gpu_mem_wdata_data,
    input  wire [soc_pkg::SOC_SDRAM_NATIVE_DW/8-1:0] gpu_mem_wdata_we,
    output wire               gpu_mem_rdata_valid,
    input  wire               gpu_mem_rdata_ready,
    output wire [soc_pkg::SOC_SDRAM_NATIVE_DW-1:0]   gpu_mem_rdata_data
);
    wire [15:0] dq;
    assign dq = chip_dq_oe ? chip_dq : 16'bz;
    assign sdram_dq_pins = dq;
    assign ctrl_dq_oe = !dut.u_core.TRELLIS_IO.T;

    soc_sdram dut (
        .clk (clk), .clk2x (clk2x), .rst (rst), .init_done (init_done),
        .sdram_cyc (wb_cyc), .sdram_stb (wb_stb), .sdram_we (wb_we), .sdram_adr (wb_adr),
        .sdram_dat_w (wb_dat_w), .sdram_sel (wb_sel), .sdram_cti (wb_cti), .sdram_dat_r (wb_dat_r),
        .sdram_ack (wb_ack),
        .sdram_err (wb_err),
        .sdram_ctrl_cyc (ctrl_cyc), .sdram_ctrl_stb (ctrl_stb), .sdram_ctrl_we (ctrl_we),
        .sdram_ctrl_adr (ctrl_adr), .sdram_ctrl_dat_w (ctrl_dat_w), .sdram_ctrl_sel (ctrl_sel),
        .sdram_ctrl_dat_r (ctrl_dat_r), .sdram_ctrl_ack (ctrl_ack), .sdram_ctrl_err (ctrl_err),
        `SOC_GPU_MEM_PORTS,
        .pin_a (sdram_a), .pin_ba (sdram_ba), .pin_cs_n (sdram_cs_n), .pin_ras_n (sdram_ras_n),
        .pin_cas_n (sdram_cas_n), .pin_we_n (sdram_we_n), .pin_cke (sdram_cke), .pin_dqm (sdram_dqm),
        .pin_dq (dq)
    );
endmodule

`default_nettype wire
