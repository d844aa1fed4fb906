// The squared-quadratic device's squaring stage (ours), as modules/squared/squaring_stage.h: one
// squarer iterated k = 9 - z times.
//   MX_SQ   hold (RG_SQ), load (ADD11: the quadratic at n'), square (MUL_SQ)   <- ctl_sq.sel
//   RG_SQ   Q1.18, latches MX_SQ at every falling edge of clk (hold = recirculate)
//   MUL_SQ  RG_SQ x RG_SQ: Q1.18^2 = Q2.36, 18 low wires open (floor), the 19 above kept
//   sync17  strobe 17's request into clk's domain (synchroniser.v, `SQUARED_SYNC_STAGES flip-flops)
//   ctl_sq  sq_ctrl.v: LOAD at the rising edge after the request crossed, k SQUAREs, then done
// The result is RG_SQ after the k-th square: brdf, read by the colour multipliers.
`include "shading_formats.vh"
module squaring_stage (
    input  wire                    clk,
    input  wire                    ctl17,
    input  wire [`SQUARED_Z_W-1:0] z,
    input  wire [`SQUARED_Q_W-1:0] q,     // ADD11
    output wire [`SQUARED_Q_W-1:0] brdf,  // RG_SQ
    output wire                    done   // output 29's gate
);
    localparam WQ = `SQUARED_Q_W;

    wire ctl_sq_req;   // strobe 17's request (its domain)
    wire sync17_req;   // the same, synchronised to clk
    wire [`SQUARED_SEL_W-1:0] mx_sq_sel;
    wire [WQ-1:0] mx_sq_next;
    wire [WQ-1:0] mul_sq_square;
    // MX_SQ's inputs at the controller's select codes.
    wire [`SQUARED_MX_SQ_INPUTS*WQ-1:0] mx_sq_in;
    assign mx_sq_in[`SQUARED_SEL_HOLD*WQ +: WQ] = brdf;
    assign mx_sq_in[`SQUARED_SEL_LOAD*WQ +: WQ] = q;
    assign mx_sq_in[`SQUARED_SEL_SQUARE*WQ +: WQ] = mul_sq_square;

    synchroniser #(.W(1), .STAGES(`SQUARED_SYNC_STAGES)) sync17 (.clk(clk), .d(ctl_sq_req), .q(sync17_req));
    sq_ctrl ctl_sq (.clk(clk), .ctl17(ctl17), .req_s(sync17_req), .z(z), .sel(mx_sq_sel), .req(ctl_sq_req),
                    .done(done));
    mux #(.W(WQ), .N(`SQUARED_MX_SQ_INPUTS), .SW(`SQUARED_SEL_W)) mx_sq (
        .in(mx_sq_in), .sel(mx_sq_sel), .y(mx_sq_next));
    reg_block #(.W(WQ)) rg_sq (.ctl(clk), .d(mx_sq_next), .q(brdf));
    // Q1.18 x Q1.18 -> Q2.36, floor to Q1.18
    mul #(.WA(WQ), .WB(WQ), .WP(WQ), .DROP(`SQUARED_Q_FRAC)) mul_sq (
        .a(brdf), .b(brdf), .p(mul_sq_square));
endmodule
