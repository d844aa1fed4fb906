// The SystemC shading pipeline (modules/pipeline/) against the golden model (src/golden_pipeline): hand-made
// intervals (an exact pixel, cubic case 1 and 2, quadratic, every length 4..32, saturating samples),
// then small renders planned by make_plan for every device and both evaluators; the pixel stream's
// count and order, the clocks per pixel against the design (hardware_ops), and bad input. Every test
// elaborates once (its own process, gtest_discover_tests); SHADING_TRACE=<dir> writes its VCD there
// as <Suite.Test>.vcd.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "core/report_ids.h"
#include "pipeline_sim.h"
#include "pipeline_test.h"

namespace shading::pipeline {
void PrintTo(evaluator e, std::ostream* os) { *os << evaluator_name(e); }
}  // namespace shading::pipeline

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_sim {

using namespace shading;
using namespace shading::pipeline;

namespace {

// Frame constants chosen by hand: distinct per channel, a visible highlight (n = 32).
frame_constants hand_constants() {
    frame_constants k;
    k.n = 32;
    k.ksi = {200, 180, 90};
    k.kdi = {150 * 256, 100 * 256 + 128, 60 * 256 + 77};  // Q8.8: 150.0, 100.5, 60.3
    k.ambient = {10 * 256, 8 * 256 + 77, 12 * 256 + 3};
    return k;
}

sim_options traced() {
    sim_options o;
    if (const char* dir = std::getenv("SHADING_TRACE"); dir != nullptr && *dir != '\0')
        o.vcd_path = std::string(dir) + "/" + tb::current_test_name();
    return o;
}

// A job whose samples follow a smooth highlight across the interval (N.H peaking in the middle).
interval_job job(unsigned y, unsigned x0, unsigned m, unsigned len, bool deg2, uint32_t base = 0) {
    interval_job j;
    j.y = y;
    j.x0 = x0;
    j.m = m;
    j.len = len;
    j.deg2 = deg2;
    const uint32_t nh[4] = {30000, 32600, 32200, 29000}, nl[4] = {20000, 22000, 24000, 26000};
    for (int i = 0; i < 4; ++i) j.s[i] = {nh[i] - base, nl[i] - base};
    if (m == 0) j.s[1] = j.s[2] = j.s[3] = j.s[0];
    if (deg2) j.s[3] = j.s[2];
    return j;
}

plan make_hand_plan(unsigned w, unsigned h, std::vector<interval_job> jobs) {
    plan p;
    p.width = w;
    p.height = h;
    p.jobs = std::move(jobs);
    for (const auto& j : p.jobs) p.pixels += j.len;
    return p;
}

plan_config config(evaluator e, unsigned m = 4, interp::sample_set set = interp::sample_set::case1) {
    plan_config c;
    c.eval = e;
    c.m = m;
    c.set = set;
    return c;
}

const scene::device_config patent{};
const scene::device_config squared{scene::specular_device::squared, overflow_mode::saturate};

}  // namespace

// ---- Hand-made intervals ----

// An exact pixel is its sample: the codes golden_sample gives (Q8.8 through the output clamp
// unchanged), written once.
TEST(PipelineSimHand, ExactPixelIsItsSampleHorner) {
    const auto k = hand_constants();
    const plan p = make_hand_plan(8, 2, {job(1, 5, 0, 1, false)});
    const sim_result r = simulate_frame(p, k, patent, config(evaluator::horner), traced());
    EXPECT_EQ(r.mismatches, 0u);
    ASSERT_EQ(r.write_order.size(), 1u);
    EXPECT_EQ(r.write_order[0], 1u * 8 + 5);
    EXPECT_EQ(r.f.px[13], golden_sample(patent, k, p.jobs[0].s[0]));
    EXPECT_EQ(r.f.degree[13], 1);
}

TEST(PipelineSimHand, ExactPixelIsItsSampleFd) {
    const auto k = hand_constants();
    const plan p = make_hand_plan(8, 2, {job(0, 2, 0, 1, false)});
    const sim_result r = simulate_frame(p, k, patent, config(evaluator::fd), traced());
    EXPECT_EQ(r.mismatches, 0u);
    ASSERT_EQ(r.write_order.size(), 1u);
    EXPECT_EQ(r.f.px[2], golden_sample(patent, k, p.jobs[0].s[0]));
}

// One of each kind on a line and the next, back to back: cubic (full and short), quadratic, exact.
struct mix_case {
    evaluator e;
    interp::sample_set set;
    interp::div3_mode div;
    const char* name;
};
void PrintTo(const mix_case& c, std::ostream* os) { *os << c.name; }
class PipelineSimMix : public ::testing::TestWithParam<mix_case> {};

TEST_P(PipelineSimMix, MixedIntervalsBitExact) {
    const auto mc = GetParam();
    const auto k = hand_constants();
    plan_config c = config(mc.e, 4, mc.set);
    c.div = mc.div;
    const plan p = make_hand_plan(48, 2, {job(0, 0, 4, 16, false), job(0, 16, 4, 16, true, 500), job(0, 32, 4, 7, false, 900),
                                          job(0, 39, 0, 1, false, 100), job(0, 40, 4, 8, true, 300),
                                          job(1, 3, 0, 1, false, 2000), job(1, 4, 4, 16, false, 50)});
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.write_order, job_order(p));
    expect_golden_frame(r, p, k, patent, c);
}

// The carry: jobs that start where the one before ended (its t = 1 codes again) take that colour
// from the last-sample registers. Hand-made line: cubic 0..16, quadratic 16..32 starting at the
// cubic's t = 1 codes (carried), exact pixel at 32 with the quadratic's t = 1 codes (carried), exact
// 33 with other codes, cubic 34.. starting at those (carried); then a line whose first job repeats
// nothing. 4 + 2 + 0 + 1 + 3 + 4 = 14 samples formed, 3 carried (17 without), pixels bit-exact
// (squared-quadratic device: the carried samples skip its wait for output 29).
class PipelineSimCarry : public ::testing::TestWithParam<evaluator> {};

TEST_P(PipelineSimCarry, CarriedSamplesBitExactAndCounted) {
    const auto k = hand_constants();
    plan_config c = config(GetParam());
    c.length = length_policy::adaptive;  // fd: any m per interval
    c.carry_samples = true;
    interval_job a = job(0, 0, 4, 16, false), b = job(0, 16, 4, 16, true, 700), x = job(0, 32, 0, 1, false),
                 z = job(0, 33, 0, 1, false, 1500), d = job(0, 34, 2, 4, false, 900), e = job(1, 0, 4, 16, false, 40);
    b.s[0] = a.s[3];
    x.s = {b.s[2], b.s[2], b.s[2], b.s[2]};
    d.s[0] = z.s[0];
    const plan p = make_hand_plan(48, 2, {a, b, x, z, d, e});
    const sim_result r = simulate_frame(p, k, squared, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    expect_golden_frame(r, p, k, squared, c);
    EXPECT_EQ(r.samples_formed, 14u);
    EXPECT_EQ(r.samples_carried, 3u);
    const hardware_counts h = hardware_ops(p, c, squared, k.n);
    EXPECT_EQ(r.samples_formed, h.samples);
    EXPECT_EQ(r.samples_carried, h.carried);
}

INSTANTIATE_TEST_SUITE_P(Evaluators, PipelineSimCarry, ::testing::Values(evaluator::horner, evaluator::fd),
                         [](const ::testing::TestParamInfo<evaluator>& i) { return std::string(evaluator_name(i.param)); });

INSTANTIATE_TEST_SUITE_P(Evaluators, PipelineSimMix,
                         ::testing::Values(mix_case{evaluator::horner, interp::sample_set::case1, interp::div3_mode::shift_add, "HornerCase1"},
                                           mix_case{evaluator::horner, interp::sample_set::case2, interp::div3_mode::exact, "HornerCase2Exact"},
                                           mix_case{evaluator::fd, interp::sample_set::case1, interp::div3_mode::shift_add, "FdCase1"},
                                           mix_case{evaluator::fd, interp::sample_set::case2, interp::div3_mode::exact, "FdCase2Exact"}),
                         [](const ::testing::TestParamInfo<mix_case>& i) { return std::string(i.param.name); });

// Every interval length 4..32 (m = 2..5), full and one short of full, cubic and quadratic (Horner:
// any m in one run).
TEST(PipelineSimHand, EveryLengthHorner) {
    const auto k = hand_constants();
    std::vector<interval_job> jobs;
    unsigned y = 0;
    for (unsigned m = 2; m <= 5; ++m)
        for (bool q : {false, true})
            for (unsigned len : {1u << m, (1u << m) - 1}) {
                jobs.push_back(job(y, 1, m, len, q, 37 * y));
                ++y;
            }
    const plan p = make_hand_plan(40, y, jobs);
    const plan_config c = config(evaluator::horner);
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.write_order, job_order(p));
    expect_golden_frame(r, p, k, patent, c);
}

// Forward differences for any m per interval (fd_eval_var, built when the length is adaptive): every
// length 4..64 (m = 2..6), cubic and quadratic, exact pixels between, in one run.
TEST(PipelineSimHand, EveryLengthFdAnyM) {
    const auto k = hand_constants();
    std::vector<interval_job> jobs;
    unsigned y = 0;
    for (unsigned m = 2; m <= 6; ++m)
        for (bool q : {false, true})
            for (unsigned len : {1u << m, (1u << m) - 1}) {
                jobs.push_back(job(y, 1, m, len, q, 37 * y));
                jobs.push_back(job(y, 0, 0, 1, false, 3 * y));
                ++y;
            }
    const plan p = make_hand_plan(66, y, jobs);
    plan_config c = config(evaluator::fd);
    c.length = length_policy::adaptive;
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.jobs_dropped, 0u);
    EXPECT_EQ(r.write_order, job_order(p));
    expect_golden_frame(r, p, k, patent, c);
}

class PipelineSimFdLength : public ::testing::TestWithParam<unsigned> {};
TEST_P(PipelineSimFdLength, EveryLengthOfItsM) {
    const unsigned m = GetParam();
    const auto k = hand_constants();
    std::vector<interval_job> jobs;
    unsigned y = 0;
    for (bool q : {false, true})
        for (unsigned len = 1; len <= (1u << m); len += (m > 3 ? 3 : 1)) jobs.push_back(job(y++, 0, m, len, q, 11 * len));
    const plan p = make_hand_plan(1u << m, y, jobs);
    const plan_config c = config(evaluator::fd, m);
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.write_order, job_order(p));
    expect_golden_frame(r, p, k, patent, c);
}
INSTANTIATE_TEST_SUITE_P(M, PipelineSimFdLength, ::testing::Values(2u, 3u, 4u, 5u));

// Samples that saturate the colour adder (ambient + diffuse + specular > 255.996) and the output
// clamp (the cubic overshoots above 0xFFFF and below 0 between bright and dark samples).
class PipelineSimSaturate : public ::testing::TestWithParam<evaluator> {};
TEST_P(PipelineSimSaturate, SaturatingSamplesAndClampedPixels) {
    frame_constants k;
    k.n = 4;
    k.ksi = {255, 255, 255};
    k.kdi = {255 * 256, 255 * 256, 40 * 256};
    k.ambient = {200 * 256, 10 * 256, 0};
    interval_job bright = job(0, 0, 4, 16, false);
    bright.s = {sample_geometry{32768, 32768}, sample_geometry{0, 0}, sample_geometry{32768, 32768}, sample_geometry{0, 0}};
    interval_job q = job(1, 0, 4, 16, true);
    q.s = {sample_geometry{0, 0}, sample_geometry{32768, 32768}, sample_geometry{0, 0}, sample_geometry{0, 0}};
    const plan p = make_hand_plan(17, 2, {bright, q, job(1, 16, 0, 1, false)});
    // The adder saturates: the hand-worked sum of the first sample exceeds 0xFFFF in R and G.
    EXPECT_EQ(golden_sample(patent, k, bright.s[0])[0], 0xFFFFu);
    const plan_config c = config(GetParam());
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    std::size_t at_max = 0, at_zero = 0;
    for (std::size_t i = 0; i < 16; ++i) {
        at_max += r.f.px[i][0] == 0xFFFF;
        at_zero += r.f.px[i][2] == 0;
    }
    EXPECT_GT(at_max, 0u) << "some pixels clamp at 0xFFFF";
    expect_golden_frame(r, p, k, patent, c);
}
INSTANTIATE_TEST_SUITE_P(Evaluators, PipelineSimSaturate, ::testing::Values(evaluator::horner, evaluator::fd),
                         [](const ::testing::TestParamInfo<evaluator>& i) { return std::string(evaluator_name(i.param)); });

// The checker can fail: one corrupted golden pixel is one mismatch, reported (shading/mismatch).
TEST(PipelineSimHand, CheckerCatchesOneWrongPixel) {
    tb::report_log::get().expect(msg::mismatch);
    const plan p = make_hand_plan(16, 1, {job(0, 0, 4, 16, false)});
    sim_options o = traced();
    o.inject_mismatch = 5;
    const sim_result r = simulate_frame(p, hand_constants(), patent, config(evaluator::horner), o);
    EXPECT_EQ(r.mismatches, 1u);
    EXPECT_EQ(tb::report_log::get().count(msg::mismatch), 1u);
}

// Without the write log (soak_pipeline's long runs) the verdict is the same: the corrupted pixel is
// still the sixth written and still one mismatch; only the log is empty.
TEST(PipelineSimHand, CheckerWithoutWriteLogStillCatchesIt) {
    tb::report_log::get().expect(msg::mismatch);
    const plan p = make_hand_plan(16, 1, {job(0, 0, 4, 16, false)});
    sim_options o = traced();
    o.inject_mismatch = 5;
    o.keep_write_order = false;
    const sim_result r = simulate_frame(p, hand_constants(), patent, config(evaluator::horner), o);
    EXPECT_EQ(r.mismatches, 1u);
    EXPECT_EQ(tb::report_log::get().count(msg::mismatch), 1u);
    EXPECT_TRUE(r.write_order.empty());
}

// ---- Clocks per pixel, as designed ----

// Fill latency, from the rising edge where the geometry side sees the frame load taken to the edge
// where the evaluators take the first pixel: the first job is taken 1.5 clocks later (ready returns
// with the frame strobes' fall), checked a clock later where its first sample starts, four samples
// take 8 clocks, the hand-over (ld_e) 1.5 clocks and the coefficient units 1: 12 clocks.
constexpr uint64_t fill_clocks = 12;

// Horner: 6 clocks per cubic pixel and 4 per quadratic one (hardware_ops' count), back to back
// across intervals and exact pixels: the run takes that plus the fill latency, whatever the number
// of intervals. (The sample stage needs 8 clocks per cubic job, 6 per quadratic, 2 per exact
// pixel: here it always has the next interval ready in time.)
TEST(PipelineSimClocks, HornerBackToBack) {
    const auto k = hand_constants();
    std::vector<interval_job> jobs;
    for (unsigned i = 0; i < 6; ++i) jobs.push_back(job(0, 16 * i, 4, 16, i % 2 == 1, 10 * i));
    jobs.push_back(job(1, 0, 2, 4, false, 5));
    jobs.push_back(job(1, 4, 0, 1, false));
    jobs.push_back(job(1, 5, 0, 1, false, 5));
    const plan p = make_hand_plan(96, 2, jobs);
    const plan_config c = config(evaluator::horner);
    const hardware_counts hw = hardware_ops(p, c);
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(hw.clocks, 3u * 16 * 6 + 3u * 16 * 4 + 4 * 6 + 2 * 6);
    EXPECT_EQ(r.clocks, r.frame_load_clocks + fill_clocks + hw.clocks) << "frame loaded at clock " << r.frame_load_clocks;
}

// A short cubic interval after an exact pixel: the sample stage's 8 clocks for the four samples are
// more than the exact pixel's 6, so the Horner units wait 2 clocks.
TEST(PipelineSimClocks, HornerWaitsForASlowSampleStage) {
    const auto k = hand_constants();
    const plan p = make_hand_plan(8, 1, {job(0, 0, 0, 1, false), job(0, 1, 2, 4, false)});
    const plan_config c = config(evaluator::horner);
    const hardware_counts hw = hardware_ops(p, c);
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(hw.clocks, 5u * 6);
    // The exact pixel's fill is 6 clocks shorter (one sample, not four); the cubic job is taken at
    // the exact pixel's sample latch, checked a clock later, and its four samples take 8 clocks, so
    // its first pixel is taken 8 clocks after the exact pixel, not 6: a wait of 2 clocks.
    EXPECT_EQ(r.clocks, r.frame_load_clocks + (fill_clocks - 6) + 8 + 4 * 6);
}

// Forward differences: one pixel per clock while the sample stage keeps up (2^4 pixels per
// interval take longer than its four samples), no clock lost between intervals.
TEST(PipelineSimClocks, FdOnePixelPerClock) {
    const auto k = hand_constants();
    std::vector<interval_job> jobs;
    for (unsigned i = 0; i < 6; ++i) jobs.push_back(job(0, 16 * i, 4, 16, i % 2 == 1, 10 * i));
    const plan p = make_hand_plan(96, 1, jobs);
    const plan_config c = config(evaluator::fd);
    const hardware_counts hw = hardware_ops(p, c);
    const sim_result r = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(hw.clocks, 96u);
    EXPECT_EQ(r.clocks, r.frame_load_clocks + fill_clocks + hw.clocks) << "frame loaded at clock " << r.frame_load_clocks;
}

// The squared-quadratic device takes k + 4 clocks from its strobe to output 29 (its synchroniser's
// two rising edges, the taking edge, k = 9 - z squarings for the frame's n, the done edge) where a
// Fig. 1 device takes one: the sample controller raises strobe 17 after its clock low as before and
// latches at the first falling edge with output 29 high, so each sample costs k + 3 clocks more
// (sample_fsm.h). One cubic job of 16 pixels: the fill latency of a Fig. 1 device (12 clocks,
// above) plus 4 (k + 3), then the Horner units' 16 x 6 clocks.
class PipelineSimSquaredClocks : public ::testing::TestWithParam<std::pair<unsigned, unsigned>> {};

TEST_P(PipelineSimSquaredClocks, EachSampleWaitsKPlusThreeClocksMore) {
    const auto [n, k_squarings] = GetParam();
    auto k = hand_constants();
    k.n = n;
    const plan p = make_hand_plan(16, 1, {job(0, 0, 4, 16, false)});
    const plan_config c = config(evaluator::horner);
    const sim_result sq = simulate_frame(p, k, squared, c, traced());
    EXPECT_EQ(sq.mismatches, 0u);
    expect_golden_frame(sq, p, k, squared, c);
    EXPECT_EQ(sq.clocks, sq.frame_load_clocks + fill_clocks + 4 * (k_squarings + 3) + 16 * 6)
        << "frame loaded at clock " << sq.frame_load_clocks;
}
INSTANTIATE_TEST_SUITE_P(N, PipelineSimSquaredClocks,
                         ::testing::Values(std::pair<unsigned, unsigned>{1, 0}, std::pair<unsigned, unsigned>{20, 4},
                                           std::pair<unsigned, unsigned>{512, 9}),
                         [](const ::testing::TestParamInfo<std::pair<unsigned, unsigned>>& i) {
                             return "n" + std::to_string(i.param.first);
                         });

// ---- Bad input ----

// Jobs the units cannot take are reported (shading/input) and dropped; the others still come out
// bit-exact and in order.
TEST(PipelineSimBad, InvalidJobsReportedAndDropped) {
    tb::report_log::get().expect(msg::input);
    const auto k = hand_constants();
    interval_job len0 = job(0, 0, 3, 0, false), too_long = job(0, 0, 2, 5, false), m7 = job(0, 0, 7, 4, false),
                 m1 = job(0, 0, 1, 2, false), exact_q = job(0, 0, 0, 1, true);
    const plan p = make_hand_plan(32, 2, {len0, job(0, 0, 4, 16, false), too_long, m7, m1, exact_q, job(1, 5, 3, 8, true)});
    const sim_result r = simulate_frame(p, k, patent, config(evaluator::horner), traced());
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.jobs_dropped, 5u);
    EXPECT_EQ(tb::report_log::get().count(msg::input), 5u);
    EXPECT_EQ(r.write_order.size(), 24u);
}

// The forward differences are built for one m: an interval of another m is refused (exact pixels
// pass), a write beyond the frame is dropped by the frame buffer; both reported.
TEST(PipelineSimBad, FdOtherMAndOutsideTheFrame) {
    tb::report_log::get().expect(msg::input);
    const auto k = hand_constants();
    const plan p = make_hand_plan(20, 1, {job(0, 0, 3, 8, false), job(0, 0, 4, 16, false), job(0, 16, 0, 1, false),
                                          job(0, 17, 4, 5, false)});
    const sim_result r = simulate_frame(p, k, patent, config(evaluator::fd, 4), traced());
    EXPECT_EQ(r.jobs_dropped, 1u);
    EXPECT_EQ(tb::report_log::get().count(msg::input), 1u + 2u);  // m = 3 refused; x = 20, 21 dropped
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.write_order.size(), 16u + 1u + 3u);
}

// A forward-difference evaluator for an m it cannot be built for: a configuration error, no run.
TEST(PipelineSimBad, FdBuiltForAnImpossibleM) {
    tb::report_log::get().expect(msg::config);
    const plan p = make_hand_plan(4, 1, {job(0, 0, 0, 1, false)});
    const sim_result r = simulate_frame(p, hand_constants(), patent, config(evaluator::fd, 7), traced());
    EXPECT_EQ(tb::report_log::get().count(msg::config), 1u);
    EXPECT_EQ(r.write_order.size(), 0u);
    EXPECT_EQ(r.mismatches, 1u);
}

// ---- Small renders: make_plan on the built-in scenes, every device, both evaluators ----

class PipelineSimRender : public ::testing::TestWithParam<render_case> {};

// The SystemC frame equals golden_frame bit for bit (and the bench's own per-job check finds no
// mismatch); every planned pixel is written once, in the plan's order (line by line, left to
// right); the clocks are the evaluator's own (hardware_ops) plus the fill and the clocks the
// evaluators wait for the sample stage, which the plan's mix of exact pixels and short intervals
// bounds.
TEST_P(PipelineSimRender, BitExactAgainstTheGoldenFrame) {
    const auto rc = GetParam();
    render_setup rs(rc);
    auto& [w, r, k, dev, c] = rs;
    c.m = std::string(rc.scene) == "head" ? 4 : 3;
    c.degree = std::string(rc.scene) == "head" ? degree_policy::zones : degree_policy::adaptive;
    const plan p = make_plan(r, k, dev, c);
    ASSERT_GT(p.pixels, 100u);
    std::size_t quad = 0, exact = 0;
    for (const auto& j : p.jobs) {
        quad += j.deg2;
        exact += j.m == 0;
    }
    const sim_result s = simulate_frame(p, k, dev, c, traced());
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.write_order, job_order(p));
    expect_golden_frame(s, p, k, dev, c);
    const hardware_counts hw = hardware_ops(p, c);
    EXPECT_GE(s.clocks, s.frame_load_clocks + hw.clocks);
    // Waits: at most the sample stage's 10 clocks per job beyond the evaluator's clocks for it.
    EXPECT_LE(s.clocks, s.frame_load_clocks + fill_clocks + hw.clocks + 10 * p.jobs.size());
    std::printf("%s%u %s %s: %zu pixels, %zu jobs (%zu quadratic, %zu exact), %llu clocks (evaluator %llu), "
                "%.2f clocks/pixel, %.0f pixels/s\n",
                rc.scene, rc.size, scene::device_name(rc.device), evaluator_name(rc.e), p.pixels, p.jobs.size(), quad,
                exact, (unsigned long long)s.clocks, (unsigned long long)hw.clocks, double(s.clocks) / p.pixels,
                p.pixels / s.seconds);
}

// The head with adaptive length and degree (the configuration that meets the NMSE target), through
// forward differences for any m per interval (fd_eval_var) and through Horner.
class PipelineSimAdaptive : public ::testing::TestWithParam<evaluator> {};
TEST_P(PipelineSimAdaptive, HeadAdaptiveLengthAndDegree) {
    const scene::world w = scene::builtin_scene("head", SHADING_SOURCE_DIR, 64, 64);
    const scene::rasterised r = scene::rasterise(w);
    const frame_constants k = frame_constants_of(w);
    plan_config c;
    c.length = length_policy::adaptive;
    c.degree = degree_policy::adaptive;
    const plan p = make_plan(r, k, patent, c);  // planned as for Horner: fd's plan needs a fixed length
    std::set<unsigned> ms;
    for (const auto& j : p.jobs) ms.insert(j.m);
    EXPECT_GE(ms.size(), 3u) << "several interval lengths in one frame";
    c.eval = GetParam();
    const sim_result s = simulate_frame(p, k, patent, c, traced());
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.jobs_dropped, 0u);
    EXPECT_EQ(s.write_order, job_order(p));
    expect_golden_frame(s, p, k, patent, c);
}
INSTANTIATE_TEST_SUITE_P(Evaluators, PipelineSimAdaptive, ::testing::Values(evaluator::horner, evaluator::fd),
                         [](const ::testing::TestParamInfo<evaluator>& i) { return std::string(evaluator_name(i.param)); });

std::vector<render_case> render_cases() {
    std::vector<render_case> v;
    for (auto sc : {std::pair<const char*, unsigned>{"sphere", 32}, {"head", 48}})
        for (auto d : {scene::specular_device::patent, scene::specular_device::minimax, scene::specular_device::rom_matched,
                       scene::specular_device::ua22802, scene::specular_device::squared})
            for (auto e : {evaluator::horner, evaluator::fd}) v.push_back({sc.first, sc.second, d, e});
    return v;
}
INSTANTIATE_TEST_SUITE_P(Scenes, PipelineSimRender, ::testing::ValuesIn(render_cases()), render_case_name);

// ---- The waveform view ----

// traces/pipeline.gtkw is hand-written for the VCD this test writes (SHADING_TRACE=traces: to
// traces/pipeline.vcd, else a temporary folder): every net it lists exists, and a user sees it at
// first sight as intended (vcd_names.h, view_problems): dump file beside the view, marker inside the
// opening window and off every edge, every bus a number in its format, the pixel stream on top.
TEST(PipelineSimView, GtkwaveViewMatchesItsVcd) {
    const char* env = std::getenv("SHADING_TRACE");
    const std::string dir = env != nullptr && *env != '\0' ? std::string(env) : ::testing::TempDir();
    const plan p = make_hand_plan(8, 1, {job(0, 0, 2, 4, false), job(0, 4, 0, 1, false)});
    sim_options o;
    o.vcd_path = dir + "/pipeline";
    const sim_result r = simulate_frame(p, hand_constants(), patent, config(evaluator::horner), o);
    EXPECT_EQ(r.mismatches, 0u);
    const std::string gtkw = tb::source_path("traces/pipeline.gtkw"), vcd = dir + "/pipeline.vcd";
    const auto declared = tb::vcd_declared(vcd);
    const auto shown = tb::gtkw_listed(gtkw);
    EXPECT_GE(shown.size(), 20u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";
    tb::view_formats f;
    for (const char* s : {"tb.px_r", "tb.px_g", "tb.px_b", "tb.dut.smp_r.colour"}) f[s] = colour_fmt;
    f["tb.px_x"] = f["tb.px_y"] = qfmt{16, false, 0};
    f["tb.dut.smp_sel"] = qfmt{2, false, 0};
    f["tb.dut.in18_cos"] = spec::cos_fmt;
    f["tb.dut.out25_r"] = spec::out_fmt;
    for (const char* s : {"tb.dut.ca_r", "tb.dut.cd_r", "tb.dut.horner_r.i_t"}) f[s] = interp::coef_fmt;
    f["tb.dut.t"] = interp::t_fmt;
    f["tb.dut.horner_r.horner.step"] = qfmt{3, false, 0};
    const auto problems = tb::view_problems(gtkw, vcd, "pipeline", f,
                                            {"tb.px_valid", "tb.px_x", "tb.px_y", "tb.px_r", "tb.px_g", "tb.px_b"});
    EXPECT_TRUE(problems.empty()) << tb::joined(problems);
}

}  // namespace test_pipeline_sim
