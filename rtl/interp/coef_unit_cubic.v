// Cubic coefficient unit of the interpolation paper (modules/interp/coef_unit_cubic.h): A, B, C, D of
// I(t) = A t^3 + B t^2 + C t + D from four exact intensities, shifts and adds only. rg_i1..rg_i4
// latch the samples on the falling edge of clk; the networks settle within the low phase, so A..D
// are valid at the next rising edge. Formats: I Q8.8 unsigned -> sums Q16.8 signed -> A..D Q16.16
// signed. SET 0 = case 1 (t = 0, 1/4, 1/2, 1), 1 = case 2 (t = 0, 1/2, 3/4, 1); DIV 0 = the interpolation paper's
// shift-and-add /3, 1 = exact constant divider. Widths from shading_formats.vh (src/floor/formats), term
// tables from interp_terms.vh (coef_terms), both generated. This module only instantiates and wires.
`include "shading_formats.vh"
`include "interp_terms.vh"
module coef_unit_cubic #(
    parameter SET = 0,
    parameter DIV = 0,
    parameter WI = `INTERP_SAMPLE_W,
    parameter WS = `INTERP_SUM_W,
    parameter WC = `INTERP_COEF_W,
    parameter ALIGN = `INTERP_DIV3_SHIFT
) (
    input  wire          clk,
    input  wire [WI-1:0] i1,
    input  wire [WI-1:0] i2,
    input  wire [WI-1:0] i3,
    input  wire [WI-1:0] i4,
    output wire [WC-1:0] a,
    output wire [WC-1:0] b,
    output wire [WC-1:0] c,
    output wire [WC-1:0] d
);
    localparam NA = SET == 0 ? `INTERP_A8_CASE1_N : `INTERP_A8_CASE2_N;
    localparam NB = SET == 0 ? `INTERP_B_CASE1_N : `INTERP_B_CASE2_N;
    localparam NC = SET == 0 ? `INTERP_C3_CASE1_N : `INTERP_C3_CASE2_N;
    localparam SLOTS = `INTERP_TERM_SLOTS;
    localparam [16*SLOTS-1:0] TA = SET == 0 ? `INTERP_A8_CASE1 : `INTERP_A8_CASE2;
    localparam [16*SLOTS-1:0] TB = SET == 0 ? `INTERP_B_CASE1 : `INTERP_B_CASE2;
    localparam [16*SLOTS-1:0] TC = SET == 0 ? `INTERP_C3_CASE1 : `INTERP_C3_CASE2;

    // Nets.
    wire [WI-1:0] held_i1, held_i2, held_i3, held_i4;
    wire [WS-1:0] a8_sum, b_sum, c3_sum;

    // Blocks.
    reg_block #(.W(WI)) rg_i1 (.ctl(clk), .d(i1), .q(held_i1));
    reg_block #(.W(WI)) rg_i2 (.ctl(clk), .d(i2), .q(held_i2));
    reg_block #(.W(WI)) rg_i3 (.ctl(clk), .d(i3), .q(held_i3));
    reg_block #(.W(WI)) rg_i4 (.ctl(clk), .d(i4), .q(held_i4));
    // Q8.8 -> Q16.8: 8 * (-S_A), B, -S_C.
    shift_add_network #(.WIN(WI), .W(WS), .IN_SIGNED(0), .NIN(4), .NT(NA), .SLOTS(SLOTS), .TERMS(TA)) net_a (
        .in({held_i4, held_i3, held_i2, held_i1}), .y(a8_sum));
    shift_add_network #(.WIN(WI), .W(WS), .IN_SIGNED(0), .NIN(4), .NT(NB), .SLOTS(SLOTS), .TERMS(TB)) net_b (
        .in({held_i4, held_i3, held_i2, held_i1}), .y(b_sum));
    shift_add_network #(.WIN(WI), .W(WS), .IN_SIGNED(0), .NIN(4), .NT(NC), .SLOTS(SLOTS), .TERMS(TC)) net_c (
        .in({held_i4, held_i3, held_i2, held_i1}), .y(c3_sum));
    // Q16.8 / 3 -> Q16.16.
    generate
        if (DIV == 0) begin : shift_add
            div3_shift_add #(.WIN(WS), .WOUT(WC), .ALIGN(ALIGN)) div3_a (.x(a8_sum), .y(a));
            div3_shift_add #(.WIN(WS), .WOUT(WC), .ALIGN(ALIGN)) div3_c (.x(c3_sum), .y(c));
        end else begin : exact
            const_div #(.WIN(WS), .WOUT(WC), .K(3), .ALIGN(ALIGN)) div3_a (.x(a8_sum), .y(a));
            const_div #(.WIN(WS), .WOUT(WC), .K(3), .ALIGN(ALIGN)) div3_c (.x(c3_sum), .y(c));
        end
    endgenerate
    // Q16.8 -> Q16.16 and Q8.8 -> Q16.16: wiring.
    shifter #(.WIN(WS), .WOUT(WC), .IN_SIGNED(1), .SHIFT(ALIGN)) align_b (.x(b_sum), .y(b));
    shifter #(.WIN(WI), .WOUT(WC), .IN_SIGNED(0), .SHIFT(ALIGN)) align_d (.x(held_i1), .y(d));
endmodule
