// The golden pipeline on whole frames (a hand-built plan, per-pixel shading against the scene's
// device reference, the geometry side's plan), the error measures and the operation counts against
// hand sums. No simulation here: these tests may share a process.
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
namespace test_pipeline_frame {

using namespace shading;
using namespace shading::pipeline;
using namespace golden_test;

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

// Hand-worked: the pixels beyond 4, 16 and 64 levels (error_levels), by each pixel's largest channel
// error: 4 (not beyond 4: strictly), 4.5, 17 (on the second of three channels), 70.
TEST(PipelineMetrics, PixelsBeyondLevelsHandWorked) {
    ASSERT_EQ(error_levels, (std::array<double, 3>{4.0, 16.0, 64.0}));
    const std::vector<scene::rgb> ref{{10, 20, 30}, {0, 0, 0}, {100, 100, 100}, {200, 200, 200}};
    const std::vector<scene::rgb> a{{14, 20, 30}, {0, 0, 4.5}, {100, 83, 110}, {130, 200, 200}};
    const error_stats all = compare(image2x2(a, {1, 1, 1, 1}), image2x2(ref, {1, 1, 1, 1}));
    EXPECT_EQ(all.pixels_over, (std::array<std::size_t, 3>{3, 2, 1}));
    EXPECT_DOUBLE_EQ(all.max_abs, 70.0);
    // The reference's uncovered pixel (the 70) counts nowhere.
    const error_stats three = compare(image2x2(a, {1, 1, 1, 1}), image2x2(ref, {1, 1, 1, 0}));
    EXPECT_EQ(three.pixels_over, (std::array<std::size_t, 3>{2, 1, 0}));
    // Zones 1, 2, 1, 1: zone 1 is the 4, the 17 and the 70; zone 2 the 4.5.
    const std::vector<uint8_t> zones{1, 2, 1, 1};
    EXPECT_EQ(compare(image2x2(a, {1, 1, 1, 1}), image2x2(ref, {1, 1, 1, 1}), &zones, 1).pixels_over,
              (std::array<std::size_t, 3>{2, 2, 1}));
    EXPECT_EQ(compare(image2x2(a, {1, 1, 1, 1}), image2x2(ref, {1, 1, 1, 1}), &zones, 2).pixels_over,
              (std::array<std::size_t, 3>{1, 0, 0}));
}

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

// The sample stage's carry: a job whose first sample's codes equal the last sample's (the previous
// job's t = 1 sample, or an exact pixel's own) forms one sample less. Hand-built sequence, codes as
// letters: cubic (P0 P1 P2 P3) 4; cubic (P3 ..) 3, carried; exact R 1; exact R 0, carried; quadratic
// (R S1 S2) 2, carried; cubic (S1 ..) 4, not carried (the quadratic's last sample is S2): 14 samples,
// 3 carried, each formed sample 5 mul + 2 add (device) + 3 mul + 6 add. Without the carry 4 + 4 + 1 +
// 1 + 3 + 4 = 17.
TEST(PipelineOps, CarriedSamplesAreNotFormedAgain) {
    plan p;
    p.width = 64;
    p.height = 1;
    p.jobs.push_back(job_of({100, 200, 300, 400}, 2, false));
    p.jobs.push_back(job_of({400, 500, 600, 700}, 2, false));
    p.jobs.push_back(job_of({900, 900, 900, 900}, 0, false, 1));
    p.jobs.push_back(job_of({900, 900, 900, 900}, 0, false, 1));
    p.jobs.push_back(job_of({900, 1000, 1100, 1100}, 2, true));
    p.jobs.push_back(job_of({1000, 1200, 1300, 1400}, 2, false));
    plan_config c;
    c.eval = evaluator::fd;
    const hardware_counts plain = hardware_ops(p, c);
    EXPECT_EQ(plain.samples, 17u);
    EXPECT_EQ(plain.carried, 0u);
    c.carry_samples = true;
    const hardware_counts h = hardware_ops(p, c);
    EXPECT_EQ(h.samples, 14u);
    EXPECT_EQ(h.carried, 3u);
    EXPECT_EQ(h.sample_stage, (scene::op_counts{14 * 8, 0, 0, 14 * 8, 0}));
    EXPECT_EQ(h.interpolation, plain.interpolation);
    EXPECT_EQ(h.geometry, plain.geometry);
}

}  // namespace test_pipeline_frame
