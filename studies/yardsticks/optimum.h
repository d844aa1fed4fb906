// The optimum plan: a yardstick for the golden pipeline's length and degree policies
// (src/golden_pipeline/pipeline.h, make_plan), not a policy. It knows every pixel's colour and its
// reference and pays nothing to decide, so no policy can need fewer geometry points at its NMSE.
#pragma once

#include "golden_pipeline/pipeline.h"

namespace shading::yardsticks {

// What the optimum is asked for: the largest NMSE allowed, against per-pixel shading through the
// device (interpolation) or against exact Phong (total).
struct optimum_config {
    enum class reference { interpolation, total };
    double nmse = 1e-5;
    reference ref = reference::interpolation;
    // Instead of the optimum, the length policies' greedy structure with perfect estimates (see
    // optimal_plan): what a policy that knew every interval's error could reach. The certificate
    // (points_bound, nmse, lambda) stays the optimum's; the plan is the greedy's.
    bool greedy = false;
    // Negative: off. Else the optimum (or the greedy) prices each candidate with the line above's
    // error of the same candidate, the largest over starts within this many pixels: what a planner
    // that knew every colour of the line above, but none of its own line, could reach (see
    // optimal_plan). The certificate stays the optimum's.
    int from_above = -1;
};
inline constexpr unsigned window_max = 16;  // the widest window over the line above (pixels)
// Throws scene::scene_error for an NMSE below 0 or not finite, or a window above window_max.
void validate(const optimum_config& o);

// The optimum's certificate.
struct optimum_certificate {
    double points_bound = 0.0;   // no plan of these segments reaching the NMSE has fewer geometry points
    double nmse = 0.0;           // the plan's own NMSE against its reference (<= o.nmse if feasible)
    double lambda = 0.0;         // the Lagrange multiplier it was found with (points per squared level)
    bool feasible = false;       // false: even the lowest-error plan misses o.nmse (it is the plan)
    double point_long_min = 0.0; // long ops of the cheapest geometry point (a step, no set-up or run start)
    // With o.greedy: the greedy's tolerance (RMS levels per interval) and its plan's NMSE.
    double greedy_tolerance = 0.0, greedy_nmse = 0.0;
    // With o.from_above >= 0: the plan's NMSE (a plan priced from the line above may miss o.nmse even
    // at the largest lambda), and the share of candidates priced by their own line because the line
    // above had none there.
    double above_nmse = 0.0, above_fallback = 0.0;
    double above_lambda = 0.0;  // the lambda it was chosen at (the optimum's way; 0 for the greedy)
};

struct optimum {
    pipeline::plan p;
    optimum_certificate certificate;
};

// The optimum over every plan the pipeline can express for make_plan's segments of c (intervals of
// 2^c.m_min .. 2^c.m_max pixels, quadratic or cubic in c.set, exact pixels, tails as make_plan's),
// with no decision cost: fewest distinct geometry points such that the frame's NMSE against o.ref is
// at most o.nmse. A dynamic programme per segment minimises points + lambda x squared error; lambda
// is bisected to the smallest that meets the NMSE, and every lambda tried gives a Lagrangian lower
// bound (points + lambda (error - allowed error)) on the true optimum: certificate.points_bound. Its
// geometry is counted as make_plan's (pipeline::plan_of_jobs), its decision is the segments' fold
// tests; c.length and c.degree are not read. With o.greedy the plan is instead the length policies'
// structure given perfect estimates: per segment left to right, the longest m (growing by one level
// at most, as adaptive length) whose quadratic, else cubic, has an RMS error of at most a tolerance,
// bisected to the largest that meets the NMSE; where 2^m_min misses, 2^m_min exact pixels. Its gap to
// the optimum is the structure's cost. With o.from_above = W >= 0 the plan (either one) is chosen on
// prices from the line above: each candidate's error is the largest of the same candidate's on line
// y - 1 starting within W pixels (its own where the line above has none); lambda or the tolerance is
// bisected on the plan's true NMSE. Throws scene::scene_error for an invalid c or o.
optimum optimal_plan(const scene::rasterised& r, const pipeline::frame_constants& k, const scene::device_config& dev,
                     const pipeline::plan_config& c, const optimum_config& o);

}  // namespace shading::yardsticks
