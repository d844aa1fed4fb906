// A synchroniser, as modules/blocks/synchroniser.h: STAGES flip-flops in series on the rising edge
// of the receiving domain's clock, W wires wide. The first may go metastable when d changes near a
// rising edge; each stage after it gives it a clock period to settle; only q, the last stage, may
// be read in clk's domain. A change at d reaches q at the STAGES-th rising edge after it. Each wire
// is synchronised on its own: W > 1 only for words that change one wire at a time.
// No reset, as the SystemC block: every stage is 0 in simulation until the first edge.
module synchroniser #(
    parameter W = 1,
    parameter STAGES = 2
) (
    input  wire         clk,
    input  wire [W-1:0] d,
    output wire [W-1:0] q
);
    // stages[W-1:0] samples d; stages[W*STAGES-1 -: W] is q
    reg [W*STAGES-1:0] stages = {W*STAGES{1'b0}};

    always @(posedge clk) stages <= {stages[W*(STAGES-1)-1:0], d};

    assign q = stages[W*STAGES-1 -: W];
endmodule
