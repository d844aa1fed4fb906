// A small memory of DEPTH words of W bits (ours: the cells' column buffers), as modules/blocks/ram.h:
// one synchronous write port, at a rising edge of clk where `we` is 1 it stores `wd` at `wa` (the
// values before the edge); one asynchronous read port, `rd` the word at `ra` (a register file). An
// address beyond DEPTH: the write dropped, the read 0 (the SystemC block reports it; a report is not
// hardware). A memory array with one write and one read process, so synthesis infers a memory.
// No reset pin, as the SystemC block: every word starts at 0. AW = interp::code_width(DEPTH).
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
    output wire [W-1:0]  rd
);
    localparam [31:0] DEPTH_WORD = DEPTH;
    localparam [AW:0] WORDS = DEPTH_WORD[AW:0];  // DEPTH <= 2^AW
    reg [W-1:0] mem [0:DEPTH-1];

    integer i;
    initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {W{1'b0}};

    generate
        if (DEPTH < (1 << AW)) begin : g_partial
            // Some addresses name no word.
            always @(posedge clk) if (we && {1'b0, wa} < WORDS) mem[wa] <= wd;
            assign rd = {1'b0, ra} < WORDS ? mem[ra] : {W{1'b0}};
        end else begin : g_full
            // Every address names a word.
            always @(posedge clk) if (we) mem[wa] <= wd;
            assign rd = mem[ra];
        end
    endgenerate
endmodule
