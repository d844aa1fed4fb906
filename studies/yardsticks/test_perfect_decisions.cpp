// Perfect decisions (perfect_decisions.h), the adaptive length policy's yardstick: checked against the
// rasteriser's geometry and the golden model, as test_pipeline_refine.cpp checks the policy's own
// refinements. No simulation here: these tests may share a process.
#include "studies/yardsticks/perfect_decisions.h"
#include "testbenches/pipeline/plan_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_perfect_decisions {

using namespace shading;
using namespace shading::pipeline;
using namespace shading::yardsticks;
using namespace plan_test;

// With perfect decisions every decision is right: what the policy sends for each accepted interval (a
// cubic of 2^m_min, else its two halves split at the check point) has an RMS error against per-pixel
// shading of at most length_tol, and every longer interval the growth rule and the segment allowed
// sends more (both recomputed here from the rasteriser and the golden model). Only the adaptive
// length policy takes it.
TEST(PipelinePlan, PerfectDecisionsAreRight) {
    const auto& f = head();
    plan_config c = adaptive_length(2, 5, 1.0);
    c.degree = degree_policy::cubic;
    c.split_at_check = true;
    c.exact_fallback = true;  // else 2^m_min is taken unchecked
    const plan p = perfect_decisions_plan(f.r, f.k, patent, c);
    expect_valid_plan(f.r, p, c);
    const frame exact = per_pixel_frame(f.r, f.k, patent);
    // RMS error (levels per channel) of what the policy sends for an interval of 2^m at (y, x0).
    auto sent_rms = [&](unsigned y, unsigned x0, unsigned m) {
        const double e = m > c.m_min ? interval_squared_error(f, exact, interval_at(x0, m - 1, true), y, c) +
                                           interval_squared_error(f, exact, interval_at(x0 + (1u << (m - 1)), m - 1, true), y, c)
                                     : interval_squared_error(f, exact, interval_at(x0, m, false), y, c);
        return std::sqrt(e / (3.0 * double(1u << m)));
    };
    std::size_t decisions = 0, longer = 0, misses = 0;
    unsigned line = ~0u, seg_end = 0, allowed = c.m_max, exact_left = 0;
    for (std::size_t i = 0; i < p.jobs.size(); ++i) {
        const interval_job& j = p.jobs[i];
        const unsigned end = segment_end(cuts(f.r, j.y, c), j.x0);
        if (j.y != line || end != seg_end) allowed = c.m_max;
        line = j.y;
        seg_end = end;
        if (j.m == 0) {
            // 2^m_min exact pixels where even 2^m_min sends too much (else the segment's tail).
            if (exact_left > 0) {
                --exact_left;
            } else if ((1u << c.m_min) <= end - j.x0) {
                ++misses;
                EXPECT_GT(sent_rms(j.y, j.x0, c.m_min), c.length_tol) << "exact pixels where 2^m_min is within, line "
                                                                      << j.y << ", x " << j.x0;
                exact_left = (1u << c.m_min) - 1;
            }
            allowed = std::min(c.m_min + 1, c.m_max);
            continue;
        }
        exact_left = 0;
        // A quadratic is the first half of a split cubic of one level more; its second half follows.
        const unsigned m = j.deg2 ? j.m + 1 : j.m;
        if (j.deg2) {
            ASSERT_LT(i + 1, p.jobs.size());
            ASSERT_TRUE(p.jobs[i + 1].deg2 && p.jobs[i + 1].x0 == j.x0 + j.len) << "line " << j.y << ", x " << j.x0;
            ++i;
        }
        ++decisions;
        EXPECT_LE(sent_rms(j.y, j.x0, m), c.length_tol * (1 + 1e-9)) << "line " << j.y << ", x " << j.x0 << ", m " << m;
        for (unsigned mm = m + 1; mm <= allowed && (1u << mm) <= end - j.x0; ++mm) {
            ++longer;
            EXPECT_GT(sent_rms(j.y, j.x0, mm), c.length_tol) << "a longer interval is within, line " << j.y << ", x " << j.x0;
        }
        allowed = std::min(m + 1, c.m_max);
    }
    EXPECT_GT(decisions, 200u);
    EXPECT_GT(longer, 100u);
    EXPECT_GT(misses, 10u);
    c.length = length_policy::geometry;
    EXPECT_THROW(perfect_decisions_plan(f.r, f.k, patent, c), scene::scene_error);
}

}  // namespace test_perfect_decisions
