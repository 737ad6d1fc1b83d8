// soc_sdram: the SoC's SDRAM — LiteDRAM's controller, generated at build time into the build tree
// (litedram_core, soc_rtl/litedram/gen_litedram.py), behind soc_top's two SDRAM ports, the chip's
// pins out. A system with SDRAM (socsim's, a board's) instantiates it beside soc_top.
//
// Contract:
//   sdram_*       soc_top's SDRAM port (Wishbone B4 classic with CTI): word addresses from
//                 SOC_SDRAM_BASE; the decoder sends only addresses below SDRAM_BYTES. Served by
//                 sdram_wb_burst on LiteDRAM's 32-bit native user port: an incrementing burst
//                 (sdram_cti 3'b010, the caches' line refills) has the rest of its 32-byte line read
//                 ahead and streamed, one word a clock at best; writes are posted (acked in their
//                 first clock while its queue has room). Once the power-up sequence has set
//                 init_done; before that a request is refused with err in its second clock (a bus
//                 error the CPU's SYS record shows), never left hanging.
//   sdram_ctrl_*  soc_top's SDRAM_CTRL port: LiteDRAM's control registers (word addresses of its
//                 csr.csv), always answered.
//   gpu_mem_*     soc_top's GPU frame memory port (a GPU built with FRAME_DRAM; idle otherwise):
//                 LiteDRAM's second native user port ("gpu" of ulx3s_sdram.yml), 32-bit words from
//                 the SDRAM's base, as it is: the GPU speaks the native protocol itself
//                 (gpu_frame_dram). LiteDRAM's crossbar serves the two ports round robin per bank;
//                 a port waits for init_done like the CPU's (the GPU's frames are written only once
//                 the firmware, which runs after the power-up sequence, draws).
//   clocks        clk, the controller's and every port's; clk2x, twice its rate with rising edges
//                 aligned (one PLL), LiteDRAM's HalfRateGENSDRPHY's: each clk's commands and two
//                 16-bit beats go to the pins over two clk2x clocks.
//   pins          the chip's, as the PHY drives them on clk2x (commands and data registered in the
//                 I/O cells, DQ through TRELLIS_IO buffers); the chip's clock is clk2x inverted
//                 (docs/sdram.md): not made here.
// SDRAM_BYTES must be the generated core's size (gen_litedram.py --expect-bytes checks it).
`default_nettype none

module soc_sdram #(
    parameter integer SDRAM_BYTES = soc_pkg::SOC_SDRAM_DEFAULT_BYTES,  // the chip's size
    localparam integer AW = $clog2(soc_pkg::SOC_SDRAM_WINDOW_BYTES / 4),       // soc_top's word address
    localparam integer CORE_AW = $clog2(SDRAM_BYTES / 4),                     // the core's
    localparam integer CTRL_AW = $clog2(soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES / 4),
    localparam integer NATIVE_DW = soc_pkg::SOC_SDRAM_NATIVE_DW,   // LiteDRAM's user ports (no converter)
    localparam integer GPU_MEM_AW = soc_pkg::SOC_SDRAM_NATIVE_AW   // soc_top's, native words
) (
    input  wire               clk,
    input  wire               clk2x,            // 2 x clk, rising edges aligned: the PHY's pins
    input  wire               rst,              // the system's reset (button, PLL unlock): LiteDRAM
                                                // synchronises it; it also clears the early-err flop
    output wire               init_done,        // the controller owns the pins: the SDRAM answers
    // ---- soc_top's SDRAM port
    input  wire               sdram_cyc,
    input  wire               sdram_stb,
    input  wire               sdram_we,
    input  wire [AW-1:0]      sdram_adr,
    input  wire [31:0]        sdram_dat_w,
    input  wire [3:0]         sdram_sel,
    input  wire [2:0]         sdram_cti,        // 3'b010: another beat follows (a line refill)
    output wire [31:0]        sdram_dat_r,
    output wire               sdram_ack,
    output wire               sdram_err,
    // ---- soc_top's SDRAM_CTRL port
    input  wire               sdram_ctrl_cyc,
    input  wire               sdram_ctrl_stb,
    input  wire               sdram_ctrl_we,
    input  wire [CTRL_AW-1:0] sdram_ctrl_adr,
    input  wire [31:0]        sdram_ctrl_dat_w,
    input  wire [3:0]         sdram_ctrl_sel,
    output wire [31:0]        sdram_ctrl_dat_r,
    output wire               sdram_ctrl_ack,
    output wire               sdram_ctrl_err,
    // ---- soc_top's GPU frame memory port (LiteDRAM's native protocol, NATIVE_DW-bit words)
    input  wire               gpu_mem_cmd_valid,
    output wire               gpu_mem_cmd_ready,
    input  wire               gpu_mem_cmd_we,
    input  wire [GPU_MEM_AW-1:0] gpu_mem_cmd_addr,
    input  wire               gpu_mem_wdata_valid,
    output wire               gpu_mem_wdata_ready,
    input  wire [NATIVE_DW-1:0]   gpu_mem_wdata_data,
    input  wire [NATIVE_DW/8-1:0] gpu_mem_wdata_we,
    output wire               gpu_mem_rdata_valid,
    input  wire               gpu_mem_rdata_ready,
    output wire [NATIVE_DW-1:0]   gpu_mem_rdata_data,
    // ---- the chip's pins
    output wire [12:0]        pin_a,
    output wire [1:0]         pin_ba,
    output wire               pin_cs_n,
    output wire               pin_ras_n,
    output wire               pin_cas_n,
    output wire               pin_we_n,
    output wire               pin_cke,
    output wire [1:0]         pin_dqm,
    inout  wire [15:0]        pin_dq
);
    generate if (SDRAM_BYTES <= 0 || (1 << CORE_AW) * 4 != SDRAM_BYTES || CORE_AW > AW) begin : g_bad_size
        $error("soc_sdram: SDRAM_BYTES must be a power of two within SOC_SDRAM_WINDOW_BYTES");
    end endgenerate

    // The CPU's port: Wishbone onto LiteDRAM's native port (user port "cpu" of ulx3s_sdram.yml).
    localparam integer NAW = CORE_AW + $clog2(32 / NATIVE_DW);
    wire                 cmd_valid, cmd_ready, cmd_we;       // sdram_wb_burst's commands
    wire [NAW-1:0]       cmd_addr;
    wire                 core_cmd_valid, core_cmd_ready, core_cmd_we;   // ... into LiteDRAM
    wire [NAW-1:0]       core_cmd_addr;
    wire                 wdata_valid, wdata_ready;
    wire [NATIVE_DW-1:0] wdata_data;
    wire [NATIVE_DW/8-1:0] wdata_we;
    wire                 rdata_valid, rdata_ready;
    wire [NATIVE_DW-1:0] rdata_data;

    sdram_wb_burst #(
        .AW        (CORE_AW),
        .NATIVE_DW (NATIVE_DW)
    ) u_port (
        .clk                (clk),
        .rst                (rst),
        .init_done          (init_done),
        .wb_cyc             (sdram_cyc),
        .wb_stb             (sdram_stb),
        .wb_we              (sdram_we),
        .wb_adr             (sdram_adr[CORE_AW-1:0]),
        .wb_dat_w           (sdram_dat_w),
        .wb_sel             (sdram_sel),
        .wb_cti             (sdram_cti),
        .wb_dat_r           (sdram_dat_r),
        .wb_ack             (sdram_ack),
        .wb_err             (sdram_err),
        .native_cmd_valid   (cmd_valid),
        .native_cmd_ready   (cmd_ready),
        .native_cmd_we      (cmd_we),
        .native_cmd_addr    (cmd_addr),
        .native_wdata_valid (wdata_valid),
        .native_wdata_ready (wdata_ready),
        .native_wdata_data  (wdata_data),
        .native_wdata_we    (wdata_we),
        .native_rdata_valid (rdata_valid),
        .native_rdata_ready (rdata_ready),
        .native_rdata_data  (rdata_data)
    );

    // LiteDRAM's cmd_ready is combinational through its crossbar: a register slice keeps it out of
    // sdram_wb_burst's (and so the CPU bus's) clock. One clock more per command's start, none per
    // command of a line's stream (issue #27; docs/sdram.md).
    soc_stream_slice #(
        .W (NAW + 1)
    ) u_cmd_slice (
        .clk       (clk),
        .rst       (rst),
        .in_valid  (cmd_valid),
        .in_ready  (cmd_ready),
        .in_data   ({cmd_we, cmd_addr}),
        .out_valid (core_cmd_valid),
        .out_ready (core_cmd_ready),
        .out_data  ({core_cmd_we, core_cmd_addr})
    );

    wire unused_adr = &{1'b0, sdram_adr[AW-1:CORE_AW],     // above SDRAM_BYTES: the decoder refuses it
                        gpu_mem_cmd_addr[GPU_MEM_AW-1:NAW]};  // soc_top places the frames below it
    wire unused_clk, unused_rst, unused_init_error;

    // user_clk, user_rst: the core's clock and reset handed back; init_error: LiteDRAM's, set only by
    // a calibrating BIOS (an SDR chip has nothing to calibrate).
    litedram_core u_core (
        .clk                  (clk),
        .clk2x                (clk2x),
        .rst                  (rst),
        .init_done            (init_done),
        .init_error           (unused_init_error),
        .user_clk             (unused_clk),
        .user_rst             (unused_rst),
        .sdram_a              (pin_a),
        .sdram_ba             (pin_ba),
        .sdram_cs_n           (pin_cs_n),
        .sdram_ras_n          (pin_ras_n),
        .sdram_cas_n          (pin_cas_n),
        .sdram_we_n           (pin_we_n),
        .sdram_cke            (pin_cke),
        .sdram_dm             (pin_dqm),
        .sdram_dq             (pin_dq),
        .user_port_cpu_cmd_valid   (core_cmd_valid),
        .user_port_cpu_cmd_ready   (core_cmd_ready),
        .user_port_cpu_cmd_we      (core_cmd_we),
        .user_port_cpu_cmd_addr    (core_cmd_addr),
        .user_port_cpu_wdata_valid (wdata_valid),
        .user_port_cpu_wdata_ready (wdata_ready),
        .user_port_cpu_wdata_data  (wdata_data),
        .user_port_cpu_wdata_we    (wdata_we),
        .user_port_cpu_rdata_valid (rdata_valid),
        .user_port_cpu_rdata_ready (rdata_ready),
        .user_port_cpu_rdata_data  (rdata_data),
        .user_port_gpu_cmd_valid   (gpu_mem_cmd_valid),
        .user_port_gpu_cmd_ready   (gpu_mem_cmd_ready),
        .user_port_gpu_cmd_we      (gpu_mem_cmd_we),
        .user_port_gpu_cmd_addr    (gpu_mem_cmd_addr[NAW-1:0]),
        .user_port_gpu_wdata_valid (gpu_mem_wdata_valid),
        .user_port_gpu_wdata_ready (gpu_mem_wdata_ready),
        .user_port_gpu_wdata_data  (gpu_mem_wdata_data),
        .user_port_gpu_wdata_we    (gpu_mem_wdata_we),
        .user_port_gpu_rdata_valid (gpu_mem_rdata_valid),
        .user_port_gpu_rdata_ready (gpu_mem_rdata_ready),
        .user_port_gpu_rdata_data  (gpu_mem_rdata_data),
        .wb_ctrl_cyc          (sdram_ctrl_cyc),
        .wb_ctrl_stb          (sdram_ctrl_stb),
        .wb_ctrl_we           (sdram_ctrl_we),
        .wb_ctrl_adr          ({{(30 - CTRL_AW){1'b0}}, sdram_ctrl_adr}),
        .wb_ctrl_dat_w        (sdram_ctrl_dat_w),
        .wb_ctrl_sel          (sdram_ctrl_sel),
        .wb_ctrl_cti          (3'b000),
        .wb_ctrl_bte          (2'b00),
        .wb_ctrl_dat_r        (sdram_ctrl_dat_r),
        .wb_ctrl_ack          (sdram_ctrl_ack),
        .wb_ctrl_err          (sdram_ctrl_err)
    );
endmodule

`default_nettype wire
