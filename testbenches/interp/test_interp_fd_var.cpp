// The forward-difference evaluator with a per-interval length (fd_eval_var) against the golden model
// interp::golden_fd(coefs, m, len) and the Horner unit's golden model, one pixel per clock, and its
// clock-phase requirements against hand sums. Each TEST elaborates its own bench.
#include <gtest/gtest.h>

#include <random>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/common/vcd_names.h"
#include "core/trace.h"
#include "testbenches/interp/interp_fd_var_bench.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_fd_var {

using namespace shading;
using namespace shading::tb;
using sc_core::sc_time;
using sc_core::SC_PS;

namespace {
const sc_time limit(10, sc_core::SC_MS);

// Random coefficients over the units' whole range (as test_interp_fd.cpp) and, unless `len` is
// given, a random length 1..2^m.
std::vector<fd_var_interval> random_intervals(std::size_t n, unsigned m, unsigned seed, unsigned len = 0) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int64_t> ua(-24 * 256 * 65536 + 1, 24 * 256 * 65536 - 1),
        ub(-38 * 256 * 65536 + 1, 38 * 256 * 65536 - 1), uc(-15 * 256 * 65536 + 1, 15 * 256 * 65536 - 1),
        ud(0, 256 * 65536 - 1);
    std::uniform_int_distribution<unsigned> ulen(1, 1u << m);
    std::vector<fd_var_interval> v;
    for (std::size_t i = 0; i < n; ++i) {
        const interp::cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
        v.push_back({k, m, len ? len : ulen(rng)});
    }
    return v;
}

std::size_t pixels_in(const std::vector<fd_var_interval>& ivs) {
    std::size_t n = 0;
    for (const auto& iv : ivs) n += iv.len;
    return n;
}

template <unsigned MMIN, unsigned MMAX>
void expect_exact_and_close_to_horner(fd_var_bench<MMIN, MMAX>& bench, std::size_t pixels) {
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.samples().size(), pixels);
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    // 0 <= FD - Horner <= 2 LSB of Q16.16 (FD exact then floored; Horner three floors below).
    EXPECT_GE(bench.checker.min_vs_horner(), 0);
    EXPECT_LE(bench.checker.max_vs_horner(), 2);
}
}  // namespace

// Every m of the units' range through one evaluator built for all of them (fd_eval_var<2, 6>):
// random coefficients, random lengths 1..2^m and full intervals, bit-exact against golden_fd(k, m,
// len), within the bound of Horner, one pixel per clock, and the default clock meets the phases.
class InterpFdVarLength : public ::testing::TestWithParam<unsigned> {};

TEST_P(InterpFdVarLength, BitExactAgainstGoldenFdForThisM) {
    const unsigned m = GetParam();
    auto ivs = random_intervals(60, m, 40 + m);
    const auto full = random_intervals(10, m, 50 + m, 1u << m);
    ivs.insert(ivs.end(), full.begin(), full.end());
    fd_var_bench<interp::m_min, interp::m_max> bench("tb", ivs);
    expect_exact_and_close_to_horner(bench, pixels_in(ivs));
    EXPECT_EQ(bench.checker.pixels_of().size(), ivs.size());
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u) << "the default 20 ns clock meets both phases";
}

INSTANTIATE_TEST_SUITE_P(EveryM, InterpFdVarLength, ::testing::Range(interp::m_min, interp::m_max + 1),
                         [](const ::testing::TestParamInfo<unsigned>& i) { return "M" + std::to_string(i.param); });

// The pipeline's unit (fd_eval_var<2, 5>): intervals of different m back to back, short (2 .. 2^m
// pixels) and full, with an exact pixel (m = 0, len 1, A = B = C = 0) among them: pixel k of every
// interval on the output (k + 1) clocks after its acceptance, and no clock without a pixel from the
// first acceptance to the last pixel but one: after the exact pixel's acceptance the source holds
// A..D a clock (to the falling edge where they load), so the next interval is taken a clock after
// the exact pixel is out (a handshake property of len 1, not of the length change).
TEST(InterpFdVar, BackToBackIntervalsOfDifferentLengthsWithoutABubble) {
    std::vector<fd_var_interval> ivs;
    const unsigned ms[] = {2, 5, 3, 4, 5, 2, 4, 3, 2, 5};
    unsigned seed = 60;
    for (unsigned m : ms) {
        for (const auto& iv : random_intervals(1, m, seed++, 1u << m)) ivs.push_back(iv);
        for (auto iv : random_intervals(1, m, seed++)) {
            iv.len = std::max(iv.len, 2u);
            ivs.push_back(iv);
        }
    }
    const interp::cubic_coefs exact{0, 0, 0, 0x00ABCDEF};  // an exact pixel: I1 = 171.8044 in Q16.16
    ivs.insert(ivs.begin() + 5, fd_var_interval{exact, 0, 1});
    fd_var_bench<2, 5> bench("tb", ivs);
    expect_exact_and_close_to_horner(bench, pixels_in(ivs));
    for (const auto& [k, lat] : bench.checker.latencies()) {
        ASSERT_EQ(lat.size(), 1u) << "pixel " << k;
        EXPECT_EQ(*lat.begin(), (k + 1) * interp_period()) << "pixel " << k;
    }
    const double pixels = static_cast<double>(pixels_in(ivs));
    EXPECT_DOUBLE_EQ(bench.checker.cycles_per_pixel(), (pixels + 1.0) / pixels);
    for (std::size_t i = 0; i < ivs.size(); ++i) EXPECT_EQ(bench.checker.pixels_of().at(i), ivs[i].len) << i;
    // The exact pixel is D itself (hand value, not the golden model).
    const auto& s = bench.checker.samples();
    const auto at = std::find_if(s.begin(), s.end(), [](const fd_var_sample& x) { return x.interval == 5; });
    ASSERT_NE(at, s.end());
    EXPECT_EQ(at->out, 0x00ABCDEFu);
    EXPECT_EQ(bench.dut.chk_clock.violations(), 0u);
}

// Bad input, each reported once (shading/input) with a defined result: m neither 0 nor 2..5 is
// evaluated as m = 5, then len outside 1..2^m as a full interval of 2^m. Pixel counts by hand.
TEST(InterpFdVar, BadMOrLenIsReportedAndADefinedIntervalEvaluated) {
    report_log::get().expect(msg::input);
    auto ivs = random_intervals(7, 4, 70);
    const unsigned m[] = {1, 7, 0, 3, 2, 4, 6}, len[] = {7, 40, 2, 9, 0, 16, 33};
    for (std::size_t i = 0; i < ivs.size(); ++i) {
        ivs[i].m = m[i];
        ivs[i].len = len[i];
    }
    ivs[2].k = {0, 0, 0, ivs[2].k.d};  // the exact pixel's polynomial is the constant D
    fd_var_bench<2, 5> bench("tb", ivs);
    const unsigned pixels[] = {7, 32, 1, 8, 4, 16, 32};
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_EQ(bench.checker.mismatches(), 0u);
    for (std::size_t i = 0; i < ivs.size(); ++i) EXPECT_EQ(bench.checker.pixels_of().at(i), pixels[i]) << i;
    // m = 1, m = 7 and len 40, len 2 at m = 0, len 9 at m = 3, len 0, m = 6 and len 33.
    EXPECT_EQ(report_log::get().count(msg::input), 8u);
}

// Clock phases from the elaborated blocks. High: at the accepting rising edge A..D may just have
// settled, so the deepest set-up network (D1, D2: three terms, two adder levels, 2 ns), the set-up
// multiplexer (0.3 ns) and MX (0.3 ns) must settle before the falling edge: 2.6 ns, fd_eval's 2.3 plus
// one multiplexer. Low: RG_P's clock-to-output 0.2 ns onto i_px; the recurrence RG -> ADD -> MX ->
// RG (0.2 + 1 + 0.3 = 1.5 ns) spans both phases and fits in 2.6 + 0.2.
TEST(InterpFdVarTiming, PhasesAreTheHandSums) {
    struct pins : sc_core::sc_module {
        using unit = fd_eval_var<2, 5>;
        sc_core::sc_signal<bool> clk{"clk"}, start{"start"}, valid{"valid"}, last{"last"};
        sc_core::sc_signal<unit::len_t> len{"len"};
        sc_core::sc_signal<unit::m_t> m{"m"};
        sc_core::sc_vector<sc_core::sc_signal<coef_t>> k{"k", 4};
        sc_core::sc_signal<coef_t> i_px{"i_px"};
        unit dut{"dut"};
        explicit pins(const sc_core::sc_module_name& n) : sc_module(n) {
            dut.clk(clk); dut.start(start); dut.len(len); dut.m(m);
            dut.a(k[0]); dut.b(k[1]); dut.c(k[2]); dut.d(k[3]);
            dut.i_px(i_px); dut.valid(valid); dut.last(last);
        }
    } p("p");
    sc_core::sc_start(sc_core::SC_ZERO_TIME);
    const auto& chk = p.dut.chk_clock;
    EXPECT_EQ(chk.min_high(), sc_time(2600, SC_PS)) << chk.high_path().to_string();
    EXPECT_NE(chk.high_path().to_string().find("mx_setup_d"), std::string::npos) << chk.high_path().to_string();
    EXPECT_EQ(chk.min_low(), sc_time(200, SC_PS));
    EXPECT_EQ(chk.loop_path().delay, sc_time(1500, SC_PS));
}

// A high phase of 2.5 ns (enough for fd_eval's 2.3 ns, not for the set-up multiplexer's extra
// 0.3 ns): reported at falling edges (the first 10); the low phase is long enough.
TEST(InterpFdVarTiming, HighPhaseShorterThanTheSetupMuxPathIsReported) {
    report_log::get().expect(msg::timing);
    interp_clock ck;
    ck.high = sc_time(2500, SC_PS);
    ck.low = sc_time(17500, SC_PS);
    fd_var_bench<2, 5> bench("tb", random_intervals(4, 3, 80, 8), ck);
    EXPECT_TRUE(tb::run_to_completion(bench, limit));
    EXPECT_GT(bench.dut.chk_clock.high_violations(), 10u);
    EXPECT_EQ(bench.dut.chk_clock.low_violations(), 0u);
    EXPECT_EQ(report_log::get().count(msg::timing), 10u) << "the first 10 violations are reported";
}

// The VCD names the per-length set-up by its m (init_d1_m2 .. init_d3_m5, setup_sel) beside fd_eval's
// nets; the file is this test's own (ctest runs tests in parallel).
TEST(InterpFdVar, VcdNamesTheSetupOfEveryLength) {
    const std::string base = ::testing::TempDir() + "interp_fd_var_names";
    {
        fd_var_bench<2, 5> bench("tb", random_intervals(2, 5, 90));
        vcd_file vcd(base);
        vcd.trace(bench);
        EXPECT_TRUE(tb::run_to_completion(bench, limit));
    }
    const auto declared = vcd_declared(base + ".vcd");
    auto has = [&](const std::string& net) {
        for (const auto& d : declared)
            if (d.rfind("SystemC.tb.dut." + net + "[", 0) == 0) return true;
        return false;
    };
    for (unsigned m = 2; m <= 5; ++m)
        for (const char* dk : {"init_d1_m", "init_d2_m", "init_d3_m"})
            EXPECT_TRUE(has(dk + std::to_string(m))) << dk << m;
    for (const char* net : {"init_p", "init_d1", "init_d2", "init_d3", "setup_sel", "fd_sel", "p_value", "pixel"})
        EXPECT_TRUE(has(net)) << net;
    EXPECT_FALSE(has("init_d1_m6")) << "no set-up for a length the unit is not built for";
}

}  // namespace test_interp_fd_var
