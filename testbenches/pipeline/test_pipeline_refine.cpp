// What refines an adaptive plan beyond its own checks (plan.cpp): splitting an accepted cubic at its
// check point, and the line above's levels limiting this line's intervals. Checked as in
// test_pipeline_plan.cpp (one executable), against the rasteriser's geometry and the plan's own jobs.
// Fixtures in plan_test_fixtures.h. No simulation here: these tests may share a process.
#include "plan_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_refine {

using namespace shading;
using namespace shading::pipeline;
using namespace plan_test;

// ---- Splitting at the check point ----

// split_at_check changes no decision: the plan with it is the plan without it, each accepted cubic
// above 2^m_min replaced by two quadratics of half its length whose samples are the geometry at its
// t = 0, 1/4, 1/2 and 1/2, 3/4, 1 (recomputed here from the rasteriser), in either sample set and under
// either checking length policy; the geometry side computes the same points. Fixed lengths ignore it.
TEST(PipelinePlan, SplitAtCheckKeepsTheDecisions) {
    const auto& f = head();
    for (const auto length : {length_policy::adaptive, length_policy::geometry, length_policy::fixed})
        for (const auto set : {interp::sample_set::case1, interp::sample_set::case2}) {
            SCOPED_TRACE(std::string(length_policy_name(length)) + (set == interp::sample_set::case1 ? " case1" : " case2"));
            plan_config c = head_fixed(4);
            c.length = length;
            c.set = set;
            c.length_tol = 1.0;
            const plan whole = make_plan(f.r, f.k, patent, c);
            c.split_at_check = true;
            const plan split = make_plan(f.r, f.k, patent, c);
            expect_valid_plan(f.r, split, c);
            EXPECT_EQ(split.geometry_points, whole.geometry_points);
            EXPECT_EQ(split.geometry_stepped.long_ops(), whole.geometry_stepped.long_ops());
            std::size_t k = 0, halved = 0;
            for (const interval_job& j : whole.jobs) {
                ASSERT_LT(k, split.jobs.size());
                const bool splits = length != length_policy::fixed && !j.deg2 && j.m > c.m_min;
                if (!splits) {
                    const interval_job& s = split.jobs[k++];
                    EXPECT_EQ(s.y, j.y);
                    EXPECT_EQ(s.x0, j.x0);
                    EXPECT_EQ(s.m, j.m);
                    EXPECT_EQ(s.deg2, j.deg2);
                    EXPECT_EQ(s.s, j.s);
                    continue;
                }
                ++halved;
                ASSERT_LT(k + 1, split.jobs.size());
                const unsigned n = 1u << j.m;
                for (unsigned h = 0; h < 2; ++h) {
                    const interval_job& s = split.jobs[k++];
                    EXPECT_EQ(s.y, j.y);
                    EXPECT_EQ(s.x0, j.x0 + h * n / 2);
                    EXPECT_EQ(s.m, j.m - 1);
                    EXPECT_TRUE(s.deg2);
                    for (unsigned i = 0; i < 3; ++i)
                        EXPECT_EQ(s.s[i], sample_of(scene::geometry_at(f.r, s.x0 + i * n / 4, s.y, nullptr)));
                }
            }
            EXPECT_EQ(k, split.jobs.size());
            if (length == length_policy::fixed) {
                EXPECT_EQ(halved, 0u);
            } else {
                EXPECT_GT(halved, 0u);
            }
        }
}

// Without the exact fallback the shortest interval is taken unchecked, so it has no check point to
// reuse: with m_min = 3 those cubics stay whole, and the split still computes no extra geometry.
TEST(PipelinePlan, SplitAtCheckLeavesUncheckedIntervalsWhole) {
    const auto& f = head();
    plan_config c = head_fixed(4);
    c.length = length_policy::adaptive;
    c.m_min = 3;
    c.exact_fallback = false;
    c.length_tol = 0.5;
    const plan whole = make_plan(f.r, f.k, patent, c);
    c.split_at_check = true;
    const plan split = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, split, c);
    EXPECT_EQ(split.geometry_points, whole.geometry_points);
    std::size_t unchecked = 0, halves = 0;
    for (const interval_job& j : whole.jobs) unchecked += j.m == 3 && !j.deg2;
    for (const interval_job& j : split.jobs) halves += j.m == 3 && j.deg2;
    EXPECT_GT(unchecked, 0u);
    EXPECT_GT(halves, 0u) << "longer cubics are still split";
    std::size_t kept = 0;
    for (const interval_job& j : split.jobs) kept += j.m == 3 && !j.deg2;
    EXPECT_EQ(kept, unchecked);
}

// The point of the split: the halves' quadratics pass through the check point as well, so the frame
// is closer to per-pixel shading than with the whole cubics (head at 128, adaptive length).
TEST(PipelinePlan, SplitAtCheckLowersTheError) {
    const auto& f = head();
    plan_config c = head_fixed(4);
    c.length = length_policy::adaptive;
    c.length_tol = 1.0;
    const scene::device_config squared{scene::specular_device::squared};
    const scene::shaded_image ref = to_image(per_pixel_frame(f.r, f.k, squared));
    const double whole = compare(to_image(golden_frame(make_plan(f.r, f.k, squared, c), f.k, squared, c)), ref).nmse;
    c.split_at_check = true;
    const double split = compare(to_image(golden_frame(make_plan(f.r, f.k, squared, c), f.k, squared, c)), ref).nmse;
    EXPECT_GT(whole, 0.0);
    EXPECT_LT(split, 0.9 * whole) << "whole cubics " << whole << ", split " << split;
}

// ---- The line above ----

// The line-above limit (above_slack): each interval above 2^m_min is at most `slack` levels longer
// than the shortest interval the line above has over its pixels (recomputed here from the plan's own jobs of
// that line), and within that limit and the growth of one level it is still the longest the checks
// accept. Slack 1 on the sphere at tolerance 1 limits some intervals; a slack of m_max none.
TEST(PipelinePlan, AboveSlackLimitsByTheLineAbove) {
    const auto& f = sphere();
    plan_config c = adaptive_length(2, 6, 1.0);
    c.above_slack = 1;
    const plan p = make_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    std::map<unsigned, std::vector<int>> level;  // line -> level at each pixel (-1: no interval)
    for (const auto& j : p.jobs) {
        auto& l = level[j.y];
        if (l.empty()) l.assign(f.r.width, -1);
        for (unsigned i = 0; i < j.len; ++i) l[j.x0 + i] = int(j.m);
    }
    auto limit = [&](unsigned y, unsigned x0, unsigned m) {
        if (y == 0 || !level.count(y - 1)) return true;
        for (unsigned x = x0; x < x0 + (1u << m); ++x) {
            const int a = level[y - 1][x];
            if (a >= 0 && a + c.above_slack < int(m)) return false;
        }
        return true;
    };
    std::size_t limited = 0;
    unsigned line = ~0u, seg_end = 0, allowed = c.m_max;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        const unsigned end = segment_end(cuts(f.r, j.y, c), j.x0);
        if (j.y != line || end != seg_end) allowed = c.m_max;
        line = j.y;
        seg_end = end;
        if (j.m > c.m_min) {
            EXPECT_TRUE(limit(j.y, j.x0, j.m)) << "line " << j.y << ", x " << j.x0 << ", m " << j.m;
        }
        for (unsigned m = j.m + 1; m <= allowed && (1u << m) <= end - j.x0; ++m) {
            if (!limit(j.y, j.x0, m)) {
                ++limited;
                break;  // longer ones reach the same pixels above
            }
            EXPECT_FALSE(estimates(f, j.y, j.x0, 1u << m).accepted(c.length_tol)) << "a longer interval passes, line " << j.y;
        }
        allowed = std::min(j.m + 1, c.m_max);
    }
    EXPECT_GT(limited, 0u) << "intervals limited by the line above";
    EXPECT_GT(p.jobs.size(), make_plan(f.r, f.k, patent, adaptive_length(2, 6, 1.0)).jobs.size());
    // A slack of m_max limits nothing: the plan without the limit.
    c.above_slack = int(c.m_max);
    const plan q = make_plan(f.r, f.k, patent, c);
    const plan free = make_plan(f.r, f.k, patent, adaptive_length(2, 6, 1.0));
    ASSERT_EQ(q.jobs.size(), free.jobs.size());
    for (std::size_t i = 0; i < q.jobs.size(); ++i) {
        EXPECT_EQ(q.jobs[i].x0, free.jobs[i].x0);
        EXPECT_EQ(q.jobs[i].m, free.jobs[i].m);
    }
}

// ---- The lit guard ----

namespace {
// The head at 256 lit from the side (azimuth -40, elevation 25, n = 5): much of it unlit, with lit
// patches of a few pixels among the folds of the ear and the eye.
const scene_fixture& head_side_lit() {
    static const scene_fixture f([] {
        scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 256, 256);
        const double deg = std::acos(-1.0) / 180.0, a = -40.0 * deg, e = 25.0 * deg;
        w.lights.at(0).vector = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
        for (auto& o : w.objects) o.mat.n = 5;
        return w;
    }());
    return f;
}

// Jobs above 2^m_min whose samples and check point are all unlit (recomputed from the rasteriser's
// geometry) but which cover a lit pixel (N.L > 0 there, from the same geometry).
std::size_t lit_pixels_jumped(const scene_fixture& f, const plan& p, const plan_config& c) {
    std::size_t jumped = 0;
    auto lit = [&](unsigned x, unsigned y) { return sample_of(scene::geometry_at(f.r, x, y, nullptr)).cos_nl > 0; };
    for (const interval_job& j : p.jobs) {
        if (j.m <= c.m_min) continue;
        std::vector<unsigned> pts = job_points(j, c.set);
        pts.push_back(c.set == interp::sample_set::case1 ? 6 : 2);  // the length check
        if (std::any_of(pts.begin(), pts.end(), [&](unsigned e) { return lit(at(j, e), j.y); })) continue;
        for (unsigned x = j.x0; x < j.x0 + j.len; ++x)
            if (lit(x, j.y)) {
                ++jumped;
                break;
            }
    }
    return jumped;
}
}  // namespace

// With the lit guard no interval above 2^m_min whose points are all unlit covers a lit pixel, under
// either checking length policy and in either sample set; without it, on this scene, some do (the
// guard is what keeps them out). The guard's arithmetic is the decision's: it costs more than without.
TEST(PipelinePlan, LitGuardJumpsNoLitPixel) {
    const auto& f = head_side_lit();
    for (const auto length : {length_policy::adaptive, length_policy::geometry})
        for (const auto set : {interp::sample_set::case1, interp::sample_set::case2}) {
            SCOPED_TRACE(std::string(length_policy_name(length)) + (set == interp::sample_set::case1 ? " case1" : " case2"));
            plan_config c;
            c.length = length;
            c.set = set;
            c.m_min = 2;
            c.m_max = 5;
            c.length_tol = 1.5;
            const plan free = make_plan(f.r, f.k, patent, c);
            c.lit_guard = true;
            const plan guarded = make_plan(f.r, f.k, patent, c);
            expect_valid_plan(f.r, guarded, c);
            EXPECT_GT(lit_pixels_jumped(f, free, c), 0u) << "no lit patch jumped without the guard";
            EXPECT_EQ(lit_pixels_jumped(f, guarded, c), 0u);
            EXPECT_GT(guarded.decision.mul, free.decision.mul);
        }
}

}  // namespace test_pipeline_refine
