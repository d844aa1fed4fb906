// The components study's pieces (components.h): the parts' frame constants add up to the sum's
// per-pixel shading through every device, and the counting helpers against hand-worked plans.
#include <gtest/gtest.h>

#include "components.h"
#include "scene/world.h"
#include "testbenches/pipeline/plan_test_fixtures.h"  // interval_at

namespace {

using namespace shading;
using namespace shading::pipeline;
using namespace shading::study;

// Per-pixel shading of ambient + diffuse and of specular alone, added and saturated, is the sum's
// per-pixel shading (the sample stage forms the sum in one go): on the head and the sphere, every
// device. Both parts must light some pixel, or the test would prove nothing.
TEST(Components, PartsAddUpToTheSum) {
    for (const char* name : {"head", "sphere"}) {
        const scene::world w = scene::builtin_scene(name, SHADING_SOURCE_DIR, 96, 96);
        const scene::rasterised r = scene::rasterise(w);
        const frame_constants k = frame_constants_of(w);
        for (scene::specular_device d : {scene::specular_device::patent, scene::specular_device::ua22802,
                                         scene::specular_device::squared}) {
            const scene::device_config dev{d, overflow_mode::saturate};
            const frame sum = per_pixel_frame(r, k, dev), dif = per_pixel_frame(r, diffuse_part(k), dev),
                        spec = per_pixel_frame(r, specular_part(k), dev);
            std::size_t lit_d = 0, lit_s = 0, differ = 0;
            const frame added = add_saturated(dif, spec);
            for (std::size_t i = 0; i < sum.px.size(); ++i) {
                lit_d += dif.px[i][1] > 0;
                lit_s += spec.px[i][1] > 0;
                differ += added.px[i] != sum.px[i];
            }
            EXPECT_GT(lit_d, 1000u) << name;
            EXPECT_GT(lit_s, 100u) << name;
            EXPECT_EQ(differ, 0u) << name << ", device " << int(d);
        }
    }
}

// Saturation at the pixel format's largest code (0xFFFF), per channel.
TEST(Components, AddSaturatesPerChannel) {
    frame a, b;
    a.px = {{0xFF00, 10, 0}};
    b.px = {{0x0200, 20, 0xFFFF}};
    EXPECT_EQ(add_saturated(a, b).px[0], (rgb_codes{0xFFFF, 30, 0xFFFF}));
}

const auto& job = plan_test::interval_at;

// Sample pixels by hand: a quadratic of 4 at 0 (0, 2, 4), an exact pixel at 5, a cubic of 8 at 8
// (case 1: 8, 10, 12, 16; case 2: 8, 12, 14, 16).
TEST(Components, SamplePixelsByHand) {
    plan p;
    p.width = 20;
    p.height = 1;
    p.jobs = {job(0, 2, true), job(5, 0, false), job(8, 3, false)};
    auto on = [](const std::vector<uint8_t>& f) {
        std::vector<unsigned> x;
        for (unsigned i = 0; i < f.size(); ++i)
            if (f[i]) x.push_back(i);
        return x;
    };
    EXPECT_EQ(on(sample_pixels(p, interp::sample_set::case1)), (std::vector<unsigned>{0, 2, 4, 5, 8, 10, 12, 16}));
    EXPECT_EQ(on(sample_pixels(p, interp::sample_set::case2)), (std::vector<unsigned>{0, 2, 4, 5, 8, 12, 14, 16}));
    // A cubic of 8 at 16 cut to 4 pixels: its t = 1 point (24) lies past the 20-pixel line.
    interval_job cut = job(16, 3, false);
    cut.len = 4;
    p.jobs.push_back(cut);
    EXPECT_EQ(on(sample_pixels(p, interp::sample_set::case1)), (std::vector<unsigned>{0, 2, 4, 5, 8, 10, 12, 16, 18}));
}

// The diffuse plan samples 0, 2, 4 and computed 4 points (a check at 3); the specular plan samples
// pixel 2 and computed 2 points. Shared samples 1, unsent points 1 + 1: at least 4 - 1 - 1 - 1 = 1
// diffuse-only point (the truth is 2 or 3, by where the specular's unsent point lies). With 9
// specular points computed the bound is 0, not negative.
TEST(Components, DiffuseOnlyPointsBoundByHand) {
    plan d, e;
    d.width = e.width = 8;
    d.height = e.height = 1;
    d.jobs = {job(0, 2, true)};
    d.geometry_points = 4;
    e.jobs = {job(2, 0, false)};
    e.geometry_points = 2;
    const auto sd = sample_pixels(d, interp::sample_set::case1), se = sample_pixels(e, interp::sample_set::case1);
    EXPECT_EQ(diffuse_only_points_bound(d, sd, e, se), 1u);
    e.geometry_points = 9;
    EXPECT_EQ(diffuse_only_points_bound(d, sd, e, se), 0u);
    // Disjoint samples and nothing unsent: every diffuse point is diffuse-only.
    e.jobs = {job(6, 0, false)};
    e.geometry_points = 1;
    d.geometry_points = 3;
    EXPECT_EQ(diffuse_only_points_bound(d, sd, e, sample_pixels(e, interp::sample_set::case1)), 3u);
}

}  // namespace
