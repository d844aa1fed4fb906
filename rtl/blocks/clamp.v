// Saturating output stage, as modules/blocks/clamp.h: y = min(max(floor(x / 2^DROP), 0), 2^WOUT - 1).
// The DROP low wires are left unconnected (floor, as in mul.v), then a comparator forces every wire
// to 0 for a negative value (IN_SIGNED = 1: the sign wire) and every wire to 1 above the range. The
// shading pipeline's pixel clamp: Q16.16 signed -> Q8.8 unsigned (WIN 32, WOUT 16, DROP 8;
// golden_output_clamp, src/floor/arith/pipeline_arith.h).
module clamp #(
    parameter WIN = 32,
    parameter WOUT = 16,
    parameter DROP = 0,
    parameter IN_SIGNED = 1
) (
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [WIN-1:0]  x,  // the DROP low wires are not read
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [WOUT-1:0] y
);
    localparam WV = WIN - DROP;  // the value's wires after the floor
    wire [WV-1:0] v = x[WIN-1:DROP];
    wire negative = (IN_SIGNED != 0) & x[WIN-1];
    generate
        if (WV > WOUT) begin : g_narrow
            // Above the range: a 1 on any wire over the output's (for a signed input the sign wire
            // is one of them; a negative value is caught first).
            wire above = |v[WV-1:WOUT];
            assign y = negative ? {WOUT{1'b0}} : above ? {WOUT{1'b1}} : v[WOUT-1:0];
        end else if (WV == WOUT) begin : g_same
            // Every value fits: only the sign can force the output.
            assign y = negative ? {WOUT{1'b0}} : v;
        end else begin : g_wide
            assign y = negative ? {WOUT{1'b0}} : {{(WOUT-WV){1'b0}}, v};
        end
    endgenerate
endmodule
