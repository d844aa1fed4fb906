// The fast pin-level abstraction of the Horner unit (interp/horner_unit_fast.h): alone in the Horner
// bench against the golden model (every micro-step's RG, latency, throughput; random differential
// runs back to back and with gaps), and side by side with the block-level unit on the same pins,
// every output compared at every rising edge. One elaboration per test (its own process).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "testbenches/common/pin_compare.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_horner_bench.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_horner_fast {

using namespace shading;
using namespace shading::tb;

namespace {

const sc_core::sc_time limit(1, sc_core::SC_SEC);

// One stimulus (driven by the block unit's handshake), both units on its pins, the comparator.
class horner_pair_bench : public sc_core::sc_module {
public:
    sc_core::sc_clock clk{"clk", interp_period()};
    sc_core::sc_signal<bool> start{"start"}, deg2{"deg2"}, done_b{"done_b"}, busy_b{"busy_b"}, done_f{"done_f"},
        busy_f{"busy_f"};
    sc_core::sc_signal<coef_t> a{"a"}, b{"b"}, c{"c"}, d{"d"}, i_b{"i_b"}, i_f{"i_f"};
    sc_core::sc_signal<t_t> t{"t"};
    horner_unit blk{"blk"};
    horner_unit_fast fst{"fst"};
    horner_stimulus stim;
    tb::pin_compare cmp{"cmp"};  // done, busy, i_t and RG at every rising edge

    horner_pair_bench(const sc_core::sc_module_name& name, item_source<horner_request> reqs, unsigned gap)
        : sc_module(name), stim("stim", std::move(reqs), gap) {
        blk.clk(clk); blk.start(start); blk.deg2(deg2); blk.a(a); blk.b(b); blk.c(c); blk.d(d); blk.t(t);
        blk.i_t(i_b); blk.done(done_b); blk.busy(busy_b);
        fst.clk(clk); fst.start(start); fst.deg2(deg2); fst.a(a); fst.b(b); fst.c(c); fst.d(d); fst.t(t);
        fst.i_t(i_f); fst.done(done_f); fst.busy(busy_f);
        stim.clk(clk); stim.busy(busy_b); stim.done(done_b); stim.start(start); stim.deg2(deg2);
        stim.a(a); stim.b(b); stim.c(c); stim.d(d); stim.t(t);
        cmp.clk(clk);
        cmp.pair("done", done_b, done_f);
        cmp.pair("busy", busy_b, busy_f);
        cmp.pair("i_t", i_b, i_f);
        cmp.pair("rg", blk.rg_value, fst.rg_value);
        cmp.count(done_b);
    }
    bool finished() const { return stim.finished(); }
};

}  // namespace

// Random requests (random samples through every coefficient unit's golden coefficients, both
// degrees, t in [0, 1]) back to back and with gaps: every micro-step's RG equals golden_horner_steps,
// one result per 6 (cubic) or 4 (degree 2) clocks, each 6 / 4 clocks after its acceptance.
class InterpHornerFastRandom : public ::testing::TestWithParam<unsigned> {};
TEST_P(InterpHornerFastRandom, BitExactAgainstTheGoldenModel) {
    const unsigned gap = GetParam();
    horner_bench_fast bench("tb", random_horner_requests(20000, 11 + gap), gap);
    bench.checker.keep_samples(false);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.checked(), 20000u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    const std::set<sc_core::sc_time> want{4 * interp_period(), 6 * interp_period()};
    EXPECT_EQ(bench.checker.latencies(), want);
    if (gap == 0) {
        // Back to back: the clocks per result lie between the degree-2 and the cubic step counts.
        EXPECT_GT(bench.checker.cycles_per_result(), 4.0);
        EXPECT_LT(bench.checker.cycles_per_result(), 6.0);
    }
}
INSTANTIATE_TEST_SUITE_P(Gaps, InterpHornerFastRandom, ::testing::Values(0u, 1u, 3u));

// Side by side with the block-level unit: done, busy, i_t and RG equal at every rising edge.
class InterpHornerFastPins : public ::testing::TestWithParam<unsigned> {};
TEST_P(InterpHornerFastPins, SameAsBlockLevelAtEveryEdge) {
    const unsigned gap = GetParam();
    horner_pair_bench bench("tb", random_horner_requests(3000, 21 + gap), gap);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.cmp.differences(), 0u);
    EXPECT_EQ(bench.cmp.counted(), 3000u);
    EXPECT_GT(bench.cmp.edges(), 3000u * 4u);
}
INSTANTIATE_TEST_SUITE_P(Gaps, InterpHornerFastPins, ::testing::Values(0u, 2u));

// t above 1 (extrapolation) is reported as the block model's controller does and evaluated as given.
TEST(InterpHornerFast, TAboveOneIsReportedAndEvaluatedAsGiven) {
    tb::report_log::get().expect(msg::input);
    std::vector<horner_request> reqs{{{1 << 16, 2 << 16, 3 << 16, 4 << 16}, 128, false},
                                     {{1 << 16, 2 << 16, 3 << 16, 4 << 16}, 300, false},
                                     {{1 << 16, 2 << 16, 3 << 16, 4 << 16}, 64, true}};
    horner_bench_fast bench("tb", reqs);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.checker.checked(), 3u);
    EXPECT_EQ(tb::report_log::get().count(msg::input), 1u);
}

// The checker can fail on the fast unit too: one corrupted golden value is one mismatch.
TEST(InterpHornerFast, CheckerCatchesOneWrongResult) {
    tb::report_log::get().expect(msg::mismatch);
    horner_bench_fast bench("tb", random_horner_requests(50, 5));
    bench.checker.inject_mismatch(17);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.mismatches(), 1u);
}

}  // namespace test_interp_horner_fast
