// Two-input AND gate on single wires, as modules/blocks/and_gate.h. The squared-quadratic
// device's output 29 is strobe 17 gated by its squaring stage's done flag: y = a AND b.
module and_gate (
    input  wire a,
    input  wire b,
    output wire y
);
    assign y = a & b;
endmodule
