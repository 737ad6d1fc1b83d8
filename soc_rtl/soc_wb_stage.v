// soc_wb_stage: one register stage on the SoC's bus in front of its slow slaves (the flash, SYS,
// the UART, the USB host's and the SDRAM controller's registers), so that their requests come from
// flops: the path from the CPU's request through the arbiter and the decoder ends here instead of
// in each slave's logic (issue #27: the board's system path ran from the instruction cache's
// request into the flash reader's request flag by its pins, 19.5 ns, 15 of them routing).
//
// Contract (Wishbone B4 classic on both sides; N slaves):
//   master side  the bus after the decoder: cyc, one stb per slave (m_stb, one-hot or zero: the
//                decoder's selects), we, adr, dat_w, sel. The master holds its request until it is
//                answered (classic, no abort: the arbiter and the decoder assume the same; VexRiscv's
//                buses never abort).
//   taken        a request (cyc && m_stb[k]) while the stage is idle is taken at the clock's end;
//                from the next clock s_cyc and s_stb[k] are high with s_we, s_adr, s_dat_w and s_sel
//                the request's, until slave k answers (s_ack[k] or s_err[k]: once, only while its
//                s_stb is high). The stage is idle again in the clock after the answer, where it
//                takes the master's next request: every access costs one clock more than on the bus.
//   answers      not handled here: the slaves' ack, err and dat_r go to the decoder as before. A
//                slave answers only while its s_stb is high, so only during the master's request
//                to it, and never in that request's first clock (the stage's clock).
`default_nettype none

module soc_wb_stage #(
    parameter integer N = 5,             // slaves behind the stage
    parameter integer AW = 30            // word address bits passed on
) (
    input  wire          clk,
    input  wire          rst,            // synchronous, active high
    // ---- master side: the bus after the decoder
    input  wire          cyc,
    input  wire [N-1:0]  m_stb,          // the decoder's select of each slave (at most one)
    input  wire          we,
    input  wire [AW-1:0] adr,
    input  wire [31:0]   dat_w,
    input  wire [3:0]    sel,
    // ---- slave side: the request, from flops
    output reg           s_cyc,          // high exactly while some s_stb is
    output reg  [N-1:0]  s_stb,
    output reg           s_we,
    output reg  [AW-1:0] s_adr,
    output reg  [31:0]   s_dat_w,
    output reg  [3:0]    s_sel,
    input  wire [N-1:0]  s_answer        // slave k's ack or err (only while its s_stb is high)
);
    wire idle = !s_cyc;

    always @(posedge clk) begin
        if (rst) begin
            s_cyc <= 1'b0;
            s_stb <= '0;
        end else if (idle) begin
            s_cyc <= cyc && m_stb != '0;
            s_stb <= cyc ? m_stb : '0;
        end else if (s_answer != '0) begin
            s_cyc <= 1'b0;
            s_stb <= '0;
        end
        // The request's fields: taken with it, held while it is served.
        if (idle) begin
            s_we <= we;
            s_adr <= adr;
            s_dat_w <= dat_w;
            s_sel <= sel;
        end
    end

`ifdef FORMAL
    // ---- formal properties (tests/formal/soc_wb_stage.sby, proved by induction): the invariant
    // that ties the two state flops together; the check (soc_wb_stage_check.sv) has the rest.
    always @(*) if (!rst) assert(s_cyc == (s_stb != '0));
`endif
endmodule

`default_nettype wire
