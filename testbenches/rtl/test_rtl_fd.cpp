// Our forward-difference evaluators' RTL (rtl/interp/fd_eval.v at every M, fd_eval_var.v for m in
// 2..6), Verilated with --sc, beside the SystemC units (fd_eval<M>, fd_eval_var<2, 6>) on the pins of
// their benches: at every rising edge i_px, valid and last equal ours, and every RTL pixel equals
// interp::golden_fd of its interval as the unit documents taking it (bad m or len included). Each
// TEST elaborates its own bench (one process per test through gtest_discover_tests).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "Vrtl_fd_eval_m2.h"
#include "Vrtl_fd_eval_m3.h"
#include "Vrtl_fd_eval_m4.h"
#include "Vrtl_fd_eval_m5.h"
#include "Vrtl_fd_eval_m6.h"
#include "Vrtl_fd_eval_var.h"
#include "testbenches/common/report_log.h"
#include "testbenches/common/sim_guard.h"
#include "testbenches/rtl/rtl_fd_cosim.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_rtl_fd {

using namespace shading;
using namespace shading::tb;

namespace {

constexpr std::size_t random_pixels = 20000;
const sc_core::sc_time limit(1, sc_core::SC_SEC);

// fd_eval<M>: every length of bad input first (len 0 and 2^M + 1 .. 2^(M+1) - 1, each a full
// interval, reported), then random intervals of random units' coefficients, lengths 1..2^M.
template <unsigned M>
std::vector<fd_interval> intervals_with_bad_lengths(uint64_t seed, std::size_t& bad, std::size_t& pixels) {
    auto source = random_fd_intervals<M>(random_pixels, seed);
    std::vector<fd_interval> random;
    for (std::size_t i = 0; i < source.size(); ++i) random.push_back(source[i]);  // a generator never goes back
    std::vector<fd_interval> v;
    for (unsigned len = 0; len < (2u << M); len = len == 0 ? (1u << M) + 1 : len + 1)
        v.push_back({random[len % random.size()].k, len});
    bad = v.size();
    pixels = bad << M;
    for (const auto& iv : random) {
        v.push_back(iv);
        pixels += iv.len;
    }
    return v;
}

template <unsigned M, class Rtl>
void fd_bit_exact(uint64_t seed) {
    report_log::get().expect(msg::input);
    std::size_t bad = 0, pixels = 0;
    fd_cosim<fd_bench<M>, Rtl> b("tb", intervals_with_bad_lengths<M>(seed, bad, pixels));
    b.bench.checker.keep_samples(false);
    b.rtl_checker.keep_samples(false);
    EXPECT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(b.rtl_checker.checked(), pixels);
    EXPECT_EQ(b.rtl_checker.mismatches(), 0u) << "RTL against golden_fd";
    EXPECT_EQ(b.bench.checker.checked(), pixels);
    EXPECT_EQ(b.bench.checker.mismatches(), 0u) << "ours against golden_fd";
    EXPECT_EQ(b.edge_mismatches, 0u) << "RTL against ours, every rising edge";
    EXPECT_GT(b.edges, pixels);
    EXPECT_EQ(report_log::get().count(msg::input), bad) << "our unit reports each bad length once";
}

// Random coefficients over the units' whole range (as test_interp_fd_var.cpp), m and length given.
fd_var_interval random_var_interval(std::mt19937& rng, unsigned m, unsigned len) {
    constexpr int64_t one = 256 * 65536;
    std::uniform_int_distribution<int64_t> ua(-24 * one + 1, 24 * one - 1), ub(-38 * one + 1, 38 * one - 1),
        uc(-15 * one + 1, 15 * one - 1), ud(0, one - 1);
    interp::cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
    if (m == 0) k = {0, 0, 0, k.d};  // an exact pixel: P = D
    return {k, m, len};
}

}  // namespace

TEST(RtlFdEval, M2BitExactEveryEdge) { fd_bit_exact<2, Vrtl_fd_eval_m2>(301); }
TEST(RtlFdEval, M3BitExactEveryEdge) { fd_bit_exact<3, Vrtl_fd_eval_m3>(302); }
TEST(RtlFdEval, M4BitExactEveryEdge) { fd_bit_exact<4, Vrtl_fd_eval_m4>(303); }
TEST(RtlFdEval, M5BitExactEveryEdge) { fd_bit_exact<5, Vrtl_fd_eval_m5>(304); }
TEST(RtlFdEval, M6BitExactEveryEdge) { fd_bit_exact<6, Vrtl_fd_eval_m6>(305); }

// fd_eval_var<2, 6>: intervals of random m (exact pixels m = 0 among them) and random length back
// to back, full ones, and every bad m (1, 7) and bad length (0, above 2^m) of test_interp_fd_var's
// rule: m neither 0 nor 2..6 as m = 6, then len outside 1..2^m as 2^m. Pixel counts by that rule.
TEST(RtlFdEvalVar, RandomLengthsAndBadInputBitExactEveryEdge) {
    report_log::get().expect(msg::input);
    std::mt19937 rng(306);
    const unsigned ms[] = {0, 2, 3, 4, 5, 6};
    std::uniform_int_distribution<std::size_t> pick(0, 5);
    std::vector<fd_var_interval> ivs;
    const unsigned bad_m[] = {1, 7, 0, 3, 2, 6, 1}, bad_len[] = {7, 40, 2, 9, 0, 65, 0};
    const unsigned bad_pixels[] = {7, 40, 1, 8, 4, 64, 64};
    std::size_t pixels = 0;
    for (std::size_t i = 0; i < 7; ++i) {
        ivs.push_back(random_var_interval(rng, bad_m[i], bad_len[i]));
        pixels += bad_pixels[i];
    }
    for (std::size_t i = 0; i < 3000; ++i) {
        const unsigned m = ms[pick(rng)];
        const unsigned len = i % 4 == 0 ? 1u << m : std::uniform_int_distribution<unsigned>(1, 1u << m)(rng);
        ivs.push_back(random_var_interval(rng, m, len));
        pixels += len;
    }
    fd_cosim<fd_var_bench<interp::m_min, interp::m_max>, Vrtl_fd_eval_var> b("tb", ivs);
    b.bench.checker.keep_samples(false);
    b.rtl_checker.keep_samples(false);
    EXPECT_TRUE(run_to_completion(b, limit));
    EXPECT_EQ(b.rtl_checker.checked(), pixels);
    EXPECT_EQ(b.rtl_checker.mismatches(), 0u) << "RTL against golden_fd";
    EXPECT_EQ(b.bench.checker.checked(), pixels);
    EXPECT_EQ(b.bench.checker.mismatches(), 0u) << "ours against golden_fd";
    EXPECT_EQ(b.edge_mismatches, 0u) << "RTL against ours, every rising edge";
    // m = 1; m = 7 (len 40 fits m = 6); len 2 at m = 0; len 9 at m = 3; len 0; len 65; m = 1 and len 0.
    EXPECT_EQ(report_log::get().count(msg::input), 8u);
}

// The verdict can fail: one corrupted golden value is one reported mismatch of the RTL's checker.
TEST(RtlFdEval, ComparisonCatchesAWrongGolden) {
    report_log::get().expect(msg::mismatch);
    fd_cosim<fd_bench<4>, Vrtl_fd_eval_m4> b("tb", random_fd_intervals<4>(200, 9));
    b.rtl_checker.inject_mismatch(37);
    EXPECT_TRUE(run_to_completion(b, sc_core::sc_time(1, sc_core::SC_MS)));
    EXPECT_EQ(b.rtl_checker.checked(), 200u);
    EXPECT_EQ(b.rtl_checker.mismatches(), 1u);
    EXPECT_EQ(b.bench.checker.mismatches(), 0u);
    EXPECT_EQ(b.edge_mismatches, 0u);
    EXPECT_EQ(report_log::get().count(msg::mismatch), 1u);
}

}  // namespace test_rtl_fd
