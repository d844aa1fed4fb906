// The interpolation target in two dimensions, measured before it is built: a quadtree of square
// cells over the frame, each sent as the biquadratic through a 3 x 3 lattice of samples, decided from
// the differences of samples the scheme reads anyway. The line schemes (two_line.h) pay a check point
// for every decision and are held about 1.2x short of their perfect decisions by it; the lines above
// and below a raster line predict it twice as well as its own neighbours do (edge_study), which a
// cell uses directly. A departure from the interpolation paper's independent raster lines.
//
// The planner cannot run on cells, so the scheme is emulated here, real-valued, over the colours
// per-pixel shading gives (as two_line.h emulates the adaptive policy); cell_study prints it and
// test_cell_tree holds its pieces to hand-worked cases.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "two_line.h"

namespace shading::study {

// The scheme, in the order it runs (the bit-accurate cells' walk, golden_pipeline/quadtree.h, with
// this emulation's decisions), band by band (s_max lines) and in each band level by level, every
// level's reads batched in raster order across the band before any of its cells decides:
//  - tiles of s_max x s_max pixels, aligned to the frame; a cell [x0, x0 + s) x [y0, y0 + s) is
//    *whole* when every pixel of its closed box [x0, x0 + s] x [y0, y0 + s] is covered, each row of
//    the box lies in one of the planner's segments (pipeline::line_segments: no silhouette, fold or
//    depth step along it) and each pixel of the box is one patch with the one below it (no
//    pipeline::surface_break: the same triangle, or two of one object sharing a vertex);
//  - a whole cell reads its lattice, the 3 x 3 pixels at (x0 + i s/2, y0 + j s/2), and is sent as
//    the biquadratic through them (a quadratic through 0, s/2, s along each lattice column, then along
//    each row) when
//      (a) the second difference along every lattice row and column is within d2_factor x tol, and
//      (b) for a cell below the tile size, the third difference through four points of its family
//          lattice along each of its lattice rows and columns, times k3 (the quadratic's share of a
//          cubic term on [0, 2] lattice steps), is within d3_factor x tol. The family lattice is the
//          5 x 5 lattice (spacing s/2) over its parent, read when the parent is turned down, before
//          any of the four children decides: the children's own lattices together;
//    otherwise its four children are tried;
//  - a whole cell of s_min that is turned down: every one of its rows read at 0, 2 and 4 and sent as
//    the quadratic through them, checked at (1, 1), then (3, 3), within fallback_tol (the largest
//    channel); where a check misses, the cell's pixels are read exact;
//  - the pixels no cell delivered (next to silhouettes, folds and segment ends, and where a tile does
//    not fit): in runs along a column where a pixel's run along its column is at least column_ratio x
//    its run along its row and at least 5 pixels, else along rows, each run by the planner's adaptive
//    policy emulated (emulate_adaptive: cubic, split at the check, growth by one level, the exact
//    fallback, tol = line_tol, m <= line_m_max, no line-above limit).
// Every point read is delivered as read (the sample stage formed its colour; a check inside a sent
// cell or interval included). The decisions are adders and compares on colours the sample stage has
// formed; the biquadratic is forward differences down the lattice columns and along each row (the
// Lagrange weights' denominators are powers of two): no long operation beyond the points' geometry
// and colours.
// perfect: a yardstick, each cell (and each fallback) decided on the true RMS (levels, the three
// channels) of what it would send, at most tol (fallback_tol); every lattice and check point still read.
struct cell_tree_config {
    double tol = 0.9;            // levels
    double d2_factor = 8.0;
    double d3_factor = 1.0;
    double fallback_tol = 1.0;   // levels
    double line_tol = 1.5;       // levels
    unsigned s_max = 32, s_min = 4;  // powers of two, 4 <= s_min <= s_max <= 256
    unsigned line_m_max = 4;
    double column_ratio = 1.0;
    bool perfect = false;
};
// max over t in [0, 2] of |t (t - 1) (t - 2)| / 6: how far the quadratic through lattice points 0, 1, 2
// strays from a cubic whose third difference is 1 (at t = 1 -+ 1/sqrt(3)).
inline constexpr double k3 = 0.0641500299099584;

struct cell_frame {
    std::vector<rgb_levels> out;
    std::vector<uint8_t> point;                 // per pixel (row-major): 1 where the scheme read the colour
    std::vector<std::array<unsigned, 2>> order;  // {x, y} of every point, in the order the scheme reads them
    std::vector<uint8_t> order_down;  // empty, or per point of order: stepped down its column (the bit-accurate cells')
    // Cells sent as biquadratics, by size: sent[k] cells of s_min << k pixels.
    std::vector<std::size_t> sent;
    std::size_t fallback_rows = 0, fallback_exact = 0;  // s_min cells sent as row quadratics / read exact
    std::size_t pixels = 0, pixels_cells = 0, pixels_columns = 0, pixels_rows = 0;
    std::size_t points_lines = 0;  // points the column and row runs added
    double se = 0.0, ref2 = 0.0;   // squared error against colour, and its sum of squares (covered pixels)
    std::size_t points() const { return order.size(); }
    double nmse() const { return ref2 > 0.0 ? se / ref2 : 0.0; }
};

// The two estimates a cell is decided on (levels, the largest channel), for the tests and the study:
// the largest second difference along the rows and columns of the 3 x 3 lattice of the cell at
// (x0, y0) of s pixels; the largest third difference through its family lattice (the parent's at
// (px, py), 2s pixels), times k3. colour is row-major, width pixels a line; nothing is checked.
double lattice_second_difference(const std::vector<rgb_levels>& colour, unsigned width, unsigned x0, unsigned y0,
                                 unsigned s);
double family_third_difference(const std::vector<rgb_levels>& colour, unsigned width, unsigned x0, unsigned y0,
                               unsigned s, unsigned px, unsigned py);

// The scheme over a frame's per-pixel colours (row-major, levels), the segments and patches of r,
// the planner's segment rules from cfg. Throws std::invalid_argument for colours of another size or
// a configuration outside the ranges above.
cell_frame emulate_cells(const scene::rasterised& r, const std::vector<rgb_levels>& colour,
                         const pipeline::plan_config& cfg, const cell_tree_config& t);

// What the frame's points cost, counted as the planner counts a plan's (emulated_long_ops): each
// point's geometry stepped (pipeline::stepped_geometry) in the order the scheme reads them, or with
// raster_order line by line, left to right, and one colour formed at each.
emulated_cost cell_long_ops(const scene::rasterised& r, const cell_frame& f, const scene::device_config& dev,
                            unsigned n, bool walk_edges, bool raster_order);

}  // namespace shading::study
