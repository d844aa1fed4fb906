// Forward-difference evaluator for intervals of any length 2^m, m in MMIN..MMAX, chosen per interval
// (ours; modules/interp/fd_eval_var.h): fd_eval.v's registers, adders, pins and timing, the same
// recurrence  P <- P + D1,  D1 <- D1 + D2,  D2 <- D2 + D3  (fd_recurrence.vh), one pixel per clock.
// Only the set-up depends on m: per m one set of fd_eval's shift-and-add networks (fd_setup.h's
// tables, generated into interp_terms.vh), in generate block setup_m[i] for m = MMIN + i (the SystemC
// model's setup_d1_m<m> ... ), and per difference a multiplexer mx_setup_d1..3 on setup_sel =
// m - MMIN (fd_ctrl_var.v, which latches m with len at acceptance) feeding the register's load
// input. Pins: fd_eval's plus m (codes 0..MMAX; 0 is an exact pixel, len 1). Formats as fd_eval.v.
// This module only instantiates and wires; the SystemC model's clock-phase monitor chk_clock is not
// hardware and has no counterpart here.
`include "shading_formats.vh"
`include "interp_terms.vh"
module fd_eval_var #(
    parameter MMIN = `INTERP_M_MIN,
    parameter MMAX = `INTERP_M_MAX,
    parameter WL = MMAX + 1,                               // interp::len_width(MMAX)
    parameter WM = (MMAX + 1 > 2 ? $clog2(MMAX + 1) : 1),  // interp::code_width(MMAX + 1)
    parameter WC = `INTERP_COEF_W,
    parameter W_SEL = (`INTERP_FD_MX_INPUTS > 2 ? $clog2(`INTERP_FD_MX_INPUTS) : 1)
) (
    input  wire          clk,
    input  wire          start,
    input  wire [WL-1:0] len,
    input  wire [WM-1:0] m,
    input  wire [WC-1:0] a,
    input  wire [WC-1:0] b,
    input  wire [WC-1:0] c,
    input  wire [WC-1:0] d,
    output wire [WC-1:0] i_px,
    output wire          valid,
    output wire          last
);
    localparam WF = `INTERP_FD_W;  // Q22.34
    localparam S = `INTERP_FD_ALIGN;  // Q.16 -> Q.34
    localparam NX = `INTERP_FD_MX_INPUTS;
    localparam LENGTHS = MMAX - MMIN + 1;  // set-up networks per difference
    localparam W_SETUP = (LENGTHS > 2 ? $clog2(LENGTHS) : 1);
    // fd_setup.h's terms of every m of the format (interp::m_min..m_max); each network cuts its m's.
    localparam N1 = `INTERP_FD_D1_N, N2 = `INTERP_FD_D2_N, N3 = `INTERP_FD_D3_N;
    localparam ALL_LENGTHS = `INTERP_M_MAX - `INTERP_M_MIN + 1;
    localparam [16*N1*ALL_LENGTHS-1:0] ALL1 = `INTERP_FD_D1;
    localparam [16*N2*ALL_LENGTHS-1:0] ALL2 = `INTERP_FD_D2;
    localparam [16*N3*ALL_LENGTHS-1:0] ALL3 = `INTERP_FD_D3;

    // Nets, as fd_eval_var.h names them. init_dK_m: the set-up of difference K for every m (m =
    // MMIN + i at [i*WF +: WF], the set-up multiplexer's input i); init_dK: the one selected.
    wire [LENGTHS*WF-1:0] init_d1_m, init_d2_m, init_d3_m;
    wire [WF-1:0] init_p, init_d1, init_d2, init_d3;
    wire [WF-1:0] p_value, d1_value, d2_value, d3_value;
    wire [WF-1:0] p_next, d1_next, d2_next;
    wire [WF-1:0] p_sum, d1_sum, d2_sum, d3_keep;
    wire [W_SEL-1:0] fd_sel;
    wire [W_SETUP-1:0] setup_sel;
    wire [WL-1:0] pixel;
    wire carry0;

    // Set-up: D is m-independent; D1..D3 per m (inputs: 0 = A, 1 = B, 2 = C) and a mux each.
    shifter #(.WIN(WC), .WOUT(WF), .IN_SIGNED(1), .SHIFT(S)) setup_p (.x(d), .y(init_p));
    genvar i;
    generate
        for (i = 0; i < LENGTHS; i = i + 1) begin : setup_m
            localparam AT = MMIN + i - `INTERP_M_MIN;  // this m's place in the tables
            localparam [16*N1-1:0] T1 = ALL1[16*N1*AT +: 16*N1];
            localparam [16*N2-1:0] T2 = ALL2[16*N2*AT +: 16*N2];
            localparam [16*N3-1:0] T3 = ALL3[16*N3*AT +: 16*N3];
            shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(3), .NT(N1), .SLOTS(N1), .TERMS(T1)) setup_d1 (
                .in({c, b, a}), .y(init_d1_m[i*WF +: WF]));  // A/N^3 + B/N^2 + C/N
            shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(2), .NT(N2), .SLOTS(N2), .TERMS(T2)) setup_d2 (
                .in({b, a}), .y(init_d2_m[i*WF +: WF]));  // (4A + 2A)/N^3 + 2B/N^2
            shift_add_network #(.WIN(WC), .W(WF), .IN_SIGNED(1), .NIN(1), .NT(N3), .SLOTS(N3), .TERMS(T3)) setup_d3 (
                .in(a), .y(init_d3_m[i*WF +: WF]));  // (4A + 2A)/N^3
        end
    endgenerate
    mux #(.W(WF), .N(LENGTHS), .SW(W_SETUP)) mx_setup_d1 (.in(init_d1_m), .sel(setup_sel), .y(init_d1));
    mux #(.W(WF), .N(LENGTHS), .SW(W_SETUP)) mx_setup_d2 (.in(init_d2_m), .sel(setup_sel), .y(init_d2));
    mux #(.W(WF), .N(LENGTHS), .SW(W_SETUP)) mx_setup_d3 (.in(init_d3_m), .sel(setup_sel), .y(init_d3));

    // The recurrence (wire_fd_recurrence in fd_eval.h), as in fd_eval.v.
    `include "fd_recurrence.vh"

    fd_ctrl_var #(.MMIN(MMIN), .MMAX(MMAX), .WL(WL), .WM(WM), .LENGTHS(LENGTHS), .W_SETUP(W_SETUP), .W_SEL(W_SEL)) ctrl (
        .clk(clk), .start(start), .len(len), .m(m), .fd_sel(fd_sel), .setup_sel(setup_sel), .pixel(pixel),
        .valid(valid), .last(last));
    wire unused_ok = &{1'b0, pixel, 1'b0};  // the pixel index is for the waveform
endmodule
