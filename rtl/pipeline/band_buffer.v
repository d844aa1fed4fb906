// The cells' band buffer (ours; modules/pipeline/cell_stores.h's band_buffer): the block library's
// RAM of LINES x PITCH words of `PIPELINE_BAND_WORD_W bits ({r, g, b} colour samples), PITCH the
// frame width rounded up to a power of two, the sample at line offset l (from the band's top) and x
// at {l, x}: wiring, no multiplier. An offset beyond LINES is an address beyond the RAM's words:
// the write dropped, `overflow` set (the RAM's flag). x on 16 wires as the pixel coordinates, of
// which the pitch's low XW address the RAM (the geometry side sends x < WIDTH). LINES defaults to
// the format's capacity (cell_store_formats.h). WIDTH >= 2.
//   ram_words  ram: LINES x PITCH words
`include "shading_formats.vh"
module band_buffer #(
    parameter WIDTH = 512,
    parameter LINES = `PIPELINE_BAND_LINES,
    parameter XW = $clog2(WIDTH)  // PITCH = 2^XW
) (
    input  wire clk,
    input  wire we,
    input  wire [`PIPELINE_BAND_LINE_W-1:0] wa_hi,
    input  wire [15:0] wa_lo,
    input  wire [`PIPELINE_BAND_LINE_W-1:0] ra_hi,
    input  wire [15:0] ra_lo,
    input  wire [`PIPELINE_BAND_WORD_W-1:0] wd,
    output wire [`PIPELINE_BAND_WORD_W-1:0] rd,
    output wire overflow
);
    localparam integer AW = `PIPELINE_BAND_LINE_W + XW;
    // x's wires above the pitch's: no RAM address.
    wire unused_ok = &{1'b0, wa_lo[15:XW], ra_lo[15:XW], 1'b0};
    ram #(.W(`PIPELINE_BAND_WORD_W), .DEPTH(LINES << XW), .AW(AW)) ram_words (
        .clk(clk), .we(we), .wa({wa_hi, wa_lo[XW-1:0]}), .ra({ra_hi, ra_lo[XW-1:0]}), .wd(wd), .rd(rd),
        .overflow(overflow));
endmodule
