// Pixel controller for the Horner evaluators (ours; modules/pipeline/horner_pixel_ctrl.h; the
// interpolation paper leaves the control open): a clocked FSM on the rising edge of clk that takes an
// interval from the sample stage and issues its pixels to the three channels' Fig. 4 Horner units,
// pixel k at t = k << (8 - m) (t = k / 2^m, Q1.8).
// - Hand-over: with samples_ready = 1 and the interval registers free it raises ld_e for one clock
//   and captures the descriptor (y, x0, len, m, deg2); the interval registers latch where ld_e
//   falls, the coefficient units' registers half a clock later.
// - The registers are free once the previous interval's last pixel is in its last two micro-steps:
//   its last read of D (cubic step 6) or C (degree 2, step 4) is at the falling edge where the
//   coefficient registers latch the new samples, whose values arrive after that edge (in the RTL:
//   the registers' nonblocking update), so intervals follow each other with no idle clock.
// - Pixels: start follows horner_ctrl's rule (taken at a rising edge where start = 1 and the unit
//   is idle or done); at the taking edge t, px_x and px_y are set for that pixel, and deg2 / deg_sel
//   at an interval's first pixel.
// The next state is computed in the SystemC method's order (the taking first, the hand-over then
// reading what the taking left), all from the values before the edge; the registers take it at the
// rising edge. No reset pin: every register starts at 0, as the SystemC members and signals do. The
// SystemC model's bookkeeping for its testbench (in_flight_, intervals_) is not hardware.
`include "shading_formats.vh"
`include "interp_terms.vh"
module horner_pixel_ctrl #(
    parameter WX = `PIPELINE_PINS_COORD_W,  // x, y
    parameter WN = `PIPELINE_PINS_LEN_W,    // the job's len
    parameter WM = `PIPELINE_PINS_M_W,      // the job's m
    parameter WT = `INTERP_T_W,
    parameter W_STEP = (`INTERP_HORNER_STEP_CODES > 2 ? $clog2(`INTERP_HORNER_STEP_CODES) : 1)
) (
    input  wire          clk,
    input  wire          samples_ready,
    input  wire [WX-1:0] y,
    input  wire [WX-1:0] x0,
    input  wire [WN-1:0] len,
    input  wire [WM-1:0] m,
    input  wire          deg2_in,
    input  wire          busy,  // channel R's Horner unit (the three run in step)
    input  wire          done,
    output reg           ld_e = 1'b0,
    output reg           start = 1'b0,
    output reg           deg2 = 1'b0,
    output reg           deg_sel = 1'b0,
    output reg  [WT-1:0] t = {WT{1'b0}},
    output reg  [WX-1:0] px_x = {WX{1'b0}},
    output reg  [WX-1:0] px_y = {WX{1'b0}}
);
    // Clocks from the taking edge of an interval's last pixel until the interval registers are free:
    // its micro-steps less the last two (horner_pixel_ctrl.h).
    localparam TAIL = 2;
    localparam [W_STEP-1:0] FREE_CUBIC = `INTERP_HORNER_STEPS_CUBIC - TAIL;
    localparam [W_STEP-1:0] FREE_QUAD = `INTERP_HORNER_STEPS_QUAD - TAIL;
    localparam [W_STEP-1:0] STEP_ZERO = {W_STEP{1'b0}}, STEP_ONE = {{(W_STEP-1){1'b0}}, 1'b1};
    localparam [WN-1:0] LEN_ONE = {{(WN-1){1'b0}}, 1'b1};

    // The intervals: cur (issuing pixels), pend (in the interval registers, waiting), captured (the
    // descriptor taken with ld_e). pend's and captured's issued count is always 0, captured's active
    // flag always 1 where it is read: neither is a register.
    reg cur_active = 1'b0, cur_deg2 = 1'b0;
    reg [WX-1:0] cur_y = {WX{1'b0}}, cur_x0 = {WX{1'b0}};
    // cur_issued counts as the SystemC model's unsigned for every len but 0 (dropped before).
    reg [WN-1:0] cur_len = {WN{1'b0}}, cur_issued = {WN{1'b0}};
    reg [WM-1:0] cur_m = {WM{1'b0}};
    reg pend_active = 1'b0, pend_deg2 = 1'b0;
    reg [WX-1:0] pend_y = {WX{1'b0}}, pend_x0 = {WX{1'b0}};
    reg [WN-1:0] pend_len = {WN{1'b0}};
    reg [WM-1:0] pend_m = {WM{1'b0}};
    reg cap_deg2 = 1'b0;
    reg [WX-1:0] cap_y = {WX{1'b0}}, cap_x0 = {WX{1'b0}};
    reg [WN-1:0] cap_len = {WN{1'b0}};
    reg [WM-1:0] cap_m = {WM{1'b0}};
    reg [W_STEP-1:0] free_in = STEP_ZERO;  // clocks until the interval registers are free

    // Next state.
    reg cur_active_n, cur_deg2_n;
    reg [WX-1:0] cur_y_n, cur_x0_n;
    reg [WN-1:0] cur_len_n, cur_issued_n;
    reg [WM-1:0] cur_m_n;
    reg pend_active_n, pend_deg2_n;
    reg [WX-1:0] pend_y_n, pend_x0_n;
    reg [WN-1:0] pend_len_n;
    reg [WM-1:0] pend_m_n;
    reg cap_deg2_n;
    reg [WX-1:0] cap_y_n, cap_x0_n;
    reg [WN-1:0] cap_len_n;
    reg [WM-1:0] cap_m_n;
    reg [W_STEP-1:0] free_in_n;
    reg ld_e_n, start_n, deg2_n, deg_sel_n;
    reg [WT-1:0] t_n;
    reg [WX-1:0] px_x_n, px_y_n;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [WN-1:0] t_wide;  // issued << (8 - m); t takes its low wires (the SystemC t_t conversion)
    /* verilator lint_on UNUSEDSIGNAL */

    always @(*) begin
        cur_active_n = cur_active; cur_deg2_n = cur_deg2; cur_y_n = cur_y; cur_x0_n = cur_x0;
        cur_len_n = cur_len; cur_issued_n = cur_issued; cur_m_n = cur_m;
        pend_active_n = pend_active; pend_deg2_n = pend_deg2; pend_y_n = pend_y; pend_x0_n = pend_x0;
        pend_len_n = pend_len; pend_m_n = pend_m;
        cap_deg2_n = cap_deg2; cap_y_n = cap_y; cap_x0_n = cap_x0; cap_len_n = cap_len; cap_m_n = cap_m;
        free_in_n = free_in;
        ld_e_n = ld_e; start_n = start; deg2_n = deg2; deg_sel_n = deg_sel;
        t_n = t; px_x_n = px_x; px_y_n = px_y;
        t_wide = {WN{1'b0}};
        // A pixel is taken here (horner_ctrl's rule, read before this edge).
        if (start && (!busy || done)) begin
            if (cur_issued == cur_len && pend_active) begin  // the interval's first pixel
                cur_active_n = 1'b1; cur_deg2_n = pend_deg2; cur_y_n = pend_y; cur_x0_n = pend_x0;
                cur_len_n = pend_len; cur_m_n = pend_m; cur_issued_n = {WN{1'b0}};
                pend_active_n = 1'b0;
                deg2_n = pend_deg2;
                deg_sel_n = pend_deg2;
            end
            t_wide = cur_issued_n << (`INTERP_T_FRAC - {{(32-WM){1'b0}}, cur_m_n});
            t_n = t_wide[WT-1:0];
            px_x_n = cur_x0_n + cur_issued_n[WX-1:0];
            px_y_n = cur_y_n;
            cur_issued_n = cur_issued_n + LEN_ONE;
            if (cur_issued_n == cur_len_n) begin  // its last pixel
                cur_active_n = 1'b0;
                free_in_n = cur_deg2_n ? FREE_QUAD : FREE_CUBIC;
            end
            start_n = cur_active_n || pend_active_n;
        end else if (free_in != STEP_ZERO) begin
            free_in_n = free_in - STEP_ONE;
        end
        // Interval hand-over, reading what the taking left.
        if (ld_e) begin
            ld_e_n = 1'b0;  // the interval registers latch now
            pend_active_n = 1'b1; pend_deg2_n = cap_deg2; pend_y_n = cap_y; pend_x0_n = cap_x0;
            pend_len_n = cap_len; pend_m_n = cap_m;
            start_n = 1'b1;
        end else if (samples_ready && !pend_active_n && !cur_active_n && free_in_n == STEP_ZERO) begin
            ld_e_n = 1'b1;
            cap_deg2_n = deg2_in; cap_y_n = y; cap_x0_n = x0; cap_len_n = len; cap_m_n = m;
        end
    end

    always @(posedge clk) begin
        cur_active <= cur_active_n; cur_deg2 <= cur_deg2_n; cur_y <= cur_y_n; cur_x0 <= cur_x0_n;
        cur_len <= cur_len_n; cur_issued <= cur_issued_n; cur_m <= cur_m_n;
        pend_active <= pend_active_n; pend_deg2 <= pend_deg2_n; pend_y <= pend_y_n; pend_x0 <= pend_x0_n;
        pend_len <= pend_len_n; pend_m <= pend_m_n;
        cap_deg2 <= cap_deg2_n; cap_y <= cap_y_n; cap_x0 <= cap_x0_n; cap_len <= cap_len_n; cap_m <= cap_m_n;
        free_in <= free_in_n;
        ld_e <= ld_e_n; start <= start_n; deg2 <= deg2_n; deg_sel <= deg_sel_n;
        t <= t_n; px_x <= px_x_n; px_y <= px_y_n;
    end
endmodule
