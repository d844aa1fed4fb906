// N-input multiplexer, W bits wide, as modules/blocks/mux.h: y = in[sel]. Verilog-2005 has no
// array ports: input i is wires i*W .. i*W+W-1 of the flat bus `in`. Select codes >= N (possible
// when N is not a power of two) drive all wires to 0. SW = the select width select_width(N).
module mux #(
    parameter W = 8,
    parameter N = 2,
    parameter SW = 1
) (
    input  wire [N*W-1:0] in,
    input  wire [SW-1:0]  sel,
    output reg  [W-1:0]   y
);
    integer i;
    always @* begin
        y = {W{1'b0}};
        for (i = 0; i < N; i = i + 1)
            if ({{(32-SW){1'b0}}, sel} == i) y = in[i*W +: W];
    end
endmodule
