// A two-line scheme for the interpolation target, measured before it is built: the even lines
// rendered by the adaptive length policy, then each odd line predicted by the mean of the delivered
// lines above and below (a line buffer and an adder a channel) and the same policy run on the
// residual, its samples correcting the prediction; and its generalisation to a hierarchy of such
// passes (every fourth line first, then the lines between them two apart, then the odd ones).
// edge_study measures how much smoother that residual is at fixed spacings; this measures what the
// policy makes of it.
//
// The planner cannot run on a residual, so its adaptive policy is emulated here, real-valued
// (emulate_adaptive); two_line_study prints the emulation beside the planner on the same frame, and
// test_two_line holds them to each other.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edge_split.h"
#include "golden_pipeline/pipeline.h"
#include "scene/raster.h"

namespace shading::study {

// plan.cpp's adaptive length with the cubic degree, sample set case 1, split at the check point, the
// exact fallback and growth by one level, on one run of values v (levels): from each position the
// longest m in m_min..grow (2^m pixels of room) whose quadratic through t = 0, 1/2, 1 misses the
// sample at t = 1/4 by at most 2 tol and whose cubic through t = 0, 1/4, 1/2, 1 misses the check
// point t = 3/4 by at most tol (the largest channel); sent as the two halves' quadratics (2^m_min:
// the cubic itself); where even 2^m_min misses, its pixels exact; the tail exact. With the line-above
// limit (above_slack K >= 0 and the levels `above` of the run's pixels on the line before), a
// candidate longer than 2^m_min is not tried where a pixel's level there plus K is below m.
// points: the distinct pixels whose value it read (samples, check points, candidates turned down);
// level: each pixel's interval m as sent (a split interval's halves m - 1, exact pixels 0), the next
// line's `above`.
struct adaptive_emulation {
    double tol = 1.0;  // levels
    unsigned m_min = interp::m_min, m_max = 5;
    int above_slack = -1;  // plan_config::above_slack; negative: no limit
    // The planner's perfect decisions (studies/yardsticks/perfect_decisions.h), a yardstick: every
    // candidate's samples and check point still read, each decision taken on the true RMS (levels,
    // the three channels) of what the candidate sends, at most tol, instead of on the two misses above.
    bool perfect = false;
};
inline constexpr uint8_t no_level = 0xFF;  // `above` where the line before sent nothing
struct emulated_run {
    std::vector<rgb_levels> out;
    std::vector<uint8_t> level;
    std::vector<uint8_t> point;  // 1 where the policy read the value: the points, counted in `points`
    std::size_t points = 0;
};
emulated_run emulate_adaptive(const std::vector<rgb_levels>& v, const adaptive_emulation& e,
                              const uint8_t* above = nullptr);

// A frame's per-pixel colours (row-major, levels; uncovered pixels ignored) rendered by the emulated
// policy over the planner's segments (pipeline::line_segments with cfg), with cfg's m_min, m_max and
// line-above limit (and with `perfect` the perfect decisions), in passes over the lines; tols holds one
// tolerance a pass, L + 1 of them (L = 0..4):
//  - pass 0: every 2^L-th line (y = 0, 2^L, ...) from its colours alone at tols[0]; L = 0 is one line
//    at a time, L = 1 the two-line scheme (the even lines, then the odd ones);
//  - pass i = 1..L: the lines halfway between those rendered so far, d = 2^(L - i) from them
//    (y = d, 3d, 5d, ...), each predicted by the mean of the delivered lines d above and d below and
//    the policy run on the residual at tols[i], in runs where the pixel and those above and below lie
//    on one patch of the mesh (one_patch), from its colours in runs where not; a line with no line d
//    below (the last) on its own.
// Each line's limit reads the levels of the line before it in its own pass. first_exact: pass 0's
// lines are the colours themselves, each pixel a point, so the other passes' figures show what the
// prediction gives at best.
struct emulated_frame {
    std::vector<rgb_levels> out;
    std::vector<uint8_t> point;   // per pixel (row-major): 1 where a geometry point was taken
    std::vector<unsigned> lines;  // the lines in the order the passes render them
    // "first": pass 0's lines; "rest": the lines of the later passes; pixels_predicted: the rest's
    // pixels rendered from a prediction.
    std::size_t points_first = 0, points_rest = 0, pixels_first = 0, pixels_rest = 0, pixels_predicted = 0;
    double se_first = 0.0, se_rest = 0.0, ref2 = 0.0;  // squared error against colour, and its sum of squares
    std::size_t points() const { return points_first + points_rest; }
    std::size_t pixels() const { return pixels_first + pixels_rest; }
    double nmse() const { return ref2 > 0.0 ? (se_first + se_rest) / ref2 : 0.0; }
};
emulated_frame emulate_lines(const scene::rasterised& r, const std::vector<rgb_levels>& colour,
                             const pipeline::plan_config& cfg, const std::vector<double>& tols,
                             bool first_exact = false, bool perfect = false);

// What the emulated frame's points cost, counted as the planner counts a plan's (hardware_ops with the
// carry): each point's geometry stepped along its line (pipeline::stepped_geometry, in the order the
// passes render the lines, left to right in each) and one colour formed at each
// (pipeline::colour_sample_ops). The rest is adders: the coefficient units, the forward differences,
// and the prediction (the mean of two lines, a shift) with its subtraction at the samples and
// addition at every pixel.
struct emulated_cost {
    scene::op_counts geometry, colours;
    scene::stepping_stats stepping;
    double long_ops() const { return double(geometry.long_ops() + colours.long_ops()); }
};
std::vector<std::array<unsigned, 2>> points_in_order(const emulated_frame& f, unsigned width);
// Points {x, y} taken in this order, counted so: stepped_geometry (down: its column flags) and a
// colour at each.
emulated_cost points_cost(const scene::rasterised& r, const std::vector<std::array<unsigned, 2>>& points,
                          const scene::device_config& dev, unsigned n, bool walk_edges,
                          const std::vector<uint8_t>& down = {});
emulated_cost emulated_long_ops(const scene::rasterised& r, const emulated_frame& f, const scene::device_config& dev,
                                unsigned n, bool walk_edges);

}  // namespace shading::study
