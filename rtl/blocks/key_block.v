// Key block BK of the interpolation paper, Fig. 4, as modules/blocks/key_block.h: one AND gate per wire, so
// the block passes x when `pass` is 1 and forces every wire to 0 when it is 0.
module key_block #(
    parameter W = 8
) (
    input  wire [W-1:0] x,
    input  wire         pass,
    output wire [W-1:0] y
);
    assign y = x & {W{pass}};
endmodule
