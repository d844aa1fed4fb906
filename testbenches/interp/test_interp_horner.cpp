// The iterative Horner unit (the interpolation paper, Fig. 4) against its golden model, micro-step by
// micro-step, and its latency and throughput in clocks. Each TEST elaborates its own bench.
#include <gtest/gtest.h>

#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_horner_bench.h"
#include "core/trace.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_horner {

using namespace shading;
using namespace shading::tb;
using sc_core::sc_time;

namespace {
const sc_time limit(10, sc_core::SC_MS);

// Random coefficients within the documented bounds (interp_formats.h), every t = k/2^m of an
// interval including t = 1.
std::vector<horner_request> every_t(std::size_t intervals, unsigned m, bool deg2, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int64_t> ua(-24 * 256 * 65536 + 1, 24 * 256 * 65536 - 1),
        ub(-38 * 256 * 65536 + 1, 38 * 256 * 65536 - 1), uc(-15 * 256 * 65536 + 1, 15 * 256 * 65536 - 1),
        ud(0, 256 * 65536 - 1);
    std::vector<horner_request> r;
    for (std::size_t i = 0; i < intervals; ++i) {
        const interp::cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
        for (unsigned j = 0; j <= (1u << m); ++j) r.push_back({k, uint64_t{j} << (8 - m), deg2});
    }
    return r;
}
}  // namespace

// The two degrees differ only in constants: the micro-steps per pixel (6 cubic, 4 degree 2), the
// interval of t values and the random seeds.
struct degree_case {
    bool deg2;
    unsigned steps;         // micro-steps (clocks) per pixel
    unsigned m;             // every t = k / 2^m, k = 0..2^m, for the bit-exact run
    unsigned exact_seed, timing_seed;
};
void PrintTo(const degree_case& c, std::ostream* os) { *os << (c.deg2 ? "degree 2" : "cubic"); }

class InterpHornerDegree : public ::testing::TestWithParam<degree_case> {};

TEST_P(InterpHornerDegree, BitExactEveryTOfAnInterval) {
    const auto p = GetParam();
    horner_bench bench("tb", every_t(12, p.m, p.deg2, p.exact_seed));
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), 12u * ((1u << p.m) + 1u));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    for (const auto& s : bench.checker.samples()) EXPECT_EQ(s.steps.size(), p.steps);
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u) << "the default 20 ns clock meets both phases";
}

// Latency: I(t) is on the output 6 clocks (cubic) / 4 clocks (degree 2) after the edge that
// accepted the request. Throughput back to back: one pixel per 6 / 4 clocks.
TEST_P(InterpHornerDegree, LatencyAndThroughput) {
    const auto p = GetParam();
    horner_bench bench("tb", every_t(2, 4, p.deg2, p.timing_seed));
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 34u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    for (const auto& x : s) EXPECT_EQ(x.valid - x.accepted, static_cast<double>(p.steps) * interp_period()) << "at " << x.valid;
    for (std::size_t i = 1; i < s.size(); ++i)
        EXPECT_EQ(s[i].accepted, s[i - 1].valid) << "back-to-back: the done edge accepts the next request";
    EXPECT_DOUBLE_EQ(bench.checker.cycles_per_result(), static_cast<double>(p.steps));
    EXPECT_EQ(s.front().accepted, interp_period());  // presented after the edge at 0, accepted at the next
}

INSTANTIATE_TEST_SUITE_P(Degrees, InterpHornerDegree,
                         ::testing::Values(degree_case{false, 6, 5, 21, 23}, degree_case{true, 4, 6, 22, 24}),
                         [](const ::testing::TestParamInfo<degree_case>& i) { return i.param.deg2 ? "Degree2" : "Cubic"; });

// Idle gaps between requests change neither results nor latency; RG holds I(t) while idle.
TEST(InterpHorner, GapsBetweenRequestsAndHoldWhileIdle) {
    auto reqs = every_t(3, 3, false, 25);
    for (std::size_t i = 0; i < reqs.size(); i += 2) reqs[i].deg2 = true;  // mixed degrees
    const auto last = interp::golden_horner(reqs.back().k, reqs.back().t, reqs.back().deg2);
    horner_bench bench("tb", reqs, 3);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), reqs.size());
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    for (const auto& x : s)
        EXPECT_EQ(x.valid - x.accepted, (x.req.deg2 ? 4 : 6) * interp_period());
    EXPECT_GT(bench.checker.cycles_per_result(), 6.0);
    // The bench stops two clocks after the last done: the output still holds the last I(t).
    EXPECT_EQ(bench.i_t.read().to_uint64(), last);
    EXPECT_FALSE(bench.busy.read());
}

// t > 1 is bad input: reported (shading/input) and evaluated as given, bit-exact to the golden
// model (which applies the same floors and wraps).
TEST(InterpHorner, TAboveOneIsReportedAndEvaluatedAsGiven) {
    report_log::get().expect(msg::input);
    auto reqs = every_t(1, 2, false, 26);
    reqs.push_back({reqs.front().k, 300, false});
    reqs.push_back({reqs.front().k, 511, true});
    horner_bench bench("tb", reqs);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), reqs.size());
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
}

// The checker can fail: a golden model whose step 3 is off by one LSB is caught every time.
TEST(InterpHorner, CheckerCatchesAWrongMicroStep) {
    report_log::get().expect(msg::mismatch);
    auto wrong = [](const horner_request& r) {
        auto s = horner_checker::golden(r);
        s[2] = (s[2] + 1) & interp::coef_fmt.mask();
        return s;
    };
    horner_bench bench("tb", every_t(1, 2, false, 27), 0, wrong);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.mismatches(), 5u);
    EXPECT_GT(report_log::get().count(msg::mismatch), 0u);
}

TEST(InterpHorner, GtkwaveViewShowsOnlyNetsTheVcdDeclares) {
    // traces/interp_horner.gtkw is hand-written: every signal it lists must exist in the VCD of the bench
    // the testbench program builds, or GTKWave silently drops it.
    const std::string base = ::testing::TempDir() + "interp_horner_names";
    {
        horner_bench bench("tb", every_t(1, 2, false, 1));
        vcd_file vcd(base);
        vcd.trace(bench);
        EXPECT_TRUE(tb::run_to_completion(bench, limit));
    }
    const auto declared = vcd_declared(base + ".vcd");
    const auto shown = gtkw_listed(source_path("traces/interp_horner.gtkw"));
    EXPECT_GE(shown.size(), 10u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";

    // What a user sees at first sight (vcd_names.h, view_problems): the view names its dump file,
    // opens with the marker inside the window and off every edge, and shows each bus as a number
    // in its format from src/floor/formats/interp_formats.h (counters and selects: integers).
    using interp::coef_fmt, interp::sample_fmt, interp::sum_fmt;
    view_formats f;
    for (const char* s : {"tb.a", "tb.b", "tb.c", "tb.d", "tb.i_t", "tb.dut.mx1_operand", "tb.dut.mul_product",
                          "tb.dut.mx2_operand", "tb.dut.bk_operand", "tb.dut.sm_sum", "tb.dut.rg_value"})
        f[s] = interp::horner_fmt;
    f["tb.t"] = interp::t_fmt;
    f["tb.dut.step"] = f["tb.dut.mx2_sel"] = qfmt{3, false, 0};
    const auto problems = view_problems(source_path("traces/interp_horner.gtkw"), base + ".vcd", "interp_horner", f,
                                        {"tb.done", "tb.busy", "tb.i_t"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

// High phase 1 ns shorter (3.6 ns, period still 20 ns): RG latches Sm before MUL's product has
// reached it. Every falling edge is a violation; the first 10 are reported, the results are wrong.
TEST(InterpHornerTiming, HighPhaseOneNanosecondShortIsReportedAndResultsAreWrong) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    interp_clock ck;
    ck.high = sc_time(3600, sc_core::SC_PS);
    ck.low = sc_time(16400, sc_core::SC_PS);
    horner_bench bench("tb", every_t(2, 3, false, 28), 0, &horner_checker::golden, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.chk_clock.high_violations(), 10u);
    EXPECT_EQ(bench.dut.chk_clock.low_violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 10u) << "the first 10 violations are reported";
    EXPECT_GT(bench.checker.mismatches(), 0u) << "RG latched unsettled sums";
}

// Both phases 1 ns longer than required (5.6 ns high, 1.2 ns low: a 6.8 ns clock): silent,
// bit-exact, and still 6 clocks per cubic pixel.
TEST(InterpHornerTiming, PhasesOneNanosecondLongerAreSilentAndBitExact) {
    interp_clock ck;
    ck.high = sc_time(5600, sc_core::SC_PS);
    ck.low = sc_time(1200, sc_core::SC_PS);
    horner_bench bench("tb", every_t(4, 4, false, 29), 0, &horner_checker::golden, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), 4u * 17u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 0u);
    for (const auto& x : bench.checker.samples()) EXPECT_EQ(x.valid - x.accepted, 6 * sc_time(6800, sc_core::SC_PS));
}

}  // namespace test_interp_horner
