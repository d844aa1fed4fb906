// The squared-quadratic device's golden model (no simulation): hand-worked generator words and
// pixels, the generator against its law in real numbers, the squaring against exact squares, both
// overflow modes, and the accuracy claims computed here directly against cos^n.
#include <gtest/gtest.h>

#include <cmath>

#include "arith/squared_arith.h"
#include "formats/specular_formats.h"
#include "formats/squared_formats.h"
#include "reference/brdf_reference.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_squared_golden {

using namespace shading;

namespace {
constexpr auto sat = overflow_mode::saturate;
constexpr auto wrap = overflow_mode::wrap;
double q_real(uint64_t bits) { return to_real(bits, squared::q_fmt); }
}  // namespace

TEST(SquaredGolden, HandWorkedGeneratorWords) {
    // n = 3 = 0b0000000011: z = 8, n << 8 = 768 = 1.5 (Q1.9), f = 256 = 0.5; ~f = 255;
    // e = 256 * 255 = 65280; e << 8 = 16711680; >> 17 = 127 (127.5 floored); a = 256*8 + 127 = 2175.
    auto g = golden_squared_a(3);
    EXPECT_EQ(g.z, 8u);
    EXPECT_EQ(g.mant, 768u);
    EXPECT_EQ(g.f, 256u);
    EXPECT_EQ(g.e, 65280u);
    EXPECT_EQ(g.esh, 16711680u);
    EXPECT_EQ(g.bend, 127u);
    EXPECT_EQ(g.a, 2175u);
    EXPECT_EQ(g.k, 1u);
    // n = 1000 = 0b1111101000: z = 0, f = 488, ~f = 23, e = 11224, bend = 11224 >> 17 = 0, a = 3904.
    g = golden_squared_a(1000);
    EXPECT_EQ(g.z, 0u);
    EXPECT_EQ(g.f, 488u);
    EXPECT_EQ(g.e, 11224u);
    EXPECT_EQ(g.bend, 0u);
    EXPECT_EQ(g.a, 3904u);
    EXPECT_EQ(g.k, 9u);
    // Powers of two: f = 0, a = 0, k = log2 n: the device computes cos^(2^k) by squaring alone.
    for (unsigned k = 0; k <= 9; ++k) {
        g = golden_squared_a(1u << k);
        EXPECT_EQ(g.a, 0u) << k;
        EXPECT_EQ(g.k, k);
    }
    // n = 0 (out of range): the LZC reads 10 zeros; f = 0, a = 0, no squaring: q = cos, as n = 1.
    g = golden_squared_a(0);
    EXPECT_EQ(g.z, 10u);
    EXPECT_EQ(g.a, 0u);
    EXPECT_EQ(g.k, 0u);
}

TEST(SquaredGolden, GeneratorIsItsLawInRealNumbers) {
    // a = f + f (1 - f - 2^-9) / 2^(k + 2), floored onto Q0.12 (f is on that grid already), from
    // n alone: k = floor(log2 n), f = n / 2^k - 1.
    for (unsigned n = 1; n < 1024; ++n) {
        const unsigned k = ref::squared_k(n);
        const double f = ref::squared_f(n);
        const double bend = f * (1.0 - f - 1.0 / 512.0) / std::ldexp(1.0, static_cast<int>(k) + 2);
        const double want = f + std::floor(bend * 4096.0 + 1e-9) / 4096.0;
        const auto g = golden_squared_a(n);
        EXPECT_EQ(g.k, k) << n;
        EXPECT_DOUBLE_EQ(to_real(g.a, squared::a_fmt), want) << n;
        EXPECT_LT(g.a, 1u << 12) << n;  // a < 1: the quadratic at n' has no negative region
    }
}

TEST(SquaredGolden, HandWorkedPixel) {
    // n = 3, cos = 0.5: d = 2^28 - 2^29 = -2^28 (-0.25); a d = -2175 * 2^28, >> 24 = -34800;
    // q = 0.5 * 2^18 - 34800 = 96272 (0.36725); k = 1: 96272^2 = 9268297984 = 35355 * 2^18 + 196864
    // -> 35355 (0.13487; cos^3 = 0.125, the tail); out = (35355 >> 3) * 200 >> 7 = 4419 * 200 >> 7 = 6904.
    const auto r = golden_squared(3, 0x4000, {200, 0, 255}, sat);
    EXPECT_EQ(r.prod, wrap_bits(-34800, squared::mul10_fmt.width));
    EXPECT_EQ(r.q, 96272u);
    EXPECT_EQ(r.sq[1], 35355u);
    EXPECT_EQ(r.brdf, 35355u);
    EXPECT_EQ(r.out[0], 6904u);
    EXPECT_EQ(r.out[1], 0u);
    EXPECT_EQ(r.out[2], 4419u * 255u >> 7);
}

TEST(SquaredGolden, PowersOfTwoAreRepeatedFlooredSquares) {
    // n = 2^k: q = cos exactly (on Q1.18), then k floored squares, each checked against the exact
    // square of the previous word.
    for (unsigned k = 0; k <= 9; ++k)
        for (uint64_t c : {0ull, 1ull, 0x2000ull, 0x4000ull, 0x7001ull, 0x7FFFull, 0x8000ull}) {
            const auto r = golden_squared(1u << k, c, {255, 255, 255}, sat);
            EXPECT_EQ(r.q, c << 3);
            uint64_t s = c << 3;
            for (unsigned i = 1; i <= k; ++i) {
                const double exact = q_real(s) * q_real(s);
                s = static_cast<uint64_t>(std::floor(exact * 262144.0));
                EXPECT_EQ(r.sq[i], s) << "k " << k << " cos " << c << " square " << i;
            }
            EXPECT_EQ(r.brdf, s);
        }
    // cos = 1.0 stays 1.0 through every square (1.0^2 fits the Q1.18 bus).
    EXPECT_EQ(golden_squared(512, 0x8000, {255, 255, 255}, sat).brdf, squared::q_one);
    EXPECT_EQ(golden_squared(512, 0x8000, {255, 255, 255}, sat).out[0], 255u << 8);
}

TEST(SquaredGolden, InRangeTheModesAgreeAndTheQuadraticIsNeverNegative) {
    // For cos <= 1.0 ADD11's sum lies in [0, 1.0] (formats: the floor of MUL10 cannot pass 8 cos),
    // so wrap and saturate give the same bits for every n and code.
    for (unsigned n = 0; n < 1024; ++n)
        for (uint64_t c = 0; c <= spec::cos_one; c += (c < 256 ? 1 : 61)) {
            const auto s = golden_squared(n, c, {255, 1, 128}, sat);
            const auto w = golden_squared(n, c, {255, 1, 128}, wrap);
            const int64_t sum = code_value(s.prod, squared::mul10_fmt) + static_cast<int64_t>(c << 3);
            ASSERT_GE(sum, 0) << n << " " << c;
            ASSERT_LE(sum, static_cast<int64_t>(squared::q_one)) << n << " " << c;
            ASSERT_EQ(s.out, w.out) << n << " " << c;
        }
}

TEST(SquaredGolden, CosAboveOneSaturatesOrWraps) {
    // cos = 1.5 (0xC000), n = 3: d = 0.75, a d = 0.398 -> q = 1.898 on 19 wires.
    const auto s = golden_squared(3, 0xC000, {255, 255, 255}, sat);
    EXPECT_EQ(s.q, squared::q_one);  // clamped to 1.0
    EXPECT_EQ(s.brdf, squared::q_one);
    const auto w = golden_squared(3, 0xC000, {255, 255, 255}, wrap);
    const int64_t d = 0xC000ll * 0xC000ll - (0xC000ll << 15);
    const int64_t sum = ((2175ll * d) >> 24) + (0xC000ll << 3);
    EXPECT_EQ(w.q, static_cast<uint64_t>(sum) & squared::q_fmt.mask());
    EXPECT_EQ(w.brdf, ((w.q * w.q) >> 18) & squared::q_fmt.mask());  // the square's high wires dropped
}

TEST(SquaredGolden, WorstRelativeErrorAboveTheBrdfPaperThresholdIsBelowOnePercent) {
    // Computed here against cos^n of the code (the quadratic-BRDF paper's measure, where cos^n >= 0.56).
    double worst = 0;
    unsigned worst_n = 0;
    for (unsigned n = 1; n <= squared::n_max; ++n)
        for (uint64_t c = spec::cos_one; c > 0; --c) {
            const double p = std::pow(to_real(c, spec::cos_fmt), n);
            if (p < 0.56) break;
            const double e = std::fabs(q_real(golden_squared(n, c, {0, 0, 0}, sat).brdf) - p) / p;
            if (e > worst) worst = e, worst_n = n;
        }
    EXPECT_LT(worst, 0.01) << "at n = " << worst_n;
    EXPECT_GT(worst, 0.001) << "a law this simple cannot be that exact: check the measure";
    EXPECT_EQ(worst_n, 3u);  // the law's own worst case, one squaring
}

TEST(SquaredGolden, CloseToItsRealValuedLaw) {
    // The hardware's words against the law in real numbers (a with 1 - f, no floors): the squared
    // outputs differ by less than 0.2 % of full scale for every n and code.
    double worst = 0;
    for (unsigned n = 1; n <= squared::n_max; n += 7)
        for (uint64_t c = 0; c <= spec::cos_one; c += 13) {
            const double want = ref::squared_law(to_real(c, spec::cos_fmt), n);
            worst = std::max(worst, std::fabs(q_real(golden_squared(n, c, {0, 0, 0}, sat).brdf) - want));
        }
    EXPECT_LT(worst, 0.002);
}

}  // namespace test_squared_golden
