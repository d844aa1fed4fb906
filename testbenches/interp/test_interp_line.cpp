// The raster-line interpolator (modules/interp_line_unit.h): the coefficient unit feeding the
// forward-difference evaluator, against the golden chain (golden_cubic_coefs + golden_fd) and
// hand-worked clock counts. Each TEST elaborates its own bench.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "testbenches/interp/interp_line.h"
#include "testbenches/interp/interp_line_bench.h"
#include "core/trace.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_line {

using namespace shading;
using namespace shading::tb;
using interp::div3_mode;
using interp::sample_set;
using sc_core::sc_time;

namespace {
const sc_time limit(10, sc_core::SC_MS);

// Random samples over the whole Q8.8 range, every interval `len` pixels long.
std::vector<interp::interval_samples> random_intervals(std::size_t n, unsigned len, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint64_t> u(0, 0xffff);
    std::vector<interp::interval_samples> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back({{u(rng), u(rng), u(rng), u(rng)}, len});
    return v;
}

// Random samples, intervals of 1 and 4 pixels alternating (N = 4).
std::vector<interp::interval_samples> alternating_intervals(std::size_t n, unsigned seed) {
    auto v = random_intervals(n, 4, seed);
    for (std::size_t i = 0; i < n; i += 2) v[i].len = 1;
    return v;
}

// The golden chain by hand: the ramp I(t) = 64 + 128 t sampled for case 1 (I1..I4 = 64, 96, 128, 192
// at t = 0, 1/4, 1/2, 1) gives A = B = 0, D = 64 and C = 128 with the exact /3, but C = 384 * 43/128
// = 129 with the shift-and-add /3 (the paper's 0.78 % in C): pixels D + C k/4 on Q16.16. A len of 3
// outputs 3 pixels, a len of 0 (out of range) a full interval of 4, as fd_ctrl does.
TEST(InterpLineGolden, HandWorkedRamp) {
    const std::array<uint64_t, 4> ramp{64 * 256, 96 * 256, 128 * 256, 192 * 256};  // Q8.8
    const uint64_t q16 = 65536;
    EXPECT_EQ(interp::golden_interp_line({{ramp, 4}}, 2, sample_set::case1, div3_mode::exact),
              (std::vector<uint64_t>{64 * q16, 96 * q16, 128 * q16, 160 * q16}));
    EXPECT_EQ(interp::golden_interp_line({{ramp, 4}, {ramp, 3}}, 2, sample_set::case1, div3_mode::shift_add),
              (std::vector<uint64_t>{64 * q16, 96 * q16 + q16 / 4, 128 * q16 + q16 / 2, 160 * q16 + 3 * q16 / 4,
                                     64 * q16, 96 * q16 + q16 / 4, 128 * q16 + q16 / 2}));
    EXPECT_EQ(interp::golden_interp_line({{ramp, 0}}, 2, sample_set::case1, div3_mode::exact).size(), 4u);
}

// The 200-pixel raster line (make_line: 6 intervals of 32 pixels and a last one of 8) through the
// line unit: bit-exact against the golden chain, one pixel per clock with no bubble, `last` on the
// last pixel of every interval, and max |I - exact| no larger than the figure measured for this
// variant through the separate units (modules/interp/README.md, "Measured": the same pixels, so the same figure).
template <typename Bench>
void expect_raster_line(Bench& bench, const line_scenario& line, sample_set set, div3_mode mode,
                        double measured_max_error) {
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 200u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.checker.pixels(), interp::golden_interp_line(line_intervals(line, set), 5, set, mode))
        << "the whole line against the golden chain";
    // Hand count: samples presented just after edge E0, accepted at E0 + T (latched at E0 + T/2,
    // A..D formed in that low phase), loaded into the FD registers at E0 + 3T/2, pixel 0 at E0 + 2T;
    // then one pixel per clock across the interval boundaries: pixel p at E0 + (p + 2) T, the last
    // (p = 199) at E0 + 201 T.
    const sc_time e0 = bench.stim.presented().front();
    for (std::size_t p = 0; p < s.size(); ++p) {
        EXPECT_EQ(s[p].valid, e0 + static_cast<double>(p + 2) * interp_period()) << "pixel " << p;
        const bool interval_end = (p + 1) % 32 == 0 || p == 199;
        EXPECT_EQ(s[p].last, interval_end) << "pixel " << p;
    }
    EXPECT_DOUBLE_EQ(bench.clocks_first_samples_to_last_pixel(), 201.0);
    EXPECT_EQ(s.back().interval, 6u);
    EXPECT_EQ(s.back().k, 7u) << "the last interval is 8 pixels long";
    double max_err = 0.0;
    for (std::size_t p = 0; p < s.size(); ++p)
        max_err = std::max(max_err, std::abs(to_real(s[p].out, interp::coef_fmt) - line.exact[p]));
    EXPECT_LE(max_err, measured_max_error);
    EXPECT_EQ(bench.dut.phase_violations(), 0u) << "the default 20 ns clock meets every phase";
}
}  // namespace

// The four coefficient variants differ only in the sample set, the divider and the measured
// maximum error: case 1 (t = 0, 1/4, 1/2, 1, the interpolation paper's preferred) and case 2 (t = 0, 1/2, 3/4, 1,
// with the exact /3 the variant with the smallest error), /3 by the Fig. 2 shift-and-add or exact.
struct line_case {
    sample_set set;
    div3_mode mode;
    double measured_max_error;  // intensity levels (modules/interp/README.md, "Measured")
};
void PrintTo(const line_case& c, std::ostream* os) {
    *os << (c.set == sample_set::case1 ? "case 1, " : "case 2, ") << (c.mode == div3_mode::shift_add ? "shift-and-add" : "exact");
}

template <sample_set SET, div3_mode DIV>
void expect_line_variant(const line_case& c) {
    const auto line = make_line(200, 5);
    line_bench<5, SET, DIV> bench("tb", line_intervals(line, SET));
    expect_raster_line(bench, line, SET, DIV, c.measured_max_error);
}

class InterpLineVariant : public ::testing::TestWithParam<line_case> {};

TEST_P(InterpLineVariant, RasterLineBitExactOnePixelPerClock) {
    const auto c = GetParam();
    const bool sa = c.mode == div3_mode::shift_add;
    if (c.set == sample_set::case1) {
        if (sa) expect_line_variant<sample_set::case1, div3_mode::shift_add>(c);
        else expect_line_variant<sample_set::case1, div3_mode::exact>(c);
    } else {
        if (sa) expect_line_variant<sample_set::case2, div3_mode::shift_add>(c);
        else expect_line_variant<sample_set::case2, div3_mode::exact>(c);
    }
}

INSTANTIATE_TEST_SUITE_P(Variants, InterpLineVariant,
                         ::testing::Values(line_case{sample_set::case1, div3_mode::shift_add, 32.35},
                                           line_case{sample_set::case1, div3_mode::exact, 32.15},
                                           line_case{sample_set::case2, div3_mode::shift_add, 30.85},
                                           line_case{sample_set::case2, div3_mode::exact, 30.55}),
                         [](const ::testing::TestParamInfo<line_case>& i) {
                             return std::string(i.param.set == sample_set::case1 ? "Case1" : "Case2") +
                                    (i.param.mode == div3_mode::shift_add ? "ShiftAdd" : "ExactDiv");
                         });

// A line of 193 pixels in intervals of 16: twelve full ones and a last one of a single pixel,
// accepted at the edge of the previous interval's last pixel. 193 + 1 clocks from the first samples.
TEST(InterpLine, LastIntervalOfOnePixel) {
    const auto line = make_line(193, 4);
    ASSERT_EQ(line.intervals.back().len, 1u);
    line_bench<4, sample_set::case1, div3_mode::shift_add> bench("tb", line_intervals(line, sample_set::case1));
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 193u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.checker.pixels(),
              interp::golden_interp_line(line_intervals(line, sample_set::case1), 4, sample_set::case1,
                                         div3_mode::shift_add));
    EXPECT_EQ(s.back().interval, 12u);
    EXPECT_EQ(s.back().k, 0u);
    EXPECT_TRUE(s.back().last);
    EXPECT_TRUE(s[191].last) << "the last pixel of the last full interval";
    EXPECT_DOUBLE_EQ(bench.clocks_first_samples_to_last_pixel(), 194.0);
}

// Intervals of 1 and 4 pixels alternating, back to back: each 4-pixel interval's samples are
// presented at the edge that accepts the 1-pixel one before it, latched half a clock later and
// loaded into the FD registers one clock after that, so the path between the units
// (sample_to_load) is exercised by every 4-pixel interval, and its D1..D3 show in pixels 1..3. A 1-pixel
// interval outputs D = I1 (Q8.8 -> Q16.16). 100 pixels in 101 clocks.
TEST(InterpLine, ShortIntervalsBackToBack) {
    const auto ivs = alternating_intervals(40, 47);
    line_bench<2, sample_set::case2, div3_mode::shift_add> bench("tb", ivs);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 100u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.checker.pixels(), interp::golden_interp_line(ivs, 2, sample_set::case2, div3_mode::shift_add));
    for (const auto& px : s)
        if (px.interval % 2 == 0) {
            EXPECT_EQ(px.out, ivs[px.interval].i[0] << 8) << "interval " << px.interval;
        }
    EXPECT_DOUBLE_EQ(bench.clocks_first_samples_to_last_pixel(), 101.0);
}

// A source that presents each interval 3 clocks after the previous one's last pixel: the unit is
// idle in between, and each interval's pixel k comes k + 2 clocks after its samples were presented.
TEST(InterpLine, GapsBetweenIntervalsLatencyTwoClocks) {
    const auto ivs = random_intervals(5, 8, 42);
    line_bench<3, sample_set::case1, div3_mode::exact> bench("tb", ivs, 3);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    const auto& s = bench.checker.samples();
    ASSERT_EQ(s.size(), 40u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    const auto& presented = bench.stim.presented();
    ASSERT_EQ(presented.size(), 5u);
    for (std::size_t i = 0; i < s.size(); ++i)
        EXPECT_EQ(s[i].valid, presented[s[i].interval] + static_cast<double>(s[i].k + 2) * interp_period())
            << "interval " << s[i].interval << " pixel " << s[i].k;
}

// A golden chain with one pixel's LSB flipped: the checker reports exactly that pixel.
TEST(InterpLine, CheckerCatchesAWrongGolden) {
    report_log::get().expect(msg::mismatch);
    const auto ivs = random_intervals(4, 8, 43);
    const auto bad = ivs[2];
    auto wrong = [bad](const interp::interval_samples& iv) {
        auto px = interp::golden_interp_line({iv}, 3, sample_set::case1, div3_mode::shift_add);
        if (iv.i == bad.i) px[5] ^= 1u;
        return px;
    };
    line_bench<3, sample_set::case1, div3_mode::shift_add> bench("tb", ivs, 0, wrong);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), 32u);
    EXPECT_EQ(bench.checker.mismatches(), 1u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 1u);
    EXPECT_FALSE(bench.checker.samples()[2 * 8 + 5].matched);
}

TEST(InterpLine, GtkwaveViewShowsOnlyNetsTheVcdDeclares) {
    // traces/interp_line.gtkw is hand-written: every signal it lists must exist in the VCD of the
    // bench interp_line_tb builds (default: case 1, shift-and-add /3, m = 5), or GTKWave drops it.
    const std::string base = ::testing::TempDir() + "interp_line_names";
    {
        line_bench<5, sample_set::case1, div3_mode::shift_add> bench("tb", random_intervals(2, 32, 1));
        vcd_file vcd(base);
        vcd.trace(bench);
        EXPECT_TRUE(tb::run_to_completion(bench, limit));
    }
    const auto declared = vcd_declared(base + ".vcd");
    const auto shown = gtkw_listed(source_path("traces/interp_line.gtkw"));
    EXPECT_GE(shown.size(), 20u);
    for (const auto& s : shown) EXPECT_EQ(declared.count(s), 1u) << s << " is in the view but not in the VCD";

    // What a user sees at first sight (vcd_names.h, view_problems): the view names its dump file,
    // opens with the marker inside the window and off every edge, and shows each bus as a number
    // in its format from src/floor/formats/interp_formats.h (counters and selects: integers).
    using interp::coef_fmt, interp::sample_fmt, interp::sum_fmt;
    view_formats f;
    for (int i = 1; i <= 4; ++i)
        f["tb.i" + std::to_string(i)] = f["tb.dut.coef.held_i" + std::to_string(i)] = sample_fmt;
    for (const char* s : {"a8_sum", "b_sum", "c3_sum"}) f[std::string("tb.dut.coef.") + s] = sum_fmt;
    for (const char* s : {"tb.dut.a", "tb.dut.b", "tb.dut.c", "tb.dut.d", "tb.i_px"}) f[s] = coef_fmt;
    for (const char* s : {"init_p", "init_d1", "init_d2", "init_d3", "p_value", "d1_value", "d2_value", "d3_value",
                          "p_sum", "d1_sum", "d2_sum"})
        f[std::string("tb.dut.fd.") + s] = interp::fd_fmt;
    f["tb.len"] = f["tb.dut.fd.pixel"] = qfmt{6, false, 0};
    f["tb.dut.fd.fd_sel"] = qfmt{2, false, 0};
    const auto problems = view_problems(source_path("traces/interp_line.gtkw"), base + ".vcd", "interp_line", f,
                                        {"tb.ready", "tb.valid", "tb.last", "tb.i_px"});
    EXPECT_TRUE(problems.empty()) << joined(problems);
}

// Low phase 1 ns shorter than the coefficient unit needs (6.3 ns; high 13.7 ns, period 20 ns):
// coef's chk_clock reports it, but in the joined unit nothing samples A..D at the rising edge; the
// path between the units still fits the period (9.6 < 20 ns), so the pixels stay exact. The
// alternating 1- and 4-pixel intervals put that path into every other clock.
TEST(InterpLineTiming, LowPhaseShortIsReportedButThePeriodStillHoldsThePath) {
    report_log::get().expect(msg::timing);
    interp_clock ck;
    ck.high = sc_time(13700, sc_core::SC_PS);
    ck.low = sc_time(6300, sc_core::SC_PS);
    line_bench<2, sample_set::case2, div3_mode::shift_add> bench("tb", alternating_intervals(20, 44), 0, nullptr, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.coef.chk_clock.low_violations(), 10u);
    EXPECT_EQ(bench.dut.fd.chk_clock.violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 10u) << "the first 10 violations are reported";
    EXPECT_EQ(bench.checker.samples().size(), 50u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
}

// A period shorter than the path between the units (high 3.3 ns, enough for fd; low 5.3 ns, 2 ns
// short for coef; 8.6 < 9.6 ns): reported, and the FD registers load unsettled set-up values.
TEST(InterpLineTiming, PeriodShorterThanThePathBetweenTheUnitsGivesWrongPixels) {
    report_log::get().expect(msg::timing);
    report_log::get().expect(msg::mismatch);
    report_log::get().expect(msg::setup);
    interp_clock ck;
    ck.high = sc_time(3300, sc_core::SC_PS);
    ck.low = sc_time(5300, sc_core::SC_PS);
    line_bench<2, sample_set::case2, div3_mode::shift_add> bench("tb", alternating_intervals(20, 45), 0, nullptr, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.coef.chk_clock.low_violations(), 0u);
    EXPECT_GT(report_log::get().count(msg::timing), 0u);
    EXPECT_GT(bench.checker.mismatches(), 0u);
    // Only the slow path fails: pixel 0 is D = I1 (0.2 + 0.3 ns to the register), pixels 1..3 of the
    // 4-pixel intervals carry D1..D3 from the set-up networks.
    for (const auto& px : bench.checker.samples())
        if (!px.matched) {
            EXPECT_GT(px.k, 0u) << "interval " << px.interval;
        }
}

// Both phases 1 ns longer than the units need (high 3.3 ns, low 8.3 ns: an 11.6 ns clock), with
// the alternating 1- and 4-pixel intervals: silent, bit-exact, one pixel per clock (100 pixels in
// 101 clocks).
TEST(InterpLineTiming, PhasesOneNanosecondLongerAreSilentAndBitExact) {
    interp_clock ck;
    ck.high = sc_time(3300, sc_core::SC_PS);
    ck.low = sc_time(8300, sc_core::SC_PS);
    line_bench<2, sample_set::case2, div3_mode::shift_add> bench("tb", alternating_intervals(40, 46), 0, nullptr, ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), 100u);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    EXPECT_EQ(bench.dut.phase_violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 0u);
    EXPECT_EQ(bench.checker.samples().back().valid - bench.stim.presented().front(), 101.0 * ck.period());
}

}  // namespace test_interp_line
