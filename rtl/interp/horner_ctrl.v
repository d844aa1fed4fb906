// Controller of the iterative Horner unit (modules/interp/horner_ctrl.h, the interpolation paper, Fig. 4): the
// paper's micro-sequence, one step per clock, a state machine on the rising edge of clk (RG latches
// on the falling edge, so every step's selects settle for half a period first).
// Handshake: start is a level "request pending"; a request is accepted at a rising edge where
// start = 1 and the unit is idle or finishing (done = 1). done is high during the last step
// (step 6, or step 4 when deg2 = 1, read entering step 4); busy while a step runs. Idle: MX2 = 0
// with BK passing, so RG recirculates. The SystemC model has no reset pin: the state starts idle
// (initial values, as its members do).
//   step  MX1  MX2  BK      step  MX1  MX2  BK
//   1     -    B    zero    4     -    C    pass
//   2     A    MUL  pass    5     RG   MUL  zero
//   3     RG   MUL  zero    6     -    D    pass
`include "shading_formats.vh"
`include "interp_terms.vh"
module horner_ctrl #(
    parameter WT = `INTERP_T_W,
    parameter W_MX1 = (`INTERP_HORNER_MX1_INPUTS > 2 ? $clog2(`INTERP_HORNER_MX1_INPUTS) : 1),
    parameter W_MX2 = (`INTERP_HORNER_MX2_INPUTS > 2 ? $clog2(`INTERP_HORNER_MX2_INPUTS) : 1),
    parameter W_STEP = (`INTERP_HORNER_STEP_CODES > 2 ? $clog2(`INTERP_HORNER_STEP_CODES) : 1)
) (
    input  wire              clk,
    input  wire              start,
    input  wire              deg2,
    input  wire [WT-1:0]     t,        // read only by the SystemC model's range assertion
    output reg  [W_MX1-1:0]  mx1_sel,
    output reg  [W_MX2-1:0]  mx2_sel,
    output reg               bk_pass,
    output wire [W_STEP-1:0] step,
    output wire              done,
    output wire              busy
);
    localparam [W_STEP-1:0] IDLE = 0, FIRST = 1, C_STEP = 4, LAST_CUBIC = 6;

    reg [W_STEP-1:0] state = IDLE;       // 0 idle, 1..6 the micro-step running
    reg [W_STEP-1:0] last = LAST_CUBIC;  // the step that ends this request
    reg [W_STEP-1:0] next;

    wire finishing = state != IDLE && state == last;

    always @(*) begin
        if (start && (state == IDLE || finishing)) next = FIRST;
        else if (state != IDLE && !finishing) next = state + 1'b1;
        else next = IDLE;
    end

    always @(posedge clk) begin
        state <= next;
        if (next == FIRST) last <= LAST_CUBIC;  // until step 4 says otherwise
        else if (next == C_STEP && deg2) last <= C_STEP;
    end

    // Selects of the step that runs (decoded from the state register: they change right after
    // the rising edge, as the SystemC controller writes them).
    always @(*) begin
        mx1_sel = `INTERP_MX1_A;
        mx2_sel = `INTERP_MX2_ZERO;
        bk_pass = 1'b1;
        case (state)
            3'd1: begin mx2_sel = `INTERP_MX2_B; bk_pass = 1'b0; end
            3'd2: begin mx1_sel = `INTERP_MX1_A; mx2_sel = `INTERP_MX2_MUL; bk_pass = 1'b1; end
            3'd3: begin mx1_sel = `INTERP_MX1_RG; mx2_sel = `INTERP_MX2_MUL; bk_pass = 1'b0; end
            3'd4: begin mx2_sel = `INTERP_MX2_C; bk_pass = 1'b1; end
            3'd5: begin mx1_sel = `INTERP_MX1_RG; mx2_sel = `INTERP_MX2_MUL; bk_pass = 1'b0; end
            3'd6: begin mx2_sel = `INTERP_MX2_D; bk_pass = 1'b1; end
            default: ;  // idle: hold
        endcase
    end

    assign step = state;
    assign done = finishing;
    assign busy = state != IDLE;
    wire unused_ok = &{1'b0, t, 1'b0};
endmodule
