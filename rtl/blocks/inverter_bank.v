// Inverter bank, as modules/blocks/inverter_bank.h: one inverter per wire of a WOUT-bit bus. The
// WIN-bit input lands on wires ALIGN..ALIGN+WIN-1; the other wires are tied to 0, so their
// inverters output 1: y = ~(x << ALIGN), the one's complement an adder turns into -x with cin = 1.
module inverter_bank #(
    parameter WIN = 16,
    parameter WOUT = WIN,
    parameter ALIGN = 0
) (
    input  wire [WIN-1:0]  x,
    output wire [WOUT-1:0] y
);
    genvar i;
    generate
        for (i = 0; i < WOUT; i = i + 1) begin : g_wire
            if (i >= ALIGN && i < ALIGN + WIN) begin : g_in
                assign y[i] = ~x[i-ALIGN];
            end else begin : g_tied0
                assign y[i] = 1'b1;  // the inverter of a wire tied to 0
            end
        end
    endgenerate
endmodule
