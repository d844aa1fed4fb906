// A specular-colour device of UA 60553, Fig. 1, as modules/specular/specular_device.h: the
// datapath UA 60553 shares with its prototype UA 22802 (registers 1-5, the squaring multiplier 7,
// inverter bank 8, subtracting adder 9 with carry node 28 = 1, the a-multiplier 10, adder 11 with
// carry node 30 = 0, the colour multipliers 12-14, the wire from strobe 17 to output 29) and one
// generator of `a` (n -> a), chosen by AGEN as the SystemC template argument is:
//   AGEN = 0  a_gen_linear (rtl/ua60553/)  UA 60553: MUL6 + ADD15, formula 10
//   AGEN = 1  a_gen_rom    (rtl/ua22802/)  UA 22802: the ROM holding a(n)
//   AGEN = 2  a_gen_tuned  (rtl/tuned/)    the tuned line: MUL6 + ADD15 + OR + key
// SATURATE = 1 (the SystemC default, overflow_mode::saturate) clamps ADD11 to [0, 1.0]; 0 is
// the patent-faithful wrap. Only instantiates and wires; every width from shading_formats.vh.
// The generator sits in the generate block `generator` (Verilog scopes an if-generate), so its
// path is generator.a_gen where the SystemC model has a_gen.
`include "shading_formats.vh"
module specular_device #(
    parameter AGEN = 0,
    parameter SATURATE = 1
) (
    // Device pins, numbered as in UA 60553, Fig. 1.
    input  wire ctl15, ctl17, ctl20, ctl22, ctl24,
    input  wire [`UA60553_N_W-1:0] in16_n,
    input  wire [`SPEC_COS_W-1:0]  in18_cos,
    input  wire [`SPEC_KSI_W-1:0]  in19_ksi_r, in21_ksi_g, in23_ksi_b,
    output wire [`SPEC_OUT_W-1:0]  out25_r, out26_g, out27_b,
    output wire out29_valid
);
    // The generator's `a` bus: Q10.6 from the ROM, Q11.7 from MUL6 + ADD15.
    localparam WA = AGEN == 1 ? `UA22802_A_W : `UA60553_A_W;
    localparam MUL10_DROP = AGEN == 1 ? `UA22802_MUL10_DROP : `UA60553_MUL10_DROP;

    // Nets, named by the block that drives them and what they carry.
    wire [`UA60553_N_W-1:0] rg1_n;
    wire [`SPEC_COS_W-1:0] rg2_cos;
    wire [`SPEC_KSI_W-1:0] rg3_ksi_r, rg4_ksi_g, rg5_ksi_b;
    wire [WA-1:0] a_coef;
    wire [`SPEC_COS2_W-1:0] mul7_cos2;
    wire [`SPEC_INV8_W-1:0] inv8_not_cos;
    wire node28_carry1, node30_carry0;
    wire [`SPEC_D_W-1:0] add9_cos2_minus_cos;
    wire [`SPEC_MUL10_W-1:0] mul10_a_x_diff;
    wire [`SPEC_BRDF_W-1:0] add11_brdf;

    reg_block #(.W(`UA60553_N_W)) rg1 (.ctl(ctl15), .d(in16_n), .q(rg1_n));
    reg_block #(.W(`SPEC_COS_W)) rg2 (.ctl(ctl17), .d(in18_cos), .q(rg2_cos));
    reg_block #(.W(`SPEC_KSI_W)) rg3 (.ctl(ctl20), .d(in19_ksi_r), .q(rg3_ksi_r));
    reg_block #(.W(`SPEC_KSI_W)) rg4 (.ctl(ctl22), .d(in21_ksi_g), .q(rg4_ksi_g));
    reg_block #(.W(`SPEC_KSI_W)) rg5 (.ctl(ctl24), .d(in23_ksi_b), .q(rg5_ksi_b));

    generate
        if (AGEN == 1) begin : generator
            a_gen_rom a_gen (.n(rg1_n), .a(a_coef));
        end else if (AGEN == 2) begin : generator
            a_gen_tuned a_gen (.n(rg1_n), .a(a_coef));
        end else begin : generator
            a_gen_linear a_gen (.n(rg1_n), .a(a_coef));
        end
    endgenerate

    // Q1.15^2 -> Q2.30
    mul #(.WA(`SPEC_COS_W), .WB(`SPEC_COS_W), .WP(`SPEC_COS2_W)) mul7 (
        .a(rg2_cos), .b(rg2_cos), .p(mul7_cos2));
    // ~(cos << 15)
    inverter_bank #(.WIN(`SPEC_COS_W), .WOUT(`SPEC_INV8_W), .ALIGN(`SPEC_INV8_ALIGN)) inv8 (
        .x(rg2_cos), .y(inv8_not_cos));
    constant #(.W(1), .VALUE(1'b1)) node28 (.y(node28_carry1));
    constant #(.W(1), .VALUE(1'b0)) node30 (.y(node30_carry0));
    // cos^2 + ~cos + 1 = cos^2 - cos
    adder #(.WA(`SPEC_COS2_W), .WB(`SPEC_INV8_W), .WS(`SPEC_D_W)) add9 (
        .a(mul7_cos2), .b(inv8_not_cos), .cin(node28_carry1), .s(add9_cos2_minus_cos));
    // a x Q2.30s -> Q12.15s floor
    mul #(.WA(WA), .WB(`SPEC_D_W), .WP(`SPEC_MUL10_W), .DROP(MUL10_DROP), .BSIGNED(1)) mul10 (
        .a(a_coef), .b(add9_cos2_minus_cos), .p(mul10_a_x_diff));
    // Q12.15s + Q1.15 -> Q1.15, wrapped or saturated to [0, 1.0]
    adder #(.WA(`SPEC_MUL10_W), .WB(`SPEC_COS_W), .WS(`SPEC_BRDF_W), .ASIGNED(1),
            .SATURATE(SATURATE), .SAT_LO(`SPEC_BRDF_SAT_LO), .SAT_HI(`SPEC_BRDF_SAT_HI)) add11 (
        .a(mul10_a_x_diff), .b(rg2_cos), .cin(node30_carry0), .s(add11_brdf));
    // Q1.15 x 8.0 -> Q9.8 floor
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul12 (
        .a(add11_brdf), .b(rg3_ksi_r), .p(out25_r));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul13 (
        .a(add11_brdf), .b(rg4_ksi_g), .p(out26_g));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul14 (
        .a(add11_brdf), .b(rg5_ksi_b), .p(out27_b));
    wire_block out29 (.x(ctl17), .y(out29_valid));  // Fig. 3: output 29 is RG2's strobe itself
endmodule
