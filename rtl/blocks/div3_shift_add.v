// Division by 3 as the interpolation paper, Fig. 2 (modules/blocks/div3_shift_add.h): x/2 - x/8 - x/32 - x/128
// = 43x/128 on a signed WIN-bit bus, onto a signed WOUT-bit bus with ALIGN more fraction bits
// (ALIGN >= 7: no wire is dropped, the result is exactly 43x/128). One shift-and-add network.
module div3_shift_add #(
    parameter WIN = 8,
    parameter WOUT = 8,
    parameter ALIGN = 8
) (
    input  wire [WIN-1:0]  x,
    output wire [WOUT-1:0] y
);
    // Terms (input 0): +x << (ALIGN-1), -x << (ALIGN-3), -x << (ALIGN-5), -x << (ALIGN-7).
    localparam [15:0] T0 = (ALIGN - 1) & 255;
    localparam [15:0] T1 = 16'h0100 | ((ALIGN - 3) & 255);
    localparam [15:0] T2 = 16'h0100 | ((ALIGN - 5) & 255);
    localparam [15:0] T3 = 16'h0100 | ((ALIGN - 7) & 255);

    shift_add_network #(.WIN(WIN), .W(WOUT), .IN_SIGNED(1), .NIN(1), .NT(4), .SLOTS(4), .TERMS({T3, T2, T1, T0})) net (
        .in(x), .y(y));
endmodule
