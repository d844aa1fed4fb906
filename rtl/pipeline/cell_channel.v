// One colour channel of the cell unit (ours; modules/pipeline/cell_channel.h): the biquadratic through
// a 3 x 3 lattice of colour samples, from the pipeline's own blocks:
//   rg_lat_0..8     the lattice registers (strobe ld_lat), lattice[3 i + j] at (j s/2, i s/2)
//   cq_col_0..2     quadratic coefficient units down lattice columns 0, 1, 2 (lattice j, 3 + j, 6 + j)
//   fd_col_0..2     forward-difference channels (quadratic, any m): the column's value at every row
//   buf_col_0..2    column buffers of CELL_BUF_DEPTH words, written while the column channels stream
//                   (we = col_valid, at wa)
//   cq_row, fd_row  the quadratic through the three column values of row ra, along the row: px
// The cubic inputs of the forward-difference channels are tied to zero (k_zero) and their degree
// select to the quadratic (k_quad: fd_channel's multiplexers take input 1, the quadratic's a, b, c).
// Ports and names as the SystemC module's; its sc_vector ports and nets are numbered wires here
// (in_lat_0..8, lat_0..8, col_a_0..2, ...). Only instantiates and wires.
`include "shading_formats.vh"
`include "interp_terms.vh"
module cell_channel #(
    parameter WI = `INTERP_SAMPLE_W,  // lattice, column values, px: Q8.8 unsigned
    parameter WC = `INTERP_COEF_W,    // coefficients: Q16.16 signed
    parameter WL = `INTERP_FD_LEN_W,
    parameter WM = `INTERP_FD_M_W,
    parameter DEPTH = `CELL_BUF_DEPTH,
    parameter WA = `CELL_BUF_ADDR_W
) (
    input  wire          clk,
    input  wire          ld_lat,
    input  wire [WI-1:0] in_lat_0,
    input  wire [WI-1:0] in_lat_1,
    input  wire [WI-1:0] in_lat_2,
    input  wire [WI-1:0] in_lat_3,
    input  wire [WI-1:0] in_lat_4,
    input  wire [WI-1:0] in_lat_5,
    input  wire [WI-1:0] in_lat_6,
    input  wire [WI-1:0] in_lat_7,
    input  wire [WI-1:0] in_lat_8,
    input  wire          col_start,
    input  wire          row_start,
    input  wire [WL-1:0] len,
    input  wire [WM-1:0] m,
    input  wire [WA-1:0] wa,
    input  wire [WA-1:0] ra,
    output wire [WI-1:0] px,
    output wire          col_valid,
    output wire          col_last,
    output wire          valid,
    output wire          last
);
    // Nets.
    wire [WI-1:0] lat_0, lat_1, lat_2, lat_3, lat_4, lat_5, lat_6, lat_7, lat_8;
    wire [WC-1:0] col_a_0, col_a_1, col_a_2, col_b_0, col_b_1, col_b_2, col_c_0, col_c_1, col_c_2;
    wire [WI-1:0] col_px_0, col_px_1, col_px_2, col_rd_0, col_rd_1, col_rd_2;
    // Columns 1 and 2 report their streams on nets of their own (the three run in step with column 0).
    wire col_valid_n_0, col_valid_n_1, col_last_n_0, col_last_n_1;
    wire [WC-1:0] row_a, row_b, row_c, zero_word;
    wire quad_sel;
    // The column buffers' overflow flags: 6 address wires name only words, so they stay 0.
    wire buf_overflow_0, buf_overflow_1, buf_overflow_2;
    wire unused_ok = &{1'b0, col_valid_n_0, col_valid_n_1, col_last_n_0, col_last_n_1, buf_overflow_0, buf_overflow_1,
                       buf_overflow_2, 1'b0};

    // Blocks.
    reg_block #(.W(WI)) rg_lat_0 (.ctl(ld_lat), .d(in_lat_0), .q(lat_0));
    reg_block #(.W(WI)) rg_lat_1 (.ctl(ld_lat), .d(in_lat_1), .q(lat_1));
    reg_block #(.W(WI)) rg_lat_2 (.ctl(ld_lat), .d(in_lat_2), .q(lat_2));
    reg_block #(.W(WI)) rg_lat_3 (.ctl(ld_lat), .d(in_lat_3), .q(lat_3));
    reg_block #(.W(WI)) rg_lat_4 (.ctl(ld_lat), .d(in_lat_4), .q(lat_4));
    reg_block #(.W(WI)) rg_lat_5 (.ctl(ld_lat), .d(in_lat_5), .q(lat_5));
    reg_block #(.W(WI)) rg_lat_6 (.ctl(ld_lat), .d(in_lat_6), .q(lat_6));
    reg_block #(.W(WI)) rg_lat_7 (.ctl(ld_lat), .d(in_lat_7), .q(lat_7));
    reg_block #(.W(WI)) rg_lat_8 (.ctl(ld_lat), .d(in_lat_8), .q(lat_8));
    constant #(.W(WC), .VALUE(0)) k_zero (.y(zero_word));
    constant #(.W(1), .VALUE(1)) k_quad (.y(quad_sel));
    coef_unit_quad cq_col_0 (
        .clk(clk), .i1(lat_0), .i2(lat_3), .i3(lat_6), .a(col_a_0), .b(col_b_0), .c(col_c_0));
    coef_unit_quad cq_col_1 (
        .clk(clk), .i1(lat_1), .i2(lat_4), .i3(lat_7), .a(col_a_1), .b(col_b_1), .c(col_c_1));
    coef_unit_quad cq_col_2 (
        .clk(clk), .i1(lat_2), .i2(lat_5), .i3(lat_8), .a(col_a_2), .b(col_b_2), .c(col_c_2));
    fd_channel #(.FIXED_M(0)) fd_col_0 (
        .clk(clk), .start(col_start), .deg_sel(quad_sel), .len(len), .m(m), .ca(zero_word), .cb(zero_word),
        .cc(zero_word), .cd(zero_word), .qa(col_a_0), .qb(col_b_0), .qc(col_c_0), .px(col_px_0), .valid(col_valid),
        .last(col_last));
    fd_channel #(.FIXED_M(0)) fd_col_1 (
        .clk(clk), .start(col_start), .deg_sel(quad_sel), .len(len), .m(m), .ca(zero_word), .cb(zero_word),
        .cc(zero_word), .cd(zero_word), .qa(col_a_1), .qb(col_b_1), .qc(col_c_1), .px(col_px_1), .valid(col_valid_n_0),
        .last(col_last_n_0));
    fd_channel #(.FIXED_M(0)) fd_col_2 (
        .clk(clk), .start(col_start), .deg_sel(quad_sel), .len(len), .m(m), .ca(zero_word), .cb(zero_word),
        .cc(zero_word), .cd(zero_word), .qa(col_a_2), .qb(col_b_2), .qc(col_c_2), .px(col_px_2), .valid(col_valid_n_1),
        .last(col_last_n_1));
    ram #(.W(WI), .DEPTH(DEPTH), .AW(WA)) buf_col_0 (
        .clk(clk), .we(col_valid), .wa(wa), .ra(ra), .wd(col_px_0), .rd(col_rd_0),
        .overflow(buf_overflow_0));
    ram #(.W(WI), .DEPTH(DEPTH), .AW(WA)) buf_col_1 (
        .clk(clk), .we(col_valid), .wa(wa), .ra(ra), .wd(col_px_1), .rd(col_rd_1),
        .overflow(buf_overflow_1));
    ram #(.W(WI), .DEPTH(DEPTH), .AW(WA)) buf_col_2 (
        .clk(clk), .we(col_valid), .wa(wa), .ra(ra), .wd(col_px_2), .rd(col_rd_2),
        .overflow(buf_overflow_2));
    coef_unit_quad cq_row (.clk(clk), .i1(col_rd_0), .i2(col_rd_1), .i3(col_rd_2), .a(row_a), .b(row_b), .c(row_c));
    fd_channel #(.FIXED_M(0)) fd_row (
        .clk(clk), .start(row_start), .deg_sel(quad_sel), .len(len), .m(m), .ca(zero_word), .cb(zero_word),
        .cc(zero_word), .cd(zero_word), .qa(row_a), .qb(row_b), .qc(row_c), .px(px), .valid(valid), .last(last));
endmodule
