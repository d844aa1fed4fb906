// The two counted Phong baselines (src/scene): per-pixel geometry from scratch (geometry_at) and the
// scan-line one that steps the interpolated attributes along the span (scanline.h: span_stepper),
// their operation counts against hand counts on small cases (a 4-pixel span, a single triangle) and
// their images against each other. No simulation: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "scene/raster.h"
#include "scene/scanline.h"
#include "scene/scene.h"
#include "scene/shade.h"
#include "tiny_scenes.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_scanline {

using namespace shading::scene;
using shading::scene::tiny::counts;
using shading::scene::tiny::one_triangle;

namespace {

void expect_same_geometry(const pixel_geometry& a, const pixel_geometry& b) {
    EXPECT_NEAR(a.n.x.value(), b.n.x.value(), 1e-13);
    EXPECT_NEAR(a.n.y.value(), b.n.y.value(), 1e-13);
    EXPECT_NEAR(a.n.z.value(), b.n.z.value(), 1e-13);
    EXPECT_NEAR(a.h[0].x.value(), b.h[0].x.value(), 1e-13);
    EXPECT_NEAR(a.h[0].y.value(), b.h[0].y.value(), 1e-13);
    EXPECT_NEAR(a.h[0].z.value(), b.h[0].z.value(), 1e-13);
    EXPECT_NEAR(a.p.x.value(), b.p.x.value(), 1e-12);
    EXPECT_NEAR(a.p.z.value(), b.p.z.value(), 1e-12);
}

// The stepper's geometry at points xs of line y, each checked against geometry_at; its counts.
op_counts step_through(span_stepper& st, const rasterised& r, unsigned y, std::initializer_list<unsigned> xs) {
    op_counts ops;
    for (unsigned x : xs) expect_same_geometry(st.at(x, y, &ops), geometry_at(r, x, y, nullptr));
    return ops;
}

// Two images of one frame: NMSE of a against b and the largest difference (levels).
struct image_difference {
    double nmse = 0.0, worst = 0.0;
};
image_difference difference(const shaded_image& a, const shaded_image& b) {
    double d2 = 0.0, r2 = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < a.value.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = a.value[i][c] - b.value[i][c];
            d2 += d * d;
            r2 += b.value[i][c] * b.value[i][c];
            worst = std::max(worst, std::abs(d));
        }
    return {r2 > 0.0 ? d2 / r2 : 1.0, worst};  // an all-black reference fails every test below
}

}  // namespace

// The 4-pixel span (line 3, x = 0..3), orthographic camera, directional light: no position needed,
// so only U_N = sum g_i N_i is stepped (3 components).
//   scan-line: set-up 3 components x 3 coefficients x (3 mul, 2 add) = 27 mul, 18 add;
//              run start at x = 0: 3 x (2 mul, 2 add) = 6 mul, 6 add;  3 steps x 3 adds = 9 add;
//              per pixel: normalise N (dot 3 mul 2 add, sqrt, 1/len div, 3 mul) = 6 mul, 2 add, 1 sqrt,
//              1 div; V constant; H = L + V (3 add) normalised (6 mul, 2 add, 1 sqrt, 1 div)
//              = 12 mul, 7 add, 2 sqrt, 2 div a pixel.
//              Total: mul 27 + 6 + 4 x 12 = 81, add 18 + 6 + 9 + 4 x 7 = 61, sqrt 8, div 8 (97 long).
//   from scratch, per pixel: g_i = a x + b y + c (3 x (2 mul, 2 add)), sum (2 add), 1/sum (div),
//              b_i (3 mul), N = sum b_i N_i (9 mul, 6 add), normalise N, H as above:
//              mul 6 + 3 + 9 + 6 + 6 = 30, add 6 + 2 + 6 + 2 + 3 + 2 = 21, div 3, sqrt 2 (35 long).
//              Four pixels: mul 120, add 84, div 12, sqrt 8 (140 long).
TEST(ScanlinePhong, FourPixelSpanCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    for (unsigned x = 0; x < 4; ++x) ASSERT_TRUE(r.covered(x, 3)) << x;
    ASSERT_FALSE(r.covered(4, 3));
    span_stepper st(r);
    op_counts stepped, scratch;
    for (unsigned x = 0; x < 4; ++x) {
        const pixel_geometry a = st.at(x, 3, &stepped);
        const pixel_geometry b = geometry_at(r, x, 3, &scratch);
        expect_same_geometry(a, b);
    }
    EXPECT_EQ(stepped, counts(81, 8, 8, 61)) << stepped;
    EXPECT_EQ(scratch, counts(120, 12, 8, 84)) << scratch;
    EXPECT_EQ(st.stats().triangle_setups, 1u);
    EXPECT_EQ(st.stats().run_starts, 1u);
    EXPECT_EQ(st.stats().steps, 3u);
}

// The same span through a perspective camera (z = 5, 60 degrees): the position is needed for V, so
// U_N, U_P (3 components each) and Q = 1/w are stepped.
//   scan-line: set-up U_N 27 mul 18 add, U_P 27 mul 18 add, Q 3 coefficients x 2 add = 6 add;
//              run start 7 x (2 mul, 2 add) = 14 mul, 14 add; 3 steps x 7 add = 21 add;
//              per pixel: normalise N (6 mul, 2 add, sqrt, div); V = Q eye - U_P (3 mul, 3 add: no
//              P = U_P / Q) normalised (6 mul, 2 add, sqrt, div); H (3 add; 6 mul, 2 add, sqrt,
//              div) = 21 mul, 12 add, 3 sqrt, 3 div a pixel.
//              Total: mul 54 + 14 + 84 = 152, add 42 + 14 + 21 + 48 = 125, sqrt 12, div 12 (176 long).
//   from scratch, per pixel (test_scene's GeometryCountsHandCounted): mul 6 + 3 + 9 + 6 + 9 + 6 + 6 = 45,
//              add 6 + 2 + 6 + 2 + 6 + 3 + 2 + 3 + 2 = 32, div 4, sqrt 3 (52 long); four: 180, 128, 16, 12.
TEST(ScanlinePhong, PerspectiveSpanCountedByHand) {
    const world s = one_triangle(true);
    const rasterised r = rasterise(s);
    // Four covered pixels of one line on the triangle, found from the rasteriser.
    unsigned y = 0, x0 = 0;
    bool found = false;
    for (y = 0; y < 8 && !found; ++y)
        for (x0 = 0; x0 + 4 <= 8 && !found; ++x0)
            found = r.covered(x0, y) && r.covered(x0 + 1, y) && r.covered(x0 + 2, y) && r.covered(x0 + 3, y);
    ASSERT_TRUE(found);
    --y;
    --x0;
    span_stepper st(r);
    op_counts stepped, scratch;
    for (unsigned x = x0; x < x0 + 4; ++x) {
        const pixel_geometry a = st.at(x, y, &stepped);
        const pixel_geometry b = geometry_at(r, x, y, &scratch);
        expect_same_geometry(a, b);
    }
    EXPECT_EQ(stepped, counts(152, 12, 12, 125)) << stepped;
    EXPECT_EQ(scratch, counts(180, 16, 12, 128)) << scratch;
}

// Steps longer than one pixel (a sparse geometry side): + d a is a shift for d = 2^k (1 add per
// component) and a shift-and-add otherwise (popcount(d) adds). Orthographic span of line 0, x = 0..6:
// points 0, 4, 6 (steps 4 and 2: 1 add each per component) and then a new run at 1 (left: run start).
//   set-up 27 mul 18 add; run starts at 0 and 1: 2 x (6 mul, 6 add); steps 2 x 3 add; per point 12 mul,
//   7 add, 2 sqrt, 2 div x 4 points. mul 27 + 12 + 48 = 87, add 18 + 12 + 6 + 28 = 64, sqrt 8, div 8.
// Then 0 -> 3 on line 1 (x = 0..5): a run start, then d = 3 (2 adds per component):
//   6 mul 6 add + 6 add + 2 x (12 mul, 7 add, 2 sqrt, 2 div): mul 30, add 26, sqrt 4, div 4.
TEST(ScanlinePhong, SparseStepsCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    span_stepper st(r);
    EXPECT_EQ(step_through(st, r, 0, {0, 4, 6, 1}), counts(87, 8, 8, 64));
    EXPECT_EQ(step_through(st, r, 1, {0, 3}), counts(30, 4, 4, 26));
    EXPECT_EQ(st.stats().triangle_setups, 1u);
}

// Points read down a column (the cells' column runs): column 0 holds lines 0..6. Lines 0, 1, 3, 4
// with `down`: set-up 27 mul 18 add, a run start at line 0 (6 mul 6 add), then steps of 1, 2 and 1
// lines (+ d b: one add per component each, d = 2 a shift), 4 points x (12 mul, 7 add, 2 sqrt, 2 div):
// mul 27 + 6 + 48 = 81, add 18 + 6 + 9 + 28 = 61, as the 4-pixel span across. Line 2 after them lies
// above: a run start (18 mul, 13 add). Without `down` each of lines 1, 3, 4 is a run start too.
TEST(ScanlinePhong, DownAColumnCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    auto column = [&r](span_stepper& st, std::initializer_list<unsigned> ys, bool down) {
        op_counts ops;
        for (unsigned y : ys) expect_same_geometry(st.at(0, y, &ops, down), geometry_at(r, 0, y, nullptr));
        return ops;
    };
    span_stepper st(r);
    EXPECT_EQ(column(st, {0, 1, 3, 4}, true), counts(81, 8, 8, 61));
    EXPECT_EQ(column(st, {2}, true), counts(18, 2, 2, 13));
    EXPECT_EQ(st.stats().steps, 3u);
    EXPECT_EQ(st.stats().run_starts, 2u);
    span_stepper across(r);
    EXPECT_EQ(column(across, {0, 1, 3, 4}, false), counts(81 + 18, 8, 8, 61 - 9 + 18));
    EXPECT_EQ(across.stats().run_starts, 4u);
}

// The whole single triangle through both references (28 pixels, 7 runs, 21 steps):
//   scan-line geometry: mul 27 + 7 x 6 + 28 x 12 = 405, add 18 + 7 x 6 + 21 x 3 + 28 x 7 = 319,
//                       sqrt 56, div 56 (517 long, 18.46 a pixel);
//   from scratch: 28 x (30 mul, 21 add, 3 div, 2 sqrt) = 840 mul, 588 add, 84 div, 56 sqrt (980 long).
// Shading is the same code for both, so equal counts; the images agree to rounding.
TEST(ScanlinePhong, SingleTriangleFrameCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    ASSERT_EQ(r.covered_pixels(), 28u);
    render_stats a, b;
    stepping_stats steps;
    const shaded_image ia = render_phong_scanline(r, &a, &steps);
    const shaded_image ib = render_phong(r, &b);
    EXPECT_EQ(steps.triangle_setups, 1u);
    EXPECT_EQ(steps.run_starts, 7u);
    EXPECT_EQ(steps.steps, 21u);
    EXPECT_EQ(a.geometry, counts(405, 56, 56, 319)) << a.geometry;
    EXPECT_EQ(b.geometry, counts(840, 84, 56, 588)) << b.geometry;
    EXPECT_EQ(a.shading, b.shading);
    EXPECT_EQ(a.pixels, 28u);
    EXPECT_LT(difference(ia, ib).worst, 1e-10);
}

// On the head (perspective, thousands of triangles and occlusions) the scan-line image equals the
// per-pixel one to rounding, and the counts split as the hand counts above say. (Whether stepping
// pays depends on the pixels per triangle: at 128 x 128 the head's set-ups cost more than they save;
// at 512 the scan-line Phong costs 51.4 long operations a pixel against 68.1, render_pipeline's report.)
TEST(ScanlinePhong, HeadImageEqualsPerPixelPhong) {
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 128, 128);
    const rasterised r = rasterise(s);
    render_stats a, b;
    stepping_stats steps;
    const shaded_image ia = render_phong_scanline(r, &a, &steps);
    const shaded_image ib = render_phong(r, &b);
    const image_difference d = difference(ia, ib);
    EXPECT_LT(d.nmse, 1e-20) << d.nmse;
    std::printf("scan-line Phong against per-pixel Phong: NMSE %.3g, largest difference %.3g levels\n", d.nmse, d.worst);
    EXPECT_LT(d.worst, 1e-8);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(steps.points, a.pixels);
    EXPECT_EQ(steps.run_starts + steps.steps, steps.points);
    // Perspective camera, one directional light: per triangle set-up 2 x 27 mul, per run start
    // 7 x 2 mul, per pixel 3 mul (Q eye) and three normalisations of 8 long operations each.
    EXPECT_EQ(a.geometry.long_ops(), 54 * steps.triangle_setups + 14 * steps.run_starts + 27 * steps.points);
    // With a reciprocal square root unit each normalisation is 7.
    EXPECT_EQ(a.geometry.long_ops_rsqrt(), 54 * steps.triangle_setups + 14 * steps.run_starts + 24 * steps.points);
    EXPECT_EQ(b.geometry.long_ops(), 52 * b.pixels);
}

// ---- Edge walking (span_stepper with walk_edges) ----

// Sparse points in raster order with the triangle's values walked from its last point instead of a
// new a x + b y + c. Line 0: points 0, 4, 6:
//   set-up 27 mul 18 add; run start at 0: 6 mul 6 add; steps 2 x 3 add; per point 12 mul, 7 add,
//   2 sqrt, 2 div x 3. mul 27 + 6 + 36 = 69, add 18 + 6 + 6 + 21 = 51, sqrt 6, div 6.
// Line 1: 0 is walked from (6, 0) (one line down: 1 add; x - x' = -6: popcount 2 adds), then d = 3
// (2 adds): 3 x (3 + 2) add + 2 x (12 mul, 7 add, 2 sqrt, 2 div): mul 24, add 29, sqrt 4, div 4.
// Line 4 (x = 0..2): 0 walked from (3, 1), three lines down (3 adds) and x - x' = -3 (2 adds):
//   3 x 5 add + 12 mul, 7 add, 2 sqrt, 2 div: mul 12, add 22, sqrt 2, div 2.
// Then point 0 of line 2, behind (0, 4) in raster order: from there on the walker jumps, each of
// (y - y') b and (x - x') a a multiplication by a small integer and an add per component:
//   3 x (2 mul, 2 add) + 12 mul, 7 add, 2 sqrt, 2 div: mul 18, add 13.
TEST(ScanlineEdgeWalk, SparseStepsCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    span_stepper st(r, true);
    EXPECT_EQ(step_through(st, r, 0, {0, 4, 6}), counts(69, 6, 6, 51));
    EXPECT_EQ(step_through(st, r, 1, {0, 3}), counts(24, 4, 4, 29));
    EXPECT_EQ(step_through(st, r, 4, {0}), counts(12, 2, 2, 22));
    EXPECT_EQ(step_through(st, r, 2, {1}), counts(18, 2, 2, 13));
    EXPECT_EQ(st.stats().triangle_setups, 1u);
    EXPECT_EQ(st.stats().run_starts, 4u);
    EXPECT_EQ(st.stats().walked_starts, 3u);
}

// Lines not rendered top to bottom (a scheme that renders the even lines first, then the odd ones)
// leave raster order, so the walker jumps: line 2's point 0 is a run start (6 mul, 6 add); line 1's
// point 0 is walked one line up from it ((y - y') b: 1 mul, 1 add per component); line 0's point 2
// one line up and two pixels right (2 mul, 2 add per component). Each point 12 mul, 7 add, 2 sqrt,
// 2 div; the values are geometry_at's (step_through).
TEST(ScanlineEdgeWalk, UpwardsCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    span_stepper st(r, true);
    EXPECT_EQ(step_through(st, r, 2, {0}), counts(27 + 6 + 12, 2, 2, 18 + 6 + 7));
    EXPECT_EQ(step_through(st, r, 1, {0}), counts(3 + 12, 2, 2, 3 + 7));
    EXPECT_EQ(step_through(st, r, 0, {2}), counts(6 + 12, 2, 2, 6 + 7));
    EXPECT_EQ(st.stats().run_starts, 3u);
    EXPECT_EQ(st.stats().walked_starts, 2u);
}

// The whole single triangle with edges walked: only line 0's run start is evaluated (6 mul 6 add);
// line y + 1's start x = 0 is walked from line y's last pixel x = 6 - y: one add down and
// popcount(6 - y) across, y = 0..5: 6 + (2 + 2 + 1 + 2 + 1 + 1) = 15 adds per component, 45 in all.
//   mul 405 - 6 x 6 = 369, add 319 - 6 x 6 + 45 = 328, sqrt 56, div 56 (481 long against 517).
TEST(ScanlineEdgeWalk, SingleTriangleFrameCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    render_stats a, b;
    stepping_stats steps;
    const shaded_image ia = render_phong_scanline(r, &a, &steps, true);
    const shaded_image ib = render_phong(r, &b);
    EXPECT_EQ(steps.run_starts, 7u);
    EXPECT_EQ(steps.walked_starts, 6u);
    EXPECT_EQ(a.geometry, counts(369, 56, 56, 328)) << a.geometry;
    EXPECT_EQ(a.shading, b.shading);
    EXPECT_LT(difference(ia, ib).worst, 1e-10);
}

// The transposed frame (a planner's lines run down the columns on it): on the head at 128 x 96
// (perspective, non-square, so a swapped index shows), every pixel's triangle and depth at (y, x),
// and geometry_at there the same values bit for bit: the planes' two products are added in the
// other order, which IEEE addition does not see.
TEST(ScanlineTransposed, HeadGeometryBitForBit) {
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 128, 96);
    const rasterised r = rasterise(s);
    const rasterised t = transposed(r);
    ASSERT_EQ(t.width, 96u);
    ASSERT_EQ(t.height, 128u);
    std::size_t covered = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x) {
            ASSERT_EQ(t.tri[t.index(y, x)], r.tri[r.index(x, y)]);
            ASSERT_EQ(t.depth[t.index(y, x)], r.depth[r.index(x, y)]);
            if (!r.covered(x, y)) continue;
            ++covered;
            const pixel_geometry a = geometry_at(r, x, y, nullptr), b = geometry_at(t, y, x, nullptr);
            auto same = [](const cvec3& u, const cvec3& w) {
                return u.x.value() == w.x.value() && u.y.value() == w.y.value() && u.z.value() == w.z.value();
            };
            ASSERT_TRUE(same(a.n, b.n) && same(a.p, b.p) && same(a.v, b.v) && same(a.h[0], b.h[0])) << x << ", " << y;
        }
    EXPECT_GT(covered, 2000u);
}

// On the head (perspective: U_N, U_P and Q walked) the walked values still give the per-pixel
// image to rounding, and the walked run starts (raster order) cost no long operation: set-ups 54,
// evaluated run starts 14, per pixel 27, as the hand counts above split them.
TEST(ScanlineEdgeWalk, HeadImageEqualsPerPixelPhong) {
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 256, 256);
    const rasterised r = rasterise(s);
    render_stats a, b;
    stepping_stats steps;
    const shaded_image ia = render_phong_scanline(r, &a, &steps, true);
    const shaded_image ib = render_phong(r, &b);
    const image_difference d = difference(ia, ib);
    EXPECT_LT(d.nmse, 1e-20) << d.nmse;
    EXPECT_LT(d.worst, 1e-8);
    EXPECT_GT(steps.walked_starts, steps.triangle_setups);
    EXPECT_EQ(a.geometry.long_ops(),
              54 * steps.triangle_setups + 14 * (steps.run_starts - steps.walked_starts) + 27 * steps.points);
    EXPECT_EQ(steps.run_starts - steps.walked_starts, steps.triangle_setups);  // one evaluated start a triangle
}

}  // namespace test_scanline
