// Saturating stage on an unsigned bus: y = x clamped to HI when SATURATE = 1 (a comparator and a
// multiplexer), y = x when SATURATE = 0 (wires). The square-and-multiply baseline clamps the
// loaded cos to 1.0 with it, as the squared-quadratic device's ADD11 clamps its sum.
module saturator #(
    parameter W = 8,
    parameter SATURATE = 1,
    parameter [W-1:0] HI = {W{1'b1}}
) (
    input  wire [W-1:0] x,
    output wire [W-1:0] y
);
    generate
        if (SATURATE != 0) begin : g_clamp
            assign y = x > HI ? HI : x;
        end else begin : g_wires
            assign y = x;
        end
    endgenerate
endmodule
