// A small design for synth/sdf_slack.py's test (tests/boards/sdf_slack.sh): a DSP product into a
// carry chain between flops, and a second flop stage, so that the worst path crosses a MULT18X18D,
// a CCU2C chain and routing.
`default_nettype none

module adder_mul (
    input  wire       clk,
    input  wire [7:0] a,
    output reg  [7:0] q
);
    reg [7:0] r;
    always @(posedge clk) begin
        r <= a;
        q <= r * 8'd5 + r;
    end
endmodule

`default_nettype wire
