// The race (src/golden_pipeline/race.h) against independent values: on the one-triangle scene the
// Phong 1975 row's state by hand, its operations from render_phong_scanline directly and its
// normalisations counted by hand; rounded() on hand values; on the head at 128 every row's image
// from the scheme's own golden model or renderer called directly; the frozen configuration against
// the values race.cpp states; bad input refused; and the procedural OBJ (test_obj.h) read back by
// the loader as it was generated. Plain C++, no simulation: these tests may share a process.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "golden_pipeline/cells.h"
#include "golden_pipeline/frame_setup.h"
#include "golden_pipeline/race.h"
#include "scene/gouraud.h"
#include "scene/mesh.h"
#include "scene/raster.h"
#include "scene/shade.h"
#include "testbenches/scene/test_obj.h"
#include "testbenches/scene/tiny_scenes.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_race {

namespace {

using namespace shading;
using namespace shading::pipeline;

scene::device_config sqmul() {
    scene::device_config d;
    d.device = scene::specular_device::sqmul;
    return d;
}

bool same_image(const scene::shaded_image& a, const scene::shaded_image& b) {
    return a.width == b.width && a.height == b.height && a.covered == b.covered && a.value == b.value;
}

// ---- The one-triangle scene (tiny_scenes.h): one triangle live, so the state is its words alone ----

// Phong 1975's words a live triangle holds (scanline.h): per stepped component its plane a, b, c and
// its stepped value. Orthographic under a directional light only U_N (3 components): 12 words; with
// the perspective camera U_P (3) and Q (1) too: 28. Normalisations a pixel: N and H, and with the
// perspective camera V as well (orthographic V and the directional L are constants): 2 or 3, each a
// square root and a division that one reciprocal square root replaces.
struct one_triangle_case {
    bool perspective;
    uint64_t state_bits;           // 1 x words x 32
    double normalisations;         // a pixel
};

TEST(RaceOneTriangle, PhongRowsByHand) {
    for (const one_triangle_case& t : {one_triangle_case{true, 1 * 28 * 32, 3.0}, one_triangle_case{false, 1 * 12 * 32, 2.0}}) {
        SCOPED_TRACE(t.perspective ? "perspective" : "orthographic");
        const scene::world w = scene::tiny::one_triangle(t.perspective);
        const scene::rasterised r = scene::rasterise(w);
        const auto rows = run_race(r, sqmul(), frozen_race_config(), {"phong1975", "phong1975_device"});
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_EQ(rows[0].scheme, "phong1975");
        EXPECT_EQ(rows[1].scheme, "phong1975_device");
        for (const race_row& row : rows) {
            EXPECT_EQ(row.state_bits, t.state_bits) << row.scheme;
            EXPECT_NEAR(row.long_ops - row.long_ops_rsqrt, t.normalisations, 1e-12) << row.scheme;
        }
        // The frozen configuration walks edges: the scan-line Phong so, over its covered pixels.
        scene::render_stats st;
        const scene::shaded_image direct = scene::render_phong_scanline(r, &st, nullptr, true);
        const double px = double(r.covered_pixels());
        ASSERT_GT(px, 0.0);
        EXPECT_DOUBLE_EQ(rows[0].long_ops, double(st.total().long_ops()) / px);
        EXPECT_DOUBLE_EQ(rows[0].adds, double(st.total().add) / px);
        EXPECT_TRUE(same_image(rows[0].image, direct));
        EXPECT_LT(rows[0].frame_buffer.nmse, 1e-20);
        EXPECT_EQ(rows[0].frame_buffer.pixels, r.covered_pixels());
        // The device row: the same geometry, the device's operations a pixel instead of cos^n's.
        EXPECT_GT(rows[1].frame_buffer.nmse, 0.0);
    }
    // Orthographic, edges walked: the geometry is hand-counted in test_scanline (369 mul, 56 div,
    // 56 sqrt over the 28 pixels); what remains of a pixel's long operations is its shading.
    const scene::world w = scene::tiny::one_triangle(false);
    const scene::rasterised r = scene::rasterise(w);
    ASSERT_EQ(r.covered_pixels(), 28u);
    scene::render_stats st;
    scene::render_phong_scanline(r, &st, nullptr, true);
    const auto rows = run_race(r, sqmul(), frozen_race_config(), {"phong1975"});
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_DOUBLE_EQ(rows[0].long_ops * 28.0, double(369 + 56 + 56 + st.shading.long_ops()));
}

// ---- rounded(): to nearest, halves away from zero (std::round), clamped to 0..255 first ----

TEST(Race, RoundedByHand) {
    scene::shaded_image s;
    s.width = 3;
    s.height = 2;
    s.covered = {1, 1, 1, 1, 1, 0};
    s.value = {{0.49, 0.5, 254.6}, {300.0, -3.0, 254.5}, {1.5, 2.5, 127.49999}, {0.0, 255.0, 100.0},
               {-0.4, 1e9, 0.51}, {0.0, 0.0, 0.0}};
    const scene::shaded_image o = rounded(s);
    ASSERT_EQ(o.value.size(), 6u);
    const std::vector<scene::rgb> want{{0, 1, 255}, {255, 0, 255}, {2, 3, 127}, {0, 255, 100}, {0, 255, 1}, {0, 0, 0}};
    for (std::size_t i = 0; i < want.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(o.value[i][ch], want[i][ch]) << i << "," << ch;
    EXPECT_EQ(o.covered, s.covered);
    EXPECT_EQ(o.width, 3u);
}

// ---- The frozen configuration: the values race.cpp's comment states ----

TEST(Race, FrozenConfigurationAsStated) {
    const race_config c = frozen_race_config();
    EXPECT_EQ(c.lines.length, length_policy::adaptive);
    EXPECT_EQ(c.lines.degree, degree_policy::cubic);
    EXPECT_DOUBLE_EQ(c.lines.length_tol, 1.80);
    EXPECT_EQ(c.lines.m_max, 5u);
    EXPECT_EQ(c.lines.above_slack, 2);
    EXPECT_TRUE(c.lines.split_at_check);
    EXPECT_TRUE(c.lines.carry_samples);
    EXPECT_EQ(c.lines.eval, evaluator::fd);
    EXPECT_TRUE(c.lines.walk_edges);
    EXPECT_EQ(c.cell_lines.eval, evaluator::fd);
    EXPECT_EQ(c.cell_lines.length, length_policy::adaptive);
    EXPECT_TRUE(c.cell_lines.walk_edges);
    EXPECT_DOUBLE_EQ(c.cells.tol, 0.85);
    EXPECT_DOUBLE_EQ(c.fast_phong_budget, 8.0);
    EXPECT_TRUE(c.walk_edges);
    EXPECT_NO_THROW(validate(c.lines));
    EXPECT_NO_THROW(validate(c.cell_lines));
    EXPECT_NO_THROW(validate(c.cells));
}

// ---- Bad input ----

TEST(Race, BadInputThrows) {
    const scene::world w = scene::tiny::one_triangle(false);
    const scene::rasterised r = scene::rasterise(w);
    race_config c = frozen_race_config();
    c.cells.tol = -0.5;
    EXPECT_THROW(run_race(r, sqmul(), c), scene::scene_error);
    c = frozen_race_config();
    c.lines.m_max = 9;  // the units take m = 2..6
    EXPECT_THROW(run_race(r, sqmul(), c), scene::scene_error);
    c = frozen_race_config();
    c.cell_lines.above_slack = 7;
    EXPECT_THROW(run_race(r, sqmul(), c), scene::scene_error);
    // frame_constants_of's rule: the hardware schemes shade exactly one light.
    scene::world two = scene::tiny::one_triangle(false);
    two.lights.push_back(two.lights.front());
    const scene::rasterised r2 = scene::rasterise(two);
    EXPECT_THROW(run_race(r2, sqmul(), frozen_race_config()), scene::scene_error);
    EXPECT_THROW(run_race(r2, sqmul(), frozen_race_config(), {"gouraud"}), scene::scene_error);
    // (A scene with no light never reaches the race: rasterise refuses it.)
}

// ---- The head at 128, n = 20, the square-and-multiply device: the race as render_race runs it ----

class RaceHead : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        head_ = std::make_unique<frame_setup>("head", SHADING_SOURCE_DIR, 128, "sqmul", true, std::vector<double>{}, 20);
        rows_ = std::make_unique<std::vector<race_row>>(run_race(head_->r, head_->dev, frozen_race_config()));
    }
    static void TearDownTestSuite() {
        rows_.reset();
        head_.reset();
    }
    static const race_row& row(const std::string& scheme) {
        for (const race_row& r : *rows_)
            if (r.scheme == scheme) return r;
        throw std::runtime_error("no row " + scheme);
    }
    static std::unique_ptr<frame_setup> head_;
    static std::unique_ptr<std::vector<race_row>> rows_;
};
std::unique_ptr<frame_setup> RaceHead::head_;
std::unique_ptr<std::vector<race_row>> RaceHead::rows_;

// The nine schemes of race.h's list, each once, in its order.
TEST_F(RaceHead, EverySchemeOnceInOrder) {
    const std::vector<std::string> want{"phong1975", "phong1975_device", "gouraud", "fast_phong", "fast_phong_table",
                                        "fast_phong_split", "lyon", "lines", "cells"};
    EXPECT_EQ(race_schemes(), want);
    ASSERT_EQ(rows_->size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ((*rows_)[i].scheme, want[i]);
        EXPECT_TRUE((*rows_)[i].frozen);
        EXPECT_EQ((*rows_)[i].frame_buffer.pixels, head_->pixels) << want[i];
    }
}

// Each row's image is its scheme's golden model or renderer called directly at the frozen settings.
TEST_F(RaceHead, ImagesAreTheSchemesOwn) {
    const race_config c = frozen_race_config();
    const scene::rasterised& r = head_->r;
    const cell_plan cp = make_cell_plan(r, head_->k, head_->dev, c.cell_lines, c.cells);
    EXPECT_TRUE(same_image(row("cells").image, to_image(golden_cell_frame(cp, head_->k, head_->dev, c.cell_lines))));
    const plan lp = make_plan(r, head_->k, head_->dev, c.lines);
    EXPECT_TRUE(same_image(row("lines").image, to_image(golden_frame(lp, head_->k, head_->dev, c.lines))));
    EXPECT_TRUE(same_image(row("gouraud").image, scene::render_gouraud(r, head_->dev)));
    EXPECT_TRUE(same_image(row("phong1975").image, scene::render_phong_scanline(r, nullptr, nullptr, true)));
    EXPECT_TRUE(same_image(row("phong1975_device").image, scene::render_device_scanline(r, head_->dev, nullptr, true)));
}

// Phong 1975 is exact Phong to rounding; every other scheme differs from it somewhere. A reciprocal
// square root never costs more than the square root and division it replaces.
TEST_F(RaceHead, ErrorsAndConventions) {
    for (const race_row& r : *rows_) {
        SCOPED_TRACE(r.scheme);
        if (r.scheme == "phong1975")
            EXPECT_LT(r.frame_buffer.nmse, 1e-20);
        else
            EXPECT_GT(r.frame_buffer.nmse, 0.0);
        EXPECT_LE(r.long_ops_rsqrt, r.long_ops);
        EXPECT_GT(r.long_ops, 0.0);
        EXPECT_GT(r.state_bits, 0u);
        EXPECT_EQ(r.image.width, 128u);
    }
    // The scan-line Phong's long operations a covered pixel, as frame_setup counts them (walking edges).
    EXPECT_DOUBLE_EQ(row("phong1975").long_ops, head_->scanline);
}

// `only`: just the named schemes, in the race's order whatever the order named, each the full race's row.
TEST_F(RaceHead, OnlyTheNamedSchemes) {
    const auto some = run_race(head_->r, head_->dev, frozen_race_config(), {"cells", "gouraud"});
    ASSERT_EQ(some.size(), 2u);
    EXPECT_EQ(some[0].scheme, "gouraud");
    EXPECT_EQ(some[1].scheme, "cells");
    for (const race_row& s : some) {
        const race_row& full = row(s.scheme);
        EXPECT_TRUE(same_image(s.image, full.image)) << s.scheme;
        EXPECT_EQ(s.long_ops, full.long_ops) << s.scheme;
        EXPECT_EQ(s.state_bits, full.state_bits) << s.scheme;
    }
    EXPECT_EQ(run_race(head_->r, head_->dev, frozen_race_config(), {"lyon"}).size(), 1u);
}

// ---- The procedural OBJ (testbenches/scene/test_obj.h), through the project's loader ----

std::string temp_obj(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("shading_test_race_" + name + ".obj")).string();
}

// A blob of 16 segments: 2 poles + 7 rings of 16 = 114 vertices, 16 x 14 = 224 triangles (16 a pole
// fan, 2 x 16 x 6 between the rings); the cluster six of them. Read back as written (17 digits), every
// corner with its normal, no quad; every radius within the displacement's bound 1 +- 0.27.
TEST(TestObj, WrittenFileLoadsAsGenerated) {
    for (const std::string shape : {"blob", "cluster"}) {
        SCOPED_TRACE(shape);
        const unsigned parts = shape == "blob" ? 1 : 6;
        const scene::mesh m = tb::test_obj::make_shape(shape, 16);
        ASSERT_EQ(m.positions.size(), parts * 114u);
        ASSERT_EQ(m.triangles.size(), parts * 224u);
        const std::string path = temp_obj(shape);
        ASSERT_TRUE(tb::test_obj::write_obj(m, path, "test"));
        const scene::mesh l = scene::load_obj(path);
        std::filesystem::remove(path);
        EXPECT_TRUE(l.file_had_normals);
        EXPECT_EQ(l.file_faces, parts * 224u);
        EXPECT_EQ(l.file_quads, 0u);
        ASSERT_EQ(l.positions.size(), m.positions.size());
        ASSERT_EQ(l.triangles, m.triangles);
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            EXPECT_LT(glm::length(l.positions[i] - m.positions[i]), 1e-14) << i;
            EXPECT_LT(glm::length(l.normals[i] - m.normals[i]), 1e-14) << i;
        }
        if (shape == "blob")
            for (const auto& p : m.positions) {
                EXPECT_GE(glm::length(p), 0.73);
                EXPECT_LE(glm::length(p), 1.27);
            }
    }
    EXPECT_TRUE(tb::test_obj::make_shape("teapot", 16).positions.empty());
}

// The analytic normals against the faces' (scene::compute_normals, angle-weighted) on a fine blob:
// they agree to within a few degrees everywhere and closely on average, and every face's winding
// (its cross product) points the way its corners' normals do: outward.
TEST(TestObj, NormalsAgreeWithTheFaces) {
    const scene::mesh m = tb::test_obj::make_shape("blob", 256);
    scene::mesh faces = m;
    scene::compute_normals(faces, scene::normal_weighting::angle);
    double worst = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < m.normals.size(); ++i) {
        const double a = std::acos(std::min(1.0, glm::dot(m.normals[i], faces.normals[i])));
        worst = std::max(worst, a);
        sum += a;
    }
    const double deg = 180.0 / 3.14159265358979323846;
    EXPECT_LT(worst * deg, 5.0);
    EXPECT_LT(sum / double(m.normals.size()) * deg, 0.5);
    std::size_t inward = 0;
    for (const auto& t : m.triangles) {
        const glm::dvec3 c = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
        inward += glm::dot(c, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) <= 0.0;
    }
    EXPECT_EQ(inward, 0u);
}

}  // namespace

}  // namespace test_race
