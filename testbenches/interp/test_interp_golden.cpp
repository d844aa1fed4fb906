// Golden models of the interpolation units against the real-valued solution, hand-worked values
// and the re-derived formulas. No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "formats/interp_formats.h"
#include "golden/interp_golden.h"
#include "reference/interp_reference.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_interp_golden {

using namespace shading;
using namespace shading::interp;

namespace {
constexpr double lsb = 1.0 / 65536.0;  // coef_fmt
double q8(uint64_t code) { return static_cast<double>(code) / 256.0; }

std::array<uint64_t, 4> random_samples(std::mt19937& rng) {
    std::uniform_int_distribution<uint64_t> u(0, sample_fmt.mask());
    return {u(rng), u(rng), u(rng), u(rng)};
}
}  // namespace

//'s formulas re-derived: the cubic through the samples, found by solving the Vandermonde
// system, has the formulas' coefficients, and it reproduces the samples.
TEST(InterpFormulas, CubicThroughTheSamplesBothSets) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0.0, 255.0);
    for (auto set : {sample_set::case1, sample_set::case2}) {
        const auto ts = ref::sample_ts(set);
        for (int n = 0; n < 200; ++n) {
            const std::array<double, 4> s{u(rng), u(rng), u(rng), u(rng)};
            const auto p = ref::cubic_coefs(s, set);
            for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(ref::eval(p, ts[i]), s[i], 1e-9);
            const auto fit = ref::fit_polynomial({ts.begin(), ts.end()}, {s.begin(), s.end()});
            EXPECT_NEAR(fit[0], p.d, 1e-8);
            EXPECT_NEAR(fit[1], p.c, 1e-8);
            EXPECT_NEAR(fit[2], p.b, 1e-8);
            EXPECT_NEAR(fit[3], p.a, 1e-8);
        }
    }
}

TEST(InterpFormulas, QuadraticThroughTheSamples) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 255.0);
    for (int n = 0; n < 200; ++n) {
        const std::array<double, 3> s{u(rng), u(rng), u(rng)};
        const auto p = ref::quad_coefs(s);
        EXPECT_NEAR(ref::eval(p, 0.0), s[0], 1e-9);
        EXPECT_NEAR(ref::eval(p, 0.5), s[1], 1e-9);
        EXPECT_NEAR(ref::eval(p, 1.0), s[2], 1e-9);
        const auto fit = ref::fit_polynomial({0.0, 0.5, 1.0}, {s[0], s[1], s[2]});
        EXPECT_NEAR(fit[2], p.b, 1e-8);  // t^2
        EXPECT_NEAR(fit[1], p.c, 1e-8);  // t
        EXPECT_NEAR(fit[0], p.d, 1e-8);
    }
}

// A linear ramp I(t) = 128 t, case 1: samples 0, 32, 64, 128 -> A = B = D = 0, C = 128.
// N_C = 32*32 - 12*64 + 128 = 384 (Q.8 code 98304): exact C = 128 (8388608); the shift-and-add
// gives 98304 * 86 = 8454144 = 129.0, the paper's 43/128 instead of 1/3.
TEST(InterpCoefGolden, HandWorkedRamp) {
    const std::array<uint64_t, 4> s{0, 32 * 256, 64 * 256, 128 * 256};
    const auto ex = golden_cubic_coefs(s, sample_set::case1, div3_mode::exact);
    const auto sa = golden_cubic_coefs(s, sample_set::case1, div3_mode::shift_add);
    EXPECT_EQ(ex, (cubic_coefs{0, 0, 128 * 65536, 0}));
    EXPECT_EQ(sa, (cubic_coefs{0, 0, 129 * 65536, 0}));
    // Quadratic through I(t) = 100 t^2: samples 0, 25, 100 -> a = 100, b = 0, c = 0.
    EXPECT_EQ(golden_quad_coefs({0, 25 * 256, 100 * 256}), (cubic_coefs{100 * 65536, 0, 0, 0}));
}

// Exact division: A and C are the real-valued coefficients floored to Q16.16; B and D exact.
// Shift-and-add: A and C are exactly 129/128 of the real ones (no wire is dropped), a relative
// error of 0.78125 %, within the paper's "<= 0.79 %".
TEST(InterpCoefGolden, WithinDocumentedBoundOfTheRealSolution) {
    std::mt19937 rng(6);
    double worst_rel = 0.0;
    for (auto set : {sample_set::case1, sample_set::case2}) {
        for (int n = 0; n < 2000; ++n) {
            const auto s = random_samples(rng);
            const auto r = ref::cubic_coefs({q8(s[0]), q8(s[1]), q8(s[2]), q8(s[3])}, set);
            const auto ex = golden_cubic_coefs(s, set, div3_mode::exact);
            const auto sa = golden_cubic_coefs(s, set, div3_mode::shift_add);
            EXPECT_DOUBLE_EQ(ex.b * lsb, r.b);
            EXPECT_DOUBLE_EQ(ex.d * lsb, r.d);
            EXPECT_EQ(sa.b, ex.b);
            EXPECT_EQ(sa.d, ex.d);
            for (auto [g, real] : {std::pair{ex.a, r.a}, std::pair{ex.c, r.c}}) {
                EXPECT_LE(g * lsb, real + 1e-9);
                EXPECT_GT(g * lsb, real - lsb - 1e-9);
            }
            for (auto [g, real] : {std::pair{sa.a, r.a}, std::pair{sa.c, r.c}}) {
                EXPECT_NEAR(g * lsb, real * 129.0 / 128.0, 1e-9);
                if (std::abs(real) > 1.0) worst_rel = std::max(worst_rel, std::abs(g * lsb - real) / std::abs(real));
            }
        }
    }
    EXPECT_NEAR(worst_rel, 1.0 / 128.0, 1e-9);
    EXPECT_LE(worst_rel, 0.0079);  // the interpolation paper's claim
}

// The interpolation paper's grouping of the /3 (div3_grouping::partial_sum) against the real solution. With the
// shift-and-add, x * 43/128 = x/3 + x/384, so each coefficient is off by exactly its divided part
// over 384 (in Q.8 levels): case 1 A by (64I2 + 8I4)/384, C by (32I2 + I4)/384; case 2, where
// the quotient is subtracted, A by -(8I1 + 64I3)/384, C by -(13I1 + 32I3)/384. The whole-sum
// grouping is off by the whole sum over 384 (the 129/128 above).
TEST(InterpCoefGolden, PartialSumShiftAddOffByTheDividedPartOver384) {
    std::mt19937 rng(16);
    for (int n = 0; n < 2000; ++n) {
        const auto s = random_samples(rng);
        const double i1 = q8(s[0]), i2 = q8(s[1]), i3 = q8(s[2]), i4 = q8(s[3]);
        const auto r1 = ref::cubic_coefs({i1, i2, i3, i4}, sample_set::case1);
        const auto g1 = golden_cubic_coefs(s, sample_set::case1, div3_mode::shift_add, div3_grouping::partial_sum);
        EXPECT_NEAR(g1.a * lsb - r1.a, (64 * i2 + 8 * i4) / 384.0, 1e-9);
        EXPECT_NEAR(g1.c * lsb - r1.c, (32 * i2 + i4) / 384.0, 1e-9);
        const auto r2 = ref::cubic_coefs({i1, i2, i3, i4}, sample_set::case2);
        const auto g2 = golden_cubic_coefs(s, sample_set::case2, div3_mode::shift_add, div3_grouping::partial_sum);
        EXPECT_NEAR(g2.a * lsb - r2.a, -(8 * i1 + 64 * i3) / 384.0, 1e-9);
        EXPECT_NEAR(g2.c * lsb - r2.c, -(13 * i1 + 32 * i3) / 384.0, 1e-9);
        for (auto set : {sample_set::case1, sample_set::case2}) {  // B and D do not depend on the grouping
            const auto w = golden_cubic_coefs(s, set, div3_mode::shift_add);
            const auto p = golden_cubic_coefs(s, set, div3_mode::shift_add, div3_grouping::partial_sum);
            EXPECT_EQ(p.b, w.b);
            EXPECT_EQ(p.d, w.d);
        }
    }
}

// A flat line, every sample 1.0: the real cubic is 0 t^3 + 0 t^2 + 0 t + 1, and so is the whole-sum
// shift-and-add (its sum is 0). The paper's grouping divides 72 (A) and 33 (C) levels and subtracts
// 24 and 11: case 1 A = 72 * 43/128 - 24 = 0.1875 (12288 LSB), C = 33 * 43/128 - 11 = 0.0859375
// (5632); case 2 A = 24 - 72 * 43/128 = -0.1875, C = 15 - 45 * 43/128 = -0.1171875 (-7680).
TEST(InterpCoefGolden, PartialSumHandWorkedFlatLine) {
    const std::array<uint64_t, 4> flat{256, 256, 256, 256};
    for (auto set : {sample_set::case1, sample_set::case2})
        EXPECT_EQ(golden_cubic_coefs(flat, set, div3_mode::shift_add), (cubic_coefs{0, 0, 0, 65536}));
    EXPECT_EQ(golden_cubic_coefs(flat, sample_set::case1, div3_mode::shift_add, div3_grouping::partial_sum),
              (cubic_coefs{12288, 0, 5632, 65536}));
    EXPECT_EQ(golden_cubic_coefs(flat, sample_set::case2, div3_mode::shift_add, div3_grouping::partial_sum),
              (cubic_coefs{-12288, 0, -7680, 65536}));
}

// With the exact divider the grouping costs nothing: in case 1 the integer part Y enters as
// 256 Y - floor(256 X / 3) = floor(256 (X - 3Y) / 3), bit for bit the whole-sum result; in case 2
// the quotient is subtracted, Y - floor(X/3) rounds up where the whole sum floors: +1 LSB at most.
TEST(InterpCoefGolden, PartialSumExactDividerIsTheWholeSumWithinOneLsb) {
    std::mt19937 rng(17);
    unsigned case2_up = 0;
    for (int n = 0; n < 5000; ++n) {
        const auto s = random_samples(rng);
        EXPECT_EQ(golden_cubic_coefs(s, sample_set::case1, div3_mode::exact, div3_grouping::partial_sum),
                  golden_cubic_coefs(s, sample_set::case1, div3_mode::exact));
        const auto p = golden_cubic_coefs(s, sample_set::case2, div3_mode::exact, div3_grouping::partial_sum);
        const auto w = golden_cubic_coefs(s, sample_set::case2, div3_mode::exact);
        for (auto diff : {p.a - w.a, p.c - w.c}) {
            EXPECT_GE(diff, 0);
            EXPECT_LE(diff, 1);
            case2_up += diff == 1 ? 1u : 0u;
        }
    }
    EXPECT_GT(case2_up, 0u) << "case 2 rounds up where the quotient is not exact";
}

TEST(InterpCoefGolden, Div3ShiftAddAgainstOneThird) {
    for (int64_t x : {int64_t{3}, int64_t{-3}, int64_t{300}, int64_t{-18432 * 256}, int64_t{18432 * 256}}) {
        EXPECT_EQ(golden_div3(x, div3_mode::shift_add), 86 * x);  // x * 43/128 on Q.16 from Q.8
        EXPECT_EQ(golden_div3(x, div3_mode::exact) * 3, x * 256);  // multiples of 3: exact
    }
    EXPECT_EQ(golden_div3(-1, div3_mode::exact), -86);  // floor(-256/3) = -85.33 -> -86
    EXPECT_EQ(golden_div3(1, div3_mode::exact), 85);
}

// Horner: P - I_hw = e1 t^2 + e2 t + e3 with each floor error e in [0, 1) LSB: 0 <= P - I < 3 LSB,
// P the exact polynomial of the coefficient codes (checked in exact integer arithmetic).
TEST(InterpHornerGolden, WithinThreeLsbBelowTheExactPolynomial) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int64_t> ua(-24 * 255 * 65536, 24 * 255 * 65536), ub(-38 * 255 * 65536, 38 * 255 * 65536),
        uc(-15 * 255 * 65536, 15 * 255 * 65536), ud(0, 255 * 65536);
    for (int n = 0; n < 3000; ++n) {
        const cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
        for (int64_t t = 0; t <= 256; t += 8) {
            const __int128 exact = ((static_cast<__int128>(k.a) * t + static_cast<__int128>(k.b) * 256) * t +
                                    static_cast<__int128>(k.c) * 65536) * t + static_cast<__int128>(k.d) * 16777216;
            const int64_t hw = code_value(golden_horner(k, static_cast<uint64_t>(t), false), coef_fmt);
            const __int128 err = exact - static_cast<__int128>(hw) * 16777216;
            EXPECT_GE(static_cast<int64_t>(err), 0);
            EXPECT_LT(static_cast<int64_t>(err), 3 * 16777216);
        }
    }
}

TEST(InterpHornerGolden, HandWorkedSteps) {
    // A = 1, B = -2, C = 0.5, D = 3, t = 0.5: RG = -2, -1.5, -0.75, -0.25, -0.125, 2.875.
    const cubic_coefs k{65536, -2 * 65536, 32768, 3 * 65536};
    const auto s = golden_horner_steps(k, 128, false);
    const std::vector<int64_t> want{-131072, -98304, -49152, -16384, -8192, 188416};
    ASSERT_EQ(s.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(code_value(s[i], coef_fmt), want[i]) << "step " << i + 1;
    // Degree 2, a = 1, b = -2, c = 0.5 at t = 0.5: 0.25 - 1 + 0.5 = -0.25; 4 steps.
    const auto q = golden_horner_steps(k, 128, true);
    ASSERT_EQ(q.size(), 4u);
    EXPECT_EQ(code_value(q.back(), coef_fmt), -16384);
    // Floor of a negative product: RG = -1 LSB times t = 0.5 -> -0.5 LSB -> -1 LSB.
    EXPECT_EQ(code_value(golden_horner({0, -1, 0, 0}, 128, false), coef_fmt), -1);
}

// Forward differences with 16 + 3m fraction bits: the set-up is exact, so every output is the
// exact polynomial floored to Q16.16 -- no accumulated error over the longest interval.
TEST(InterpFdGolden, ExactFloorOfThePolynomialForEveryM) {
    std::mt19937 rng(8);
    std::uniform_int_distribution<int64_t> ua(-24 * 255 * 65536, 24 * 255 * 65536), ub(-38 * 255 * 65536, 38 * 255 * 65536),
        uc(-15 * 255 * 65536, 15 * 255 * 65536), ud(0, 255 * 65536);
    for (unsigned m = m_min; m <= m_max; ++m) {
        for (int n = 0; n < 300; ++n) {
            const cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
            const unsigned nn = 1u << m;
            const auto out = golden_fd(k, m, nn);
            for (unsigned i = 0; i < nn; ++i) {
                const __int128 n3 = static_cast<__int128>(nn) * nn * nn;
                const __int128 num = ((static_cast<__int128>(k.a) * i + static_cast<__int128>(k.b) * nn) * i +
                                      static_cast<__int128>(k.c) * nn * nn) * i + static_cast<__int128>(k.d) * n3;
                __int128 fl = num / n3;
                if (num % n3 != 0 && num < 0) --fl;
                ASSERT_EQ(code_value(out[i], coef_fmt), static_cast<int64_t>(fl)) << "m=" << m << " k=" << i;
                // And within [0, 2] LSB above the Horner unit's result at the same t.
                const int64_t h = code_value(golden_horner(k, static_cast<uint64_t>(i) << (8 - m), false), coef_fmt);
                EXPECT_GE(static_cast<int64_t>(fl) - h, 0);
                EXPECT_LE(static_cast<int64_t>(fl) - h, 2);
            }
        }
    }
}

// With fewer fraction bits the floored set-up errors grow as k e1 + C(k,2) e2 + C(k,3) e3: the
// derived bound holds over the longest interval, and is nearly reached (so it is not vacuous).
TEST(InterpFdGolden, ReducedFractionBitsStayWithinTheDerivedBound) {
    std::mt19937 rng(9);
    std::uniform_int_distribution<int64_t> ua(-24 * 255 * 65536, 24 * 255 * 65536), ub(-38 * 255 * 65536, 38 * 255 * 65536),
        uc(-15 * 255 * 65536, 15 * 255 * 65536), ud(0, 255 * 65536);
    const unsigned m = m_max, nn = 1u << m;
    for (int frac : {20, 24, 28, 32}) {
        double worst = 0.0;
        for (int n = 0; n < 300; ++n) {
            const cubic_coefs k{ua(rng), ub(rng), uc(rng), ud(rng)};
            const auto out = golden_fd(k, m, nn, frac);
            for (unsigned i = 0; i < nn; ++i) {
                const double t = static_cast<double>(i) / nn;
                const double exact = ((k.a * t + k.b) * t + k.c) * t + k.d;  // in LSB units
                const double err = std::abs(code_value(out[i], coef_fmt) - exact) * lsb;
                const double bound = fd_error_bound(i, m, frac) + lsb;  // + the output floor
                EXPECT_LE(err, bound + 1e-9) << "frac=" << frac << " k=" << i;
                worst = std::max(worst, err / bound);
            }
        }
        EXPECT_GT(worst, 0.25) << "frac=" << frac << ": the bound should be nearly reached";
    }
    EXPECT_EQ(fd_error_bound(nn, m, fd_fmt.frac), 0.0);
}

}  // namespace test_interp_golden
