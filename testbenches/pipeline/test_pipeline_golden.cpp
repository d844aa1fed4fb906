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
#include "pipeline/pipeline.h"
#include "reference/interp_reference.h"
#include "scene/scene.h"

using namespace shading;
using namespace shading::pipeline;

namespace {

// Frame constants with no specular term (k_s*I = 0, so the device adds 0) and k_d*I = 128.0
// (Q8.8 0x8000): 0x8000 x cos_nl >> 15 = cos_nl, so a sample's code is ambient + cos_nl, chosen
// freely up to 0x8000. kdi in whole levels (times 256 here).
frame_constants diffuse_only(uint64_t kdi = 128, uint64_t ambient = 0) {
    kdi *= 256;
    frame_constants k;
    k.n = 32;
    k.ksi = {0, 0, 0};
    k.kdi = {kdi, kdi, kdi};
    k.ambient = {ambient, ambient, ambient};
    return k;
}

sample_geometry diffuse_sample(uint32_t cos_nl) { return {0, cos_nl}; }

scene::cvec3 vec(double x, double y, double z) { return {scene::cnum(x, nullptr), scene::cnum(y, nullptr), scene::cnum(z, nullptr)}; }

scene::pixel_geometry geometry(scene::cvec3 n, scene::cvec3 l, scene::cvec3 h) {
    scene::pixel_geometry g;
    g.n = n;
    g.v = vec(0.0, 0.0, 1.0);
    g.l = {l};
    g.h = {h};
    return g;
}

const scene::device_config patent{};

std::vector<scene::device_config> all_devices() {
    std::vector<scene::device_config> d;
    for (const auto& name : scene::device_names()) d.push_back({scene::parse_device(name), overflow_mode::saturate});
    return d;
}

}  // namespace

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

namespace {
// Sample codes at the points of a set for I(t) = codes, via diffuse_only (code = cos_nl).
interval_job job_of(const std::array<uint32_t, 4>& codes, unsigned m, bool deg2, unsigned len = 0) {
    interval_job job;
    job.m = m;
    job.len = len ? len : 1u << m;
    job.deg2 = deg2;
    for (int i = 0; i < 4; ++i) job.s[i] = diffuse_sample(codes[i]);
    return job;
}
}  // namespace

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

// ---- A whole frame ----

// A hand-built plan on an 8 x 2 frame (exact divider, so linear samples come out exact): line 0 a
// cubic of 4 (1000 + 4000 t: 1000, 2000, 3000, 4000) and an exact pixel; line 1 a quadratic of 3 of
// an interval of 4 (1000 + 4000 t: 1000, 2000, 3000). The maps say what each pixel went through.
TEST(PipelineFrame, GoldenFrameHandBuiltPlan) {
    plan p;
    p.width = 8;
    p.height = 2;
    interval_job a = job_of({1000, 2000, 3000, 5000}, 2, false);
    a.zone = 4;
    interval_job x;  // exact pixel at (4, 0)
    x.x0 = 4;
    x.s.fill(diffuse_sample(777));
    x.zone = 5;
    interval_job q = job_of({1000, 3000, 5000, 5000}, 2, true, 3);
    q.y = 1;
    q.x0 = 1;
    q.zone = 7;
    p.jobs = {a, x, q};
    plan_config c;
    c.div = interp::div3_mode::exact;
    for (evaluator e : {evaluator::horner, evaluator::fd}) {
        c.eval = e;
        const frame f = golden_frame(p, diffuse_only(), patent, c);
        ASSERT_EQ(f.px.size(), 16u);
        const std::vector<uint64_t> want{1000, 2000, 3000, 4000, 777, 0, 0, 0, 0, 1000, 2000, 3000, 0, 0, 0, 0};
        const std::vector<uint8_t> cov{1, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0};
        const std::vector<uint8_t> deg{3, 3, 3, 3, 1, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0, 0};
        const std::vector<uint8_t> len{2, 2, 2, 2, 0, 0, 0, 0, 0, 2, 2, 2, 0, 0, 0, 0};
        const std::vector<uint8_t> zone{4, 4, 4, 4, 5, 0, 0, 0, 0, 7, 7, 7, 0, 0, 0, 0};
        for (std::size_t i = 0; i < 16; ++i)
            EXPECT_EQ(f.px[i], (rgb_codes{want[i], want[i], want[i]})) << evaluator_name(e) << " pixel " << i;
        EXPECT_EQ(f.covered, cov);
        EXPECT_EQ(f.degree, deg);
        EXPECT_EQ(f.log2_len, len);
        EXPECT_EQ(f.zone, zone);
    }
    // An interval that leaves the frame is refused.
    p.jobs.push_back(job_of({1, 1, 1, 1}, 2, false));
    p.jobs.back().x0 = 5;
    EXPECT_THROW(golden_frame(p, diffuse_only(), patent, c), scene::scene_error);
}

// Per-pixel shading through the same device against the scene's double-precision device reference
// (render_device): the specular terms are the same codes, so per channel the two differ only by the
// sample stage's quantisation, bounded by
//   |kdi / 256 - 255 k_d I| x N.L   (k_d*I rounded to Q8.8; N.L <= 1)
// + kdi / 256 x 2^-16             (N.L rounded to Q1.15: at most half an LSB, 2^-16)
// + 1/256                   (the diffuse product floored to Q.8)
// + |ambient code / 256 - 255 ambient|  (the ambient rounded to Q8.8).
// The reference is clamped to 255 and golden_sample saturates at 255.996: both compared after
// min(., 255) (a clamp can only shrink a difference).
TEST(PipelineFrame, PerPixelFrameAgainstDeviceReference) {
    for (double kd : {0.6, 0.5, 0.66}) {  // 153 and 127.5 exact on Q8.8; 168.3 rounds to 168.30078
        scene::world w = scene::builtin_scene("sphere", SHADING_SOURCE_DIR, 32, 32);
        for (auto& o : w.objects) o.mat.k_d = {kd, kd, kd};
        const scene::rasterised r = scene::rasterise(w);
        const frame_constants k = frame_constants_of(w);
        const scene::material& m = w.objects.front().mat;
        const scene::light& l = w.lights.front();
        for (const auto& dev : all_devices()) {
            const frame f = per_pixel_frame(r, k, dev);
            const scene::shaded_image ref = scene::render_device(r, dev);
            ASSERT_EQ(f.covered, ref.covered);
            std::size_t n = 0;
            double worst = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double kdi_real = 255.0 * m.k_d[c] * l.intensity[c];
                const double kdi = static_cast<double>(k.kdi[c]) / 256.0;
                const double bound = std::abs(kdi - kdi_real) + kdi / 65536.0 + 1.0 / 256.0 +
                                     std::abs(static_cast<double>(k.ambient[c]) / 256.0 - 255.0 * m.ambient[c]) + 1e-9;
                for (std::size_t i = 0; i < f.px.size(); ++i) {
                    if (!f.covered[i]) {
                        EXPECT_EQ(f.px[i], (rgb_codes{0, 0, 0}));
                        continue;
                    }
                    EXPECT_EQ(f.degree[i], 1u);
                    const double got = std::min(static_cast<double>(f.px[i][c]) / 256.0, 255.0);
                    const double d = std::abs(got - ref.value[i][c]);
                    worst = std::max(worst, d);
                    EXPECT_LE(d, bound) << scene::device_name(dev.device) << " k_d " << kd << " pixel " << i << " channel " << c;
                    ++n;
                }
            }
            EXPECT_EQ(n, 3 * r.covered_pixels());
            EXPECT_GT(r.covered_pixels(), 200u);  // the sphere is a disc about 19 pixels across
            // With k_d*I on Q8.8 every difference stays within the floors: under 0.01 level, where an
            // 8-bit code (127.5 coded as 128) reached most of 0.5.
            EXPECT_LT(worst, 0.01) << scene::device_name(dev.device) << " k_d " << kd;
            EXPECT_GT(worst, 1.0 / 512.0) << "the floors of Q.8 do show: the measure can see them";
        }
    }
}

// ---- Error measures ----

TEST(PipelineMetrics, ToImage) {
    frame f;
    f.width = 2;
    f.height = 1;
    f.px = {rgb_codes{0x8000, 0xFFFF, 1}, rgb_codes{0, 0, 0}};
    f.covered = {1, 0};
    const scene::shaded_image img = to_image(f);
    EXPECT_EQ(img.width, 2u);
    EXPECT_EQ(img.height, 1u);
    EXPECT_EQ(img.covered, f.covered);
    EXPECT_EQ(img.value[0], scene::rgb(128.0, 255.99609375, 0.00390625));
    EXPECT_EQ(img.value[1], scene::rgb(0.0));
}

namespace {
scene::shaded_image image2x2(std::vector<scene::rgb> v, std::vector<uint8_t> cov) {
    scene::shaded_image img;
    img.width = img.height = 2;
    img.value = std::move(v);
    img.covered = std::move(cov);
    return img;
}
}  // namespace

// Hand-worked: over the reference's three covered pixels, differences 1, 2, -3 (one per pixel):
// sum d^2 = 14, sum ref^2 = 100 + 400 + 900 + 3 x 10000 = 31400, MSE = 14 / 9. The uncovered pixel's
// difference (50) is ignored.
TEST(PipelineMetrics, CompareHandWorked) {
    const auto ref = image2x2({{10, 20, 30}, {0, 0, 0}, {100, 100, 100}, {0, 0, 0}}, {1, 1, 1, 0});
    const auto a = image2x2({{11, 20, 30}, {0, 0, 2}, {100, 97, 100}, {50, 50, 50}}, {1, 1, 1, 1});
    const error_stats s = compare(a, ref);
    EXPECT_EQ(s.pixels, 3u);
    EXPECT_DOUBLE_EQ(s.nmse, 14.0 / 31400.0);
    EXPECT_DOUBLE_EQ(s.psnr_db, 10.0 * std::log10(65025.0 * 9.0 / 14.0));
    EXPECT_DOUBLE_EQ(s.max_abs, 3.0);
    // Zones 1, 2, 1, 1: zone 1 is pixels 0 and 2 (3 uncovered): d^2 = 10, ref^2 = 31400, MSE = 10 / 6.
    const std::vector<uint8_t> zones{1, 2, 1, 1};
    const error_stats z1 = compare(a, ref, &zones, 1);
    EXPECT_EQ(z1.pixels, 2u);
    EXPECT_DOUBLE_EQ(z1.nmse, 10.0 / 31400.0);
    EXPECT_DOUBLE_EQ(z1.psnr_db, 10.0 * std::log10(65025.0 * 6.0 / 10.0));
    EXPECT_DOUBLE_EQ(z1.max_abs, 3.0);
    // Zone 2: the black pixel off by 2: NMSE unbounded, MSE = 4 / 3.
    const error_stats z2 = compare(a, ref, &zones, 2);
    EXPECT_EQ(z2.pixels, 1u);
    EXPECT_TRUE(std::isinf(z2.nmse));
    EXPECT_DOUBLE_EQ(z2.psnr_db, 10.0 * std::log10(65025.0 * 3.0 / 4.0));
    EXPECT_DOUBLE_EQ(z2.max_abs, 2.0);
    // A zone with no pixels, and an image against itself: no error, PSNR +inf.
    const error_stats z5 = compare(a, ref, &zones, 5);
    EXPECT_EQ(z5.pixels, 0u);
    EXPECT_EQ(z5.nmse, 0.0);
    const error_stats same = compare(ref, ref);
    EXPECT_EQ(same.nmse, 0.0);
    EXPECT_EQ(same.max_abs, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr_db) && same.psnr_db > 0);
    // Bad calls: different sizes; a zone without a zone map.
    scene::shaded_image small = ref;
    small.width = 1;
    small.value.resize(2);
    small.covered.resize(2);
    EXPECT_THROW(compare(small, ref), scene::scene_error);
    EXPECT_THROW(compare(a, ref, nullptr, 1), scene::scene_error);
}

// ---- Operation counts ----

namespace {
// Two cubics (len 16 and 10 of 16), a quadratic of 8, three exact pixels.
plan mixed_plan() {
    plan p;
    p.width = 64;
    p.height = 4;
    p.geometry = {10, 2, 1, 20, 3};
    p.geometry_stepped = {6, 1, 1, 30, 3};
    p.decision = {1, 0, 0, 4, 0};
    p.jobs.push_back(job_of({0, 0, 0, 0}, 4, false));
    p.jobs.push_back(job_of({0, 0, 0, 0}, 4, false, 10));
    p.jobs.push_back(job_of({0, 0, 0, 0}, 3, true));
    for (int i = 0; i < 3; ++i) p.jobs.push_back(interval_job{});
    p.pixels = 37;
    p.check_samples = 5;
    return p;
}
}  // namespace

// Hand sums. Samples: 2 x 4 + 3 + 3 x 1 = 14, each 5 mul + 2 add (device) + 3 mul + 6 add (diffuse
// and adders): 112 mul, 112 add. The 5 check samples of the adaptive policies cost the same each
// (40 mul, 40 add) and are the geometry side's: {10 + 1 + 40, 2, 1, 20 + 4 + 40, 3}. Horner, case 1, shift-and-add /3: coefficient units 5 cubic-unit
// intervals x 3 channels x 22 adders = 330 and 1 x 3 x 5 = 15; Horner 29 cubic pixels x 3 x (3, 3) =
// 261 mul, 261 add and 8 quadratic pixels x 3 x (2, 2) = 48, 48; clocks 29 x 6 + 8 x 4 = 206.
// The geometry side from scratch (plan.geometry); stepped (the default) the stepped count instead:
// {6 + 1 + 40, 1, 1, 30 + 4 + 40, 3}.
TEST(PipelineOps, HornerHandSums) {
    plan_config c;
    EXPECT_EQ(hardware_ops(mixed_plan(), c).geometry, (scene::op_counts{47, 1, 1, 74, 3}));
    c.unit = geometry_unit::scratch;
    c.set = interp::sample_set::case1;
    c.div = interp::div3_mode::shift_add;
    c.eval = evaluator::horner;
    const hardware_counts h = hardware_ops(mixed_plan(), c);
    EXPECT_EQ(h.geometry, (scene::op_counts{51, 2, 1, 64, 3}));
    EXPECT_EQ(h.samples, 14u);
    EXPECT_EQ(h.intervals, 6u);
    EXPECT_EQ(h.pixels, 37u);
    EXPECT_EQ(h.sample_stage, (scene::op_counts{112, 0, 0, 112, 0}));
    EXPECT_EQ(h.interpolation, (scene::op_counts{261 + 48, 0, 0, 330 + 15 + 261 + 48, 0}));
    EXPECT_EQ(h.clocks, 206u);
    EXPECT_EQ(h.total(), (scene::op_counts{51 + 112 + 309, 2, 1, 64 + 112 + 654, 3}));
}

// The squared-quadratic device adds one MUL_SQ per squaring to each sample: at n = 20 (k = 4) each of
// the 14 samples and 5 check samples costs 9 mul + 2 add (device) + 3 mul + 6 add; at n = 1 (k = 0)
// and with a Fig. 1 device the hand sums above.
TEST(PipelineOps, SquaredDeviceSamplesCountTheirSquarings) {
    const scene::device_config sq{scene::specular_device::squared, overflow_mode::saturate};
    EXPECT_EQ(device_sample_ops(sq, 20), (scene::op_counts{9, 0, 0, 2, 0}));
    EXPECT_EQ(device_sample_ops(sq, 1), (scene::op_counts{5, 0, 0, 2, 0}));
    EXPECT_EQ(device_sample_ops(sq, 1000), (scene::op_counts{14, 0, 0, 2, 0}));
    EXPECT_EQ(device_sample_ops(scene::device_config{}, 1000), (scene::op_counts{5, 0, 0, 2, 0}));
    plan_config c;
    c.eval = evaluator::horner;
    c.unit = geometry_unit::scratch;
    const hardware_counts h = hardware_ops(mixed_plan(), c, sq, 20);
    EXPECT_EQ(h.sample_stage, (scene::op_counts{14 * 12, 0, 0, 14 * 8, 0}));
    EXPECT_EQ(h.geometry, (scene::op_counts{10 + 1 + 5 * 12, 2, 1, 20 + 4 + 5 * 8, 3}));
    EXPECT_EQ(hardware_ops(mixed_plan(), c, sq, 1).sample_stage, hardware_ops(mixed_plan(), c).sample_stage);
}

// FD, case 2, exact /3: cubic unit 18 adders + 2 divisions per channel (5 x 3 = 15 units: 270 add,
// 30 div), quadratic 15 add, FD set-up 6 intervals x 3 x 5 = 90 add, 37 pixels x 3 x 3 = 333 add;
// one clock per pixel.
TEST(PipelineOps, FdHandSums) {
    plan_config c;
    c.set = interp::sample_set::case2;
    c.div = interp::div3_mode::exact;
    c.eval = evaluator::fd;
    const hardware_counts h = hardware_ops(mixed_plan(), c);
    EXPECT_EQ(h.sample_stage, (scene::op_counts{112, 0, 0, 112, 0}));
    EXPECT_EQ(h.interpolation, (scene::op_counts{0, 30, 0, 270 + 15 + 90 + 333, 0}));
    EXPECT_EQ(h.clocks, 37u);
    EXPECT_EQ(h.pixels, 37u);
}

// ---- With the geometry side's plan ----

// make_plan + golden_frame on the sphere, against per_pixel_frame (which reads geometry_at itself):
// every covered pixel is some interval's, nothing else is; each job's samples are sample_of at the
// pixels pipeline.h names (case 1: x0 + 0, N/4, N/2, N; case 2: x0 + 0, N/2, 3N/4, N; quadratic
// x0 + 0, N/2, N); an interval's first pixel (t = 0: the evaluators return D = I1 exactly) and every
// exact pixel equal the per-pixel frame bit for bit; the counts cover every pixel once; the
// interpolated pixels stay near the per-pixel ones.
TEST(PipelineFrame, PlannedFrameAgainstPerPixel) {
    const scene::world w = scene::builtin_scene("sphere", SHADING_SOURCE_DIR, 64, 64);
    const scene::rasterised r = scene::rasterise(w);
    const frame_constants k = frame_constants_of(w);
    const frame ref = per_pixel_frame(r, k, patent);
    for (evaluator e : {evaluator::horner, evaluator::fd})
        for (degree_policy d : {degree_policy::cubic, degree_policy::quadratic}) {
            plan_config c;
            c.m = 3;
            c.degree = d;
            c.eval = e;
            c.set = e == evaluator::fd ? interp::sample_set::case2 : interp::sample_set::case1;
            const plan p = make_plan(r, k, patent, c);
            const frame f = golden_frame(p, k, patent, c);
            const std::string what = std::string(evaluator_name(e)) + " " + degree_policy_name(d);
            EXPECT_EQ(f.covered, ref.covered) << what;
            std::size_t starts = 0, samples = 0;
            for (const interval_job& job : p.jobs) {
                const std::size_t at = r.index(job.x0, job.y);
                EXPECT_EQ(f.px[at], ref.px[at]) << what << " interval at (" << job.x0 << ", " << job.y << ")";
                ++starts;
                if (job.m == 0) continue;
                const unsigned n = 1u << job.m;
                const std::array<unsigned, 4> at_case1{0, n / 4, n / 2, n}, at_case2{0, n / 2, 3 * n / 4, n};
                const std::array<unsigned, 4> at_quad{0, n / 2, n, n};
                const auto& pos = job.deg2 ? at_quad : (c.set == interp::sample_set::case1 ? at_case1 : at_case2);
                for (unsigned i = 0; i < (job.deg2 ? 3u : 4u); ++i) {
                    const unsigned x = job.x0 + pos[i];
                    ASSERT_TRUE(x < r.width && r.covered(x, job.y)) << what << " sample " << i << " off the surface";
                    EXPECT_EQ(job.s[i], sample_of(scene::geometry_at(r, x, job.y, nullptr)))
                        << what << " sample " << i << " of the interval at (" << job.x0 << ", " << job.y << ")";
                    ++samples;
                }
            }
            EXPECT_GT(samples, 0u) << what;
            EXPECT_GT(starts, 100u);
            const hardware_counts h = hardware_ops(p, c);
            EXPECT_EQ(h.pixels, r.covered_pixels()) << what;
            EXPECT_EQ(h.intervals, p.jobs.size()) << what;
            // Interpolation error against per-pixel shading: bounded, and not zero (it interpolates).
            const error_stats s = compare(to_image(f), to_image(ref));
            EXPECT_GT(s.max_abs, 0.0) << what;
            EXPECT_LT(s.nmse, 1e-2) << what;
            RecordProperty(what + " nmse", std::to_string(s.nmse));
        }
}
