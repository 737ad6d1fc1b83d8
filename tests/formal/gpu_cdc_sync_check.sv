// gpu_cdc_sync_check: formal properties of gpu_cdc_sync (gpu_rtl/gpu_cdc_sync.v), from its ports
// (tests/formal/gpu_cdc_sync.sby; make formal).
//
// Environment: in is free at every clock (asynchronous to clk, or from another domain; the formal
// model cannot show metastability, only the logic around it). Properties (asserted, proved by
// induction): for the first STAGES clocks out is RESET_VALUE, the value held from configuration;
// after that, out is exactly in as it was STAGES clocks earlier, every bit, so nothing reaches out
// through fewer than STAGES flops and nothing is lost on the way.
`default_nettype none

module gpu_cdc_sync_check #(
    parameter integer STAGES = 2
) (
    input wire       clk,
    input wire [2:0] in
);
    localparam [2:0] RESET_VALUE = 3'b101;  // not all zeros: the initial value is the parameter's

    wire [2:0] out;
    gpu_cdc_sync #(.WIDTH(3), .STAGES(STAGES), .RESET_VALUE(RESET_VALUE)) dut (
        .clk(clk), .in(in), .out(out)
    );

    reg [3:0] clocks = 4'd0;  // clock edges so far, saturating
    always @(posedge clk) if (clocks != 4'd15) clocks <= clocks + 4'd1;

    always @(posedge clk) begin
        if (clocks < STAGES) assert(out == RESET_VALUE);
        else assert(out == $past(in, STAGES));
    end

    always @(posedge clk) cover(clocks > STAGES && out != RESET_VALUE && out != $past(out));
endmodule

`default_nettype wire
