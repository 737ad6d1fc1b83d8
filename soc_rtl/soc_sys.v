// soc_sys: the SoC's system registers (SYS in contract/soc-memory-map.md): identification, the build's
// clock, RAM and SDRAM sizes, the exit port, the LEDs, the machine timer and the bus-error record.
//
// Contract (bus): every request is answered in the next clock, once: wb_ack for the registers of the
// map, wb_err for any other offset of the window. Writes honour wb_sel (byte lanes) on the rw
// registers; writes to ro registers are ignored, reads of EXIT (wo) return 0. Effects happen in a
// request's first clock.
//   MTIME: a 64-bit count of clocks since reset. Reading MTIME_LO latches the high word, which
//          MTIME_HI then returns, so LO-then-HI is a consistent pair.
//   MTIMECMP: resets to all ones; timer_irq = (mtime >= mtimecmp), registered (one clock late).
//   EXIT: the first write sets exit_valid and exit_code = wb_dat_w[7:0]; both hold until reset.
//   BUS_ERR: buserr_stb (one clock per refused beat, from soc_top) records the first error's byte
//          address, direction and bus, and counts (saturating); buserr_irq is high while one is
//          recorded. Any write to BUS_ERR clears the record (an error in the same clock wins).
`default_nettype none

module soc_sys #(
    parameter integer CLK_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,       // reported in CLK_HZ
    parameter integer RAM_BYTES = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // reported in RAM_BYTES
    parameter integer SDRAM_BYTES = 0                              // reported in SDRAM_BYTES
) (
    input  wire        clk,
    input  wire        rst,           // synchronous, active high
    // Wishbone B4 slave (the SYS window)
    input  wire        wb_cyc,
    input  wire        wb_stb,        // selected by the decoder
    input  wire        wb_we,
    input  wire [7:2]  wb_adr,        // word offset in the window
    input  wire [31:0] wb_dat_w,
    input  wire [3:0]  wb_sel,        // byte lanes of a write
    output reg  [31:0] wb_dat_r,      // valid with wb_ack
    output wire        wb_ack,
    output wire        wb_err,
    // bus errors seen by soc_top (the refused beats of either CPU bus)
    input  wire        buserr_stb,    // a beat was answered with err this clock
    input  wire [31:0] buserr_addr,   // its byte address
    input  wire        buserr_write,  // it was a store
    input  wire        buserr_fetch,  // it was on the instruction bus
    // outputs
    output wire        timer_irq,     // to the core's timerInterrupt
    output wire        buserr_irq,    // to the core's externalInterruptArray[SOC_IRQ_BUS_ERROR]
    output reg  [7:0]  leds,
    output reg         exit_valid,
    output reg  [7:0]  exit_code
);
    localparam [7:0] OFF_ID          = soc_pkg::SOC_SYS_REG_ID;
    localparam [7:0] OFF_CLK_HZ      = soc_pkg::SOC_SYS_REG_CLK_HZ;
    localparam [7:0] OFF_RAM_BYTES   = soc_pkg::SOC_SYS_REG_RAM_BYTES;
    localparam [7:0] OFF_SDRAM_BYTES = soc_pkg::SOC_SYS_REG_SDRAM_BYTES;
    localparam [7:0] OFF_EXIT        = soc_pkg::SOC_SYS_REG_EXIT;
    localparam [7:0] OFF_LEDS        = soc_pkg::SOC_SYS_REG_LEDS;
    localparam [7:0] OFF_MTIME_LO    = soc_pkg::SOC_SYS_REG_MTIME_LO;
    localparam [7:0] OFF_MTIME_HI    = soc_pkg::SOC_SYS_REG_MTIME_HI;
    localparam [7:0] OFF_MTIMECMP_LO = soc_pkg::SOC_SYS_REG_MTIMECMP_LO;
    localparam [7:0] OFF_MTIMECMP_HI = soc_pkg::SOC_SYS_REG_MTIMECMP_HI;
    localparam [7:0] OFF_BUS_ERR_ADDR = soc_pkg::SOC_SYS_REG_BUS_ERR_ADDR;
    localparam [7:0] OFF_BUS_ERR     = soc_pkg::SOC_SYS_REG_BUS_ERR;
    localparam [31:0] CLK_HZ_VALUE    = CLK_HZ;
    localparam [31:0] RAM_BYTES_VALUE = RAM_BYTES;
    localparam [31:0] SDRAM_BYTES_VALUE = SDRAM_BYTES;

    reg  ack_q, err_q;
    wire req = wb_cyc && wb_stb;
    wire accept = req && !ack_q && !err_q;
    wire [7:0] off = {wb_adr, 2'b00};
    wire known = off == OFF_ID || off == OFF_CLK_HZ || off == OFF_RAM_BYTES || off == OFF_SDRAM_BYTES || off == OFF_EXIT
              || off == OFF_LEDS || off == OFF_MTIME_LO || off == OFF_MTIME_HI
              || off == OFF_MTIMECMP_LO || off == OFF_MTIMECMP_HI || off == OFF_BUS_ERR_ADDR
              || off == OFF_BUS_ERR;
    wire wr = accept && wb_we;
    wire rd = accept && !wb_we;
    assign wb_ack = ack_q && req;
    assign wb_err = err_q && req;

    // A write's new value of a register: the selected lanes of wb_dat_w over the old value.
    wire [31:0] lanes = {{8{wb_sel[3]}}, {8{wb_sel[2]}}, {8{wb_sel[1]}}, {8{wb_sel[0]}}};
    function automatic [31:0] merge(input [31:0] old);
        merge = (old & ~lanes) | (wb_dat_w & lanes);
    endfunction

    // LEDS is the register's low byte (checked): its lanes are lane 0.
    generate if (soc_pkg::SOC_SYS_LEDS_VALUE_LSB != 0 || soc_pkg::SOC_SYS_LEDS_VALUE_WIDTH != 8) begin : g_bad_leds
        $error("soc_sys: LEDS must be bits [7:0] of its register");
    end endgenerate

    // ---- timer ----
    reg [63:0] mtime_q, mtimecmp_q;
    reg [31:0] mtime_hi_q;        // the high word latched by the last MTIME_LO read
    reg        timer_irq_q;
    assign timer_irq = timer_irq_q;

    // ---- bus-error record ----
    reg        be_valid_q, be_write_q, be_fetch_q;
    reg [31:0] be_addr_q;
    reg [15:0] be_count_q;
    assign buserr_irq = be_valid_q;
    wire [31:0] be_status = ({31'd0, be_valid_q} << soc_pkg::SOC_SYS_BUS_ERR_VALID_LSB)
                          | ({31'd0, be_write_q} << soc_pkg::SOC_SYS_BUS_ERR_WRITE_LSB)
                          | ({31'd0, be_fetch_q} << soc_pkg::SOC_SYS_BUS_ERR_FETCH_LSB)
                          | ({16'd0, be_count_q} << soc_pkg::SOC_SYS_BUS_ERR_COUNT_LSB);

    always @(posedge clk) begin
        if (rst) begin
            ack_q <= 1'b0;
            err_q <= 1'b0;
            wb_dat_r <= 32'd0;
            mtime_q <= 64'd0;
            mtimecmp_q <= {64{1'b1}};
            mtime_hi_q <= 32'd0;
            timer_irq_q <= 1'b0;
            leds <= 8'd0;
            exit_valid <= 1'b0;
            exit_code <= 8'd0;
            be_valid_q <= 1'b0;
            be_write_q <= 1'b0;
            be_fetch_q <= 1'b0;
            be_addr_q <= 32'd0;
            be_count_q <= 16'd0;
        end else begin
            ack_q <= accept && known;
            err_q <= accept && !known;
            mtime_q <= mtime_q + 1'b1;
            timer_irq_q <= mtime_q >= mtimecmp_q;

            if (rd) begin
                case (off)
                    OFF_ID:           wb_dat_r <= soc_pkg::SOC_SYS_ID_VALUE;
                    OFF_CLK_HZ:       wb_dat_r <= CLK_HZ_VALUE;
                    OFF_RAM_BYTES:    wb_dat_r <= RAM_BYTES_VALUE;
                    OFF_SDRAM_BYTES:  wb_dat_r <= SDRAM_BYTES_VALUE;
                    OFF_LEDS:         wb_dat_r <= {24'd0, leds};
                    OFF_MTIME_LO:     wb_dat_r <= mtime_q[31:0];
                    OFF_MTIME_HI:     wb_dat_r <= mtime_hi_q;
                    OFF_MTIMECMP_LO:  wb_dat_r <= mtimecmp_q[31:0];
                    OFF_MTIMECMP_HI:  wb_dat_r <= mtimecmp_q[63:32];
                    OFF_BUS_ERR_ADDR: wb_dat_r <= be_addr_q;
                    OFF_BUS_ERR:      wb_dat_r <= be_status;
                    default:          wb_dat_r <= 32'd0;   // EXIT (wo) and refused offsets
                endcase
                if (off == OFF_MTIME_LO) mtime_hi_q <= mtime_q[63:32];
            end

            if (wr) begin
                case (off)
                    OFF_EXIT: if (!exit_valid) begin
                        exit_valid <= 1'b1;
                        exit_code <= wb_dat_w[soc_pkg::SOC_SYS_EXIT_CODE_LSB +: soc_pkg::SOC_SYS_EXIT_CODE_WIDTH];
                    end
                    OFF_LEDS:        leds <= wb_sel[0] ? wb_dat_w[7:0] : leds;
                    OFF_MTIMECMP_LO: mtimecmp_q[31:0] <= merge(mtimecmp_q[31:0]);
                    OFF_MTIMECMP_HI: mtimecmp_q[63:32] <= merge(mtimecmp_q[63:32]);
                    OFF_BUS_ERR: begin
                        be_valid_q <= 1'b0;
                        be_write_q <= 1'b0;
                        be_fetch_q <= 1'b0;
                        be_addr_q <= 32'd0;
                        be_count_q <= 16'd0;
                    end
                    default: ;
                endcase
            end

            // A bus error (never in the same clock as a SYS access: both use the one bus).
            if (buserr_stb) begin
                if (!be_valid_q) begin
                    be_valid_q <= 1'b1;
                    be_write_q <= buserr_write;
                    be_fetch_q <= buserr_fetch;
                    be_addr_q <= buserr_addr;
                end
                if (be_count_q != 16'hFFFF) be_count_q <= be_count_q + 1'b1;
            end
        end
    end
endmodule

`default_nettype wire
