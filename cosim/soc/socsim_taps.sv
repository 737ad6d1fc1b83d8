// socsim_taps: what socsim observes inside soc_top without a port for it, bound in by module name
// (`bind`), so the harness depends on no instance path of soc_rtl and the RTL is not edited. The
// taps only watch: every input of theirs is an existing signal of the module they are bound into,
// and they drive nothing of it. They report through DPI-C calls, on events only (a bus write, a
// swap, a bus transaction start), so the cost per cycle is a few compares.
//
//   socsim_gpu_tap (in gpu_core): every bus write the GPU takes (byte offset, data) — the golden
//                                 model is fed the same writes —, every read's answer (compared
//                                 with the model's registers), and each change of FRAME_COUNT (a
//                                 buffer swap, after which the next VGA frame is captured), and each
//                                 change of its scan-out underflow count (SCANOUT_UNDERFLOWS: a GPU
//                                 whose frames are in the SDRAM).
//   socsim_frame_tap (in gpu_frame_dram): the slowest row fetch of the scan-out (below).
//   socsim_cpu_tap (in VexRiscv): the start of every Wishbone cycle of either bus (a fetch or load
//                                 of a cached address starts a cache-line refill: the misses), every
//                                 acknowledged load of UART DATA (the firmware reading keys), every
//                                 load of USB KEY that returns an event (VALID set: the firmware
//                                 took a key of the USB keyboard), the retired-instruction counter,
//                                 the clocks each bus spent in a cycle, by kind (below), and, when
//                                 socsim profiles (--profile), the address of every instruction
//                                 that retires.
`default_nettype none

module socsim_gpu_tap (
    input wire        clk,
    input wire        bus_valid,    // gpu_core's bus slave port, as gpu_regs takes it
    input wire        bus_write,
    input wire [16:2] bus_addr,
    input wire [31:0] bus_wdata,
    input wire [31:0] bus_rdata,    // valid with bus_rvalid, the cycle after the read request
    input wire        bus_rvalid,
    input wire [31:0] frame_count,  // gpu_core's FRAME_COUNT
    input wire [31:0] scanout_underflows  // gpu_core's SCANOUT_UNDERFLOWS input (0 but with FRAME_DRAM)
);
    import "DPI-C" function void socsim_gpu_write(input int unsigned offset, input int unsigned value);
    import "DPI-C" function void socsim_gpu_read(input int unsigned offset, input int unsigned value);
    import "DPI-C" function void socsim_gpu_swap(input int unsigned frame_count);
    import "DPI-C" function void socsim_gpu_underflows(input int unsigned count);

    reg [31:0] frame_count_q = 32'd0;
    reg [31:0] underflows_q = 32'd0;
    reg [16:2] read_addr_q = 15'd0;   // the address of the read whose data comes next
    always @(posedge clk) begin
        if (bus_valid && bus_write) begin
            socsim_gpu_write({15'd0, bus_addr, 2'b00}, bus_wdata);
        end
        if (bus_rvalid) begin
            socsim_gpu_read({15'd0, read_addr_q, 2'b00}, bus_rdata);
        end
        if (bus_valid && !bus_write) begin
            read_addr_q <= bus_addr;
        end
        if (frame_count != frame_count_q) begin
            socsim_gpu_swap(frame_count);
        end
        frame_count_q <= frame_count;
        if (scanout_underflows != underflows_q) begin
            socsim_gpu_underflows(scanout_underflows);
        end
        underflows_q <= scanout_underflows;
    end
endmodule

// socsim_frame_tap (in gpu_frame_dram, a GPU whose frames are in the SDRAM): the clocks each row
// fetch of the scan-out took, from its start to its last word, once the display is in step (after
// the first vertical blank); each new worst is reported. Its deadline is a display line.
module socsim_frame_tap (
    input wire clk,
    input wire start,        // a row's fetch starts
    input wire last_answer,  // its last word arrives
    input wire synced_q      // the display has passed its first vertical blank
);
    import "DPI-C" function void socsim_row_fetch(input int unsigned clocks);
    reg [31:0] clocks_q = 32'd0, worst_q = 32'd0;
    always @(posedge clk) begin
        clocks_q <= start ? 32'd1 : clocks_q + 32'd1;
        if (last_answer && synced_q && clocks_q > worst_q) begin
            worst_q <= clocks_q;
            socsim_row_fetch(clocks_q);
        end
    end
endmodule

module socsim_cpu_tap #(
    // The memory map's UART DATA register (contract/soc_map.toml, through soc_pkg).
    parameter [31:0] UART_DATA_ADDR = soc_pkg::SOC_UART_BASE + 32'(soc_pkg::SOC_UART_REG_DATA),
    // USB KEY and its VALID bit (a build without the USB host answers that address with 0)
    parameter [31:0] USB_KEY_ADDR = soc_pkg::SOC_USB_BASE + 32'(soc_pkg::SOC_USB_REG_KEY),
    parameter integer USB_KEY_VALID = soc_pkg::SOC_USB_KEY_VALID_LSB
) (
    input wire        clk,
    input wire        i_cyc,        // iBusWishbone_*
    input wire        d_cyc,        // dBusWishbone_*
    input wire        d_stb,
    input wire        d_ack,
    input wire        d_we,
    input wire [29:0] d_adr,
    input wire [31:0] d_dat_r,      // the load's data, with d_ack
    input wire [63:0] minstret,     // CsrPlugin_minstret
    input wire        retire,       // lastStageIsFiring: an instruction leaves the pipeline
    input wire [31:0] retire_pc     // lastStagePc: its address
);
    import "DPI-C" function void socsim_bus_cycle(input int unsigned ibus, input int unsigned word_addr,
                                                  input int unsigned write);
    import "DPI-C" function void socsim_uart_data_read();
    import "DPI-C" function void socsim_usb_key_read(input int unsigned value);
    // Called once at time 0 so that the harness learns this instance's scope for the export below
    // (svGetScope in a context import), wherever soc_top put the core.
    import "DPI-C" context function void socsim_cpu_scope();
    initial socsim_cpu_scope();
    // --profile: one call a retired instruction (socsim charges it the clocks since the last one);
    // without it none, so that the runs that do not profile pay nothing for it.
    import "DPI-C" function int unsigned socsim_profiling();
    import "DPI-C" function void socsim_retire(input int unsigned pc);
    reg profiling = 1'b0;
    initial profiling = socsim_profiling() != 0;

    reg i_cyc_q = 1'b0;
    reg d_cyc_q = 1'b0;
    // Clocks with a cycle open on the instruction bus (its refills), and on the data bus by kind: a
    // line refill (a load of a cached address, below 0x8000_0000, as the harness counts refills), a
    // store (write-through: every one is a bus cycle), or an uncached load (the GPU's and the
    // peripherals' registers); and the stores' number. A cycle's kind is its first clock's. The core
    // waits through most of them, so they are where its clocks go beyond one an instruction; the
    // two buses may overlap.
    reg        d_refill_q = 1'b0;
    reg        d_store_q = 1'b0;
    wire       d_start = d_cyc && !d_cyc_q;
    wire       d_refill = d_start ? (!d_we && !d_adr[29]) : d_refill_q;
    wire       d_store = d_start ? d_we : d_store_q;
    reg [63:0] i_cycles = 64'd0;
    reg [63:0] d_refill_cycles = 64'd0;
    reg [63:0] d_store_cycles = 64'd0;
    reg [63:0] d_load_cycles = 64'd0;
    reg [63:0] d_stores = 64'd0;
    always @(posedge clk) begin
        d_refill_q <= d_refill;
        d_store_q <= d_store;
        if (i_cyc) begin
            i_cycles <= i_cycles + 64'd1;
        end
        if (d_cyc && d_refill) begin
            d_refill_cycles <= d_refill_cycles + 64'd1;
        end
        if (d_cyc && d_store) begin
            d_store_cycles <= d_store_cycles + 64'd1;
        end
        if (d_cyc && !d_refill && !d_store) begin
            d_load_cycles <= d_load_cycles + 64'd1;
        end
        if (d_cyc && d_stb && d_ack && d_we) begin
            d_stores <= d_stores + 64'd1;
        end
        if (i_cyc && !i_cyc_q) begin
            socsim_bus_cycle(1, 0, 0);
        end
        if (d_cyc && !d_cyc_q) begin
            socsim_bus_cycle(0, {2'b00, d_adr}, {31'd0, d_we});
        end
        if (profiling && retire) begin
            socsim_retire(retire_pc);
        end
        if (d_cyc && d_stb && d_ack && !d_we && {d_adr, 2'b00} == UART_DATA_ADDR) begin
            socsim_uart_data_read();
        end
        if (d_cyc && d_stb && d_ack && !d_we && {d_adr, 2'b00} == USB_KEY_ADDR && d_dat_r[USB_KEY_VALID]) begin
            socsim_usb_key_read(d_dat_r);
        end
        i_cyc_q <= i_cyc;
        d_cyc_q <= d_cyc;
    end
    // The counter as it is now, read by the harness when it reports.
    export "DPI-C" function socsim_read_instret;
    function longint unsigned socsim_read_instret();
        return minstret;
    endfunction
    // The bus counts so far: which = 0 the instruction bus's clocks, 1 data refills', 2 stores',
    // 3 uncached loads', 4 the stores acknowledged.
    export "DPI-C" function socsim_read_bus_clocks;
    function longint unsigned socsim_read_bus_clocks(input int unsigned which);
        case (which)
            0: return i_cycles;
            1: return d_refill_cycles;
            2: return d_store_cycles;
            3: return d_load_cycles;
            default: return d_stores;
        endcase
    endfunction
endmodule

bind gpu_core socsim_gpu_tap u_socsim_gpu_tap (
    .clk(clk), .bus_valid(bus_valid), .bus_write(bus_write), .bus_addr(bus_addr),
    .bus_wdata(bus_wdata), .bus_rdata(bus_rdata), .bus_rvalid(bus_rvalid), .frame_count(frame_count),
    .scanout_underflows(scanout_underflows)
);

bind gpu_frame_dram socsim_frame_tap u_socsim_frame_tap (
    .clk(clk), .start(start), .last_answer(last_answer), .synced_q(synced_q)
);

bind VexRiscv socsim_cpu_tap u_socsim_cpu_tap (
    .clk(clk), .i_cyc(iBusWishbone_CYC), .d_cyc(dBusWishbone_CYC), .d_stb(dBusWishbone_STB),
    .d_ack(dBusWishbone_ACK), .d_we(dBusWishbone_WE), .d_adr(dBusWishbone_ADR),
    .d_dat_r(dBusWishbone_DAT_MISO), .minstret(CsrPlugin_minstret), .retire(lastStageIsFiring),
    .retire_pc(lastStagePc)
);
