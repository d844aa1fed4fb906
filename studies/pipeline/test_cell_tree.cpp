// The quadtree of biquadratic cells (cell_tree.h): its two estimates worked by hand, a biquadratic
// field sent whole from its lattices, a bump on a lattice point traced to the pixels it spreads to,
// the frame's bookkeeping recomputed from its pixels on the head at 512, its count against the
// two-line study's, and bad configurations refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "scene/scene.h"
#include "cell_tree.h"
#include "testbenches/pipeline/flat_square.h"
#include "line_kinks.h"
#include "study_frame.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_cell_tree {

namespace {

using namespace shading;
using namespace shading::study;

// A biquadratic in x and y (every term x^a y^b with a, b <= 2), in three channels.
std::vector<rgb_levels> biquadratic(unsigned size) {
    std::vector<rgb_levels> c(std::size_t(size) * size);
    for (unsigned y = 0; y < size; ++y)
        for (unsigned x = 0; x < size; ++x) {
            const double q = 100.0 + 0.3 * x - 0.2 * y + 0.01 * x * x - 0.002 * x * y + 0.01 * y * y +
                             2e-7 * x * x * y * y;
            c[std::size_t(y) * size + x] = {q, 0.5 * q, 0.8 * q};
        }
    return c;
}

cell_tree_config config(double tol) {
    cell_tree_config t;
    t.tol = tol;
    return t;
}

}  // namespace

// k3 = max |t (t - 1) (t - 2)| / 6 on [0, 2]: at u = t - 1 = -1/sqrt(3), u (u^2 - 1) = 2 / (3 sqrt(3)),
// so k3 = 1 / (9 sqrt(3)). The second differences of a lattice with 10 levels at its centre (s = 8,
// spacing 4): 0 - 2 x 10 + 0 along the middle row and the middle column, 20. The third differences
// through a family lattice (parent at (0, 0), s = 16, spacing 4) with 6 levels at (12, 4), family
// index (row 1, column 3): for the child at (0, 0) only its row 1 reaches it (points x = 0, 4, 8, 12,
// weight +1): 6 k3; for the child at (8, 0) its row 1 through x = 4, 8, 12, 16 (weight -3) and its
// column x = 12 through y = 0, 4, 8, 12 (weight +3): 18 k3; the children below at (0, 8) and (8, 8)
// read rows 2..4 and columns through y = 4..16 (weight -1 for the child at (8, 8), whose column
// x = 12 starts at y = 4): 0 and 6 k3.
TEST(CellTree, EstimatesByHand) {
    EXPECT_NEAR(k3, 1.0 / (9.0 * std::sqrt(3.0)), 1e-15);
    std::vector<rgb_levels> c(17 * 17, rgb_levels{0.0, 0.0, 0.0});
    c[4 * 17 + 4] = {10.0, 5.0, 0.0};
    EXPECT_DOUBLE_EQ(lattice_second_difference(c, 17, 0, 0, 8), 20.0);
    c[4 * 17 + 4] = {0.0, 0.0, 0.0};
    c[4 * 17 + 12] = {0.0, 6.0, 2.0};
    EXPECT_DOUBLE_EQ(family_third_difference(c, 17, 0, 0, 8, 0, 0), 6.0 * k3);
    EXPECT_DOUBLE_EQ(family_third_difference(c, 17, 8, 0, 8, 0, 0), 18.0 * k3);
    EXPECT_DOUBLE_EQ(family_third_difference(c, 17, 0, 8, 8, 0, 0), 0.0);
    EXPECT_DOUBLE_EQ(family_third_difference(c, 17, 8, 8, 8, 0, 0), 6.0 * k3);
}

// A biquadratic field over 65 x 65 pixels: each 32-pixel tile's lattice (spacing 16) reproduces it,
// its second differences are at most 2 x (0.01 + 2e-7 x 64^2) x 16^2 = 5.5 levels, within 8 T, so
// the four tiles that fit (their closed boxes end at pixel 64) are sent whole: inside [0, 64)^2 the
// only points are the lattice {0, 16, 32, 48}^2. Column 64 and row 64 are no cell's: column 64 (a
// column run of 65 against a row run of 1) by the policy along it (m <= 4), 16-pixel intervals read
// at 0, 4, 8, 16 and checked at 12, and so on: every fourth pixel, 17 points, of which 0, 16, 32, 48,
// 64 are the tiles' lattice points; row 64 (x = 0..63) along it: 0..16, 16..32 and 32..48 the same
// (every fourth pixel), 48..56 (50, 52, 54, 56), 56..60 (57, 58, 59, 60: the shortest cubic and its
// check) and the tail 61, 62, 63 exact, of which 0, 16, 32, 48 were read. Every quadratic and cubic
// reproduces the field: no error.
TEST(CellTree, BiquadraticFieldSentWholeFromItsLattices) {
    const scene::rasterised r = tb::flat_square(65);
    const std::vector<rgb_levels> c = biquadratic(65);
    const cell_frame f = emulate_cells(r, c, pipeline::plan_config{}, config(1.0));
    ASSERT_EQ(f.sent.size(), 4u);  // 4, 8, 16, 32
    EXPECT_EQ(f.sent[3], 4u);
    EXPECT_EQ(f.sent[0] + f.sent[1] + f.sent[2], 0u);
    EXPECT_EQ(f.pixels, 65u * 65u);
    EXPECT_EQ(f.pixels_cells, 64u * 64u);
    EXPECT_EQ(f.pixels_columns, 65u);
    EXPECT_EQ(f.pixels_rows, 64u);
    std::set<std::pair<unsigned, unsigned>> inside;
    for (const auto& p : f.order)
        if (p[0] < 64 && p[1] < 64) inside.insert({p[0], p[1]});
    std::set<std::pair<unsigned, unsigned>> lattice;
    for (unsigned y : {0u, 16u, 32u, 48u})
        for (unsigned x : {0u, 16u, 32u, 48u}) lattice.insert({x, y});
    EXPECT_EQ(inside, lattice);
    // 16 inside, the lattice's 9 on column 64 and row 64 ((64, 64) once: 5 + 4), then the column's 12
    // others and the row's 20 (4, 8, 12, 20, 24, 28, 36, 40, 44, 50, 52, 54, 56, 57, 58, 59, 60, 61, 62, 63).
    EXPECT_EQ(f.points(), 16u + 9u + 12u + 20u);
    EXPECT_EQ(f.points_lines, 12u + 20u);
    EXPECT_LT(f.se, 1e-12);
    EXPECT_GT(f.ref2, 0.0);
}

// The same field with a 100-level bump at (16, 16), a corner of the four 16-pixel children of tile
// (0, 0) and of four 4-pixel cells. Every cell whose lattice or family line holds it is turned down
// and the others are sent exact; the 4-pixel cells at (12, 16) and (16, 16) fall back to row
// quadratics through x = 12, 14, 16 and 16, 18, 20, whose checks at (13, 17), (15, 19), (17, 17) and
// (19, 19) lie on rows without the bump and pass. Row 16 carries it: the quadratic through 0, 2, 4
// weighs the node at 4 by -1/8 at 1 and 3/8 at 3, the node at 0 by 3/8 at 1 and -1/8 at 3, so
// (13, 16) is 12.5 levels low, (15, 16) and (17, 16) 37.5 high, (19, 16) 12.5 low, in every channel;
// nothing else misses. The bump itself is a point, delivered as read. With perfect decisions those
// two cells' RMS (sqrt((37.5^2 + 12.5^2) / 16) = 9.9 levels) is over the fallback's tolerance: exact.
TEST(CellTree, BumpOnALatticePointSpreadsAlongItsRow) {
    const scene::rasterised r = tb::flat_square(65);
    std::vector<rgb_levels> c = biquadratic(65);
    for (int ch = 0; ch < 3; ++ch) c[16 * 65 + 16][ch] += 100.0;
    const cell_frame f = emulate_cells(r, c, pipeline::plan_config{}, config(1.0));
    EXPECT_EQ(f.sent[3], 3u);
    EXPECT_EQ(f.fallback_rows, 4u);  // (12, 12), (16, 12), (12, 16), (16, 16)
    EXPECT_EQ(f.fallback_exact, 0u);
    EXPECT_TRUE(f.point[16 * 65 + 16]);
    for (unsigned y = 0; y < 65; ++y)
        for (unsigned x = 0; x < 65; ++x) {
            double want = 0.0;
            if (y == 16 && (x == 13 || x == 19)) want = -12.5;
            if (y == 16 && (x == 15 || x == 17)) want = 37.5;
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_NEAR(f.out[y * 65 + x][ch] - c[y * 65 + x][ch], want, 1e-9) << x << ", " << y << ", " << ch;
        }
    EXPECT_NEAR(f.se, 3.0 * (2.0 * 37.5 * 37.5 + 2.0 * 12.5 * 12.5), 1e-6);
    cell_tree_config perfect = config(1.0);
    perfect.perfect = true;
    const cell_frame p = emulate_cells(r, c, pipeline::plan_config{}, perfect);
    EXPECT_LT(p.se, 1e-12);
    EXPECT_EQ(p.fallback_exact, 2u);
}

// Sizes that are not powers of two, s_min below 4 or above s_max, s_max above 256, a tolerance or
// factor not positive, colours of another size: refused.
TEST(CellTree, BadConfigurationsRefused) {
    const scene::rasterised r = tb::flat_square(17);
    const std::vector<rgb_levels> c = biquadratic(17);
    const pipeline::plan_config cfg;
    auto with = [](auto change) {
        cell_tree_config t;
        change(t);
        return t;
    };
    EXPECT_NO_THROW(emulate_cells(r, c, cfg, cell_tree_config{}));
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.s_min = 2; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.s_min = 6; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.s_min = 64; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.s_max = 512; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.tol = 0.0; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.d3_factor = -1.0; })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, c, cfg, with([](auto& t) { t.line_tol = std::nan(""); })), std::invalid_argument);
    EXPECT_THROW(emulate_cells(r, std::vector<rgb_levels>(5), cfg, cell_tree_config{}), std::invalid_argument);
}

class CellTreeHead : public ::testing::Test {
protected:
    const study_frame head{"head", SHADING_SOURCE_DIR, 512, "squared", false};
    const scene::rasterised& r = head.r;
    const std::vector<rgb_levels>& colour = head.colour;
    const scene::device_config& dev = head.dev;
    const unsigned n = head.k.n;
};
// On the head at 512: the NMSE, the points and the pixels recomputed from the frame; every point read
// once and delivered as read; every covered pixel delivered by a cell, a column or a row. Counted with
// edges walked the order cannot matter (a walked run start is additions), so the scheme's order and
// raster order cost the same; in raster order the count is the two-line study's (emulated_long_ops,
// held to the planner's own count) of a frame with the same points.
TEST_F(CellTreeHead, BookkeepingFromTheFrame) {
    const cell_frame f = emulate_cells(r, colour, pipeline::plan_config{}, config(0.9));
    double se = 0.0, ref2 = 0.0;
    std::size_t covered = 0, points = 0;
    for (std::size_t i = 0; i < colour.size(); ++i) {
        if (r.tri[i] < 0) {
            EXPECT_FALSE(f.point[i]);
            continue;
        }
        ++covered;
        points += f.point[i];
        for (int ch = 0; ch < 3; ++ch) {
            se += (f.out[i][ch] - colour[i][ch]) * (f.out[i][ch] - colour[i][ch]);
            ref2 += colour[i][ch] * colour[i][ch];
            if (f.point[i]) {
                ASSERT_EQ(f.out[i][ch], colour[i][ch]);
            }
        }
    }
    EXPECT_EQ(f.pixels, covered);
    EXPECT_EQ(f.pixels_cells + f.pixels_columns + f.pixels_rows, covered);
    EXPECT_EQ(f.points(), points);
    std::set<std::pair<unsigned, unsigned>> once;
    for (const auto& p : f.order) once.insert({p[0], p[1]});
    EXPECT_EQ(once.size(), f.order.size());
    EXPECT_NEAR(f.se, se, 1e-9 * se);
    EXPECT_NEAR(f.nmse(), se / ref2, 1e-12);

    for (bool walk : {false, true}) {
        emulated_frame e;
        e.point = f.point;
        for (unsigned y = 0; y < r.height; ++y) e.lines.push_back(y);
        EXPECT_EQ(cell_long_ops(r, f, dev, n, walk, true).long_ops(), emulated_long_ops(r, e, dev, n, walk).long_ops())
            << walk;
    }
    // Walked in the scheme's order the walker jumps (a multiplication each, scanline.h): dearer than raster order.
    EXPECT_GT(cell_long_ops(r, f, dev, n, true, false).long_ops(), cell_long_ops(r, f, dev, n, true, true).long_ops());
    // Not walked, the scheme's order starts more runs than raster order.
    EXPECT_GT(cell_long_ops(r, f, dev, n, false, false).long_ops(), cell_long_ops(r, f, dev, n, false, true).long_ops());
}

// Against one line at a time at the same NMSE: the one-line emulation of the planner's adaptive policy
// without the line-above limit at T = 1.36 (NMSE 9.5e-6) against the cells at T = 0.85, which must
// come within that NMSE with at least a quarter fewer points. Perfect decisions take fewer points
// than the differences at a lower NMSE.
TEST_F(CellTreeHead, FewerPointsThanOneLineAtATime) {
    pipeline::plan_config c;
    c.m_max = 5;
    c.above_slack = -1;
    const emulated_frame one = emulate_lines(r, colour, c, {1.36});
    const cell_frame f = emulate_cells(r, colour, pipeline::plan_config{}, config(0.85));
    EXPECT_LE(f.nmse(), one.nmse());
    EXPECT_LT(double(f.points()), 0.75 * double(one.points()));
    cell_tree_config perfect = config(0.6);
    perfect.perfect = true;
    const cell_frame p = emulate_cells(r, colour, pipeline::plan_config{}, perfect);
    EXPECT_LT(p.points(), f.points());
    EXPECT_LT(p.nmse(), 1e-5);
}

}  // namespace test_cell_tree
