// The geometry side's two units (src/golden_pipeline/plan.cpp): stepped along the line as a scan-line
// renderer does (the default) or from scratch per point, and the geometry-only policy's decisions.
// Plain C++, no simulation: tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <set>
#include <utility>

#include "golden_pipeline/pipeline.h"
#include "scene/scanline.h"
#include "scene/scene.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_baselines {

using namespace shading;
using namespace shading::pipeline;

namespace {

const scene::device_config squared{scene::specular_device::squared, overflow_mode::saturate};

struct fixture {
    scene::world w;
    scene::rasterised r;
    frame_constants k;
    explicit fixture(const char* name, unsigned size)
        : w(scene::builtin_scene(name, SHADING_SOURCE_DIR, size, size)), r(scene::rasterise(w)), k(frame_constants_of(w)) {}
};

std::vector<unsigned> job_points(const interval_job& j, interp::sample_set set) {
    if (j.m == 0) return {0};
    if (j.deg2) return {0, 4, 8};
    return set == interp::sample_set::case1 ? std::vector<unsigned>{0, 2, 4, 8} : std::vector<unsigned>{0, 4, 6, 8};
}

// The dot products the geometry side charges per point (N.L, its gate, N.H and its clamp).
void charge_dots(const scene::pixel_geometry& g, scene::op_counts* ops) {
    auto re = [ops](const scene::cvec3& v) {
        return scene::cvec3{scene::cnum(v.x.value(), ops), scene::cnum(v.y.value(), ops), scene::cnum(v.z.value(), ops)};
    };
    const scene::cnum zero(0.0, ops);
    const scene::cvec3 n = re(g.n);
    if (dot(n, re(g.l[0])) > zero) max(dot(n, re(g.h[0])), zero);
}

}  // namespace

// A fixed-length plan touches only its sample points: the stepped count is one span_stepper walked
// over exactly those pixels line by line, left to right (a std::set of (y, x) is in that order), plus
// the dot products; the from-scratch count is geometry_at at the same pixels. The two units give
// the same plan (same jobs, same codes), only the counts differ, and hardware_ops charges the one
// plan_config.unit names. With edges walked (plan_config.walk_edges) the stepper walks them too.
TEST(PipelineGeometryUnit, SteppedCountIsAStepperOverTheSamplePoints) {
    const fixture f("sphere", 64);
    for (bool walk : {false, true}) {
        for (unsigned m : {2u, 3u, 5u}) {
            plan_config c;
            c.m = m;
            c.walk_edges = walk;
            const plan p = make_plan(f.r, f.k, squared, c);
            std::set<std::pair<unsigned, unsigned>> px;
            for (const auto& j : p.jobs)
                for (unsigned e : job_points(j, c.set)) px.insert({j.y, j.x0 + e * (1u << j.m) / 8});
            ASSERT_EQ(px.size(), p.geometry_points);
            scene::span_stepper st(f.r, walk);
            scene::op_counts stepped, scratch;
            for (const auto& [y, x] : px) {
                charge_dots(st.at(x, y, &stepped), &stepped);
                charge_dots(scene::geometry_at(f.r, x, y, &scratch), &scratch);
            }
            EXPECT_EQ(p.geometry_stepped, stepped) << m;
            EXPECT_EQ(p.geometry, scratch) << m;
            // stepped_geometry, for points planned elsewhere, charges the same points as make_plan.
            std::vector<std::array<unsigned, 2>> points;
            for (const auto& [y, x] : px) points.push_back({x, y});
            const stepped_count sc = stepped_geometry(f.r, points, walk);
            EXPECT_EQ(sc.ops, stepped) << m;
            EXPECT_EQ(sc.stats.run_starts, p.stepping.run_starts) << m;
            EXPECT_EQ(sc.stats.walked_starts, p.stepping.walked_starts) << m;
            EXPECT_EQ(sc.stats.triangle_setups, p.stepping.triangle_setups) << m;
            EXPECT_EQ(p.stepping.points, px.size());
            EXPECT_EQ(p.stepping.walked_starts, st.stats().walked_starts);
            if (walk) {
                EXPECT_GT(p.stepping.walked_starts, 0u);
            }
            stepped += p.decision;  // the fold test's compares
            scratch += p.decision;
            EXPECT_EQ(hardware_ops(p, c).geometry, stepped);
            c.unit = geometry_unit::scratch;
            EXPECT_EQ(hardware_ops(p, c).geometry, scratch);
        }
    }
}

// A point that is no covered pixel has no geometry: stepped_geometry says which, and counts nothing.
TEST(PipelineGeometryUnit, SteppedGeometryRefusesAnUncoveredPoint) {
    const fixture f("sphere", 64);
    EXPECT_FALSE(f.r.covered(0, 0));
    EXPECT_THROW(stepped_geometry(f.r, {{0, 0}}, false), std::invalid_argument);
    EXPECT_THROW(stepped_geometry(f.r, {{64, 10}}, false), std::invalid_argument);
    EXPECT_EQ(stepped_geometry(f.r, {}, true).ops, scene::op_counts{});
}

// On the head at 512 with adaptive length and degree the stepped unit is cheaper than from scratch
// (set-ups are shared by the points on a triangle, neighbouring points step) and the plans agree.
// Not at every size: where a triangle covers few pixels (the 64x64 sphere above, the head at 256)
// its set-up costs more than the steps save, and the from-scratch unit is the cheaper one.
TEST(PipelineGeometryUnit, SteppedCheaperOnTheHeadSamePlan) {
    const fixture f("head", 512);
    plan_config c;
    c.length = length_policy::adaptive;
    c.degree = degree_policy::adaptive;
    const plan a = make_plan(f.r, f.k, squared, c);
    c.unit = geometry_unit::scratch;
    const plan b = make_plan(f.r, f.k, squared, c);
    ASSERT_EQ(a.jobs.size(), b.jobs.size());
    for (std::size_t i = 0; i < a.jobs.size(); ++i) ASSERT_EQ(a.jobs[i].s, b.jobs[i].s) << i;
    EXPECT_EQ(a.geometry, b.geometry);
    EXPECT_LT(a.geometry_stepped.long_ops(), a.geometry.long_ops());
    EXPECT_GT(a.stepping.steps, 0u);
}

// Walking the edges changes what the geometry side pays, never the plan: for every length policy the
// same jobs with the same codes, the same points, fewer long operations; for the plans without check
// points (fixed) the walked count is one walking span_stepper over the plan's sample points, plus the
// dot products. (The optimum's, a yardstick: studies/yardsticks/test_optimum.cpp.)
TEST(PipelineGeometryUnit, WalkingEdgesChangesOnlyTheCounts) {
    const fixture f("head", 256);
    for (length_policy lp : {length_policy::fixed, length_policy::adaptive, length_policy::geometry}) {
        plan_config c;
        c.length = lp;
        c.eval = evaluator::fd;
        c.degree = lp == length_policy::fixed ? degree_policy::quadratic : degree_policy::cubic;
        const plan a = make_plan(f.r, f.k, squared, c);
        c.walk_edges = true;
        const plan b = make_plan(f.r, f.k, squared, c);
        const char* name = length_policy_name(lp);
        ASSERT_EQ(a.jobs.size(), b.jobs.size()) << name;
        for (std::size_t i = 0; i < a.jobs.size(); ++i) {
            ASSERT_EQ(a.jobs[i].x0, b.jobs[i].x0) << name << i;
            ASSERT_EQ(a.jobs[i].s, b.jobs[i].s) << name << i;
        }
        EXPECT_EQ(a.geometry_points, b.geometry_points) << name;
        EXPECT_EQ(a.geometry, b.geometry) << name;  // from scratch: no stepper
        EXPECT_EQ(a.stepping.walked_starts, 0u) << name;
        EXPECT_GT(b.stepping.walked_starts, 0u) << name;
        EXPECT_LT(b.geometry_stepped.long_ops(), a.geometry_stepped.long_ops()) << name;
        // The checked policies' check points have geometry too.
        if (lp == length_policy::adaptive || lp == length_policy::geometry) continue;
        std::set<std::pair<unsigned, unsigned>> px;
        for (const auto& j : b.jobs)
            for (unsigned e : job_points(j, c.set)) px.insert({j.y, j.x0 + e * (1u << j.m) / 8});
        ASSERT_EQ(px.size(), b.geometry_points) << name;
        scene::span_stepper st(f.r, true);
        scene::op_counts walked;
        for (const auto& [y, x] : px) charge_dots(st.at(x, y, &walked), &walked);
        EXPECT_EQ(b.geometry_stepped, walked) << name;
    }
}

// ---- The geometry-only policies ----

// Hand-worked constants: n = 20, k_s I code 102 (0.4 x 255), 255 k_d I = 153 (code 39168 in Q8.8),
// tolerance 1 level, degree tolerance 0.5, case 1:
//   highlight c_n = (0.5 / 102)^(1/20) = 0.766511 -> x 32768 = 25117.04 (codes)
//   N.L's miss 1 / 153 x 32768 = 214.170; for the degree 0.5 / 153 x 32768 = 107.085
//   N.H's miss 0.5 / (102 x 20) x 32768 = 8.0314
//   spread, cubic: K = max |t (t - 1/4)(t - 1/2)(t - 1)| / 4! = 0.027008 / 24 = 0.00112534 (at t = 0.832),
//     (0.5 / (102 K))^(1/4) / 20 x 32768 = 2366.96; quadratic: K = 0.048112 / 3! = 0.00801874
//     (t = 0.211), (0.5 / (102 K))^(1/3) / 20 x 32768 = 1390.51.
TEST(PipelineGeometryPolicy, LimitsHandWorked) {
    frame_constants k;
    k.n = 20;
    k.ksi = {102, 102, 102};
    k.kdi = {39168, 39168, 39168};
    plan_config c;
    c.length_tol = 1.0;
    c.degree_tol = 0.5;
    const geometry_limits g = geometry_limits_of(k, c);
    EXPECT_NEAR(g.highlight, 25117.04, 0.01);
    EXPECT_NEAR(g.nl_miss, 214.170, 0.001);
    EXPECT_NEAR(g.nl_miss_degree, 107.085, 0.001);
    EXPECT_NEAR(g.nh_miss, 8.0314, 0.0001);
    EXPECT_NEAR(g.spread_cubic, 2366.96, 0.05);
    EXPECT_NEAR(g.spread_quad, 1390.51, 0.05);
    // No specular term: no highlight anywhere (a bound above every code).
    k.ksi = {0, 0, 0};
    EXPECT_GT(geometry_limits_of(k, c).highlight, 65536.0);
}

// The labels: only the policies that read exact colours cannot run on a geometry side.
TEST(PipelineGeometryPolicy, Labels) {
    EXPECT_TRUE(policy_runs_on_geometry_side(length_policy::fixed));
    EXPECT_TRUE(policy_runs_on_geometry_side(length_policy::geometry));
    EXPECT_FALSE(policy_runs_on_geometry_side(length_policy::adaptive));
    EXPECT_TRUE(policy_runs_on_geometry_side(degree_policy::geometry));
    EXPECT_TRUE(policy_runs_on_geometry_side(degree_policy::zones));
    EXPECT_FALSE(policy_runs_on_geometry_side(degree_policy::adaptive));
    EXPECT_STREQ(length_policy_name(length_policy::geometry), "geometry");
    EXPECT_STREQ(degree_policy_name(degree_policy::geometry), "geometry");
}

// An unbounded tolerance accepts every first try: the geometry length policy then tiles exactly as
// the adaptive one does (same positions, lengths, degrees), reading no colour (no check samples).
// At tolerance 0 every interval in light fails (c_n = 0: all highlight, no spread allowed) and the
// plan is nearly all exact pixels; a tighter tolerance never costs fewer operations.
TEST(PipelineGeometryPolicy, ExtremesAndNoColourRead) {
    const fixture f("sphere", 64);
    plan_config c;
    c.length = length_policy::adaptive;
    c.length_tol = 1e12;
    const plan a = make_plan(f.r, f.k, squared, c);
    c.length = length_policy::geometry;
    const plan g = make_plan(f.r, f.k, squared, c);
    ASSERT_EQ(a.jobs.size(), g.jobs.size());
    for (std::size_t i = 0; i < a.jobs.size(); ++i) {
        EXPECT_EQ(a.jobs[i].x0, g.jobs[i].x0);
        EXPECT_EQ(a.jobs[i].len, g.jobs[i].len);
        EXPECT_EQ(a.jobs[i].s, g.jobs[i].s);
    }
    EXPECT_EQ(g.check_samples, 0u);
    c.length_tol = 0.0;
    const plan z = make_plan(f.r, f.k, squared, c);
    std::size_t exact = 0;
    for (const auto& j : z.jobs) exact += j.m == 0;
    EXPECT_GT(exact, z.pixels * 9 / 10);
    EXPECT_EQ(z.check_samples, 0u);
    c.length_tol = 1.0;
    c.degree = degree_policy::geometry;
    const plan one = make_plan(f.r, f.k, squared, c);
    c.length_tol = 0.25;
    const plan quarter = make_plan(f.r, f.k, squared, c);
    EXPECT_EQ(one.check_samples + quarter.check_samples, 0u);
    EXPECT_GE(hardware_ops(quarter, c).total().long_ops(), hardware_ops(one, c).total().long_ops());
}

// The geometry degree policy: cubic wherever the highlight reaches (some sample's N.H >= c_n), and
// on the sphere some quadratic intervals (diffuse flanks, where N.L is nearly quadratic).
TEST(PipelineGeometryPolicy, DegreeCubicInTheHighlight) {
    const fixture f("sphere", 64);
    plan_config c;
    c.m = 3;
    c.degree = degree_policy::geometry;
    const plan p = make_plan(f.r, f.k, squared, c);
    const geometry_limits lim = geometry_limits_of(f.k, c);
    std::size_t quad = 0;
    for (const auto& j : p.jobs) {
        if (j.m == 0) continue;
        double hi = 0.0;
        for (const auto& s : j.s) hi = std::max(hi, double(s.cos_nh));
        if (hi >= lim.highlight) {
            EXPECT_FALSE(j.deg2) << j.y << " " << j.x0;
        }
        quad += j.deg2;
    }
    EXPECT_GT(quad, 0u);
    EXPECT_EQ(p.check_samples, 0u);
}

}  // namespace test_pipeline_baselines
