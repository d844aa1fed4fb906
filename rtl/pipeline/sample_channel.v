// One colour channel of the shading pipeline's sample stage and coefficient units (SystemC twin
// modules/pipeline/sample_channel.h, instance for instance; the interpolation paper's system, the
// sample stage's formats ours, src/floor/formats/pipeline_formats.h):
//   mul_diffuse   k_d*I (Q8.8) x N.L (Q1.15) -> Q9.8, the low wires dropped (floor)
//   add_ambient   ambient (Q8.8) + diffuse (Q9.8) -> Q10.8 (never overflows)
//   add_colour    + the device's specular out25/26/27 (Q9.8), saturated to Q8.8 (0xFFFF)
//   mx_carry      the colour bus (ours): the colour just formed, or with carry_sel the last sample's
//                 colour from rg_last (a job whose first point is the last sample's point)
//   rg_last       the last sample's colour (strobe ld_last, at every sample's latch)
//   rg_i1..rg_i4  the sample registers I1..I4 on the colour bus, each latched by its own strobe
//   rg_e1..rg_e4  the interval registers, latched where the pixel controller's ld_e falls, so the
//                 next interval's samples can be formed while this interval's pixels are evaluated
//   coef_cubic    coef_unit_cubic.v (A..D; SET: 0 case 1, 1 case 2; DIV: 0 shift-and-add /3, 1 exact)
//   coef_quad     coef_unit_quad.v (a, b, c through rg_e1..rg_e3 at t = 0, 1/2, 1)
// Every register latches at the falling edge of its strobe (reg_block.v). Only instantiates and
// wires; every width from shading_formats.vh.
`include "shading_formats.vh"
module sample_channel #(
    parameter SET = 0,
    parameter DIV = 0
) (
    input  wire clk,
    input  wire ld_i1, ld_i2, ld_i3, ld_i4, ld_e,
    input  wire [`PIPELINE_KDI_W-1:0]     kdi,        // frame constant k_d * I_l
    input  wire [`PIPELINE_AMBIENT_W-1:0] ambient,    // frame constant 255 * ambient, Q8.8
    input  wire [`SPEC_COS_W-1:0]         cos_nl,     // this sample's N.L
    input  wire [`SPEC_OUT_W-1:0]         specular,   // the device's out25 / out26 / out27
    input  wire                           carry_sel,  // 1: the bus carries the last sample
    input  wire                           ld_last,
    output wire [`INTERP_COEF_W-1:0]      ca, cb, cc, cd,  // cubic A..D, Q16.16
    output wire [`INTERP_COEF_W-1:0]      qa, qb, qc       // quadratic a..c
);
    localparam WI = `INTERP_SAMPLE_W;

    // Nets.
    wire [`PIPELINE_DIFFUSE_W-1:0] mul_diffuse_p;
    wire [`PIPELINE_AD_W-1:0] add_ambient_s;
    wire [`PIPELINE_COLOUR_W-1:0] colour;
    wire [WI-1:0] bus, last;  // the colour bus, the last sample
    wire [WI-1:0] i1, i2, i3, i4;  // sample registers
    wire [WI-1:0] e1, e2, e3, e4;  // interval registers
    wire carry0;

    // Blocks.
    mul #(.WA(`PIPELINE_KDI_W), .WB(`SPEC_COS_W), .WP(`PIPELINE_DIFFUSE_W), .DROP(`PIPELINE_DIFFUSE_DROP))
        mul_diffuse (.a(kdi), .b(cos_nl), .p(mul_diffuse_p));
    constant #(.W(1), .VALUE(1'b0)) k_carry0 (.y(carry0));
    adder #(.WA(`PIPELINE_AMBIENT_W), .WB(`PIPELINE_DIFFUSE_W), .WS(`PIPELINE_AD_W)) add_ambient (
        .a(ambient), .b(mul_diffuse_p), .cin(carry0), .s(add_ambient_s));
    adder #(.WA(`PIPELINE_AD_W), .WB(`SPEC_OUT_W), .WS(`PIPELINE_COLOUR_W), .SATURATE(1), .SAT_LO(0),
            .SAT_HI(`PIPELINE_COLOUR_SAT_HI)) add_colour (
        .a(add_ambient_s), .b(specular), .cin(carry0), .s(colour));
    mux #(.W(WI), .N(2), .SW(1)) mx_carry (.in({last, colour}), .sel(carry_sel), .y(bus));
    reg_block #(.W(WI)) rg_last (.ctl(ld_last), .d(bus), .q(last));
    reg_block #(.W(WI)) rg_i1 (.ctl(ld_i1), .d(bus), .q(i1));
    reg_block #(.W(WI)) rg_i2 (.ctl(ld_i2), .d(bus), .q(i2));
    reg_block #(.W(WI)) rg_i3 (.ctl(ld_i3), .d(bus), .q(i3));
    reg_block #(.W(WI)) rg_i4 (.ctl(ld_i4), .d(bus), .q(i4));
    reg_block #(.W(WI)) rg_e1 (.ctl(ld_e), .d(i1), .q(e1));
    reg_block #(.W(WI)) rg_e2 (.ctl(ld_e), .d(i2), .q(e2));
    reg_block #(.W(WI)) rg_e3 (.ctl(ld_e), .d(i3), .q(e3));
    reg_block #(.W(WI)) rg_e4 (.ctl(ld_e), .d(i4), .q(e4));
    coef_unit_cubic #(.SET(SET), .DIV(DIV)) coef_cubic (
        .clk(clk), .i1(e1), .i2(e2), .i3(e3), .i4(e4), .a(ca), .b(cb), .c(cc), .d(cd));
    coef_unit_quad coef_quad (.clk(clk), .i1(e1), .i2(e2), .i3(e3), .a(qa), .b(qb), .c(qc));
endmodule
