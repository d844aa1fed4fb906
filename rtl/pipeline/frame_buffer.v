// Frame buffer of the shading pipeline (ours; modules/pipeline/frame_buffer.h): the block library's
// RAM of PITCH x HEIGHT words of `PIPELINE_FRAME_WORD_W bits, {r, g, b} (three pixel codes, r on the
// high wires), PITCH the width rounded up to a power of two so that the word of (x, y) is at {y, x}:
// wiring, no multiplier. Its write port is the pixel stream: at a rising edge of clk where `valid`
// is 1 it stores r, g, b at (x, y). The frame check (x <= WIDTH - 1, y <= HEIGHT - 1) gates the
// RAM's write enable: a write outside the frame is dropped and sets a sticky flip-flop; `overflow`
// is it or the RAM's own flag (a dropped write of either kind). Read port: the word at address `ra`
// ({y, x}), at once, for a testbench to read the frame back (the SystemC model reads through its
// back door). WIDTH, HEIGHT >= 2. No reset pin, as the SystemC model: words and flag start at 0.
//   in_x, in_y    le_const: the frame check
//   ram_frame     ram: PITCH x HEIGHT words
`include "shading_formats.vh"
`include "interp_terms.vh"
module frame_buffer #(
    parameter WIDTH = 64,
    parameter HEIGHT = 64,
    parameter XW = $clog2(WIDTH),   // x's address wires: PITCH = 2^XW
    parameter YW = $clog2(HEIGHT),
    parameter AW = XW + YW
) (
    input  wire clk,
    input  wire valid,
    input  wire [`PIPELINE_PINS_COORD_W-1:0] x,
    input  wire [`PIPELINE_PINS_COORD_W-1:0] y,
    input  wire [`PIPELINE_PIXEL_W-1:0] r,
    input  wire [`PIPELINE_PIXEL_W-1:0] g,
    input  wire [`PIPELINE_PIXEL_W-1:0] b,
    input  wire [AW-1:0] ra,
    output wire [`PIPELINE_FRAME_WORD_W-1:0] rd,
    output wire overflow
);
    localparam integer DEPTH = HEIGHT << XW;
    // Nets.
    wire x_in, y_in, mem_we, mem_overflow;
    wire [AW-1:0] mem_wa = {y[YW-1:0], x[XW-1:0]};
    wire [`PIPELINE_FRAME_WORD_W-1:0] mem_wd = {r, g, b};
    reg out_of_frame = 1'b0;

    // Blocks.
    le_const #(.W(`PIPELINE_PINS_COORD_W), .K(WIDTH - 1)) in_x (.x(x), .y(x_in));
    le_const #(.W(`PIPELINE_PINS_COORD_W), .K(HEIGHT - 1)) in_y (.x(y), .y(y_in));
    assign mem_we = valid & x_in & y_in;
    always @(posedge clk) if (valid && !(x_in && y_in)) out_of_frame <= 1'b1;
    ram #(.W(`PIPELINE_FRAME_WORD_W), .DEPTH(DEPTH), .AW(AW)) ram_frame (
        .clk(clk), .we(mem_we), .wa(mem_wa), .ra(ra), .wd(mem_wd), .rd(rd), .overflow(mem_overflow));
    assign overflow = out_of_frame | mem_overflow;
endmodule
