// Adder block with a carry input, as modules/blocks/adder.h: s = a + b + cin. Operands are zero-
// or sign-extended (ASIGNED/BSIGNED = 1) and summed exactly; the WS-bit output then carries the
// low WS bits of the sum (SATURATE = 0, a real two's-complement adder) or the sum clamped to
// [SAT_LO, SAT_HI] (SATURATE = 1, a saturating output stage). WA, WB <= 61.
module adder #(
    parameter WA = 16,
    parameter WB = 16,
    parameter WS = 16,
    parameter ASIGNED = 0,
    parameter BSIGNED = 0,
    parameter SATURATE = 0,
    parameter signed [63:0] SAT_LO = 64'sd0,
    parameter signed [63:0] SAT_HI = (64'sd1 <<< WS) - 64'sd1
) (
    input  wire [WA-1:0] a,
    input  wire [WB-1:0] b,
    input  wire          cin,
    output wire [WS-1:0] s
);
    localparam WX = (WA > WB ? WA : WB) + 2;  // the exact sum, sign included
    wire ea = (ASIGNED != 0) & a[WA-1];
    wire eb = (BSIGNED != 0) & b[WB-1];
    wire [WX-1:0] ax = {{(WX-WA){ea}}, a};
    wire [WX-1:0] bx = {{(WX-WB){eb}}, b};
    wire [WX-1:0] sum = ax + bx + {{(WX-1){1'b0}}, cin};
    wire signed [63:0] sum64 = {{(64-WX){sum[WX-1]}}, sum};
    /* verilator lint_off UNUSEDSIGNAL */
    // wrap: the high wires of the exact sum stay unconnected; saturate: only the low WS bits of
    // the clamped value leave the block.
    wire signed [63:0] out = (SATURATE == 0) ? sum64
                           : (sum64 < SAT_LO) ? SAT_LO
                           : (sum64 > SAT_HI) ? SAT_HI : sum64;
    /* verilator lint_on UNUSEDSIGNAL */
    assign s = out[WS-1:0];
endmodule
