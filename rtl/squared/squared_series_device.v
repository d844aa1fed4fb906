// The squared-quadratic device with the series squaring stage (ours, for the cost comparison):
// squared_device.v's registers, generator, Fig. 1 datapath at n' and colour multipliers
// (squared_fig1.vh), but the k squares done by squaring_series.v (9 squarers with bypass
// multiplexers, combinational). So it has UA 60553's pins and Fig. 3 timing exactly: no clock,
// output 29 is strobe 17 itself (a wire, as in UA 60553), and the outputs settle within the
// strobe's low phase - a phase that must now cover 9 multipliers more. The same golden model as
// the iterative device (golden_squared). SATURATE as in squared_device.v.
`include "shading_formats.vh"
module squared_series_device #(
    parameter SATURATE = 1
) (
    // Device pins, numbered as in UA 60553, Fig. 1.
    input  wire ctl15, ctl17, ctl20, ctl22, ctl24,
    input  wire [`SQUARED_N_W-1:0] in16_n,
    input  wire [`SPEC_COS_W-1:0]  in18_cos,
    input  wire [`SPEC_KSI_W-1:0]  in19_ksi_r, in21_ksi_g, in23_ksi_b,
    output wire [`SPEC_OUT_W-1:0]  out25_r, out26_g, out27_b,
    output wire out29_valid
);
    wire [`SQUARED_Q_W-1:0] sq_brdf;  // after k squares, cos^n

`include "squared_fig1.vh"

    squaring_series sq (.z(z_lead), .q(add11_q), .brdf(sq_brdf));
    wire_block out29 (.x(ctl17), .y(out29_valid));  // Fig. 3: output 29 is RG2's strobe itself
endmodule
