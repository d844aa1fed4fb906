// A wire between two nets, as modules/blocks/wire.h (`wire` is a Verilog keyword): y follows x.
// Kept as a block so the device keeps the patent's output 29 as a named instance.
module wire_block #(
    parameter W = 1
) (
    input  wire [W-1:0] x,
    output wire [W-1:0] y
);
    assign y = x;
endmodule
