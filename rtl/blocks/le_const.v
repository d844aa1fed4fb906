// Comparator with a hardwired constant: y = 1 when the unsigned W-wire bus x is at most K (a few
// gates). The series squaring stage of the squared-quadratic device decodes z with it: stage i
// squares when z <= 9 - i, i.e. when k = 9 - z >= i.
module le_const #(
    parameter W = 4,
    parameter integer K = 0  // 0 <= K < 2^W
) (
    input  wire [W-1:0] x,
    output wire         y
);
    localparam [W-1:0] KW = K[W-1:0];
    assign y = x <= KW;
endmodule
