// The golden pipeline (pipeline.h): the sample stage against hand-worked codes, one interval against
// the real-valued interpolation reference (src/reference/interp_reference.h), whole frames against
// the scene's per-pixel device reference, the error measures and the operation counts against hand
// sums. No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "golden/interp_golden.h"
#include "golden_pipeline/pipeline.h"
#include "reference/interp_reference.h"
#include "scene/scene.h"

#include "golden_test_fixtures.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_golden {

using namespace shading;
using namespace shading::pipeline;
using namespace golden_test;


// ---- Sample stage ----

// k_d*I = 153.0 (0.6 x 255) at N.L = 1 (0x8000): 153 x 256 x 32768 >> 15 = 153 x 256, exactly 153.0
// levels.
TEST(PipelineSample, DiffuseHandWorked) {
    const frame_constants k = diffuse_only(153);
    EXPECT_EQ(golden_sample(patent, k, diffuse_sample(0x8000)), (rgb_codes{153 * 256, 153 * 256, 153 * 256}));
    // 200 x 0.5: 200 x 16384 >> 7 = 25600 = 100.0 levels.
    EXPECT_EQ(golden_sample(patent, diffuse_only(200), diffuse_sample(0x4000))[1], 25600u);
    // Floor: 255 x 256 x 32767 / 32768 = 255 x 32767 / 128 = 65278.0078 -> 65278.
    EXPECT_EQ(golden_sample(patent, diffuse_only(255), diffuse_sample(0x7FFF))[0], 65278u);
    // 3 x 256 x 1 / 32768 < 1 LSB: floored to 0, the ambient alone remains.
    EXPECT_EQ(golden_sample(patent, diffuse_only(3, 77), diffuse_sample(1))[2], 77u);
    // The fraction of k_d*I counts: 127.5 levels (0x7F80) at N.L = 1 is 0x7F80 = 127.5 levels,
    // where an 8-bit code would have been 127 or 128.
    frame_constants f = diffuse_only();
    f.kdi = {0x7F80, 0x7F80, 0x7F80};
    EXPECT_EQ(golden_sample(patent, f, diffuse_sample(0x8000))[0], 0x7F80u);
    // 100.25 (0x6440) x 0.75 (0x6000) = 75.1875 levels = 19248 (0x4B30), exact.
    f.kdi = {0x6440, 0, 0};
    EXPECT_EQ(golden_sample(patent, f, diffuse_sample(0x6000))[0], 0x4B30u);
}

// Per channel: the three channels' constants are independent.
TEST(PipelineSample, ChannelsIndependent) {
    frame_constants k = diffuse_only();
    k.kdi = {128 * 256, 64 * 256, 0};
    k.ambient = {1, 2, 3};
    EXPECT_EQ(golden_sample(patent, k, diffuse_sample(0x1000)), (rgb_codes{0x1001, 0x802, 3}));
}

// Ambient 255.0 (0xFF00) plus a full diffuse 255.0 is 510 levels: saturated to 0xFFFF (255.996).
TEST(PipelineSample, Saturates) {
    EXPECT_EQ(golden_sample(patent, diffuse_only(255, 0xFF00), diffuse_sample(0x8000)), (rgb_codes{0xFFFF, 0xFFFF, 0xFFFF}));
    // At the top without saturating: kdi 1 x 0x7F80 >> 7 = 0xFF, and 0xFF00 + 0xFF = 0xFFFF exactly.
    EXPECT_EQ(golden_sample(patent, diffuse_only(1, 0xFF00), diffuse_sample(0x7F80))[0], 0xFFFFu);
    EXPECT_EQ(golden_sample(patent, diffuse_only(1, 0xFE00), diffuse_sample(0x7F80))[0], 0xFEFFu);
}

// The specular term is the device's out code added in Q.8 as it is: against device_specular called
// directly, on every device, and 0 at cos_nh = 0 (so N.L <= 0 leaves the ambient alone).
TEST(PipelineSample, SpecularIsTheDeviceOutput) {
    frame_constants k = diffuse_only(100, 500);
    k.ksi = {255, 128, 7};
    for (const auto& dev : all_devices()) {
        for (uint32_t c : {0u, 0x4000u, 0x7800u, 0x7F00u, 0x8000u}) {
            const auto spec = scene::device_specular(dev, k.n, c, k.ksi);
            const auto s = golden_sample(dev, k, {c, 0x8000});
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_EQ(s[ch], std::min<uint64_t>(500 + 100 * 256 + spec[ch], 0xFFFF))
                    << scene::device_name(dev.device) << " cos " << c;
        }
        // N.L <= 0: the geometry side delivers both codes 0; ambient only.
        EXPECT_EQ(golden_sample(dev, k, {}), (rgb_codes{500, 500, 500})) << scene::device_name(dev.device);
    }
    // A highlight at full strength on the patent device is about k_s*I: 255 at cos 1 -> ~255 levels.
    EXPECT_NEAR(static_cast<double>(scene::device_specular(patent, 32, 0x8000, {255, 0, 0})[0]) / 256.0, 255.0, 1.0);
}

// sample_of: the codes of N.H and N.L of light 0; both 0 where N.L <= 0; N.H < 0 gives 0.
TEST(PipelineSample, SampleOf) {
    // N.L = 0.8 -> round(0.8 x 32768) = round(26214.4) = 26214; N.H = 1 -> 0x8000.
    EXPECT_EQ(sample_of(geometry(vec(0, 0, 1), vec(0.6, 0, 0.8), vec(0, 0, 1))), (sample_geometry{0x8000, 26214}));
    // N.L < 0 with N.H = 1: no highlight where the light does not reach.
    EXPECT_EQ(sample_of(geometry(vec(0, 0, 1), vec(0, 0.6, -0.8), vec(0, 0, 1))), (sample_geometry{0, 0}));
    // N.L = 0 exactly: gated too (shade.cpp needs N.L > 0).
    EXPECT_EQ(sample_of(geometry(vec(0, 0, 1), vec(1, 0, 0), vec(0, 0, 1))), (sample_geometry{0, 0}));
    // N.L > 0, N.H < 0: cos_nh 0; N.L = 0.5 -> 0x4000.
    EXPECT_EQ(sample_of(geometry(vec(0, 0, 1), vec(0, 0.8660254037844386, 0.5), vec(0, 0.6, -0.8))),
              (sample_geometry{0, 0x4000}));
    // Geometry without a light is a caller's error, not a dark pixel.
    scene::pixel_geometry none = geometry(vec(0, 0, 1), vec(0, 0, 1), vec(0, 0, 1));
    none.l.clear();
    none.h.clear();
    EXPECT_THROW(sample_of(none), scene::scene_error);
}

namespace {
scene::world one_light_world() {
    scene::world w;
    w.name = "hand";
    scene::material m;
    m.ambient = {0.05, 0.1, 1.0};
    m.k_d = {0.6, 0.3, 0.0};
    m.k_s = {0.4, 0.7, 1.0};
    m.n = 77;
    w.objects.push_back({"a", scene::mesh{}, m});
    w.objects.push_back({"b", scene::mesh{}, m});
    w.lights.push_back({scene::light::kind::directional, {0.0, 0.0, 1.0}, {1.0, 0.5, 1.0}});
    return w;
}
}  // namespace

// ksi = round(255 k_s I), kdi = round(255 x 256 x k_d I), ambient = round(255 x 256 x ambient).
TEST(PipelineSample, FrameConstantsHandWorked) {
    const frame_constants k = frame_constants_of(one_light_world());
    EXPECT_EQ(k.n, 77u);
    // k_s I = 0.4, 0.35, 1.0: 102, 89.25 -> 89, 255.
    EXPECT_EQ(k.ksi, (rgb_codes{102, 89, 255}));
    // k_d I = 0.6, 0.15, 0: 153 x 256 = 39168, 38.25 x 256 = 9792 (exact on Q8.8), 0.
    EXPECT_EQ(k.kdi, (rgb_codes{39168, 9792, 0}));
    // Rounded to the nearest Q8.8 code: 0.5 x 255 x 256 = 32640; 1/3 x 255 x 256 = 21760; clamped.
    EXPECT_EQ(kdi_code(0.5), 32640u);
    EXPECT_EQ(kdi_code(1.0 / 3.0), 21760u);
    EXPECT_EQ(kdi_code(1.7), 65280u);
    EXPECT_EQ(kdi_code(-0.2), 0u);
    // 0.05 x 255 x 256 = 3264, 0.1 -> 6528, 1.0 -> 65280.
    EXPECT_EQ(k.ambient, (rgb_codes{3264, 6528, 65280}));
}

// One material under one light: two lights, no light or differing materials throw, naming the scene.
TEST(PipelineSample, FrameConstantsRefusesWhatTheHardwareCannotShade) {
    auto expect_throw = [](const scene::world& w, const std::string& what) {
        try {
            frame_constants_of(w);
            ADD_FAILURE() << "no error for " << what;
        } catch (const scene::scene_error& e) {
            EXPECT_NE(std::string(e.what()).find("'hand'"), std::string::npos) << e.what();
        }
    };
    scene::world two = one_light_world();
    two.lights.push_back(two.lights.front());
    expect_throw(two, "two lights");
    scene::world none = one_light_world();
    none.lights.clear();
    expect_throw(none, "no light");
    scene::world differ = one_light_world();
    differ.objects[1].mat.n = 78;
    expect_throw(differ, "two materials");
}

// ---- Output clamp and one interval ----

// Q16.16 signed bus bits -> Q8.8: negatives 0, floor, overflow 0xFFFF.
TEST(PipelineInterval, OutputClamp) {
    EXPECT_EQ(golden_output_clamp(0xFFFFFFFFu), 0u);        // -1 LSB
    EXPECT_EQ(golden_output_clamp(0x80000000u), 0u);        // most negative
    EXPECT_EQ(golden_output_clamp(0xFFFF0000u), 0u);        // -1.0
    EXPECT_EQ(golden_output_clamp(0x00000000u), 0u);
    EXPECT_EQ(golden_output_clamp(0x000000FFu), 0u);        // 255/65536 floors to 0
    EXPECT_EQ(golden_output_clamp(0x00000100u), 1u);        // 1/256
    EXPECT_EQ(golden_output_clamp(0x00012345u), 0x123u);    // 1.137 -> 0x123 (floor)
    EXPECT_EQ(golden_output_clamp(0x00FFFFFFu), 0xFFFFu);   // 255.99998 -> 255.996
    EXPECT_EQ(golden_output_clamp(0x01000000u), 0xFFFFu);   // 256.0: above the pixel format
    EXPECT_EQ(golden_output_clamp(0x7FFFFFFFu), 0xFFFFu);   // largest positive
    EXPECT_EQ(golden_output_clamp(0x1234500012345ull), 0x123u);  // wires above the bus are not read
}

TEST(PipelineInterval, Names) {
    EXPECT_STREQ(evaluator_name(evaluator::horner), "horner");
    EXPECT_STREQ(evaluator_name(evaluator::fd), "fd");
}

// An exact pixel (m = 0, len 1, four equal samples) returns its sample, on both evaluators and
// every sample set and divider.
TEST(PipelineInterval, ExactPixelIsItsSample) {
    frame_constants k = diffuse_only(211, 1234);
    k.ksi = {200, 100, 50};
    for (const auto& dev : all_devices())
        for (uint32_t nh : {0u, 0x7000u, 0x7F80u, 0x8000u}) {
            interval_job job;
            job.m = 0;
            job.len = 1;
            const sample_geometry g{nh, 0x6543};
            job.s = {g, g, g, g};
            const rgb_codes want = golden_sample(dev, k, g);
            for (evaluator e : {evaluator::horner, evaluator::fd})
                for (auto set : {interp::sample_set::case1, interp::sample_set::case2})
                    for (auto div : {interp::div3_mode::shift_add, interp::div3_mode::exact}) {
                        const auto px = golden_interval(job, k, dev, e, set, div);
                        ASSERT_EQ(px.size(), 1u);
                        EXPECT_EQ(px[0], want) << evaluator_name(e) << " nh " << nh;
                    }
        }
    // The saturated sample 0xFFFF survives the coefficient unit and the clamp.
    interval_job job;
    job.s.fill({0, 0x8000});
    EXPECT_EQ(golden_interval(job, diffuse_only(255, 0xFF00), patent, evaluator::horner, interp::sample_set::case1,
                              interp::div3_mode::shift_add)[0],
              (rgb_codes{0xFFFF, 0xFFFF, 0xFFFF}));
}


// A linear ramp 1000 + 4000 t codes (t = k/16: 1000 + 250 k) is reproduced exactly by the cubic
// (exact divider; both sets) and by the quadratic, on both evaluators.
TEST(PipelineInterval, LinearReproducedExactly) {
    const frame_constants k = diffuse_only();
    const interval_job c1 = job_of({1000, 2000, 3000, 5000}, 4, false);  // t = 0, 1/4, 1/2, 1
    const interval_job c2 = job_of({1000, 3000, 4000, 5000}, 4, false);  // t = 0, 1/2, 3/4, 1
    const interval_job q = job_of({1000, 3000, 5000, 5000}, 4, true);    // t = 0, 1/2, 1
    for (evaluator e : {evaluator::horner, evaluator::fd}) {
        const auto p1 = golden_interval(c1, k, patent, e, interp::sample_set::case1, interp::div3_mode::exact);
        const auto p2 = golden_interval(c2, k, patent, e, interp::sample_set::case2, interp::div3_mode::exact);
        const auto pq = golden_interval(q, k, patent, e, interp::sample_set::case1, interp::div3_mode::shift_add);
        ASSERT_EQ(p1.size(), 16u);
        ASSERT_EQ(pq.size(), 16u);
        for (unsigned i = 0; i < 16; ++i) {
            const uint64_t want = 1000 + 250 * i;
            EXPECT_EQ(p1[i][0], want) << evaluator_name(e) << " case 1 pixel " << i;
            EXPECT_EQ(p2[i][1], want) << evaluator_name(e) << " case 2 pixel " << i;
            EXPECT_EQ(pq[i][2], want) << evaluator_name(e) << " quadratic pixel " << i;
        }
    }
}

// A true quadratic 1000 + 2000 t + 4000 t^2 (samples 1000, 3000, 7000): every product of the Horner
// unit is exact at m = 4, so each pixel is floor(1000 + 125 k + 15.625 k^2); a shorter interval
// (len 11) gives its first 11 pixels.
TEST(PipelineInterval, QuadraticHandWorked) {
    const frame_constants k = diffuse_only();
    for (evaluator e : {evaluator::horner, evaluator::fd})
        for (unsigned len : {16u, 11u}) {
            const auto px = golden_interval(job_of({1000, 3000, 7000, 7000}, 4, true, len), k, patent, e,
                                            interp::sample_set::case1, interp::div3_mode::shift_add);
            ASSERT_EQ(px.size(), len);
            for (unsigned i = 0; i < len; ++i)
                EXPECT_EQ(px[i][0], static_cast<uint64_t>(std::floor(1000 + 125.0 * i + 15.625 * i * i)))
                    << evaluator_name(e) << " pixel " << i;
        }
}

// A cubic through sample values of a real shading line (ref::line_intensity, as codes): at every pixel
// the Horner unit gives floor((P - e) / 256) with P the real cubic through the same codes (Q16.16 LSB
// units) and 0 <= e < 5 LSB: A and C floored by the exact divider (< 1 LSB each, times t^3 and t <= 1)
// and three Horner floors (< 3 LSB). With the shift-and-add divider, P is the real cubic with A and C
// times 129/128 (x * 43/128 = x/3 * 129/128, exact), and e < 3 LSB. FD lies 0..2 LSB above Horner
// (interp_golden.h), so the two pixels differ by at most one code.
TEST(PipelineInterval, CubicMatchesRealPolynomial) {
    const frame_constants k = diffuse_only();
    std::size_t checked = 0, fd_diff = 0;
    for (auto set : {interp::sample_set::case1, interp::sample_set::case2})
        for (auto div : {interp::div3_mode::exact, interp::div3_mode::shift_add})
            for (unsigned m = interp::m_min; m <= interp::m_max; ++m)
                for (double x0 = -0.9; x0 < 0.8; x0 += 0.137) {
                    const auto ts = ref::sample_ts(set);
                    const double width = 0.02 * (1u << m);
                    std::array<uint32_t, 4> codes{};
                    std::array<double, 4> vals{};
                    for (int i = 0; i < 4; ++i) {
                        // Up to 0x8000 through the diffuse-only sample stage: half the intensity.
                        codes[i] = static_cast<uint32_t>(ref::to_sample_code(0.5 * ref::line_intensity(x0 + width * ts[i])));
                        vals[i] = static_cast<double>(codes[i]);  // codes of Q8.8
                    }
                    ref::real_poly p = ref::cubic_coefs(vals, set);
                    double e_max = 5.0;
                    if (div == interp::div3_mode::shift_add) {
                        p.a *= 129.0 / 128.0;
                        p.c *= 129.0 / 128.0;
                        e_max = 3.0;
                    }
                    const interval_job job = job_of(codes, m, false);
                    const auto h = golden_interval(job, k, patent, evaluator::horner, set, div);
                    const auto f = golden_interval(job, k, patent, evaluator::fd, set, div);
                    for (unsigned i = 0; i < job.len; ++i) {
                        const double t = static_cast<double>(i) / (1u << m);
                        const double real_q16 = ref::eval(p, t) * 256.0;
                        auto clamp = [](double v) { return std::clamp(v, 0.0, 65535.0); };
                        const double hi = clamp(std::floor(real_q16 / 256.0));
                        const double lo = clamp(std::floor((real_q16 - e_max) / 256.0));
                        const double got = static_cast<double>(h[i][0]);
                        EXPECT_TRUE(got >= lo && got <= hi)
                            << "m " << m << " x0 " << x0 << " pixel " << i << ": " << got << " not in [" << lo << ", " << hi << "]";
                        const int64_t d = static_cast<int64_t>(f[i][0]) - static_cast<int64_t>(h[i][0]);
                        EXPECT_TRUE(d == 0 || d == 1) << "FD - Horner " << d << " at m " << m << " pixel " << i;
                        fd_diff += d != 0;
                        ++checked;
                    }
                }
    EXPECT_GT(checked, 2000u);
    RecordProperty("fd_differs", static_cast<int>(fd_diff));
}

// Intervals the hardware cannot take are refused with a clear error.
TEST(PipelineInterval, RejectsInvalidJobs) {
    const frame_constants k = diffuse_only();
    auto bad = [&](unsigned m, unsigned len, bool deg2) {
        interval_job job;
        job.m = m;
        job.len = len;
        job.deg2 = deg2;
        EXPECT_THROW(golden_interval(job, k, patent, evaluator::horner, interp::sample_set::case1,
                                     interp::div3_mode::shift_add),
                     scene::scene_error)
            << "m " << m << " len " << len;
    };
    bad(1, 2, false);                 // m below m_min
    bad(interp::m_max + 1, 1, false); // above m_max
    bad(3, 9, false);                 // len beyond 2^m
    bad(3, 0, false);                 // len 0
    bad(0, 2, false);                 // exact pixel of 2
    bad(0, 1, true);                  // exact pixel as a quadratic
}

}  // namespace test_pipeline_golden
