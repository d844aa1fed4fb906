// Iterative Horner unit of the interpolation paper, Fig. 4 (modules/interp/horner_unit.h):
// I(t) = ((A t + B) t + C) t + D with one register RG, multiplexers MX1 and MX2, one multiplier
// MUL, adder Sm and key block BK: MUL = MX1 * t, MX1 in {A, RG}; Sm = MX2 + BK(RG), MX2 in
// {0, MUL, B, C, D}; RG <- Sm on the falling edge. The controller ctrl runs one micro-step per
// clock: 6 clocks per cubic pixel, 4 per quadratic one, back to back.
// Formats: A..D, RG, MX1, MX2, BK, Sm Q16.16 signed; t Q1.8 unsigned; MUL Q16.16 x Q1.8 ->
// Q17.24, floor to Q16.16. Widths from shading_formats.vh (src/floor/formats), select codes from
// interp_terms.vh (horner_ctrl.h), both generated. This module only instantiates and wires.
`include "shading_formats.vh"
`include "interp_terms.vh"
module horner_unit #(
    parameter WC = `INTERP_COEF_W,  // Q16.16
    parameter WT = `INTERP_T_W,
    parameter W_MX1 = (`INTERP_HORNER_MX1_INPUTS > 2 ? $clog2(`INTERP_HORNER_MX1_INPUTS) : 1),
    parameter W_MX2 = (`INTERP_HORNER_MX2_INPUTS > 2 ? $clog2(`INTERP_HORNER_MX2_INPUTS) : 1),
    parameter W_STEP = (`INTERP_HORNER_STEP_CODES > 2 ? $clog2(`INTERP_HORNER_STEP_CODES) : 1)
) (
    input  wire          clk,
    input  wire          start,
    input  wire          deg2,
    input  wire [WC-1:0] a,
    input  wire [WC-1:0] b,
    input  wire [WC-1:0] c,
    input  wire [WC-1:0] d,
    input  wire [WT-1:0] t,
    output wire [WC-1:0] i_t,
    output wire          done,
    output wire          busy
);
    // Nets, by what they carry.
    wire [WC-1:0] rg_value;     // RG: the partial Horner sum
    wire [WC-1:0] mx1_operand;  // A or RG
    wire [WC-1:0] mul_product;  // MX1 * t
    wire [WC-1:0] mx2_operand;  // 0, MUL, B, C or D
    wire [WC-1:0] bk_operand;   // RG or 0
    wire [WC-1:0] sm_sum;       // next RG
    wire [WC-1:0] zero_word;
    wire carry0;
    wire [W_MX1-1:0] mx1_sel;
    wire [W_MX2-1:0] mx2_sel;
    wire bk_pass;
    wire [W_STEP-1:0] step;

    // The multiplexers' inputs, each at its select code (horner_ctrl.h, via interp_terms.vh).
    wire [`INTERP_HORNER_MX1_INPUTS*WC-1:0] mx1_in;
    wire [`INTERP_HORNER_MX2_INPUTS*WC-1:0] mx2_in;
    assign mx1_in[`INTERP_MX1_A*WC +: WC] = a;
    assign mx1_in[`INTERP_MX1_RG*WC +: WC] = rg_value;
    assign mx2_in[`INTERP_MX2_ZERO*WC +: WC] = zero_word;
    assign mx2_in[`INTERP_MX2_MUL*WC +: WC] = mul_product;
    assign mx2_in[`INTERP_MX2_B*WC +: WC] = b;
    assign mx2_in[`INTERP_MX2_C*WC +: WC] = c;
    assign mx2_in[`INTERP_MX2_D*WC +: WC] = d;

    // Blocks of Fig. 4 (names from the figure) and the controller.
    reg_block #(.W(WC)) rg (.ctl(clk), .d(sm_sum), .q(rg_value));
    mux #(.W(WC), .N(`INTERP_HORNER_MX1_INPUTS), .SW(W_MX1)) mx1 (
        .in(mx1_in), .sel(mx1_sel), .y(mx1_operand));
    mul #(.WA(WC), .WB(WT), .WP(WC), .DROP(`INTERP_HORNER_MUL_DROP), .ASIGNED(1), .BSIGNED(0)) mul (
        .a(mx1_operand), .b(t), .p(mul_product));
    constant #(.W(WC), .VALUE(0)) k_zero (.y(zero_word));
    mux #(.W(WC), .N(`INTERP_HORNER_MX2_INPUTS), .SW(W_MX2)) mx2 (
        .in(mx2_in), .sel(mx2_sel), .y(mx2_operand));
    key_block #(.W(WC)) bk (.x(rg_value), .pass(bk_pass), .y(bk_operand));
    constant #(.W(1), .VALUE(0)) k_carry0 (.y(carry0));
    adder #(.WA(WC), .WB(WC), .WS(WC), .ASIGNED(1), .BSIGNED(1)) sm (
        .a(mx2_operand), .b(bk_operand), .cin(carry0), .s(sm_sum));
    wire_block #(.W(WC)) out_wire (.x(rg_value), .y(i_t));  // RG's output is the unit's output
    horner_ctrl #(.WT(WT), .W_MX1(W_MX1), .W_MX2(W_MX2), .W_STEP(W_STEP)) ctrl (
        .clk(clk), .start(start), .deg2(deg2), .t(t), .mx1_sel(mx1_sel), .mx2_sel(mx2_sel),
        .bk_pass(bk_pass), .step(step), .done(done), .busy(busy));
    wire unused_ok = &{1'b0, step, 1'b0};  // the step code is for the waveform
endmodule
