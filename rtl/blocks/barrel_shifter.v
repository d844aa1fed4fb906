// Barrel shifter, as modules/blocks/barrel_shifter.h: y = x << s, the shift amount a bus. One row
// of 2:1 multiplexers per wire of s: row j shifts by 2^j when s[j] is 1. Input wire i lands on
// output wire i + s; wires shifted past the top of the WOUT-wire output are dropped and the low s
// output wires are tied to 0.
module barrel_shifter #(
    parameter WIN = 8,
    parameter WOUT = 8,
    parameter WS = 3
) (
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [WIN-1:0]  x,  // wires at or above WOUT are shifted out by any s
    /* verilator lint_on UNUSEDSIGNAL */
    input  wire [WS-1:0]   s,
    output wire [WOUT-1:0] y
);
    // One array for the rows; split_var lets Verilator schedule the rows one by one.
    wire [WOUT-1:0] row [0:WS] /*verilator split_var*/;
    genvar i, j;
    generate
        for (i = 0; i < WOUT; i = i + 1) begin : g_in
            if (i < WIN) begin : g_wire
                assign row[0][i] = x[i];
            end else begin : g_tied0
                assign row[0][i] = 1'b0;
            end
        end
        for (j = 0; j < WS; j = j + 1) begin : g_row
            if ((1 << j) < WOUT) begin : g_shift
                assign row[j+1] = s[j] ? {row[j][WOUT-1-(1<<j):0], {(1 << j){1'b0}}} : row[j];
            end else begin : g_clear  // a shift by 2^j empties the bus
                assign row[j+1] = s[j] ? {WOUT{1'b0}} : row[j];
            end
        end
    endgenerate
    assign y = row[WS];
endmodule
