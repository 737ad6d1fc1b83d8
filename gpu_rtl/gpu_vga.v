// gpu_vga: 640x480@60 VGA scan-out of the front framebuffer through the palette.
//
// Contract: standard 800x525 timing (h: 640 visible, 16 front porch, 96 sync, 48 back porch;
// v: 480, 10, 2, 33; both syncs active low). One pixel every PIX_DIV clocks of clk — the pixel clock
// gpu_top gives it, 25 MHz on a board, or a faster clock in simulation; vga_pix_stb is high in the
// cycle whose clock edge updates the outputs, so a DAC clocked by clk with vga_pix_stb as enable (or a
// monitor model sampling when vga_pix_stb is high) sees each pixel exactly once. Each framebuffer
// pixel covers SCALE x SCALE screen pixels: 2x2 for the contract's 320x240, 1:1 for 640x480. RGB is 0 outside the visible area, where vga_de (data enable, for a
// DVI transmitter) is low. vblank_start pulses for one cycle when the last visible pixel has been
// read, the moment a buffer swap becomes invisible.
// Line schedule (for a frame read a line ahead from external memory, gpu_frame_dram): line_stb
// pulses with the strobe of each display line's first blank pixel; with it, and held until the
// next, show_row is the frame row the next display line shows (show_valid: it shows one) and
// fetch_row the row after that one (the first row at the last line of vertical blank). fb_rd_x and
// fb_rd_row_odd are the read's pixel and its row's parity, fb_rd_invalid (with fb_rd_data) says the
// row did not arrive in time: such a pixel is shown as SCANOUT_UNDERFLOW_RGB444, not its colour.
// Latency: the read pipeline (framebuffer, palette, output register) advances only on pixel strobes,
// so outputs trail the counters by two pixels with the syncs delayed to match, for any PIX_DIV >= 1.
`default_nettype none

module gpu_vga #(
    parameter integer PIX_DIV = 4,  // clocks per pixel: 1 with a 25 MHz pixel clock, 4 at 100 MHz
    parameter integer FB_WIDTH = gpu_pkg::GPU_FB_WIDTH,    // the frame: 640 / SCALE x 480 / SCALE
    parameter integer FB_HEIGHT = gpu_pkg::GPU_FB_HEIGHT,
    localparam integer FB_AW = $clog2(FB_WIDTH * FB_HEIGHT),
    localparam integer SCALE_SHIFT = $clog2(gpu_pkg::GPU_FB_MAX_WIDTH / FB_WIDTH)  // 1: 2x2; 0: 1:1
) (
    input  wire             clk,        // the pixel clock (gpu_top's clk_pix)
    input  wire             rst,        // synchronous to clk
    // framebuffer read port (front bank, one-cycle latency)
    output wire             fb_rd_en,
    output wire [FB_AW-1:0] fb_rd_addr,
    output wire [gpu_pkg::X_W-1:0] fb_rd_x,   // the same pixel as x and its row's parity
    output wire             fb_rd_row_odd,
    input  wire [7:0]       fb_rd_data,
    input  wire             fb_rd_invalid,  // with fb_rd_data: show the underflow colour
    // line schedule (a frame in external memory)
    output wire             line_stb,
    output reg              show_valid,
    output reg  [gpu_pkg::ROW_W-1:0] show_row,
    output reg              fetch_valid,
    output reg  [gpu_pkg::ROW_W-1:0] fetch_row,
    // palette read port (one-cycle latency)
    output wire             pal_rd_en,
    output wire [7:0]       pal_rd_addr,
    input  wire [11:0]      pal_rd_data,
    // frame timing for the swap (clk domain: gpu_top crosses it)
    output wire             vblank_start,
    // VGA connector
    output wire             vga_pix_stb,
    output reg              vga_de,
    output reg              vga_hsync_n,
    output reg              vga_vsync_n,
    output reg  [3:0]       vga_r,
    output reg  [3:0]       vga_g,
    output reg  [3:0]       vga_b
);
    localparam integer H_VISIBLE = 640, H_FRONT = 16, H_SYNC = 96, H_BACK = 48;
    localparam integer V_VISIBLE = 480, V_FRONT = 10, V_SYNC = 2, V_BACK = 33;
    localparam integer H_TOTAL = H_VISIBLE + H_FRONT + H_SYNC + H_BACK;  // 800
    localparam integer V_TOTAL = V_VISIBLE + V_FRONT + V_SYNC + V_BACK;  // 525
    localparam integer DIV_W = (PIX_DIV > 1) ? $clog2(PIX_DIV) : 1;

    reg [DIV_W-1:0] div_q;
    reg [9:0] h_q;
    reg [9:0] v_q;
    wire stb = (PIX_DIV == 1) ? 1'b1 : (div_q == DIV_W'(PIX_DIV - 1));

    always @(posedge clk) begin
        if (rst) begin
            div_q <= {DIV_W{1'b0}};
            h_q <= 10'd0;
            v_q <= 10'd0;
        end else begin
            div_q <= stb ? {DIV_W{1'b0}} : div_q + 1'b1;
            if (stb) begin
                if (h_q == 10'(H_TOTAL - 1)) begin
                    h_q <= 10'd0;
                    v_q <= (v_q == 10'(V_TOTAL - 1)) ? 10'd0 : v_q + 10'd1;
                end else begin
                    h_q <= h_q + 10'd1;
                end
            end
        end
    end

    // Stage 0: position -> framebuffer address y * FB_WIDTH + x, by shifts and adds of the set bits of
    // the constant FB_WIDTH (two for the contract's width): no multiplier for a constant.
    function automatic [FB_AW-1:0] times_fb_w(input [gpu_pkg::ROW_W-1:0] y);
        integer b;
        begin
            times_fb_w = {FB_AW{1'b0}};
            for (b = 0; b < FB_AW; b = b + 1) begin
                if (((FB_WIDTH >> b) & 1) != 0) begin
                    times_fb_w = times_fb_w + (FB_AW'(y) << b);
                end
            end
        end
    endfunction
    wire visible = (h_q < 10'(H_VISIBLE)) && (v_q < 10'(V_VISIBLE));
    wire hsync = (h_q >= 10'(H_VISIBLE + H_FRONT)) && (h_q < 10'(H_VISIBLE + H_FRONT + H_SYNC));
    wire vsync = (v_q >= 10'(V_VISIBLE + V_FRONT)) && (v_q < 10'(V_VISIBLE + V_FRONT + V_SYNC));
    wire [gpu_pkg::X_W-1:0] fb_x = gpu_pkg::X_W'(h_q >> SCALE_SHIFT);
    wire [gpu_pkg::ROW_W-1:0] fb_y = gpu_pkg::ROW_W'(v_q >> SCALE_SHIFT);
    assign fb_rd_en   = stb;
    assign fb_rd_addr = times_fb_w(fb_y) + FB_AW'(fb_x);
    assign fb_rd_x = fb_x;
    assign fb_rd_row_odd = fb_y[0];

    // The line schedule: at the first blank pixel of line v, the rows of line v + 1 and after.
    wire [9:0] next_line = (v_q == 10'(V_TOTAL - 1)) ? 10'd0 : v_q + 10'd1;
    wire [gpu_pkg::ROW_W-1:0] next_row = gpu_pkg::ROW_W'(next_line >> SCALE_SHIFT);
    assign line_stb = stb && h_q == 10'(H_VISIBLE);
    always @(posedge clk) begin
        if (rst) begin
            show_valid <= 1'b0;
            show_row <= {gpu_pkg::ROW_W{1'b0}};
            fetch_valid <= 1'b0;
            fetch_row <= {gpu_pkg::ROW_W{1'b0}};
        end else if (line_stb) begin
            show_valid <= next_line < 10'(V_VISIBLE);
            show_row <= next_row;
            if (next_line == 10'(V_TOTAL - 1)) begin
                fetch_valid <= 1'b1;
                fetch_row <= {gpu_pkg::ROW_W{1'b0}};
            end else begin
                fetch_valid <= next_line < 10'(V_VISIBLE) && next_row + 1'b1 < gpu_pkg::ROW_W'(FB_HEIGHT);
                fetch_row <= next_row + 1'b1;
            end
        end
    end

    // Stage 1: framebuffer data -> palette address. Stage 2: palette data -> output register.
    assign pal_rd_en   = stb;
    assign pal_rd_addr = fb_rd_data;

    reg [1:0] visible_pipe_q, hsync_pipe_q, vsync_pipe_q;
    reg invalid_q;  // fb_rd_invalid, one strobe on: with pal_rd_data
    wire [11:0] shown = invalid_q ? 12'(gpu_pkg::GPU_SCANOUT_UNDERFLOW_RGB444) : pal_rd_data;
    always @(posedge clk) begin
        if (rst) begin
            visible_pipe_q <= 2'b00;
            hsync_pipe_q <= 2'b00;
            vsync_pipe_q <= 2'b00;
            invalid_q <= 1'b0;
            vga_de <= 1'b0;
            vga_hsync_n <= 1'b1;
            vga_vsync_n <= 1'b1;
            vga_r <= 4'd0;
            vga_g <= 4'd0;
            vga_b <= 4'd0;
        end else if (stb) begin
            visible_pipe_q <= {visible_pipe_q[0], visible};
            hsync_pipe_q <= {hsync_pipe_q[0], hsync};
            vsync_pipe_q <= {vsync_pipe_q[0], vsync};
            invalid_q <= fb_rd_invalid;
            // pal_rd_data belongs to the pixel two strobes back, as do index [1] of the pipes and
            // invalid_q.
            vga_de <= visible_pipe_q[1];
            vga_hsync_n <= ~hsync_pipe_q[1];
            vga_vsync_n <= ~vsync_pipe_q[1];
            vga_r <= visible_pipe_q[1] ? shown[11:8] : 4'd0;
            vga_g <= visible_pipe_q[1] ? shown[7:4] : 4'd0;
            vga_b <= visible_pipe_q[1] ? shown[3:0] : 4'd0;
        end
    end

    assign vga_pix_stb  = stb;
    assign vblank_start = stb && (h_q == 10'(H_TOTAL - 1)) && (v_q == 10'(V_VISIBLE - 1));
endmodule

`default_nettype wire
