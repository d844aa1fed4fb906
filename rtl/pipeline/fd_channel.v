// One colour channel's evaluator with forward differences (ours; modules/pipeline/fd_channel.h), the
// alternative to the Horner unit behind the same pins: fd_eval (rtl/interp/fd_eval.v) built for
// the interval length 2^FIXED_M, or (FIXED_M = 0) fd_eval_var with MMIN..MMAX = interp::m_min..m_max,
// whose length 2^m comes with each interval on pin m. A quadratic a t^2 + b t + c is evaluated as
// the cubic A = 0, B = a, C = b, D = c: the degree-select pin switches mx_a..mx_d between the cubic
// unit's A..D and (0, a, b, c). out_clamp as in horner_channel.v. Only instantiates and wires.
// The evaluator `fd` sits in generate block any_m (FIXED_M = 0) or fixed_m (with len_wires and the net
// fd_len: the M + 1 low wires of len, as the SystemC channel builds them).
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_channel #(
    parameter FIXED_M = 4,            // fd_channel.h's fixed_m: 2..6 fd_eval<M>; 0 fd_eval_var
    parameter WC = `INTERP_COEF_W,    // A..D, a..c, the pixel before the clamp: Q16.16 signed
    parameter WI = `INTERP_SAMPLE_W,  // the pixel: Q8.8 unsigned
    parameter WL = `INTERP_FD_LEN_W,  // len, wide enough for every m
    parameter WM = `INTERP_FD_M_W     // m: 0 (exact pixel), m_min..m_max
) (
    input  wire          clk,
    input  wire          start,
    input  wire          deg_sel,
    input  wire [WL-1:0] len,
    input  wire [WM-1:0] m,  // read by fd_eval_var only (fd_eval is built for its M)
    input  wire [WC-1:0] ca,
    input  wire [WC-1:0] cb,
    input  wire [WC-1:0] cc,
    input  wire [WC-1:0] cd,
    input  wire [WC-1:0] qa,
    input  wire [WC-1:0] qb,
    input  wire [WC-1:0] qc,
    output wire [WI-1:0] px,
    output wire          valid,
    output wire          last
);
    // fd_channel.h's switch: 2..5 as given, anything else but 0 builds m_max's (the pipeline checks m).
    localparam M_FIXED = (FIXED_M >= `INTERP_M_MIN && FIXED_M < `INTERP_M_MAX) ? FIXED_M : `INTERP_M_MAX;

    // Nets.
    wire [WC-1:0] a, b, c, d, i_px, zero_word;

    // Blocks: input 0 the cubic's coefficient, input 1 the quadratic's (or 0 for A).
    constant #(.W(WC), .VALUE(0)) k_zero (.y(zero_word));
    mux #(.W(WC), .N(2), .SW(1)) mx_a (.in({zero_word, ca}), .sel(deg_sel), .y(a));
    mux #(.W(WC), .N(2), .SW(1)) mx_b (.in({qa, cb}), .sel(deg_sel), .y(b));
    mux #(.W(WC), .N(2), .SW(1)) mx_c (.in({qb, cc}), .sel(deg_sel), .y(c));
    mux #(.W(WC), .N(2), .SW(1)) mx_d (.in({qc, cd}), .sel(deg_sel), .y(d));
    generate
        if (FIXED_M == 0) begin : any_m
            fd_eval_var #(.MMIN(`INTERP_M_MIN), .MMAX(`INTERP_M_MAX), .WL(WL), .WM(WM), .WC(WC)) fd (
                .clk(clk), .start(start), .len(len), .m(m), .a(a), .b(b), .c(c), .d(d), .i_px(i_px),
                .valid(valid), .last(last));
        end else begin : fixed_m
            wire [M_FIXED:0] fd_len;  // interp::len_width(M) = M + 1 wires
            shifter #(.WIN(WL), .WOUT(M_FIXED + 1), .IN_SIGNED(0), .SHIFT(0)) len_wires (.x(len), .y(fd_len));
            fd_eval #(.M(M_FIXED), .WC(WC)) fd (
                .clk(clk), .start(start), .len(fd_len), .a(a), .b(b), .c(c), .d(d), .i_px(i_px), .valid(valid),
                .last(last));
            wire unused_ok = &{1'b0, m, 1'b0};
        end
    endgenerate
    clamp #(.WIN(WC), .WOUT(WI), .DROP(`INTERP_COEF_FRAC - `INTERP_SAMPLE_FRAC), .IN_SIGNED(1)) out_clamp (
        .x(i_px), .y(px));
endmodule
