// OR gate over wires LO..W-1 of a W-bit bus, as modules/blocks/reduce_or.h: y = 1 when the bus,
// read as unsigned, is at least 2^LO (the tuned generator's "n >= 2").
module reduce_or #(
    parameter W = 8,
    parameter LO = 0
) (
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire [W-1:0] x,  // wires below LO are not read
    /* verilator lint_on UNUSEDSIGNAL */
    output wire         y
);
    assign y = |x[W-1:LO];
endmodule
