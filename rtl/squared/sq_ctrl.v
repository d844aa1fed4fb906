// Controller of the squared-quadratic device's squaring stage (ours), as modules/squared/sq_ctrl.h
// with sq_count.h's state: LOAD at the first rising edge of clk after strobe 17 fell, one SQUARE
// per rising edge for k = 9 - z squarings, then done. MX_SQ's select changes at the rising edge,
// so RG_SQ, latching at the falling edge, reads a select that settled for half a period.
//   pending  a strobe not yet taken: set by strobe 17's falling edge, cleared by the taking edge
//   busy     loaded, not yet done;  left: squarings still to come
//   done     output 29's gate: !pending && !busy (cleared by the strobe itself, set at the rising
//            edge after the last square), so done rises k + 2 rising edges after the strobe,
//            the taking edge counted as the first
// A strobe while a result is pending or still being squared abandons that result: the new cos is
// loaded at the next rising edge (the SystemC model also reports it; a report is not hardware).
// pending crosses from strobe 17's domain to clk's as two flip-flops: strobe 17 sets req to the
// complement of ack, the taking edge copies req into ack, and pending = req XOR ack. A strobe
// falling at the very instant of a rising edge is a timing violation in hardware (the SystemC
// model takes the clock first); the platform keeps the two edges apart, as Fig. 3's timing does.
// No reset pin, as the SystemC model: the state starts idle (initial values). From any power-up
// state the controller is idle within 2^Z_W rising edges (left counts down, then busy clears).
`include "shading_formats.vh"
module sq_ctrl (
    input  wire                     clk,
    input  wire                     ctl17,
    input  wire [`SQUARED_Z_W-1:0]  z,  // the LZC of RG1: 9 - z squarings
    output reg  [`SQUARED_SEL_W-1:0] sel = `SQUARED_SEL_HOLD,
    output wire                     done
);
    localparam [`SQUARED_Z_W-1:0] Z_FULL = `SQUARED_Z_FULL;
    localparam [`SQUARED_SEL_W-1:0] HOLD = `SQUARED_SEL_HOLD, LOAD = `SQUARED_SEL_LOAD,
                                    SQUARE = `SQUARED_SEL_SQUARE;

    reg req = 1'b0, ack = 1'b0;
    reg busy = 1'b0;
    reg [`SQUARED_Z_W-1:0] left = 0;
    wire pending = req ^ ack;
    // k = 9 - z for z <= 9 (n >= 1), none for n = 0 (z = 10)
    wire [`SQUARED_Z_W-1:0] squarings = z <= Z_FULL ? Z_FULL - z : {`SQUARED_Z_W{1'b0}};

    always @(negedge ctl17) req <= ~ack;

    always @(posedge clk) begin
        if (pending) begin
            ack <= req;
            busy <= 1'b1;
            left <= squarings;
            sel <= LOAD;
        end else if (busy && left != 0) begin
            left <= left - 1'b1;
            sel <= SQUARE;
        end else begin
            busy <= 1'b0;
            sel <= HOLD;
        end
    end

    assign done = ~pending & ~busy;
endmodule
