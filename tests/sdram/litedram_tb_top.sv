// litedram_tb_top: LiteDRAM's generated controller (soc_rtl/litedram, build/litedram/...) at its
// SDRAM pins, for tests/sdram/litedram_tb.cpp, which plays the chip (cosim/sdram/sdram_chip.h) on
// the other side of those pins and a Wishbone master on the core's two buses.
//
// DQ is the one bidirectional pin group: the core drives it through its TRELLIS_IO buffers
// (cosim/sdram/ecp5/TRELLIS_IO.v) while its write enable is up, the chip through chip_dq/chip_dq_oe
// here; ctrl_dq_oe tells the harness which side the controller is on (the tristate of DQ bit 0:
// all 16 share one registered enable in LiteDRAM's GENSDRPHY).
`default_nettype none
`timescale 1ns / 1ps

module litedram_tb_top (
    // ---- clock and reset
    input  wire        clk,
    input  wire        rst,
    output wire        init_done,
    output wire        init_error,
    // ---- the SDRAM's pins as the chip sees them
    output wire [12:0] sdram_a,
    output wire [1:0]  sdram_ba,
    output wire        sdram_cas_n,
    output wire        sdram_cke,
    output wire        sdram_cs_n,
    output wire [1:0]  sdram_dm,
    output wire        sdram_ras_n,
    output wire        sdram_we_n,
    output wire [15:0] sdram_dq_pins,   // the DQ bus as resolved (either side's drive)
    output wire        ctrl_dq_oe,      // the controller drives DQ
    input  wire [15:0] chip_dq,         // the chip's drive ...
    input  wire        chip_dq_oe,      // ... while this is high
    // ---- wb_ctrl: the core's control registers (csr.csv; word addresses)
    input  wire [29:0] ctrl_adr,
    input  wire [31:0] ctrl_dat_w,
    output wire [31:0] ctrl_dat_r,
    input  wire [3:0]  ctrl_sel,
    input  wire        ctrl_cyc,
    input  wire        ctrl_stb,
    input  wire        ctrl_we,
    output wire        ctrl_ack,
    output wire        ctrl_err,
    // ---- the user port: 32-bit words of the SDRAM (word addresses)
    input  wire [22:0] wb_adr,
    input  wire [31:0] wb_dat_w,
    output wire [31:0] wb_dat_r,
    input  wire [3:0]  wb_sel,
    input  wire        wb_cyc,
    input  wire        wb_stb,
    input  wire        wb_we,
    output wire        wb_ack,
    output wire        wb_err
);
    wire [15:0] dq;
    assign dq = chip_dq_oe ? chip_dq : 16'bz;
    assign sdram_dq_pins = dq;
    assign ctrl_dq_oe = !dut.TRELLIS_IO.T;

    // user_clk and user_rst are the core's own clock and reset handed back: unused here.
    // verilator lint_off PINCONNECTEMPTY
    litedram_core dut (
        .clk(clk), .rst(rst), .init_done(init_done), .init_error(init_error),
        .sdram_a(sdram_a), .sdram_ba(sdram_ba), .sdram_cas_n(sdram_cas_n), .sdram_cke(sdram_cke),
        .sdram_cs_n(sdram_cs_n), .sdram_dm(sdram_dm), .sdram_dq(dq), .sdram_ras_n(sdram_ras_n),
        .sdram_we_n(sdram_we_n),
        .user_clk(), .user_rst(),
        .wb_ctrl_adr(ctrl_adr), .wb_ctrl_dat_w(ctrl_dat_w), .wb_ctrl_dat_r(ctrl_dat_r),
        .wb_ctrl_sel(ctrl_sel), .wb_ctrl_cyc(ctrl_cyc), .wb_ctrl_stb(ctrl_stb), .wb_ctrl_we(ctrl_we),
        .wb_ctrl_ack(ctrl_ack), .wb_ctrl_err(ctrl_err), .wb_ctrl_bte(2'b00), .wb_ctrl_cti(3'b000),
        .user_port_wb_adr(wb_adr), .user_port_wb_dat_w(wb_dat_w), .user_port_wb_dat_r(wb_dat_r),
        .user_port_wb_sel(wb_sel), .user_port_wb_cyc(wb_cyc), .user_port_wb_stb(wb_stb),
        .user_port_wb_we(wb_we), .user_port_wb_ack(wb_ack), .user_port_wb_err(wb_err)
    );
    // verilator lint_on PINCONNECTEMPTY
endmodule

`default_nettype wire
