// Pixel controller for the forward-difference evaluators (ours, like the evaluator; modules/pipeline/
// fd_pixel_ctrl.h): a clocked FSM on the rising edge of clk. Interval hand-over as in
// horner_pixel_ctrl.v (ld_e for one clock, the descriptor captured where it rises); where ld_e falls
// it sets deg_sel, len, m and start for the interval now in the interval registers. fd_ctrl takes
// it at a rising edge where start = 1 and the evaluator is idle or on its last pixel (valid = 0 or
// last = 1, channel R's, read before the edge) and loads A..D at the falling edge after: from then
// on the interval registers are free, so the next hand-over starts at that same taking edge. Pixel
// k of an interval taken at edge E is on the output at E + (k + 1) clocks; px_x / px_y are set one
// clock before, so the frame buffer reads them with the pixel.
// The next state is computed in the SystemC method's order (the taking first, the hand-over then
// reading what the taking left), all from the values before the edge; the registers take it at the
// rising edge. No reset pin: every register starts at 0, as the SystemC members and signals do. Of
// the SystemC model's current interval only x0 is read after its taking edge, so only it is a
// register here; intervals_ is the testbench's count, not hardware.
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_pixel_ctrl #(
    parameter WX = `PIPELINE_PINS_COORD_W,  // x, y
    parameter WN = `PIPELINE_PINS_LEN_W,    // the job's len
    parameter WMI = `PIPELINE_PINS_M_W,     // the job's m
    parameter WL = `INTERP_FD_LEN_W,        // the evaluators' len
    parameter WM = `INTERP_FD_M_W           // the evaluators' m (fd_eval_var)
) (
    input  wire           clk,
    input  wire           samples_ready,
    input  wire [WX-1:0]  y,
    input  wire [WX-1:0]  x0,
    input  wire [WN-1:0]  len_in,
    input  wire [WMI-1:0] m_in,
    input  wire           deg2_in,
    input  wire           valid,  // channel R's evaluator (the three run in step)
    input  wire           last,
    output reg            ld_e = 1'b0,
    output reg            start = 1'b0,
    output reg            deg_sel = 1'b0,
    output reg  [WL-1:0]  len = {WL{1'b0}},
    output reg  [WM-1:0]  m = {WM{1'b0}},  // for fd_eval_var: the interval's length 2^m
    output reg  [WX-1:0]  px_x = {WX{1'b0}},
    output reg  [WX-1:0]  px_y = {WX{1'b0}}
);
    localparam [WN-1:0] ZERO = {WN{1'b0}}, ONE = {{(WN-1){1'b0}}, 1'b1};

    // The intervals: pend (in the interval registers, waiting for fd_ctrl; its deg2 and m go out on
    // deg_sel and m where it is formed and are never read again, so they are no registers),
    // captured (the descriptor taken with ld_e; its active flag is always 1 where it is read), and
    // of the one being stepped its x0, the pixel index next and the pixels left.
    reg pend_active = 1'b0;
    reg [WX-1:0] pend_y = {WX{1'b0}}, pend_x0 = {WX{1'b0}};
    reg [WN-1:0] pend_len = ZERO;
    reg cap_deg2 = 1'b0;
    reg [WX-1:0] cap_y = {WX{1'b0}}, cap_x0 = {WX{1'b0}};
    reg [WN-1:0] cap_len = ZERO;
    reg [WMI-1:0] cap_m = {WMI{1'b0}};
    reg [WX-1:0] cur_x0 = {WX{1'b0}};
    // As the SystemC model's unsigned counters for every len but 0 (the sample stage drops len 0).
    reg [WN-1:0] next = ZERO, left = ZERO;

    // Next state.
    reg pend_active_n;
    reg [WX-1:0] pend_y_n, pend_x0_n;
    reg [WN-1:0] pend_len_n;
    reg cap_deg2_n;
    reg [WX-1:0] cap_y_n, cap_x0_n;
    reg [WN-1:0] cap_len_n;
    reg [WMI-1:0] cap_m_n;
    reg [WX-1:0] cur_x0_n;
    reg [WN-1:0] next_n, left_n;
    reg ld_e_n, start_n, deg_sel_n;
    reg [WL-1:0] len_n;
    reg [WM-1:0] m_n;
    reg [WX-1:0] px_x_n, px_y_n;

    always @(*) begin
        pend_active_n = pend_active; pend_y_n = pend_y; pend_x0_n = pend_x0; pend_len_n = pend_len;
        cap_deg2_n = cap_deg2; cap_y_n = cap_y; cap_x0_n = cap_x0; cap_len_n = cap_len; cap_m_n = cap_m;
        cur_x0_n = cur_x0; next_n = next; left_n = left;
        ld_e_n = ld_e; start_n = start; deg_sel_n = deg_sel; len_n = len; m_n = m;
        px_x_n = px_x; px_y_n = px_y;
        if (start && (!valid || last)) begin  // fd_ctrl takes the pending interval here
            cur_x0_n = pend_x0;
            pend_active_n = 1'b0;
            start_n = 1'b0;
            px_x_n = pend_x0;
            px_y_n = pend_y;
            next_n = ONE;
            left_n = pend_len - ONE;
        end else if (left != ZERO) begin  // the next pixel of the interval
            px_x_n = cur_x0 + next[WX-1:0];
            next_n = next + ONE;
            left_n = left - ONE;
        end
        // Interval hand-over, reading what the taking left.
        if (ld_e) begin
            ld_e_n = 1'b0;  // the interval registers latch now
            pend_active_n = 1'b1; pend_y_n = cap_y; pend_x0_n = cap_x0; pend_len_n = cap_len;
            deg_sel_n = cap_deg2;
            len_n = cap_len[WL-1:0];  // the SystemC len_t / m_t conversions: the low wires
            m_n = cap_m[WM-1:0];
            start_n = 1'b1;
        end else if (samples_ready && !pend_active_n) begin
            ld_e_n = 1'b1;
            cap_deg2_n = deg2_in; cap_y_n = y; cap_x0_n = x0; cap_len_n = len_in; cap_m_n = m_in;
        end
    end

    always @(posedge clk) begin
        pend_active <= pend_active_n; pend_y <= pend_y_n; pend_x0 <= pend_x0_n; pend_len <= pend_len_n;
        cap_deg2 <= cap_deg2_n; cap_y <= cap_y_n; cap_x0 <= cap_x0_n; cap_len <= cap_len_n; cap_m <= cap_m_n;
        cur_x0 <= cur_x0_n; next <= next_n; left <= left_n;
        ld_e <= ld_e_n; start <= start_n; deg_sel <= deg_sel_n; len <= len_n; m <= m_n;
        px_x <= px_x_n; px_y <= px_y_n;
    end
endmodule
