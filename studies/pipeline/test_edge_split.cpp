// The edge study's pieces (edge_split.h) against hand-worked segments: which rule reproduces which
// polynomial, the quadratic's error on a cubic worked out by hand, the points counted, the gaps
// classified by their triangles.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "edge_split.h"
#include "levels_testing.h"

namespace {

using namespace shading::study;

std::vector<rgb_levels> grey(const std::vector<double>& v) {
    std::vector<rgb_levels> out;
    for (double x : v) out.push_back({x, 2.0 * x, 0.0});
    return out;
}
std::vector<double> of(std::size_t len, double (*f)(double)) {
    std::vector<double> v;
    for (std::size_t i = 0; i < len; ++i) v.push_back(f(double(i)));
    return v;
}
using test_helpers::squared_error;

// (i - 3)^2 over 9 pixels, h = 2: samples at 0, 2, 4, 6, 8 (5 points, no tail). The quadratic pairs
// and the cubic reproduce it; the linear rule misses each odd pixel by 1 (the parabola's midpoint
// gap: ((a)^2 + (a + 2)^2) / 2 - (a + 1)^2 = 1): 4 pixels x (1 + 2^2) over the two lit channels.
TEST(EdgeSplit, ParabolaByHand) {
    const auto v = grey(of(9, [](double x) { return (x - 3.0) * (x - 3.0); }));
    std::size_t pts = 0;
    EXPECT_NEAR(squared_error(reconstruct(v, 2, reconstruction::quadratic, &pts), v), 0.0, 1e-18);
    EXPECT_EQ(pts, 5u);
    EXPECT_NEAR(squared_error(reconstruct(v, 2, reconstruction::cubic, &pts), v), 0.0, 1e-18);
    EXPECT_NEAR(squared_error(reconstruct(v, 2, reconstruction::linear, &pts), v), 4.0 * (1.0 + 4.0), 1e-12);
}

// x^3 over 13 pixels, h = 4: samples at 0, 4, 8, 12. The cubic through all four reproduces it. The
// quadratic through 0, 4, 8 misses by x (x - 4)(x - 8) (x^3's third derivative over 3!), the last
// single gap's (through 4, 8, 12) by (x - 4)(x - 8)(x - 12): at 1..3 and 5..7: 21, 24, 15, 15, 24,
// 21; at 9..11: 15, 24, 21. Sum of squares 3 726, times (1 + 2^2) for the two lit channels.
TEST(EdgeSplit, CubicByHand) {
    const auto v = grey(of(13, [](double x) { return x * x * x; }));
    std::size_t pts = 0;
    EXPECT_NEAR(squared_error(reconstruct(v, 4, reconstruction::cubic, &pts), v), 0.0, 1e-12);
    EXPECT_EQ(pts, 4u);
    const auto q = reconstruct(v, 4, reconstruction::quadratic, &pts);
    EXPECT_NEAR(q[1][0], 1.0 - 21.0, 1e-9);   // x(x-4)(x-8) at 1 is 21: the quadratic lies below
    EXPECT_NEAR(q[10][0], 1000.0 + 24.0, 1e-9);  // (x-4)(x-8)(x-12) at 10 is -24: above
    EXPECT_NEAR(squared_error(q, v), 3726.0 * 5.0, 1e-6);
}

// The tail: 11 pixels, h = 4: samples at 0, 4, 8; pixels 9 and 10 exact (2 points more); the
// reconstruction leaves them as they are, whatever the rule.
TEST(EdgeSplit, TailPixelsAreExactPoints) {
    const auto v = grey(of(11, [](double x) { return x * x * x * x; }));
    for (reconstruction k : {reconstruction::linear, reconstruction::quadratic, reconstruction::cubic}) {
        std::size_t pts = 0;
        const auto r = reconstruct(v, 4, k, &pts);
        EXPECT_EQ(pts, 5u) << reconstruction_name(k);
        EXPECT_EQ(r[9], v[9]);
        EXPECT_EQ(r[10], v[10]);
        EXPECT_EQ(r[8], v[8]);
        EXPECT_NE(r[6], v[6]) << reconstruction_name(k);  // x^4 is no cubic
    }
    // A segment shorter than one gap is all exact pixels.
    std::size_t pts = 0;
    EXPECT_EQ(reconstruct(grey({1.0, 5.0, 2.0}), 4, reconstruction::cubic, &pts), grey({1.0, 5.0, 2.0}));
    EXPECT_EQ(pts, 3u);
}

// Gaps by triangle, h = 4, 9 pixels on triangles 0 0 0 0 0 1 1 1 1: gap 0 (pixels 0..3, its closing
// sample 4 on triangle 0) within; gap 1 (4..7, closing sample 8 on 1) crossing; pixel 8, the last
// sample, exact. A kink |x - 4.5| puts the linear rule's whole error in gap 1.
TEST(EdgeSplit, ChunksByTriangle) {
    const auto v = grey(of(9, [](double x) { return x < 4.5 ? 4.5 - x : x - 4.5; }));
    const std::vector<int32_t> tri{0, 0, 0, 0, 0, 1, 1, 1, 1};
    const edge_split s = split_errors(v, tri, 4, reconstruction::linear);
    EXPECT_EQ(s.pixels_within, 4u);
    EXPECT_EQ(s.pixels_crossing, 4u);
    EXPECT_EQ(s.pixels_exact, 1u);
    EXPECT_EQ(s.points, 3u);
    EXPECT_EQ(s.se_within, 0.0);
    // Linear from 0.5 (at 4) to 3.5 (at 8): 0.5 + 0.75 i against |i - 0.5| at i = 1..3: 1.25 - 0.5,
    // 2 - 1.5, 2.75 - 2.5 = 0.75, 0.5, 0.25 (pixel 4 is the sample).
    EXPECT_NEAR(s.se_crossing, (0.75 * 0.75 + 0.5 * 0.5 + 0.25 * 0.25) * 5.0, 1e-12);
    double ref2 = 0.0;
    for (const auto& c : v) ref2 += c[0] * c[0] + c[1] * c[1];
    EXPECT_NEAR(s.ref2, ref2, 1e-12);
    // Summed as the study sums segments: every count and sum adds.
    edge_split two = s;
    two += s;
    EXPECT_EQ(two.pixels(), 18u);
    EXPECT_EQ(two.pixels_exact, 2u);
    EXPECT_EQ(two.points, 6u);
    EXPECT_DOUBLE_EQ(two.se_crossing, 2.0 * s.se_crossing);
    EXPECT_DOUBLE_EQ(two.ref2, 2.0 * s.ref2);
    EXPECT_THROW(split_errors(v, {0, 1}, 4, reconstruction::linear), std::invalid_argument);
    EXPECT_THROW(reconstruct(v, 0, reconstruction::linear, nullptr), std::invalid_argument);
}

// A kink worked by hand: v(x) = x up to e = 2.5, then slope 3 (a jump of 2), 9 pixels, h = 4.
// Samples 0, 7, 19 (v(4) = 2.5 + 3 * 1.5, v(8) = 2.5 + 3 * 5.5). The linear rule's first gap reads
// 1.75, 3.5, 5.25 at pixels 1..3 against 1, 2, 4: errors 0.75, 1.5, 1.25; its second gap is exact.
// Taken out first, the kink leaves a straight line: no error anywhere.
TEST(EdgeSplit, RampedReconstructionTakesOutAKnownKink) {
    const auto v = grey(of(9, [](double x) { return x <= 2.5 ? x : 2.5 + 3.0 * (x - 2.5); }));
    const std::vector<int32_t> tri{0, 0, 0, 1, 1, 1, 1, 1, 1};
    const edge_split plain = split_errors(v, tri, 4, reconstruction::linear);
    EXPECT_NEAR(plain.se_crossing, (0.75 * 0.75 + 1.5 * 1.5 + 1.25 * 1.25) * 5.0, 1e-12);
    EXPECT_EQ(plain.se_within, 0.0);
    const std::vector<slope_jump> jumps{{2.5, {2.0, 4.0, 0.0}}};
    std::size_t points = 0;
    EXPECT_LT(squared_error(reconstruct_ramped(v, jumps, 4, reconstruction::linear, &points), v), 1e-24);
    EXPECT_EQ(points, 3u);
    const edge_split ramped = split_errors(v, tri, 4, reconstruction::linear, {}, &jumps);
    EXPECT_LT(ramped.se_crossing, 1e-24);
    EXPECT_EQ(ramped.pixels_crossing, 4u);
    // A jump of the wrong size leaves its own ramp's error: half the jump, the same gap.
    const std::vector<slope_jump> half{{2.5, {1.0, 2.0, 0.0}}};
    EXPECT_NEAR(split_errors(v, tri, 4, reconstruction::linear, {}, &half).se_crossing, plain.se_crossing / 4.0,
                1e-12);
}

// Gaps past a vertex are the crossing gaps with a vertex pass at one of their pixels after the
// first, up to the closing sample: 13 pixels, h = 4, triangles change at 3 (an edge), 6 (a vertex)
// and 12 (a vertex, the closing sample of gap 2).
TEST(EdgeSplit, GapsPastAVertex) {
    const auto v = grey(of(13, [](double x) { return x * x; }));
    const std::vector<int32_t> tri{0, 0, 0, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3};
    std::vector<uint8_t> pass(13, 0);
    pass[6] = pass[12] = 1;
    const edge_split s = split_errors(v, tri, 4, reconstruction::linear, pass);
    EXPECT_EQ(s.pixels_within, 0u);
    EXPECT_EQ(s.pixels_crossing, 12u);
    EXPECT_EQ(s.pixels_past_vertex, 8u);  // gaps 1 (pixels 4..7) and 2 (8..11)
    // x^2 by a chord over [a, a + 4]: error (x - a)(a + 4 - x) at 1, 2, 3 = 3, 4, 3 in every gap.
    const double gap = (9.0 + 16.0 + 9.0) * 5.0;
    EXPECT_NEAR(s.se_crossing, 3.0 * gap, 1e-9);
    EXPECT_NEAR(s.se_past_vertex, 2.0 * gap, 1e-9);
    edge_split two = s;
    two += s;
    EXPECT_EQ(two.pixels_past_vertex, 16u);
    EXPECT_DOUBLE_EQ(two.se_past_vertex, 2.0 * s.se_past_vertex);
    EXPECT_THROW(split_errors(v, tri, 4, reconstruction::linear, std::vector<uint8_t>(3, 0)), std::invalid_argument);
}

// Every other line or column from the two beside it, on a 3 x 3 grid by hand (every channel alike):
//   10 20 30      triangles  1 0 0      triangle 1 is no patch with 0; (2, 2) is uncovered
//   12 26 42                 0 0 0
//   10 30  *                 0 0 -1
// Across the lines only (1, 1) is rebuilt: (20 + 30) / 2 - 26 = -1; (0, 1) sits under triangle 1 and
// (2, 1) over the uncovered pixel. Along the lines only (1, 1): (12 + 42) / 2 - 26 = 1; (1, 0) is
// beside triangle 1, (1, 2) beside the uncovered pixel. ref2: the eight covered values squared, 4 984.
TEST(EdgeSplit, MidpointsFromTheNeighboursByHand) {
    const std::vector<double> g{10, 20, 30, 12, 26, 42, 10, 30, 0};
    std::vector<rgb_levels> colour;
    for (double x : g) colour.push_back({x, x, x});
    const std::vector<int32_t> tri{1, 0, 0, 0, 0, 0, 0, 0, -1};
    const auto patch = [](int32_t a, int32_t b) { return a == b; };
    for (bool across : {true, false}) {
        const midpoint_error m = midpoint_errors(colour, tri, 3, 3, across, patch);
        EXPECT_EQ(m.pixels, 1u) << across;
        EXPECT_DOUBLE_EQ(m.se, 3.0) << across;
        EXPECT_DOUBLE_EQ(m.ref2, 3.0 * 4984.0) << across;
    }
    // Every triangle one patch: across the lines (0, 1) joins, (10 + 10) / 2 - 12 = -2.
    const midpoint_error all = midpoint_errors(colour, tri, 3, 3, true, [](int32_t, int32_t) { return true; });
    EXPECT_EQ(all.pixels, 2u);
    EXPECT_DOUBLE_EQ(all.se, 3.0 + 12.0);
    EXPECT_THROW(midpoint_errors(colour, tri, 3, 2, true, patch), std::invalid_argument);
}

// A line predicted from the lines either side, on a 5 x 3 grid by hand: above x^2 + 1, below x^2 - 1,
// the line x^2 + 2 x. The mean of the two is x^2, so the residual 2 x is a straight line: two samples
// (0 and 4, h = 4) rebuild it exactly. Directly the chord 6 x misses x^2 + 2 x by x^2 - 4 x = -3, -4,
// -3 at 1, 2, 3: 34 a channel. ref2: every pixel squared, 419 + 299 + 874 a channel. A triangle of
// another patch at (2, 1) splits the run into two of two pixels, each a sample and an exact pixel.
TEST(EdgeSplit, LinePredictedFromTheLinesEitherSideByHand) {
    std::vector<rgb_levels> colour(15);
    for (int x = 0; x < 5; ++x) {
        const double q = double(x * x);
        colour[x] = {q + 1, q + 1, q + 1};
        colour[5 + x] = {q + 2 * x, q + 2 * x, q + 2 * x};
        colour[10 + x] = {q - 1, q - 1, q - 1};
    }
    std::vector<int32_t> tri(15, 0);
    const auto patch = [](int32_t a, int32_t b) { return a == b; };
    const predicted_lines p = odd_lines_predicted(colour, tri, 5, 3, 4, reconstruction::linear, patch);
    EXPECT_EQ(p.pixels, 5u);
    EXPECT_EQ(p.points, 2u);
    EXPECT_NEAR(p.se_direct, 3.0 * 34.0, 1e-9);
    EXPECT_NEAR(p.se_predicted, 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(p.ref2, 3.0 * (419.0 + 299.0 + 874.0));
    tri[7] = 1;
    const predicted_lines split = odd_lines_predicted(colour, tri, 5, 3, 4, reconstruction::linear, patch);
    EXPECT_EQ(split.pixels, 4u);
    EXPECT_EQ(split.points, 4u);
    EXPECT_DOUBLE_EQ(split.se_direct, 0.0);
    EXPECT_DOUBLE_EQ(split.se_predicted, 0.0);
    EXPECT_THROW(odd_lines_predicted(colour, tri, 5, 2, 4, reconstruction::linear, patch), std::invalid_argument);
}

}  // namespace
