// The square-and-multiply device's iterative stage (ours; SystemC twin modules/sqmul/sqmul_stage.h): one Q1.18
// multiplier whose second operand is P or cos.
//   MX_B    P (square) or cos (multiply)                          <- ctl.mx_b_sel
//   MUL_P   RG_P x MX_B: Q1.18^2 = Q2.36, 18 low wires open (floor), the 19 above kept
//   MX_P    hold (RG_P), load (cos), product (MUL_P)              <- ctl.mx_p_sel
//   RG_P    Q1.18, latches MX_P at every falling edge of clk
//   sync17  strobe 17's request into clk's domain (synchroniser.v, `SQUARED_SYNC_STAGES flip-flops)
//   ctl     sqmul_ctrl.v: the walk over n's bits
`include "shading_formats.vh"
module sqmul_stage (
    input  wire                    clk,
    input  wire                    ctl17,
    input  wire [`SQUARED_Z_W-1:0] z,
    input  wire [`SQUARED_F_W-1:0] f,
    input  wire [`SQMUL_P_W-1:0]   c,     // cos, Q1.18
    output wire [`SQMUL_P_W-1:0]   brdf,  // RG_P
    output wire                    done   // output 29's gate
);
    localparam WP = `SQMUL_P_W;

    wire ctl_req;      // strobe 17's request (its domain)
    wire sync17_req;   // the same, synchronised to clk
    wire [`SQMUL_MX_P_SEL_W-1:0] mx_p_sel;
    wire [`SQMUL_MX_B_SEL_W-1:0] mx_b_sel;
    wire [WP-1:0] mx_b_operand, mul_p_product, mx_p_next;
    wire [`SQMUL_MX_B_INPUTS*WP-1:0] mx_b_in;
    wire [`SQMUL_MX_P_INPUTS*WP-1:0] mx_p_in;
    assign mx_b_in[`SQMUL_MX_B_P*WP +: WP] = brdf;
    assign mx_b_in[`SQMUL_MX_B_COS*WP +: WP] = c;
    assign mx_p_in[`SQMUL_MX_P_HOLD*WP +: WP] = brdf;
    assign mx_p_in[`SQMUL_MX_P_LOAD*WP +: WP] = c;
    assign mx_p_in[`SQMUL_MX_P_PRODUCT*WP +: WP] = mul_p_product;

    synchroniser #(.W(1), .STAGES(`SQUARED_SYNC_STAGES)) sync17 (.clk(clk), .d(ctl_req), .q(sync17_req));
    sqmul_ctrl ctl (.clk(clk), .ctl17(ctl17), .req_s(sync17_req), .z(z), .f(f), .mx_p_sel(mx_p_sel),
                    .mx_b_sel(mx_b_sel), .req(ctl_req), .done(done));
    mux #(.W(WP), .N(`SQMUL_MX_B_INPUTS), .SW(`SQMUL_MX_B_SEL_W)) mx_b (.in(mx_b_in), .sel(mx_b_sel), .y(mx_b_operand));
    // Q1.18 x Q1.18 -> Q2.36, floor to Q1.18
    mul #(.WA(WP), .WB(WP), .WP(WP), .DROP(`SQMUL_P_FRAC)) mul_p (
        .a(brdf), .b(mx_b_operand), .p(mul_p_product));
    mux #(.W(WP), .N(`SQMUL_MX_P_INPUTS), .SW(`SQMUL_MX_P_SEL_W)) mx_p (
        .in(mx_p_in), .sel(mx_p_sel), .y(mx_p_next));
    reg_block #(.W(WP)) rg_p (.ctl(clk), .d(mx_p_next), .q(brdf));
endmodule
