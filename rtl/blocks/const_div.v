// Divider by a hardwired constant K (modules/blocks/const_div.h): y = floor((x << ALIGN) / K) for a
// signed WIN-bit x, on a signed WOUT-bit bus (wraps if the quotient does not fit). The comparison
// option beside the interpolation paper's shift-and-add /3; described by its function, as the SystemC block is,
// and left to synthesis to build (a constant divider). ALIGN >= 1 (Verilog-2005 has no empty
// replication).
module const_div #(
    parameter WIN = 8,
    parameter WOUT = 8,
    parameter K = 3,
    parameter ALIGN = 0
) (
    input  wire [WIN-1:0]  x,
    output wire [WOUT-1:0] y
);
    localparam WV = WIN + ALIGN;
    localparam WQ = (WV > WOUT ? WV : WOUT) + 1;
    localparam signed [WV:0] KS = K;

    wire signed [WV:0] v = {x[WIN-1], x, {ALIGN{1'b0}}};   // x << ALIGN, one wire of headroom
    wire signed [WV:0] q_trunc = v / KS;                   // toward zero
    wire signed [WV:0] r = v % KS;
    // Floor: one less when a negative dividend leaves a remainder.
    wire signed [WV:0] q_floor = q_trunc - {{WV{1'b0}}, (v[WV] && r != 0)};
    wire signed [WQ:0] q_wide = {{(WQ - WV){q_floor[WV]}}, q_floor};
    assign y = q_wide[WOUT-1:0];
    wire unused_ok = &{1'b0, q_wide[WQ:WOUT], 1'b0};
endmodule
