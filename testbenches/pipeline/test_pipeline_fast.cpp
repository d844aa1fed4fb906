// The fast pin-level abstraction of the shading pipeline (modules/pipeline/shading_pipeline_fast.h)
// against the block-level pipeline and the golden model:
//   - side by side: one bench drives the block-level pipeline and the fast one from the same pins
//     (random jobs: every m, lengths, degrees, exact pixels, some invalid ones, random frame
//     constants), and every pin is compared at every edge of the clock: ready at falling and rising
//     edges, px_valid / px_x / px_y at rising edges, px_r/g/b where px_valid = 1; both frame
//     buffers against golden_interval (pipeline_checker);
//   - alone through simulate_frame (abstraction::fast): small renders equal golden_frame bit for
//     bit, in the plan's order, with the block level's clocks per pixel bounds.
// One elaboration per test (each test is its own process, gtest_discover_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "testbenches/common/bench_source.h"
#include "testbenches/common/report_log.h"
#include "core/report_ids.h"
#include "pipeline/shading_pipeline_fast.h"
#include "pipeline_bench.h"
#include "pipeline_pair.h"
#include "pipeline_sim.h"
#include "pipeline_test.h"
#include "pipeline_tops.h"
#include "tuned/a_gen_tuned.h"
#include "ua22802/a_gen_rom.h"
#include "ua60553/a_gen_linear.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "sqmul/sqmul_device.h"
#include "squared/squared_device.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_pipeline_fast {

using namespace shading;
using namespace shading::pipeline;

namespace {

// random_plan, random_constants, pin_comparator and pair_bench: pipeline_pair.h.
template <class AGen, evaluator EVAL>
using fast_pair = pair_bench<AGen, EVAL, shading_pipeline_fast<EVAL>>;

struct pair_case {
    const char* name;
    scene::specular_device device;
    evaluator eval;
    unsigned fd_m;  // forward differences: 0 any m per interval, else the fixed m
    uint64_t seed;
    bool carry = false;  // both pipelines with the carry, on a plan whose jobs chain
};
void PrintTo(const pair_case& c, std::ostream* os) { *os << c.name; }

// other_set: the fast pipeline built with the other cubic sample set (the comparison must then see
// differences: it can fail).
template <class AGen, evaluator EVAL>
void run_pair(const pair_case& pc, const typename AGen::config& gen, bool other_set = false) {
    tb::report_log::get().expect(msg::input);  // the invalid jobs, reported by both
    const plan p = random_plan(pc.seed, 400, 64, EVAL == evaluator::fd ? pc.fd_m : 0, 12, pc.carry);
    const frame_constants k = random_constants(pc.seed);
    scene::device_config dev;
    dev.device = pc.device;
    dev.mode = pc.seed % 2 ? overflow_mode::wrap : overflow_mode::saturate;
    plan_config c;
    c.carry_samples = pc.carry;
    c.eval = EVAL;
    c.length = pc.fd_m == 0 ? length_policy::adaptive : length_policy::fixed;
    c.m = pc.fd_m == 0 ? 4 : pc.fd_m;
    c.set = pc.seed % 3 ? interp::sample_set::case1 : interp::sample_set::case2;
    c.div = pc.seed % 5 ? interp::div3_mode::shift_add : interp::div3_mode::exact;
    const auto fast_set = !other_set ? c.set
                          : c.set == interp::sample_set::case1 ? interp::sample_set::case2 : interp::sample_set::case1;
    const auto fast_idle = [](const shading_pipeline_fast<EVAL>& f) { return f.idle(); };
    auto bench = std::make_unique<fast_pair<AGen, EVAL>>("tb", p, k, dev, c, gen, fast_idle, "fst", dev, fast_set,
                                                         c.div, fd_m(c), c.carry_samples);
    const auto& fst = bench->other;
    sc_core::sc_start(pipeline_period() * static_cast<double>(pair_watchdog_clocks(p)));
    ASSERT_TRUE(bench->finished());
    bench->chk_b.finish();
    bench->chk_o.finish();
    if (other_set) {
        EXPECT_GT(bench->cmp.differences(), 10u);
        EXPECT_EQ(bench->chk_b.mismatches(), 0u);
        bench.release();
        return;
    }
    EXPECT_EQ(bench->cmp.differences(), 0u);
    EXPECT_GT(bench->cmp.valid_edges(), 500u);
    EXPECT_EQ(bench->chk_b.mismatches(), 0u);
    EXPECT_EQ(bench->chk_o.mismatches(), 0u);
    EXPECT_EQ(bench->chk_o.order(), bench->chk_b.order());
    EXPECT_EQ(fst.dropped(), bench->chk_o.dropped());
    EXPECT_GT(fst.dropped(), 5u);
    EXPECT_EQ(fst.samples(), bench->blk.samples());
    EXPECT_EQ(fst.carried(), bench->blk.carried());
    if (pc.carry) {
        EXPECT_GT(bench->blk.carried(), 50u);
    } else {
        EXPECT_EQ(bench->blk.carried(), 0u);
    }
    // Each invalid job is reported once by each pipeline.
    EXPECT_EQ(tb::report_log::get().count(msg::input), 2 * bench->chk_o.dropped());
    std::printf("%s: %zu pins compared over %zu edges, %zu pixels, %zu jobs dropped\n", pc.name,
                bench->cmp.valid_edges(), bench->cmp.edges(), bench->chk_o.written(), bench->chk_o.dropped());
    bench.release();  // elaborated for the process's life
}

class PipelineFastPins : public ::testing::TestWithParam<pair_case> {};

TEST_P(PipelineFastPins, SameAsBlockLevelAtEveryEdge) {
    const pair_case pc = GetParam();
    const bool horner = pc.eval == evaluator::horner;
    switch (pc.device) {
        case scene::specular_device::patent:
            if (horner) run_pair<a_gen_linear, evaluator::horner>(pc, ua60553::patent);
            else run_pair<a_gen_linear, evaluator::fd>(pc, ua60553::patent);
            break;
        case scene::specular_device::minimax:
            if (horner) run_pair<a_gen_tuned, evaluator::horner>(pc, ua60553::minimax);
            else run_pair<a_gen_tuned, evaluator::fd>(pc, ua60553::minimax);
            break;
        case scene::specular_device::rom_matched:
            if (horner) run_pair<a_gen_tuned, evaluator::horner>(pc, ua60553::rom_matched);
            else run_pair<a_gen_tuned, evaluator::fd>(pc, ua60553::rom_matched);
            break;
        case scene::specular_device::ua22802:
            if (horner) run_pair<a_gen_rom, evaluator::horner>(pc, a_gen_rom::default_config());
            else run_pair<a_gen_rom, evaluator::fd>(pc, a_gen_rom::default_config());
            break;
        case scene::specular_device::squared:
            if (horner) run_pair<squared_device, evaluator::horner>(pc, squared_device::default_config());
            else run_pair<squared_device, evaluator::fd>(pc, squared_device::default_config());
            break;
        case scene::specular_device::sqmul:
            if (horner) run_pair<sqmul_device, evaluator::horner>(pc, sqmul_device::default_config());
            else run_pair<sqmul_device, evaluator::fd>(pc, sqmul_device::default_config());
            break;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Random, PipelineFastPins,
    ::testing::Values(pair_case{"horner_patent", scene::specular_device::patent, evaluator::horner, 0, 1},
                      pair_case{"horner_ua22802", scene::specular_device::ua22802, evaluator::horner, 0, 2},
                      pair_case{"horner_minimax", scene::specular_device::minimax, evaluator::horner, 0, 3},
                      pair_case{"fd_any_m_rom_matched", scene::specular_device::rom_matched, evaluator::fd, 0, 4},
                      pair_case{"fd_m4_patent", scene::specular_device::patent, evaluator::fd, 4, 5},
                      pair_case{"fd_m2_minimax", scene::specular_device::minimax, evaluator::fd, 2, 6},
                      pair_case{"horner_squared", scene::specular_device::squared, evaluator::horner, 0, 8},
                      pair_case{"fd_any_m_squared", scene::specular_device::squared, evaluator::fd, 0, 9},
                      pair_case{"horner_patent_carry", scene::specular_device::patent, evaluator::horner, 0, 10, true},
                      pair_case{"fd_any_m_squared_carry", scene::specular_device::squared, evaluator::fd, 0, 11, true},
                      pair_case{"fd_m3_ua22802_carry", scene::specular_device::ua22802, evaluator::fd, 3, 13, true},
                      pair_case{"horner_sqmul", scene::specular_device::sqmul, evaluator::horner, 0, 14},
                      pair_case{"fd_any_m_sqmul_carry", scene::specular_device::sqmul, evaluator::fd, 0, 15, true}),
    [](const ::testing::TestParamInfo<pair_case>& i) { return std::string(i.param.name); });

// The comparison can fail: the fast pipeline built with the other sample set differs at the pins.
TEST(PipelineFastPinsVerdict, AnotherSampleSetIsSeen) {
    tb::report_log::get().expect(msg::mismatch);  // the fast frame buffer's checker
    run_pair<a_gen_linear, evaluator::horner>(
        pair_case{"horner_other_set", scene::specular_device::patent, evaluator::horner, 0, 7}, ua60553::patent, true);
}

// ---- Alone: renders through simulate_frame ----

class PipelineFastRender : public ::testing::TestWithParam<render_case> {};

// The fast pipeline's frame equals golden_frame bit for bit, every planned pixel written once in the
// plan's order, within the block level's clock bounds (test_pipeline_sim: the evaluator's clocks plus
// at most 10 per job).
TEST_P(PipelineFastRender, BitExactAgainstTheGoldenFrame) {
    const auto rc = GetParam();
    render_setup rs(rc);
    auto& [w, r, k, dev, c] = rs;
    if (rc.adaptive) {
        c.length = length_policy::adaptive;
        c.degree = degree_policy::adaptive;
    } else {
        c.degree = degree_policy::zones;
    }
    const plan p = make_plan(r, k, dev, c);
    ASSERT_GT(p.pixels, 100u);
    sim_options o;
    o.level = abstraction::fast;
    const sim_result s = simulate_frame(p, k, dev, c, o);
    EXPECT_EQ(s.mismatches, 0u);
    EXPECT_EQ(s.write_order, job_order(p));
    expect_golden_frame(s, p, k, dev, c);
    const hardware_counts hw = hardware_ops(p, c);
    EXPECT_GE(s.clocks, s.frame_load_clocks + hw.clocks);
    // The squared-quadratic device adds k + 3 clocks to each of a job's samples (sample_fsm.h;
    // k + 4 rising edges from its strobe to output 29: its synchroniser's two, taking, k, done), the
    // square-and-multiply device its squares and multiplications + 3 (the same edges around its walk).
    uint64_t per_sample = 0;
    if (dev.device == scene::specular_device::squared)
        per_sample = squared::sq_count::squarings(static_cast<unsigned>(golden_squared_a(k.n).z)) + 3;
    if (dev.device == scene::specular_device::sqmul) {
        const auto g = golden_sqmul(k.n, 0, {0, 0, 0}, overflow_mode::saturate);
        per_sample = g.squares + g.multiplies + 3;
    }
    const uint64_t per_job = 10 + 4 * per_sample;
    EXPECT_LE(s.clocks, s.frame_load_clocks + 20 + hw.clocks + per_job * p.jobs.size());
    std::printf("%s%u %s %s fast: %zu pixels, %.2f clocks/pixel, %.0f pixels per CPU second\n", rc.scene, rc.size,
                scene::device_name(rc.device), evaluator_name(rc.e), p.pixels, double(s.clocks) / p.pixels,
                s.cpu_seconds > 0 ? p.pixels / s.cpu_seconds : 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, PipelineFastRender,
    ::testing::Values(render_case{"head", 64, scene::specular_device::patent, evaluator::horner, false},
                      render_case{"head", 64, scene::specular_device::ua22802, evaluator::fd, true},
                      render_case{"sphere", 48, scene::specular_device::minimax, evaluator::horner, true},
                      render_case{"head", 64, scene::specular_device::squared, evaluator::fd, true},
                      render_case{"head", 64, scene::specular_device::sqmul, evaluator::horner, true}),
    render_case_name);

}  // namespace

}  // namespace test_pipeline_fast
