// The geometry side (plan.cpp) and the zone map (zones.cpp): every plan is checked against the
// rasteriser's own spans and discontinuities, the geometry recomputed at the documented pixels, the
// sample points counted independently, and the adaptive policies' estimates by the hand-worked
// polynomial weights at the check points. The zone map against landmarks found on the head's mesh.
// No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "pipeline/pipeline.h"
#include "scene/image.h"

using namespace shading;
using namespace shading::pipeline;

namespace {

const scene::device_config patent{};

struct scene_fixture {
    scene::world w;
    scene::rasterised r;
    frame_constants k;
    scene_fixture(const std::string& name, unsigned size)
        : w(scene::builtin_scene(name, SHADING_SOURCE_DIR, size, size)), r(scene::rasterise(w)),
          k(frame_constants_of(w)) {}
    // rasterised points at the world: the fixture is neither copied nor moved.
    scene_fixture(const scene_fixture&) = delete;
};

const scene_fixture& sphere() {
    static const scene_fixture f("sphere", 64);
    return f;
}
const scene_fixture& head() {
    static const scene_fixture f("head", 128);
    return f;
}

// Sample points of a job in eighths of N (pipeline.h): the documented sets.
std::vector<unsigned> job_points(const interval_job& j, interp::sample_set set) {
    if (j.m == 0) return {0};
    if (j.deg2) return {0, 4, 8};
    return set == interp::sample_set::case1 ? std::vector<unsigned>{0, 2, 4, 8} : std::vector<unsigned>{0, 4, 6, 8};
}
unsigned at(const interval_job& j, unsigned eighths) { return j.x0 + eighths * (1u << j.m) / 8; }

bool fold(const scene::rasterised& r, unsigned y, unsigned x);

// The pixels of line y where the rasteriser's discontinuities fall (between x - 1 and x), and with
// surface breaks the folds too.
std::set<unsigned> cuts(const scene::rasterised& r, unsigned y, double step, bool folds) {
    std::set<unsigned> s;
    for (const auto& d : scene::line_discontinuities(r, y, step)) s.insert(d.x);
    if (folds)
        for (unsigned x = 1; x < r.width; ++x)
            if (r.covered(x - 1, y) && r.covered(x, y) && fold(r, y, x)) s.insert(x);
    return s;
}
std::set<unsigned> cuts(const scene::rasterised& r, unsigned y, const plan_config& c) {
    return cuts(r, y, c.depth_step, c.surface_breaks);
}

// The segment end (last pixel) of the segment holding pixel x on line y, from the discontinuities.
unsigned segment_end(const std::set<unsigned>& c, unsigned x) { return *c.upper_bound(x) - 1; }

// Whether the triangles under two neighbouring pixels share no vertex (a fold of the mesh), from
// the mesh's vertex indices.
bool fold(const scene::rasterised& r, unsigned y, unsigned x) {
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
void expect_valid_plan(const scene::rasterised& r, const plan& p, const plan_config& c) {
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
        // (or, with the adaptive length's exact fallback, in runs of 2^m_min: ExactFallback).
        if (j.m == 0 && !(c.length == length_policy::adaptive && c.exact_fallback)) {
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
scene::op_counts geometry_cost(const scene::rasterised& r, const std::set<std::pair<unsigned, unsigned>>& px) {
    scene::op_counts ops;
    for (const auto& [y, x] : px) {
        const scene::pixel_geometry g = scene::geometry_at(r, x, y, &ops);
        const scene::cnum zero(0.0, &ops);
        if (dot(g.n, g.l[0]) > zero) max(dot(g.n, g.h[0]), zero);
    }
    return ops;
}

std::set<std::pair<unsigned, unsigned>> sample_pixels(const plan& p, interp::sample_set set) {
    std::set<std::pair<unsigned, unsigned>> s;
    for (const auto& j : p.jobs)
        for (unsigned e : job_points(j, set)) s.insert({j.y, at(j, e)});
    return s;
}

// Colour (Q8.8 codes) at pixel x of line y.
rgb_codes colour(const scene_fixture& f, unsigned x, unsigned y) {
    return golden_sample(patent, f.k, sample_of(scene::geometry_at(f.r, x, y, nullptr)));
}

// Hand-worked polynomial values at the check points (Lagrange weights, pipeline.h's sample sets):
// the cubic through t = 0, 1/4, 1/2, 1 at t = 3/4 is (I0 - 4 I1/4 + 6 I1/2 + I1) / 4, and the
// quadratic through t = 0, 1/2, 1 at t = 1/4 is (3 I0 + 6 I1/2 - I1) / 8.
double cubic_at_three_quarters(double i0, double i1, double i2, double i3) { return (i0 - 4 * i1 + 6 * i2 + i3) / 4; }
double quad_at_quarter(double i0, double i2, double i3) { return (3 * i0 + 6 * i2 - i3) / 8; }

// The adaptive length's two estimates for a cubic interval of n pixels at x0 (case 1), the largest
// over the channels in 8-bit levels: the cubic's miss at t = 3/4, and the quadratic's miss at the
// cubic's own t = 1/4 sample. pipeline.h: accepted when the first is within the tolerance and the
// second within twice the tolerance.
struct length_estimates {
    double cubic_34 = 0.0, quad_14 = 0.0;
    bool accepted(double tol) const { return cubic_34 <= tol && quad_14 <= 2.0 * tol; }
};
length_estimates estimates(const scene_fixture& f, unsigned y, unsigned x0, unsigned n) {
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

plan_config fixed(unsigned m, double depth_step = sphere_step) {
    plan_config c;
    c.length = length_policy::fixed;
    c.m = m;
    c.depth_step = depth_step;
    c.surface_breaks = false;
    return c;
}

// The head's plans keep the defaults (depth step 0.02, surface breaks).
plan_config head_fixed(unsigned m) {
    plan_config c;
    c.length = length_policy::fixed;
    c.m = m;
    return c;
}

plan_config adaptive_length(unsigned m_min, unsigned m_max, double tol) {
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

}  // namespace

// ---- Names and configuration ----

TEST(PipelinePlan, PolicyNames) {
    EXPECT_STREQ(length_policy_name(length_policy::fixed), "fixed");
    EXPECT_STREQ(length_policy_name(length_policy::adaptive), "adaptive");
    EXPECT_STREQ(degree_policy_name(degree_policy::cubic), "cubic");
    EXPECT_STREQ(degree_policy_name(degree_policy::quadratic), "quadratic");
    EXPECT_STREQ(degree_policy_name(degree_policy::zones), "zones");
    EXPECT_STREQ(degree_policy_name(degree_policy::adaptive), "adaptive");
}

TEST(PipelinePlan, ValidateRejectsBadConfigs) {
    EXPECT_NO_THROW(validate(plan_config{}));
    auto expect_error = [](plan_config c, const std::string& words) {
        try {
            validate(c);
            ADD_FAILURE() << "accepted: " << words;
        } catch (const scene::scene_error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
        // make_plan validates too, before it reads the frame.
        EXPECT_THROW(make_plan(sphere().r, sphere().k, patent, c), scene::scene_error);
    };
    plan_config c;
    c.m = 0;
    expect_error(c, "m = 0 is outside");
    c.m = 1;
    expect_error(c, "m = 1 is outside");
    c.m = 7;
    expect_error(c, "m = 7 is outside");
    c = plan_config{};
    c.m_max = 7;
    expect_error(c, "outside the units' range");
    c = plan_config{};
    c.m_min = 1;
    expect_error(c, "outside the units' range");
    c = plan_config{};
    c.m_min = 5;
    c.m_max = 3;
    expect_error(c, "m_min = 5 exceeds m_max = 3");
    c = plan_config{};
    c.length_tol = -0.1;
    expect_error(c, "length tolerance");
    c = plan_config{};
    c.degree_tol = -1.0;
    expect_error(c, "degree tolerance");
    c = plan_config{};
    c.depth_step = 0.0;
    expect_error(c, "depth step");
    c = plan_config{};
    c.eval = evaluator::fd;
    // fd with adaptive length is fine (fd_eval_var: every m in m_min..m_max), over the units' range;
    // outside it, it is refused as for Horner.
    c.length = length_policy::adaptive;
    c.m_min = interp::m_min;
    c.m_max = interp::m_max;
    EXPECT_NO_THROW(validate(c));
    c.m_max = interp::m_max + 1;
    expect_error(c, "outside the units' range");
    c.m_max = interp::m_max;
    // fd with a fixed length is fine, quadratic or cubic; every m of the units' range is.
    c.length = length_policy::fixed;
    c.degree = degree_policy::quadratic;
    EXPECT_NO_THROW(validate(c));
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) EXPECT_NO_THROW(validate(fixed(m)));
}

// ---- Fixed length ----

TEST(PipelinePlan, FixedLengthTilesEverySegment) {
    const auto& f = sphere();
    for (unsigned m = interp::m_min; m <= interp::m_max; ++m) {
        SCOPED_TRACE("m = " + std::to_string(m));
        const plan_config c = fixed(m);
        const plan p = make_plan(f.r, f.k, patent, c);
        expect_valid_plan(f.r, p, c);
        // Intervals shorter than 2^m only where the segment's remaining pixels do not hold 2^m + 1.
        for (const auto& j : p.jobs) {
            if (j.m == 0 || j.m == m) continue;
            const unsigned end = segment_end(cuts(f.r, j.y, c), j.x0);
            EXPECT_LT(end - j.x0, 1u << (j.m + 1)) << "a shorter interval where a longer one fits, line " << j.y;
        }
        if (m == 4) {
            std::size_t full = 0;
            for (const auto& j : p.jobs) full += j.m == m;
            EXPECT_GT(full * 16, p.pixels / 2) << "most pixels in full intervals of 16";
        }
    }
}

// With a fixed length the forward-difference evaluator takes one m per frame: every interval is 2^m,
// tails are exact (the SystemC pipeline's fd channel is still fd_eval<M>).
TEST(PipelinePlan, ForwardDifferencesTakeOneLengthWhenFixed) {
    const auto& f = sphere();
    plan_config c = fixed(4);
    c.eval = evaluator::fd;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::size_t intervals = 0, exact = 0;
    for (const auto& j : p.jobs) {
        EXPECT_TRUE(j.m == 0 || j.m == 4) << "line " << j.y << ", x " << j.x0 << ", m " << j.m;
        (j.m ? intervals : exact) += 1;
    }
    EXPECT_GT(intervals, 0u);
    // The Horner unit takes the shorter tails instead: fewer exact pixels.
    c.eval = evaluator::horner;
    std::size_t exact_horner = 0;
    for (const auto& j : make_plan(f.r, f.k, patent, c).jobs) exact_horner += j.m == 0;
    EXPECT_LT(exact_horner, exact);
}

// With adaptive length the forward-difference evaluator (fd_eval_var) takes every m in m_min..m_max
// as the Horner unit does: the same plan, job for job, with intervals of several lengths.
TEST(PipelinePlan, ForwardDifferencesTakeEveryLengthWhenAdaptive) {
    const auto& f = sphere();
    plan_config c = adaptive_length(2, 5, 2.0);
    c.eval = evaluator::fd;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    c.eval = evaluator::horner;
    const plan q = make_plan(f.r, f.k, patent, c);
    ASSERT_EQ(p.jobs.size(), q.jobs.size());
    std::set<unsigned> lengths;
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        EXPECT_EQ(p.jobs[i].y, q.jobs[i].y);
        EXPECT_EQ(p.jobs[i].x0, q.jobs[i].x0);
        EXPECT_EQ(p.jobs[i].m, q.jobs[i].m);
        EXPECT_EQ(p.jobs[i].len, q.jobs[i].len);
        EXPECT_EQ(p.jobs[i].deg2, q.jobs[i].deg2);
        if (p.jobs[i].m) lengths.insert(p.jobs[i].m);
    }
    EXPECT_GE(lengths.size(), 3u) << "intervals of several lengths";
}

// A segment of 22 pixels xa .. xa + 21 with m = 4: an interval of 16 at xa (samples at xa + 0, 4, 8,
// 16), 5 pixels left after it (room for 4 + 1): an interval of 4 at xa + 16 (samples at + 16, 17, 18,
// 20), then xa + 20 (the t = 1 sample) and xa + 21 hold no interval: two exact pixels.
TEST(PipelinePlan, HandWorkedSegment) {
    const auto& f = sphere();
    const plan_config c = fixed(4);
    const plan p = make_plan(f.r, f.k, patent, c);
    bool found = false;
    for (unsigned y = 0; y < f.r.height && !found; ++y) {
        const auto spans = scene::line_spans(f.r, y);
        if (spans.size() != 1 || spans[0].x_end - spans[0].x_begin != 22) continue;
        if (cuts(f.r, y, c).size() != 2) continue;  // coverage begin and end only
        found = true;
        const unsigned xa = spans[0].x_begin;
        std::vector<interval_job> line;
        for (const auto& j : p.jobs)
            if (j.y == y) line.push_back(j);
        ASSERT_EQ(line.size(), 4u);
        const unsigned x0[] = {xa, xa + 16, xa + 20, xa + 21}, m[] = {4, 2, 0, 0}, len[] = {16, 4, 1, 1};
        for (unsigned i = 0; i < 4; ++i) {
            EXPECT_EQ(line[i].x0, x0[i]);
            EXPECT_EQ(line[i].m, m[i]);
            EXPECT_EQ(line[i].len, len[i]);
        }
        auto geo = [&](unsigned x) { return sample_of(scene::geometry_at(f.r, x, y, nullptr)); };
        EXPECT_EQ(line[0].s[1], geo(xa + 4));
        EXPECT_EQ(line[0].s[3], geo(xa + 16));
        EXPECT_EQ(line[1].s[0], geo(xa + 16));
        EXPECT_EQ(line[1].s[1], geo(xa + 17));
        EXPECT_EQ(line[1].s[3], geo(xa + 20));
        EXPECT_EQ(line[2].s[0], geo(xa + 20));
        EXPECT_EQ(line[3].s[3], geo(xa + 21));
    }
    EXPECT_TRUE(found) << "no 22-pixel line on the 64x64 sphere";
}

// Geometry is computed once per distinct sample pixel, and counted as geometry_at plus the dots.
TEST(PipelinePlan, GeometryCountedOncePerDistinctPixel) {
    const auto& f = sphere();
    for (auto set : {interp::sample_set::case1, interp::sample_set::case2})
        for (auto deg : {degree_policy::cubic, degree_policy::quadratic}) {
            plan_config c = fixed(3);
            c.set = set;
            c.degree = deg;
            const plan p = make_plan(f.r, f.k, patent, c);
            expect_valid_plan(f.r, p, c);
            const auto px = sample_pixels(p, set);
            EXPECT_EQ(p.geometry_points, px.size());
            EXPECT_EQ(p.geometry, geometry_cost(f.r, px));
            EXPECT_EQ(p.decision, scene::op_counts{});
            EXPECT_EQ(p.check_samples, 0u);
            // Shared t = 1 samples: fewer geometry points than 4 (or 3) per interval.
            std::size_t per_job = 0;
            for (const auto& j : p.jobs) per_job += job_points(j, set).size();
            EXPECT_LT(p.geometry_points, per_job);
        }
}

TEST(PipelinePlan, QuadraticSkipsTheQuarterPoint) {
    const auto& f = sphere();
    plan_config c = fixed(4);
    c.degree = degree_policy::quadratic;
    const plan q = make_plan(f.r, f.k, patent, c);
    c.degree = degree_policy::cubic;
    const plan k = make_plan(f.r, f.k, patent, c);
    for (const auto& j : q.jobs) {
        EXPECT_EQ(j.deg2, j.m != 0);
        if (j.m) {
            EXPECT_EQ(j.s[3], j.s[2]);
        }
    }
    // The cubic needs one more geometry point per interval than the quadratic.
    std::size_t intervals = 0;
    for (const auto& j : k.jobs) intervals += j.m != 0;
    EXPECT_EQ(k.geometry_points, q.geometry_points + intervals);
    EXPECT_GT(k.geometry.long_ops(), q.geometry.long_ops());
}

// Depth steps split segments: a threshold small enough to fire on the sphere's slope makes more,
// shorter segments, and the plan still respects every one of them.
TEST(PipelinePlan, DepthStepsSplitSegments) {
    const auto& f = sphere();
    const plan_config c = fixed(4, 0.05);
    const plan fine = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, fine, c);
    std::size_t steps = 0;
    for (unsigned y = 0; y < f.r.height; ++y)
        for (const auto& d : scene::line_discontinuities(f.r, y, c.depth_step)) steps += (d.kinds & scene::depth_step) != 0;
    EXPECT_GT(steps, 0u) << "the threshold should fire on the sphere's rim";
    const plan coarse = make_plan(f.r, f.k, patent, fixed(4));
    EXPECT_GT(fine.jobs.size(), coarse.jobs.size());
}

// ---- Adaptive length ----

TEST(PipelinePlan, AdaptiveLengthHugeToleranceTakesTheLongest) {
    const auto& f = sphere();
    const plan_config c = adaptive_length(2, 5, 1e9);
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    // Same tiling as fixed m = 5: the longest that fits, every time.
    plan_config f5 = fixed(5);
    const plan q = make_plan(f.r, f.k, patent, f5);
    ASSERT_EQ(p.jobs.size(), q.jobs.size());
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        EXPECT_EQ(p.jobs[i].x0, q.jobs[i].x0);
        EXPECT_EQ(p.jobs[i].m, q.jobs[i].m);
    }
    // Each interval longer than m_min looked at one check point (t = 3/4) before being accepted.
    EXPECT_GT(p.check_samples, 0u);
    EXPECT_GT(p.geometry_points, q.geometry_points);
    EXPECT_GT(p.decision.add, 0u);
    EXPECT_EQ(p.decision.long_ops(), 0u) << "the estimate's weights are shifts and adds";
}

// Tolerance 0: an interval longer than m_min only where its cubic hits the exact colour at t = 3/4 and
// the quadratic hits the t = 1/4 sample in every channel (flat or polynomial shading), checked by the
// hand-worked weights.
TEST(PipelinePlan, AdaptiveLengthZeroToleranceTakesTheShortest) {
    const auto& f = sphere();
    const plan_config c = adaptive_length(2, 5, 0.0);
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::size_t shortest = 0, longer = 0;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        if (j.m == c.m_min) {
            ++shortest;
            continue;
        }
        ++longer;
        EXPECT_TRUE(estimates(f, j.y, j.x0, 1u << j.m).accepted(0.0)) << "line " << j.y << ", x " << j.x0 << ", m " << j.m;
    }
    EXPECT_GT(shortest, 4 * longer) << "tolerance 0 should leave almost every interval at m_min";
}

// In between: each interval is the longest the policy may try whose hand-worked estimate is within
// the tolerance. It may try up to m_max at a segment's start, then at most one level above the previous
// interval, and only lengths whose t = 1 pixel lies in the segment; every longer candidate it could try
// misses its check.
TEST(PipelinePlan, AdaptiveLengthAcceptsWithinTolerance) {
    const auto& f = sphere();
    const plan_config c = adaptive_length(2, 6, 1.0);
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::map<unsigned, std::size_t> by_m;
    std::size_t grew = 0;
    unsigned line = ~0u, seg_end = 0, allowed = c.m_max;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;  // tails only (no fallback here)
        const unsigned end = segment_end(cuts(f.r, j.y, c), j.x0);
        if (j.y != line || end != seg_end) allowed = c.m_max;  // a new segment
        line = j.y;
        seg_end = end;
        ++by_m[j.m];
        EXPECT_LE(j.m, allowed);
        if (j.m > c.m_min) {
            EXPECT_TRUE(estimates(f, j.y, j.x0, 1u << j.m).accepted(c.length_tol)) << "line " << j.y << ", x " << j.x0;
        }
        for (unsigned m = j.m + 1; m <= allowed && (1u << m) <= end - j.x0; ++m)
            EXPECT_FALSE(estimates(f, j.y, j.x0, 1u << m).accepted(c.length_tol)) << "a longer interval passes, line " << j.y;
        grew += j.m == allowed && allowed < c.m_max;
        allowed = std::min(j.m + 1, c.m_max);
    }
    EXPECT_GT(by_m[2] + by_m[3], 0u);
    EXPECT_GT(by_m[4] + by_m[5] + by_m[6], 0u) << "a mix of lengths at tolerance 1 level";
    EXPECT_GT(grew, 0u) << "intervals limited by the growth of one level";
}

// With the exact fallback, where even an interval of 2^m_min misses its checks, its pixels are exact:
// at tolerance 0 every group of exact pixels that is not a segment's tail is one whose interval of 4
// misses an exact colour (at t = 3/4 by the cubic, or at t = 1/4 by the quadratic; hand-worked
// weights), and every interval hits both.
TEST(PipelinePlan, ExactFallback) {
    const auto& f = sphere();
    plan_config c = adaptive_length(2, 5, 0.0);
    c.exact_fallback = true;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    auto cubic_hits = [&f](unsigned y, unsigned x0, unsigned n) { return estimates(f, y, x0, n).accepted(0.0); };
    std::size_t groups = 0, intervals = 0;
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        const interval_job& j = p.jobs[i];
        if (j.m != 0) {
            ++intervals;
            EXPECT_TRUE(cubic_hits(j.y, j.x0, 1u << j.m)) << "line " << j.y << ", x " << j.x0;
            continue;
        }
        const unsigned end = segment_end(cuts(f.r, j.y, c), j.x0);
        if (end - j.x0 < 4) continue;  // the tail
        ++groups;
        EXPECT_FALSE(cubic_hits(j.y, j.x0, 4)) << "line " << j.y << ", x " << j.x0;
        for (unsigned k = 1; k < 4; ++k) {
            ASSERT_LT(i + k, p.jobs.size());
            EXPECT_EQ(p.jobs[i + k].m, 0u);
            EXPECT_EQ(p.jobs[i + k].x0, j.x0 + k);
        }
        i += 3;
    }
    EXPECT_GT(groups, 0u);
    // A huge tolerance never falls back: the same tiling as fixed m = 5.
    c.length_tol = 1e9;
    const plan q = make_plan(f.r, f.k, patent, c);
    const plan r5 = make_plan(f.r, f.k, patent, fixed(5));
    ASSERT_EQ(q.jobs.size(), r5.jobs.size());
    for (std::size_t i = 0; i < q.jobs.size(); ++i) EXPECT_EQ(q.jobs[i].m, r5.jobs[i].m);
}

// Folds: on the head, neighbouring pixels whose triangles share no vertex (eyelids, ears, nostrils)
// end segments; without surface breaks intervals straddle some of them, and the interpolation's
// error against per-pixel shading through the same device is larger.
TEST(PipelinePlan, SurfaceBreaksSplitFolds) {
    const auto& f = head();
    plan_config with = head_fixed(3);
    plan_config without = with;
    without.surface_breaks = false;
    const plan a = make_plan(f.r, f.k, patent, with);
    const plan b = make_plan(f.r, f.k, patent, without);
    expect_valid_plan(f.r, a, with);
    expect_valid_plan(f.r, b, without);
    std::size_t straddling = 0;
    for (const auto& j : b.jobs)
        for (unsigned x = j.x0 + 1; j.m && x <= j.x0 + (1u << j.m); ++x) straddling += fold(f.r, j.y, x);
    EXPECT_GT(straddling, 0u);
    EXPECT_GT(a.decision.cmp, 0u) << "the vertex comparisons are counted";
    const auto ref = to_image(per_pixel_frame(f.r, f.k, patent));
    const double err_with = compare(to_image(golden_frame(a, f.k, patent, with)), ref).nmse;
    const double err_without = compare(to_image(golden_frame(b, f.k, patent, without)), ref).nmse;
    EXPECT_LT(err_with, err_without);
}

// ---- Degree policies ----

TEST(PipelinePlan, AdaptiveDegreeExtremes) {
    const auto& f = sphere();
    plan_config c = fixed(4);
    c.degree = degree_policy::adaptive;
    c.degree_tol = 1e9;
    const plan all = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, all, c);
    for (const auto& j : all.jobs) EXPECT_EQ(j.deg2, j.m != 0);
    // The policy computes the quarter point's geometry anyway, so the cubic's points are all there.
    c.degree = degree_policy::cubic;
    const plan cubic = make_plan(f.r, f.k, patent, c);
    EXPECT_EQ(all.geometry_points, cubic.geometry_points);
    EXPECT_EQ(all.geometry, cubic.geometry);
    EXPECT_GT(all.check_samples, 0u) << "the t = 1/4 colours that no quadratic job carries";

    c.degree = degree_policy::adaptive;
    c.degree_tol = 0.0;
    const plan none = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, none, c);
    std::size_t quad = 0, cub = 0;
    for (const auto& j : none.jobs) {
        if (j.m == 0) continue;
        if (!j.deg2) {
            ++cub;
            continue;
        }
        ++quad;
        // Chosen only where the quadratic hits the exact colour at t = 1/4 (hand-worked weights).
        const unsigned n = 1u << j.m;
        const auto i0 = colour(f, j.x0, j.y), iq = colour(f, j.x0 + n / 4, j.y), i2 = colour(f, j.x0 + n / 2, j.y),
                   i3 = colour(f, j.x0 + n, j.y);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_EQ(quad_at_quarter(double(i0[ch]), double(i2[ch]), double(i3[ch])), double(iq[ch]));
    }
    EXPECT_GT(cub, 4 * quad) << "tolerance 0 should leave almost every interval cubic";
    EXPECT_EQ(none.check_samples, quad);
}

// Case 2 checks the other side: degree (and the length's first estimate) at t = 3/4, length at t = 1/4.
TEST(PipelinePlan, Case2SamplePoints) {
    const auto& f = sphere();
    plan_config c = adaptive_length(2, 5, 0.5);
    c.set = interp::sample_set::case2;
    c.degree = degree_policy::adaptive;
    c.degree_tol = 0.25;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    // Hand-worked weights: the cubic through t = 0, 1/2, 3/4, 1 at t = 1/4 is (I0 + 6 I1/2 - 4 I3/4 + I1)/4;
    // the quadratic through 0, 1/2, 1 at 3/4 is (-I0 + 6 I1/2 + 3 I1)/8 and at 1/4 (3 I0 + 6 I1/2 - I1)/8.
    auto worst = [&f](const interval_job& j, auto value_at) {
        const unsigned n = 1u << j.m;
        double w = 0.0;
        const auto i0 = colour(f, j.x0, j.y), ih = colour(f, j.x0 + n / 2, j.y), i3 = colour(f, j.x0 + 3 * n / 4, j.y),
                   i1 = colour(f, j.x0 + n, j.y), iq = colour(f, j.x0 + n / 4, j.y);
        for (int ch = 0; ch < 3; ++ch) {
            const auto [poly, exact] = value_at(double(i0[ch]), double(ih[ch]), double(i3[ch]), double(i1[ch]),
                                                double(iq[ch]), double(i3[ch]));
            w = std::max(w, std::abs(poly - exact));
        }
        return w / 256.0;
    };
    auto quad_three_quarters = [](double a, double h, double, double b, double, double e3) {
        return std::pair<double, double>{(-a + 6 * h + 3 * b) / 8, e3};
    };
    auto quad_quarter = [](double a, double h, double, double b, double eq, double) {
        return std::pair<double, double>{(3 * a + 6 * h - b) / 8, eq};
    };
    auto cubic_quarter = [](double a, double h, double t3, double b, double eq, double) {
        return std::pair<double, double>{(a + 6 * h - 4 * t3 + b) / 4, eq};
    };
    std::size_t quad = 0, cubic = 0;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        SCOPED_TRACE("line " + std::to_string(j.y) + ", x " + std::to_string(j.x0) + ", m " + std::to_string(j.m));
        if (j.deg2) {
            ++quad;
            EXPECT_LE(worst(j, quad_three_quarters), c.degree_tol);
            if (j.m > c.m_min) {
                EXPECT_LE(worst(j, quad_quarter), c.length_tol);
            }
        } else {
            ++cubic;
            EXPECT_GT(worst(j, quad_three_quarters), c.degree_tol);
            if (j.m > c.m_min) {
                EXPECT_LE(worst(j, cubic_quarter), c.length_tol);
                EXPECT_LE(worst(j, quad_three_quarters), 2.0 * c.length_tol);
            }
        }
    }
    EXPECT_GT(quad, 0u);
    EXPECT_GT(cubic, 0u);
}

// ---- Zones ----

TEST(PipelineZones, Names) {
    const char* names[] = {"other", "brows", "forehead", "eyes", "cheeks", "nose", "mouth", "chin"};
    for (unsigned z = 0; z < zone_count; ++z) EXPECT_STREQ(zone_name(z), names[z]);
    EXPECT_STREQ(zone_name(zone_count), "?");
    // Seed 004: zones 2, 4 and 7 quadratic; with our numbering forehead, cheeks and chin.
    for (unsigned z = 0; z < zone_count; ++z) EXPECT_EQ(zone_is_quadratic(z), z == 2 || z == 4 || z == 7) << z;
}

// Landmarks found on the head's mesh, independently of the zone boxes: the nose tip (the vertex
// farthest along +z), the top of the skull, the lowest vertex (the shoulders), and along the face's
// centre line the most forward vertex at a given height (forehead, chin) and beside the nose.
TEST(PipelineZones, LandmarksOfTheHead) {
    const auto& f = head();
    const scene::mesh& m = f.w.objects[0].geometry;
    auto zone_at = [&f](const glm::dvec3& p) {
        scene::pixel_geometry g;
        g.object = 0;
        g.p = {scene::cnum(p.x, nullptr), scene::cnum(p.y, nullptr), scene::cnum(p.z, nullptr)};
        return head_zone(f.r, g);
    };
    glm::dvec3 tip = m.positions[0], top = m.positions[0], low = m.positions[0];
    for (const auto& p : m.positions) {
        if (p.z > tip.z) tip = p;
        if (p.y > top.y) top = p;
        if (p.y < low.y) low = p;
    }
    EXPECT_STREQ(zone_name(zone_at(tip)), "nose");
    EXPECT_STREQ(zone_name(zone_at(top)), "other");
    EXPECT_STREQ(zone_name(zone_at(low)), "other");
    // The most forward vertex near the centre line (|x - tip.x| < 5 mm) within a band of heights.
    auto front = [&m, &tip](double x_off, double y_lo, double y_hi) {
        glm::dvec3 best(0.0, 0.0, -1e9);
        for (const auto& p : m.positions)
            if (std::abs(p.x - tip.x - x_off) < 0.005 && p.y >= y_lo && p.y < y_hi && p.z > best.z) best = p;
        return best;
    };
    const double h = top.y - tip.y;  // about 0.15 world units
    // Forehead: the centre line halfway between the brows' ridge and the top, well above the eyes.
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y + 0.6 * h, tip.y + 0.7 * h))), "forehead");
    // Chin: the most forward point of the centre line's lowest tenth of the face (below the lips).
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y - 0.6 * h, tip.y - 0.45 * h))), "chin");
    // Beside the nose, a third of h out, level with the tip: the cheek.
    EXPECT_STREQ(zone_name(zone_at(front(0.3 * h, tip.y - 0.05 * h, tip.y + 0.05 * h))), "cheeks");
    // The eye socket: the deepest point of the line through the eye (x = 0.033), between the brow
    // ridge and the cheek.
    glm::dvec3 socket(0.0, 0.0, 1e9);
    for (const auto& p : m.positions)
        if (std::abs(p.x - tip.x - 0.033) < 0.004 && p.y > tip.y + 0.05 * h && p.y < tip.y + 0.35 * h && p.z < socket.z &&
            p.z > tip.z - 0.3 * h)
            socket = p;
    EXPECT_STREQ(zone_name(zone_at(socket)), "eyes");
    // The brow ridge: the most forward point of that line above the socket.
    EXPECT_STREQ(zone_name(zone_at(front(0.033, socket.y + 0.12 * h, socket.y + 0.35 * h))), "brows");
    // The lips: the most forward point of the centre line below the nose, above the chin.
    EXPECT_STREQ(zone_name(zone_at(front(0.0, tip.y - 0.3 * h, tip.y - 0.12 * h))), "mouth");
}

// Without a position (an orthographic camera and a directional light: geometry_at leaves g.p at 0)
// there is no zone, rather than the zone of the origin.
TEST(PipelineZones, NoPositionNoZone) {
    scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 48, 48);
    w.cam.fov_y_deg = 0.0;
    w.cam.ortho_height = 0.6;
    const scene::rasterised r = scene::rasterise(w);
    std::size_t covered = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x)
            if (r.covered(x, y)) {
                ++covered;
                EXPECT_EQ(head_zone(r, scene::geometry_at(r, x, y, nullptr)), 0u);
            }
    EXPECT_GT(covered, 0u);
    // The same head in perspective has face zones.
    const auto& f = head();
    std::size_t face = 0;
    for (unsigned y = 0; y < f.r.height; ++y)
        for (unsigned x = 0; x < f.r.width; ++x)
            if (f.r.covered(x, y)) face += head_zone(f.r, scene::geometry_at(f.r, x, y, nullptr)) != 0;
    EXPECT_GT(face, 0u);
}

// Every zone is on the rendered head, the face's zones in the face's pixels; writes the zone map over
// the shaded head (build/out/pipeline/zones_head.png) to look at.
TEST(PipelineZones, ZoneMapOfTheHead) {
    const auto& f = head();
    const scene::shaded_image img = scene::render_phong(f.r);
    scene::rgb_image out = scene::to_rgb8(img);
    // other grey, brows red, forehead green, eyes blue, cheeks yellow, nose magenta, mouth cyan, chin orange.
    const uint8_t palette[zone_count][3] = {{128, 128, 128}, {255, 0, 0},   {0, 200, 0},   {0, 0, 255},
                                            {255, 255, 0},   {255, 0, 255}, {0, 255, 255}, {255, 128, 0}};
    std::vector<std::size_t> count(zone_count, 0);
    for (unsigned y = 0; y < f.r.height; ++y)
        for (unsigned x = 0; x < f.r.width; ++x) {
            if (!f.r.covered(x, y)) continue;
            const unsigned z = head_zone(f.r, scene::geometry_at(f.r, x, y, nullptr));
            ASSERT_LT(z, zone_count);
            ++count[z];
            uint8_t* p = out.at(x, y);
            for (int ch = 0; ch < 3; ++ch) p[ch] = static_cast<uint8_t>((p[ch] + palette[z][ch]) / 2);
        }
    const std::size_t face = f.r.covered_pixels();
    for (unsigned z = 1; z < zone_count; ++z) EXPECT_GT(count[z] * 200, face) << zone_name(z) << ": under 0.5 %";
    // The face is a part of the bust, not most of it.
    EXPECT_GT(count[0] * 3, face);
    std::filesystem::create_directories("out/pipeline");
    scene::save_png(out, "out/pipeline/zones_head.png");
}

TEST(PipelinePlan, ZonesPolicyIsTheZoneMap) {
    const auto& f = head();
    plan_config c = head_fixed(3);
    c.degree = degree_policy::zones;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::size_t quad = 0, cubic = 0;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        const bool q = zone_is_quadratic(head_zone(f.r, scene::geometry_at(f.r, j.x0, j.y, nullptr)));
        EXPECT_EQ(j.deg2, q) << "line " << j.y << ", x " << j.x0;
        (q ? quad : cubic) += 1;
    }
    EXPECT_GT(quad, 0u);
    EXPECT_GT(cubic, 0u);
    // Quadratic intervals do not compute the quarter point: the geometry is exactly the jobs' points.
    EXPECT_EQ(p.geometry_points, sample_pixels(p, c.set).size());
    EXPECT_EQ(p.geometry, geometry_cost(f.r, sample_pixels(p, c.set)));
    EXPECT_EQ(p.check_samples, 0u);
}

TEST(PipelinePlan, HeadWithEveryPolicy) {
    const auto& f = head();
    for (auto len : {length_policy::fixed, length_policy::adaptive})
        for (auto deg : {degree_policy::cubic, degree_policy::quadratic, degree_policy::zones, degree_policy::adaptive}) {
            SCOPED_TRACE(std::string(length_policy_name(len)) + " / " + degree_policy_name(deg));
            plan_config c;
            c.length = len;
            c.degree = deg;
            const plan p = make_plan(f.r, f.k, patent, c);
            expect_valid_plan(f.r, p, c);
        }
}
