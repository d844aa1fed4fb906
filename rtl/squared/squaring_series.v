// The series variant of the squared-quadratic device's squaring stage (ours, for the cost
// comparison; no SystemC block): up to 9 squarers in series, each followed by a bypass
// multiplexer, so the stage is combinational and the device keeps UA 60553's pins and Fig. 3
// timing exactly (no clock), at the price of a path through 9 multipliers.
//   SEL_i   le_const: z <= 9 - i, i.e. k = 9 - z >= i (stage i squares)
//   MUL_i   s(i-1) x s(i-1): Q1.18^2 = Q2.36, 18 low wires open (floor), the 19 above kept
//   MX_i    s(i) = SEL_i ? MUL_i : s(i-1)   (bypass)
// s(0) is ADD11, s(9) the result: the same k squares of the same word as the iterative stage,
// so the same golden model (golden_squared) holds.
`include "shading_formats.vh"
module squaring_series (
    input  wire [`SQUARED_Z_W-1:0] z,
    input  wire [`SQUARED_Q_W-1:0] q,     // ADD11
    output wire [`SQUARED_Q_W-1:0] brdf   // after k squares
);
    localparam WQ = `SQUARED_Q_W;
    localparam NS = `SQUARED_MAX_SQUARINGS;

    wire [WQ-1:0] s [0:NS] /*verilator split_var*/;  // s[i]: after stage i
    assign s[0] = q;
    genvar i;
    generate
        for (i = 1; i <= NS; i = i + 1) begin : stage
            wire sel;
            wire [WQ-1:0] square;
            le_const #(.W(`SQUARED_Z_W), .K(`SQUARED_Z_FULL - i)) sel_k (.x(z), .y(sel));
            // Q1.18 x Q1.18 -> Q2.36, floor to Q1.18
            mul #(.WA(WQ), .WB(WQ), .WP(WQ), .DROP(`SQUARED_Q_FRAC)) mul_sq (
                .a(s[i-1]), .b(s[i-1]), .p(square));
            mux #(.W(WQ), .N(2), .SW(1)) mx_sq (.in({square, s[i-1]}), .sel(sel), .y(s[i]));
        end
    endgenerate
    assign brdf = s[NS];
endmodule
