// Register written on the falling edge of its control input (UA 60553, Fig. 3: "write on the
// trailing edge"), as modules/blocks/reg.h. Named reg_block because `reg` is a Verilog keyword.
// No reset, as the SystemC block: q is 0 in simulation until the first edge (Verilator's default).
// The SystemC block's setup check is a monitor, not hardware, and has no RTL counterpart.
module reg_block #(
    parameter W = 8
) (
    input  wire         ctl,
    input  wire [W-1:0] d,
    output reg  [W-1:0] q
);
    always @(negedge ctl) q <= d;
endmodule
