// The line kinks (line_kinks.h) against independent values on the head at 512: the colour of one
// triangle's extended planes at a pixel centre against the per-pixel Phong from scratch
// (geometry_at's barycentrics, shade_phong); at every shared edge both triangles' colours agreeing
// at the crossing found; the jump predicting the next pixel's Phong from the triangle before it to
// first order; every triangle change an edge crossed or a vertex passed, the vertex a corner of
// both; the normal field's Laplacian on a fan worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "golden_pipeline/pipeline.h"
#include "line_kinks.h"
#include "scene/scene.h"
#include "scene/shade.h"

namespace {

using namespace shading;
using namespace shading::study;

double largest_difference(const rgb_levels& a, const rgb_levels& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

class LineKinks : public ::testing::Test {
protected:
    scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 512, 512);
    scene::rasterised r = scene::rasterise(w);
    rgb_levels phong_at(unsigned x, unsigned y) const {
        const scene::pixel_geometry g = scene::geometry_at(r, x, y, nullptr);
        const scene::rgb c = scene::shade_phong(g, w.objects[g.object].mat, w.lights);
        return {c.x, c.y, c.z};
    }
};

TEST_F(LineKinks, ColourOnATriangleIsPhongAtItsPixels) {
    std::size_t checked = 0;
    for (unsigned y = 0; y < r.height; y += 3)
        for (unsigned x = 0; x < r.width; ++x)
            if (r.covered(x, y)) {
                EXPECT_LT(largest_difference(colour_on(r, r.tri[r.index(x, y)], x + 0.5, y + 0.5), phong_at(x, y)), 1e-9)
                    << x << "," << y;
                ++checked;
            }
    EXPECT_GT(checked, 1000u);
}

TEST_F(LineKinks, JumpsSitOnTheSharedEdgeAndPredictTheNextPixel) {
    const pipeline::plan_config cfg;
    std::size_t edges = 0, vertices = 0, changes = 0, jumps = 0;
    std::size_t better = 0;  // jumps whose prediction is nearer than A's colour alone
    double worst_miss = 0.0, se_jump = 0.0, se_plain = 0.0;
    std::vector<double> misses;
    for (unsigned y = 0; y < r.height; ++y)
        for (const auto& s : pipeline::line_segments(r, y, cfg, nullptr)) {
            const segment_kinks k = kinks_of(r, y, s[0], s[1]);
            ASSERT_EQ(k.vertex_pass.size(), s[1] - s[0] + 1);
            edges += k.edges;
            vertices += k.vertices;
            for (unsigned x = s[0] + 1; x <= s[1]; ++x) {
                changes += r.tri[r.index(x, y)] != r.tri[r.index(x - 1, y)];
                // Inside a segment every neighbour is on the same patch of the mesh (the planner cuts folds).
                EXPECT_TRUE(one_patch(r, r.tri[r.index(x - 1, y)], r.tri[r.index(x, y)])) << x << "," << y;
                if (!k.vertex_pass[x - s[0]]) continue;
                // The vertex passed is a corner of both triangles.
                for (unsigned p : {x - 1, x}) {
                    const scene::triangle_setup& ts = r.setups[static_cast<std::size_t>(r.tri[r.index(p, y)])];
                    const auto& t = w.objects[ts.object].geometry.triangles[ts.triangle];
                    EXPECT_NE(std::find(t.begin(), t.end(), k.passed[x - s[0]]), t.end()) << p << "," << y;
                }
            }
            for (const slope_jump& j : k.jumps) {
                const unsigned after = s[0] + static_cast<unsigned>(std::floor(j.e)) + 1;  // first pixel past it
                ASSERT_GE(j.e, double(after - 1 - s[0]));
                ASSERT_LE(j.e, double(after - s[0]));
                const int32_t ta = r.tri[r.index(after - 1, y)], tb = r.tri[r.index(after, y)];
                const double xs = s[0] + j.e + 0.5, ys = y + 0.5;
                // Both triangles' normals and positions meet on their shared edge: one colour.
                worst_miss = std::max(worst_miss, largest_difference(colour_on(r, ta, xs, ys), colour_on(r, tb, xs, ys)));
                // The next pixel's colour = A's extended + the jump's ramp, to first order.
                const rgb_levels plain = colour_on(r, ta, after + 0.5, ys), truth = phong_at(after, y);
                rgb_levels predicted = plain;
                for (int ch = 0; ch < 3; ++ch) predicted[ch] += j.s[ch] * (after - s[0] - j.e);
                for (int ch = 0; ch < 3; ++ch) {
                    se_jump += (predicted[ch] - truth[ch]) * (predicted[ch] - truth[ch]);
                    se_plain += (plain[ch] - truth[ch]) * (plain[ch] - truth[ch]);
                }
                misses.push_back(largest_difference(predicted, truth));
                better += largest_difference(predicted, truth) <= largest_difference(plain, truth);
                ++jumps;
            }
        }
    EXPECT_GT(jumps, 1000u);
    EXPECT_EQ(edges + vertices, changes);  // the planner's segments hold no fold (no shared vertex)
    EXPECT_GE(edges, jumps);
    EXPECT_LT(worst_miss, 1e-6);
    // First order: a median miss of 0.002 levels, 98.8 % of the jumps nearer than A's colour alone,
    // 82 % of its squared miss explained. The rest: curvature over up to a pixel where the highlight
    // turns fast, and the terminator, where N.L <= 0 cuts the specular (tens of levels, a few pixels).
    std::sort(misses.begin(), misses.end());
    EXPECT_LT(misses[misses.size() / 2], 0.01);
    EXPECT_GE(double(better), 0.98 * double(jumps));
    EXPECT_LT(se_jump, 0.25 * se_plain);
}

// one_patch against the meshes' own vertex lists: a triangle with itself, with a triangle that shares
// one corner, with one sharing none, and two objects' triangles.
TEST_F(LineKinks, OnePatchMeansASharedCorner) {
    std::size_t shared = 0, apart = 0;
    const auto corners = [&](int32_t t) {
        const scene::triangle_setup& ts = r.setups[static_cast<std::size_t>(t)];
        return std::make_pair(ts.object, w.objects[ts.object].geometry.triangles[ts.triangle]);
    };
    for (int32_t a = 0; a < static_cast<int32_t>(r.setups.size()); a += 97)
        for (int32_t b = 0; b < static_cast<int32_t>(r.setups.size()); b += 13) {
            const auto [oa, va] = corners(a);
            const auto [ob, vb] = corners(b);
            bool common = a == b;
            for (auto v : va) common = common || (oa == ob && std::find(vb.begin(), vb.end(), v) != vb.end());
            EXPECT_EQ(one_patch(r, a, b), common) << a << "," << b;
            (common ? shared : apart) += 1;
        }
    EXPECT_TRUE(one_patch(r, 5, 5));
    EXPECT_GT(shared, 0u);
    EXPECT_GT(apart, 1000u);
}

// A fan worked by hand: centre 0 with N = (0, 0, 1), corners 1..4 around it with normals tilted
// 0.6 outwards, (±0.6, 0, 0.8) and (0, ±0.6, 0.8), and a vertex in no triangle. The corners'
// mean is (0, 0, 0.8): 0.2 for the centre. Corner 1 (0.6, 0, 0.8) neighbours the centre and
// corners 3, 4: their mean (0, 0, 2.6 / 3), so |(0.6, 0, 0.8 - 2.6 / 3)| = sqrt(0.36 + 1 / 225).
TEST(NormalLaplacian, FanByHand) {
    scene::mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {5, 5, 5}};
    m.normals = {{0, 0, 1}, {0.6, 0, 0.8}, {-0.6, 0, 0.8}, {0, 0.6, 0.8}, {0, -0.6, 0.8}, {0, 0, 1}};
    m.triangles = {{0, 1, 3}, {0, 3, 2}, {0, 2, 4}, {0, 4, 1}};
    const std::vector<double> l = normal_laplacian(m);
    ASSERT_EQ(l.size(), 6u);
    EXPECT_NEAR(l[0], 0.2, 1e-12);
    for (int corner = 1; corner <= 4; ++corner) EXPECT_NEAR(l[corner], std::sqrt(0.36 + 1.0 / 225.0), 1e-12) << corner;
    EXPECT_EQ(l[5], 0.0);
    // A flat patch: every normal the same, nothing stands out.
    for (auto& n : m.normals) n = {0, 0, 1};
    for (double v : normal_laplacian(m)) EXPECT_EQ(v, 0.0);
}

}  // namespace
