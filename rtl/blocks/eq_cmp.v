// Equality comparator on two W-wire buses, as modules/blocks/eq_cmp.h: y = 1 where every wire of a
// equals its wire of b (an XNOR per wire and an AND tree). The shading pipeline's sample stage uses
// it to see that a job's first sample point is the point whose colour it formed last (eq_nh, eq_nl).
module eq_cmp #(
    parameter W = 8
) (
    input  wire [W-1:0] a,
    input  wire [W-1:0] b,
    output wire         y
);
    assign y = &(a ~^ b);
endmodule
