// A two-line scheme for the interpolation target, measured before it is built: the even lines
// rendered by the adaptive length policy, then each odd line predicted by the mean of the delivered
// lines above and below (a line buffer and an adder a channel) and the same policy run on the
// residual, its samples correcting the prediction. edge_study measures how much smoother that
// residual is at fixed spacings; this measures what the policy makes of it.
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
// line-above limit. One line at a time (two_line false: tol_even everywhere), or the two-line scheme:
// the even lines first at tol_even, then each odd line with a line below at tol_odd, in runs where the
// pixel and those above and below lie on one patch of the mesh (one_patch; the residual against the
// mean of the delivered lines above and below) and runs where not (the colour itself); the last line,
// odd without a line below, on its own. Each line's limit reads the levels of the line before it in
// its own pass (one line at a time y - 1; two lines y - 2). even_exact (two lines only): the even lines
// are the colours themselves, each pixel a point, so the odd lines' figures show what the prediction
// gives at best.
struct emulated_frame {
    std::vector<rgb_levels> out;
    std::vector<uint8_t> point;  // per pixel (row-major): 1 where a geometry point was taken
    std::size_t points_even = 0, points_odd = 0, pixels_even = 0, pixels_odd = 0, pixels_predicted = 0;
    double se_even = 0.0, se_odd = 0.0, ref2 = 0.0;  // squared error against colour, and its sum of squares
    std::size_t points() const { return points_even + points_odd; }
    std::size_t pixels() const { return pixels_even + pixels_odd; }
    double nmse() const { return ref2 > 0.0 ? (se_even + se_odd) / ref2 : 0.0; }
};
emulated_frame emulate_frame(const scene::rasterised& r, const std::vector<rgb_levels>& colour,
                             const pipeline::plan_config& cfg, double tol_even, double tol_odd, bool two_line,
                             bool even_exact = false);

// What the emulated frame's points cost, counted as the planner counts a plan's (hardware_ops with the
// carry): each point's geometry stepped along its line (pipeline::stepped_geometry, in the order the
// scheme renders: one line at a time y = 0, 1, 2, ...; two lines the even lines, then the odd ones;
// left to right in each) and one colour formed at each (pipeline::colour_sample_ops). The rest is
// adders: the coefficient units, the forward differences, and the two-line prediction (the mean of
// two lines, a shift) with its subtraction at the samples and addition at every pixel.
struct emulated_cost {
    scene::op_counts geometry, colours;
    scene::stepping_stats stepping;
    double long_ops() const { return double(geometry.long_ops() + colours.long_ops()); }
};
std::vector<std::array<unsigned, 2>> points_in_order(const emulated_frame& f, unsigned width, unsigned height,
                                                     bool two_line);
emulated_cost emulated_long_ops(const scene::rasterised& r, const emulated_frame& f, bool two_line,
                                const scene::device_config& dev, unsigned n, bool walk_edges);

}  // namespace shading::study
