// The square-and-multiply device (ours; golden model src/floor/arith/sqmul_arith.*, SystemC twin
// modules/sqmul/sqmul_device.h, instance for instance):
// cos^n over the bits of n with one Q1.18 multiplier, on the squared-quadratic device's pins
// (UA 60553's plus clk) and handshake (output 29 = strobe 17 AND done).
//   RG1..RG5     UA 60553's registers, written on the falling edges of strobes 15, 17, 20, 22, 24
//   LZC, BSH1    z = leading zeros of n, n << z: its 9 low wires f are the bits to walk
//   cos_align    RG2's Q1.15 onto Q1.18;  sat_cos: clamped to 1.0 (SATURATE = 1) or not (0)
//   stage        MX_B, MUL_P, MX_P, RG_P and the controller (sqmul_stage.v, sqmul_ctrl.v)
//   MUL12..14    UA 60553's colour multipliers on RG_P's 16 high wires
//   out29        strobe 17 AND the stage's done
// Clocks per sample: floor(log2 n) + popcount(n) + 3 rising edges from strobe 17's fall to done
// (two for the synchroniser sync17, the taking edge, one per square and per multiplication, the
// done edge): 4..21 for n in 1..1000 (21 at n = 767, 895, 959, 991; 9 at n = 20).
// Only instantiates and wires; every width from shading_formats.vh.
`include "shading_formats.vh"
module sqmul_device #(
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
    wire [`SQUARED_Z_W-1:0] z_lead;
    wire [`SQUARED_MANT_W-1:0] bsh1_mant;
    wire [`SQUARED_F_W-1:0] f_frac;
    wire [WP-1:0] cos_aligned, cos_p;
    wire [WP-1:0] p_brdf;  // RG_P: cos^n
    wire [`SPEC_BRDF_W-1:0] brdf_q15;
    wire p_done;

    reg_block #(.W(`SQUARED_N_W)) rg1 (.ctl(ctl15), .d(in16_n), .q(rg1_n));
    reg_block #(.W(`SPEC_COS_W)) rg2 (.ctl(ctl17), .d(in18_cos), .q(rg2_cos));
    reg_block #(.W(`SPEC_KSI_W)) rg3 (.ctl(ctl20), .d(in19_ksi_r), .q(rg3_ksi_r));
    reg_block #(.W(`SPEC_KSI_W)) rg4 (.ctl(ctl22), .d(in21_ksi_g), .q(rg4_ksi_g));
    reg_block #(.W(`SPEC_KSI_W)) rg5 (.ctl(ctl24), .d(in23_ksi_b), .q(rg5_ksi_b));

    lzc #(.W(`SQUARED_N_W), .ZW(`SQUARED_Z_W)) lzc_n (.x(rg1_n), .z(z_lead));
    barrel_shifter #(.WIN(`SQUARED_N_W), .WOUT(`SQUARED_MANT_W), .WS(`SQUARED_Z_W)) bsh1 (
        .x(rg1_n), .s(z_lead), .y(bsh1_mant));
    // the 9 low wires
    shifter #(.WIN(`SQUARED_MANT_W), .WOUT(`SQUARED_F_W), .SHIFT(0)) f_wires (.x(bsh1_mant), .y(f_frac));
    // Q1.15 onto Q1.18
    shifter #(.WIN(`SPEC_COS_W), .WOUT(WP), .SHIFT(`SQMUL_COS_ALIGN)) cos_align (.x(rg2_cos), .y(cos_aligned));
    saturator #(.W(WP), .SATURATE(SATURATE), .HI(`SQMUL_P_ONE)) sat_cos (.x(cos_aligned), .y(cos_p));
    sqmul_stage stage (.clk(clk), .ctl17(ctl17), .z(z_lead), .f(f_frac), .c(cos_p), .brdf(p_brdf),
                       .done(p_done));
    // the stage's 16 high wires, Q1.15 (3 low wires open: floor)
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
