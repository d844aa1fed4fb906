// Forward-difference evaluator for intervals of 2^M pixels (ours; modules/interp/fd_eval.h): the
// classic alternative to Horner for a cubic at equally spaced t = k / 2^M: after a set-up of shifts
// and adds,  P <- P + D1,  D1 <- D1 + D2,  D2 <- D2 + D3  (three additions per pixel, no
// multiplier), with P(0) = D, D1 = A/N^3 + B/N^2 + C/N, D2 = 6A/N^3 + 2B/N^2, D3 = 6A/N^3. One pixel
// per clock. Set-up: shift_add_network (N = 2^M makes every /N^k a shift; term tables fd_setup.h,
// generated into interp_terms.vh). Registers rg_p, rg_d1, rg_d2, rg_d3 latch on the falling edge of
// clk, each fed by a multiplexer on fd_sel: hold (its own output), load (the set-up), step (the
// adder). Formats (interp_formats.h): A..D Q16.16 signed in; set-up, registers and adders Q22.34
// signed (exact for M <= 6); the output drops the 18 low wires (floor) -> Q16.16.
// The controller ctrl is fd_ctrl.v. This module only instantiates and wires; the SystemC model's
// clock-phase monitor chk_clock is not hardware and has no counterpart here.
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_eval #(
    parameter M = 4,
    parameter WL = M + 1,  // interp::len_width(M)
    parameter WC = `INTERP_COEF_W,
    parameter W_SEL = (`INTERP_FD_MX_INPUTS > 2 ? $clog2(`INTERP_FD_MX_INPUTS) : 1)
) (
    input  wire          clk,
    input  wire          start,
    input  wire [WL-1:0] len,
    input  wire [WC-1:0] a,
    input  wire [WC-1:0] b,
    input  wire [WC-1:0] c,
    input  wire [WC-1:0] d,
    output wire [WC-1:0] i_px,
    output wire          valid,
    output wire          last
);
    localparam WF = `INTERP_FD_W;  // Q22.34
    localparam S = `INTERP_FD_ALIGN;  // Q.16 -> Q.34
    localparam NX = `INTERP_FD_MX_INPUTS;
    // This M's set-up terms (fd_setup.h), cut from the generated tables of every m.
    localparam N1 = `INTERP_FD_D1_N, N2 = `INTERP_FD_D2_N, N3 = `INTERP_FD_D3_N;
    localparam LENGTHS = `INTERP_M_MAX - `INTERP_M_MIN + 1, AT = M - `INTERP_M_MIN;
    localparam [16*N1*LENGTHS-1:0] ALL1 = `INTERP_FD_D1;
    localparam [16*N2*LENGTHS-1:0] ALL2 = `INTERP_FD_D2;
    localparam [16*N3*LENGTHS-1:0] ALL3 = `INTERP_FD_D3;
    localparam [16*N1-1:0] T1 = ALL1[16*N1*AT +: 16*N1];
    localparam [16*N2-1:0] T2 = ALL2[16*N2*AT +: 16*N2];
    localparam [16*N3-1:0] T3 = ALL3[16*N3*AT +: 16*N3];

    // Nets, as fd_eval.h names them.
    wire [WF-1:0] init_p, init_d1, init_d2, init_d3;
    wire [WF-1:0] p_value, d1_value, d2_value, d3_value;
    wire [WF-1:0] p_next, d1_next, d2_next;
    wire [WF-1:0] p_sum, d1_sum, d2_sum, d3_keep;
    wire [W_SEL-1:0] fd_sel;
    wire [WL-1:0] pixel;
    wire carry0;

    // Set-up: shifts and adds of the Q16.16 coefficients onto Q22.34 (inputs: 0 = A, 1 = B, 2 = C).
    shifter #(.WIN(WC), .WOUT(WF), .IN_SIGNED(1), .SHIFT(S)) setup_p (.x(d), .y(init_p));
    shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(3), .NT(N1), .SLOTS(N1), .TERMS(T1)) setup_d1 (
        .in({c, b, a}), .y(init_d1));  // A/N^3 + B/N^2 + C/N
    shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(2), .NT(N2), .SLOTS(N2), .TERMS(T2)) setup_d2 (
        .in({b, a}), .y(init_d2));  // (4A + 2A)/N^3 + 2B/N^2
    shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(1), .NT(N3), .SLOTS(N3), .TERMS(T3)) setup_d3 (
        .in(a), .y(init_d3));  // (4A + 2A)/N^3

    // The recurrence (wire_fd_recurrence in fd_eval.h, shared with fd_eval_var.v).
    `include "fd_recurrence.vh"

    fd_ctrl #(.M(M), .WL(WL), .W_SEL(W_SEL)) ctrl (
        .clk(clk), .start(start), .len(len), .fd_sel(fd_sel), .pixel(pixel), .valid(valid), .last(last));
    wire unused_ok = &{1'b0, pixel, 1'b0};  // the pixel index is for the waveform
endmodule
