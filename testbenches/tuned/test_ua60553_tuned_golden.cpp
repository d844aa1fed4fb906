// The tuned UA 60553 variant's golden model (no simulation): hand-worked a words and pixels, and its
// accuracy against cos^n and against the ROM prototype. The search that chose its constants
// re-derives them in the accuracy study's tests (studies/accuracy/test_generator_search.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "reference/brdf_reference.h"
#include "formats/specular_formats.h"
#include "arith/ua22802_arith.h"
#include "arith/ua60553_tuned_arith.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua60553_tuned_golden {

using namespace shading;

TEST(UA60553TunedGolden, HandWorkedCoefficients) {
    // minimax: a = n * 101/128 - 80/128 on the Q11.7 bus, n < 2 -> 0.
    EXPECT_EQ(golden_a_tuned(0, ua60553::minimax), 0u);
    EXPECT_EQ(golden_a_tuned(1, ua60553::minimax), 0u);
    EXPECT_EQ(golden_a_tuned(2, ua60553::minimax), 202u - 80u);          // 0.953125
    EXPECT_EQ(golden_a_tuned(1000, ua60553::minimax), 101000u - 80u);    // 788.4375
    EXPECT_EQ(golden_a_tuned(1023, ua60553::minimax), 103323u - 80u);
    // With the patent's constants and a positive K32 the law is formula 10 (= golden_a_linear).
    const ua60553::tuned_generator as_patent{"p", "1100101", "1000000", false};
    for (unsigned n = 2; n < 1024; ++n)
        EXPECT_EQ(golden_a_tuned(n, as_patent), golden_a_linear(n, ua60553::patent)) << n;
}

TEST(UA60553TunedGolden, HandWorkedPixel) {
    // n = 2, cos = 0.5: a = 122/128 = 0.953125; d = -0.25; a*d = -0.23828125 -> -7808 (exact);
    // q = 16384 - 7808 = 8576 (0.26171875, vs cos^2 = 0.25). out = 8576 * 200 >> 7 = 13400.
    const auto r = golden_ua60553_tuned(2, 0x4000, {200, 0, 0}, overflow_mode::saturate);
    EXPECT_EQ(r.brdf, 8576u);
    EXPECT_EQ(r.out[0], 13400u);
}

TEST(UA60553TunedGolden, WorstCaseBeatsTheRomAndTheBrdfPaperBound) {
    // Computed here directly (not through study_metrics) against cos^n.
    double worst_tuned = 0, worst_rom = 0;
    for (unsigned n = 1; n <= 1000; ++n)
        for (uint64_t c = spec::cos_one; c > 0; --c) {
            const double p = std::pow(to_real(c, spec::cos_fmt), n);
            if (p < 0.56) break;
            const auto t = golden_ua60553_tuned(n, c, {0, 0, 0}, overflow_mode::saturate).brdf;
            const auto r = golden_ua22802(n, c, {0, 0, 0}, overflow_mode::saturate).brdf;
            worst_tuned = std::max(worst_tuned, std::fabs(to_real(t, spec::brdf_fmt) - p) / p);
            worst_rom = std::max(worst_rom, std::fabs(to_real(r, spec::brdf_fmt) - p) / p);
        }
    EXPECT_LT(worst_tuned, 0.04) << "the quadratic-BRDF paper's bound";
    EXPECT_LT(worst_tuned, worst_rom) << "no worse than the ROM prototype in the worst case";
    EXPECT_NEAR(worst_tuned, 0.0309, 0.0005);
    EXPECT_NEAR(worst_rom, 0.0316, 0.0005);
}

TEST(UA60553TunedGolden, RomMatchedHandWorkedWords) {
    // a(2) = (202 - 73)/128 = 1.0078125 (exact a(2) = 1), a(1) = 0.
    EXPECT_EQ(golden_a_tuned(2, ua60553::rom_matched), 129u);
    EXPECT_EQ(golden_a_tuned(1, ua60553::rom_matched), 0u);
}

TEST(UA60553TunedGolden, RomMatchedFollowsTheRomNByN) {
    // Computed here directly against cos^n, n by n: never more than 0.27 points above the ROM
    // prototype, and no worse than it from n = 31 on (modules/tuned/README.md, "A better ROM-free a(n)").
    for (unsigned n = 1; n <= 1000; ++n) {
        double tuned = 0, rom = 0;
        for (uint64_t c = spec::cos_one; c > 0; --c) {
            const double p = std::pow(to_real(c, spec::cos_fmt), n);
            if (p < 0.56) break;
            const auto t = golden_ua60553_tuned(n, c, {0, 0, 0}, overflow_mode::saturate, ua60553::rom_matched).brdf;
            const auto r = golden_ua22802(n, c, {0, 0, 0}, overflow_mode::saturate).brdf;
            tuned = std::max(tuned, std::fabs(to_real(t, spec::brdf_fmt) - p) / p);
            rom = std::max(rom, std::fabs(to_real(r, spec::brdf_fmt) - p) / p);
        }
        ASSERT_LE(tuned - rom, 0.0027) << "n = " << n;
        if (n >= 31) {
            ASSERT_LE(tuned, rom) << "n = " << n;
        }
        ASSERT_LT(tuned, 0.0316) << "below the ROM's own worst case, n = " << n;
    }
}

}  // namespace test_ua60553_tuned_golden
