// Generator of the squared-quadratic device (ours), as modules/squared/a_gen_squared.h: from RG1's
// n, the leading-zero count z (the squaring stage does k = 9 - z squarings) and the coefficient a
// of the quadratic at n' = 1 + f,
//     a = f + f (1 - f - 2^-9) / 2^(k + 2)        (formats/squared_formats.h)
// with n = 2^k (1 + f). No ROM and no constant multiplier:
//   LZC   z = leading zeros of n                           10 wires -> 0..10
//   BSH1  n << z = 1.f (Q1.9); its 9 low wires are f (Q0.9)
//   INV_F ~f = 1 - f - 2^-9
//   MUL_E e = f x ~f (Q0.18, exact)
//   BSH2  e << z on 27 wires, read as Q0.29 = e / 2^(k+2); 17 low wires open -> bend, Q0.12
//   ADD_A a = (f aligned by 3 wires) + bend, Q0.12
// Only instantiates and wires; every width from shading_formats.vh.
`include "shading_formats.vh"
module a_gen_squared (
    input  wire [`SQUARED_N_W-1:0] n,
    output wire [`SQUARED_A_W-1:0] a,
    output wire [`SQUARED_Z_W-1:0] z
);
    // Nets, by what they carry.
    wire [`SQUARED_MANT_W-1:0] bsh1_mant;
    wire [`SQUARED_F_W-1:0] f_frac, inv_f_not_f;
    wire [`SQUARED_E_W-1:0] mul_e_f_x_not_f;
    wire [`SQUARED_ESH_W-1:0] bsh2_e_shifted;
    wire [`SQUARED_BEND_W-1:0] bend;
    wire [`SQUARED_A_W-1:0] f_aligned;
    wire add_a_carry0;

    lzc #(.W(`SQUARED_N_W), .ZW(`SQUARED_Z_W)) lzc_n (.x(n), .z(z));
    barrel_shifter #(.WIN(`SQUARED_N_W), .WOUT(`SQUARED_MANT_W), .WS(`SQUARED_Z_W)) bsh1 (
        .x(n), .s(z), .y(bsh1_mant));
    // the 9 low wires
    shifter #(.WIN(`SQUARED_MANT_W), .WOUT(`SQUARED_F_W), .SHIFT(0)) f_wires (.x(bsh1_mant), .y(f_frac));
    inverter_bank #(.WIN(`SQUARED_F_W)) inv_f (.x(f_frac), .y(inv_f_not_f));
    // 0.9 x 0.9 -> 0.18, exact
    mul #(.WA(`SQUARED_F_W), .WB(`SQUARED_F_W), .WP(`SQUARED_E_W)) mul_e (
        .a(f_frac), .b(inv_f_not_f), .p(mul_e_f_x_not_f));
    barrel_shifter #(.WIN(`SQUARED_E_W), .WOUT(`SQUARED_ESH_W), .WS(`SQUARED_Z_W)) bsh2 (
        .x(mul_e_f_x_not_f), .s(z), .y(bsh2_e_shifted));
    // 17 low wires open (floor)
    shifter #(.WIN(`SQUARED_ESH_W), .WOUT(`SQUARED_BEND_W), .SHIFT(`SQUARED_BEND_FRAC - `SQUARED_ESH_FRAC)) bend_wires (
        .x(bsh2_e_shifted), .y(bend));
    // Q0.9 onto Q0.12
    shifter #(.WIN(`SQUARED_F_W), .WOUT(`SQUARED_A_W), .SHIFT(`SQUARED_A_FRAC - `SQUARED_F_FRAC)) f_align (
        .x(f_frac), .y(f_aligned));
    constant #(.W(1), .VALUE(1'b0)) add_a_cin (.y(add_a_carry0));
    // 0.12 + 0.12 -> 0.12
    adder #(.WA(`SQUARED_A_W), .WB(`SQUARED_BEND_W), .WS(`SQUARED_A_W)) add_a (
        .a(f_aligned), .b(bend), .cin(add_a_carry0), .s(a));
endmodule
