// Controller of the cell unit (ours; modules/pipeline/cell_ctrl.h), state for state: a clocked FSM on
// the rising edge of clk.
//   idle     ready = 1; where start = 1 it takes the cell's x0, y0 and m (s = 2^m pixels a side),
//            raises ld_lat and drops ready;
//   latch    ld_lat falls (the lattice registers latch at this edge); col_start = 1;
//   columns  the column channels take the cell where col_start = 1 and they are idle; wa counts the
//            column values written into the buffers (each at an edge that sees col_valid);
//   rows     with the last column value written, ra = 0 and row_start = 1; the row channel takes row
//            y at an edge where it is idle or on its last pixel, and one clock later ra moves to row
//            y + 1; px_x / px_y are set at the taking edge and stepped one clock ahead of each pixel;
//   back to idle at the edge that sees the last row's last pixel.
// The next state is computed in the SystemC method's order from the values before the edge; every
// register takes it at the rising edge. Bad input: m outside m_min .. m_max is taken as the nearest
// (the SystemC model reports it; a report is not hardware). No reset pin: ready starts at 1 (its
// initialize(true)), every other register at the SystemC member's start; the cell count is the
// testbench's, not hardware. The register s_ of the SystemC model is len here (written together).
`include "shading_formats.vh"
`include "interp_terms.vh"
module cell_ctrl #(
    parameter WX = `CELL_COORD_W,     // x0, y0, px_x, px_y
    parameter WL = `INTERP_FD_LEN_W,  // len = s, and the row and pixel counters (up to s)
    parameter WM = `INTERP_FD_M_W,    // m
    parameter WA = `CELL_BUF_ADDR_W   // wa, ra
) (
    input  wire          clk,
    input  wire          start,
    input  wire [WX-1:0] in_x0,
    input  wire [WX-1:0] in_y0,
    input  wire [WM-1:0] in_m,
    input  wire          col_valid,  // channel R's (the three run in step)
    input  wire          col_last,
    input  wire          row_valid,
    input  wire          row_last,
    output reg           ready = 1'b1,
    output reg           ld_lat = 1'b0,
    output reg           col_start = 1'b0,
    output reg           row_start = 1'b0,
    output reg  [WL-1:0] len = {WL{1'b0}},
    output reg  [WM-1:0] m = {WM{1'b0}},
    output reg  [WA-1:0] wa = {WA{1'b0}},
    output reg  [WA-1:0] ra = {WA{1'b0}},
    output reg  [WX-1:0] px_x = {WX{1'b0}},
    output reg  [WX-1:0] px_y = {WX{1'b0}}
);
    // cell_ctrl::phase, in its order.
    localparam [1:0] IDLE = 2'd0, LATCH = 2'd1, COLUMNS = 2'd2, ROWS = 2'd3;
    localparam [WM-1:0] M_MIN = `INTERP_M_MIN, M_MAX = `INTERP_M_MAX;
    localparam [WL-1:0] ONE = {{(WL-1){1'b0}}, 1'b1}, ZERO = {WL{1'b0}};

    // The SystemC members: col_start_ and row_start_ are the outputs col_start and row_start, wa_ is
    // wa, s_ is len.
    reg [1:0] phase = IDLE;
    reg move_ra = 1'b0;
    reg [WX-1:0] x0 = {WX{1'b0}}, y0 = {WX{1'b0}};
    reg [WL-1:0] row = ZERO, next_x = ZERO, left = ZERO;

    // Next state.
    reg [1:0] phase_n;
    reg move_ra_n;
    reg [WX-1:0] x0_n, y0_n;
    reg [WL-1:0] row_n, next_x_n, left_n;
    reg ready_n, ld_lat_n, col_start_n, row_start_n;
    reg [WL-1:0] len_n;
    reg [WM-1:0] m_n, mm;
    reg [WA-1:0] wa_n, ra_n;
    reg [WX-1:0] px_x_n, px_y_n;

    always @(*) begin
        phase_n = phase; move_ra_n = move_ra; x0_n = x0; y0_n = y0;
        row_n = row; next_x_n = next_x; left_n = left;
        ready_n = ready; ld_lat_n = ld_lat; col_start_n = col_start; row_start_n = row_start;
        len_n = len; m_n = m; wa_n = wa; ra_n = ra; px_x_n = px_x; px_y_n = px_y;
        mm = in_m < M_MIN ? M_MIN : in_m > M_MAX ? M_MAX : in_m;  // take(): the nearest size
        case (phase)
            IDLE:
                if (start) begin  // take()
                    x0_n = in_x0;
                    y0_n = in_y0;
                    len_n = ONE << mm;
                    m_n = mm;
                    ld_lat_n = 1'b1;
                    ready_n = 1'b0;
                    phase_n = LATCH;
                end
            LATCH: begin
                ld_lat_n = 1'b0;  // the lattice registers latch at this edge
                col_start_n = 1'b1;
                phase_n = COLUMNS;
            end
            COLUMNS:  // columns()
                if (col_start && !col_valid) begin  // the column channels take the cell here
                    col_start_n = 1'b0;
                    wa_n = {WA{1'b0}};
                end else if (col_valid && !col_last) begin  // this edge writes row wa's column values
                    wa_n = wa + 1'b1;
                end else if (col_valid) begin  // the last column value is written here: the rows start
                    row_n = ZERO;
                    ra_n = {WA{1'b0}};
                    row_start_n = 1'b1;
                    phase_n = ROWS;
                end
            default: begin  // ROWS: rows()
                if (move_ra) begin  // one clock after a row was taken: the next row's column values
                    ra_n = row[WA-1:0];
                    move_ra_n = 1'b0;
                end
                if (row_start && (!row_valid || row_last)) begin  // the row channel takes row `row` here
                    px_x_n = x0;
                    px_y_n = y0 + {{(WX-WL){1'b0}}, row};
                    next_x_n = ONE;
                    left_n = len - ONE;
                    row_n = row + ONE;
                    if (row + ONE < len) move_ra_n = 1'b1;
                    else row_start_n = 1'b0;
                end else if (left != ZERO) begin  // px_x one clock ahead of the pixel
                    px_x_n = x0 + {{(WX-WL){1'b0}}, next_x};
                    next_x_n = next_x + ONE;
                    left_n = left - ONE;
                end else if (!row_start && row_valid && row_last) begin  // the cell's last pixel is stored here
                    ready_n = 1'b1;
                    phase_n = IDLE;
                end
            end
        endcase
    end

    always @(posedge clk) begin
        phase <= phase_n; move_ra <= move_ra_n; x0 <= x0_n; y0 <= y0_n;
        row <= row_n; next_x <= next_x_n; left <= left_n;
        ready <= ready_n; ld_lat <= ld_lat_n; col_start <= col_start_n; row_start <= row_start_n;
        len <= len_n; m <= m_n; wa <= wa_n; ra <= ra_n; px_x <= px_x_n; px_y <= px_y_n;
    end
endmodule
