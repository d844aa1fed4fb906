// The coefficient units (SystemC) against their golden models, bit for bit. Each TEST elaborates
// its own bench (one process per test through gtest_discover_tests).
#include <gtest/gtest.h>

#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_line.h"
#include "testbenches/interp/interp_coef_bench.h"
#include "core/trace.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_coef {

using namespace shading;
using namespace shading::tb;
using sc_core::sc_time;

namespace {
std::vector<coef_inputs> random_sets(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint64_t> u(0, interp::sample_fmt.mask());
    std::vector<coef_inputs> v;
    // Corners: all zero, all full scale, and the sign patterns that maximise |A|, |B|, |C|.
    const uint64_t hi = interp::sample_fmt.mask();
    v.push_back({{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0}});
    v.push_back({{hi, hi, hi, hi}, {hi, hi, hi, hi}, {hi, hi, hi}});
    v.push_back({{hi, 0, hi, 0}, {hi, 0, hi, 0}, {hi, 0, hi}});
    v.push_back({{0, hi, 0, hi}, {0, hi, 0, hi}, {0, hi, 0}});
    v.push_back({{hi, 0, 0, hi}, {0, hi, hi, 0}, {hi, hi, 0}});
    while (v.size() < n) v.push_back({{u(rng), u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}});
    return v;
}
}  // namespace

TEST(InterpCoefUnits, BitExactAgainstGoldenRandomAndCorners) {
    coef_bench bench("tb", random_sets(400, 11));
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(bench.checker.samples().size(), 400u);
    for (std::size_t u = 0; u < 5; ++u) EXPECT_EQ(bench.checker.mismatches(u), 0u) << "unit " << u;
    EXPECT_EQ(report_log::get().count(msg::timing), 0u) << "the default 20 ns clock meets every unit's phases";
}

// A raster line's intervals: the units' coefficients are those of the real-valued formulas
// within the documented bounds (exact division: floor, < 1 LSB; shift-and-add: x 129/128).
TEST(InterpCoefUnits, RasterLineCoefficientsAgainstRealFormulas) {
    const auto line = make_line(200, 5);
    std::vector<coef_inputs> sets;
    for (const auto& iv : line.intervals) sets.push_back({iv.c1, iv.c2, iv.q});
    coef_bench bench("tb", sets);
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    ASSERT_EQ(bench.checker.samples().size(), sets.size());
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    const double lsb = interp::coef_fmt.lsb();
    for (const auto& s : bench.checker.samples()) {
        auto r8 = [](uint64_t c) { return static_cast<double>(c) / 256.0; };
        const auto r1 = ref::cubic_coefs({r8(s.in.c1[0]), r8(s.in.c1[1]), r8(s.in.c1[2]), r8(s.in.c1[3])}, interp::sample_set::case1);
        EXPECT_NEAR(s.out[1].a * lsb, r1.a, lsb);  // exact division
        EXPECT_NEAR(s.out[1].c * lsb, r1.c, lsb);
        EXPECT_NEAR(s.out[0].a * lsb, r1.a * 129.0 / 128.0, 1e-9);  // shift-and-add
        EXPECT_NEAR(s.out[0].c * lsb, r1.c * 129.0 / 128.0, 1e-9);
        EXPECT_DOUBLE_EQ(s.out[0].b * lsb, r1.b);
        EXPECT_DOUBLE_EQ(s.out[0].d * lsb, r1.d);
        const auto rq = ref::quad_coefs({r8(s.in.q[0]), r8(s.in.q[1]), r8(s.in.q[2])});
        EXPECT_DOUBLE_EQ(s.out[4].a * lsb, rq.b);
        EXPECT_DOUBLE_EQ(s.out[4].b * lsb, rq.c);
        EXPECT_DOUBLE_EQ(s.out[4].c * lsb, rq.d);
    }
}

// Latency one clock, throughput one interval per clock: the samples presented after edge e are
// checked (and match) at edge e + T, one set per edge.
TEST(InterpCoefUnits, OneIntervalPerClock) {
    coef_bench bench("tb", random_sets(50, 12));
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 50u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    for (std::size_t i = 1; i < s.size(); ++i) EXPECT_EQ(s[i].at - s[i - 1].at, interp_period());
    EXPECT_EQ(s.front().at, interp_period());  // presented after the edge at 0, valid at the next
}

// The checker can fail: a golden model with B off by one LSB is caught on every sample.
TEST(InterpCoefUnits, CheckerCatchesAWrongGolden) {
    report_log::get().expect(msg::mismatch);
    auto wrong = [](std::size_t unit, const coef_inputs& in) {
        auto k = coef_checker::golden(unit, in);
        if (unit == 0) ++k.b;
        return k;
    };
    coef_bench bench("tb", random_sets(20, 13), wrong);
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(bench.checker.mismatches(0), 20u);
    EXPECT_EQ(bench.checker.mismatches(1), 0u);
    EXPECT_GT(report_log::get().count(msg::mismatch), 0u);
}

TEST(InterpCoefUnits, GtkwaveViewShowsOnlyNetsTheVcdDeclares) {
    // traces/interp_coef.gtkw is hand-written: every signal it lists must exist in the VCD of the bench
    // the testbench program builds, or GTKWave silently drops it.
    const std::string base = ::testing::TempDir() + "interp_coef_names";
    {
        coef_bench bench("tb", random_sets(4, 1));
        vcd_file vcd(base);
        vcd.trace(bench);
        EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    }
    const auto declared = vcd_declared(base + ".vcd");
    const auto shown = gtkw_listed(source_path("traces/interp_coef.gtkw"));
    EXPECT_GE(shown.size(), 10u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";

    // What a user sees at first sight (vcd_names.h, view_problems): the view names its dump file,
    // opens with the marker inside the window and off every edge, and shows each bus as a number
    // in its format from src/floor/formats/interp_formats.h (counters and selects: integers).
    using interp::coef_fmt, interp::sample_fmt, interp::sum_fmt;
    view_formats f;
    for (const char* s : {"tb.c1_i", "tb.c2_i", "tb.dut_c1_sa.held_i"})
        for (int i = 1; i <= 4; ++i) f[s + std::to_string(i)] = sample_fmt;
    for (int i = 1; i <= 3; ++i) f["tb.q_i" + std::to_string(i)] = sample_fmt;
    for (const char* s : {"a8_sum", "b_sum", "c3_sum"}) f[std::string("tb.dut_c1_sa.") + s] = sum_fmt;
    for (const char* u : {"c1sa_", "c1ex_", "c2sa_", "c2ex_", "quad_"})
        for (const char* k : {"a", "b", "c", "d"}) f[std::string("tb.") + u + k] = coef_fmt;
    const auto problems = view_problems(source_path("traces/interp_coef.gtkw"), base + ".vcd", "interp_coef", f,
                                        {"tb.sample_valid", "tb.c1sa_a", "tb.c1sa_b", "tb.c1sa_c", "tb.c1sa_d"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

// Low phase 1 ns shorter than the quadratic unit needs (2.3 ns; period 20 ns): every unit
// reports, and each one's coefficients are sampled before they settle.
TEST(InterpCoefTiming, LowPhaseOneNanosecondShortIsReportedByEveryUnit) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    interp_clock ck;
    ck.high = sc_time(17700, sc_core::SC_PS);
    ck.low = sc_time(2300, sc_core::SC_PS);
    coef_bench bench("tb", random_sets(30, 14), &coef_checker::golden, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    for (auto v : {bench.dut_c1_sa.chk_clock.low_violations(), bench.dut_c1_ex.chk_clock.low_violations(),
                   bench.dut_c2_sa.chk_clock.low_violations(), bench.dut_c2_ex.chk_clock.low_violations(),
                   bench.dut_quad.chk_clock.low_violations()})
        EXPECT_GT(v, 0u);
    EXPECT_GT(report_log::get().count(msg::timing), 0u);
    for (std::size_t u = 0; u < 5; ++u) EXPECT_GT(bench.checker.mismatches(u), 0u) << "unit " << u;
}

// Phases 1 ns longer than the slowest unit needs (1 ns high, 8.3 ns low: a 9.3 ns clock):
// silent, bit-exact, one interval per clock.
TEST(InterpCoefTiming, PhasesOneNanosecondLongerAreSilentAndBitExact) {
    interp_clock ck;
    ck.high = sc_time(1000, sc_core::SC_PS);
    ck.low = sc_time(8300, sc_core::SC_PS);
    coef_bench bench("tb", random_sets(60, 15), &coef_checker::golden, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 60u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 0u);
    for (std::size_t i = 1; i < s.size(); ++i) EXPECT_EQ(s[i].at - s[i - 1].at, ck.period());
}

}  // namespace test_interp_coef
