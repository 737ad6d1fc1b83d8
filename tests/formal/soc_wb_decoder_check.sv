// soc_wb_decoder_check: formal properties of soc_wb_decoder (soc_rtl/soc_wb_decoder.v) from its
// ports, in the manner of ZipCPU's fwb_slave/fwb_master (tests/formal/soc_wb_decoder.sby; make formal),
// against the memory map of contract/soc_map.toml through soc_pkg, as the module reads it.
//
// Environment (assumed): rst in the first clock; the bus's master (the arbiter) follows Wishbone B4
// classic: no request after a reset clock, stb only within cyc, adr held until the request's ack
// or err. Each slave answers only while its own stb is high (ack or err, never both; the RAM has
// no err), after any number of clocks (RAM_BYTES tasks) or at most SLAVE_WAIT clocks after the
// request's first (task bounded).
// Properties (asserted): the region of an address is computed here independently (base <= address
// < base + size, the RAM's size RAM_BYTES and the SDRAM's SDRAM_BYTES, not their windows; the
// SDRAM's registers and the flash only in a build with SDRAM, the USB host's registers only in a
// build with one), and each slave's stb is cyc && stb &&
// (the address in its region), nothing else: exactly one slave per request, or none for an address
// outside every region; such a request is answered by err and nothing else in its second clock
// (one clock late, once), with dat_r 0; ack, err and dat_r are the selected slave's, so a slave's
// answer reaches the master only during a request to it; no answer without a request, never ack
// and err together; the slaves' ports keep the Wishbone rules (a request held until answered).
// Task bounded: every request answered at most SLAVE_WAIT clocks after its first.
`default_nettype none

module soc_wb_decoder_check #(
    parameter integer RAM_BYTES  = soc_pkg::SOC_RAM_DEFAULT_BYTES,  // as soc_top passes it
    parameter integer SDRAM_BYTES = 0, // 0: a build without SDRAM
    parameter integer USB_HOST = 0,    // 0: a build without the USB host
    parameter integer SLAVE_WAIT = 0   // > 0: every slave answers at most this many clocks late
) (
    input wire        clk,
    input wire        rst,
    input wire        cyc,
    input wire        stb,
    input wire [29:0] adr,
    input wire [31:0] ram_dat_r,
    input wire        ram_ack,
    input wire [31:0] sdram_dat_r,
    input wire        sdram_ack,
    input wire        sdram_err,
    input wire [31:0] sdram_ctrl_dat_r,
    input wire        sdram_ctrl_ack,
    input wire        sdram_ctrl_err,
    input wire [31:0] flash_dat_r,
    input wire        flash_ack,
    input wire        flash_err,
    input wire [31:0] gpu_dat_r,
    input wire        gpu_ack,
    input wire        gpu_err,
    input wire [31:0] uart_dat_r,
    input wire        uart_ack,
    input wire        uart_err,
    input wire [31:0] sys_dat_r,
    input wire        sys_ack,
    input wire        sys_err,
    input wire [31:0] usb_dat_r,
    input wire        usb_ack,
    input wire        usb_err
);
    wire [31:0] dat_r;
    wire        ack, err, ram_stb, sdram_stb, sdram_ctrl_stb, flash_stb, gpu_stb, uart_stb, sys_stb, usb_stb;
    soc_wb_decoder #(.RAM_BYTES(RAM_BYTES), .SDRAM_BYTES(SDRAM_BYTES), .USB_HOST(USB_HOST)) dut (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(stb), .adr(adr),
        .dat_r(dat_r), .ack(ack), .err(err),
        .ram_stb(ram_stb), .ram_dat_r(ram_dat_r), .ram_ack(ram_ack),
        .sdram_stb(sdram_stb), .sdram_dat_r(sdram_dat_r), .sdram_ack(sdram_ack), .sdram_err(sdram_err),
        .sdram_ctrl_stb(sdram_ctrl_stb), .sdram_ctrl_dat_r(sdram_ctrl_dat_r),
        .sdram_ctrl_ack(sdram_ctrl_ack), .sdram_ctrl_err(sdram_ctrl_err),
        .flash_stb(flash_stb), .flash_dat_r(flash_dat_r), .flash_ack(flash_ack), .flash_err(flash_err),
        .gpu_stb(gpu_stb), .gpu_dat_r(gpu_dat_r), .gpu_ack(gpu_ack), .gpu_err(gpu_err),
        .uart_stb(uart_stb), .uart_dat_r(uart_dat_r), .uart_ack(uart_ack), .uart_err(uart_err),
        .sys_stb(sys_stb), .sys_dat_r(sys_dat_r), .sys_ack(sys_ack), .sys_err(sys_err),
        .usb_stb(usb_stb), .usb_dat_r(usb_dat_r), .usb_ack(usb_ack), .usb_err(usb_err)
    );

    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;
    always @(*) if (!f_past_valid) assume(rst);

    // The regions, independently: [base, base + size) on the 33-bit byte address (no wrap).
    wire [32:0] a = {1'b0, adr, 2'b00};
    function automatic in_region(input [32:0] addr, input [32:0] base, input [32:0] size);
        in_region = addr >= base && addr < base + size;
    endfunction
    wire in_ram  = in_region(a, {1'b0, soc_pkg::SOC_RAM_BASE}, RAM_BYTES);
    wire in_sdram = in_region(a, {1'b0, soc_pkg::SOC_SDRAM_BASE}, SDRAM_BYTES);
    wire in_sdram_ctrl = in_region(a, {1'b0, soc_pkg::SOC_SDRAM_CTRL_BASE},
                                   SDRAM_BYTES != 0 ? soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES : 0);
    wire in_gpu  = in_region(a, {1'b0, soc_pkg::SOC_GPU_BASE}, soc_pkg::SOC_GPU_WINDOW_BYTES);
    wire in_uart = in_region(a, {1'b0, soc_pkg::SOC_UART_BASE}, soc_pkg::SOC_UART_WINDOW_BYTES);
    wire in_sys  = in_region(a, {1'b0, soc_pkg::SOC_SYS_BASE}, soc_pkg::SOC_SYS_WINDOW_BYTES);
    wire in_flash = in_region(a, {1'b0, soc_pkg::SOC_FLASH_BASE},
                              SDRAM_BYTES != 0 ? soc_pkg::SOC_FLASH_WINDOW_BYTES : 0);
    wire in_usb  = in_region(a, {1'b0, soc_pkg::SOC_USB_BASE},
                             USB_HOST != 0 ? soc_pkg::SOC_USB_WINDOW_BYTES : 0);
    wire in_none = !(in_ram || in_sdram || in_sdram_ctrl || in_flash || in_gpu || in_uart || in_sys
                     || in_usb);
    wire req     = cyc && stb;

    // The Wishbone rules: upstream the master's requests assumed and the decoder's answers asserted;
    // to each slave the decoder's requests asserted and the slave's answers assumed.
    wire [3:0] up_wait;
    soc_wb_decoder_port #(.DUT_ANSWERS(1), .MAX_WAIT(SLAVE_WAIT)) p_up (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(stb), .adr(adr), .ack(ack), .err(err),
        .f_wait(up_wait)
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_ram (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(ram_stb), .adr(adr), .ack(ram_ack), .err(1'b0),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_sdram (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(sdram_stb), .adr(adr), .ack(sdram_ack), .err(sdram_err),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_sdram_ctrl (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(sdram_ctrl_stb), .adr(adr), .ack(sdram_ctrl_ack),
        .err(sdram_ctrl_err), .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_flash (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(flash_stb), .adr(adr), .ack(flash_ack), .err(flash_err),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_gpu (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(gpu_stb), .adr(adr), .ack(gpu_ack), .err(gpu_err),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_uart (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(uart_stb), .adr(adr), .ack(uart_ack), .err(uart_err),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_sys (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(sys_stb), .adr(adr), .ack(sys_ack), .err(sys_err),
        .f_wait()
    );
    soc_wb_decoder_port #(.DUT_ANSWERS(0), .MAX_WAIT(SLAVE_WAIT)) p_usb (
        .clk(clk), .rst(rst), .cyc(cyc), .stb(usb_stb), .adr(adr), .ack(usb_ack), .err(usb_err),
        .f_wait()
    );

    wire ram_answer  = ram_stb && ram_ack;
    wire sdram_answer = sdram_stb && (sdram_ack || sdram_err);
    wire sdram_ctrl_answer = sdram_ctrl_stb && (sdram_ctrl_ack || sdram_ctrl_err);
    wire flash_answer = flash_stb && (flash_ack || flash_err);
    wire gpu_answer  = gpu_stb && (gpu_ack || gpu_err);
    wire uart_answer = uart_stb && (uart_ack || uart_err);
    wire sys_answer  = sys_stb && (sys_ack || sys_err);
    wire usb_answer  = usb_stb && (usb_ack || usb_err);
    wire none_err    = req && in_none && up_wait != 4'd0;  // the error responder's answer, expected

    always @(*) begin
        // Exactly one slave per request, the one whose region holds the address; none outside.
        assert(ram_stb == (req && in_ram));
        assert(sdram_stb == (req && in_sdram));
        assert(sdram_ctrl_stb == (req && in_sdram_ctrl));
        assert(flash_stb == (req && in_flash));
        assert(gpu_stb == (req && in_gpu));
        assert(uart_stb == (req && in_uart));
        assert(sys_stb == (req && in_sys));
        assert(usb_stb == (req && in_usb));
        if (req) assert($onehot({ram_stb, sdram_stb, sdram_ctrl_stb, flash_stb, gpu_stb, uart_stb, sys_stb,
                                 usb_stb, in_none}));
        // An address outside every region: err in the request's second clock, nothing before it
        // (the request has then been answered: it never waits longer), dat_r 0.
        // (From the second clock on: the error responder's flop starts at any value.)
        if (f_past_valid && req && in_none)
            assert(!ack && err == (up_wait != 4'd0) && up_wait <= 4'd1 && dat_r == 32'd0);
        // The answer is the selected slave's, or the error responder's: nothing else reaches the
        // master, so a slave's answer only during a request to it.
        assert(ack == (ram_answer || (sdram_stb && sdram_ack) || (sdram_ctrl_stb && sdram_ctrl_ack)
                       || (flash_stb && flash_ack) || (gpu_stb && gpu_ack) || (uart_stb && uart_ack) || (sys_stb && sys_ack)
                       || (usb_stb && usb_ack)));
        if (f_past_valid)
            assert(err == (none_err || (sdram_stb && sdram_err) || (sdram_ctrl_stb && sdram_ctrl_err)
                           || (flash_stb && flash_err) || (gpu_stb && gpu_err) || (uart_stb && uart_err) || (sys_stb && sys_err)
                           || (usb_stb && usb_err)));
        if (ram_answer)  assert(dat_r == ram_dat_r);
        if (sdram_answer) assert(dat_r == sdram_dat_r);
        if (sdram_ctrl_answer) assert(dat_r == sdram_ctrl_dat_r);
        if (flash_answer) assert(dat_r == flash_dat_r);
        if (gpu_answer)  assert(dat_r == gpu_dat_r);
        if (uart_answer) assert(dat_r == uart_dat_r);
        if (sys_answer)  assert(dat_r == sys_dat_r);
        if (usb_answer)  assert(dat_r == usb_dat_r);
    end

    // Covers, out of reset: a request answered by each slave (ack; err from those that can refuse),
    // an address outside every region and the RAM's window, one in the RAM's window above RAM_BYTES
    // (when it has such addresses), each answered by err; two such requests in a row, each answered two clocks apart.
    wire f_run = f_past_valid && !rst;
    reg [1:0] f_errs = 2'b00;  // err one and two clocks ago
    always @(posedge clk) f_errs <= {f_errs[0], err};
    always @(*) begin
        cover(f_run && ram_stb && ack);
        if (SDRAM_BYTES != 0) begin
            cover(f_run && sdram_stb && ack);
            cover(f_run && sdram_stb && err);
            cover(f_run && sdram_ctrl_stb && ack);
            cover(f_run && sdram_ctrl_stb && err);
            cover(f_run && flash_stb && ack);
            cover(f_run && flash_stb && err);
        end else begin
            // without SDRAM, its regions and the flash answer err
            cover(f_run && req && in_none && err && a >= soc_pkg::SOC_SDRAM_BASE
                  && a < soc_pkg::SOC_SDRAM_BASE + soc_pkg::SOC_SDRAM_WINDOW_BYTES);
            cover(f_run && req && in_none && err && a >= soc_pkg::SOC_SDRAM_CTRL_BASE
                  && a < soc_pkg::SOC_SDRAM_CTRL_BASE + soc_pkg::SOC_SDRAM_CTRL_WINDOW_BYTES);
            cover(f_run && req && in_none && err && a >= soc_pkg::SOC_FLASH_BASE
                  && a < soc_pkg::SOC_FLASH_BASE + soc_pkg::SOC_FLASH_WINDOW_BYTES);
        end
        if (SDRAM_BYTES != 0 && SDRAM_BYTES < soc_pkg::SOC_SDRAM_WINDOW_BYTES)
            cover(f_run && req && in_none && err && a >= soc_pkg::SOC_SDRAM_BASE + SDRAM_BYTES
                  && a < soc_pkg::SOC_SDRAM_BASE + soc_pkg::SOC_SDRAM_WINDOW_BYTES);
        cover(f_run && gpu_stb && ack);
        cover(f_run && gpu_stb && err);
        cover(f_run && uart_stb && ack);
        cover(f_run && uart_stb && err);
        cover(f_run && sys_stb && ack);
        cover(f_run && sys_stb && err);
        if (USB_HOST != 0) begin
            cover(f_run && usb_stb && ack);
            cover(f_run && usb_stb && err);
        end else begin
            // without the USB host, its region answers err
            cover(f_run && req && in_none && err && a >= soc_pkg::SOC_USB_BASE
                  && a < soc_pkg::SOC_USB_BASE + soc_pkg::SOC_USB_WINDOW_BYTES);
        end
        cover(f_run && req && in_none && err && a >= soc_pkg::SOC_RAM_WINDOW_BYTES);
        if (RAM_BYTES < soc_pkg::SOC_RAM_WINDOW_BYTES)
            cover(f_run && req && in_none && err && a >= RAM_BYTES && a < soc_pkg::SOC_RAM_WINDOW_BYTES);
        cover(f_run && req && in_none && err && f_errs == 2'b10);
    end
endmodule

// soc_wb_decoder_port: the Wishbone B4 classic rules of one port, both sides of it (ZipCPU's
// fwb_slave when DUT_ANSWERS is 1: the port's master is the environment, so its requests are
// assumed and the answers asserted; fwb_master when 0: the reverse). The decoder sees only cyc,
// stb and adr of a request (soc_top wires we, dat_w, sel and cti to the slaves around it).
//   requests: none in the clock after a reset clock; stb only within cyc; a request, stb and adr,
//             held unchanged until its ack or err.
//   answers:  ack or err only to a request in this clock, never both; MAX_WAIT > 0: at most
//             MAX_WAIT clocks after the request's first.
module soc_wb_decoder_port #(
    parameter integer DUT_ANSWERS = 1,  // 1: the DUT answers on this port; 0: the DUT requests
    parameter integer MAX_WAIT = 0      // > 0: the answer's latest clock after the request's first
) (
    input  wire        clk,
    input  wire        rst,
    input  wire        cyc,
    input  wire        stb,
    input  wire [29:0] adr,
    input  wire        ack,
    input  wire        err,
    output reg  [3:0]  f_wait    // clocks the request has waited before this one (saturating)
);
// Statements, no `;` after them: a rule of the port's master, and of its slave.
`define SOC_WB_REQUEST(p) begin if (DUT_ANSWERS != 0) begin assume(p); end else begin assert(p); end end
`define SOC_WB_ANSWER(p)  begin if (DUT_ANSWERS != 0) begin assert(p); end else begin assume(p); end end
    reg f_past_valid = 1'b0;
    reg f_prev_rst, f_held;   // last clock: rst; a request left unanswered
    reg [29:0] f_prev_adr;
    wire answer = ack || err;
    always @(posedge clk) begin
        f_past_valid <= 1'b1;
        f_prev_rst   <= rst;
        f_held       <= cyc && stb && !answer;
        f_prev_adr   <= adr;
        if (rst || !(cyc && stb) || answer) f_wait <= 4'd0;
        else if (f_wait != 4'd15)           f_wait <= f_wait + 4'd1;
    end

    always @(*) begin
        if (f_past_valid) begin
            if (f_prev_rst) `SOC_WB_REQUEST(!cyc)
            else if (f_held) `SOC_WB_REQUEST(cyc && stb && adr == f_prev_adr)
        end
        if (stb) `SOC_WB_REQUEST(cyc)
        if (answer) `SOC_WB_ANSWER(cyc && stb)
        `SOC_WB_ANSWER(!(ack && err))
        if (MAX_WAIT > 0 && f_past_valid && cyc && stb && f_wait >= MAX_WAIT) `SOC_WB_ANSWER(answer)
    end
`undef SOC_WB_REQUEST
`undef SOC_WB_ANSWER
endmodule

`default_nettype wire
