// UA 22802's generator of `a`, as modules/ua22802/a_gen_rom.h: RG1 addresses a ROM holding a(n)
// (Q10.6, 1024 words), whose word drives MUL10 directly. The ROM is the case table
// ua22802_a_rom.v that src/tools/gen_rtl.cpp generates from the same formula and rounding as the
// SystemC ROM's content (in the build tree: generated/rtl/).
`include "shading_formats.vh"
module a_gen_rom (
    input  wire [`UA22802_ADDR_W-1:0] n,
    output wire [`UA22802_A_W-1:0]    a
);
    ua22802_a_rom rom (.addr(n), .data(a));  // n (10.0) -> a (Q10.6)
endmodule
