// A memory of DEPTH words of W bits addressed by AW wires (ours: the cells' column buffers, the frame
// buffer, the geometry side's stores), as modules/blocks/ram.h: one synchronous write port, at a
// rising edge of clk where `we` is 1 it stores `wd` at `wa` (the values before the edge); one
// asynchronous read port, `rd` the word at `ra` (a register file). A write address beyond DEPTH is
// dropped and sets `overflow`, a sticky flip-flop; a read address beyond DEPTH reads 0 (the SystemC
// block also reports both; a report is not hardware). A memory array with one write and one read
// process, so synthesis infers a memory. No reset pin, as the SystemC block: every word and the
// flag start at 0 (in simulation). AW >= clog2(DEPTH).
module ram #(
    parameter W = 16,
    parameter DEPTH = 64,
    parameter AW = (DEPTH > 2 ? $clog2(DEPTH) : 1)
) (
    input  wire          clk,
    input  wire          we,
    input  wire [AW-1:0] wa,
    input  wire [AW-1:0] ra,
    input  wire [W-1:0]  wd,
    output wire [W-1:0]  rd,
    output wire          overflow
);
    localparam [31:0] DEPTH_WORD = DEPTH;
    localparam [AW:0] WORDS = DEPTH_WORD[AW:0];  // DEPTH <= 2^AW
    localparam integer IW = DEPTH > 2 ? $clog2(DEPTH) : 1;  // the wires that index the words
    reg [W-1:0] mem [0:DEPTH-1];

`ifndef SYNTHESIS
    // Simulation only: a RAM macro has no initial contents to synthesize (a frame buffer's million
    // words would be a million initial values).
    integer i;
    initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {W{1'b0}};
`endif

    generate
        if (DEPTH < (1 << AW)) begin : g_partial
            // Some addresses name no word: a write to one is dropped and flagged.
            reg dropped = 1'b0;
            always @(posedge clk) if (we && {1'b0, wa} < WORDS) mem[wa[IW-1:0]] <= wd;
            always @(posedge clk) if (we && {1'b0, wa} >= WORDS) dropped <= 1'b1;
            assign rd = {1'b0, ra} < WORDS ? mem[ra[IW-1:0]] : {W{1'b0}};
            assign overflow = dropped;
        end else begin : g_full
            // Every address names a word: nothing to drop.
            always @(posedge clk) if (we) mem[wa] <= wd;
            assign rd = mem[ra];
            assign overflow = 1'b0;
        end
    endgenerate
endmodule
