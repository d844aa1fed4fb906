// The tuned generator of `a`, as modules/tuned/a_gen_tuned.h: the patent's MUL6 and ADD15 on the
// same buses, node 32 a signed Q1.7 constant (default the search's minimax: a = 0.7890625 n -
// 0.625), and n < 2 forces a = 0 (an OR gate over n's wires 9..1 opens the key block on a).
`include "shading_formats.vh"
module a_gen_tuned #(
    parameter [`UA60553_K_W-1:0] K31 = `TUNED_K31,
    parameter [`TUNED_K32S_W-1:0] K32 = `TUNED_K32  // node 32's wires: two's complement
) (
    input  wire [`UA60553_N_W-1:0] n,
    output wire [`UA60553_A_W-1:0] a
);
    wire [`UA60553_K_W-1:0] node31_k;
    wire [`TUNED_K32S_W-1:0] node32_k;
    wire [`UA60553_MUL6_W-1:0] mul6_n_x_k;
    wire [`UA60553_A_W-1:0] add15_a_linear;
    wire add15_carry0, or_n_ge2;

    constant #(.W(`UA60553_K_W), .VALUE(K31)) node31 (.y(node31_k));
    constant #(.W(`TUNED_K32S_W), .VALUE(K32)) node32 (.y(node32_k));
    constant #(.W(1), .VALUE(1'b0)) add15_cin (.y(add15_carry0));
    // 10.0 x 0.7 -> 10.7
    mul #(.WA(`UA60553_N_W), .WB(`UA60553_K_W), .WP(`UA60553_MUL6_W)) mul6 (
        .a(n), .b(node31_k), .p(mul6_n_x_k));
    // 10.7 + 1.7 signed -> 11.7, wraps
    adder #(.WA(`UA60553_MUL6_W), .WB(`TUNED_K32S_W), .WS(`UA60553_A_W), .BSIGNED(1)) add15 (
        .a(mul6_n_x_k), .b(node32_k), .cin(add15_carry0), .s(add15_a_linear));
    reduce_or #(.W(`UA60553_N_W), .LO(`TUNED_OR_LO)) or_n (.x(n), .y(or_n_ge2));  // n >= 2
    key_block #(.W(`UA60553_A_W)) key_a (.x(add15_a_linear), .pass(or_n_ge2), .y(a));
endmodule
