// gpu_regs: the GPU's bus slave — register file, window decode and buffer write routing.
//
// Contract (contract/gpu-contract.md; offsets and fields are gpu_pkg::GPU_*, generated from the
// contract): aligned 32-bit accesses. A write is taken in the cycle bus_valid && bus_write is high
// (no wait states). A read returns bus_rdata with bus_rvalid one cycle after bus_valid && !bus_write.
// Writes to the palette, the buffers and the batch registers while busy are dropped and flag
// ERR_WRITE_BUSY; a DOORBELL write while idle latches its tag and pulses start for one cycle; a RESET
// write (busy or not) pulses soft_reset. The batch registers hold still while busy, so the rasterizer
// reads them directly.
`default_nettype none

module gpu_regs #(
    parameter integer VTX_CAP = gpu_pkg::GPU_VTX_CAP,  // vertices; the vertex RAM holds 2 words each
    parameter integer TRI_CAP = gpu_pkg::GPU_TRI_CAP,  // primitives; the index RAM holds 2 words each
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,    // the frame (FB_SIZE)
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    parameter integer STRIP_ROWS = gpu_pkg::GPU_DEFAULT_STRIP_ROWS,  // the strip buffer (STRIP_ROWS)
    parameter [31:0]  CAPS = 32'h0,    // value of the CAPS register, set by gpu_top from its parameters
    parameter integer ENABLE_WMASK = gpu_pkg::GPU_DEFAULT_ENABLE_WMASK,  // FB_WRITE_MASK is writable
    localparam integer VTX_AW = $clog2(VTX_CAP * 2),
    localparam integer IDX_AW = $clog2(TRI_CAP * 2)
) (
    input  wire              clk,
    input  wire              rst,
    // bus slave
    input  wire              bus_valid,
    input  wire              bus_write,
    input  wire [16:2]       bus_addr,     // word address within the 128 KiB aperture
    input  wire [31:0]       bus_wdata,
    output reg  [31:0]       bus_rdata,
    output reg               bus_rvalid,
    // batch description, stable while busy
    output reg               ctrl_clear,
    output reg               ctrl_swap,
    output reg               ctrl_ztest,
    output reg               ctrl_zclear,
    output reg               ctrl_dither,
    output reg               ctrl_walk,
    output reg  [31:0]       vtx_base,
    output reg  [31:0]       vtx_count,
    output reg  [31:0]       tri_base,
    output reg  [31:0]       tri_count,
    output reg  [7:0]        clear_color,
    output reg  [1:0]        fb_wmask,     // FB_WRITE_MASK: {WMASK_HI, WMASK_LO}, 2'b11 without ENABLE_WMASK
    output reg  [31:0]       strip,        // STRIP as written: {STRIP_LAST, STRIP_FIRST}
    output reg  [31:0]       doorbell_tag,
    output reg               start,        // one-cycle pulse: run the batch
    output reg               soft_reset,   // one-cycle pulse: RESET was written
    // buffer writes (data is bus_wdata)
    output wire              vtx_wr_en,
    output wire [VTX_AW-1:0] vtx_wr_addr,
    output wire              idx_wr_en,
    output wire [IDX_AW-1:0] idx_wr_addr,
    output wire              pal_wr_en,
    output wire [7:0]        pal_wr_addr,
    // state reported by the rasterizer
    input  wire              busy,
    input  wire              front,
    input  wire [31:0]       done_seq,
    input  wire [31:0]       frame_count,
    input  wire [3:0]        raster_errors,  // {ERR_STRIP, ERR_KIND, ERR_COUNT, ERR_VTX_INDEX}
    input  gpu_pkg::perf_t   perf,         // the PERF_* counters
    input  wire [31:0]       scanout_underflows  // SCANOUT_UNDERFLOWS (0 with the frames on chip)
);
    wire [16:0] byte_addr = {bus_addr, 2'b00};
    wire is_write = bus_valid && bus_write;

    // Window decode. Buffer offsets beyond the RAM's capacity are unmapped.
    wire in_regs = byte_addr < gpu_pkg::GPU_WIN_REGS + gpu_pkg::GPU_WIN_REGS_BYTES;
    wire in_pal  = byte_addr >= gpu_pkg::GPU_WIN_PALETTE
                && byte_addr < gpu_pkg::GPU_WIN_PALETTE + gpu_pkg::GPU_WIN_PALETTE_BYTES;
    wire [16:0] vtx_offset = byte_addr - gpu_pkg::GPU_WIN_VTX;
    wire [16:0] idx_offset = byte_addr - gpu_pkg::GPU_WIN_IDX;
    wire in_vtx = byte_addr >= gpu_pkg::GPU_WIN_VTX && vtx_offset < 17'(VTX_CAP * 8);
    wire in_idx = byte_addr >= gpu_pkg::GPU_WIN_IDX && idx_offset < 17'(TRI_CAP * 8);
    wire [7:0] reg_offset = byte_addr[7:0];
    wire is_batch_reg = in_regs && (reg_offset == gpu_pkg::GPU_REG_CTRL
        || reg_offset == gpu_pkg::GPU_REG_VTX_BASE || reg_offset == gpu_pkg::GPU_REG_VTX_COUNT
        || reg_offset == gpu_pkg::GPU_REG_TRI_BASE || reg_offset == gpu_pkg::GPU_REG_TRI_COUNT
        || reg_offset == gpu_pkg::GPU_REG_CLEAR_COLOR || reg_offset == gpu_pkg::GPU_REG_DOORBELL
        || reg_offset == gpu_pkg::GPU_REG_FB_WRITE_MASK || reg_offset == gpu_pkg::GPU_REG_STRIP);
    wire write_dropped = is_write && busy && (in_pal || in_vtx || in_idx || is_batch_reg);
    wire write_ok = is_write && !busy;

    assign vtx_wr_en   = write_ok && in_vtx;
    assign vtx_wr_addr = vtx_offset[VTX_AW+1:2];
    assign idx_wr_en   = write_ok && in_idx;
    assign idx_wr_addr = idx_offset[IDX_AW+1:2];
    assign pal_wr_en   = write_ok && in_pal;
    assign pal_wr_addr = byte_addr[9:2];

    reg err_write_busy_q;
    reg [31:0] reset_value_q;

    always @(posedge clk) begin
        if (rst) begin
            ctrl_clear <= 1'b0;
            ctrl_swap <= 1'b0;
            ctrl_ztest <= 1'b0;
            ctrl_zclear <= 1'b0;
            ctrl_dither <= 1'b0;
            ctrl_walk <= 1'b0;
            soft_reset <= 1'b0;
            reset_value_q <= 32'd0;
            vtx_base <= 32'd0;
            vtx_count <= 32'd0;
            tri_base <= 32'd0;
            tri_count <= 32'd0;
            clear_color <= 8'd0;
            fb_wmask <= 2'b11;
            strip <= 32'(FB_HEIGHT - 1) << gpu_pkg::GPU_STRIP_LAST_LSB;  // the whole frame
            doorbell_tag <= 32'd0;
            start <= 1'b0;
            err_write_busy_q <= 1'b0;
        end else begin
            start <= 1'b0;
            soft_reset <= 1'b0;
            // RESET is taken even while busy: it is how a watchdog recovers a stuck batch.
            if (is_write && in_regs && reg_offset == gpu_pkg::GPU_REG_RESET) begin
                reset_value_q <= bus_wdata;
                soft_reset <= 1'b1;
            end
            if (write_ok && in_regs) begin
                case (reg_offset)
                    gpu_pkg::GPU_REG_CTRL: begin
                        ctrl_clear <= bus_wdata[gpu_pkg::GPU_CTRL_CLEAR_LSB];
                        ctrl_swap <= bus_wdata[gpu_pkg::GPU_CTRL_SWAP_LSB];
                        ctrl_ztest <= bus_wdata[gpu_pkg::GPU_CTRL_ZTEST_LSB];
                        ctrl_zclear <= bus_wdata[gpu_pkg::GPU_CTRL_ZCLEAR_LSB];
                        ctrl_dither <= bus_wdata[gpu_pkg::GPU_CTRL_DITHER_LSB];
                        ctrl_walk <= bus_wdata[gpu_pkg::GPU_CTRL_WALK_LSB];
                    end
                    gpu_pkg::GPU_REG_VTX_BASE:    vtx_base <= bus_wdata;
                    gpu_pkg::GPU_REG_VTX_COUNT:   vtx_count <= bus_wdata;
                    gpu_pkg::GPU_REG_TRI_BASE:    tri_base <= bus_wdata;
                    gpu_pkg::GPU_REG_TRI_COUNT:   tri_count <= bus_wdata;
                    gpu_pkg::GPU_REG_CLEAR_COLOR: clear_color <= bus_wdata[7:0];
                    gpu_pkg::GPU_REG_FB_WRITE_MASK: begin
                        // A GPU built without the mask keeps writing both planes.
                        if (ENABLE_WMASK != 0) begin
                            fb_wmask <= {bus_wdata[gpu_pkg::GPU_WMASK_HI_LSB],
                                         bus_wdata[gpu_pkg::GPU_WMASK_LO_LSB]};
                        end
                    end
                    gpu_pkg::GPU_REG_STRIP:       strip <= bus_wdata;
                    gpu_pkg::GPU_REG_DOORBELL: begin
                        doorbell_tag <= bus_wdata;
                        start <= 1'b1;
                        err_write_busy_q <= 1'b0;  // errors are per batch
                    end
                    default: ;
                endcase
            end
            if (write_dropped) begin
                err_write_busy_q <= 1'b1;
            end
        end
    end

    // Read mux, registered: one cycle of latency.
    wire [31:0] ctrl_value = (32'(ctrl_clear) << gpu_pkg::GPU_CTRL_CLEAR_LSB)
                           | (32'(ctrl_swap) << gpu_pkg::GPU_CTRL_SWAP_LSB)
                           | (32'(ctrl_ztest) << gpu_pkg::GPU_CTRL_ZTEST_LSB)
                           | (32'(ctrl_zclear) << gpu_pkg::GPU_CTRL_ZCLEAR_LSB)
                           | (32'(ctrl_dither) << gpu_pkg::GPU_CTRL_DITHER_LSB)
                           | (32'(ctrl_walk) << gpu_pkg::GPU_CTRL_WALK_LSB);
    wire [31:0] status_value = (32'(busy) << gpu_pkg::GPU_STATUS_BUSY_LSB)
                             | (32'(front) << gpu_pkg::GPU_STATUS_FRONT_LSB);
    wire [31:0] errors_value = (32'(raster_errors[0]) << gpu_pkg::GPU_ERR_VTX_INDEX_LSB)
                             | (32'(raster_errors[1]) << gpu_pkg::GPU_ERR_COUNT_LSB)
                             | (32'(raster_errors[2]) << gpu_pkg::GPU_ERR_KIND_LSB)
                             | (32'(raster_errors[3]) << gpu_pkg::GPU_ERR_STRIP_LSB)
                             | (32'(err_write_busy_q) << gpu_pkg::GPU_ERR_WRITE_BUSY_LSB);
    reg [31:0] reg_value;
    always @(*) begin
        case (reg_offset)
            gpu_pkg::GPU_REG_ID:                 reg_value = gpu_pkg::GPU_ID_VALUE;
            gpu_pkg::GPU_REG_VERSION:            reg_value = gpu_pkg::GPU_VERSION_VALUE;
            gpu_pkg::GPU_REG_CAPS:               reg_value = CAPS;
            gpu_pkg::GPU_REG_VTX_CAP:            reg_value = 32'(VTX_CAP);
            gpu_pkg::GPU_REG_TRI_CAP:            reg_value = 32'(TRI_CAP);
            gpu_pkg::GPU_REG_FB_SIZE:            reg_value = {16'(FB_HEIGHT),
                                                              16'(FB_WIDTH)};
            gpu_pkg::GPU_REG_STRIP_ROWS:         reg_value = 32'(STRIP_ROWS);
            gpu_pkg::GPU_REG_SCANOUT_UNDERFLOWS: reg_value = scanout_underflows;
            gpu_pkg::GPU_REG_CTRL:               reg_value = ctrl_value;
            gpu_pkg::GPU_REG_VTX_BASE:           reg_value = vtx_base;
            gpu_pkg::GPU_REG_VTX_COUNT:          reg_value = vtx_count;
            gpu_pkg::GPU_REG_TRI_BASE:           reg_value = tri_base;
            gpu_pkg::GPU_REG_TRI_COUNT:          reg_value = tri_count;
            gpu_pkg::GPU_REG_CLEAR_COLOR:        reg_value = {24'd0, clear_color};
            gpu_pkg::GPU_REG_FB_WRITE_MASK:      reg_value = (32'(fb_wmask[1]) << gpu_pkg::GPU_WMASK_HI_LSB)
                                                           | (32'(fb_wmask[0]) << gpu_pkg::GPU_WMASK_LO_LSB);
            gpu_pkg::GPU_REG_STRIP:              reg_value = strip;
            gpu_pkg::GPU_REG_DOORBELL:           reg_value = doorbell_tag;
            gpu_pkg::GPU_REG_RESET:              reg_value = reset_value_q;
            gpu_pkg::GPU_REG_STATUS:             reg_value = status_value;
            gpu_pkg::GPU_REG_DONE_SEQ:           reg_value = done_seq;
            gpu_pkg::GPU_REG_FRAME_COUNT:        reg_value = frame_count;
            gpu_pkg::GPU_REG_ERRORS:             reg_value = errors_value;
            gpu_pkg::GPU_REG_PERF_BUSY_CYCLES:   reg_value = perf.busy_cycles;
            gpu_pkg::GPU_REG_PERF_TRIS_IN:       reg_value = perf.tris_in;
            gpu_pkg::GPU_REG_PERF_TRIS_DRAWN:    reg_value = perf.tris_drawn;
            gpu_pkg::GPU_REG_PERF_TRIS_REJECTED: reg_value = perf.tris_rejected;
            gpu_pkg::GPU_REG_PERF_PIXELS:        reg_value = perf.pixels;
            gpu_pkg::GPU_REG_PERF_SAMPLES:       reg_value = perf.samples;
            gpu_pkg::GPU_REG_PERF_SPANS_WRITTEN: reg_value = perf.spans_written;
            gpu_pkg::GPU_REG_PERF_SPANS_VISITED: reg_value = perf.spans_visited;
            default:                             reg_value = 32'd0;
        endcase
    end

    always @(posedge clk) begin
        if (rst) begin
            bus_rvalid <= 1'b0;
            bus_rdata <= 32'd0;
        end else begin
            bus_rvalid <= bus_valid && !bus_write;
            bus_rdata <= (bus_valid && !bus_write && in_regs) ? reg_value : 32'd0;
        end
    end
endmodule

`default_nettype wire
