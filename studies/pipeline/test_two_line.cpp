// The two-line scheme's pieces (two_line.h): the emulated adaptive policy on runs worked by hand,
// against the planner itself on the head at 512 (its geometry points and NMSE, fixed-point against
// real-valued), and the two-line frame's bookkeeping recomputed from its pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>
#include <vector>

#include "scene/scene.h"
#include "studies/yardsticks/perfect_decisions.h"
#include "line_kinks.h"
#include "levels_testing.h"
#include "study_frame.h"
#include "two_line.h"

namespace {

using namespace shading;
using namespace shading::study;

std::vector<rgb_levels> grey(const std::vector<double>& v) {
    std::vector<rgb_levels> out;
    for (double x : v) out.push_back({x, x, x});
    return out;
}

adaptive_emulation policy(double tol, unsigned m_min, unsigned m_max, int above_slack = -1) {
    adaptive_emulation e;
    e.tol = tol;
    e.m_min = m_min;
    e.m_max = m_max;
    e.above_slack = above_slack;
    return e;
}

using test_helpers::squared_error;

// x^2 over 33 pixels: the 32-pixel candidate's quadratic through 0, 16, 32 meets x^2 at 8 and the
// cubic through 0, 8, 16, 32 at the check 24, so it is sent whole (as two exact quadratics): five
// points, 0, 8, 16, 24, 32, and no error.
TEST(EmulateAdaptive, ParabolaSentWhole) {
    std::vector<double> v;
    for (int x = 0; x <= 32; ++x) v.push_back(double(x * x));
    const emulated_run r = emulate_adaptive(grey(v), policy(1.0, 2, 5));
    EXPECT_EQ(r.points, 5u);
    EXPECT_LT(squared_error(r.out, grey(v)), 1e-12);
    // Its levels: the 32-pixel interval went out as two 16-pixel halves (m = 4), the tail pixel exact.
    for (int x = 0; x < 32; ++x) EXPECT_EQ(r.level[x], 4) << x;
    EXPECT_EQ(r.level[32], 0);
}

// The line-above limit: the line before at level 2 everywhere and K = 1 allow m <= 3, so x^2 goes out
// in 8-pixel intervals (samples 0, 2, 4, 8 and the check 6 each, the first shared): 4 x 4 + 1 = 17
// points, every level 2 (the 8-pixel cubics' 4-pixel halves); the line before sending nothing there
// (no_level) limits nothing.
TEST(EmulateAdaptive, LineAboveLimitsTheLength) {
    std::vector<double> v;
    for (int x = 0; x <= 32; ++x) v.push_back(double(x * x));
    std::vector<uint8_t> above(33, 2);
    const emulated_run r = emulate_adaptive(grey(v), policy(1.0, 2, 5, 1), above.data());
    EXPECT_EQ(r.points, 17u);
    EXPECT_LT(squared_error(r.out, grey(v)), 1e-12);
    for (int x = 0; x < 32; ++x) EXPECT_EQ(r.level[x], 2) << x;
    std::fill(above.begin(), above.end(), no_level);
    EXPECT_EQ(emulate_adaptive(grey(v), policy(1.0, 2, 5, 1), above.data()).points, 5u);
}

// A bump between the samples: 100 at pixel 13, 0 elsewhere. Samples 0, 8, 16, 32 and the check 24
// all read 0, so the 32-pixel interval is sent and the bump is lost: 3 x 100^2, five points.
TEST(EmulateAdaptive, BumpBetweenTheSamplesIsMissed) {
    std::vector<double> v(33, 0.0);
    v[13] = 100.0;
    const emulated_run r = emulate_adaptive(grey(v), policy(1.0, 2, 5));
    EXPECT_EQ(r.points, 5u);
    EXPECT_DOUBLE_EQ(squared_error(r.out, grey(v)), 3.0 * 100.0 * 100.0);
}

// The same bump with perfect decisions (studies/yardsticks/perfect_decisions.h): each candidate is decided
// on the true RMS of what it sends (three channels), every point still read. Traced by hand:
//  - at 0, 32 (points 0, 8, 16, 32, check 24) and 16 pixels (4, 12): every point 0, so the halves'
//    quadratics are 0 and the bump costs an RMS of 100 / sqrt(32) and 25: no; 8 pixels (2, 6): no
//    bump in 0..7, sent; the next may grow to 16;
//  - at 8, 16 (20) and 8 pixels (10, 14): the bump at 13, no; 4 pixels (9, 11): sent;
//  - at 12, 8 pixels (18): no; 4 pixels (13, 15): 13 is a sample, the cubic misses 15: 12..15 exact;
//  - at 16 and 24, growing to 8 pixels only (22; 26, 28, 30): sent.
// Points 0, 2, 4, 6, 8, 12, 16, 24, 32 | 9, 10, 11, 14, 20 | 13, 15, 18 | 22 | 26, 28, 30 = 21, no
// error anywhere, where the heuristic decisions took 5 points and lost the bump.
TEST(EmulateAdaptive, PerfectDecisionsSeeTheBump) {
    std::vector<double> v(33, 0.0);
    v[13] = 100.0;
    adaptive_emulation e = policy(1.0, 2, 5);
    e.perfect = true;
    const emulated_run r = emulate_adaptive(grey(v), e);
    EXPECT_EQ(r.points, 21u);
    EXPECT_LT(squared_error(r.out, grey(v)), 1e-18);
    for (int x = 0; x < 32; ++x) EXPECT_EQ(r.level[x], x >= 12 && x < 16 ? 0 : 2) << x;
}

// A step from 0 to 50 at pixel 10, 17 pixels, m 2..4, T = 1, traced by hand:
//  - at 0, 16 pixels: the quadratic through 0, 8, 16 (0, 0, 50) at 4 is -50/8 = -6.25, beyond 2T;
//  - 8 pixels: samples 0, 2, 4, 8 and the check 6 all 0: sent; next at 8, growing to 16 at most;
//  - at 8, 8 pixels: the quadratic through 8, 12, 16 (0, 50, 50) at 10 is 31.25 against 50: no;
//    4 pixels: through 8, 10, 12 at 9 is 31.25 against 0: no, so 8..11 are exact;
//  - at 12, 4 pixels: all 50, the check 15 too: the cubic is sent. The tail pixel 16 was a sample.
// Points: 0, 2, 4, 6, 8, 9, 10, 11, 12, 13, 14, 15, 16 = 13; no error anywhere.
TEST(EmulateAdaptive, StepByHand) {
    std::vector<double> v(17, 0.0);
    for (int x = 10; x <= 16; ++x) v[x] = 50.0;
    const emulated_run r = emulate_adaptive(grey(v), policy(1.0, 2, 4));
    EXPECT_EQ(r.points, 13u);
    EXPECT_LT(squared_error(r.out, grey(v)), 1e-18);
    // Shorter than the shortest interval: every pixel exact.
    EXPECT_EQ(emulate_adaptive(grey({1, 2, 3, 4}), policy(1.0, 2, 4)).points, 4u);
    EXPECT_EQ(emulate_adaptive({}, policy(1.0, 2, 4)).points, 0u);
    EXPECT_THROW(emulate_adaptive(grey(v), policy(1.0, 1, 4)), std::invalid_argument);
    EXPECT_THROW(emulate_adaptive(grey(v), policy(1.0, 4, 3)), std::invalid_argument);
}

class TwoLineHead : public ::testing::Test {
protected:
    scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 512, 512);
    scene::rasterised r = scene::rasterise(w);
    pipeline::frame_constants k = pipeline::frame_constants_of(w);
    scene::device_config dev = [] {
        scene::device_config d;
        d.device = scene::parse_device("squared");
        return d;
    }();
    pipeline::frame pp = pipeline::per_pixel_frame(r, k, dev);
    std::vector<rgb_levels> colour() const { return levels_of(pp); }
    pipeline::plan_config config(double tol, int above_slack = -1) const {
        pipeline::plan_config c;
        c.length = pipeline::length_policy::adaptive;
        c.degree = pipeline::degree_policy::cubic;
        c.split_at_check = true;
        c.carry_samples = true;
        c.eval = pipeline::evaluator::fd;
        c.m_max = 5;
        c.length_tol = tol;
        c.above_slack = above_slack;
        return c;
    }
};

// The emulation is the planner: on the head at 512, without and with the line-above limit, its points
// are the planner's geometry points to 0.1 % and its NMSE the golden frame's against per-pixel shading
// to 2 % (the planner decides on Q8.8 codes and interpolates in fixed point, the emulation in doubles).
TEST_F(TwoLineHead, EmulationIsThePlanner) {
    const std::vector<rgb_levels> c = colour();
    for (const auto& [tol, above_slack] : {std::pair{1.0, -1}, std::pair{1.6, -1}, std::pair{1.9, 2}}) {
        const pipeline::plan_config cfg = config(tol, above_slack);
        const pipeline::plan p = pipeline::make_plan(r, k, dev, cfg);
        const double nmse =
            pipeline::compare(pipeline::to_image(pipeline::golden_frame(p, k, dev, cfg)), pipeline::to_image(pp)).nmse;
        const emulated_frame f = emulate_lines(r, c, cfg, {tol});
        EXPECT_EQ(f.pixels(), p.pixels) << tol;
        EXPECT_NEAR(double(f.points()), double(p.geometry_points), 1e-3 * double(p.geometry_points)) << tol;
        EXPECT_NEAR(f.nmse(), nmse, 0.02 * nmse) << tol;
    }
}

// The yardstick too: with perfect decisions (each decision on the true RMS of what is sent) the
// emulation's points are the planner's to 1 % and its NMSE the golden frame's to 3 %, with and
// without the limit (the planner decides on the golden frame's fixed-point pixels against per-pixel
// shading, the emulation on doubles).
TEST_F(TwoLineHead, PerfectDecisionsAsThePlannersAre) {
    const std::vector<rgb_levels> c = colour();
    for (const auto& [tol, above_slack] : {std::pair{0.7, -1}, std::pair{1.5, 2}}) {
        const pipeline::plan_config cfg = config(tol, above_slack);
        const pipeline::plan p = yardsticks::perfect_decisions_plan(r, k, dev, cfg);
        const double nmse =
            pipeline::compare(pipeline::to_image(pipeline::golden_frame(p, k, dev, cfg)), pipeline::to_image(pp)).nmse;
        const emulated_frame f = emulate_lines(r, c, cfg, {tol}, false, true);
        EXPECT_NEAR(double(f.points()), double(p.geometry_points), 0.01 * double(p.geometry_points)) << tol;
        EXPECT_NEAR(f.nmse(), nmse, 0.03 * nmse) << tol;
        // And they are not the heuristic's: fewer points at this tolerance.
        EXPECT_LT(f.points(), emulate_lines(r, c, cfg, {tol}).points()) << tol;
    }
}

// Counted as the planner counts a plan: the one-line emulation's long operations (its points stepped
// line by line, a colour at each) are the planner's hardware_ops to 1 % on the same frame, with and
// without the limit and the walked edges (the planner forms a colour per sample and check point
// with the carry, the emulation one per point; the points agree to 0.1 %, above).
TEST_F(TwoLineHead, CountedAsThePlannerCounts) {
    const std::vector<rgb_levels> c = colour();
    for (bool walk : {false, true})
        for (const auto& [tol, above_slack] : {std::pair{1.6, -1}, std::pair{1.9, 2}}) {
            pipeline::plan_config cfg = config(tol, above_slack);
            cfg.walk_edges = walk;
            const pipeline::plan p = pipeline::make_plan(r, k, dev, cfg);
            const double planner = double(pipeline::hardware_ops(p, cfg, dev, k.n).total().long_ops());
            const emulated_frame f = emulate_lines(r, c, cfg, {tol});
            const emulated_cost e = emulated_long_ops(r, f, dev, k.n, walk);
            EXPECT_EQ(e.stepping.points, f.points());
            EXPECT_NEAR(e.long_ops(), planner, 0.01 * planner) << tol << (walk ? " walked" : "");
            if (walk) {
                EXPECT_GT(e.stepping.walked_starts, 0u);
            }
        }
}

// The points in the order the lines are rendered (the frame's `lines`), left to right in each.
TEST(EmulatedCost, PointsInTheOrderTheLinesAreRendered) {
    emulated_frame f;
    f.point = {1, 0, 1,   // y = 0
               0, 1, 0,   // y = 1
               1, 1, 0,   // y = 2
               0, 0, 1};  // y = 3
    using pts = std::vector<std::array<unsigned, 2>>;
    f.lines = {0, 1, 2, 3};
    EXPECT_EQ(points_in_order(f, 3), (pts{{0, 0}, {2, 0}, {1, 1}, {0, 2}, {1, 2}, {2, 3}}));
    f.lines = {0, 2, 1, 3};
    EXPECT_EQ(points_in_order(f, 3), (pts{{0, 0}, {2, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 3}}));
    f.lines = {0, 4};
    EXPECT_THROW(points_in_order(f, 3), std::invalid_argument);
}

// The passes' order by hand on 16 lines: one line at a time; two lines; every fourth line first (then
// the lines two apart, then the odd ones); every eighth. Bad tolerance lists are refused.
TEST(EmulateLines, PassesInOrderByHand) {
    const scene::world w = scene::builtin_scene("sphere", SHADING_SOURCE_DIR, 16, 16);
    const scene::rasterised r = scene::rasterise(w);
    const std::vector<rgb_levels> c(r.tri.size(), rgb_levels{10.0, 20.0, 30.0});
    const pipeline::plan_config cfg;
    using lines = std::vector<unsigned>;
    EXPECT_EQ(emulate_lines(r, c, cfg, {1.0}).lines, (lines{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}));
    EXPECT_EQ(emulate_lines(r, c, cfg, {1.0, 1.0}).lines, (lines{0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15}));
    EXPECT_EQ(emulate_lines(r, c, cfg, {1.0, 1.0, 1.0}).lines,
              (lines{0, 4, 8, 12, 2, 6, 10, 14, 1, 3, 5, 7, 9, 11, 13, 15}));
    EXPECT_EQ(emulate_lines(r, c, cfg, {1.0, 1.0, 1.0, 1.0}).lines,
              (lines{0, 8, 4, 12, 2, 6, 10, 14, 1, 3, 5, 7, 9, 11, 13, 15}));
    // A flat colour: every line exact, whatever the passes.
    EXPECT_EQ(emulate_lines(r, c, cfg, {1.0, 1.0, 1.0}).nmse(), 0.0);
    EXPECT_THROW(emulate_lines(r, c, cfg, {}), std::invalid_argument);
    EXPECT_THROW(emulate_lines(r, c, cfg, {1, 1, 1, 1, 1, 1}), std::invalid_argument);
    EXPECT_THROW(emulate_lines(r, std::vector<rgb_levels>(3), cfg, {1.0}), std::invalid_argument);
}

// Points of a frame on the lines where `keep` holds, and its squared error and covered pixels there.
struct line_tally {
    std::size_t points = 0, pixels = 0;
    double se = 0.0;
};
template <class Keep>
line_tally tally(const scene::rasterised& r, const emulated_frame& f, const std::vector<rgb_levels>& c, Keep keep) {
    line_tally t;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            const std::size_t i = r.index(x, y);
            if (r.tri[i] < 0 || !keep(y)) continue;
            ++t.pixels;
            t.points += f.point[i];
            for (int ch = 0; ch < 3; ++ch) t.se += (f.out[i][ch] - c[i][ch]) * (f.out[i][ch] - c[i][ch]);
        }
    return t;
}

// A frame's bookkeeping recomputed from its pixels: the points, pixels and squared error of the first
// pass's lines (first(y)) and of the rest; and most of the rest predicted.
template <class First>
void expect_bookkeeping(const scene::rasterised& r, const emulated_frame& f, const std::vector<rgb_levels>& c,
                        First first) {
    const line_tally a = tally(r, f, c, first), b = tally(r, f, c, [&](unsigned y) { return !first(y); });
    EXPECT_EQ(f.points_first, a.points);
    EXPECT_EQ(f.points_rest, b.points);
    EXPECT_EQ(f.pixels_first, a.pixels);
    EXPECT_EQ(f.pixels_rest, b.pixels);
    EXPECT_NEAR(f.se_first, a.se, 1e-9 * a.se);
    EXPECT_NEAR(f.se_rest, b.se, 1e-9 * b.se);
    EXPECT_GT(f.pixels_predicted, 9 * f.pixels_rest / 10);
}

// Two lines: the even lines are exactly the one-line emulation's (nothing of the odd lines reaches
// them); the parts of the error, the points and the pixels recomputed from the frame; most odd pixels
// predicted; and the prediction pays: fewer points on the odd lines than on the even ones at the same
// tolerance.
TEST_F(TwoLineHead, EvenLinesFirstThenTheOddOnesPredicted) {
    const std::vector<rgb_levels> c = colour();
    const pipeline::plan_config cfg = config(1.2);
    const emulated_frame one = emulate_lines(r, c, cfg, {1.2});
    const emulated_frame two = emulate_lines(r, c, cfg, {1.2, 1.2});
    for (unsigned y = 0; y < r.height; y += 2)
        for (unsigned x = 0; x < r.width; ++x)
            for (int ch = 0; ch < 3; ++ch) ASSERT_EQ(two.out[r.index(x, y)][ch], one.out[r.index(x, y)][ch]) << x << "," << y;
    auto even = [](unsigned y) { return y % 2 == 0; };
    expect_bookkeeping(r, two, c, even);
    EXPECT_EQ(two.points_first, tally(r, one, c, even).points);
    // With the even lines exact, they are the colours, each pixel a point, and no error is theirs.
    const emulated_frame best = emulate_lines(r, c, cfg, {1.2, 1.2}, true);
    EXPECT_EQ(best.points_first, two.pixels_first);
    EXPECT_EQ(best.se_first, 0.0);
    EXPECT_EQ(best.pixels_rest, two.pixels_rest);
    EXPECT_LT(double(two.points_rest) / double(two.pixels_rest), 0.75 * double(two.points_first) / double(two.pixels_first));
}

// Every fourth line first: without the line-above limit a line's plan depends on no other line, so
// the lines 0 mod 4 are the one-line emulation's bit for bit; the rest's points, pixels and error
// recomputed from the frame; most of them predicted; and the image within 1e-5 at the tolerances the
// study finds cheapest (1, 0.8, 1.1), with fewer points than one line at a time there.
TEST_F(TwoLineHead, FourthLinesFirstThenTheRestPredicted) {
    const std::vector<rgb_levels> c = colour();
    const pipeline::plan_config cfg = config(1.0);
    const emulated_frame one = emulate_lines(r, c, cfg, {1.0});
    const emulated_frame four = emulate_lines(r, c, cfg, {1.0, 0.8, 1.1});
    for (unsigned y = 0; y < r.height; y += 4)
        for (unsigned x = 0; x < r.width; ++x)
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_EQ(four.out[r.index(x, y)][ch], one.out[r.index(x, y)][ch]) << x << "," << y;
    expect_bookkeeping(r, four, c, [](unsigned y) { return y % 4 == 0; });
    EXPECT_LE(four.nmse(), 1e-5);
    EXPECT_LT(four.points(), one.points());
}

}  // namespace
