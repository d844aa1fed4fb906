// The right-to-left square-and-multiply design's iterative stage (ours, for comparison): two
// multipliers on the P word, both written in the same clock.
//   MUL_X   RG_X x RG_X: the square, Q1.F^2 = Q2.2F, F low wires open (floor), the F + 1 above kept
//   MUL_P   RG_P x RG_X: the accumulated product, the same floor
//   MX_X    hold (RG_X), load (cos), product (MUL_X)          <- ctl.mx_x_sel
//   MX_P    hold (RG_P), load (1.0), product (MUL_P)          <- ctl.mx_p_sel
//   RG_X    Q1.F, latches MX_X at every falling edge of clk
//   RG_P    Q1.F, latches MX_P at every falling edge of clk
//   sync17  strobe 17's request into clk's domain (synchroniser.v, `SQUARED_SYNC_STAGES flip-flops)
//   ctl     sqmul_r2l_ctrl.v: the walk over n's bits
// F = SQMUL_P_FRAC (shading_formats.vh).
`include "shading_formats.vh"
`include "sqmul_r2l_codes.vh"
module sqmul_r2l_stage (
    input  wire                    clk,
    input  wire                    ctl17,
    input  wire [`SQUARED_N_W-1:0] n,
    input  wire [`SQMUL_P_W-1:0]   c,     // cos on the P word
    output wire [`SQMUL_P_W-1:0]   brdf,  // RG_P
    output wire                    done   // output 29's gate
);
    localparam WP = `SQMUL_P_W;
    localparam NI = `SQMUL_R2L_MX_INPUTS;

    wire ctl_req;      // strobe 17's request (its domain)
    wire sync17_req;   // the same, synchronised to clk
    wire [`SQMUL_R2L_SEL_W-1:0] mx_x_sel, mx_p_sel;
    wire [WP-1:0] x_power, mul_x_square, mul_p_product, mx_x_next, mx_p_next, one_p;
    wire [NI*WP-1:0] mx_x_in, mx_p_in;
    assign mx_x_in[`SQMUL_R2L_HOLD*WP +: WP] = x_power;
    assign mx_x_in[`SQMUL_R2L_LOAD*WP +: WP] = c;
    assign mx_x_in[`SQMUL_R2L_PRODUCT*WP +: WP] = mul_x_square;
    assign mx_p_in[`SQMUL_R2L_HOLD*WP +: WP] = brdf;
    assign mx_p_in[`SQMUL_R2L_LOAD*WP +: WP] = one_p;
    assign mx_p_in[`SQMUL_R2L_PRODUCT*WP +: WP] = mul_p_product;

    synchroniser #(.W(1), .STAGES(`SQUARED_SYNC_STAGES)) sync17 (.clk(clk), .d(ctl_req), .q(sync17_req));
    sqmul_r2l_ctrl ctl (.clk(clk), .ctl17(ctl17), .req_s(sync17_req), .n(n), .mx_x_sel(mx_x_sel),
                        .mx_p_sel(mx_p_sel), .req(ctl_req), .done(done));
    constant #(.W(WP), .VALUE(`SQMUL_P_ONE)) one (.y(one_p));
    // Q1.F x Q1.F -> Q2.2F, floor to Q1.F
    mul #(.WA(WP), .WB(WP), .WP(WP), .DROP(`SQMUL_P_FRAC)) mul_x (.a(x_power), .b(x_power), .p(mul_x_square));
    mul #(.WA(WP), .WB(WP), .WP(WP), .DROP(`SQMUL_P_FRAC)) mul_p (.a(brdf), .b(x_power), .p(mul_p_product));
    mux #(.W(WP), .N(NI), .SW(`SQMUL_R2L_SEL_W)) mx_x (.in(mx_x_in), .sel(mx_x_sel), .y(mx_x_next));
    mux #(.W(WP), .N(NI), .SW(`SQMUL_R2L_SEL_W)) mx_p (.in(mx_p_in), .sel(mx_p_sel), .y(mx_p_next));
    reg_block #(.W(WP)) rg_x (.ctl(clk), .d(mx_x_next), .q(x_power));
    reg_block #(.W(WP)) rg_p (.ctl(clk), .d(mx_p_next), .q(brdf));
endmodule
