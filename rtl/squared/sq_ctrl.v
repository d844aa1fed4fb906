// Controller of the squared-quadratic device's squaring stage (ours), as modules/squared/sq_ctrl.h
// with sq_count.h's state. Strobe 17 has no clock of its own: its request crosses into clk's
// domain through the synchroniser sync17 (rtl/blocks/synchroniser.v, in squaring_stage.v), and
// every flip-flop here on clk reads only its output req_s.
//   req     strobe 17's domain: its falling edge sets req = ~taken (raises a request, or keeps one
//           not yet taken); out to sync17
//   taken   the request last taken: a rising edge with req_s != taken takes it (LOAD), k = 9 - z
//   busy    loaded, not yet done; left: squarings still to come (one SQUARE per rising edge)
//   ack     set to taken at the rising edge after the last square, when busy falls
//   done    output 29's gate: req == ack and !busy. The strobe clears it at once (req changes),
//           before its request has crossed; it rises at the (k + SYNC + 2)-th rising edge after
//           the strobe (SYNC = `SQUARED_SYNC_STAGES = 2: k + 4, the synchroniser's two counted)
// MX_SQ's select changes at the rising edge, so RG_SQ, latching at the falling edge, reads a
// select that settled for half a period.
// Crossings: req -> sync17 (clk's domain reads nothing else of strobe 17's); taken -> req's
// flip-flop, sampled at strobe 17's fall: taken changes only at a taking edge, and a platform that
// strobes after output 29 rose (Fig. 3) strobes when taken has been still for k + 1 clocks. The gate
// done is a function of req and two flip-flops on clk, never sampled on clk: it falls only when req
// changes, and at a clock edge busy and ack move it the same way (busy rises alone when a request
// is taken; busy falls with ack taking req's value when the result is valid), so in Fig. 3's use it
// cannot glitch high. A strobe while a result is pending or still being squared abandons that
// result (the SystemC model also reports it; a report is not hardware): before the taking edge the
// request stays raised and the new cos is loaded; after it, a new request is raised and taken once
// it has crossed.
// No reset pin, as the SystemC model: the state starts idle (initial values). From any other
// power-up state the stages flush in SYNC rising edges and left counts down within 2^Z_W; done
// may stay low (req != ack) until the first strobe, whose result is then validated as usual.
`include "shading_formats.vh"
module sq_ctrl (
    input  wire                     clk,
    input  wire                     ctl17,
    input  wire                     req_s,  // req through sync17
    input  wire [`SQUARED_Z_W-1:0]  z,      // the LZC of RG1: 9 - z squarings
    output reg  [`SQUARED_SEL_W-1:0] sel = `SQUARED_SEL_HOLD,
    output reg                      req = 1'b0,
    output wire                     done
);
    localparam [`SQUARED_Z_W-1:0] Z_FULL = `SQUARED_Z_FULL;
    localparam [`SQUARED_SEL_W-1:0] HOLD = `SQUARED_SEL_HOLD, LOAD = `SQUARED_SEL_LOAD,
                                    SQUARE = `SQUARED_SEL_SQUARE;

    reg taken = 1'b0, ack = 1'b0;
    reg busy = 1'b0;
    reg [`SQUARED_Z_W-1:0] left = 0;
    // k = 9 - z for z <= 9 (n >= 1), none for n = 0 (z = 10)
    wire [`SQUARED_Z_W-1:0] squarings = z <= Z_FULL ? Z_FULL - z : {`SQUARED_Z_W{1'b0}};

    always @(negedge ctl17) req <= ~taken;

    always @(posedge clk) begin
        if (req_s != taken) begin
            taken <= req_s;
            busy <= 1'b1;
            left <= squarings;
            sel <= LOAD;
        end else if (busy && left != 0) begin
            left <= left - 1'b1;
            sel <= SQUARE;
        end else begin
            if (busy) ack <= taken;
            busy <= 1'b0;
            sel <= HOLD;
        end
    end

    assign done = ~(req ^ ack) & ~busy;
endmodule
