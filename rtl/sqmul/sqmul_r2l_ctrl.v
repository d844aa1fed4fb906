// Controller of the right-to-left square-and-multiply design (ours, for comparison; no SystemC
// block): walks the bits of n from the least significant up, one step per rising edge of clk:
//     taking edge   LOAD (RG_X <- cos, RG_P <- 1.0 at the falling edge that follows); bits = n
//     per bit       RG_X <- X^2, and RG_P <- P x X when the bit is 1 (else RG_P holds); bits >>= 1
//     done edge     (bits = 0) HOLD; done = 1
// Strobe 17's request reaches the taking edge through the synchroniser sync17 (in
// sqmul_r2l_stage.v, `SQUARED_SYNC_STAGES = 2 flip-flops), so done rises floor(log2 n) + 5 rising
// edges after strobe 17 fell (the synchroniser's two, the taking edge, one per bit up to n's
// leading one, the done edge; n = 0: 4, P = 1.0). No leading-zero count: the walk ends when no 1
// bit is left.
// The strobe handshake (req in strobe 17's domain, req_s from sync17 the only one of it read on
// clk, taken and ack on clk, done = req == ack && !busy), a strobe before done abandoning the
// result, the start-up state: as sqmul_ctrl.v and sq_ctrl.v.
`include "shading_formats.vh"
`include "sqmul_r2l_codes.vh"
module sqmul_r2l_ctrl (
    input  wire                          clk,
    input  wire                          ctl17,
    input  wire                          req_s,  // req through sync17
    input  wire [`SQUARED_N_W-1:0]       n,  // RG1
    output reg  [`SQMUL_R2L_SEL_W-1:0]   mx_x_sel = `SQMUL_R2L_HOLD,
    output reg  [`SQMUL_R2L_SEL_W-1:0]   mx_p_sel = `SQMUL_R2L_HOLD,
    output reg                           req = 1'b0,
    output wire                          done
);
    localparam NW = `SQUARED_N_W;
    localparam [`SQMUL_R2L_SEL_W-1:0] HOLD = `SQMUL_R2L_HOLD, LOAD = `SQMUL_R2L_LOAD, PRODUCT = `SQMUL_R2L_PRODUCT;

    reg taken = 1'b0, ack = 1'b0;
    reg busy = 1'b0;
    reg [NW-1:0] bits = 0;  // the bits still to walk, the next one at bits[0]

    always @(negedge ctl17) req <= ~taken;

    always @(posedge clk) begin
        if (req_s != taken) begin
            taken <= req_s;
            busy <= 1'b1;
            bits <= n;
            mx_x_sel <= LOAD;
            mx_p_sel <= LOAD;
        end else if (busy && bits != 0) begin
            bits <= {1'b0, bits[NW-1:1]};
            mx_x_sel <= PRODUCT;
            mx_p_sel <= bits[0] ? PRODUCT : HOLD;
        end else begin
            if (busy) ack <= taken;
            busy <= 1'b0;
            mx_x_sel <= HOLD;
            mx_p_sel <= HOLD;
        end
    end

    assign done = ~(req ^ ack) & ~busy;
endmodule
