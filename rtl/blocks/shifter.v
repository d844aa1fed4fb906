// Shift by a constant, as modules/blocks/shifter.h: pure wiring. Input wire i lands on output
// wire i + SHIFT; output wires below SHIFT are tied to 0, those above the input to 0 (IN_SIGNED
// = 0) or to the input's sign wire (IN_SIGNED = 1). A negative SHIFT leaves the -SHIFT low input
// wires unconnected (floor), and the result wraps to WOUT wires.
module shifter #(
    parameter WIN = 16,
    parameter WOUT = 16,
    parameter IN_SIGNED = 0,
    parameter SHIFT = 0
) (
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [WIN-1:0]  x,  // with a negative SHIFT the low wires are not read
    /* verilator lint_on UNUSEDSIGNAL */
    output wire [WOUT-1:0] y
);
    /* verilator lint_off UNUSEDSIGNAL */
    wire ext = (IN_SIGNED != 0) & x[WIN-1];  // unread when no output wire lies above the input
    /* verilator lint_on UNUSEDSIGNAL */
    genvar i;
    generate
        for (i = 0; i < WOUT; i = i + 1) begin : g_wire
            if (i - SHIFT < 0) begin : g_low
                assign y[i] = 1'b0;
            end else if (i - SHIFT < WIN) begin : g_in
                assign y[i] = x[i-SHIFT];
            end else begin : g_ext
                assign y[i] = ext;
            end
        end
    endgenerate
endmodule
