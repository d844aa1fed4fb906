// Cells (ours, a departure from the interpolation paper's independent raster lines): the frame tiled
// in square cells, each sent as the biquadratic through a 3 x 3 lattice of colour samples when the
// lattice's own differences say it may be, split in four otherwise; what no cell delivers goes to the
// adaptive length policy along its raster line. Bit-accurate, as golden_interval: every colour is a
// sample stage's code (golden_sample), every interpolation the quadratic coefficient unit and an
// evaluator (quadratic_pixels), every decision an adder or a compare on codes against per-frame
// constants. The study that chose the scheme and its constants emulates it in doubles
// (studies/pipeline/cell_tree.h); this is the model a SystemC cell unit is to match.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "golden_pipeline/pipeline.h"

namespace shading::pipeline {

// The scheme, band by band (s_max lines) and in each band level by level, each level's points read
// together in raster order across the band before any of its cells decides:
//  - tiles of s_max x s_max pixels aligned to the frame; a cell [x0, x0 + s) x [y0, y0 + s) is whole
//    when every pixel of its closed box [x0, x0 + s] x [y0, y0 + s] is covered, each row of the box
//    lies in one segment (line_segments) and no pixel of the box is a fold (surface_break) from the
//    one below it;
//  - a whole cell reads its lattice, the 3 x 3 pixels at (x0 + j s/2, y0 + i s/2), and is sent when
//      (a) the second difference |c0 - 2 c1 + c2| along every lattice row and column, every channel,
//          is at most d2 = floor(d2_factor x tol x 256) codes, and
//      (b) below the tile size, the third difference |c3 - 3 c2 + 3 c1 - c0| through four points of
//          its family lattice (the 5 x 5 lattice over its parent, read when the parent was turned
//          down) along each of its lattice rows and columns is at most d3 = floor(d3_factor x tol x
//          256 / k3) codes, k3 = 1 / (9 sqrt 3) the quadratic's share of a cubic term;
//    otherwise its four children are tried;
//  - a whole cell of s_min turned down: each row read at 0, 2 and 4 and sent as a quadratic interval
//    (interval_job, m = 2), checked at (1, 1) and then (3, 3) against the colour there within
//    floor(fallback_tol x 256) codes; where a check misses, its pixels are exact (m = 0 jobs);
//  - the pixels no cell delivered (next to silhouettes, folds and segment ends, where a tile does not
//    fit) by make_plan (the taken map): adaptive length, cubic, split at the check, the exact
//    fallback, length_tol = line_tol, m <= line_m_max; first down the columns, over the pixels whose
//    run of such pixels down their column (joined where a pixel is one surface with the one below)
//    is at least 5 pixels and at least column_ratio x their run along their row (within one
//    segment), by make_plan on the transposed frame (scene::transposed); then along the rows, over
//    the rest of each line.
struct cell_config {
    double tol = 0.9;            // levels
    double d2_factor = 8.0;
    double d3_factor = 1.0;
    double fallback_tol = 1.0;   // levels
    unsigned s_max = 32, s_min = 4;  // powers of two, s_min = 4 (the fallback's rows), s_max <= 2^interp::m_max
    double line_tol = 1.5;       // levels
    unsigned line_m_max = 4;     // interp::m_min .. interp::m_max
    double column_ratio = 1.0;   // >= 0; 0: no column runs, the rest along rows only
};
// Throws scene::scene_error naming what is wrong.
void validate(const cell_config& t);

// max over t in [0, 2] of |t (t - 1) (t - 2)| / 6 = 1 / (9 sqrt 3).
inline constexpr double cell_k3 = 0.0641500299099584;

// The decision unit's per-frame constants, colour_fmt codes.
struct cell_limits {
    uint64_t d2 = 0, d3 = 0, fallback = 0;
};
cell_limits cell_limits_of(const cell_config& t);

// A cell sent as a biquadratic: pixels [x0, x0 + s) x [y0, y0 + s); its lattice's geometry row-major,
// lattice[3 i + j] at (x0 + j s/2, y0 + i s/2) (the points at x0 + s and y0 + s are pixels of the
// cells beside and below).
struct cell_job {
    unsigned x0 = 0, y0 = 0, s = 0;
    std::array<sample_geometry, 9> lattice{};
};

struct cell_plan {
    unsigned width = 0, height = 0;
    std::vector<cell_job> cells;
    // The s_min cells' fallbacks (row quadratics, exact pixels), then the rows' intervals.
    std::vector<interval_job> jobs;
    // The columns' intervals, in the transposed frame: job.y is the column, job.x0 its first line,
    // the pixels (job.y, job.x0 + i).
    std::vector<interval_job> column_jobs;
    // Every pixel whose geometry and colour were formed, once, in the order the scheme reads them,
    // and its geometry (what the sample stage is given there); point_down[i] where it was read down
    // a column (the columns' runs: the geometry side steps it from the point above).
    std::vector<std::array<unsigned, 2>> points;
    std::vector<sample_geometry> point_geometry;
    std::vector<uint8_t> point_down;
    std::vector<std::size_t> sent;   // cells sent by size: sent[k] of s_min << k pixels
    std::size_t fallback_rows = 0, fallback_exact = 0;  // s_min cells sent as row quadratics / exact
    std::size_t pixels = 0, pixels_cells = 0;  // covered; by cells and fallbacks
    std::size_t pixels_columns = 0, pixels_rows = 0;  // by the columns' and the rows' intervals
    std::size_t points_lines = 0;   // points the columns and rows added
    scene::op_counts decision;      // the cells' differences and compares; the fold compares between neighbours
                                    // along rows and down columns, charged by the cells and again by the rows' and
                                    // the columns' planners, which each test them; the planners' estimates
};

// c: the segments' rules (depth_step, surface_breaks), the evaluator whose pixels the fallbacks'
// checks read, and the lines' sample set and /3 mode; its length and degree fields are not read.
// Throws scene::scene_error for an invalid configuration.
cell_plan make_cell_plan(const scene::rasterised& r, const frame_constants& k, const scene::device_config& dev,
                         const plan_config& c, const cell_config& t);

// The lattice's nine colours, row-major (the sample stage's codes).
std::array<rgb_codes, 9> cell_lattice_colours(const cell_job& cell, const frame_constants& k,
                                              const scene::device_config& dev);
// The biquadratic's s x s pixels, row-major: quadratic_pixels (m = log2 s) down each of the three
// lattice columns gives three colours per row, then along each row. The column values are pixel_fmt
// words like any evaluator's output (clamped to 0 .. 0xFFFF), so a column overshooting the colour
// range parts from the real-valued biquadratic there. Throws scene::scene_error for a
// size outside 4 .. 2^interp::m_max or not a power of two.
std::vector<rgb_codes> cell_pixels(const std::array<rgb_codes, 9>& lattice, unsigned s, evaluator e);

// The frame the scheme delivers: cell_pixels for every cell, golden_interval for every job and
// column job (c.eval, c.set, c.div); degree 2 and log2_len log2 s on a cell's pixels. Then at every
// point inside a cell the colour the sample stage formed there, as an exact pixel (point_jobs;
// degree 1): the biquadratic only comes within a tolerance of it. Points inside an interval keep
// the interval's pixel, as the shading pipeline delivers them.
frame golden_cell_frame(const cell_plan& p, const frame_constants& k, const scene::device_config& dev,
                        const plan_config& c);
// The exact pixels (m = 0 jobs) of the points no job covers, in the order read.
std::vector<interval_job> point_jobs(const cell_plan& p);
// What the shading pipeline (modules/pipeline/shading_pipeline.h) takes of the scheme: the plan's
// jobs, its column jobs, then point_jobs. The pipeline interpolates along whatever run its job
// describes; a column job's pixels go down the column. So the plan's frame is the cells' frame with
// the transposed frame stacked below it (width max(W, H), height H + W): a column job's descriptor is
// y = H + its column, x0 its first line, and cells_frame_of folds that part back. With the cells
// from the cell unit (modules/pipeline/cell_unit.h) first, the pipeline's frame buffer, folded, over
// theirs is golden_cell_frame.
plan pipeline_plan(const cell_plan& p);
// The W x H frame of a pipeline_plan's frame buffer (its stacked part transposed back). Throws
// scene::scene_error for a frame of another size or a pixel delivered in both parts.
frame cells_frame_of(const cell_plan& p, const frame& stacked);

// The long operations' side of the count: each point's geometry stepped (stepped_geometry) in the
// order read, the columns' points down their columns (or, with raster_order, line by line), and one
// colour formed at each (colour_sample_ops).
// The cells' evaluators are forward differences and their decisions adders and compares.
struct cell_counts {
    scene::op_counts geometry, colours;
    scene::stepping_stats stepping;
    double long_ops() const { return double(geometry.long_ops() + colours.long_ops()); }
};
cell_counts cell_ops(const scene::rasterised& r, const cell_plan& p, const scene::device_config& dev, unsigned n,
                     bool walk_edges, bool raster_order = false);

}  // namespace shading::pipeline
