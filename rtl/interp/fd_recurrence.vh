// The forward-difference recurrence's wiring, the same in fd_eval.v and fd_eval_var.v (as
// wire_fd_recurrence in modules/interp/fd_eval.h serves fd_eval.h and fd_eval_var.h): the adders
// P + D1, D1 + D2, D2 + D3 (carry-in 0, wrapping), each register's hold / load / step multiplexer on
// fd_sel (load: init_*, the set-up), the registers on clk, RG_P onto i_px (18 low wires dropped).
// Included in the body of both modules, after their nets init_*, *_value, *_next, *_sum, d3_keep,
// fd_sel, carry0 and localparams WF, WC, S, NX, W_SEL are declared.
    constant #(.W(1), .VALUE(0)) k_carry0 (.y(carry0));
    adder #(.WA(WF), .WB(WF), .WS(WF), .ASIGNED(1), .BSIGNED(1)) add_p (
        .a(p_value), .b(d1_value), .cin(carry0), .s(p_sum));
    adder #(.WA(WF), .WB(WF), .WS(WF), .ASIGNED(1), .BSIGNED(1)) add_d1 (
        .a(d1_value), .b(d2_value), .cin(carry0), .s(d1_sum));
    adder #(.WA(WF), .WB(WF), .WS(WF), .ASIGNED(1), .BSIGNED(1)) add_d2 (
        .a(d2_value), .b(d3_value), .cin(carry0), .s(d2_sum));

    // Each multiplexer's inputs at their select codes (fd_ctrl.h, via interp_terms.vh).
    wire [NX*WF-1:0] mx_p_in, mx_d1_in, mx_d2_in, mx_d3_in;
    assign mx_p_in[`INTERP_FD_SEL_HOLD*WF +: WF] = p_value;
    assign mx_p_in[`INTERP_FD_SEL_LOAD*WF +: WF] = init_p;
    assign mx_p_in[`INTERP_FD_SEL_STEP*WF +: WF] = p_sum;
    assign mx_d1_in[`INTERP_FD_SEL_HOLD*WF +: WF] = d1_value;
    assign mx_d1_in[`INTERP_FD_SEL_LOAD*WF +: WF] = init_d1;
    assign mx_d1_in[`INTERP_FD_SEL_STEP*WF +: WF] = d1_sum;
    assign mx_d2_in[`INTERP_FD_SEL_HOLD*WF +: WF] = d2_value;
    assign mx_d2_in[`INTERP_FD_SEL_LOAD*WF +: WF] = init_d2;
    assign mx_d2_in[`INTERP_FD_SEL_STEP*WF +: WF] = d2_sum;
    assign mx_d3_in[`INTERP_FD_SEL_HOLD*WF +: WF] = d3_value;
    assign mx_d3_in[`INTERP_FD_SEL_LOAD*WF +: WF] = init_d3;
    assign mx_d3_in[`INTERP_FD_SEL_STEP*WF +: WF] = d3_value;  // D3 is constant while stepping
    mux #(.W(WF), .N(NX), .SW(W_SEL)) mx_p (.in(mx_p_in), .sel(fd_sel), .y(p_next));
    mux #(.W(WF), .N(NX), .SW(W_SEL)) mx_d1 (.in(mx_d1_in), .sel(fd_sel), .y(d1_next));
    mux #(.W(WF), .N(NX), .SW(W_SEL)) mx_d2 (.in(mx_d2_in), .sel(fd_sel), .y(d2_next));
    mux #(.W(WF), .N(NX), .SW(W_SEL)) mx_d3 (.in(mx_d3_in), .sel(fd_sel), .y(d3_keep));

    reg_block #(.W(WF)) rg_p (.ctl(clk), .d(p_next), .q(p_value));
    reg_block #(.W(WF)) rg_d1 (.ctl(clk), .d(d1_next), .q(d1_value));
    reg_block #(.W(WF)) rg_d2 (.ctl(clk), .d(d2_next), .q(d2_value));
    reg_block #(.W(WF)) rg_d3 (.ctl(clk), .d(d3_keep), .q(d3_value));

    // Q22.34 -> Q16.16: 18 low wires dropped (floor), wiring.
    shifter #(.WIN(WF), .WOUT(WC), .IN_SIGNED(1), .SHIFT(-S)) out_align (.x(p_value), .y(i_px));
