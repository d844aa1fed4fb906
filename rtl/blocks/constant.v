// Hardwired constant, as modules/blocks/constant.h: W wires tied to logic 1 or 0.
module constant #(
    parameter W = 1,
    parameter [W-1:0] VALUE = {W{1'b0}}
) (
    output wire [W-1:0] y
);
    assign y = VALUE;
endmodule
