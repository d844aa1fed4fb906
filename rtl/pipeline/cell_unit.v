// The cell unit (ours; modules/pipeline/cell_unit.h, page modules/pipeline/cell_unit.md): the
// biquadratic through a 3 x 3 lattice of colour samples over a cell of s x s pixels, s = 2^m (4 .. 64),
// streamed row by row as R, G, B pixels on the shading pipeline's pixel stream. A device top: it only
// instantiates and wires.
//   ctl        the controller (cell_ctrl.v): handshake, lattice strobe, column and row phases,
//              buffer addresses, pixel coordinates
//   ch_r/g/b   per channel: lattice registers, column coefficient units and forward-difference
//              channels, column buffers, the row's coefficient unit and channel (cell_channel.v)
// Pins as the SystemC module's, in its order; its lattice vectors in_lat_r/g/b[0..8] are the
// numbered pins in_lat_r_0..8 (as sc_vector names them), lattice[3 i + j] at (x0 + j s/2, y0 + i s/2).
// At a rising edge of clk where px_valid = 1, px_r/g/b belong at (px_x, px_y).
`include "shading_formats.vh"
`include "interp_terms.vh"
module cell_unit (
    input  wire clk,
    input  wire start,
    output wire ready,
    input  wire [`CELL_COORD_W-1:0] in_x0,
    input  wire [`CELL_COORD_W-1:0] in_y0,
    input  wire [`INTERP_FD_M_W-1:0] in_m,
    input  wire [`INTERP_SAMPLE_W-1:0] in_lat_r_0, in_lat_r_1, in_lat_r_2, in_lat_r_3, in_lat_r_4,
                                       in_lat_r_5, in_lat_r_6, in_lat_r_7, in_lat_r_8,
    input  wire [`INTERP_SAMPLE_W-1:0] in_lat_g_0, in_lat_g_1, in_lat_g_2, in_lat_g_3, in_lat_g_4,
                                       in_lat_g_5, in_lat_g_6, in_lat_g_7, in_lat_g_8,
    input  wire [`INTERP_SAMPLE_W-1:0] in_lat_b_0, in_lat_b_1, in_lat_b_2, in_lat_b_3, in_lat_b_4,
                                       in_lat_b_5, in_lat_b_6, in_lat_b_7, in_lat_b_8,
    output wire px_valid,
    output wire [`CELL_COORD_W-1:0] px_x,
    output wire [`CELL_COORD_W-1:0] px_y,
    output wire [`INTERP_SAMPLE_W-1:0] px_r,
    output wire [`INTERP_SAMPLE_W-1:0] px_g,
    output wire [`INTERP_SAMPLE_W-1:0] px_b
);
    // Nets.
    wire ld_lat, col_start, row_start;
    wire col_valid, col_last, row_last;
    wire [`INTERP_FD_LEN_W-1:0] len;
    wire [`INTERP_FD_M_W-1:0] m;
    wire [`CELL_BUF_ADDR_W-1:0] wa, ra;
    // Channels G and B report their streams on nets of their own (the three run in step with R).
    wire col_valid_g, col_last_g, valid_g, last_g, col_valid_b, col_last_b, valid_b, last_b;
    wire unused_ok = &{1'b0, col_valid_g, col_last_g, valid_g, last_g, col_valid_b, col_last_b, valid_b, last_b,
                       1'b0};

    cell_ctrl ctl (
        .clk(clk), .start(start), .in_x0(in_x0), .in_y0(in_y0), .in_m(in_m), .col_valid(col_valid),
        .col_last(col_last), .row_valid(px_valid), .row_last(row_last), .ready(ready), .ld_lat(ld_lat),
        .col_start(col_start), .row_start(row_start), .len(len), .m(m), .wa(wa), .ra(ra), .px_x(px_x),
        .px_y(px_y));
    cell_channel ch_r (
        .clk(clk), .ld_lat(ld_lat), .in_lat_0(in_lat_r_0), .in_lat_1(in_lat_r_1), .in_lat_2(in_lat_r_2),
        .in_lat_3(in_lat_r_3), .in_lat_4(in_lat_r_4), .in_lat_5(in_lat_r_5),
        .in_lat_6(in_lat_r_6), .in_lat_7(in_lat_r_7), .in_lat_8(in_lat_r_8),
        .col_start(col_start), .row_start(row_start), .len(len), .m(m), .wa(wa), .ra(ra), .px(px_r),
        .col_valid(col_valid), .col_last(col_last), .valid(px_valid), .last(row_last));
    cell_channel ch_g (
        .clk(clk), .ld_lat(ld_lat), .in_lat_0(in_lat_g_0), .in_lat_1(in_lat_g_1), .in_lat_2(in_lat_g_2),
        .in_lat_3(in_lat_g_3), .in_lat_4(in_lat_g_4), .in_lat_5(in_lat_g_5),
        .in_lat_6(in_lat_g_6), .in_lat_7(in_lat_g_7), .in_lat_8(in_lat_g_8),
        .col_start(col_start), .row_start(row_start), .len(len), .m(m), .wa(wa), .ra(ra), .px(px_g),
        .col_valid(col_valid_g), .col_last(col_last_g), .valid(valid_g), .last(last_g));
    cell_channel ch_b (
        .clk(clk), .ld_lat(ld_lat), .in_lat_0(in_lat_b_0), .in_lat_1(in_lat_b_1), .in_lat_2(in_lat_b_2),
        .in_lat_3(in_lat_b_3), .in_lat_4(in_lat_b_4), .in_lat_5(in_lat_b_5),
        .in_lat_6(in_lat_b_6), .in_lat_7(in_lat_b_7), .in_lat_8(in_lat_b_8),
        .col_start(col_start), .row_start(row_start), .len(len), .m(m), .wa(wa), .ra(ra), .px(px_b),
        .col_valid(col_valid_b), .col_last(col_last_b), .valid(valid_b), .last(last_b));
endmodule
