// The edge walker's live triangles for the cells (ours; modules/pipeline/cell_stores.h's
// walker_store): the block library's RAM of SLOTS x 2^`PIPELINE_WALKER_WORD_AW words of
// `PIPELINE_WALKER_WORD_W bits, the word k of slot s at {s, k}: wiring, no multiplier. The slot
// pins are 16 wires, so that a slot beyond SLOTS can be asked for: its write is dropped and
// `overflow` set (the RAM's flag). SLOTS defaults to the format's capacity (cell_store_formats.h).
//   ram_words  ram: SLOTS x 2^WORD_AW words
`include "shading_formats.vh"
module walker_store #(
    parameter SLOTS = `PIPELINE_WALKER_SLOTS
) (
    input  wire clk,
    input  wire we,
    input  wire [15:0] wa_hi,
    input  wire [`PIPELINE_WALKER_WORD_AW-1:0] wa_lo,
    input  wire [15:0] ra_hi,
    input  wire [`PIPELINE_WALKER_WORD_AW-1:0] ra_lo,
    input  wire [`PIPELINE_WALKER_WORD_W-1:0] wd,
    output wire [`PIPELINE_WALKER_WORD_W-1:0] rd,
    output wire overflow
);
    localparam integer AW = 16 + `PIPELINE_WALKER_WORD_AW;
    ram #(.W(`PIPELINE_WALKER_WORD_W), .DEPTH(SLOTS << `PIPELINE_WALKER_WORD_AW), .AW(AW)) ram_words (
        .clk(clk), .we(we), .wa({wa_hi, wa_lo}), .ra({ra_hi, ra_lo}), .wd(wd), .rd(rd), .overflow(overflow));
endmodule
