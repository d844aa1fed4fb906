// UA 60553's ROM-free generator of `a` (Fig. 1, formula 10), as modules/ua60553/a_gen_linear.h:
// a = n * K31 + K32, MUL6 with the hardwired constant at node 31 and ADD15 with the one at node
// 32 (default the patent's 0.1100101b and 0.1b), ADD15's carry tied to 0 by the unit itself.
`include "shading_formats.vh"
module a_gen_linear #(
    parameter [`UA60553_K_W-1:0] K31 = `UA60553_K31,
    parameter [`UA60553_K_W-1:0] K32 = `UA60553_K32
) (
    input  wire [`UA60553_N_W-1:0] n,
    output wire [`UA60553_A_W-1:0] a
);
    wire [`UA60553_K_W-1:0] node31_k, node32_k;
    wire [`UA60553_MUL6_W-1:0] mul6_n_x_k;
    wire add15_carry0;

    constant #(.W(`UA60553_K_W), .VALUE(K31)) node31 (.y(node31_k));
    constant #(.W(`UA60553_K_W), .VALUE(K32)) node32 (.y(node32_k));
    constant #(.W(1), .VALUE(1'b0)) add15_cin (.y(add15_carry0));
    // 10.0 x 0.7 -> 10.7
    mul #(.WA(`UA60553_N_W), .WB(`UA60553_K_W), .WP(`UA60553_MUL6_W)) mul6 (
        .a(n), .b(node31_k), .p(mul6_n_x_k));
    // 10.7 + 0.7 -> 11.7
    adder #(.WA(`UA60553_MUL6_W), .WB(`UA60553_K_W), .WS(`UA60553_A_W)) add15 (
        .a(mul6_n_x_k), .b(node32_k), .cin(add15_carry0), .s(a));
endmodule
