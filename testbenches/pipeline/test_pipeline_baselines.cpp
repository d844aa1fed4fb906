// The geometry side's two units (src/pipeline/plan.cpp): stepped along the line as a scan-line
// renderer does (the default) or from scratch per point, and the geometry-only policy's decisions.
// Plain C++, no simulation: tests may share a process.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "pipeline/pipeline.h"
#include "scene/scanline.h"
#include "scene/scene.h"

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
// plan_config.unit names.
TEST(PipelineGeometryUnit, SteppedCountIsAStepperOverTheSamplePoints) {
    const fixture f("sphere", 64);
    for (unsigned m : {2u, 3u, 5u}) {
        plan_config c;
        c.m = m;
        const plan p = make_plan(f.r, f.k, squared, c);
        std::set<std::pair<unsigned, unsigned>> px;
        for (const auto& j : p.jobs)
            for (unsigned e : job_points(j, c.set)) px.insert({j.y, j.x0 + e * (1u << j.m) / 8});
        ASSERT_EQ(px.size(), p.geometry_points);
        scene::span_stepper st(f.r);
        scene::op_counts stepped, scratch;
        for (const auto& [y, x] : px) {
            charge_dots(st.at(x, y, &stepped), &stepped);
            charge_dots(scene::geometry_at(f.r, x, y, &scratch), &scratch);
        }
        EXPECT_EQ(p.geometry_stepped, stepped) << m;
        EXPECT_EQ(p.geometry, scratch) << m;
        EXPECT_EQ(p.stepping.points, px.size());
        stepped += p.decision;  // the fold test's compares
        scratch += p.decision;
        EXPECT_EQ(hardware_ops(p, c).geometry, stepped);
        c.unit = geometry_unit::scratch;
        EXPECT_EQ(hardware_ops(p, c).geometry, scratch);
    }
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
