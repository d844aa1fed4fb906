// Shift-and-add network (modules/blocks/shift_add_network.h): y = sum of +/-(in[k] << s), a
// multiplication by constants with no multiplier (the interpolation paper: "10I = 8I + 2I"). From a term table:
// each term a shifter (wiring) onto the W-bit bus; the positive terms summed by a balanced adder
// tree (P), the negative ones by another (Q), one inverter bank, and a last adder with carry-in 1:
// y = P + ~Q + 1 = P - Q. The trees pair neighbours level by level, an odd one passing to the next
// level, as the SystemC block's reduce() does. Every adder wraps on W wires.
// Term k is TERMS[16k +: 16]: [15:12] input index, [8] negative, [7:0] shift (two's complement);
// TERMS holds SLOTS terms, of which the first NT are used (so tables of different lengths share
// one width). The tables come from the generated header interp_terms.vh, never typed here.
module shift_add_network #(
    parameter WIN = 8,
    parameter W = 8,
    parameter IN_SIGNED = 0,
    parameter NIN = 1,
    parameter NT = 2,
    parameter SLOTS = NT,
    parameter [16*SLOTS-1:0] TERMS = 0
) (
    input  wire [NIN*WIN-1:0] in,
    output wire [W-1:0]       y
);
    /* verilator lint_off UNUSEDSIGNAL */  // each reader takes its own field of the term word
    function [15:0] term_word(input integer k);
        term_word = TERMS[16*k +: 16];
    endfunction
    function integer term_input(input integer k);
        reg [15:0] t;
        begin
            t = term_word(k);
            term_input = {28'd0, t[15:12]};
        end
    endfunction
    function integer term_negative(input integer k);
        reg [15:0] t;
        begin
            t = term_word(k);
            term_negative = {31'd0, t[8]};
        end
    endfunction
    function integer term_shift(input integer k);
        reg [15:0] t;
        begin
            t = term_word(k);
            term_shift = {{24{t[7]}}, t[7:0]};
        end
    endfunction
    /* verilator lint_on UNUSEDSIGNAL */
    // How many terms have this sign, and which term is the k-th of them (table order kept).
    function integer sign_count(input integer neg);
        integer i;
        begin
            sign_count = 0;
            for (i = 0; i < NT; i = i + 1) if (term_negative(i) == neg) sign_count = sign_count + 1;
        end
    endfunction
    function integer nth_of_sign(input integer neg, input integer k);
        integer i, seen;
        begin
            nth_of_sign = 0;
            seen = 0;
            for (i = 0; i < NT; i = i + 1)
                if (term_negative(i) == neg) begin
                    if (seen == k) nth_of_sign = i;
                    seen = seen + 1;
                end
        end
    endfunction
    // A tree over n leaves: level 0 holds the leaves, level l + 1 ceil(count(l) / 2) nodes; the
    // nodes of all levels are stored one level after another.
    function integer level_count(input integer n, input integer lvl);
        integer i;
        begin
            level_count = n;
            for (i = 0; i < lvl; i = i + 1) level_count = (level_count + 1) / 2;
        end
    endfunction
    function integer level_offset(input integer n, input integer lvl);
        integer i;
        begin
            level_offset = 0;
            for (i = 0; i < lvl; i = i + 1) level_offset = level_offset + level_count(n, i);
        end
    endfunction
    function integer levels(input integer n);
        integer cnt;
        begin
            levels = 0;
            cnt = n;
            while (cnt > 1) begin
                cnt = (cnt + 1) / 2;
                levels = levels + 1;
            end
        end
    endfunction

    localparam NP = sign_count(0);
    localparam NQ = sign_count(1);
    localparam LP = levels(NP);
    localparam LQ = levels(NQ);
    localparam P_NODES = level_offset(NP, LP) + 1;
    localparam Q_NODES = NQ > 0 ? level_offset(NQ, LQ) + 1 : 1;

    wire [W-1:0] term [0:NT-1];
    // Every tree node in one array per tree; split_var lets Verilator schedule the nodes one by one.
    wire [W-1:0] p_node [0:P_NODES-1] /*verilator split_var*/;
    wire [W-1:0] q_node [0:Q_NODES-1] /*verilator split_var*/;
    wire carry0, carry1;

    constant #(.W(1), .VALUE(0)) tie0 (.y(carry0));
    constant #(.W(1), .VALUE(1)) tie1 (.y(carry1));

    genvar k, l, j;
    generate
        for (k = 0; k < NT; k = k + 1) begin : sh
            shifter #(.WIN(WIN), .WOUT(W), .IN_SIGNED(IN_SIGNED), .SHIFT(term_shift(k))) shift (
                .x(in[term_input(k)*WIN +: WIN]), .y(term[k]));
        end
        for (k = 0; k < NP; k = k + 1) begin : p_leaf
            assign p_node[k] = term[nth_of_sign(0, k)];
        end
        for (l = 0; l < LP; l = l + 1) begin : p_level
            for (j = 0; j < level_count(NP, l + 1); j = j + 1) begin : node
                localparam SRC = level_offset(NP, l) + 2 * j, DST = level_offset(NP, l + 1) + j;
                if (2 * j + 1 < level_count(NP, l)) begin : add
                    adder #(.WA(W), .WB(W), .WS(W), .ASIGNED(1), .BSIGNED(1)) add (
                        .a(p_node[SRC]), .b(p_node[SRC + 1]), .cin(carry0), .s(p_node[DST]));
                end else begin : pass
                    assign p_node[DST] = p_node[SRC];
                end
            end
        end
        if (NQ == 0) begin : no_negative
            assign y = p_node[P_NODES-1];
            assign q_node[0] = {W{1'b0}};
            wire unused_ok = &{1'b0, carry1, q_node[0], 1'b0};
        end else begin : negative
            wire [W-1:0] neg_inv;
            for (k = 0; k < NQ; k = k + 1) begin : q_leaf
                assign q_node[k] = term[nth_of_sign(1, k)];
            end
            for (l = 0; l < LQ; l = l + 1) begin : q_level
                for (j = 0; j < level_count(NQ, l + 1); j = j + 1) begin : node
                    localparam SRC = level_offset(NQ, l) + 2 * j, DST = level_offset(NQ, l + 1) + j;
                    if (2 * j + 1 < level_count(NQ, l)) begin : add
                        adder #(.WA(W), .WB(W), .WS(W), .ASIGNED(1), .BSIGNED(1)) add (
                            .a(q_node[SRC]), .b(q_node[SRC + 1]), .cin(carry0), .s(q_node[DST]));
                    end else begin : pass
                        assign q_node[DST] = q_node[SRC];
                    end
                end
            end
            inverter_bank #(.WIN(W), .WOUT(W), .ALIGN(0)) inv (.x(q_node[Q_NODES-1]), .y(neg_inv));
            // P + ~Q + 1 = P - Q (two's complement).
            adder #(.WA(W), .WB(W), .WS(W), .ASIGNED(1), .BSIGNED(1)) add_last (
                .a(p_node[P_NODES-1]), .b(neg_inv), .cin(carry1), .s(y));
        end
    endgenerate
endmodule
