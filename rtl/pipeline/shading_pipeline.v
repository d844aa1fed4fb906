// The interpolation paper's shading system in hardware, as modules/pipeline/shading_pipeline.h with the
// square-and-multiply device (sqmul_device, the pipeline's default): a raster-line shading unit
// that takes one interval at a time from the geometry side and writes its pixels as an R, G, B
// stream. Pins as modules/pipeline/pipeline_pins.h (names, order); instances and nets as the
// SystemC model's members:
//   rg_y, rg_x0, rg_len, rg_m, rg_deg2, rg_nh1..4, rg_nl1..4   job registers (ld_job falls)
//   rg_dy, rg_dx0, rg_dlen, rg_dm, rg_ddeg2   the descriptor of the interval in the sample
//                  registers (ld_d falls at its last sample's latch), read by the pixel controller
//   mx_nh, mx_nl   the sample being formed (smp_sel); rg_lnh, rg_lnl the last sample's codes;
//   eq_nh, eq_nl, and_carry   the job's first codes are those (carry_hit; CARRY, ours)
//   dev            sqmul_device on clk, driven through UA 60553's Fig. 3 strobes ctl15..ctl24
//   rg_kd_*, rg_amb_*   the frame's k_d*I and ambient codes (ld_k)
//   smp_r/g/b      sample channels (sample_channel.v); horner_r/g/b or fd_r/g/b the evaluators
//   ctl_sample     sample controller (falling edges); ctl_pixel pixel controller (rising edges)
// Parameters: EVAL 0 the Horner unit (the interpolation paper, Fig. 4), 1 our forward
// differences; FD_M 0 any m per interval (fd_eval_var), else 2..6 (fd_eval<M>); SET 0 the
// cubic's sample set case 1, 1 case 2; DIV 0 the shift-add /3, 1 the exact one; CARRY 1 reuses
// the last sample's colour (ours); SATURATE the device's overflow mode (1 saturate, 0 wrap).
// The evaluators and the pixel controller sit in the generate block `evaluator` (Verilog scopes
// an if-generate): evaluator.horner_r, evaluator.ctl_pixel where the SystemC model has horner_r,
// ctl_pixel. Only instantiates and wires; every width from shading_formats.vh and interp_terms.vh
// (the job registers' widths: pipeline_pins.h). Co-simulated pin for pin with the SystemC pipeline
// (testbenches/rtl/test_rtl_pipeline.cpp).
`include "shading_formats.vh"
`include "interp_terms.vh"
module shading_pipeline #(
    parameter EVAL = 0,
    parameter FD_M = 4,
    parameter SET = 0,
    parameter DIV = 0,
    parameter CARRY = 0,
    parameter SATURATE = 1
) (
    // From the geometry side: the clock, the handshake (sample_ctrl.v) and one job's registers.
    input  wire clk,
    input  wire start, load_frame,
    output wire ready,
    input  wire [`PIPELINE_PINS_COORD_W-1:0] in_y, in_x0,
    input  wire [`PIPELINE_PINS_LEN_W-1:0]   in_len,
    input  wire [`PIPELINE_PINS_M_W-1:0]     in_m,
    input  wire                         in_deg2,
    input  wire [`SPEC_COS_W-1:0]       in_nh1, in_nh2, in_nh3, in_nh4,
    input  wire [`SPEC_COS_W-1:0]       in_nl1, in_nl2, in_nl3, in_nl4,
    // Frame constants.
    input  wire [`UA60553_N_W-1:0]      in_n,
    input  wire [`SPEC_KSI_W-1:0]       in_ksi_r, in_ksi_g, in_ksi_b,
    input  wire [`PIPELINE_KDI_W-1:0]   in_kdi_r, in_kdi_g, in_kdi_b,
    input  wire [`INTERP_SAMPLE_W-1:0]  in_amb_r, in_amb_g, in_amb_b,
    // Pixel stream: px_r/g/b (Q8.8 codes) belong at (px_x, px_y) at a rising edge where px_valid = 1.
    output wire                         px_valid,
    output wire [`PIPELINE_PINS_COORD_W-1:0] px_x, px_y,
    output wire [`INTERP_SAMPLE_W-1:0]  px_r, px_g, px_b
);
    localparam WCOS = `SPEC_COS_W;
    localparam WXY = `PIPELINE_PINS_COORD_W;
    localparam WLEN = `PIPELINE_PINS_LEN_W;
    localparam WM = `PIPELINE_PINS_M_W;
    localparam WK = `PIPELINE_KDI_W;
    localparam WI = `INTERP_SAMPLE_W;
    localparam WC = `INTERP_COEF_W;
    localparam WSEL = 2;  // smp_sel: one of the job's four samples

    // Nets, named as the SystemC model's.
    wire ld_job, ld_d, ld_k, samples_ready, ld_e;
    wire ctl15, ctl17, ctl20, ctl22, ctl24;
    wire out29_valid;
    wire ld_i1, ld_i2, ld_i3, ld_i4;
    wire [WXY-1:0] y, x0;
    wire [WLEN-1:0] len;
    wire [WM-1:0] m;
    wire deg2_job;
    wire [WXY-1:0] d_y, d_x0;  // the descriptor of the interval in I1..I4
    wire [WLEN-1:0] d_len;
    wire [WM-1:0] d_m;
    wire d_deg2;
    wire [WCOS-1:0] nh1, nh2, nh3, nh4, nl1, nl2, nl3, nl4;
    wire [WSEL-1:0] smp_sel;
    wire [WCOS-1:0] in18_cos, cos_nl;
    wire [WCOS-1:0] last_nh, last_nl;  // the last sample's codes
    wire ld_last, nh_hit, nl_hit, carry_hit;
    wire carry_sel;
    wire [`SPEC_OUT_W-1:0] out25_r, out26_g, out27_b;
    wire [WK-1:0] kdi_r, kdi_g, kdi_b;
    wire [WI-1:0] amb_r, amb_g, amb_b;
    wire [WC-1:0] ca_r, ca_g, ca_b, cb_r, cb_g, cb_b, cc_r, cc_g, cc_b, cd_r, cd_g, cd_b;
    wire [WC-1:0] qa_r, qa_g, qa_b, qb_r, qb_g, qb_b, qc_r, qc_g, qc_b;
    wire ev_start;
    wire deg_sel;
    // Horner: done, busy; forward differences: valid, last.
    wire ev_done_r, ev_done_g, ev_done_b, ev_busy_r, ev_busy_g, ev_busy_b;
    // Channels G and B run in step with R, whose flags the pixel controller reads: theirs are for
    // the waveform, as in the SystemC model.
    wire unused_ok = &{1'b0, ev_done_g, ev_done_b, ev_busy_g, ev_busy_b, 1'b0};

    // Job registers: latched where ld_job falls.
    reg_block #(.W(WXY)) rg_y (.ctl(ld_job), .d(in_y), .q(y));
    reg_block #(.W(WXY)) rg_x0 (.ctl(ld_job), .d(in_x0), .q(x0));
    reg_block #(.W(WLEN)) rg_len (.ctl(ld_job), .d(in_len), .q(len));
    reg_block #(.W(WM)) rg_m (.ctl(ld_job), .d(in_m), .q(m));
    reg_block #(.W(1)) rg_deg2 (.ctl(ld_job), .d(in_deg2), .q(deg2_job));
    // Descriptor registers: the job's y, x0, len, m, deg2 travel with its samples (ld_d falls at
    // the last sample's latch), so the job registers are free for the next job.
    reg_block #(.W(WXY)) rg_dy (.ctl(ld_d), .d(y), .q(d_y));
    reg_block #(.W(WXY)) rg_dx0 (.ctl(ld_d), .d(x0), .q(d_x0));
    reg_block #(.W(WLEN)) rg_dlen (.ctl(ld_d), .d(len), .q(d_len));
    reg_block #(.W(WM)) rg_dm (.ctl(ld_d), .d(m), .q(d_m));
    reg_block #(.W(1)) rg_ddeg2 (.ctl(ld_d), .d(deg2_job), .q(d_deg2));
    reg_block #(.W(WCOS)) rg_nh1 (.ctl(ld_job), .d(in_nh1), .q(nh1));
    reg_block #(.W(WCOS)) rg_nl1 (.ctl(ld_job), .d(in_nl1), .q(nl1));
    reg_block #(.W(WCOS)) rg_nh2 (.ctl(ld_job), .d(in_nh2), .q(nh2));
    reg_block #(.W(WCOS)) rg_nl2 (.ctl(ld_job), .d(in_nl2), .q(nl2));
    reg_block #(.W(WCOS)) rg_nh3 (.ctl(ld_job), .d(in_nh3), .q(nh3));
    reg_block #(.W(WCOS)) rg_nl3 (.ctl(ld_job), .d(in_nl3), .q(nl3));
    reg_block #(.W(WCOS)) rg_nh4 (.ctl(ld_job), .d(in_nh4), .q(nh4));
    reg_block #(.W(WCOS)) rg_nl4 (.ctl(ld_job), .d(in_nl4), .q(nl4));
    mux #(.W(WCOS), .N(4), .SW(WSEL)) mx_nh (.in({nh4, nh3, nh2, nh1}), .sel(smp_sel), .y(in18_cos));
    mux #(.W(WCOS), .N(4), .SW(WSEL)) mx_nl (.in({nl4, nl3, nl2, nl1}), .sel(smp_sel), .y(cos_nl));
    // The last sample's codes, and whether the job's first sample is that point again.
    reg_block #(.W(WCOS)) rg_lnh (.ctl(ld_last), .d(in18_cos), .q(last_nh));
    reg_block #(.W(WCOS)) rg_lnl (.ctl(ld_last), .d(cos_nl), .q(last_nl));
    eq_cmp #(.W(WCOS)) eq_nh (.a(nh1), .b(last_nh), .y(nh_hit));
    eq_cmp #(.W(WCOS)) eq_nl (.a(nl1), .b(last_nl), .y(nl_hit));
    and_gate and_carry (.a(nh_hit), .b(nl_hit), .y(carry_hit));

    // The specular device: frame constants straight from the pins through its own registers.
    sqmul_device #(.SATURATE(SATURATE)) dev (
        .clk(clk), .ctl15(ctl15), .ctl17(ctl17), .ctl20(ctl20), .ctl22(ctl22), .ctl24(ctl24),
        .in16_n(in_n), .in18_cos(in18_cos), .in19_ksi_r(in_ksi_r), .in21_ksi_g(in_ksi_g), .in23_ksi_b(in_ksi_b),
        .out25_r(out25_r), .out26_g(out26_g), .out27_b(out27_b), .out29_valid(out29_valid));
    reg_block #(.W(WK)) rg_kd_r (.ctl(ld_k), .d(in_kdi_r), .q(kdi_r));
    reg_block #(.W(WK)) rg_kd_g (.ctl(ld_k), .d(in_kdi_g), .q(kdi_g));
    reg_block #(.W(WK)) rg_kd_b (.ctl(ld_k), .d(in_kdi_b), .q(kdi_b));
    reg_block #(.W(WI)) rg_amb_r (.ctl(ld_k), .d(in_amb_r), .q(amb_r));
    reg_block #(.W(WI)) rg_amb_g (.ctl(ld_k), .d(in_amb_g), .q(amb_g));
    reg_block #(.W(WI)) rg_amb_b (.ctl(ld_k), .d(in_amb_b), .q(amb_b));

    // The sample channels: colour of each sample, sample and interval registers, coefficients.
    sample_channel #(.SET(SET), .DIV(DIV)) smp_r (
        .clk(clk), .ld_i1(ld_i1), .ld_i2(ld_i2), .ld_i3(ld_i3), .ld_i4(ld_i4), .ld_e(ld_e),
        .kdi(kdi_r), .ambient(amb_r), .cos_nl(cos_nl), .specular(out25_r), .carry_sel(carry_sel), .ld_last(ld_last),
        .ca(ca_r), .cb(cb_r), .cc(cc_r), .cd(cd_r), .qa(qa_r), .qb(qb_r), .qc(qc_r));
    sample_channel #(.SET(SET), .DIV(DIV)) smp_g (
        .clk(clk), .ld_i1(ld_i1), .ld_i2(ld_i2), .ld_i3(ld_i3), .ld_i4(ld_i4), .ld_e(ld_e),
        .kdi(kdi_g), .ambient(amb_g), .cos_nl(cos_nl), .specular(out26_g), .carry_sel(carry_sel), .ld_last(ld_last),
        .ca(ca_g), .cb(cb_g), .cc(cc_g), .cd(cd_g), .qa(qa_g), .qb(qb_g), .qc(qc_g));
    sample_channel #(.SET(SET), .DIV(DIV)) smp_b (
        .clk(clk), .ld_i1(ld_i1), .ld_i2(ld_i2), .ld_i3(ld_i3), .ld_i4(ld_i4), .ld_e(ld_e),
        .kdi(kdi_b), .ambient(amb_b), .cos_nl(cos_nl), .specular(out27_b), .carry_sel(carry_sel), .ld_last(ld_last),
        .ca(ca_b), .cb(cb_b), .cc(cc_b), .cd(cd_b), .qa(qa_b), .qb(qb_b), .qc(qc_b));

    // The evaluators and the pixel controller; the pixel stream's valid is channel R's.
    generate
        if (EVAL == 0) begin : evaluator
            wire deg2;
            wire [`INTERP_T_W-1:0] t;
            horner_channel horner_r (
                .clk(clk), .start(ev_start), .deg2(deg2), .deg_sel(deg_sel), .t(t),
                .ca(ca_r), .cb(cb_r), .cc(cc_r), .cd(cd_r), .qa(qa_r), .qb(qb_r), .qc(qc_r),
                .px(px_r), .done(ev_done_r), .busy(ev_busy_r));
            horner_channel horner_g (
                .clk(clk), .start(ev_start), .deg2(deg2), .deg_sel(deg_sel), .t(t),
                .ca(ca_g), .cb(cb_g), .cc(cc_g), .cd(cd_g), .qa(qa_g), .qb(qb_g), .qc(qc_g),
                .px(px_g), .done(ev_done_g), .busy(ev_busy_g));
            horner_channel horner_b (
                .clk(clk), .start(ev_start), .deg2(deg2), .deg_sel(deg_sel), .t(t),
                .ca(ca_b), .cb(cb_b), .cc(cc_b), .cd(cd_b), .qa(qa_b), .qb(qb_b), .qc(qc_b),
                .px(px_b), .done(ev_done_b), .busy(ev_busy_b));
            horner_pixel_ctrl ctl_pixel (
                .clk(clk), .samples_ready(samples_ready), .y(d_y), .x0(d_x0), .len(d_len), .m(d_m),
                .deg2_in(d_deg2), .busy(ev_busy_r), .done(ev_done_r), .ld_e(ld_e), .start(ev_start),
                .deg2(deg2), .deg_sel(deg_sel), .t(t), .px_x(px_x), .px_y(px_y));
        end else begin : evaluator
            wire [`INTERP_FD_LEN_W-1:0] ev_len;  // the interval's length, every m
            wire [`INTERP_FD_M_W-1:0] ev_m;      // its m (0, m_min..m_max), read by fd_eval_var
            fd_channel #(.FIXED_M(FD_M)) fd_r (
                .clk(clk), .start(ev_start), .deg_sel(deg_sel), .len(ev_len), .m(ev_m),
                .ca(ca_r), .cb(cb_r), .cc(cc_r), .cd(cd_r), .qa(qa_r), .qb(qb_r), .qc(qc_r),
                .px(px_r), .valid(ev_done_r), .last(ev_busy_r));
            fd_channel #(.FIXED_M(FD_M)) fd_g (
                .clk(clk), .start(ev_start), .deg_sel(deg_sel), .len(ev_len), .m(ev_m),
                .ca(ca_g), .cb(cb_g), .cc(cc_g), .cd(cd_g), .qa(qa_g), .qb(qb_g), .qc(qc_g),
                .px(px_g), .valid(ev_done_g), .last(ev_busy_g));
            fd_channel #(.FIXED_M(FD_M)) fd_b (
                .clk(clk), .start(ev_start), .deg_sel(deg_sel), .len(ev_len), .m(ev_m),
                .ca(ca_b), .cb(cb_b), .cc(cc_b), .cd(cd_b), .qa(qa_b), .qb(qb_b), .qc(qc_b),
                .px(px_b), .valid(ev_done_b), .last(ev_busy_b));
            fd_pixel_ctrl ctl_pixel (
                .clk(clk), .samples_ready(samples_ready), .y(d_y), .x0(d_x0), .len_in(d_len), .m_in(d_m),
                .deg2_in(d_deg2), .valid(ev_done_r), .last(ev_busy_r), .ld_e(ld_e), .start(ev_start),
                .deg_sel(deg_sel), .len(ev_len), .m(ev_m), .px_x(px_x), .px_y(px_y));
        end
    endgenerate
    wire_block #(.W(1)) out_valid (.x(ev_done_r), .y(px_valid));

    // The sample controller: the geometry side's handshake, the device's strobes, the samples. The
    // clocked device: each sample latches where output 29 is high (WAIT_VALID).
    sample_ctrl #(.FD_M(EVAL == 0 ? 0 : FD_M), .CLOCKED(1), .CARRY(CARRY), .LEN_W(WLEN), .M_W(WM), .SEL_W(WSEL))
        ctl_sample (
        .clk(clk), .start(start), .load_frame(load_frame), .len(len), .m(m), .deg2(deg2_job), .ld_e(ld_e),
        .dev_valid(out29_valid), .carry_hit(carry_hit), .ready(ready), .ld_job(ld_job), .ld_d(ld_d),
        .ctl15(ctl15), .ctl17(ctl17), .ctl20(ctl20), .ctl22(ctl22), .ctl24(ctl24), .ld_k(ld_k),
        .smp_sel(smp_sel), .ld_i1(ld_i1), .ld_i2(ld_i2), .ld_i3(ld_i3), .ld_i4(ld_i4),
        .samples_ready(samples_ready), .carry_sel(carry_sel), .ld_last(ld_last));
endmodule
