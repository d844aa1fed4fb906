// Leading-zero counter (a priority encoder), as modules/blocks/lzc.h: z = the number of 0 wires
// above the highest 1 of the W-wire bus x, W for an all-zero bus. The squared-quadratic device
// normalises n with it (n = 2^(W-1-z) * 1.f). ZW = the z bus's width, select_width(W + 1).
module lzc #(
    parameter W = 8,
    parameter ZW = 4
) (
    input  wire [W-1:0]  x,
    output wire [ZW-1:0] z
);
    // Scanned from the low wire up, so the highest 1 decides last.
    integer i;
    reg [31:0] count;
    always @* begin
        count = W;
        for (i = 0; i < W; i = i + 1)
            if (x[i]) count = W - 1 - i;
    end
    assign z = count[ZW-1:0];
    wire unused_ok = &{1'b0, count[31:ZW], 1'b0};  // 0..W fits ZW wires
endmodule
