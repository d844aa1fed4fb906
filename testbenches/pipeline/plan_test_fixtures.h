// Fixtures and independent checks shared by the geometry side's tests (test_pipeline_plan.cpp) and
// the zone map's (test_pipeline_zones.cpp): scenes rasterised once, cuts and folds recomputed from
// the rasteriser, the plan validity check, geometry counted by hand rules.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "golden_pipeline/pipeline.h"
#include "scene/image.h"

namespace plan_test {

using namespace shading;
using namespace shading::pipeline;


const scene::device_config patent{};

struct scene_fixture {
    scene::world w;
    scene::rasterised r;
    frame_constants k;
    scene_fixture(const std::string& name, unsigned size) : scene_fixture(scene::builtin_scene(name, SHADING_SOURCE_DIR, size, size)) {}
    explicit scene_fixture(scene::world world) : w(std::move(world)), r(scene::rasterise(w)), k(frame_constants_of(w)) {}
    // rasterised points at the world: the fixture is neither copied nor moved.
    scene_fixture(const scene_fixture&) = delete;
};

inline const scene_fixture& sphere() {
    static const scene_fixture f("sphere", 64);
    return f;
}
inline const scene_fixture& head() {
    static const scene_fixture f("head", 128);
    return f;
}

// Sample points of a job in eighths of N (pipeline.h): the documented sets.
inline std::vector<unsigned> job_points(const interval_job& j, interp::sample_set set) {
    if (j.m == 0) return {0};
    if (j.deg2) return {0, 4, 8};
    return set == interp::sample_set::case1 ? std::vector<unsigned>{0, 2, 4, 8} : std::vector<unsigned>{0, 4, 6, 8};
}
inline unsigned at(const interval_job& j, unsigned eighths) { return j.x0 + eighths * (1u << j.m) / 8; }

inline bool fold(const scene::rasterised& r, unsigned y, unsigned x);

// The pixels of line y where the rasteriser's discontinuities fall (between x - 1 and x), and with
// surface breaks the folds too.
inline std::set<unsigned> cuts(const scene::rasterised& r, unsigned y, double step, bool folds) {
    std::set<unsigned> s;
    for (const auto& d : scene::line_discontinuities(r, y, step)) s.insert(d.x);
    if (folds)
        for (unsigned x = 1; x < r.width; ++x)
            if (r.covered(x - 1, y) && r.covered(x, y) && fold(r, y, x)) s.insert(x);
    return s;
}
inline std::set<unsigned> cuts(const scene::rasterised& r, unsigned y, const plan_config& c) {
    return cuts(r, y, c.depth_step, c.surface_breaks);
}

// The segment end (last pixel) of the segment holding pixel x on line y, from the discontinuities.
inline unsigned segment_end(const std::set<unsigned>& c, unsigned x) { return *c.upper_bound(x) - 1; }

// Whether the triangles under two neighbouring pixels share no vertex (a fold of the mesh), from
// the mesh's vertex indices.
inline bool fold(const scene::rasterised& r, unsigned y, unsigned x) {
    const auto& a = r.setups[static_cast<std::size_t>(r.tri[r.index(x - 1, y)])];
    const auto& b = r.setups[static_cast<std::size_t>(r.tri[r.index(x, y)])];
    if (a.object != b.object) return true;
    const auto& m = r.src->objects[a.object].geometry;
    std::set<uint32_t> va(m.triangles[a.triangle].begin(), m.triangles[a.triangle].end());
    for (uint32_t v : m.triangles[b.triangle])
        if (va.count(v)) return false;
    return true;
}

// The checks every plan must pass, whatever its policies.
inline void expect_valid_plan(const scene::rasterised& r, const plan& p, const plan_config& c) {
    ASSERT_EQ(p.width, r.width);
    ASSERT_EQ(p.height, r.height);
    std::vector<int> hits(static_cast<std::size_t>(r.width) * r.height, 0);
    std::size_t pixels = 0;
    // Fixed length: tails take shorter intervals down to the units' m_min, except for the forward-
    // difference evaluator, built for one m (its tails are exact pixels).
    const unsigned lowest = c.length != length_policy::fixed ? c.m_min : c.eval == evaluator::fd ? c.m : interp::m_min;
    const unsigned highest = c.length == length_policy::fixed ? c.m : c.m_max;
    std::map<unsigned, std::set<unsigned>> line_cuts;
    unsigned prev_y = 0, prev_end = 0;
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        const interval_job& j = p.jobs[i];
        SCOPED_TRACE("job " + std::to_string(i) + " at line " + std::to_string(j.y) + ", x " + std::to_string(j.x0) +
                     ", m " + std::to_string(j.m));
        // Lines in order, left to right, no overlap.
        ASSERT_TRUE(j.y > prev_y || (j.y == prev_y && (i == 0 || j.x0 >= prev_end)));
        prev_y = j.y;
        prev_end = j.x0 + j.len;
        if (j.m == 0) {
            EXPECT_EQ(j.len, 1u);
            EXPECT_FALSE(j.deg2);
        } else {
            EXPECT_GE(j.m, lowest);
            EXPECT_LE(j.m, highest);
            EXPECT_EQ(j.len, 1u << j.m);  // full intervals only
        }
        for (unsigned x = j.x0; x < j.x0 + j.len; ++x) {
            ASSERT_LT(x, r.width);
            EXPECT_TRUE(r.covered(x, j.y));
            ++hits[r.index(x, j.y)];
        }
        pixels += j.len;
        // No discontinuity between the first pixel and the last sample point.
        auto& lc = line_cuts[j.y];
        if (lc.empty()) lc = cuts(r, j.y, c);
        const unsigned last = j.m == 0 ? j.x0 : j.x0 + (1u << j.m);
        const auto next_cut = lc.upper_bound(j.x0);
        ASSERT_NE(next_cut, lc.end());
        EXPECT_GT(*next_cut, last) << "a discontinuity inside the interval's samples";
        if (c.surface_breaks) {
            for (unsigned x = j.x0 + 1; x <= last; ++x) EXPECT_FALSE(fold(r, j.y, x)) << "a fold at x " << x;
        }
        // The samples are the geometry at the documented pixels.
        const auto pts = job_points(j, c.set);
        for (std::size_t s = 0; s < 4; ++s) {
            const unsigned x = at(j, pts[std::min(s, pts.size() - 1)]);
            EXPECT_EQ(j.s[s], sample_of(scene::geometry_at(r, x, j.y, nullptr))) << "sample " << s << " at x " << x;
        }
        EXPECT_EQ(j.zone, head_zone(r, scene::geometry_at(r, j.x0, j.y, nullptr)));
        // Exact pixels only in a segment's tail, shorter than the shortest interval plus its t = 1 pixel
        // (or, with a checking length policy's exact fallback, in runs of 2^m_min: ExactFallback).
        if (j.m == 0 && !(c.length != length_policy::fixed && c.exact_fallback)) {
            const unsigned end = segment_end(lc, j.x0);
            for (std::size_t k = i + 1; k < p.jobs.size() && p.jobs[k].y == j.y && p.jobs[k].x0 <= end; ++k)
                EXPECT_EQ(p.jobs[k].m, 0u) << "an interval after an exact pixel in the same segment";
            // The run of exact pixels ending at `end` is at most 2^lowest long.
            unsigned run_begin = j.x0;
            for (std::size_t k = i; k-- > 0 && p.jobs[k].y == j.y && p.jobs[k].m == 0 &&
                                    p.jobs[k].x0 + 1 == run_begin && lc.count(run_begin) == 0;)
                run_begin = p.jobs[k].x0;
            EXPECT_LE(end - run_begin + 1, 1u << lowest);
        }
    }
    // Every covered pixel exactly once.
    std::size_t covered = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            if (r.covered(x, y)) {
                ++covered;
                EXPECT_EQ(hits[r.index(x, y)], 1) << "pixel " << x << ", " << y;
            } else {
                EXPECT_EQ(hits[r.index(x, y)], 0);
            }
        }
    EXPECT_EQ(covered, r.covered_pixels());
    EXPECT_EQ(pixels, covered);
    EXPECT_EQ(p.pixels, covered);
}

// What the geometry side must have computed at a set of pixels: geometry_at and the dot products
// with the N.L > 0 gate and N.H's clamp, as the references compute them (shade.cpp).
inline scene::op_counts geometry_cost(const scene::rasterised& r, const std::set<std::pair<unsigned, unsigned>>& px) {
    scene::op_counts ops;
    for (const auto& [y, x] : px) {
        const scene::pixel_geometry g = scene::geometry_at(r, x, y, &ops);
        const scene::cnum zero(0.0, &ops);
        if (dot(g.n, g.l[0]) > zero) max(dot(g.n, g.h[0]), zero);
    }
    return ops;
}

inline std::set<std::pair<unsigned, unsigned>> sample_pixels(const plan& p, interp::sample_set set) {
    std::set<std::pair<unsigned, unsigned>> s;
    for (const auto& j : p.jobs)
        for (unsigned e : job_points(j, set)) s.insert({j.y, at(j, e)});
    return s;
}

// Squared error (8-bit levels^2, three channels) of interval j (x0, m, len, deg2) placed on line y,
// its samples the geometry at its documented points (recomputed from the rasteriser), its pixels
// golden_interval's, against `exact` (per-pixel shading through the device).
inline double interval_squared_error(const scene_fixture& f, const frame& exact, interval_job j, unsigned y,
                                     const plan_config& c) {
    j.y = y;
    const auto pts = job_points(j, c.set);
    for (std::size_t s = 0; s < 4; ++s)
        j.s[s] = sample_of(scene::geometry_at(f.r, at(j, pts[std::min(s, pts.size() - 1)]), y, nullptr));
    const auto px = golden_interval(j, f.k, patent, c.eval, c.set, c.div);
    double e = 0.0;
    for (unsigned i = 0; i < j.len; ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double d = (double(px[i][ch]) - double(exact.px[f.r.index(j.x0 + i, y)][ch])) / 256.0;
            e += d * d;
        }
    return e;
}
inline interval_job interval_at(unsigned x0, unsigned m, bool deg2) {
    interval_job j;
    j.x0 = x0;
    j.m = m;
    j.len = 1u << m;
    j.deg2 = deg2;
    return j;
}

// Colour (Q8.8 codes) at pixel x of line y.
inline rgb_codes colour(const scene_fixture& f, unsigned x, unsigned y) {
    return golden_sample(patent, f.k, sample_of(scene::geometry_at(f.r, x, y, nullptr)));
}

// Hand-worked polynomial values at the check points (Lagrange weights, pipeline.h's sample sets):
// the cubic through t = 0, 1/4, 1/2, 1 at t = 3/4 is (I0 - 4 I1/4 + 6 I1/2 + I1) / 4, and the
// quadratic through t = 0, 1/2, 1 at t = 1/4 is (3 I0 + 6 I1/2 - I1) / 8.
inline double cubic_at_three_quarters(double i0, double i1, double i2, double i3) { return (i0 - 4 * i1 + 6 * i2 + i3) / 4; }
inline double quad_at_quarter(double i0, double i2, double i3) { return (3 * i0 + 6 * i2 - i3) / 8; }

// The adaptive length's two estimates for a cubic interval of n pixels at x0 (case 1), the largest
// over the channels in 8-bit levels: the cubic's miss at t = 3/4, and the quadratic's miss at the
// cubic's own t = 1/4 sample. pipeline.h: accepted when the first is within the tolerance and the
// second within twice the tolerance.
struct length_estimates {
    double cubic_34 = 0.0, quad_14 = 0.0;
    bool accepted(double tol) const { return cubic_34 <= tol && quad_14 <= 2.0 * tol; }
};
inline length_estimates estimates(const scene_fixture& f, unsigned y, unsigned x0, unsigned n) {
    const auto i0 = colour(f, x0, y), iq = colour(f, x0 + n / 4, y), ih = colour(f, x0 + n / 2, y),
               i1 = colour(f, x0 + n, y), i3 = colour(f, x0 + 3 * n / 4, y);
    length_estimates e;
    for (int ch = 0; ch < 3; ++ch) {
        const double c = cubic_at_three_quarters(double(i0[ch]), double(iq[ch]), double(ih[ch]), double(i1[ch]));
        const double q = quad_at_quarter(double(i0[ch]), double(ih[ch]), double(i1[ch]));
        e.cubic_34 = std::max(e.cubic_34, std::abs(c - double(i3[ch])) / 256.0);
        e.quad_14 = std::max(e.quad_14, std::abs(q - double(iq[ch])) / 256.0);
    }
    return e;
}

// The 64x64 sphere is 38 pixels across, 0.06 world units per pixel: the default depth step (0.02, set
// for the head at 256) fires all over its slopes. 0.5 fires nowhere on it (DepthStepsSplitSegments).
// Its triangles are about a pixel wide, so neighbouring pixels often lie on triangles that share no
// vertex: the sphere's tests plan without surface breaks (the head's tests plan with them).
constexpr double sphere_step = 0.5;

inline plan_config fixed(unsigned m, double depth_step = sphere_step) {
    plan_config c;
    c.length = length_policy::fixed;
    c.m = m;
    c.depth_step = depth_step;
    c.surface_breaks = false;
    return c;
}

// The head's plans keep the defaults (depth step 0.02, surface breaks).
inline plan_config head_fixed(unsigned m) {
    plan_config c;
    c.length = length_policy::fixed;
    c.m = m;
    return c;
}

inline plan_config adaptive_length(unsigned m_min, unsigned m_max, double tol) {
    plan_config c;
    c.length = length_policy::adaptive;
    c.m_min = m_min;
    c.m_max = m_max;
    c.length_tol = tol;
    c.exact_fallback = false;
    c.depth_step = sphere_step;
    c.surface_breaks = false;
    return c;
}


}  // namespace plan_test
