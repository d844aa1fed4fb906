// The right-to-left square-and-multiply design (ours, for comparison; golden model
// golden_sqmul_r2l in src/floor/arith/sqmul_arith.*): cos^n over the bits of n, least significant
// first, with a squarer and a multiplier written in the same clock, on the squared-quadratic
// device's pins (UA 60553's plus clk) and handshake (output 29 = strobe 17 AND done).
//   RG1..RG5     UA 60553's registers, written on the falling edges of strobes 15, 17, 20, 22, 24
//   cos_align    RG2's Q1.15 onto the P word;  sat_cos: clamped to 1.0 (SATURATE = 1) or not (0)
//   stage        MUL_X, MUL_P, MX_X, MX_P, RG_X, RG_P and the controller (sqmul_r2l_stage.v,
//                sqmul_r2l_ctrl.v), which walks RG1's bits itself (no leading-zero count)
//   MUL12..14    UA 60553's colour multipliers on RG_P's 16 high wires
//   out29        strobe 17 AND the stage's done
// Clocks per sample: floor(log2 n) + 5 rising edges from strobe 17's fall to done (two for the
// synchroniser sync17, the taking edge, one per bit of n up to its leading one, the done edge):
// 5..14 for n in 1..1000.
// Only instantiates and wires; every width from shading_formats.vh.
`include "shading_formats.vh"
module sqmul_r2l_device #(
    parameter SATURATE = 1
) (
    // Device pins, numbered as in UA 60553, Fig. 1, and the stage's clock.
    input  wire clk,
    input  wire ctl15, ctl17, ctl20, ctl22, ctl24,
    input  wire [`SQUARED_N_W-1:0] in16_n,
    input  wire [`SPEC_COS_W-1:0]  in18_cos,
    input  wire [`SPEC_KSI_W-1:0]  in19_ksi_r, in21_ksi_g, in23_ksi_b,
    output wire [`SPEC_OUT_W-1:0]  out25_r, out26_g, out27_b,
    output wire out29_valid
);
    localparam WP = `SQMUL_P_W;

    // Nets, named by the block that drives them and what they carry.
    wire [`SQUARED_N_W-1:0] rg1_n;
    wire [`SPEC_COS_W-1:0] rg2_cos;
    wire [`SPEC_KSI_W-1:0] rg3_ksi_r, rg4_ksi_g, rg5_ksi_b;
    wire [WP-1:0] cos_aligned, cos_p;
    wire [WP-1:0] p_brdf;  // RG_P: cos^n
    wire [`SPEC_BRDF_W-1:0] brdf_q15;
    wire p_done;

    reg_block #(.W(`SQUARED_N_W)) rg1 (.ctl(ctl15), .d(in16_n), .q(rg1_n));
    reg_block #(.W(`SPEC_COS_W)) rg2 (.ctl(ctl17), .d(in18_cos), .q(rg2_cos));
    reg_block #(.W(`SPEC_KSI_W)) rg3 (.ctl(ctl20), .d(in19_ksi_r), .q(rg3_ksi_r));
    reg_block #(.W(`SPEC_KSI_W)) rg4 (.ctl(ctl22), .d(in21_ksi_g), .q(rg4_ksi_g));
    reg_block #(.W(`SPEC_KSI_W)) rg5 (.ctl(ctl24), .d(in23_ksi_b), .q(rg5_ksi_b));

    // Q1.15 onto the P word
    shifter #(.WIN(`SPEC_COS_W), .WOUT(WP), .SHIFT(`SQMUL_COS_ALIGN)) cos_align (.x(rg2_cos), .y(cos_aligned));
    saturator #(.W(WP), .SATURATE(SATURATE), .HI(`SQMUL_P_ONE)) sat_cos (.x(cos_aligned), .y(cos_p));
    sqmul_r2l_stage stage (.clk(clk), .ctl17(ctl17), .n(rg1_n), .c(cos_p), .brdf(p_brdf), .done(p_done));
    // the stage's 16 high wires, Q1.15 (the low wires open: floor)
    shifter #(.WIN(WP), .WOUT(`SPEC_BRDF_W), .SHIFT(`SPEC_BRDF_FRAC - `SQMUL_P_FRAC)) brdf_wires (
        .x(p_brdf), .y(brdf_q15));
    // Q1.15 x 8.0 -> Q9.8 floor
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul12 (
        .a(brdf_q15), .b(rg3_ksi_r), .p(out25_r));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul13 (
        .a(brdf_q15), .b(rg4_ksi_g), .p(out26_g));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul14 (
        .a(brdf_q15), .b(rg5_ksi_b), .p(out27_b));
    and_gate out29 (.a(ctl17), .b(p_done), .y(out29_valid));
endmodule
