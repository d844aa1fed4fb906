// The squared-quadratic specular device (ours, built from UA 60553's Fig. 1), as
// modules/squared/squared_device.h: the patent's datapath evaluates the quadratic at the small
// exponent n' = n / 2^k in [1, 2), a squaring stage squares the result k times, and the colour
// multipliers take it (formats/squared_formats.h).
//   RG1..RG5     UA 60553's registers, written on the falling edges of strobes 15, 17, 20, 22, 24
//   a_gen        n -> a, z (a_gen_squared.v): LZC, barrel shifts, a 9 x 9 multiplier, an adder
//   MUL7, INV8, node 28, ADD9, MUL10, node 30, ADD11   Fig. 1 at n' (squared_fig1.vh)
//   sq           the squaring stage (squaring_stage.v): MX_SQ, RG_SQ, MUL_SQ, its controller and
//                sync17, strobe 17's request synchronised to clk
//   MUL12..14    Fig. 1's colour multipliers on RG_SQ's 16 high wires
//   out29        strobe 17 AND the stage's done: output 29 rises when the result is valid
// Pins: UA 60553's, plus clk, the squaring stage's clock. Output 29 rises k + 4 rising edges of
// clk after strobe 17 fell (two for the synchroniser sync17, the taking edge, k squares, the done
// edge), or at strobe 17's rise if that comes later.
// SATURATE = 1 (the SystemC default, overflow_mode::saturate) clamps ADD11 to [0, 1.0]; 0 wraps.
// Only instantiates and wires; every width from shading_formats.vh.
`include "shading_formats.vh"
module squared_device #(
    parameter SATURATE = 1
) (
    // Device pins, numbered as in UA 60553, Fig. 1, and the squaring stage's clock.
    input  wire clk,
    input  wire ctl15, ctl17, ctl20, ctl22, ctl24,
    input  wire [`SQUARED_N_W-1:0] in16_n,
    input  wire [`SPEC_COS_W-1:0]  in18_cos,
    input  wire [`SPEC_KSI_W-1:0]  in19_ksi_r, in21_ksi_g, in23_ksi_b,
    output wire [`SPEC_OUT_W-1:0]  out25_r, out26_g, out27_b,
    output wire out29_valid
);
    wire [`SQUARED_Q_W-1:0] sq_brdf;  // RG_SQ: after k squares, cos^n
    wire sq_done;

`include "squared_fig1.vh"

    squaring_stage sq (.clk(clk), .ctl17(ctl17), .z(z_lead), .q(add11_q), .brdf(sq_brdf), .done(sq_done));
    and_gate out29 (.a(ctl17), .b(sq_done), .y(out29_valid));
endmodule
