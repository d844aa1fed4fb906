// Quadratic coefficient unit of the interpolation paper (modules/interp/coef_unit_quad.h): a, b, c of
// I(t) = a t^2 + b t + c through I1, I2, I3 at t = 0, 1/2, 1, shifts and adds only, no division:
//   a = 2 I1 - 4 I2 + 2 I3,  b = -3 I1 + 4 I2 - I3,  c = I1.
// Same timing and formats as coef_unit_cubic.v: rg_i1..rg_i3 latch the samples on the falling edge of
// clk, a..c are valid at the next rising edge; I Q8.8 unsigned -> sums Q16.8 signed -> a..c Q16.16
// signed (exact). Widths from shading_formats.vh, term tables from interp_terms.vh (coef_terms::a_quad,
// b_quad), both generated. This module only instantiates and wires.
`include "shading_formats.vh"
`include "interp_terms.vh"
module coef_unit_quad #(
    parameter WI = `INTERP_SAMPLE_W,
    parameter WS = `INTERP_SUM_W,
    parameter WC = `INTERP_COEF_W,
    parameter ALIGN = `INTERP_DIV3_SHIFT
) (
    input  wire          clk,
    input  wire [WI-1:0] i1,
    input  wire [WI-1:0] i2,
    input  wire [WI-1:0] i3,
    output wire [WC-1:0] a,
    output wire [WC-1:0] b,
    output wire [WC-1:0] c
);
    localparam SLOTS = `INTERP_TERM_SLOTS;
    localparam [16*SLOTS-1:0] TA = `INTERP_A_QUAD;
    localparam [16*SLOTS-1:0] TB = `INTERP_B_QUAD;

    // Nets.
    wire [WI-1:0] held_i1, held_i2, held_i3;
    wire [WS-1:0] a_sum, b_sum;

    // Blocks.
    reg_block #(.W(WI)) rg_i1 (.ctl(clk), .d(i1), .q(held_i1));
    reg_block #(.W(WI)) rg_i2 (.ctl(clk), .d(i2), .q(held_i2));
    reg_block #(.W(WI)) rg_i3 (.ctl(clk), .d(i3), .q(held_i3));
    // Q8.8 -> Q16.8: a, b.
    shift_add_network #(.WIN(WI), .W(WS), .IN_SIGNED(0), .NIN(3), .NT(`INTERP_A_QUAD_N), .SLOTS(SLOTS), .TERMS(TA))
        net_a (.in({held_i3, held_i2, held_i1}), .y(a_sum));
    shift_add_network #(.WIN(WI), .W(WS), .IN_SIGNED(0), .NIN(3), .NT(`INTERP_B_QUAD_N), .SLOTS(SLOTS), .TERMS(TB))
        net_b (.in({held_i3, held_i2, held_i1}), .y(b_sum));
    // Q16.8 -> Q16.16 and Q8.8 -> Q16.16: wiring.
    shifter #(.WIN(WS), .WOUT(WC), .IN_SIGNED(1), .SHIFT(ALIGN)) align_a (.x(a_sum), .y(a));
    shifter #(.WIN(WS), .WOUT(WC), .IN_SIGNED(1), .SHIFT(ALIGN)) align_b (.x(b_sum), .y(b));
    shifter #(.WIN(WI), .WOUT(WC), .IN_SIGNED(0), .SHIFT(ALIGN)) align_c (.x(held_i1), .y(c));
endmodule
