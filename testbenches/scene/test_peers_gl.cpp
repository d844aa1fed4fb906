// The per-pixel references' interpolating peers: Gouraud (colours per vertex through the specular
// device, stepped over the triangle) and Lyon (the Taylor-normalised normal and the chord power),
// with Lyon's scalar law. Their counts against hand counts on the one-triangle scene, their images
// against hand-mixed vertex colours, render_device and render_phong within hand-derived bounds.
// No simulation: these tests may share a process.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "reference/brdf_reference.h"
#include "scene/gouraud.h"
#include "scene/image.h"
#include "scene/lyon.h"
#include "scene/raster.h"
#include "scene/shade.h"
#include "tiny_scenes.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_peers_gl {

using namespace shading::scene;
using shading::scene::tiny::counts;
using shading::scene::tiny::one_triangle;
namespace ref = shading::ref;

namespace {

// The one-triangle scene with every vertex normal (0, 0, 1) and the light turned by `theta` radians
// about the y axis: N.L = cos theta and N.H = cos(theta / 2) at every pixel (V = (0, 0, 1)).
world flat_triangle(double theta, unsigned n) {
    world s = one_triangle(false);
    for (auto& nv : s.objects[0].geometry.normals) nv = {0.0, 0.0, 1.0};
    s.lights[0].vector = {std::sin(theta), 0.0, std::cos(theta)};
    s.objects[0].mat.n = n;
    return s;
}

// Orthographic one-triangle scene: the screen-space barycentrics of pixel (x, y) (tiny_scenes.h).
std::array<double, 3> barycentrics(unsigned x, unsigned y) {
    return {1.0 - (x + y + 1.0) / 8.0, (x + 0.5) / 8.0, (y + 0.5) / 8.0};
}

// Run starts of a frame read line by line: covered pixels whose left neighbour is empty or on
// another triangle.
std::size_t run_starts(const rasterised& r) {
    std::size_t n = 0;
    for (unsigned y = 0; y < r.height; ++y)
        for (unsigned x = 0; x < r.width; ++x)
            if (r.covered(x, y) && (x == 0 || r.tri[r.index(x - 1, y)] != r.tri[r.index(x, y)])) ++n;
    return n;
}

}  // namespace

// ---- Lyon's scalar law (reference/brdf_reference.h) ----

// gamma from n: the largest power of two not above n.
TEST(LyonLaw, GammaFromN) {
    EXPECT_EQ(ref::lyon_gamma(1), 1u);
    EXPECT_EQ(ref::lyon_gamma(2), 2u);
    EXPECT_EQ(ref::lyon_gamma(3), 2u);
    EXPECT_EQ(ref::lyon_gamma(20), 16u);
    EXPECT_EQ(ref::lyon_gamma(32), 32u);
    EXPECT_EQ(ref::lyon_gamma(1000), 512u);
}

// By hand: D.D/2 = 1 - cos for unit vectors.
//   cos 0.9, n = gamma = 16: (1 - 0.1)^16 = 0.9^16 = 0.18530201888518416 (the law is cos^n when gamma = n);
//   cos 0.95, n 20, gamma 4: 1 - 5 x 0.05 = 0.75, 0.75^4 = 0.31640625;
//   cos 0.7, n 20, gamma 4: 1 - 5 x 0.3 < 0: 0 (clamped);
//   cos 0.98, n 20, gamma from n = 16: 1 - 1.25 x 0.02 = 0.975, 0.975^16 = 0.6669201684248254.
TEST(LyonLaw, HandValues) {
    EXPECT_NEAR(ref::lyon_power(0.9, 16, 16), 0.18530201888518416, 1e-15);
    EXPECT_NEAR(ref::lyon_power(0.95, 20, 4), 0.31640625, 1e-15);
    EXPECT_EQ(ref::lyon_power(0.7, 20, 4), 0.0);
    EXPECT_NEAR(ref::lyon_power(0.98, 20, 0), 0.6669201684248254, 1e-15);
    EXPECT_NEAR(ref::lyon_power(0.98, 20, 16), 0.6669201684248254, 1e-15);
}

// Against cos^n at small angles, lambda = 1 - cos, f = n / gamma >= 1 (gamma from n):
//   gamma ln(1 - f lambda) - n ln(1 - lambda) = -n sum_{j>=2} (f^(j-1) - 1) lambda^j / j,
// every term <= 0, and >= -n sum_{j>=2} f^(j-1) lambda^j / j >= -n f lambda^2 / (2 (1 - f lambda)).
// So 0 <= cos^n - lyon <= cos^n n f lambda^2 / (2 (1 - f lambda)), and strictly below unless f = 1.
TEST(LyonLaw, BelowCosPowWithinSecondOrderBound) {
    for (unsigned n : {3u, 20u, 100u, 1000u}) {
        const double f = double(n) / ref::lyon_gamma(n);
        for (double lambda = 1e-4; lambda <= 0.2 / f; lambda *= 1.5) {
            const double c = 1.0 - lambda, exact = std::pow(c, n), lyon = ref::lyon_power(c, n, 0);
            const double bound = exact * n * f * lambda * lambda / (2.0 * (1.0 - f * lambda));
            EXPECT_GT(exact - lyon, 0.0) << n << ' ' << lambda;
            EXPECT_LE(exact - lyon, bound * (1 + 1e-9) + 1e-15) << n << ' ' << lambda;
        }
    }
}

// ---- Lyon's normalisation ----

// Three Taylor terms of 1/sqrt(s) about 1, r = 1 - u/2 + 3u^2/8, u = N.N - 1; Lagrange's remainder
// 1/sqrt(1 + u) - r = -(5/16) (1 + xi)^(-7/2) u^3, xi between 0 and u.
//   N = (0.6, 0, 0.7): s = 0.85, u = -0.15, r = 1 + 0.075 + 0.375 x 0.0225 = 1.0834375; the
//   remainder lies in [(5/16) 0.15^3, (5/16) 0.15^3 / 0.85^3.5] = [0.00105469, 0.00186276].
//   N = (1.1, 0, 0): s = 1.21, u = 0.21, r = 1 - 0.105 + 0.375 x 0.0441 = 0.9115375; r - 1/1.1 lies
//   in [(5/16) 0.21^3 / 1.21^3.5, (5/16) 0.21^3] = [0.00148511, 0.00289406].
// Each 8 mul, 5 add, no division, no square root.
TEST(LyonNormalize, TaylorAgainstInverseSqrtByHand) {
    op_counts ops;
    auto cv = [&ops](double x, double y, double z) { return cvec3{cnum(x, &ops), cnum(y, &ops), cnum(z, &ops)}; };
    const cvec3 a = lyon_normalize(cv(0.6, 0.0, 0.7));
    EXPECT_EQ(ops, counts(8, 0, 0, 5)) << ops;
    EXPECT_NEAR(a.x.value(), 0.6 * 1.0834375, 1e-15);
    EXPECT_NEAR(a.z.value(), 0.7 * 1.0834375, 1e-15);
    EXPECT_EQ(a.y.value(), 0.0);
    const double ra = a.x.value() / 0.6, rem_a = 1.0 / std::sqrt(0.85) - ra;
    EXPECT_GE(rem_a, 0.00105468);
    EXPECT_LE(rem_a, 0.00186277);
    const cvec3 b = lyon_normalize(cv(1.1, 0.0, 0.0));
    EXPECT_NEAR(b.x.value(), 1.1 * 0.9115375, 1e-15);
    const double rem_b = b.x.value() / 1.1 - 1.0 / 1.1;
    EXPECT_GE(rem_b, 0.00148511);
    EXPECT_LE(rem_b, 0.00289407);
}

// ---- Gouraud ----

// The single triangle (orthographic, directional light, 28 pixels, 7 runs, 21 steps), by hand:
//   per vertex, geometry: H = L + V (3 add) normalised (6 mul, 2 add, sqrt, div); 3 vertices:
//     18 mul, 15 add, 3 sqrt, 3 div; shading (shade_device): N.L, N.H (3 mul, 2 add each), per
//     channel k_d I N.L (1 mul) added with ambient and the device's term (2 add), and the device
//     (UA 60553's Fig. 1: MUL7, MUL10, MUL12..14, ADD9, ADD11: 5 mul, 2 add): 14 mul, 12 add;
//     3 vertices: 42 mul, 36 add;
//   colour planes: 3 channels x 3 coefficients x (3 mul, 2 add) = 27 mul, 18 add;
//   run starts 7 x 3 channels x (2 mul, 2 add) = 42 mul, 42 add; steps 21 x 3 add = 63 add.
//   geometry: mul 18 + 27 + 42 = 87, add 15 + 18 + 42 + 63 = 138, sqrt 3, div 3 (93 long);
//   shading: mul 42, add 36 (135 long operations in all: 4.8 a pixel against Phong 1975's 30).
TEST(Gouraud, SingleTriangleCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    ASSERT_EQ(r.covered_pixels(), 28u);
    render_stats st;
    scheme_state state;
    render_gouraud(r, device_config{}, &st, &state);
    EXPECT_EQ(st.geometry, counts(87, 3, 3, 138)) << st.geometry;
    op_counts shading = counts(42, 0, 0, 36);
    shading.cmp = 6;  // N.L > 0 and max(N.H, 0) at each vertex
    EXPECT_EQ(st.shading, shading) << st.shading;
    EXPECT_EQ(st.pixels, 28u);
    EXPECT_EQ(state.per_triangle_words, 12u);
    EXPECT_TRUE(state.fixed.empty());
}

// Each pixel is the screen-linear mix of the vertex colours, each colour shade_device's at the vertex
// (its normal; V = L = (0, 0, 1), H = (0, 0, 1) by hand): pixel (0, 0) = (14 C0 + C1 + C2) / 16, pixel
// (3, 3) = (2 C0 + 7 C1 + 7 C2) / 16, pixel (6, 0) = (2 C0 + 13 C1 + C2) / 16 (tiny_scenes.h).
TEST(Gouraud, PixelIsTheBarycentricMixOfVertexColours) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    for (const device_config dev : {device_config{specular_device::patent}, device_config{specular_device::squared}}) {
        const shaded_image img = render_gouraud(r, dev);
        std::array<rgb, 3> vc;
        for (int i = 0; i < 3; ++i) {
            pixel_geometry g;
            const glm::dvec3 nv = s.objects[0].geometry.normals[i];
            g.n = {cnum(nv.x, nullptr), cnum(nv.y, nullptr), cnum(nv.z, nullptr)};
            g.v = {cnum(0.0, nullptr), cnum(0.0, nullptr), cnum(1.0, nullptr)};
            g.l = {g.v};
            g.h = {g.v};
            vc[i] = shade_device(g, s.objects[0].mat, s.lights, dev);
            ASSERT_LT(vc[i].x, 255.0);  // unclamped, so the mix is the pixel
        }
        for (const auto& [x, y] : {std::pair{0u, 0u}, std::pair{3u, 3u}, std::pair{6u, 0u}}) {
            const auto b = barycentrics(x, y);
            const rgb want = b[0] * vc[0] + b[1] * vc[1] + b[2] * vc[2];
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(img.value[r.index(x, y)][ch], want[ch], 1e-11) << x << ',' << y;
        }
    }
}

// Two vertices off the screen (the camera moved 2 units right: screen x = X + 2, the vertices at
// x = -2, 6, -2): every covered pixel is still rendered, each the mix of all three vertex colours with
// the barycentrics by hand: lambda_1 = (x + 2.5)/8, lambda_2 = (y + 0.5)/8, lambda_0 the rest.
TEST(Gouraud, VerticesOffScreen) {
    world s = one_triangle(false);
    s.cam.position.x = s.cam.target.x = 2.0;
    const rasterised r = rasterise(s);
    const shaded_image img = render_gouraud(r, device_config{});
    std::array<rgb, 3> vc;
    for (int i = 0; i < 3; ++i) {
        pixel_geometry g;
        const glm::dvec3 nv = s.objects[0].geometry.normals[i];
        g.n = {cnum(nv.x, nullptr), cnum(nv.y, nullptr), cnum(nv.z, nullptr)};
        g.v = {cnum(0.0, nullptr), cnum(0.0, nullptr), cnum(1.0, nullptr)};
        g.l = {g.v};
        g.h = {g.v};
        vc[i] = shade_device(g, s.objects[0].mat, s.lights, device_config{});
    }
    std::size_t covered = 0;
    for (unsigned y = 0; y < 8; ++y)
        for (unsigned x = 0; x < 8; ++x) {
            const std::size_t i = r.index(x, y);
            ASSERT_EQ(img.covered[i], r.covered(x, y) ? 1 : 0) << x << ',' << y;
            if (!r.covered(x, y)) continue;
            ++covered;
            const double l1 = (x + 2.5) / 8.0, l2 = (y + 0.5) / 8.0;
            const rgb want = (1.0 - l1 - l2) * vc[0] + l1 * vc[1] + l2 * vc[2];
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(img.value[i][ch], want[ch], 1e-11) << x << ',' << y;
        }
    // Line y holds the centres x + 2.5 < 7.5 - y: x = 0 .. 4 - y on lines 0 .. 4, 15 pixels.
    EXPECT_EQ(covered, 15u);
}

// Equal vertex normals, a directional light, an orthographic view: every vertex has the same colour
// and so has every pixel of render_device (N, V, L, H constant), which Gouraud must reproduce.
TEST(Gouraud, FlatNormalsEqualRenderDevice) {
    const world s = flat_triangle(0.5, 32);
    const rasterised r = rasterise(s);
    const shaded_image g = render_gouraud(r, device_config{});
    const shaded_image d = render_device(r, device_config{});
    for (unsigned y = 0; y < 8; ++y)
        for (unsigned x = 0; x < 8; ++x) {
            const std::size_t i = r.index(x, y);
            ASSERT_EQ(g.covered[i], d.covered[i]);
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(g.value[i][ch], d.value[i][ch], 1e-10) << x << ',' << y;
        }
    EXPECT_LT(d.value[0].x, 250.0);  // not clamped: the comparison sees the lighting
    EXPECT_GT(d.value[0].x, 100.0);
}

// ---- Lyon ----

// The single triangle (orthographic, directional light, n = 32 so gamma = 32: 5 squarings), by hand:
//   geometry: set-up U_N 3 x 3 x (3 mul, 2 add) = 27 mul, 18 add; run starts 7 x 3 x (2 mul, 2 add)
//     = 42 mul, 42 add; steps 21 x 3 add; per pixel lyon_normalize (8 mul, 5 add) and H (3 add; 6 mul,
//     2 add, sqrt, div): 14 mul, 10 add, 1 sqrt, 1 div. mul 27 + 42 + 28 x 14 = 461,
//     add 18 + 42 + 63 + 280 = 403, sqrt 28, div 28 (517 long: scan-line Phong's 517 too, its
//     division and square root of N traded for multiplications).
//   shading per pixel: N.L (3 mul, 2 add), D = N - H (3 add), D.D (3 mul, 2 add), x (1 mul),
//     1 - x (1 add), 5 squarings, per channel k_d I N.L + k_s I S (2 mul, 2 add): 18 mul, 14 add,
//     2 cmp (N.L > 0, max(0, 1 - x)); 28 pixels: 504 mul, 392 add, 56 cmp.
TEST(Lyon, SingleTriangleCountedByHand) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    render_stats st;
    scheme_state state;
    render_lyon(r, &st, &state);
    EXPECT_EQ(st.geometry, counts(461, 28, 28, 403)) << st.geometry;
    op_counts shading = counts(504, 0, 0, 392);
    shading.cmp = 56;
    EXPECT_EQ(st.shading, shading) << st.shading;
    EXPECT_EQ(state.per_triangle_words, 12u);  // U_N only: 3 x (a, b, c, value)
    EXPECT_TRUE(state.fixed.empty());
    // Perspective: U_N, U_P and Q stepped, 7 x 4 words.
    const world p = one_triangle(true);
    render_lyon(rasterise(p), nullptr, &state);
    EXPECT_EQ(state.per_triangle_words, 28u);
}

// n = gamma = 32: the power is cos^n exactly for a unit N, so Lyon differs from exact Phong only by
// its normalisation. Per pixel, hand barycentrics give s = |sum lambda_i N_i|^2 and u = s - 1 < 0;
// the normal's length after lyon_normalize is 1 + eps with |eps| <= E = (5/16)|u|^3 (1 - |u|)^(-7/2)
// (LyonNormalize above). Then the diffuse term moves by at most 255 k_d E and D.D/2 = 1 - cos +
// eps (1 - cos) + eps^2/2, so the power (slope at most gamma (n/gamma) = n) by at most
// 255 k_s n (E + E^2/2). Lyon must stay within that of render_phong, and differ somewhere.
TEST(Lyon, TaylorNormalisationAgainstPhongWithinHandBound) {
    const world s = one_triangle(false);
    const rasterised r = rasterise(s);
    const shaded_image lyon = render_lyon(r), phong = render_phong(r);
    const material& m = s.objects[0].mat;
    ASSERT_EQ(m.n, 32u);
    const auto& nv = s.objects[0].geometry.normals;
    double worst = 0.0;
    for (unsigned y = 0; y < 8; ++y)
        for (unsigned x = 0; x + y < 7; ++x) {
            const auto b = barycentrics(x, y);
            const glm::dvec3 n = b[0] * nv[0] + b[1] * nv[1] + b[2] * nv[2];
            const double u = std::abs(glm::dot(n, n) - 1.0);
            const double e = 5.0 / 16.0 * u * u * u * std::pow(1.0 - u, -3.5);
            const double bound = 255.0 * (m.k_d.x * e + m.k_s.x * m.n * (e + e * e / 2.0)) + 1e-9;
            const std::size_t i = r.index(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                const double d = std::abs(lyon.value[i][ch] - phong.value[i][ch]);
                EXPECT_LE(d, bound) << x << ',' << y;
                worst = std::max(worst, d);
            }
        }
    EXPECT_GT(worst, 1e-6);
}

// Unit normals everywhere (flat), n = 20 (gamma 16, f = 1.25), the light 0.2 rad off the view: N.H =
// cos 0.1 at every pixel, lambda = 1 - cos 0.1. The diffuse terms agree; the specular is below exact
// Phong's by at most 255 k_s cos^n n f lambda^2 / (2 (1 - f lambda)) (LyonLaw above), and above 0.
TEST(Lyon, PowerAgainstPhongWithinHandBound) {
    const world s = flat_triangle(0.2, 20);
    const rasterised r = rasterise(s);
    const shaded_image lyon = render_lyon(r), phong = render_phong(r);
    const double lambda = 1.0 - std::cos(0.1), f = 1.25;
    const double bound = 255.0 * 0.4 * std::pow(std::cos(0.1), 20) * 20 * f * lambda * lambda / (2.0 * (1.0 - f * lambda));
    for (unsigned y = 0; y < 7; ++y)
        for (unsigned x = 0; x + y < 7; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                const double d = phong.value[r.index(x, y)][ch] - lyon.value[r.index(x, y)][ch];
                EXPECT_GT(d, 1e-6) << x << ',' << y;
                EXPECT_LE(d, bound + 1e-9) << x << ',' << y;
            }
    // A fixed gamma = n/4 = 5 is not a power of two; 4 is: f = 5, further from exact, still below it.
    EXPECT_THROW(render_lyon(r, nullptr, nullptr, 5), scene_error);
    const shaded_image g4 = render_lyon(r, nullptr, nullptr, 4);
    EXPECT_LT(g4.value[0].x, lyon.value[0].x);
}

// ---- The head: every covered pixel, counts split as the hand counts say ----

// Perspective camera, one directional light. Gouraud: per distinct vertex V and H normalised
// (16 long), per triangle 27 mul of colour planes, per run start 6 mul. Lyon: per triangle 54 mul
// (U_N, U_P planes), per run start 14 mul, per pixel 1/Q (1 div), P and N times it (6 mul),
// lyon_normalize (8 mul), V and H normalised (16 long): 31 long. Their errors against exact Phong
// printed; Lyon's well below Gouraud's (the highlight is not lost between vertices).
TEST(Peers, HeadEveryCoveredPixelAndCounts) {
    const world s = builtin_scene("head", SHADING_SOURCE_DIR, 128, 128);
    const rasterised r = rasterise(s);
    // The triangles the frame shows (a set-up whose pixels were all overdrawn is not one) and their
    // distinct vertices.
    std::set<int32_t> shown;
    for (int32_t t : r.tri)
        if (t >= 0) shown.insert(t);
    std::set<std::pair<uint32_t, uint32_t>> vertices;
    for (int32_t t : shown) {
        const triangle_setup& ts = r.setups[static_cast<std::size_t>(t)];
        for (uint32_t v : s.objects[ts.object].geometry.triangles[ts.triangle]) vertices.insert({ts.object, v});
    }
    const std::size_t T = shown.size(), V = vertices.size(), R = run_starts(r), P = r.covered_pixels();
    render_stats g, l, p;
    const shaded_image ig = render_gouraud(r, device_config{}, &g), il = render_lyon(r, &l), ip = render_phong(r, &p);
    EXPECT_EQ(g.pixels, P);
    EXPECT_EQ(l.pixels, P);
    for (std::size_t i = 0; i < ip.covered.size(); ++i) {
        ASSERT_EQ(ig.covered[i], ip.covered[i]) << i;
        ASSERT_EQ(il.covered[i], ip.covered[i]) << i;
    }
    EXPECT_EQ(g.geometry.long_ops(), 16 * V + 27 * T + 6 * R);
    EXPECT_EQ(l.geometry.long_ops(), 54 * T + 14 * R + 31 * P);
    EXPECT_EQ(l.geometry.div, 3 * P);  // 1/Q and V, H: none for N
    EXPECT_EQ(l.geometry.sqrt, 2 * P);
    const image_diff dg = compare_images(ig, ip), dl = compare_images(il, ip);
    std::printf("head 128: Gouraud NMSE %.3g (largest %.1f levels), Lyon NMSE %.3g (largest %.1f levels); "
                "long operations a pixel: Gouraud %.2f, Lyon %.2f, Phong %.2f\n",
                dg.nmse, dg.max_abs, dl.nmse, dl.max_abs, double(g.total().long_ops()) / P,
                double(l.total().long_ops()) / P, double(p.total().long_ops()) / P);
    EXPECT_LT(dl.nmse, dg.nmse);
}

}  // namespace test_peers_gl
