// The shading pipeline's Verilog twin (rtl/pipeline/shading_pipeline.v with the square-and-multiply
// device, verilated with --sc) co-simulated with the SystemC block model shading_pipeline<sqmul_device,
// EVAL> on the same input pins and clock, with the side-by-side bench of pipeline_pair.h: random jobs
// (every m, lengths, degrees, exact pixels, invalid jobs) and frame constants; every pin of the two
// compared at every edge (ready at every edge, px_valid / px_x / px_y at rising edges, px_r/g/b
// where px_valid = 1); each frame buffer's pixels against golden_interval.
// Three verilated variants spread the parameters (testbenches/rtl/pipeline.cmake): every one takes
// both its values in some variant.
//   horner    EVAL 0          SET 0 (case 1)  DIV 0 (shift-add)  CARRY 1  SATURATE 1
//   fd_any_m  EVAL 1, FD_M 0  SET 1 (case 2)  DIV 1 (exact)      CARRY 0  SATURATE 0
//   fd_m4     EVAL 1, FD_M 4  SET 0 (case 1)  DIV 1 (exact)      CARRY 1  SATURATE 0
// Each variant on a plan of independent jobs, on one whose jobs chain (half start at the job
// before's last sample: the carry's case), and on one with N.H codes above 1.0 (the only inputs
// where the device's overflow mode shows: saturated to 1.0 or kept). Negative tests: the model
// built with the other sample set, or the other overflow mode, than the RTL must differ at the pins. One elaboration per test
// (gtest_discover_tests runs each in its own process). SHADING_TRACE=<dir>: <dir>/<Suite.Test>.vcd
// (the bench's SystemC signals, the model's nets) and <dir>/<Suite.Test>_rtl.vcd (every net inside
// the RTL).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "core/trace.h"
#include "golden_pipeline/frame_setup.h"
#include "scene/raster.h"
#include "testbenches/rtl/rtl_pipeline_variants.h"
#include "verilated.h"
#include "verilated_vcd_sc.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_pipeline {

using namespace shading;
using namespace shading::pipeline;

using namespace shading::pipeline::rtl_variants;

// Runs the bench to its end; with SHADING_TRACE=<dir> it writes the test's two VCDs (as
// rtl_cosim_tb.h's run_cosim: a Verilated model's internals are not SystemC signals).
template <class Bench>
bool run_traced(Bench& bench, const sc_core::sc_time& limit) {
    const char* dir = std::getenv("SHADING_TRACE");
    const std::string stem = dir && *dir ? std::string(dir) + "/" + tb::current_test_name() : std::string();
    std::unique_ptr<vcd_file> vcd;
    std::unique_ptr<VerilatedVcdSc> rtl_vcd;
    if (!stem.empty()) {
        vcd = std::make_unique<vcd_file>(stem);
        vcd->trace(bench);
    }
    sc_core::sc_start(sc_core::SC_ZERO_TIME);  // Verilator traces an elaborated, initialised model
    if (!stem.empty()) {
        rtl_vcd = std::make_unique<VerilatedVcdSc>();
        bench.other.trace(rtl_vcd.get(), 99);
        rtl_vcd->open((stem + "_rtl.vcd").c_str());
    }
    sc_core::sc_start(limit);
    if (rtl_vcd) rtl_vcd->close();
    return bench.finished();
}

// What a run varies: chain, a plan whose jobs chain (the carry's case); above_one, N.H codes above
// 1.0 too (what the device makes of them is its overflow mode's: SATURATE); other_set, other_mode:
// the model built with the cubic sample set or the overflow mode the RTL was not (the comparison must
// then see differences).
struct run_kind {
    bool chain = false, above_one = false, other_set = false, other_mode = false;
};

template <class V>
void run_rtl(uint64_t seed, run_kind rk) {
    tb::report_log::get().expect(msg::input);  // the invalid jobs (and N.H above 1.0), reported by the model
    Verilated::traceEverOn(true);
    const plan p = random_plan(seed, 400, 64, V::fd_m, 12, rk.chain, rk.above_one);
    const frame_constants k = random_constants(seed);
    scene::device_config dev = V::device();
    if (rk.other_mode) dev.mode = V::mode == overflow_mode::wrap ? overflow_mode::saturate : overflow_mode::wrap;
    plan_config c = V::plan_config_of();
    using interp::sample_set;
    if (rk.other_set) c.set = V::set == sample_set::case1 ? sample_set::case2 : sample_set::case1;
    auto bench = std::make_unique<rtl_pair<V>>("tb", p, k, dev, c, sqmul_device::default_config(),
                                               std::function<bool(const typename V::rtl&)>{}, "rtl");
    const bool finished = run_traced(*bench, pipeline_period() * static_cast<double>(pair_watchdog_clocks(p)));
    ASSERT_TRUE(finished);
    bench->chk_b.finish();
    bench->chk_o.finish();
    std::printf("%zu pins compared over %zu edges, %zu differences; %zu pixels (RTL), %zu jobs dropped, "
                "%zu samples carried\n",
                bench->cmp.valid_edges(), bench->cmp.edges(), bench->cmp.differences(), bench->chk_o.written(),
                bench->chk_b.dropped(), bench->blk.carried());
    if (rk.other_set || rk.other_mode) {
        EXPECT_GT(bench->cmp.differences(), 10u);
        EXPECT_EQ(bench->chk_b.mismatches(), 0u);  // the model against its own golden configuration
        EXPECT_GT(bench->chk_o.mismatches(), 10u);  // the RTL against the model's
        bench.release();
        return;
    }
    EXPECT_EQ(bench->cmp.differences(), 0u);
    EXPECT_GT(bench->cmp.valid_edges(), 500u);
    EXPECT_EQ(bench->chk_b.mismatches(), 0u) << "SystemC model against golden_interval";
    EXPECT_EQ(bench->chk_o.mismatches(), 0u) << "RTL against golden_interval";
    EXPECT_EQ(bench->chk_o.written(), bench->chk_o.pixels());
    EXPECT_EQ(bench->chk_o.order(), bench->chk_b.order());
    // The invalid jobs: dropped by the model (each reported once) and by the RTL (no pixel of theirs
    // written: the checker counts such a write as a mismatch).
    EXPECT_EQ(bench->blk.ctl_sample.dropped(), bench->chk_b.dropped());
    EXPECT_GT(bench->chk_b.dropped(), 5u);
    if (rk.above_one) {
        EXPECT_GT(tb::report_log::get().count(msg::input), bench->chk_b.dropped() + 50);  // and the codes above 1.0
    } else {
        EXPECT_EQ(tb::report_log::get().count(msg::input), bench->chk_b.dropped());
    }
    if (V::carry && rk.chain) {
        EXPECT_GT(bench->blk.carried(), 50u);
    } else if (!V::carry) {
        EXPECT_EQ(bench->blk.carried(), 0u);
    }
    bench.release();  // elaborated for the process's life
}

struct rtl_case {
    const char* name;
    void (*run)(uint64_t, run_kind);  // run_rtl<variant>
    uint64_t seed;
    run_kind kind;
};
void PrintTo(const rtl_case& c, std::ostream* os) { *os << c.name; }

class RtlPipeline : public ::testing::TestWithParam<rtl_case> {};

TEST_P(RtlPipeline, SameAsModelAtEveryEdge) {
    const rtl_case rc = GetParam();
    rc.run(rc.seed, rc.kind);
}

INSTANTIATE_TEST_SUITE_P(
    Random, RtlPipeline,
    ::testing::Values(rtl_case{"horner", run_rtl<horner>, 21, {}},
                      rtl_case{"horner_chained", run_rtl<horner>, 22, {true}},
                      rtl_case{"horner_above_one", run_rtl<horner>, 24, {false, true}},
                      rtl_case{"fd_any_m", run_rtl<fd_any>, 21, {}},
                      rtl_case{"fd_any_m_chained", run_rtl<fd_any>, 22, {true}},
                      rtl_case{"fd_any_m_above_one", run_rtl<fd_any>, 24, {false, true}},
                      rtl_case{"fd_m4", run_rtl<fd_m4>, 21, {}},
                      rtl_case{"fd_m4_chained", run_rtl<fd_m4>, 22, {true}},
                      rtl_case{"fd_m4_above_one", run_rtl<fd_m4>, 24, {true, true}}),
    [](const ::testing::TestParamInfo<rtl_case>& i) { return std::string(i.param.name); });

// The comparison can fail: the model built with the other cubic sample set than the Horner RTL, or
// (N.H above 1.0) with the other overflow mode than the forward-difference RTL's wrap.
TEST(RtlPipelineVerdict, AnotherSampleSetIsSeen) {
    tb::report_log::get().expect(msg::mismatch);  // the RTL's frame buffer checker
    run_rtl<horner>(23, {false, false, true});
}
TEST(RtlPipelineVerdict, AnotherOverflowModeIsSeen) {
    tb::report_log::get().expect(msg::mismatch);
    run_rtl<fd_any>(24, {false, true, false, true});
}

// On a planned frame too (the head at 64, make_plan's plan as render_pipeline_rtl runs it): the model
// and its golden frame built with the case-2 samples beside the Horner RTL's case 1 must differ.
TEST(RtlPipelineVerdict, AnotherSampleSetIsSeenOnAFrame) {
    tb::report_log::get().expect(msg::mismatch);
    const plan_config c = horner::plan_config_of();
    plan_config other = c;
    other.set = interp::sample_set::case2;
    const scene::device_config dev = horner::device();
    const scene::world w = scene_of("head", SHADING_SOURCE_DIR, 64);
    const frame_constants k = frame_constants_of(w);
    const plan p = make_plan(scene::rasterise(w), k, dev, c);
    auto bench = std::make_unique<rtl_pair<horner>>("tb", p, k, dev, other, sqmul_device::default_config(),
                                                    std::function<bool(const Vrtl_pipeline_horner&)>{}, "rtl");
    ASSERT_TRUE(run_traced(*bench, pipeline_period() * static_cast<double>(pair_watchdog_clocks(p))));
    bench->chk_b.finish();
    bench->chk_o.finish();
    std::printf("%zu pixels planned, %zu valid edges, %zu differences\n", bench->chk_o.pixels(),
                bench->cmp.valid_edges(), bench->cmp.differences());
    EXPECT_GT(p.pixels, 1000u);
    EXPECT_GT(bench->cmp.differences(), 10u);
    EXPECT_EQ(bench->chk_b.mismatches(), 0u);   // the model against its own golden configuration
    EXPECT_GT(bench->chk_o.mismatches(), 10u);  // the RTL against the model's
    bench.release();  // elaborated for the process's life
}

}  // namespace test_rtl_pipeline
