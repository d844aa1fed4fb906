// Controller of the square-and-multiply device (ours; SystemC twin modules/sqmul/sqmul_ctrl.h): walks
// the bits of n below its leading one, most significant first, one step per rising edge of clk:
//     taking edge   LOAD (RG_P <- cos at the falling edge that follows); left = k = 9 - z,
//                   bits = f, the 9 wires of n << z below its leading one
//     per bit       SQUARE (P <- P x P), then, when the bit is 1, MULTIPLY (P <- P x cos)
//     done edge     HOLD; done = 1
// Strobe 17's request reaches the taking edge through the synchroniser sync17 (in sqmul_stage.v,
// `SQUARED_SYNC_STAGES = 2 flip-flops), so done rises squares + multiplies + 4 rising edges after
// strobe 17 fell (the synchroniser's two and the taking edge counted), with floor(log2 n) squares
// and popcount(n) - 1 multiplications: the baseline's clocks per sample are floor(log2 n) +
// popcount(n) + 3 (n = 0 is read as n = 1: 4). The select codes are the floor's sqmul::p_select
// and b_select (sqmul_formats.h), generated into shading_formats.vh.
// The strobe handshake (req in strobe 17's domain, req_s from sync17 the only one of it read on
// clk, taken and ack on clk, done = req == ack && !busy), a strobe before done abandoning the
// result, the start-up state: as sq_ctrl.v.
`include "shading_formats.vh"
module sqmul_ctrl (
    input  wire                       clk,
    input  wire                       ctl17,
    input  wire                       req_s,  // req through sync17
    input  wire [`SQUARED_Z_W-1:0]    z,  // the LZC of RG1
    input  wire [`SQUARED_F_W-1:0]    f,  // n's bits below its leading one, most significant first
    output reg  [`SQMUL_MX_P_SEL_W-1:0] mx_p_sel = `SQMUL_MX_P_HOLD,
    output reg  [`SQMUL_MX_B_SEL_W-1:0] mx_b_sel = `SQMUL_MX_B_P,
    output reg                        req = 1'b0,
    output wire                       done
);
    localparam [`SQUARED_Z_W-1:0] Z_FULL = `SQUARED_Z_FULL;
    localparam FW = `SQUARED_F_W;

    reg taken = 1'b0, ack = 1'b0;
    reg busy = 1'b0;
    reg [`SQUARED_Z_W-1:0] left = 0;  // squares still to come
    reg [FW-1:0] bits = 0;            // the next bit to walk is bits[FW-1]
    reg multiply_next = 1'b0;         // the square just done was of a 1 bit
    wire [`SQUARED_Z_W-1:0] squarings = z <= Z_FULL ? Z_FULL - z : {`SQUARED_Z_W{1'b0}};

    always @(negedge ctl17) req <= ~taken;

    always @(posedge clk) begin
        mx_b_sel <= `SQMUL_MX_B_P;
        if (req_s != taken) begin
            taken <= req_s;
            busy <= 1'b1;
            left <= squarings;
            bits <= f;
            multiply_next <= 1'b0;
            mx_p_sel <= `SQMUL_MX_P_LOAD;
        end else if (busy && multiply_next) begin
            multiply_next <= 1'b0;
            mx_p_sel <= `SQMUL_MX_P_PRODUCT;
            mx_b_sel <= `SQMUL_MX_B_COS;
        end else if (busy && left != 0) begin
            left <= left - 1'b1;
            multiply_next <= bits[FW-1];
            bits <= {bits[FW-2:0], 1'b0};
            mx_p_sel <= `SQMUL_MX_P_PRODUCT;
        end else begin
            if (busy) ack <= taken;
            busy <= 1'b0;
            mx_p_sel <= `SQMUL_MX_P_HOLD;
        end
    end

    assign done = ~(req ^ ack) & ~busy;
endmodule
