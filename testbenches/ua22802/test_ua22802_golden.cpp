// UA 22802 golden model (no simulation): the generated ROM against an independent evaluation of
// a(n), hand-worked words and pixels, and the bound between the bit-accurate model and the
// real-valued quadratic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reference/brdf_reference.h"
#include "formats/specular_formats.h"
#include "formats/ua22802_formats.h"
#include "arith/ua22802_arith.h"
#include "ua22802_a_rom.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua22802_golden {

using namespace shading;

namespace {
// a(n) = (t^(n-1) - 1)/(t - 1) is a geometric series: a = 1 + t + ... + t^(n-2). Summed here in
// long double, independently of ref::a_exact's closed form.
long double a_series(unsigned n) {
    const long double t = std::sqrt(static_cast<long double>(n - 1) / n);
    long double s = 0, p = 1;
    for (unsigned i = 0; i + 2 <= n; ++i, p *= t) s += p;
    return s;
}
}  // namespace

TEST(UA22802Rom, EveryWordIsTheRoundedSeriesValue) {
    ASSERT_EQ(ua22802::a_rom_content.size(), 1024u);
    EXPECT_EQ(ua22802::a_rom_content[0], 0u) << "n = 0: documented as a = 0";
    EXPECT_EQ(ua22802::a_rom_content[1], 0u) << "n = 1: a = 0 (q = cos)";
    for (unsigned n = 2; n < 1024; ++n) {
        const long double scaled = std::ldexp(a_series(n), ua22802::a_fmt.frac);
        EXPECT_LE(std::fabs(scaled - static_cast<long double>(ua22802::a_rom_content[n])), 0.5L + 1e-9L)
            << "n = " << n << ": round to nearest";
        EXPECT_EQ(ua22802::a_rom_content[n], golden_a_rom(n)) << "n = " << n << ": generated vs golden";
    }
}

TEST(UA22802Rom, HandWorkedWords) {
    // n = 2: t = sqrt(1/2), a = 1 -> 64. n = 3: a = 1 + t = 1 + sqrt(2/3) = 1.81650 -> 116.256 -> 116.
    // n = 4: a = 1 + t + t^2, t = sqrt(3/4): 1 + 0.866025 + 0.75 = 2.616025 -> 167.426 -> 167.
    EXPECT_EQ(golden_a_rom(2), 64u);
    EXPECT_EQ(golden_a_rom(3), 116u);
    EXPECT_EQ(golden_a_rom(4), 167u);
    // Large n: t^(n-1) -> e^(-1/2) and 1 - t -> 1/(2n), so a(n) ~ 2(1 - e^(-1/2)) n - 1/2
    // = 0.786939 n - 0.5 (the expansion is derived in the README). n = 1000: 786.44 -> 50332.
    EXPECT_NEAR(static_cast<double>(golden_a_rom(1000)) / 64.0, 0.786939 * 1000 - 0.5, 0.02);
    EXPECT_NEAR(static_cast<double>(golden_a_rom(500)) / 64.0, 0.786939 * 500 - 0.5, 0.02);
    // The widest word fits the 16-bit bus with the top bit in use (a(1023) = 804.6 -> 51497).
    EXPECT_GT(golden_a_rom(1023), 1u << 15);
    EXPECT_LE(golden_a_rom(1023), ua22802::a_fmt.mask());
}

TEST(UA22802Golden, HandWorkedPixels) {
    // n = 2, cos = 0.5: a = 1, q = 0.5 + (0.25 - 0.5) = 0.25 = cos^2 exactly -> 0x2000.
    // out = floor(0x2000 * 255 / 2^7) = 16320 = 63.75 in Q9.8.
    auto r = golden_ua22802(2, 0x4000, {255, 128, 1}, overflow_mode::saturate);
    EXPECT_EQ(r.brdf, 0x2000u);
    EXPECT_EQ(r.out[0], 16320u);
    EXPECT_EQ(r.out[1], 0x2000u * 128 >> 7);
    EXPECT_EQ(r.out[2], 0x2000u * 1 >> 7);
    // n = 1: a = 0, the BRDF is cos itself for every in-range code.
    for (uint64_t c = 0; c <= spec::cos_one; c += 97)
        EXPECT_EQ(golden_ua22802(1, c, {1, 1, 1}, overflow_mode::saturate).brdf, c);
    // n = 3, cos = 0.75: a = 116/64 = 1.8125; cos^2 - cos = -0.1875; a * d = -0.33984375 exactly
    // (116 * -0.1875 * 2^15 / 64 = -11136); q = 0.75 - 0.33984375 = 0.41015625 -> 13440 = 0x3480.
    EXPECT_EQ(golden_ua22802(3, 0x6000, {0, 0, 0}, overflow_mode::saturate).brdf, 0x3480u);
}

TEST(UA22802Golden, WithinTheRoundingBoundOfTheRealQuadratic) {
    // |a_rom - a| <= 2^-7 and |cos^2 - cos| <= 1/4 give <= 2^-9 on q; MUL10's floor adds < 2^-15.
    const double bound = std::ldexp(1.0, -9) + std::ldexp(1.0, -15);
    for (unsigned n = 1; n <= 1000; n += (n < 40 ? 1 : 37)) {
        const double a = ref::a_exact(n);
        double worst = 0;
        for (uint64_t c = 0; c <= spec::cos_one; ++c) {
            const double real = std::clamp(ref::quadratic(to_real(c, spec::cos_fmt), a), 0.0, 1.0);
            const double dev = to_real(golden_ua22802(n, c, {0, 0, 0}, overflow_mode::saturate).brdf,
                                       spec::brdf_fmt);
            worst = std::max(worst, std::fabs(dev - real));
        }
        EXPECT_LE(worst, bound) << "n = " << n;
    }
}

TEST(UA22802Golden, BrdfPaperAccuracyClaimHoldsBitAccurately) {
    // The quadratic-BRDF paper: relative error <= 4 % where cos^n >= 0.56, n in [1, 512]. Measured: 3.16 %.
    double worst = 0;
    for (unsigned n = 1; n <= 1000; ++n)
        for (uint64_t c = spec::cos_one; c > 0; --c) {
            const double x = to_real(c, spec::cos_fmt), p = std::pow(x, n);
            if (p < 0.56) break;
            const double q = to_real(golden_ua22802(n, c, {0, 0, 0}, overflow_mode::saturate).brdf,
                                     spec::brdf_fmt);
            worst = std::max(worst, std::fabs(q - p) / p);
        }
    EXPECT_LT(worst, 0.04);
    EXPECT_GT(worst, 0.03) << "the quadratic model's own error at large n (3.16 %) must show";
}

}  // namespace test_ua22802_golden
