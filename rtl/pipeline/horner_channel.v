// One colour channel's evaluator with the interpolation paper's Fig. 4 Horner unit (modules/pipeline/
// horner_channel.h): the degree-select pin picks the coefficient unit (mx_a, mx_b, mx_c: 0 the
// cubic's A, B, C, 1 the quadratic's a, b, c; D is the cubic's, unused at degree 2), horner
// (rtl/interp/horner_unit.v) evaluates I(t) at the t the pixel controller issues, and out_clamp
// turns the Q16.16 signed result into the pixel's Q8.8 unsigned code (floor, saturated to
// [0, 0xFFFF]; golden_output_clamp). Only instantiates and wires.
`include "shading_formats.vh"
module horner_channel #(
    parameter WC = `INTERP_COEF_W,   // A..D, a..c, I(t): Q16.16 signed
    parameter WI = `INTERP_SAMPLE_W,  // the pixel: Q8.8 unsigned
    parameter WT = `INTERP_T_W
) (
    input  wire          clk,
    input  wire          start,
    input  wire          deg2,
    input  wire          deg_sel,  // deg2 as the multiplexers' select code
    input  wire [WT-1:0] t,
    input  wire [WC-1:0] ca,
    input  wire [WC-1:0] cb,
    input  wire [WC-1:0] cc,
    input  wire [WC-1:0] cd,
    input  wire [WC-1:0] qa,
    input  wire [WC-1:0] qb,
    input  wire [WC-1:0] qc,
    output wire [WI-1:0] px,
    output wire          done,
    output wire          busy
);
    // Nets.
    wire [WC-1:0] a, b, c, i_t;

    // Blocks: input 0 the cubic's coefficient, input 1 the quadratic's.
    mux #(.W(WC), .N(2), .SW(1)) mx_a (.in({qa, ca}), .sel(deg_sel), .y(a));
    mux #(.W(WC), .N(2), .SW(1)) mx_b (.in({qb, cb}), .sel(deg_sel), .y(b));
    mux #(.W(WC), .N(2), .SW(1)) mx_c (.in({qc, cc}), .sel(deg_sel), .y(c));
    horner_unit #(.WC(WC), .WT(WT)) horner (
        .clk(clk), .start(start), .deg2(deg2), .a(a), .b(b), .c(c), .d(cd), .t(t), .i_t(i_t), .done(done),
        .busy(busy));
    clamp #(.WIN(WC), .WOUT(WI), .DROP(`INTERP_COEF_FRAC - `INTERP_SAMPLE_FRAC), .IN_SIGNED(1)) out_clamp (
        .x(i_t), .y(px));
endmodule
