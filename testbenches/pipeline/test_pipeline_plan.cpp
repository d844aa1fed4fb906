// The geometry side (plan.cpp): every plan is checked against the rasteriser's own spans and
// discontinuities, the geometry recomputed at the documented pixels, the sample points counted
// independently, and the adaptive policies' estimates by the hand-worked polynomial weights at the
// check points. Fixtures in plan_test_fixtures.h. No simulation here: these tests may share a process.
#include "plan_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_plan {

using namespace shading;
using namespace shading::pipeline;
using namespace plan_test;


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
    c.above_slack = int(interp::m_max) + 1;
    expect_error(c, "slack over the line above");
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

// ---- The adaptive length's decider, and plans made elsewhere (pipeline.h: the seams for studies) ----

namespace {
// A decider that reads nothing and answers the same every time.
struct always : length_decider {
    bool answer;
    explicit always(bool a) : answer(a) {}
    bool accept(length_candidate&) const override { return answer; }
};
// The policy's own decider, counting the candidates it is shown.
struct counting : length_decider {
    estimate_decider own;
    mutable std::size_t calls = 0;
    explicit counting(const plan_config& c) : own(c) {}
    bool accept(length_candidate& cand) const override {
        ++calls;
        return own.accept(cand);
    }
};
}  // namespace

// The decider takes the adaptive length's decisions and pays only for what it reads: accepting every
// candidate unread gives fixed m = 5's tiling with fixed m = 5's points and no check point; rejecting
// every one leaves every pixel exact (the exact fallback); the policy's own decider through the seam
// is make_plan's plan, counts and all.
TEST(PipelinePlan, DeciderTakesTheAdaptiveDecisions) {
    const auto& f = sphere();
    plan_config c = adaptive_length(2, 5, 1.0);
    const plan yes = make_plan(f.r, f.k, patent, c, always(true));
    expect_valid_plan(f.r, yes, c);
    const plan q = make_plan(f.r, f.k, patent, fixed(5));
    ASSERT_EQ(yes.jobs.size(), q.jobs.size());
    for (std::size_t i = 0; i < yes.jobs.size(); ++i) {
        EXPECT_EQ(yes.jobs[i].x0, q.jobs[i].x0);
        EXPECT_EQ(yes.jobs[i].m, q.jobs[i].m);
        EXPECT_EQ(yes.jobs[i].s, q.jobs[i].s);
    }
    EXPECT_EQ(yes.geometry_points, q.geometry_points);
    EXPECT_EQ(yes.check_samples, 0u);
    EXPECT_EQ(yes.decision, scene::op_counts{}) << "nothing estimated, no fold test (no surface breaks)";

    c.exact_fallback = true;
    const plan no = make_plan(f.r, f.k, patent, c, always(false));
    expect_valid_plan(f.r, no, c);
    for (const interval_job& j : no.jobs) EXPECT_EQ(j.m, 0u) << "line " << j.y << ", x " << j.x0;
    EXPECT_EQ(no.jobs.size(), f.r.covered_pixels());

    counting own(c);
    const plan p = make_plan(f.r, f.k, patent, c, own);
    const plan d = make_plan(f.r, f.k, patent, c);
    ASSERT_EQ(p.jobs.size(), d.jobs.size());
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        EXPECT_EQ(p.jobs[i].x0, d.jobs[i].x0);
        EXPECT_EQ(p.jobs[i].m, d.jobs[i].m);
    }
    EXPECT_EQ(p.geometry_points, d.geometry_points);
    EXPECT_EQ(p.check_samples, d.check_samples);
    EXPECT_EQ(p.decision, d.decision);
    std::size_t intervals = 0;
    for (const interval_job& j : p.jobs) intervals += j.m > 0;
    EXPECT_GT(own.calls, intervals) << "some candidates were turned down";
}

// A plan made elsewhere (plan_of_jobs, given only each job's line, start, m and degree) is counted as
// make_plan counts its own: the same samples and zones, points and geometry of both units, with edges
// walked, quadratics, cubics and exact tails; no decision. Shapes out of raster order, or with a sample
// off the covered pixels, are refused.
TEST(PipelinePlan, PlanOfJobsCountsAsMakePlan) {
    const auto& f = head();
    plan_config c = head_fixed(4);
    c.eval = evaluator::fd;  // exact tails
    c.degree = degree_policy::zones;
    c.walk_edges = true;
    const plan p = make_plan(f.r, f.k, patent, c);
    std::vector<interval_job> shapes;
    std::size_t kinds[3] = {0, 0, 0};
    for (const interval_job& j : p.jobs) {
        interval_job s;
        s.y = j.y;
        s.x0 = j.x0;
        s.m = j.m;
        s.deg2 = j.deg2;
        shapes.push_back(s);
        ++kinds[j.m == 0 ? 0 : j.deg2 ? 1 : 2];
    }
    EXPECT_GT(kinds[0], 0u);
    EXPECT_GT(kinds[1], 0u);
    EXPECT_GT(kinds[2], 0u);
    const plan q = plan_of_jobs(f.r, f.k, patent, c, shapes);
    ASSERT_EQ(q.jobs.size(), p.jobs.size());
    for (std::size_t i = 0; i < q.jobs.size(); ++i) {
        EXPECT_EQ(q.jobs[i].len, p.jobs[i].len);
        EXPECT_EQ(q.jobs[i].s, p.jobs[i].s);
        EXPECT_EQ(q.jobs[i].zone, p.jobs[i].zone);
    }
    EXPECT_EQ(q.pixels, p.pixels);
    EXPECT_EQ(q.geometry_points, p.geometry_points);
    EXPECT_EQ(q.points, p.points);
    EXPECT_EQ(q.geometry, p.geometry);
    EXPECT_EQ(q.geometry_stepped, p.geometry_stepped);
    EXPECT_EQ(q.stepping.triangle_setups, p.stepping.triangle_setups);
    EXPECT_EQ(q.stepping.run_starts, p.stepping.run_starts);
    EXPECT_EQ(q.stepping.walked_starts, p.stepping.walked_starts);
    EXPECT_EQ(q.stepping.steps, p.stepping.steps);
    EXPECT_GT(q.stepping.walked_starts, 0u);
    EXPECT_EQ(q.decision, scene::op_counts{});
    EXPECT_GT(p.decision.cmp, 0u) << "make_plan's fold tests and zone boxes";
    std::vector<interval_job> reversed(shapes.rbegin(), shapes.rend());
    EXPECT_THROW(plan_of_jobs(f.r, f.k, patent, c, reversed), std::invalid_argument);
    interval_job off;  // line 0, x 0: the head does not cover the frame's corner
    ASSERT_FALSE(f.r.covered(0, 0));
    EXPECT_THROW(plan_of_jobs(f.r, f.k, patent, c, {off}), std::invalid_argument);
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

}  // namespace test_pipeline_plan
