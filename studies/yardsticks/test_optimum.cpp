// The optimum plan (optimum.cpp), the yardstick of the length and degree policies: a valid plan whose
// NMSE, recomputed from its frame, is within the allowed one; its geometry points counted from its
// sample pixels; its Lagrangian certificate checked against every policy's plan and against plans
// perturbed from it (none may beat points + lambda x error); the cheapest point hand-counted.
#include <array>
#include <optional>
#include <random>

#include "scene/scanline.h"
#include "studies/yardsticks/optimum.h"
#include "testbenches/pipeline/plan_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_optimum {

using namespace shading;
using namespace shading::pipeline;
using namespace shading::yardsticks;
using namespace plan_test;

namespace {

using reference = optimum_config::reference;

// The pipeline's settings the optimum plans for (intervals of m_min .. m_max in either degree, the
// forward differences), and what it is asked. Its plans are checked as a length policy's of
// m_min .. m_max with exact pixels anywhere (expect_valid_plan with adaptive length and the exact
// fallback): the optimum reads no length policy.
struct optimum_case {
    plan_config c;
    optimum_config o;
};
optimum_case optimum_config_of(double nmse, reference ref = reference::interpolation) {
    optimum_case t;
    t.c.length = length_policy::adaptive;
    t.c.m_min = interp::m_min;
    t.c.m_max = interp::m_max;
    t.c.eval = evaluator::fd;
    t.o.nmse = nmse;
    t.o.ref = ref;
    return t;
}
optimum plan_of(const scene_fixture& f, const optimum_case& t) { return optimal_plan(f.r, f.k, patent, t.c, t.o); }

// The reference image and its energy (sum of squared values over covered pixels and channels),
// recomputed here from the golden model and the Phong renderer.
struct reference_image {
    scene::shaded_image img;
    double energy = 0.0;
    reference_image(const scene_fixture& f, reference ref) {
        img = ref == reference::interpolation ? to_image(per_pixel_frame(f.r, f.k, patent)) : scene::render_phong(f.r);
        for (std::size_t i = 0; i < img.value.size(); ++i)
            if (img.covered[i])
                for (int ch = 0; ch < 3; ++ch) energy += img.value[i][ch] * img.value[i][ch];
    }
};

// Squared error (8-bit levels^2) of a plan's frame against the reference: NMSE x energy.
double squared_error(const scene_fixture& f, const plan& p, const plan_config& c, const reference_image& ref) {
    return compare(to_image(golden_frame(p, f.k, patent, c)), ref.img).nmse * ref.energy;
}

// A local change of interval job i of plan p, kind 0: its pixels made exact; 1: its degree flipped;
// 2: split in two; 3: merged with the next job where that is an interval of the same length and the
// doubled interval's t = 1 sample stays in the segment. The jobs it removes and inserts (samples from
// the rasteriser) and the plan changed; nothing where the change does not apply.
struct local_change {
    std::vector<interval_job> removed, inserted;
    plan changed;
};
std::optional<local_change> change_of(const scene_fixture& f, const plan& p, const plan_config& c, std::size_t i,
                                      int kind) {
    const interval_job& j = p.jobs[i];
    auto sample = [&](unsigned x) { return sample_of(scene::geometry_at(f.r, x, j.y, nullptr)); };
    auto make = [&](unsigned x0, unsigned m, bool deg2) {
        interval_job k = j;
        k.x0 = x0;
        k.m = m;
        k.len = 1u << m;
        k.deg2 = m > 0 && deg2;
        if (m == 0) {
            k.s = {sample(x0), sample(x0), sample(x0), sample(x0)};
        } else {
            const auto pts = job_points(k, c.set);
            for (std::size_t s = 0; s < 4; ++s) k.s[s] = sample(at(k, pts[std::min(s, pts.size() - 1)]));
        }
        k.zone = static_cast<uint8_t>(head_zone(f.r, scene::geometry_at(f.r, x0, j.y, nullptr)));
        return k;
    };
    local_change ch;
    if (kind == 0) {
        for (unsigned x = j.x0; x < j.x0 + j.len; ++x) ch.inserted.push_back(make(x, 0, false));
    } else if (kind == 1) {
        ch.inserted.push_back(make(j.x0, j.m, !j.deg2));
    } else if (kind == 2) {
        if (j.m <= c.m_min) return std::nullopt;
        ch.inserted.push_back(make(j.x0, j.m - 1, j.deg2));
        ch.inserted.push_back(make(j.x0 + j.len / 2, j.m - 1, j.deg2));
    } else {
        if (i + 1 >= p.jobs.size() || j.m >= c.m_max) return std::nullopt;
        const interval_job& nx = p.jobs[i + 1];
        if (nx.y != j.y || nx.m != j.m || nx.x0 != j.x0 + j.len) return std::nullopt;
        if (j.x0 + 2 * j.len > segment_end(cuts(f.r, j.y, c), j.x0)) return std::nullopt;
        ch.inserted.push_back(make(j.x0, j.m + 1, j.deg2));
    }
    const std::size_t n_removed = kind == 3 ? 2 : 1;
    ch.removed.assign(p.jobs.begin() + std::ptrdiff_t(i), p.jobs.begin() + std::ptrdiff_t(i + n_removed));
    ch.changed = p;
    ch.changed.jobs.erase(ch.changed.jobs.begin() + std::ptrdiff_t(i), ch.changed.jobs.begin() + std::ptrdiff_t(i + n_removed));
    ch.changed.jobs.insert(ch.changed.jobs.begin() + std::ptrdiff_t(i), ch.inserted.begin(), ch.inserted.end());
    return ch;
}

}  // namespace

TEST(PipelineOptimal, IsAValidPlanWithinItsNmse) {
    const scene_fixture& f = head();
    for (const auto ref : {reference::interpolation, reference::total}) {
        const optimum_case t = optimum_config_of(ref == reference::interpolation ? 1e-4 : 1e-2, ref);
        const plan_config& c = t.c;
        const optimum best = plan_of(f, t);
        const plan& p = best.p;
        expect_valid_plan(f.r, p, c);
        ASSERT_TRUE(best.certificate.feasible);
        const reference_image img(f, ref);
        const double nmse = squared_error(f, p, c, img) / img.energy;
        EXPECT_LE(nmse, t.o.nmse);
        EXPECT_NEAR(best.certificate.nmse, nmse, 1e-9 * t.o.nmse);
        // Its points are its distinct sample pixels (no check points: it pays nothing to decide).
        EXPECT_EQ(p.geometry_points, sample_pixels(p, c.set).size());
        EXPECT_EQ(p.check_samples, 0u);
        EXPECT_LE(best.certificate.points_bound, double(p.geometry_points));
        EXPECT_GT(best.certificate.points_bound, 0.0);
    }
}

TEST(PipelineOptimal, TighterNmseNeedsMorePoints) {
    const scene_fixture& f = head();
    std::size_t prev = 0;
    for (const double nmse : {1e-3, 1e-4, 1e-5, 1e-6}) {
        const plan p = plan_of(f, optimum_config_of(nmse)).p;
        EXPECT_GE(p.geometry_points, prev) << "NMSE " << nmse;
        prev = p.geometry_points;
    }
    // NMSE 0 against per-pixel shading: every interval that is not exact costs error unless its
    // polynomial hits every pixel's code, so the plan is (nearly) all exact pixels, and still valid.
    const optimum all = plan_of(f, optimum_config_of(0.0));
    EXPECT_TRUE(all.certificate.feasible);
    EXPECT_EQ(all.certificate.nmse, 0.0);
    EXPECT_GT(all.p.geometry_points, prev);
}

// No policy's plan (same segments, same evaluator) reaches its own NMSE with fewer sample points than
// the bound the optimum certifies for that NMSE.
TEST(PipelineOptimal, BoundIsBelowEveryPolicy) {
    const scene_fixture& f = head();
    const reference_image ref(f, reference::interpolation);
    std::vector<plan_config> policies;
    for (const double tol : {0.5, 1.0, 2.0, 4.0}) {
        plan_config c;
        c.length = length_policy::adaptive;
        c.length_tol = tol;
        c.split_at_check = tol > 1.0;
        policies.push_back(c);
        c.length = length_policy::geometry;
        c.degree = degree_policy::geometry;
        policies.push_back(c);
    }
    for (const unsigned m : {2u, 3u, 4u}) policies.push_back(head_fixed(m));
    for (plan_config c : policies) {
        c.eval = evaluator::fd;
        SCOPED_TRACE(std::string(length_policy_name(c.length)) + " tol " + std::to_string(c.length_tol) + " m " +
                     std::to_string(c.m));
        const plan p = make_plan(f.r, f.k, patent, c);
        const double nmse = squared_error(f, p, c, ref) / ref.energy;
        const optimum best = plan_of(f, optimum_config_of(nmse));
        EXPECT_LE(best.certificate.points_bound, double(sample_pixels(p, c.set).size()));
        EXPECT_LE(best.p.geometry_points, sample_pixels(p, c.set).size());
    }
}

// Lagrangian optimality, checked from outside: the optimum minimises points + lambda x error over every
// plan of its segments, so no plan made from it by a local change (an interval made exact pixels, its
// degree flipped, split in two, or merged with its neighbour) may do better at its lambda.
TEST(PipelineOptimal, NoLocalChangeBeatsIt) {
    const scene_fixture& f = head();
    const optimum_case t = optimum_config_of(3e-5);
    const plan_config& c = t.c;
    const reference_image ref(f, reference::interpolation);
    const optimum found = plan_of(f, t);
    const plan& best = found.p;
    const double lambda = found.certificate.lambda;
    ASSERT_GT(lambda, 0.0);
    auto objective = [&](const plan& p) {
        return double(sample_pixels(p, c.set).size()) + lambda * squared_error(f, p, c, ref);
    };
    const double at_best = objective(best);
    std::mt19937 rng(7);
    std::size_t tried = 0;
    for (int attempt = 0; attempt < 400 && tried < 60; ++attempt) {
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, best.jobs.size() - 1)(rng);
        const interval_job& j = best.jobs[i];
        if (j.m == 0) continue;
        const int kind = attempt % 4;
        const auto ch = change_of(f, best, c, i, kind);
        if (!ch) continue;
        ++tried;
        EXPECT_GE(objective(ch->changed), at_best - 1e-6 * at_best)
            << "change " << kind << " of job " << i << " (line " << j.y << ", x " << j.x0 << ", m " << j.m << ")";
    }
    EXPECT_GE(tried, 40u);
}

TEST(PipelineOptimal, InfeasibleNmseGivesTheLowestErrorPlan) {
    const scene_fixture& f = head();
    // Against exact Phong the device's own error remains at every pixel: NMSE 0 is out of reach.
    const optimum_case t = optimum_config_of(0.0, reference::total);
    const optimum best = plan_of(f, t);
    EXPECT_FALSE(best.certificate.feasible);
    EXPECT_EQ(best.certificate.points_bound, 0.0);
    expect_valid_plan(f.r, best.p, t.c);
    const reference_image ref(f, reference::total);
    EXPECT_NEAR(best.certificate.nmse, squared_error(f, best.p, t.c, ref) / ref.energy, 1e-9);
}

TEST(PipelineOptimal, RejectsABadNmse) {
    optimum_case t = optimum_config_of(-1e-5);
    EXPECT_THROW(plan_of(head(), t), scene::scene_error);
    t.o.nmse = std::nan("");
    EXPECT_THROW(plan_of(head(), t), scene::scene_error);
}

// The cheapest point of the head (perspective camera, one directional light), counted by hand from
// scanline.h: a step is additions only; N = normalize(U_N): 3 mul for |U_N|^2, a square root, a
// division, 3 mul (8); V = normalize(Q E - U_P): 3 mul for Q E, then 8 (P = U_P / Q is never
// formed); H = normalize(L + V) (8); N.L and N.H: 6 mul. 33 long operations.
TEST(PipelineOptimal, CheapestPointIsHandCounted) {
    EXPECT_EQ(plan_of(head(), optimum_config_of(1e-3)).certificate.point_long_min, 33.0);
}

// The greedy with perfect estimates (--optimal-greedy): a valid plan within the NMSE, never below the
// optimum's bound, every interval within the tolerance, and where the growth rule allowed a longer
// interval at the same start, neither degree of it within the tolerance (recomputed here).
TEST(PipelineOptimal, GreedyFollowsItsRule) {
    const scene_fixture& f = head();
    optimum_case t = optimum_config_of(1e-4);
    t.o.greedy = true;
    const plan_config& c = t.c;
    const optimum greedy = plan_of(f, t);
    const plan& p = greedy.p;
    expect_valid_plan(f.r, p, c);
    const reference_image ref(f, reference::interpolation);
    const double nmse = squared_error(f, p, c, ref) / ref.energy;
    EXPECT_LE(nmse, t.o.nmse);
    EXPECT_NEAR(greedy.certificate.greedy_nmse, nmse, 1e-9 * t.o.nmse);
    EXPECT_GE(double(p.geometry_points), greedy.certificate.points_bound);
    const plan best = plan_of(f, optimum_config_of(1e-4)).p;
    EXPECT_GT(p.geometry_points, best.geometry_points) << "the greedy should need more points than the optimum";
    const double tol = greedy.certificate.greedy_tolerance;
    ASSERT_GT(tol, 0.0);
    const frame exact = per_pixel_frame(f.r, f.k, patent);
    // RMS error (levels, per channel) of an interval at (y, x0) of 2^m pixels, recomputed.
    auto rms = [&](unsigned y, unsigned x0, unsigned m, bool deg2) {
        return std::sqrt(interval_squared_error(f, exact, interval_at(x0, m, deg2), y, c) / (3.0 * double(1u << m)));
    };
    std::size_t longer_checked = 0;
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        const interval_job& j = p.jobs[i];
        if (j.m == 0) continue;
        EXPECT_LE(rms(j.y, j.x0, j.m, j.deg2), tol * (1 + 1e-9)) << "line " << j.y << ", x " << j.x0;
        // The previous job ends here on the same segment as an interval at least as long: the growth
        // rule allowed m + 1, so m + 1 either does not fit or misses in both degrees.
        if (i == 0 || j.m >= c.m_max) continue;
        const interval_job& prev = p.jobs[i - 1];
        const auto lc = cuts(f.r, j.y, c);
        if (prev.y != j.y || prev.m < j.m || prev.x0 + prev.len != j.x0 || lc.count(j.x0)) continue;
        if (j.x0 + (2u << j.m) > segment_end(lc, j.x0)) continue;
        ++longer_checked;
        EXPECT_GT(rms(j.y, j.x0, j.m + 1, true), tol) << "line " << j.y << ", x " << j.x0;
        EXPECT_GT(rms(j.y, j.x0, j.m + 1, false), tol) << "line " << j.y << ", x " << j.x0;
    }
    EXPECT_GT(longer_checked, 20u);
}

// Planned from the line above (--optimal-from-above 0): a valid plan whose NMSE, recomputed, is the
// one reported, with the optimum's certificate unchanged; and at its lambda no local change beats
// points + lambda x error when every interval is priced as the planner must price it: by the same
// interval on the line above where it fits a segment there, else by its own error (recomputed here
// from the rasteriser's segments and the golden model).
TEST(PipelineOptimal, FromAboveChoosesOnTheLineAbovesErrors) {
    const scene_fixture& f = head();
    optimum_case t = optimum_config_of(1e-4);
    const plan_config& c = t.c;
    const optimum best = plan_of(f, t);
    t.o.from_above = 0;
    const optimum from_above = plan_of(f, t);
    const plan& p = from_above.p;
    expect_valid_plan(f.r, p, c);
    const reference_image ref(f, reference::interpolation);
    const double nmse = squared_error(f, p, c, ref) / ref.energy;
    EXPECT_NEAR(from_above.certificate.above_nmse, nmse, 1e-9 * t.o.nmse);
    EXPECT_LE(nmse, t.o.nmse);
    EXPECT_EQ(from_above.certificate.points_bound, best.certificate.points_bound) << "the certificate is the optimum's";
    EXPECT_GT(p.geometry_points, best.p.geometry_points) << "pricing from the line above should cost points";
    EXPECT_GT(from_above.certificate.above_fallback, 0.0);
    EXPECT_LT(from_above.certificate.above_fallback, 0.2);
    const double lambda = from_above.certificate.above_lambda;
    ASSERT_GT(lambda, 0.0);

    const frame exact = per_pixel_frame(f.r, f.k, patent);
    std::map<unsigned, std::set<unsigned>> line_cuts;
    auto cuts_of = [&](unsigned y) -> const std::set<unsigned>& {
        auto it = line_cuts.find(y);
        return it != line_cuts.end() ? it->second : line_cuts.emplace(y, cuts(f.r, y, c)).first->second;
    };
    // Squared error of job j's interval placed on line y (an exact pixel is the reference itself).
    auto error_on = [&](const interval_job& j, unsigned y) {
        return j.m == 0 ? 0.0 : interval_squared_error(f, exact, j, y, c);
    };
    auto priced = [&](const interval_job& j) {
        if (j.m > 0 && j.y > 0 && f.r.covered(j.x0, j.y - 1)) {
            const auto& lc = cuts_of(j.y - 1);
            if (lc.upper_bound(j.x0) != lc.end() && j.x0 + j.len <= segment_end(lc, j.x0)) return error_on(j, j.y - 1);
        }
        return error_on(j, j.y);
    };
    const double points = double(sample_pixels(p, c.set).size());
    std::mt19937 rng(11);
    std::size_t tried = 0, above = 0;
    for (int attempt = 0; attempt < 400 && tried < 60; ++attempt) {
        const std::size_t i = std::uniform_int_distribution<std::size_t>(0, p.jobs.size() - 1)(rng);
        const interval_job& j = p.jobs[i];
        if (j.m == 0) continue;
        const int kind = attempt % 4;
        const auto ch = change_of(f, p, c, i, kind);
        if (!ch) continue;
        double delta_error = 0.0;
        for (const auto& k : ch->removed) delta_error -= priced(k);
        for (const auto& k : ch->inserted) delta_error += priced(k);
        const double delta_points = double(sample_pixels(ch->changed, c.set).size()) - points;
        ++tried;
        above += j.y > 0 && f.r.covered(j.x0, j.y - 1);
        EXPECT_GE(delta_points + lambda * delta_error, -1e-6 * points)
            << "change " << kind << " of job " << i << " (line " << j.y << ", x " << j.x0 << ", m " << j.m << ")";
    }
    EXPECT_GE(tried, 40u);
    EXPECT_GE(above, 30u);
    t.o.from_above = int(window_max) + 1;
    EXPECT_THROW(plan_of(f, t), scene::scene_error);
}

// Walking the edges changes what the geometry side pays, never the plan (as test_pipeline_baselines
// checks for every length policy): the optimum's jobs with the same codes, the same points, fewer
// long operations; and, without check points, the walked count is one walking span_stepper over the
// plan's sample points plus the dot products (recomputed here from scanline.h).
TEST(PipelineOptimal, WalkingEdgesChangesOnlyTheCounts) {
    const scene_fixture f("head", 256);
    const scene::device_config squared{scene::specular_device::squared, overflow_mode::saturate};
    optimum_case t = optimum_config_of(1e-5);
    t.c.m_max = 5;  // the pipeline's defaults otherwise, with the forward differences
    t.c.degree = degree_policy::cubic;
    const plan a = optimal_plan(f.r, f.k, squared, t.c, t.o).p;
    t.c.walk_edges = true;
    const plan b = optimal_plan(f.r, f.k, squared, t.c, t.o).p;
    ASSERT_EQ(a.jobs.size(), b.jobs.size());
    for (std::size_t i = 0; i < a.jobs.size(); ++i) {
        ASSERT_EQ(a.jobs[i].x0, b.jobs[i].x0) << i;
        ASSERT_EQ(a.jobs[i].s, b.jobs[i].s) << i;
    }
    EXPECT_EQ(a.geometry_points, b.geometry_points);
    EXPECT_EQ(a.geometry, b.geometry);  // from scratch: no stepper
    EXPECT_EQ(a.stepping.walked_starts, 0u);
    EXPECT_GT(b.stepping.walked_starts, 0u);
    EXPECT_LT(b.geometry_stepped.long_ops(), a.geometry_stepped.long_ops());
    std::set<std::pair<unsigned, unsigned>> px;
    for (const auto& j : b.jobs)
        for (unsigned e : job_points(j, t.c.set)) px.insert({j.y, at(j, e)});
    ASSERT_EQ(px.size(), b.geometry_points);
    scene::span_stepper st(f.r, true);
    scene::op_counts walked;
    for (const auto& [y, x] : px) {
        // The dot products the geometry side charges per point (N.L, its gate, N.H and its clamp).
        const scene::pixel_geometry g = st.at(x, y, &walked);
        auto re = [&walked](const scene::cvec3& v) {
            return scene::cvec3{scene::cnum(v.x.value(), &walked), scene::cnum(v.y.value(), &walked),
                                scene::cnum(v.z.value(), &walked)};
        };
        const scene::cnum zero(0.0, &walked);
        const scene::cvec3 n = re(g.n);
        if (dot(n, re(g.l[0])) > zero) max(dot(n, re(g.h[0])), zero);
    }
    EXPECT_EQ(b.geometry_stepped, walked);
}

}  // namespace test_optimum
