// Multiplier block, as modules/blocks/mul.h: WA x WB -> WP bits. The full product is formed
// exactly, then DROP low wires are left unconnected (floor, also for signed products) and the WP
// wires above them are the output. Operands are two's complement when ASIGNED/BSIGNED is 1, else
// unsigned: each is extended by one wire (its sign wire, or 0), so one signed multiplier of
// (WA + 1) x (WB + 1) bits covers every combination.
module mul #(
    parameter WA = 16,
    parameter WB = 16,
    parameter WP = 32,
    parameter DROP = 0,
    parameter ASIGNED = 0,
    parameter BSIGNED = 0
) (
    input  wire [WA-1:0] a,
    input  wire [WB-1:0] b,
    output wire [WP-1:0] p
);
    localparam WF = WA + WB + 2;  // the exact product of the extended operands
    wire signed [WA:0] ax = {(ASIGNED != 0) & a[WA-1], a};
    wire signed [WB:0] bx = {(BSIGNED != 0) & b[WB-1], b};
    /* verilator lint_off UNUSEDSIGNAL */
    wire signed [WF-1:0] full = ax * bx;  // the dropped low wires and those above p stay unconnected
    /* verilator lint_on UNUSEDSIGNAL */
    assign p = full[DROP+WP-1:DROP];
endmodule
