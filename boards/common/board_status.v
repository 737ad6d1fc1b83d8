// board_status: the two status LEDs every board top shows besides the SoC's own — a heartbeat
// (the system clock runs) and a frame blinker (the GPU swaps buffers).
//
// Contract: heartbeat toggles every 2^(clog2(SYS_HZ) - 1) clk_sys cycles (about 0.7 s on, 0.7 s off
// at 50 MHz); frames toggles every 2^FRAME_BIT frame_swapped pulses (16: about 2 Hz at 60 fps). No
// reset: both count from their power-on value 0.
`default_nettype none

module board_status #(
    parameter integer SYS_HZ = 50000000,   // clk_sys's frequency
    parameter integer FRAME_BIT = 4,       // frames toggles every 2^FRAME_BIT swaps
    localparam integer HEARTBEAT_BIT = $clog2(SYS_HZ) - 1
) (
    input  wire clk_sys,
    input  wire frame_swapped,   // one clk_sys cycle per buffer swap (soc_top's gpu_frame_swapped)
    output wire heartbeat,
    output wire frames
);
    reg [HEARTBEAT_BIT:0] heartbeat_q = '0;
    reg [FRAME_BIT:0] frames_q = '0;
    always @(posedge clk_sys) begin
        heartbeat_q <= heartbeat_q + 1'b1;
        if (frame_swapped) frames_q <= frames_q + 1'b1;
    end
    assign heartbeat = heartbeat_q[HEARTBEAT_BIT];
    assign frames = frames_q[FRAME_BIT];
endmodule

`default_nettype wire
