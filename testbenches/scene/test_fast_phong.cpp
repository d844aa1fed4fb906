// Bishop and Weimer's fast Phong shading (scene/fast_phong.h) against independent things: hand counts
// on a one-triangle scene, hand-worked Taylor coefficients and forward differences, hand-computed
// power-table entries, and render_phong / render_device where the expansion is exact. No
// simulation: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "scene/fast_phong.h"
#include "scene/image.h"
#include "scene/raster.h"
#include "scene/scene.h"
#include "scene/shade.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_fast_phong {

using namespace shading::scene;

namespace {

// An orthographic camera over the screen square [0, 8] x [0, 8] world units, `pixels` a side:
// world (X, Y) is screen ((X + 4) pixels/8, (4 - Y) pixels/8).
camera ortho(unsigned pixels) {
    camera c;
    c.position = {0.0, 0.0, 10.0};
    c.fov_y_deg = 0.0;
    c.ortho_height = 8.0;
    c.width = c.height = pixels;
    return c;
}

// test_scanline's triangle: screen (0, 0), (8, 0), (0, 8) at 8 x 8 pixels, three vertex normals, one
// directional light along +z: 28 pixels in 7 runs (line y holds x = 0 .. 6 - y), 21 steps.
// `perspective`: seen from z = 5 through 60 degrees instead.
world one_triangle(bool perspective, unsigned pixels = 8, std::array<glm::dvec3, 3> normals = {
                                                                glm::dvec3{0.2, 0.1, 1.0}, glm::dvec3{-0.3, 0.2, 1.0},
                                                                glm::dvec3{0.1, -0.4, 1.0}}) {
    world s;
    s.name = "one triangle";
    s.cam = ortho(pixels);
    if (perspective) {
        s.cam.position = {0.0, 0.0, 5.0};
        s.cam.fov_y_deg = 60.0;
    }
    s.lights.push_back({});
    object o{"tri", mesh{}, material{}};
    o.geometry.positions = {{-4.0, 4.0, 0.0}, {4.0, 4.0, 0.0}, {-4.0, -4.0, 0.0}};
    for (const auto& n : normals) o.geometry.normals.push_back(glm::normalize(n));
    o.geometry.triangles = {{0, 1, 2}};
    s.objects.push_back(o);
    return s;
}

op_counts counts(uint64_t mul, uint64_t div, uint64_t sqrt, uint64_t add, uint64_t cmp = 0) {
    op_counts c;
    c.mul = mul;
    c.div = div;
    c.sqrt = sqrt;
    c.add = add;
    c.cmp = cmp;
    return c;
}

cvec3 cv(double x, double y, double z, op_counts* ops) { return {cnum(x, ops), cnum(y, ops), cnum(z, ops)}; }

double largest_difference(const shaded_image& a, const shaded_image& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.value.size(); ++i)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.value[i][c] - b.value[i][c]));
    return worst;
}

void expect_config_error(const fast_phong_config& c, const std::string& word) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    try {
        render_fast_phong(r, device_config{}, c);
        ADD_FAILURE() << "no error for " << word;
    } catch (const scene_error& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

}  // namespace

// ---- The pieces, against hand-worked values ----

// F = x^2 + 2 x y + 3 y^2 + 4 x + 5 y + 6 on the line y = 1.5 from x = 0.5:
//   F(0.5) = 0.25 + 1.5 + 6.75 + 2 + 7.5 + 6 = 24, F(1.5) = 2.25 + 4.5 + 6.75 + 6 + 7.5 + 6 = 33,
//   F(2.5) = 6.25 + 7.5 + 6.75 + 10 + 7.5 + 6 = 44, F(3.5) = 12.25 + 10.5 + 6.75 + 14 + 7.5 + 6 = 57.
// Counts: the run start (Horner, 5 mul 5 add; the first difference, 2 add) and 3 steps x 2 add.
TEST(FastPhong, ForwardDifferencesEqualHandValues) {
    quadratic q;
    q.t5 = 1.0;
    q.t4 = 2.0;
    q.t3 = 3.0;
    q.t2 = 4.0;
    q.t1 = 5.0;
    q.t0 = 6.0;
    op_counts ops;
    const std::vector<double> f = forward_differences(q, 0.5, 1.5, 4, &ops);
    ASSERT_EQ(f.size(), 4u);
    EXPECT_DOUBLE_EQ(f[0], 24.0);
    EXPECT_DOUBLE_EQ(f[1], 33.0);
    EXPECT_DOUBLE_EQ(f[2], 44.0);
    EXPECT_DOUBLE_EQ(f[3], 57.0);
    EXPECT_EQ(ops, counts(5, 0, 0, 13)) << ops;
}

// U = (x, y, 1) (u0 = z, u_x = x, u_y = y): |U|^-1 = (1 + x^2 + y^2)^-1/2 = 1 - (x^2 + y^2)/2 + O(4), so
//   A = z: 1 - x^2/2 - y^2/2, no cubic;  A = x: x - x^3/2 - x y^2/2;  A = y: y - x^2 y/2 - y^3/2.
// Counts for one direction without the third order: the products u_x.u_x, u_x.u_y, u_y.u_y (9 mul,
// 6 add); q0 = U0.U0, U0.u_x, U0.u_y (9 mul, 6 add), 1/sqrt(q0) (sqrt, div), 1/q0 (1 mul), alpha,
// beta, c, delta, e (5 mul), alpha^2, alpha beta, beta^2 (3 mul) and g11, g12, g22 (6 add); the
// direction's p0, p1, p2 (9 mul, 6 add), r p (3 mul), the six coefficients (9 mul, 6 add):
// mul 9 + 18 + 21 = 48, add 6 + 12 + 12 = 30, 1 sqrt, 1 div.
TEST(FastPhong, ExpansionOfUnitNormalEqualsHandSeries) {
    op_counts ops;
    const cvec3 u0 = cv(0, 0, 1, &ops), ux = cv(1, 0, 0, &ops), uy = cv(0, 1, 0, &ops);
    const auto e = expand_normalised(u0, ux, uy, {cv(0, 0, 1, &ops), cv(1, 0, 0, &ops), cv(0, 1, 0, &ops)}, true);
    ASSERT_EQ(e.size(), 3u);
    auto expect_q = [](const quadratic& q, double t5, double t4, double t3, double t2, double t1, double t0) {
        EXPECT_NEAR(q.t5, t5, 1e-15);
        EXPECT_NEAR(q.t4, t4, 1e-15);
        EXPECT_NEAR(q.t3, t3, 1e-15);
        EXPECT_NEAR(q.t2, t2, 1e-15);
        EXPECT_NEAR(q.t1, t1, 1e-15);
        EXPECT_NEAR(q.t0, t0, 1e-15);
    };
    auto expect_third = [](const expansion& x, double c30, double c21, double c12, double c03) {
        EXPECT_NEAR(x.third[0], c30, 1e-15);
        EXPECT_NEAR(x.third[1], c21, 1e-15);
        EXPECT_NEAR(x.third[2], c12, 1e-15);
        EXPECT_NEAR(x.third[3], c03, 1e-15);
    };
    expect_q(e[0].q, -0.5, 0.0, -0.5, 0.0, 0.0, 1.0);
    expect_third(e[0], 0.0, 0.0, 0.0, 0.0);
    expect_q(e[1].q, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0);
    expect_third(e[1], -0.5, 0.0, -0.5, 0.0);
    expect_q(e[2].q, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    expect_third(e[2], 0.0, -0.5, 0.0, -0.5);

    op_counts one;
    expand_normalised(cv(0, 0, 1, &one), cv(1, 0, 0, &one), cv(0, 1, 0, &one), {cv(0, 0, 1, &one)}, false);
    EXPECT_EQ(one, counts(48, 1, 1, 30)) << one;
}

// Away from the axis, U = (1 + x, y, 1), A = z: f = (2 + 2x + x^2 + y^2)^-1/2 = 2^-1/2 (1 + eps)^-1/2,
// eps = x + x^2/2 + y^2/2; (1 + eps)^-1/2 = 1 - eps/2 + 3 eps^2/8 - 5 eps^3/16:
//   x: -1/2;  x^2: -1/4 + 3/8 = 1/8;  y^2: -1/4;  x^3: 3/8 - 5/16 = 1/16;  x y^2: 3/8;  the rest 0.
// And a cross term: U = (x + y, 0, 1), A = z: (1 + (x + y)^2)^-1/2 = 1 - (x^2 + 2 x y + y^2)/2 + O(4).
TEST(FastPhong, ExpansionOffAxisEqualsHandSeries) {
    const double k = 1.0 / std::sqrt(2.0);
    const auto e = expand_normalised(cv(1, 0, 1, nullptr), cv(1, 0, 0, nullptr), cv(0, 1, 0, nullptr),
                                     {cv(0, 0, 1, nullptr)}, true);
    EXPECT_NEAR(e[0].q.t0, k, 1e-15);
    EXPECT_NEAR(e[0].q.t2, -k / 2, 1e-15);
    EXPECT_NEAR(e[0].q.t1, 0.0, 1e-15);
    EXPECT_NEAR(e[0].q.t5, k / 8, 1e-15);
    EXPECT_NEAR(e[0].q.t4, 0.0, 1e-15);
    EXPECT_NEAR(e[0].q.t3, -k / 4, 1e-15);
    EXPECT_NEAR(e[0].third[0], k / 16, 1e-15);
    EXPECT_NEAR(e[0].third[1], 0.0, 1e-15);
    EXPECT_NEAR(e[0].third[2], 3 * k / 8, 1e-15);
    EXPECT_NEAR(e[0].third[3], 0.0, 1e-15);

    const auto x = expand_normalised(cv(0, 0, 1, nullptr), cv(1, 0, 0, nullptr), cv(1, 0, 0, nullptr),
                                     {cv(0, 0, 1, nullptr)}, false);
    EXPECT_NEAR(x[0].q.t5, -0.5, 1e-15);
    EXPECT_NEAR(x[0].q.t4, -1.0, 1e-15);
    EXPECT_NEAR(x[0].q.t3, -0.5, 1e-15);
    EXPECT_NEAR(x[0].q.t0, 1.0, 1e-15);
}

// n = 2, 2 bits: the bins' middles 1/8, 3/8, 5/8, 7/8 squared, times 65535, rounded:
//   0.015625 -> 1023.98 -> 1024; 0.140625 -> 9215.86 -> 9216; 0.390625 -> 25599.6 -> 25600;
//   0.765625 -> 50175.2 -> 50175 (65535 x 49/64 = 3211215/64). Index: the top two fraction bits
// (0.3 -> 1, 0.99 -> 3), 1.0 and above the last entry, 0 and below the first. Build: one squaring an entry.
TEST(FastPhong, PowerTableEqualsHandValues) {
    op_counts ops;
    const power_table t = make_power_table(2, 2, &ops);
    ASSERT_EQ(t.entry.size(), 4u);
    EXPECT_EQ(t.entry[0], 1024);
    EXPECT_EQ(t.entry[1], 9216);
    EXPECT_EQ(t.entry[2], 25600);
    EXPECT_EQ(t.entry[3], 50175);
    EXPECT_EQ(t.index(0.3), 1u);
    EXPECT_EQ(t.index(0.5), 2u);
    EXPECT_EQ(t.index(0.99), 3u);
    EXPECT_EQ(t.index(1.0), 3u);
    EXPECT_EQ(t.index(1.5), 3u);
    EXPECT_EQ(t.index(-0.2), 0u);
    EXPECT_DOUBLE_EQ(t.value(0.3), 9216.0 / 65535.0);
    EXPECT_EQ(ops, counts(4, 0, 0, 0)) << ops;
    // 10 bits, n = 20: entry 1023 = (2047/2048)^20 = 0.9902795, times 65535 = 64897.97 -> 64898.
    EXPECT_EQ(make_power_table(20, 10, nullptr).entry[1023], 64898);
}

// ---- Whole frames: hand counts ----

// The 28-pixel triangle, orthographic, one directional light (V, L, H frame constants), device path.
//   triangle set-up: u_x, u_y = sum a_i N_i, sum b_i N_i (18 mul, 12 add), their products (9 mul,
//     6 add); the part: centroid (x0 + x1 + x2) / 3 twice (2 mul, 4 add), g_i there (6 mul, 6 add),
//     U0 = sum g_i N_i (9 mul, 6 add), 1/|U| terms (18 mul, 12 add, sqrt, div), two expressions
//     x (21 mul, 12 add): mul 18 + 9 + 2 + 6 + 9 + 18 + 42 = 104, add 12 + 6 + 4 + 6 + 6 + 12 + 24 = 70;
//   run starts: 7 x (2 add + 2 x (5 mul, 7 add)) = 70 mul, 112 add;  steps: 21 x 2 x 2 add = 84 add;
//   geometry: mul 174, add 266, sqrt 1, div 1 (176 long: 6.3 a pixel, against 18.5 for the
//     scan-line Phong geometry of test_scanline);
//   shading, per pixel (N.L > 0 everywhere): 2 cmp, 3 x (1 mul, 2 add), and the device (UA 60553's
//     Fig. 1: 5 mul, 2 add): 28 x (8 mul, 8 add): 224 mul, 224 add, 56 cmp.
TEST(FastPhong, SingleTriangleFrameCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    ASSERT_EQ(r.covered_pixels(), 28u);
    render_stats st;
    fast_phong_stats fs;
    scheme_state state;
    render_fast_phong(r, device_config{}, fast_phong_config{}, &st, &state, &fs);
    EXPECT_EQ(fs.setup, counts(104, 1, 1, 70)) << fs.setup;
    EXPECT_EQ(fs.run_start, counts(70, 0, 0, 112)) << fs.run_start;
    EXPECT_EQ(fs.step, counts(0, 0, 0, 84)) << fs.step;
    EXPECT_EQ(st.geometry, counts(174, 1, 1, 266)) << st.geometry;
    EXPECT_EQ(st.shading, counts(224, 0, 0, 224, 56)) << st.shading;
    EXPECT_EQ(st.pixels, 28u);
    EXPECT_EQ(fs.triangles, 1u);
    EXPECT_EQ(fs.setups, 1u);
    EXPECT_EQ(fs.parts, 1u);
    EXPECT_EQ(fs.run_starts, 7u);
    EXPECT_EQ(fs.steps, 21u);
    EXPECT_EQ(fs.lookups, 0u);
    // One light: 2 expressions, per part 2 + 2 x 6 + 2 x 2 = 18 words; no fixed store on the device path.
    EXPECT_EQ(state.per_triangle_words, 18u);
    EXPECT_TRUE(state.fixed.empty());
}

// The table path on the same frame: per pixel 3 more mul (k_s I times S) and a look-up; the build,
// 1024 entries of (mid)^32 at 5 squarings each, in the shading counts: 5120 mul. The table's store:
// 1024 x 16 bits.
TEST(FastPhong, SingleTriangleTablePathCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    ASSERT_EQ(s.objects[0].mat.n, 32u);
    render_stats st;
    fast_phong_stats fs;
    scheme_state state;
    fast_phong_config c;
    c.power = specular_path::table;
    render_fast_phong(r, device_config{}, c, &st, &state, &fs);
    EXPECT_EQ(fs.table_build, counts(5120, 0, 0, 0)) << fs.table_build;
    EXPECT_EQ(st.shading, counts(5120 + 28 * 6, 0, 0, 168, 56)) << st.shading;
    EXPECT_EQ(fs.lookups, 28u);
    ASSERT_EQ(state.fixed.size(), 1u);
    EXPECT_EQ(state.fixed[0].total_bits(), 1024u * 16u);
    EXPECT_EQ(state.bits(1), 18u * 32u + 1024u * 16u);
}

// Perspective: V and H at the centroid's position: b_i = g_i / sum g (2 add, div, 3 mul), P (9 mul,
// 6 add), V = normalize(eye - P) (3 add; 6 mul, 2 add, sqrt, div), H = normalize(L + V) (the same):
// 24 mul, 18 add, 2 sqrt, 3 div on top of the orthographic set-up: 128 mul, 88 add, 3 sqrt, 4 div.
TEST(FastPhong, PerspectiveSetupCountedByHand) {
    const world s = one_triangle(true);
    const rasterised r = rasterise(s);
    fast_phong_stats fs;
    render_fast_phong(r, device_config{}, fast_phong_config{}, nullptr, nullptr, &fs);
    EXPECT_EQ(fs.triangles, 1u);
    EXPECT_EQ(fs.setup, counts(128, 4, 3, 88)) << fs.setup;
    EXPECT_EQ(fs.run_starts + fs.steps, r.covered_pixels());
}

// The split variant's set-up on the same frame (orthographic, directional: V, L, H constant, so the
// held directions cost nothing and stray by nothing). Judging the triangle (budget > 0, depth 0 < 1)
// adds to the 104 mul, 70 add above:
//   the third order of 1/|U|: (alpha x + beta y)(c x^2 + 2 delta x y + e y^2) 6 mul 2 add, alpha^2 beta
//     and alpha beta^2 2 mul, alpha^3, beta^3 2 mul, 3 v = v + 2 v twice 2 add, 3/2 A - 5/2 B 4 x 3 add:
//     10 mul, 16 add; per expression its four cubic coefficients (10 mul, 6 add): 20 mul, 12 add;
//   the estimate: offsets of 3 vertices and 3 midpoints (12 add), y^2 and y^3 at the 6 points (12 mul);
//     the expanded N.H at the 6 points (6 x (5 mul, 5 add), 6 cmp), clamped (2 cmp); its slope
//     32 s^31 (pow_int: 4 squarings, 4 mul; x 32: 9 mul); two cubics at the 6 points (2 x (36 mul,
//     18 add, 5 cmp)); (D + 0), (S + 0) 2 add, 255 k_d I D + 255 k_s I slope S and the sum 3 mul 2 add:
//     mul 12 + 30 + 9 + 72 + 3 = 126, add 12 + 30 + 36 + 4 = 82, cmp 6 + 2 + 10 = 18;
//   the comparison with the budget: 1 cmp.
// With a budget far above the error (no split): mul 104 + 10 + 20 + 126 = 260, add 70 + 16 + 12 + 82
// = 180, cmp 19. With a budget below it and max_depth 1: the midpoints (3 x 2 add) and four parts
// not judged, each its centroid, U0, 1/|U| and two expressions (77 mul, 52 add, sqrt, div):
// mul 260 + 308 = 568, add 180 + 6 + 208 = 394, 5 sqrt, 5 div, 19 cmp; five set-ups, four parts.
TEST(FastPhong, SplitSetupCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    fast_phong_config c;
    c.max_depth = 1;
    c.budget = 1e9;
    fast_phong_stats kept;
    render_fast_phong(r, device_config{}, c, nullptr, nullptr, &kept);
    EXPECT_EQ(kept.setup, counts(260, 1, 1, 180, 19)) << kept.setup;
    EXPECT_EQ(kept.parts, 1u);
    c.budget = 1e-9;
    fast_phong_stats split;
    scheme_state state;
    render_fast_phong(r, device_config{}, c, nullptr, &state, &split);
    EXPECT_EQ(split.setup, counts(568, 5, 5, 394, 19)) << split.setup;
    EXPECT_EQ(split.setups, 5u);
    EXPECT_EQ(split.parts, 4u);
    EXPECT_EQ(split.split_triangles, 1u);
    EXPECT_EQ(split.max_parts, 4u);
    EXPECT_EQ(split.run_starts + split.steps, 28u);
    EXPECT_EQ(state.per_triangle_words, 4u * 18u);  // the live triangle holds its four parts
}

// ---- Whole frames: images where the expansion is exact ----

// Equal vertex normals, orthographic: every expression is constant, so the expansion is exact and the
// device path's image is render_device's to rounding; the table path's differs from render_phong by
// the table alone: |S - s^n| <= n 2^-(bits+1) (half a bin, the power's slope at most n) + 2^-17 (16-bit
// rounding), times 255 k_s I = 102 levels: n = 32, 10 bits: 1.594 + 0.001 levels.
TEST(FastPhong, EqualNormalsEqualTheReferences) {
    const glm::dvec3 n{0.3, -0.2, 1.0};
    const world s = one_triangle(false, 8, {n, n, n});
    const rasterised r = rasterise(s);
    const shaded_image dev = render_fast_phong(r, device_config{}, fast_phong_config{});
    EXPECT_LT(largest_difference(dev, render_device(r, device_config{})), 1e-9);
    fast_phong_config c;
    c.power = specular_path::table;
    const double bound = 102.0 * (32.0 / 2048.0 + 1.0 / 131072.0);
    EXPECT_LT(largest_difference(render_fast_phong(r, device_config{}, c), render_phong(r)), bound);
}

// Perspective, equal normals, no specular (k_s = 0): the diffuse L.N/|N| is exact whatever the
// camera (the normalised perspective-correct normal is U_N/|U_N|, and U_N is linear on the screen),
// so the image is render_phong's to rounding. With varying normals the dropped cubic shows: more than
// rounding, less than half a level on this 32 x 32 triangle.
TEST(FastPhong, PerspectiveDiffuseEqualsPhong) {
    const glm::dvec3 n{0.3, -0.2, 1.0};
    world s = one_triangle(true, 32, {n, n, n});
    s.objects[0].mat.k_s = rgb(0.0);
    const rasterised r = rasterise(s);
    EXPECT_LT(largest_difference(render_fast_phong(r, device_config{}, fast_phong_config{}), render_phong(r)), 1e-9);
    world v = one_triangle(true, 32);
    v.objects[0].mat.k_s = rgb(0.0);
    const rasterised rv = rasterise(v);
    const double d = largest_difference(render_fast_phong(rv, device_config{}, fast_phong_config{}), render_phong(rv));
    EXPECT_GT(d, 1e-9);
    EXPECT_LT(d, 0.5);
}

// ---- The split variant ----

// A large triangle (64 x 64 pixels, perspective) whose normals spread 60 degrees, n = 20, light from
// the upper left: one expansion misses the budget; splitting gives each part its own expansion and
// H, and the error against render_phong falls strictly (table path at 16 bits: the table's own error
// below 0.02 levels: 102 (20 x 2^-17 + 2^-17)). Every budget keeps the set-ups within the bound
// 1 + 4 + ... + 4^max_depth and the parts within 4^max_depth; max_depth 0 never splits.
TEST(FastPhong, SplittingLowersTheErrorOnALargeTriangle) {
    world s = one_triangle(true, 64,
                           {glm::dvec3{0.8, 0.5, 1.0}, glm::dvec3{-0.7, 0.4, 1.0}, glm::dvec3{0.3, -0.9, 1.0}});
    s.objects[0].mat.n = 20;
    s.lights[0].vector = light_towards(-30.0, 20.0);
    const rasterised r = rasterise(s);
    const shaded_image phong = render_phong(r);
    fast_phong_config c;
    c.power = specular_path::table;
    c.table_bits = 16;
    fast_phong_stats whole, split;
    const double e0 = compare_images(render_fast_phong(r, device_config{}, c, nullptr, nullptr, &whole), phong).nmse;
    c.budget = 1.0;
    const double e1 = compare_images(render_fast_phong(r, device_config{}, c, nullptr, nullptr, &split), phong).nmse;
    EXPECT_EQ(whole.parts, 1u);
    EXPECT_GT(split.parts, 1u);
    EXPECT_LT(e1, e0);
    std::printf("large triangle: NMSE %.3g in one part, %.3g in %zu parts (%zu set-ups)\n", e0, e1, split.parts,
                split.setups);
    for (unsigned depth : {0u, 1u, 2u, 4u})
        for (double budget : {0.01, 0.3, 3.0}) {
            c.max_depth = depth;
            c.budget = budget;
            fast_phong_stats fs;
            render_fast_phong(r, device_config{}, c, nullptr, nullptr, &fs);
            const std::size_t leaves = std::size_t{1} << (2 * depth);
            EXPECT_LE(fs.setups, (4 * leaves - 1) / 3) << depth << " " << budget;
            EXPECT_LE(fs.parts, leaves) << depth << " " << budget;
            EXPECT_EQ(fs.setups, fs.parts + (fs.parts - 1) / 3);  // each split: one judged parent, 3 more leaves
            if (depth == 0) {
                EXPECT_EQ(fs.setups, 1u);
            }
        }
}

// On the head (perspective, thousands of triangles): the work splits as the stats say (every pixel a
// run start or a step; geometry = set-ups + run starts + steps), and the table path is close to
// render_phong (NMSE below 1e-4); a budget only adds set-ups.
TEST(FastPhong, HeadCloseToPhong) {
    world s = builtin_scene("head", SHADING_SOURCE_DIR, 128, 128);
    for (auto& o : s.objects) o.mat.n = 20;
    const rasterised r = rasterise(s);
    const shaded_image phong = render_phong(r);
    fast_phong_config c;
    c.power = specular_path::table;
    render_stats st;
    fast_phong_stats fs;
    const double e = compare_images(render_fast_phong(r, device_config{}, c, &st, nullptr, &fs), phong).nmse;
    EXPECT_LT(e, 1e-4);
    EXPECT_EQ(fs.run_starts + fs.steps, st.pixels);
    EXPECT_EQ(st.pixels, r.covered_pixels());
    op_counts sum = fs.setup;
    sum += fs.run_start;
    sum += fs.step;
    EXPECT_EQ(st.geometry, sum);
    // One light: per run start 2 x 5 mul, nothing long per step, per triangle (one part each without
    // a budget) PerspectiveSetupCountedByHand's 128 mul, 4 div, 3 sqrt.
    EXPECT_EQ(fs.run_start.long_ops(), 10 * fs.run_starts);
    EXPECT_EQ(fs.step.long_ops(), 0u);
    EXPECT_EQ(fs.setup.long_ops(), 135 * fs.setups);
    c.budget = 2.0;
    fast_phong_stats split;
    render_fast_phong(r, device_config{}, c, nullptr, nullptr, &split);
    EXPECT_GE(split.setups, fs.setups);
    EXPECT_GE(split.run_starts, fs.run_starts);  // spans now cross parts
    EXPECT_EQ(split.run_starts + split.steps, st.pixels);
}

TEST(FastPhong, BadConfigThrows) {
    fast_phong_config c;
    c.table_bits = 0;
    expect_config_error(c, "table_bits");
    c.table_bits = 17;
    expect_config_error(c, "table_bits");
    c = {};
    c.budget = -1.0;
    expect_config_error(c, "budget");
    c.budget = std::numeric_limits<double>::quiet_NaN();
    expect_config_error(c, "budget");
    c = {};
    c.max_depth = 9;
    expect_config_error(c, "max_depth");
    EXPECT_THROW(make_power_table(20, 0, nullptr), scene_error);
}

}  // namespace test_fast_phong
