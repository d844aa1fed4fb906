// The interpolation paper's RTL (rtl/interp: the cubic coefficient unit in its four variants, the Fig. 4 Horner
// unit with its controller), Verilated with --sc, against our SystemC units and the golden model in
// one simulation: bit-exact at every result edge over 10^5 random intervals (random requests for
// the Horner unit) plus the corners and edge cases the interp suites use. Each TEST elaborates its
// own bench (one process per test through gtest_discover_tests).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "Vrtl_coef_c1ex.h"
#include "Vrtl_coef_c1sa.h"
#include "Vrtl_coef_c2ex.h"
#include "Vrtl_coef_c2sa.h"
#include "Vrtl_horner_unit.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/interp/interp_line.h"
#include "testbenches/rtl/rtl_interp_cosim.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_interp {

using namespace shading;
using namespace shading::tb;
using interp::div3_mode;
using interp::sample_set;

namespace {

constexpr std::size_t random_intervals = 100000;

// Corners first (all zero, all full scale, the sign patterns that maximise |A|, |B|, |C|, as
// InterpCoefUnits uses), then a 200-pixel raster line's intervals, then random sets over the
// whole sample bus.
item_source<coef_inputs> corners_line_and_random(std::size_t n_random, uint64_t seed) {
    const uint64_t hi = interp::sample_fmt.mask();
    std::vector<coef_inputs> fixed{{{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0}},
                                   {{hi, hi, hi, hi}, {hi, hi, hi, hi}, {hi, hi, hi}},
                                   {{hi, 0, hi, 0}, {hi, 0, hi, 0}, {hi, 0, hi}},
                                   {{0, hi, 0, hi}, {0, hi, 0, hi}, {0, hi, 0}},
                                   {{hi, 0, 0, hi}, {0, hi, hi, 0}, {hi, hi, 0}},
                                   {{0, hi, hi, 0}, {hi, 0, 0, hi}, {0, 0, hi}}};
    for (const auto& iv : make_line(200, 5).intervals) fixed.push_back({iv.c1, iv.c2, iv.q});
    auto random = random_coef_inputs(n_random, seed);
    const std::size_t n_fixed = fixed.size();
    return item_source<coef_inputs>(n_fixed + n_random, [fixed = std::move(fixed), random, n_fixed](std::size_t i) mutable {
        return i < n_fixed ? fixed[i] : random[i - n_fixed];
    });
}

template <typename Rtl, sample_set SET, div3_mode DIV>
void coef_bit_exact(uint64_t seed) {
    coef_cosim<Rtl, SET, DIV> bench("tb", corners_line_and_random(random_intervals, seed));
    EXPECT_TRUE(run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_SEC)));
    EXPECT_GE(bench.counts.checked, random_intervals);
    EXPECT_EQ(bench.counts.rtl_vs_golden, 0u);
    EXPECT_EQ(bench.counts.rtl_vs_ours, 0u);
    EXPECT_EQ(bench.counts.ours_vs_golden, 0u);
}

// Coefficients at the documented bounds (interp_formats.h: |A| <= 24 Imax, |B| <= 38 Imax,
// |C| <= 15 Imax, 0 <= D < 256) in every sign combination, and random ones inside them, each at
// every t = k/2^m of an interval, t = 0 and t = 1 included; both degrees.
std::vector<horner_request> horner_edges(unsigned m, bool deg2, unsigned seed) {
    constexpr int64_t one = 256 * 65536;
    const int64_t amax = 24 * one - 1, bmax = 38 * one - 1, cmax = 15 * one - 1, dmax = one - 1;
    std::vector<interp::cubic_coefs> ks;
    for (int sa : {-1, 1})
        for (int sb : {-1, 1})
            for (int sc : {-1, 1}) ks.push_back({sa * amax, sb * bmax, sc * cmax, sa > 0 ? dmax : 0});
    ks.push_back({0, 0, 0, 0});
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int64_t> ua(-amax, amax), ub(-bmax, bmax), uc(-cmax, cmax), ud(0, dmax);
    for (int i = 0; i < 8; ++i) ks.push_back({ua(rng), ub(rng), uc(rng), ud(rng)});
    std::vector<horner_request> r;
    for (const auto& k : ks)
        for (unsigned j = 0; j <= (1u << m); ++j) r.push_back({k, uint64_t{j} << (8 - m), deg2});
    return r;
}

template <typename Bench>
void expect_horner_clean(const Bench& b, std::size_t results) {
    EXPECT_EQ(b.counts.checked, results);
    EXPECT_EQ(b.counts.rtl_vs_golden, 0u);
    EXPECT_EQ(b.counts.rtl_vs_ours, 0u);
    EXPECT_EQ(b.bench.checker.checked(), results);
    EXPECT_EQ(b.bench.checker.mismatches(), 0u) << "our unit against the golden micro-steps";
}

}  // namespace

TEST(RtlCoefUnit, Case1ShiftAddBitExact) { coef_bit_exact<Vrtl_coef_c1sa, sample_set::case1, div3_mode::shift_add>(101); }
TEST(RtlCoefUnit, Case1ExactBitExact) { coef_bit_exact<Vrtl_coef_c1ex, sample_set::case1, div3_mode::exact>(102); }
TEST(RtlCoefUnit, Case2ShiftAddBitExact) { coef_bit_exact<Vrtl_coef_c2sa, sample_set::case2, div3_mode::shift_add>(103); }
TEST(RtlCoefUnit, Case2ExactBitExact) { coef_bit_exact<Vrtl_coef_c2ex, sample_set::case2, div3_mode::exact>(104); }

// The comparison can fail: one corrupted golden value is one reported mismatch.
TEST(RtlCoefUnit, ComparisonCatchesAWrongGolden) {
    report_log::get().expect(msg::mismatch);
    coef_cosim<Vrtl_coef_c1sa, sample_set::case1, div3_mode::shift_add> bench("tb", random_coef_inputs(50, 7));
    bench.counts.inject = 17;
    EXPECT_TRUE(run_to_completion(bench, sc_core::sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(bench.counts.checked, 50u);
    EXPECT_EQ(bench.counts.rtl_vs_golden, 1u);
    EXPECT_EQ(bench.counts.ours_vs_golden, 1u);
    EXPECT_EQ(bench.counts.rtl_vs_ours, 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 1u);
}

// 10^5 random requests back to back (random samples through a random unit's coefficients, random
// degree and t in [0, 1]): 5 to 6 * 10^5 clocks, every edge compared.
TEST(RtlHorner, RandomRequestsBitExactEveryEdge) {
    horner_cosim<Vrtl_horner_unit> b("tb", random_horner_requests(random_intervals, 201));
    EXPECT_TRUE(run_to_completion(b, sc_core::sc_time(1, sc_core::SC_SEC)));
    expect_horner_clean(b, random_intervals);
    EXPECT_GT(b.edges, 4 * random_intervals);
}

TEST(RtlHorner, BoundsEveryTBothDegreesBitExact) {
    auto reqs = horner_edges(5, false, 202);
    const auto quad = horner_edges(6, true, 203);
    reqs.insert(reqs.end(), quad.begin(), quad.end());
    const std::size_t n = reqs.size();
    horner_cosim<Vrtl_horner_unit> b("tb", reqs);
    EXPECT_TRUE(run_to_completion(b, sc_core::sc_time(10, sc_core::SC_MS)));
    expect_horner_clean(b, n);
}

// Idle gaps between requests (RG holds I(t) while idle, compared at every idle edge too), mixed
// degrees, and t above 1 (reported by our controller, evaluated as given by both).
TEST(RtlHorner, GapsMixedDegreesAndTAboveOneBitExact) {
    report_log::get().expect(msg::input);
    auto reqs = horner_edges(3, false, 204);
    for (std::size_t i = 0; i < reqs.size(); i += 2) reqs[i].deg2 = true;
    for (std::size_t i = 0; i < reqs.size(); i += 7) reqs[i].t = interp::t_one + 1 + i % 200;
    const std::size_t n = reqs.size();
    horner_cosim<Vrtl_horner_unit> b("tb", reqs, 3);
    EXPECT_TRUE(run_to_completion(b, sc_core::sc_time(10, sc_core::SC_MS)));
    expect_horner_clean(b, n);
    EXPECT_GT(report_log::get().count(msg::input), 0u);
}

TEST(RtlHorner, ComparisonCatchesAWrongGolden) {
    report_log::get().expect(msg::mismatch);
    horner_cosim<Vrtl_horner_unit> b("tb", random_horner_requests(40, 9));
    b.counts.inject = 23;
    EXPECT_TRUE(run_to_completion(b, sc_core::sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(b.counts.checked, 40u);
    EXPECT_EQ(b.counts.rtl_vs_golden, 1u);
    EXPECT_EQ(b.counts.rtl_vs_ours, 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 1u);
}

}  // namespace test_rtl_interp
