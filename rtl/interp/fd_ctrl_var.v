// Controller of the forward-difference evaluator with a per-interval length (modules/interp/
// fd_ctrl_var.h): fd_ctrl.v's FSM (fd_count.h) plus the interval's m. At acceptance (a rising edge
// where start = 1 and the evaluator is idle or on its last pixel) it reads len and m, selects LOAD
// and sets setup_sel = m - MMIN, the set-up multiplexers' select, held until the next acceptance:
// the registers take that m's set-up at the falling edge after. Then STEP for len - 1 clocks, then
// HOLD. m = 0 is the pipeline's exact pixel (len 1, A = B = C = 0: P(0) = D whatever the set-up),
// so it takes MMIN's set-up. Bad input, as the SystemC model (which also reports it): m neither 0
// nor MMIN..MMAX is taken as m = MMAX; then len outside 1..2^m as a full interval of 2^m pixels.
// No reset pin: the state starts idle (initial values, as the SystemC members and signals do).
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_ctrl_var #(
    parameter MMIN = `INTERP_M_MIN,
    parameter MMAX = `INTERP_M_MAX,
    parameter WL = MMAX + 1,                               // interp::len_width(MMAX)
    parameter WM = (MMAX + 1 > 2 ? $clog2(MMAX + 1) : 1),  // interp::code_width(MMAX + 1): codes 0..MMAX
    parameter LENGTHS = MMAX - MMIN + 1,                   // set-up networks per difference
    parameter W_SETUP = (LENGTHS > 2 ? $clog2(LENGTHS) : 1),
    parameter W_SEL = (`INTERP_FD_MX_INPUTS > 2 ? $clog2(`INTERP_FD_MX_INPUTS) : 1)
) (
    input  wire               clk,
    input  wire               start,
    input  wire [WL-1:0]      len,
    input  wire [WM-1:0]      m,
    output reg  [W_SEL-1:0]   fd_sel = {W_SEL{1'b0}},        // the SystemC signal starts at 0 (hold)
    output reg  [W_SETUP-1:0] setup_sel = {W_SETUP{1'b0}},  // m - MMIN of the interval last accepted
    output wire [WL-1:0]      pixel,  // index k of the pixel on its way out
    output wire               valid,
    output wire               last
);
    localparam [WL-1:0] ZERO = {WL{1'b0}};
    localparam [WL-1:0] ONE = {{(WL-1){1'b0}}, 1'b1};
    localparam [WM-1:0] M_ZERO = {WM{1'b0}};
    localparam [WM-1:0] M_LO = MMIN[WM-1:0], M_HI = MMAX[WM-1:0];
    localparam [W_SEL-1:0] HOLD = `INTERP_FD_SEL_HOLD, LOAD = `INTERP_FD_SEL_LOAD, STEP = `INTERP_FD_SEL_STEP;

    reg [WL-1:0] remaining = ZERO;  // pixels of the interval not yet out, this clock's included
    reg [WL-1:0] length = ZERO;     // of the interval last accepted

    // fd_ctrl_var::accept: m checked first, then len against 2^m (checked_len).
    wire accept = start && remaining <= ONE;
    wire [WM-1:0] m_used = (m != M_ZERO && (m < M_LO || m > M_HI)) ? M_HI : m;
    wire [WL-1:0] n_pixels = ONE << m_used;
    wire [WL-1:0] checked_len = (len != ZERO && len <= n_pixels) ? len : n_pixels;
    /* verilator lint_off UNUSEDSIGNAL */  // wires above setup_sel's are 0 (m_used <= MMAX)
    wire [WM-1:0] m_offset = m_used == M_ZERO ? M_ZERO : m_used - M_LO;
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk) begin
        if (accept) begin
            length <= checked_len;
            remaining <= checked_len;
            setup_sel <= m_offset[W_SETUP-1:0];
            fd_sel <= LOAD;
        end else if (remaining > ONE) begin
            remaining <= remaining - ONE;
            fd_sel <= STEP;
        end else begin
            remaining <= ZERO;
            fd_sel <= HOLD;
        end
    end

    assign valid = remaining != ZERO;
    assign last = remaining == ONE;
    assign pixel = valid ? length - remaining : ZERO;
endmodule
