// The forward-difference evaluator against its golden model and against the Horner unit's
// golden model, one pixel per clock. Each TEST elaborates its own bench.
#include <gtest/gtest.h>

#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_line.h"
#include "testbenches/interp/interp_fd_bench.h"
#include "core/trace.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_fd {

using namespace shading;
using namespace shading::tb;
using sc_core::sc_time;

namespace {
const sc_time limit(10, sc_core::SC_MS);

std::vector<fd_interval> random_intervals(std::size_t n, unsigned len, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int64_t> ua(-24 * 256 * 65536 + 1, 24 * 256 * 65536 - 1),
        ub(-38 * 256 * 65536 + 1, 38 * 256 * 65536 - 1), uc(-15 * 256 * 65536 + 1, 15 * 256 * 65536 - 1),
        ud(0, 256 * 65536 - 1);
    std::vector<fd_interval> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back({{ua(rng), ub(rng), uc(rng), ud(rng)}, len});
    return v;
}

template <unsigned M>
void expect_exact_and_close_to_horner(fd_bench<M>& bench, std::size_t pixels) {
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), pixels);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    // Documented bound: 0 <= FD - Horner <= 2 LSB of Q16.16 (FD exact then floored; Horner three
    // floors below the exact polynomial).
    EXPECT_GE(bench.checker.min_vs_horner(), 0);
    EXPECT_LE(bench.checker.max_vs_horner(), 2);
}
}  // namespace

// The shortest and the longest supported interval (4 and 64 pixels), random coefficients over
// their whole range: bit-exact, within the bound of Horner, and the default clock meets the phases.
struct interval_case {
    unsigned m;  // N = 2^m pixels
    std::size_t intervals;
    unsigned seed;
};
void PrintTo(const interval_case& c, std::ostream* os) { *os << "N = " << (1u << c.m); }

template <unsigned M>
void expect_intervals_exact(const interval_case& c) {
    fd_bench<M> bench("tb", random_intervals(c.intervals, 1u << M, c.seed));
    expect_exact_and_close_to_horner(bench, c.intervals << M);
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u) << "the default 20 ns clock meets both phases";
}

class InterpFdLength : public ::testing::TestWithParam<interval_case> {};

TEST_P(InterpFdLength, BitExactAndWithinBoundOfHorner) {
    const auto c = GetParam();
    ASSERT_TRUE(c.m == interp::m_min || c.m == interp::m_max);
    if (c.m == interp::m_min) expect_intervals_exact<interp::m_min>(c);
    else expect_intervals_exact<interp::m_max>(c);
}

INSTANTIATE_TEST_SUITE_P(ShortestAndLongest, InterpFdLength,
                         ::testing::Values(interval_case{interp::m_min, 100, 32}, interval_case{interp::m_max, 40, 31}),
                         [](const ::testing::TestParamInfo<interval_case>& i) { return "N" + std::to_string(1u << i.param.m); });

// A raster line of 200 pixels in intervals of 32, the last one 8 pixels long, with the cubic
// and quadratic coefficients of every variant: one pixel per clock, no bubble between intervals.
TEST(InterpFd, RasterLineOnePixelPerClock) {
    const auto line = make_line(200, 5);
    std::vector<fd_interval> ivs;
    for (auto v : all_variants)
        for (const auto& iv : line.intervals) {
            const auto k = variant_coefs(v, iv);
            ivs.push_back({is_quad(v) ? as_cubic(k) : k, iv.len});
        }
    fd_bench<5> bench("tb", ivs);
    expect_exact_and_close_to_horner(bench, 5 * 200);
    for (const auto& [k, lat] : bench.checker.latencies()) {
        ASSERT_EQ(lat.size(), 1u) << "pixel " << k;
        EXPECT_EQ(*lat.begin(), (k + 1) * interp_period()) << "pixel " << k;
    }
    EXPECT_DOUBLE_EQ(bench.checker.cycles_per_pixel(), 1.0);
}

// len = 0 or len > N is bad input: reported (shading/input) and a full interval is evaluated.
TEST(InterpFd, LenOutOfRangeIsReportedAndAFullIntervalEvaluated) {
    report_log::get().expect(msg::input);
    auto ivs = random_intervals(3, 16, 33);
    ivs[1].len = 0;
    ivs[2].len = 17;
    fd_bench<4> bench("tb", ivs);
    expect_exact_and_close_to_horner(bench, 3 * 16);
    EXPECT_EQ(report_log::get().count(msg::input), 2u);
}

TEST(InterpFd, GtkwaveViewShowsOnlyNetsTheVcdDeclares) {
    // traces/interp_fd.gtkw is hand-written: every signal it lists must exist in the VCD of the bench
    // the testbench program builds, or GTKWave silently drops it.
    const std::string base = ::testing::TempDir() + "interp_fd_names";
    {
        fd_bench<5> bench("tb", random_intervals(2, 32, 1));
        vcd_file vcd(base);
        vcd.trace(bench);
        EXPECT_TRUE(tb::run_to_completion(bench, limit));
    }
    const auto declared = vcd_declared(base + ".vcd");
    const auto shown = gtkw_listed(source_path("traces/interp_fd.gtkw"));
    EXPECT_GE(shown.size(), 10u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";

    // What a user sees at first sight (vcd_names.h, view_problems): the view names its dump file,
    // opens with the marker inside the window and off every edge, and shows each bus as a number
    // in its format from src/floor/formats/interp_formats.h (counters and selects: integers).
    using interp::coef_fmt, interp::sample_fmt, interp::sum_fmt;
    view_formats f;
    for (const char* s : {"tb.a", "tb.b", "tb.c", "tb.d", "tb.i_px"}) f[s] = coef_fmt;
    for (const char* s : {"init_p", "init_d1", "init_d2", "init_d3", "p_value", "d1_value", "d2_value", "d3_value",
                          "p_sum", "d1_sum", "d2_sum", "p_next", "d1_next", "d2_next", "d3_keep"})
        f[std::string("tb.dut.") + s] = interp::fd_fmt;
    f["tb.len"] = f["tb.dut.pixel"] = qfmt{6, false, 0};
    f["tb.dut.fd_sel"] = qfmt{2, false, 0};
    const auto problems = view_problems(source_path("traces/interp_fd.gtkw"), base + ".vcd", "interp_fd", f,
                                        {"tb.valid", "tb.last", "tb.i_px"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

// High phase 1 ns shorter (1.3 ns, period 20 ns): reported at every falling edge (the first 10).
// This bench's source presents A..D a clock before the accepting edge, earlier than fd_ctrl's
// contract requires, so its set-up values have settled and the pixels stay exact; a source that
// settles A..D at the accepting edge itself would load unsettled set-up values.
TEST(InterpFdTiming, HighPhaseOneNanosecondShortIsReported) {
    report_log::get().expect(msg::timing);
    interp_clock ck;
    ck.high = sc_time(1300, sc_core::SC_PS);
    ck.low = sc_time(18700, sc_core::SC_PS);
    fd_bench<3> bench("tb", random_intervals(4, 8, 34), ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.chk_clock.high_violations(), 10u);
    EXPECT_EQ(bench.dut.chk_clock.low_violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 10u) << "the first 10 violations are reported";
    EXPECT_EQ(bench.checker.samples().size(), 4u * 8u);
}

// High phase 0.2 ns, shorter than even fd_sel -> MX (0.3 ns): the registers latch the previous
// selection's value, so intervals load late and the pixels are wrong.
TEST(InterpFdTiming, HighPhaseShorterThanTheSelectPathGivesWrongPixels) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    interp_clock ck;
    ck.high = sc_time(200, sc_core::SC_PS);
    ck.low = sc_time(19800, sc_core::SC_PS);
    fd_bench<3> bench("tb", random_intervals(4, 8, 35), ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.chk_clock.high_violations(), 0u);
    EXPECT_GT(report_log::get().count(msg::timing), 0u);
    EXPECT_GT(bench.checker.mismatches(), 0u);
}

// Both phases 1 ns longer than required (3.3 ns high, 1.2 ns low: a 4.5 ns clock): silent,
// bit-exact, one pixel per clock.
TEST(InterpFdTiming, PhasesOneNanosecondLongerAreSilentAndBitExact) {
    interp_clock ck;
    ck.high = sc_time(3300, sc_core::SC_PS);
    ck.low = sc_time(1200, sc_core::SC_PS);
    fd_bench<4> bench("tb", random_intervals(6, 16, 36), ck);
    expect_exact_and_close_to_horner(bench, 6 * 16);
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 0u);
    EXPECT_DOUBLE_EQ(bench.checker.cycles_per_pixel(), 1.0);
}

}  // namespace test_interp_fd
