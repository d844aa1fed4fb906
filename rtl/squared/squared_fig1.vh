// The part of the squared-quadratic device that its two squaring stages share (included in the
// body of squared_device.v, the iterative stage, and squared_series_device.v, the series one), as
// modules/squared/squared_device.h wires it: UA 60553's registers RG1..RG5, the generator of a and
// z from n, Fig. 1's datapath at n' (MUL7, INV8, node 28, ADD9, MUL10 on the Q0.12 a, node 30,
// ADD11 on Q1.18) and the colour multipliers MUL12..14 on the 16 high wires of the stage's result.
// The including module declares the pins, the parameter SATURATE and the stage's result sq_brdf,
// and instantiates the stage on add11_q (and z_lead, rg1_n, ctl17 as it needs).

    // Nets, named by the block that drives them and what they carry.
    wire [`SQUARED_N_W-1:0] rg1_n;
    wire [`SPEC_COS_W-1:0] rg2_cos;
    wire [`SPEC_KSI_W-1:0] rg3_ksi_r, rg4_ksi_g, rg5_ksi_b;
    wire [`SQUARED_A_W-1:0] a_coef;
    wire [`SQUARED_Z_W-1:0] z_lead;
    wire [`SPEC_COS2_W-1:0] mul7_cos2;
    wire [`SPEC_INV8_W-1:0] inv8_not_cos;
    wire node28_carry1, node30_carry0;
    wire [`SPEC_D_W-1:0] add9_cos2_minus_cos;
    wire [`SQUARED_MUL10_W-1:0] mul10_a_x_diff;
    wire [`SQUARED_Q_W-1:0] cos_aligned;
    wire [`SQUARED_Q_W-1:0] add11_q;  // the quadratic at n'
    wire [`SPEC_BRDF_W-1:0] brdf_q15;

    reg_block #(.W(`SQUARED_N_W)) rg1 (.ctl(ctl15), .d(in16_n), .q(rg1_n));
    reg_block #(.W(`SPEC_COS_W)) rg2 (.ctl(ctl17), .d(in18_cos), .q(rg2_cos));
    reg_block #(.W(`SPEC_KSI_W)) rg3 (.ctl(ctl20), .d(in19_ksi_r), .q(rg3_ksi_r));
    reg_block #(.W(`SPEC_KSI_W)) rg4 (.ctl(ctl22), .d(in21_ksi_g), .q(rg4_ksi_g));
    reg_block #(.W(`SPEC_KSI_W)) rg5 (.ctl(ctl24), .d(in23_ksi_b), .q(rg5_ksi_b));

    a_gen_squared a_gen (.n(rg1_n), .a(a_coef), .z(z_lead));
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
    // 0.12 x 2.30s -> 2.18s, floor
    mul #(.WA(`SQUARED_A_W), .WB(`SPEC_D_W), .WP(`SQUARED_MUL10_W), .DROP(`SQUARED_MUL10_DROP), .BSIGNED(1)) mul10 (
        .a(a_coef), .b(add9_cos2_minus_cos), .p(mul10_a_x_diff));
    // Q1.15 onto Q1.18
    shifter #(.WIN(`SPEC_COS_W), .WOUT(`SQUARED_Q_W), .SHIFT(`SQUARED_COS_ALIGN)) cos_align (
        .x(rg2_cos), .y(cos_aligned));
    // 2.18s + 1.18 -> 1.18, wrapped or saturated to [0, 1.0]
    adder #(.WA(`SQUARED_MUL10_W), .WB(`SQUARED_Q_W), .WS(`SQUARED_Q_W), .ASIGNED(1),
            .SATURATE(SATURATE), .SAT_LO(`SQUARED_Q_SAT_LO), .SAT_HI(`SQUARED_Q_SAT_HI)) add11 (
        .a(mul10_a_x_diff), .b(cos_aligned), .cin(node30_carry0), .s(add11_q));
    // the stage's 16 high wires, Q1.15 (3 low wires open: floor)
    shifter #(.WIN(`SQUARED_Q_W), .WOUT(`SPEC_BRDF_W), .SHIFT(-`SQUARED_SQ_TO_BRDF_DROP)) brdf_wires (
        .x(sq_brdf), .y(brdf_q15));
    // Q1.15 x 8.0 -> Q9.8 floor
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul12 (
        .a(brdf_q15), .b(rg3_ksi_r), .p(out25_r));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul13 (
        .a(brdf_q15), .b(rg4_ksi_g), .p(out26_g));
    mul #(.WA(`SPEC_BRDF_W), .WB(`SPEC_KSI_W), .WP(`SPEC_OUT_W), .DROP(`SPEC_OUT_DROP)) mul14 (
        .a(brdf_q15), .b(rg5_ksi_b), .p(out27_b));
