// soc_uart: 8N1 serial port with RX and TX FIFOs, a Wishbone B4 slave (registers: UART in
// contract/soc-memory-map.md).
//
// Contract (bus): every request is answered in the next clock, once: wb_ack for DATA, STATUS, ERRORS,
// DIVIDER, wb_err for any other offset of the window. A DATA write pushes wb_dat_w[7:0] into the TX
// FIFO (dropped when full); a DATA read returns the oldest RX byte with bit 8 set and pops it, or 0
// when the RX FIFO is empty. Reads take effect once per request, in its first clock.
// Contract (line): DIV = CLK_HZ / BAUD rounded clocks per bit. TX sends start, 8 data bits LSB
// first, stop, back to back while the FIFO holds bytes. RX synchronises uart_rx with two flops
// (uart_rx is asynchronous: `_async`), takes a falling edge as a start bit and re-checks it half a
// bit later (shorter pulses are ignored), samples each data bit and the stop bit in the middle of
// the bit; a low stop bit is a framing error (counted, the byte dropped, RX waits for the line to go
// high again); a byte that finds the RX FIFO full is an overrun (counted, dropped). Both counters
// saturate at 0xFFFF. The bit timing error of the rounding is below 0.5 / DIV of a bit.
// Contract (RX FIFO): holds RX_DEPTH bytes exactly (the RX_DEPTH+1-th unread byte is an overrun), in
// order. A received byte is visible (STATUS RX_VALID, a DATA read) from the second clock after its
// stop bit's sample, instead of the first: the read-ahead below; software cannot tell.
//
// The RX FIFO's storage is block RAM (RX_DEPTH 2048 = one ECP5 DP16KD as 2048x9). Block RAM reads
// synchronously: the address is taken at a clock edge and the byte comes out after it, in its output
// register. The bus contract needs the oldest byte in the same clock as the DATA read's request (the
// answer is registered at that clock's end), so the FIFO reads ahead: the RAM's output register is
// the head of the FIFO (rx_head_q, valid in rx_head_valid_q), and the RAM holds the bytes behind it.
// The head is refilled from the RAM at the edge that ends a pop's clock (the read address is the
// oldest byte still in the RAM), so the next byte is already the head in the ack's clock, one clock
// before the earliest next request (a request is accepted at most every second clock: its ack comes
// between). A byte pushed into an empty FIFO is written at one edge and read into the head at the
// next, hence the one clock of delay; STATUS and DATA both look at rx_head_valid_q, so they always
// agree. The RAM never reads and writes one address in the same clock (a fetch needs a byte written
// at an earlier edge, a push a free entry), so its read-during-write behaviour does not matter. Full
// counts the head too (rx_level_q), so the capacity is RX_DEPTH, not RX_DEPTH + 1.
`default_nettype none

module soc_uart #(
    parameter integer CLK_HZ = soc_pkg::SOC_CLK_HZ_DEFAULT,     // system clock, Hz
    parameter integer BAUD = soc_pkg::SOC_UART_BAUD,            // bits per second
    parameter integer RX_DEPTH = soc_pkg::SOC_UART_RX_FIFO_DEPTH,  // bytes, a power of two
    parameter integer TX_DEPTH = soc_pkg::SOC_UART_TX_FIFO_DEPTH,  // bytes, a power of two
    localparam integer DIV = (CLK_HZ + BAUD / 2) / BAUD,        // clocks per bit
    localparam integer CW = $clog2(DIV + 1),                    // bit-timer width
    localparam integer RXW = $clog2(RX_DEPTH),
    localparam integer TXW = $clog2(TX_DEPTH)
) (
    input  wire        clk,
    input  wire        rst,           // synchronous, active high
    // Wishbone B4 slave (the UART window)
    input  wire        wb_cyc,
    input  wire        wb_stb,        // selected by the decoder
    input  wire        wb_we,
    input  wire [7:2]  wb_adr,        // word offset in the window
    input  wire [7:0]  wb_dat_w,      // a DATA write's byte (the rest of the word is ignored)
    output reg  [31:0] wb_dat_r,      // valid with wb_ack
    output wire        wb_ack,
    output wire        wb_err,
    // serial lines
    input  wire        uart_rx_async, // received line, idle high, not synchronous to clk
    output reg         uart_tx        // transmitted line, idle high
);
    generate if (DIV < 4 || (1 << RXW) != RX_DEPTH || (1 << TXW) != TX_DEPTH) begin : g_bad
        $error("soc_uart: CLK_HZ / BAUD must be at least 4, FIFO depths powers of two");
    end endgenerate

    localparam [CW-1:0] BIT_CLKS  = DIV[CW-1:0] - 1'b1;       // a whole bit, counted down to 0
    localparam [CW-1:0] HALF_CLKS = DIV[CW:1] - 1'b1;         // half a bit
    localparam [7:0] OFF_DATA    = soc_pkg::SOC_UART_REG_DATA;
    localparam [7:0] OFF_STATUS  = soc_pkg::SOC_UART_REG_STATUS;
    localparam [7:0] OFF_ERRORS  = soc_pkg::SOC_UART_REG_ERRORS;
    localparam [7:0] OFF_DIVIDER = soc_pkg::SOC_UART_REG_DIVIDER;

    // ---- bus: registered answer, one clock after the request ----
    reg  ack_q, err_q;
    wire req = wb_cyc && wb_stb;
    wire accept = req && !ack_q && !err_q;   // a request's first clock: its effects happen here
    wire [7:0] off = {wb_adr, 2'b00};
    wire is_data = off == OFF_DATA, is_status = off == OFF_STATUS;
    wire is_errors = off == OFF_ERRORS, is_divider = off == OFF_DIVIDER;
    wire known = is_data || is_status || is_errors || is_divider;
    assign wb_ack = ack_q && req;
    assign wb_err = err_q && req;

    // ---- RX: synchroniser, bit timer, shift register, FIFO ----
    reg [1:0] rx_sync_q;                  // two flops: rx_sync_q[1] is the synchronous line
    wire rx = rx_sync_q[1];
    localparam [1:0] RX_IDLE = 2'd0, RX_START = 2'd1, RX_BITS = 2'd2, RX_STOP = 2'd3;
    reg [1:0]    rx_state_q;
    reg [CW-1:0] rx_timer_q;
    reg [2:0]    rx_bit_q;
    reg [7:0]    rx_shift_q;
    reg          rx_wait_high_q;           // after a framing error: wait for the line to idle
    reg [7:0]    rx_mem [0:RX_DEPTH-1];    // block RAM: the bytes behind the head
    reg [RXW:0]  rx_wr_q, rx_rd_q;         // RAM pointers, one bit wider than the index: full vs empty
    reg [7:0]    rx_head_q;                // the RAM's output register: the oldest byte
    reg          rx_head_valid_q;          // rx_head_q holds a byte not yet popped
    reg [RXW:0]  rx_level_q;               // bytes held, the head included: 0 .. RX_DEPTH
    wire rx_mem_empty = rx_wr_q == rx_rd_q;
    wire rx_full = rx_level_q == RX_DEPTH[RXW:0];
    reg [15:0]   frame_err_q, overrun_q;
    wire rx_stop_mid  = rx_state_q == RX_STOP && rx_timer_q == 0;   // the stop bit's sample
    wire rx_push      = rx_stop_mid && rx;     // a good byte ends this clock
    wire rx_frame_bad = rx_stop_mid && !rx;    // a byte with a low stop bit ends this clock
    wire rx_write     = rx_push && !rx_full;   // ... and has room
    wire rx_pop = accept && !wb_we && is_data && rx_head_valid_q;
    wire rx_fetch = !rx_mem_empty && (!rx_head_valid_q || rx_pop);   // the head (re)filled from the RAM

    always @(posedge clk) begin
        if (rst) rx_sync_q <= 2'b11;
        else     rx_sync_q <= {rx_sync_q[0], uart_rx_async};
    end

    always @(posedge clk) begin
        if (rst) begin
            rx_state_q <= RX_IDLE;
            rx_timer_q <= '0;
            rx_bit_q <= 3'd0;
            rx_shift_q <= 8'd0;
            rx_wait_high_q <= 1'b0;
        end else begin
            case (rx_state_q)
                RX_IDLE: begin
                    if (rx) rx_wait_high_q <= 1'b0;
                    if (!rx && !rx_wait_high_q) begin
                        rx_state_q <= RX_START;
                        rx_timer_q <= HALF_CLKS;
                    end
                end
                RX_START: begin   // the middle of the start bit: still low, or it was a glitch
                    if (rx_timer_q != 0) rx_timer_q <= rx_timer_q - 1'b1;
                    else if (rx) rx_state_q <= RX_IDLE;
                    else begin
                        rx_state_q <= RX_BITS;
                        rx_timer_q <= BIT_CLKS;
                        rx_bit_q <= 3'd0;
                    end
                end
                RX_BITS: begin
                    if (rx_timer_q != 0) rx_timer_q <= rx_timer_q - 1'b1;
                    else begin
                        rx_shift_q <= {rx, rx_shift_q[7:1]};   // LSB first
                        rx_timer_q <= BIT_CLKS;
                        rx_bit_q <= rx_bit_q + 1'b1;
                        if (rx_bit_q == 3'd7) rx_state_q <= RX_STOP;
                    end
                end
                default: begin    // RX_STOP: the middle of the stop bit
                    if (rx_timer_q != 0) rx_timer_q <= rx_timer_q - 1'b1;
                    else begin
                        rx_state_q <= RX_IDLE;
                        if (!rx) rx_wait_high_q <= 1'b1;   // framing error (rx_frame_bad)
                    end
                end
            endcase
        end
    end

    // The RAM and its output register: no reset (a block RAM's contents and read register have
    // none); rx_head_valid_q says when rx_head_q means something.
    always @(posedge clk) begin
        if (rx_write) rx_mem[rx_wr_q[RXW-1:0]] <= rx_shift_q;
        if (rx_fetch) rx_head_q <= rx_mem[rx_rd_q[RXW-1:0]];
    end

    always @(posedge clk) begin
        if (rst) begin
            rx_wr_q <= '0;
            rx_rd_q <= '0;
            rx_head_valid_q <= 1'b0;
            rx_level_q <= '0;
            frame_err_q <= 16'd0;
            overrun_q <= 16'd0;
        end else begin
            if (rx_write) rx_wr_q <= rx_wr_q + 1'b1;
            if (rx_fetch) rx_rd_q <= rx_rd_q + 1'b1;
            if (rx_fetch) rx_head_valid_q <= 1'b1;
            else if (rx_pop) rx_head_valid_q <= 1'b0;
            if (rx_write && !rx_pop) rx_level_q <= rx_level_q + 1'b1;
            else if (rx_pop && !rx_write) rx_level_q <= rx_level_q - 1'b1;
            if (rx_push && rx_full && overrun_q != 16'hFFFF) overrun_q <= overrun_q + 1'b1;
            if (rx_frame_bad && frame_err_q != 16'hFFFF) frame_err_q <= frame_err_q + 1'b1;
        end
    end

    // ---- TX: FIFO and shifter ----
    // The FIFO's read goes straight into tx_shift_q (a synchronous read): yosys maps the 256 bytes
    // onto one DP16KD.
    reg [7:0]    tx_fifo [0:TX_DEPTH-1];
    reg [TXW:0]  tx_wr_q, tx_rd_q;
    wire tx_empty = tx_wr_q == tx_rd_q;
    wire tx_full  = tx_wr_q == {~tx_rd_q[TXW], tx_rd_q[TXW-1:0]};
    reg          tx_busy_q;                // the shifter is sending a frame
    reg [8:0]    tx_shift_q;               // {stop, data} still to send after the current bit
    reg [3:0]    tx_bits_q;                // bits left after the current one
    reg [CW-1:0] tx_timer_q;
    wire tx_push = accept && wb_we && is_data && !tx_full;
    wire tx_load = !tx_busy_q && !tx_empty;

    always @(posedge clk) begin
        if (rst) begin
            tx_wr_q <= '0;
            tx_rd_q <= '0;
            tx_busy_q <= 1'b0;
            tx_shift_q <= 9'h1FF;
            tx_bits_q <= 4'd0;
            tx_timer_q <= '0;
            uart_tx <= 1'b1;
        end else begin
            if (tx_push) begin
                tx_fifo[tx_wr_q[TXW-1:0]] <= wb_dat_w;
                tx_wr_q <= tx_wr_q + 1'b1;
            end
            if (tx_load) begin             // start bit now, then 8 data bits and the stop bit
                uart_tx <= 1'b0;
                tx_shift_q <= {1'b1, tx_fifo[tx_rd_q[TXW-1:0]]};
                tx_bits_q <= 4'd9;
                tx_timer_q <= BIT_CLKS;
                tx_busy_q <= 1'b1;
                tx_rd_q <= tx_rd_q + 1'b1;
            end else if (tx_busy_q) begin
                if (tx_timer_q != 0) tx_timer_q <= tx_timer_q - 1'b1;
                else if (tx_bits_q != 0) begin
                    uart_tx <= tx_shift_q[0];
                    tx_shift_q <= {1'b1, tx_shift_q[8:1]};
                    tx_bits_q <= tx_bits_q - 1'b1;
                    tx_timer_q <= BIT_CLKS;
                end else begin
                    tx_busy_q <= 1'b0;     // the stop bit has had its whole bit time
                end
            end
        end
    end

    // ---- register reads and the answer ----
    // Fields at the contract's positions (soc_pkg::SOC_UART_*_LSB).
    wire tx_idle = tx_empty && !tx_busy_q;
    wire [31:0] status = ({31'd0, rx_head_valid_q} << soc_pkg::SOC_UART_STATUS_RX_VALID_LSB)
                       | ({31'd0, tx_full}   << soc_pkg::SOC_UART_STATUS_TX_FULL_LSB)
                       | ({31'd0, tx_idle}   << soc_pkg::SOC_UART_STATUS_TX_IDLE_LSB);
    wire [31:0] rx_word = ({24'd0, rx_head_q} << soc_pkg::SOC_UART_DATA_BYTE_LSB)
                        | ({31'd0, 1'b1} << soc_pkg::SOC_UART_DATA_VALID_LSB);
    wire [31:0] errors = ({16'd0, frame_err_q} << soc_pkg::SOC_UART_ERRORS_FRAMING_LSB)
                       | ({16'd0, overrun_q}   << soc_pkg::SOC_UART_ERRORS_OVERRUN_LSB);
    always @(posedge clk) begin
        if (rst) begin
            ack_q <= 1'b0;
            err_q <= 1'b0;
            wb_dat_r <= 32'd0;
        end else begin
            ack_q <= accept && known;
            err_q <= accept && !known;
            if (accept) begin
                wb_dat_r <= 32'd0;
                if (!wb_we) begin
                    if (is_data && rx_head_valid_q) wb_dat_r <= rx_word;
                    if (is_status) wb_dat_r <= status;
                    if (is_errors) wb_dat_r <= errors;
                    if (is_divider) wb_dat_r <= DIV;
                end
            end
        end
    end
`ifdef FORMAL
    // ---- formal properties (tests/formal/soc_uart.sby, with the bus rules of soc_uart_check.sv) ----
    // Invariants and FIFO properties over the module's own state (yosys reads no hierarchical
    // names, so they live here). Every register is reset in the first clock (the checker's
    // assumption); rst may come again at any clock.
    reg f_past_valid = 1'b0;
    always @(posedge clk) f_past_valid <= 1'b1;

    // The bus answer: ack or err one clock after the request's first clock, never both.
    always @(*) if (f_past_valid) assert(!(ack_q && err_q));
    always @(posedge clk) begin
        if (f_past_valid) begin
            assert(ack_q == $past(!rst && accept && known));
            assert(err_q == $past(!rst && accept && !known));
        end
    end

    // ---- TX FIFO: level, full, empty; a write when full dropped, not written ----
    wire [TXW:0] f_tx_level = tx_wr_q - tx_rd_q;
    always @(*) begin
        if (f_past_valid) begin
            assert(f_tx_level <= TX_DEPTH[TXW:0]);
            assert(tx_empty == (f_tx_level == 0));
            assert(tx_full == (f_tx_level == TX_DEPTH[TXW:0]));
        end
    end
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst)) begin
            assert(tx_wr_q == $past(tx_wr_q + {{TXW{1'b0}}, tx_push}));
            assert(tx_rd_q == $past(tx_rd_q + {{TXW{1'b0}}, tx_load}));
            if ($past(accept && wb_we && is_data && tx_full)) assert(tx_wr_q == $past(tx_wr_q));
        end
    end

    // TX: two tracked bytes. Any two successive writes (anyconst: the pointer value of the first,
    // and both bytes) leave the FIFO in order with their values: after the first is read, the next
    // read is the second.
    (* anyconst *) reg [TXW:0] f_tx_first;
    (* anyconst *) reg [7:0]   f_tx_d1, f_tx_d2;
    wire [TXW:0] f_tx_second = f_tx_first + 1'b1;
    wire f_tx_push1 = tx_push && tx_wr_q == f_tx_first && wb_dat_w == f_tx_d1;
    wire f_tx_push2 = tx_push && tx_wr_q == f_tx_second && wb_dat_w == f_tx_d2;
    wire f_tx_pop1 = tx_load && tx_rd_q == f_tx_first;
    wire f_tx_pop2 = tx_load && tx_rd_q == f_tx_second;
    localparam [1:0] F_NONE = 2'd0, F_FIRST = 2'd1, F_BOTH = 2'd2, F_SECOND = 2'd3;  // what is held
    reg [1:0] f_tx_st = F_NONE;
    always @(posedge clk) begin
        if (rst) f_tx_st <= F_NONE;
        else case (f_tx_st)
            F_NONE:   if (f_tx_push1) f_tx_st <= F_FIRST;
            F_FIRST:  if (f_tx_pop1) f_tx_st <= f_tx_push2 ? F_SECOND : F_NONE;
                      else if (f_tx_push2) f_tx_st <= F_BOTH;
            F_BOTH:   if (f_tx_pop1) f_tx_st <= F_SECOND;
            default:  if (f_tx_pop2) f_tx_st <= F_NONE;
        endcase
    end
    wire [TXW:0] f_tx_first_at = f_tx_first - tx_rd_q;    // its place from the oldest, 0 first
    wire [TXW:0] f_tx_second_at = f_tx_second - tx_rd_q;
    wire [7:0] f_tx_mem1 = tx_fifo[f_tx_first[TXW-1:0]];
    wire [7:0] f_tx_mem2 = tx_fifo[f_tx_second[TXW-1:0]];
    always @(*) begin
        if (f_past_valid) begin
            case (f_tx_st)
                F_FIRST:  assert(f_tx_first_at < f_tx_level && f_tx_mem1 == f_tx_d1);
                F_BOTH:   assert(f_tx_second_at < f_tx_level && f_tx_first_at < f_tx_second_at
                                 && f_tx_mem1 == f_tx_d1 && f_tx_mem2 == f_tx_d2);
                F_SECOND: assert(tx_rd_q == f_tx_second && !tx_empty && f_tx_mem2 == f_tx_d2);
                default: ;
            endcase
            // the reads: the shifter is loaded with the tracked bytes, in order
            if (f_tx_pop1 && f_tx_st != F_NONE && f_tx_st != F_SECOND)
                assert(tx_fifo[tx_rd_q[TXW-1:0]] == f_tx_d1);
            if (f_tx_pop2 && f_tx_st == F_SECOND) assert(tx_fifo[tx_rd_q[TXW-1:0]] == f_tx_d2);
        end
    end

    // TX line: the byte the shifter was loaded with goes out as start, 8 bits LSB first, stop.
    reg [7:0] f_tx_byte = 8'd0;      // the byte of the current (or last) frame
    always @(posedge clk) if (!rst && tx_load) f_tx_byte <= tx_fifo[tx_rd_q[TXW-1:0]];
    wire [9:0]  f_tx_frame = {1'b1, f_tx_byte, 1'b0};                   // bit 0 first
    wire [3:0]  f_tx_sent = 4'd9 - tx_bits_q;                           // the frame bit on the line
    wire [17:0] f_tx_left = {9'h1FF, 1'b1, f_tx_byte} >> f_tx_sent;     // what tx_shift_q holds
    always @(*) begin
        if (f_past_valid) begin
            assert(tx_bits_q <= 4'd9 && tx_timer_q <= BIT_CLKS);
            if (!tx_busy_q) assert(uart_tx && tx_bits_q == 4'd0);
            else assert(uart_tx == f_tx_frame[f_tx_sent] && tx_shift_q == f_tx_left[8:0]);
        end
    end

    // ---- RX FIFO: the head register and the RAM behind it ----
    wire [RXW:0] f_rx_mem_level = rx_wr_q - rx_rd_q;
    wire [RXW:0] f_rx_head_ptr = rx_rd_q - 1'b1;   // the RAM entry the head was read from
    always @(*) begin
        if (f_past_valid) begin
            assert(rx_level_q <= RX_DEPTH[RXW:0] && f_rx_mem_level <= RX_DEPTH[RXW:0]);
            assert(rx_level_q == f_rx_mem_level + {{RXW{1'b0}}, rx_head_valid_q});
            assert(rx_full == (rx_level_q == RX_DEPTH[RXW:0]));
        end
    end
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst)) begin
            // a byte is written when there is room, else counted as an overrun (saturating)
            assert(rx_level_q == $past(rx_level_q + {{RXW{1'b0}}, rx_push && !rx_full}
                                       - {{RXW{1'b0}}, rx_pop}));
            if ($past(rx_push && rx_full))
                assert(overrun_q == $past(overrun_q) + {15'd0, $past(overrun_q) != 16'hFFFF});
            else
                assert(overrun_q == $past(overrun_q));
            // a DATA read returns the head with bit 8 set if it holds a byte, else 0
            if ($past(accept && !wb_we && is_data))
                assert(wb_dat_r == ($past(rx_head_valid_q) ? $past(rx_word) : 32'd0));
        end
    end

    // RX: two tracked bytes, from the receiver (a good byte with room) to a DATA read's answer.
    (* anyconst *) reg [RXW:0] f_rx_first;
    (* anyconst *) reg [7:0]   f_rx_d1, f_rx_d2;
    wire [RXW:0] f_rx_second = f_rx_first + 1'b1;
    wire f_rx_push1 = rx_push && !rx_full && rx_wr_q == f_rx_first && rx_shift_q == f_rx_d1;
    wire f_rx_push2 = rx_push && !rx_full && rx_wr_q == f_rx_second && rx_shift_q == f_rx_d2;
    wire f_rx_pop1 = rx_pop && f_rx_head_ptr == f_rx_first;
    wire f_rx_pop2 = rx_pop && f_rx_head_ptr == f_rx_second;
    reg [1:0] f_rx_st = F_NONE;
    always @(posedge clk) begin
        if (rst) f_rx_st <= F_NONE;
        else case (f_rx_st)
            F_NONE:   if (f_rx_push1) f_rx_st <= F_FIRST;
            F_FIRST:  if (f_rx_pop1) f_rx_st <= f_rx_push2 ? F_SECOND : F_NONE;
                      else if (f_rx_push2) f_rx_st <= F_BOTH;
            F_BOTH:   if (f_rx_pop1) f_rx_st <= F_SECOND;
            default:  if (f_rx_pop2) f_rx_st <= F_NONE;
        endcase
    end
    wire [RXW:0] f_rx_first_at = f_rx_first - rx_rd_q;   // place in the RAM from its oldest
    wire [RXW:0] f_rx_second_at = f_rx_second - rx_rd_q;
    wire f_rx_mem1 = f_rx_first_at < f_rx_mem_level && rx_mem[f_rx_first[RXW-1:0]] == f_rx_d1;
    wire f_rx_mem2 = f_rx_second_at < f_rx_mem_level && rx_mem[f_rx_second[RXW-1:0]] == f_rx_d2;
    wire f_rx_head1 = rx_head_valid_q && f_rx_head_ptr == f_rx_first && rx_head_q == f_rx_d1;
    wire f_rx_head2 = rx_head_valid_q && f_rx_head_ptr == f_rx_second && rx_head_q == f_rx_d2;
    always @(*) begin
        if (f_past_valid) begin
            case (f_rx_st)
                F_FIRST:  assert(f_rx_head1 || f_rx_mem1);
                F_BOTH:   assert((f_rx_head1 || f_rx_mem1) && f_rx_mem2);
                F_SECOND: assert(f_rx_head2 || (!rx_head_valid_q && rx_rd_q == f_rx_second
                                                && f_rx_mem2));
                default: ;
            endcase
        end
    end
    // ... and the DATA reads that pop them answer with them, in order
    always @(posedge clk) begin
        if (f_past_valid && !$past(rst)) begin
            if ($past(f_rx_pop1 && (f_rx_st == F_FIRST || f_rx_st == F_BOTH)))
                assert(wb_dat_r == (({24'd0, f_rx_d1} << soc_pkg::SOC_UART_DATA_BYTE_LSB)
                                    | (32'd1 << soc_pkg::SOC_UART_DATA_VALID_LSB)));
            if ($past(f_rx_pop2 && f_rx_st == F_SECOND))
                assert(wb_dat_r == (({24'd0, f_rx_d2} << soc_pkg::SOC_UART_DATA_BYTE_LSB)
                                    | (32'd1 << soc_pkg::SOC_UART_DATA_VALID_LSB)));
        end
    end

    // Covers: both tracked TX bytes held behind a frame on the line; both tracked RX bytes
    // read; the TX FIFO full; an RX overrun counted.
    always @(posedge clk) begin
        cover(f_past_valid && f_tx_st == F_BOTH && tx_busy_q);
        cover(f_past_valid && !$past(rst) && $past(f_rx_st == F_SECOND && f_rx_pop2));
        cover(f_past_valid && tx_full);
        cover(f_past_valid && overrun_q == 16'd1);
    end
`endif
endmodule

`default_nettype wire
