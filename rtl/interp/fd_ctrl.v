// Controller of the forward-difference evaluator (modules/interp/fd_ctrl.h; its state machine is
// fd_count.h's): a clocked FSM on the rising edge of clk. `start` is a level "interval pending";
// an interval is accepted at a rising edge where start = 1 and the evaluator is idle (valid = 0) or
// on its last pixel (last = 1). There it reads len (1..2^M; 0 or above 2^M: a full interval, which
// the SystemC model also reports) and selects LOAD, so the registers take the set-up at the falling
// edge after; then STEP for len - 1 clocks, then HOLD. Pixel k is on the output at the rising edge
// acceptance + (k + 1) clocks. valid, last and pixel are decoded from the count register, so they
// change right after the rising edge, as the SystemC controller writes them. No reset pin, as the
// SystemC model: the state starts idle (initial values, as its members and signals do).
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_ctrl #(
    parameter M = 4,
    parameter WL = M + 1,  // interp::len_width(M): 1..2^M
    parameter W_SEL = (`INTERP_FD_MX_INPUTS > 2 ? $clog2(`INTERP_FD_MX_INPUTS) : 1)
) (
    input  wire             clk,
    input  wire             start,
    input  wire [WL-1:0]    len,
    output reg  [W_SEL-1:0] fd_sel = {W_SEL{1'b0}},  // the SystemC signal starts at 0 (hold)
    output wire [WL-1:0]    pixel,  // index k of the pixel on its way out
    output wire             valid,
    output wire             last
);
    localparam [WL-1:0] ZERO = {WL{1'b0}};
    localparam [WL-1:0] ONE = {{(WL-1){1'b0}}, 1'b1};
    localparam [WL-1:0] N_PIXELS = ONE << M;
    localparam [W_SEL-1:0] HOLD = `INTERP_FD_SEL_HOLD, LOAD = `INTERP_FD_SEL_LOAD, STEP = `INTERP_FD_SEL_STEP;

    reg [WL-1:0] remaining = ZERO;  // pixels of the interval not yet out, this clock's included
    reg [WL-1:0] length = ZERO;     // of the interval last accepted

    // fd_count::rising: accepted while idle or on the last pixel; the length checked (checked_len).
    wire accept = start && remaining <= ONE;
    wire [WL-1:0] checked_len = (len != ZERO && len <= N_PIXELS) ? len : N_PIXELS;

    always @(posedge clk) begin
        if (accept) begin
            length <= checked_len;
            remaining <= checked_len;
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
