// The designs the squared-quadratic device is compared with, verilated and checked bit-exact
// against their golden models on the device pins: the series variant
// (rtl/squared/squared_series_device.v: 9 squarers with bypass multiplexers, combinational, Fig. 3
// timing with no clock, no SystemC model; golden_squared), the square-and-multiply baseline
// (rtl/sqmul/sqmul_device.v: one multiplier over the bits of n, left to right; golden_sqmul;
// co-simulated with its SystemC model in test_rtl_sqmul.cpp) and its right-to-left twin
// (rtl/sqmul/sqmul_r2l_device.v: a squarer and a multiplier in one clock per bit; golden_sqmul_r2l;
// no SystemC model), all saturating (the synthesis table's variants; no range checker: n = 0,
// n > 1000 and cos > 1.0 are simply compared). Random pixels, every n 0..1023, every cos code at
// n = 1000, the clocked designs' clocks per sample for every n, strobe 17 at every phase of their
// clock, and negative tests; both square-and-multiply designs also at the word-length study's Q1.16
// P word (the same RTL read with the formats of sqmul_word/p16/).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "core/report_ids.h"
#include "formats/sqmul_formats.h"
#include "formats/squared_formats.h"
#include "arith/sqmul_arith.h"
#include "arith/squared_arith.h"
#include "rtl_squared_tb.h"
#include "testbenches/specular/specular_tb.h"
#include "verilated.h"

#include "Vrtl_sqmul_p16.h"
#include "Vrtl_sqmul_r2l_p16.h"
#include "Vrtl_sqmul_r2l_saturate.h"
#include "Vrtl_sqmul_saturate.h"
#include "Vrtl_squared_series_saturate.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_squared_variants {

using namespace shading;
using namespace shading::tb;
using sc_core::SC_MS;
using sc_core::sc_time;

constexpr auto sat = overflow_mode::saturate;

specular_checker::golden_fn series_golden() {
    return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_squared(n, c, k, sat).out;
        return r;
    };
}

specular_checker::golden_fn sqmul_golden() {
    return [](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul(n, c, k, sat).out;
        return r;
    };
}

// The RTL alone on the specular bench (stimulus, monitor, checker against `golden`); a latency
// probe on its strobe 17 and output 29. Returns the number of mismatches against golden.
template <typename Rtl>
std::size_t run_rtl(item_source<surface> surfaces, std::size_t expected_pixels, const strobe_timing& t,
                    specular_checker::golden_fn golden, latency_probe* probe = nullptr) {
    specular_bench<Rtl> bench("tb", std::move(surfaces), t, std::move(golden));
    if (probe != nullptr) {
        probe->ctl17(bench.ctl17);
        probe->out29_valid(bench.out29_valid);
    }
    EXPECT_TRUE(run_to_completion(bench, sc_time(10000, SC_MS)));
    EXPECT_EQ(bench.checker.samples(), expected_pixels);
    return bench.checker.mismatches();
}

std::vector<surface> every_n(std::vector<uint32_t> codes) {
    std::vector<surface> s;
    for (unsigned n = 0; n < (1u << squared::n_fmt.width); ++n) s.push_back({n, {255, 17, 96}, codes});
    return s;
}

std::vector<surface> every_cos_code(unsigned n) {
    std::vector<uint32_t> codes;
    for (uint64_t c = 0; c <= spec::cos_fmt.mask(); ++c) codes.push_back(static_cast<uint32_t>(c));
    return {{n, {255, 170, 3}, codes}};
}

// golden_sqmul_r2l, for n + `n_offset` (a negative test's wrong exponent).
specular_checker::golden_fn sqmul_r2l_golden(uint64_t n_offset = 0, unsigned p_frac = sqmul::p_frac) {
    return [n_offset, p_frac](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul_r2l(n + n_offset, c, k, sat, p_frac).out;
        return r;
    };
}

// golden_sqmul at another P word.
specular_checker::golden_fn sqmul_word_golden(unsigned p_frac) {
    return [p_frac](uint64_t n, uint64_t c, const std::array<uint64_t, 3>& k) {
        datapath_nets r{};
        r.out = golden_sqmul(n, c, k, sat, p_frac).out;
        return r;
    };
}

// Every n 0..1023 (three codes) with strobe 17 low for 5 ns: output 29 must rise with done, at the
// edges(n)-th rising edge after the strobe fell; the words checked against `golden` too.
template <typename Rtl>
void expect_every_n_and_clocks(specular_checker::golden_fn golden, unsigned (*edges)(unsigned), unsigned period) {
    const auto s = every_n({0x4000, 0x7800, spec::cos_one});
    const strobe_timing t = done_timing(period);
    latency_probe probe("probe");
    EXPECT_EQ(run_rtl<Rtl>(s, s.size() * 3, t, std::move(golden), &probe), 0u);
    const auto ns = pixel_ns(s);
    ASSERT_EQ(probe.falls.size(), ns.size());
    ASSERT_EQ(probe.rises.size(), ns.size());
    unsigned wrong = 0;
    for (std::size_t i = 0; i < ns.size(); ++i) {
        const sc_time want = rising_edge_after(probe.falls[i], t.clk_period, edges(ns[i]));
        if (probe.rises[i] != want && ++wrong <= 10)
            ADD_FAILURE() << "n = " << ns[i] << ": strobe fell at " << probe.falls[i] << ", output 29 rose at "
                          << probe.rises[i] << ", want " << want << " (" << edges(ns[i]) << " rising edges)";
    }
    EXPECT_EQ(wrong, 0u);
}

class RtlSquaredVariants : public ::testing::Test {
protected:
    void SetUp() override { Verilated::traceEverOn(true); }
};

// The series variant: Fig. 3's strobe timing (20 ns per pixel), no clock.
TEST_F(RtlSquaredVariants, SeriesRandom) {
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(random_surfaces(250000, 11), 250000, strobe_timing{},
                                                   series_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SeriesEveryN) {
    const auto s = every_n({0x4000, 0x6000, 0x7800, 0x7FF0, spec::cos_one});
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(s, s.size() * 5, strobe_timing{}, series_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SeriesEveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_squared_series_saturate>(every_cos_code(1000), 65536, strobe_timing{}, series_golden()), 0u);
}

// The square-and-multiply baseline: 24 clocks per pixel (its longest result takes 22).
TEST_F(RtlSquaredVariants, SqmulRandom) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(random_surfaces(250000, 12), 250000, sqmul_timing(), sqmul_golden()), 0u);
}
TEST_F(RtlSquaredVariants, SqmulEveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(every_cos_code(1000), 65536, sqmul_timing(), sqmul_golden()), 0u);
}

TEST_F(RtlSquaredVariants, SqmulEveryNAndItsClocksPerSample) {
    // Every n 0..1023, bit-exact, with strobe 17 low for 5 ns: output 29 rises with done, at the
    // (squares + multiplies + 4)-th rising edge after the strobe fell (counts from golden_sqmul:
    // the synchroniser's two edges, the taking edge, one per square and per multiplication, the
    // done edge).
    expect_every_n_and_clocks<Vrtl_sqmul_saturate>(sqmul_golden(), sqmul_edges, 44);  // n = 1023: 22 edges
    // Hand-worked: n = 1000 = 0b1111101000: 9 squares and 5 multiplications, 2 + 1 + 14 + 1 = 18
    // edges; n = 20 = 0b10100: 4 squares and 1 multiplication, 2 + 1 + 5 + 1 = 9.
    EXPECT_EQ(sqmul_edges(1000), 18u);
    EXPECT_EQ(sqmul_edges(20), 9u);
}

TEST_F(RtlSquaredVariants, SqmulStrobeSeventeenAtEveryPhaseOfTheClock) {
    // Strobe 17 at every phase of a 20 ns clock in 0.5 ns steps (phase_sweep_timing: 41 pixels per
    // n, a pixel period of 46 clocks + 0.5 ns, the longest result 22 edges), n = 1, 20, 1000, 1023:
    // every pixel bit-exact against golden_sqmul, validated once, at the (squares + multiplies +
    // 4)-th rising edge after its strobe, never twice.
    const std::vector<unsigned> n{1, 20, 1000, 1023};
    const auto s = phase_sweep_surfaces(n, 41);
    const auto ns = pixel_ns(s);
    const strobe_timing t = phase_sweep_timing(46, sc_time(500, sc_core::SC_PS), sc_time(20, sc_core::SC_NS));
    latency_probe probe("probe");
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(s, ns.size(), t, sqmul_golden(), &probe), 0u);
    EXPECT_EQ(phases_missed(probe.falls, t.clk_period, sc_time(500, sc_core::SC_PS)), 0u);
    EXPECT_EQ(phase_sweep_wrong(probe, ns, t.clk_period, sc_core::SC_ZERO_TIME, sqmul_edges), 0u);
}

TEST_F(RtlSquaredVariants, AnRtlThatDiffersFromItsGoldenIsCaught) {
    // Negative test: the baseline checked against the squared-quadratic law's golden model (another
    // approximation of cos^n) fails on every pixel.
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000, 0x7800, 0x7C00}}};
    EXPECT_EQ(run_rtl<Vrtl_sqmul_saturate>(s, 3, sqmul_timing(), series_golden()), 3u);
}

// The right-to-left design: the baseline's pixel period (its longest result takes 14 clocks).
TEST_F(RtlSquaredVariants, SqmulR2lRandom) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_saturate>(random_surfaces(250000, 13), 250000, sqmul_timing(), sqmul_r2l_golden()),
              0u);
}
TEST_F(RtlSquaredVariants, SqmulR2lEveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_saturate>(every_cos_code(1000), 65536, sqmul_timing(), sqmul_r2l_golden()), 0u);
}

TEST_F(RtlSquaredVariants, SqmulR2lEveryNAndItsClocksPerSample) {
    // Output 29 at the (steps + 4)-th rising edge: the synchroniser's two edges, the taking edge,
    // one per bit of n up to its leading one, the done edge (steps from golden_sqmul_r2l).
    expect_every_n_and_clocks<Vrtl_sqmul_r2l_saturate>(sqmul_r2l_golden(), sqmul_r2l_edges, 30);  // n = 1023: 14
    // Hand-worked: n = 1000 = 0b1111101000 has 10 bits: 2 + 1 + 10 + 1 = 14 edges; n = 20 =
    // 0b10100, 5 bits: 9; n = 5 = 0b101, 3 bits: 7; n = 0: no bit, 2 + 1 + 0 + 1 = 4 (P = 1.0).
    EXPECT_EQ(sqmul_r2l_edges(1000), 14u);
    EXPECT_EQ(sqmul_r2l_edges(20), 9u);
    EXPECT_EQ(sqmul_r2l_edges(5), 7u);
    EXPECT_EQ(sqmul_r2l_edges(0), 4u);
}

TEST_F(RtlSquaredVariants, SqmulR2lStrobeSeventeenAtEveryPhaseOfTheClock) {
    // As the baseline's: strobe 17 at every phase of a 20 ns clock in 0.5 ns steps (41 pixels per
    // n, a pixel period of 30 clocks + 0.5 ns, the longest result 14 edges), n = 1, 20, 1000, 1023:
    // every pixel bit-exact against golden_sqmul_r2l, validated once, at the (steps + 4)-th rising
    // edge after its strobe, never twice.
    const std::vector<unsigned> n{1, 20, 1000, 1023};
    const auto s = phase_sweep_surfaces(n, 41);
    const auto ns = pixel_ns(s);
    const strobe_timing t = phase_sweep_timing(30, sc_time(500, sc_core::SC_PS), sc_time(20, sc_core::SC_NS));
    latency_probe probe("probe");
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_saturate>(s, ns.size(), t, sqmul_r2l_golden(), &probe), 0u);
    EXPECT_EQ(phases_missed(probe.falls, t.clk_period, sc_time(500, sc_core::SC_PS)), 0u);
    EXPECT_EQ(phase_sweep_wrong(probe, ns, t.clk_period, sc_core::SC_ZERO_TIME, sqmul_r2l_edges), 0u);
}

TEST_F(RtlSquaredVariants, AnR2lRtlThatDiffersFromItsGoldenIsCaught) {
    // Negative test: the right-to-left RTL checked against its golden model of n + 1 (cos^21 for
    // cos^20, at cos < 1) fails on every pixel.
    report_log::get().expect(msg::mismatch);
    std::vector<surface> s{{20, {255, 255, 255}, {0x7000, 0x7800, 0x7C00}}};
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_saturate>(s, 3, sqmul_timing(), sqmul_r2l_golden(1)), 3u);
}

// Both designs at Q1.16: every n (three codes) and every cos code at n = 1000, against their
// golden models at 16 fraction bits; against the Q1.18 golden models the same RTL mismatches (the
// negative tests), so these do read the other word.
TEST_F(RtlSquaredVariants, SqmulAtQ116EveryN) {
    const auto s = every_n({0x4000, 0x7800, spec::cos_one});
    EXPECT_EQ(run_rtl<Vrtl_sqmul_p16>(s, s.size() * 3, sqmul_timing(), sqmul_word_golden(16)), 0u);
}
TEST_F(RtlSquaredVariants, SqmulAtQ116EveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_p16>(every_cos_code(1000), 65536, sqmul_timing(), sqmul_word_golden(16)), 0u);
}
TEST_F(RtlSquaredVariants, SqmulR2lAtQ116EveryN) {
    const auto s = every_n({0x4000, 0x7800, spec::cos_one});
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_p16>(s, s.size() * 3, sqmul_timing(), sqmul_r2l_golden(0, 16)), 0u);
}
TEST_F(RtlSquaredVariants, SqmulR2lAtQ116EveryCosCodeAtN1000) {
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_p16>(every_cos_code(1000), 65536, sqmul_timing(), sqmul_r2l_golden(0, 16)), 0u);
}

// n = 1000 and the 64 codes below 1.0 (cos^1000 from 0.14 up), where the Q1.16 and Q1.18 floors
// reach the outputs: every one of the 64 pixels differs (worked out outside the model in exact
// integer arithmetic, for both walks).
std::vector<surface> near_one_at_n1000() {
    std::vector<uint32_t> codes;
    for (uint32_t c = spec::cos_one - 64; c < spec::cos_one; ++c) codes.push_back(c);
    return {{1000, {255, 255, 255}, codes}};
}
TEST_F(RtlSquaredVariants, TheQ116RtlIsNotTheQ118One) {
    report_log::get().expect(msg::mismatch);
    EXPECT_EQ(run_rtl<Vrtl_sqmul_p16>(near_one_at_n1000(), 64, sqmul_timing(), sqmul_golden()), 64u);
}
TEST_F(RtlSquaredVariants, TheR2lQ116RtlIsNotTheQ118One) {
    report_log::get().expect(msg::mismatch);
    EXPECT_EQ(run_rtl<Vrtl_sqmul_r2l_p16>(near_one_at_n1000(), 64, sqmul_timing(), sqmul_r2l_golden()), 64u);
}

}  // namespace test_rtl_squared_variants
