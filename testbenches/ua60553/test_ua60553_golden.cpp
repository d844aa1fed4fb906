// The UA 60553 golden model against hand-worked values and against the real-valued datapath.
// No simulation here: these tests may share a process.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/brdf_reference.h"
#include "scene/scene.h"
#include "arith/specular_arith.h"
#include "formats/specular_formats.h"
#include "formats/ua60553_formats.h"

// A folder's suites compile as one unit (cmake/shading.cmake): this file's names stay in its own namespace.
namespace test_ua60553_golden {

using namespace shading;

TEST(UA60553Golden, PatentConstantsGiveAOf0_7890625nPlusHalf) {
    // Node 31 = 0.1100101b = 101/128, node 32 = 0.1b = 64/128, a on Q11.7.
    EXPECT_EQ(golden_a_linear(1, ua60553::patent), 165u);         // 1.2890625 * 128
    EXPECT_EQ(golden_a_linear(1000, ua60553::patent), 101064u);   // 789.5625 * 128
    EXPECT_EQ(golden_a_linear(0, ua60553::patent), 64u);          // n = 0: a = K32 = 0.5
    EXPECT_EQ(golden_a_linear(1023, ua60553::patent), 103387u);   // 10-bit maximum, no overflow
    // The patent prints 0.786 n + 0.5; its 7-bit constant is 0.7890625.
    EXPECT_NEAR(golden_a_linear(1000, ua60553::patent) / 128.0 - ref::a_patent_formula(1000), 3.0625, 1e-12);
}

TEST(UA60553Golden, HandWorkedPixel) {
    // n = 1: a = 165/128; cos = 0.5 (0x4000): cos^2 - cos = -0.25, a * -0.25 = -0.322265625
    // = -10560/32768 exactly, q = 0.5 - 0.322265625 = 0.177734375 = 5824/32768.
    const auto r = golden_ua60553(1, 0x4000, {200, 255, 0}, overflow_mode::saturate);
    EXPECT_EQ(r.cos2, 0x10000000u);                         // 0.25 in Q2.30
    EXPECT_EQ(r.diff, 0xF0000000u);                         // -0.25 in Q2.30 two's complement
    EXPECT_EQ(code_value(r.prod, spec::mul10_fmt), -10560);
    EXPECT_EQ(r.brdf, 5824u);
    EXPECT_EQ(r.out[0], 9100u);   // 5824 * 200 / 128 = 9100 -> 35.546875
    EXPECT_EQ(r.out[1], 11602u);  // 5824 * 255 / 128 = 11602.5 -> floor
    EXPECT_EQ(r.out[2], 0u);
}

TEST(UA60553Golden, NegativeBrdfSaturatesToZeroOrWrapsAsTheAdderWould) {
    // n = 2: a = 266/128 = 2.078125; cos = 0.5: q = 0.5 - 0.51953125 = -0.01953125 = -640/32768.
    const auto sat = golden_ua60553(2, 0x4000, {255, 255, 255}, overflow_mode::saturate);
    const auto wrap = golden_ua60553(2, 0x4000, {255, 255, 255}, overflow_mode::wrap);
    EXPECT_EQ(sat.brdf, 0u);
    EXPECT_EQ(sat.out[0], 0u);
    EXPECT_EQ(wrap.brdf, 65536u - 640u);          // the low 16 wires of -640
    EXPECT_EQ(wrap.out[0], (64896u * 255u) >> 7);  // read by MUL12 as q = 1.98046875
}

TEST(UA60553Golden, CosAboveOneSaturatesToFullIntensity) {
    for (uint64_t c : {0x8001u, 0xA000u, 0xFFFFu}) {
        const auto r = golden_ua60553(1000, c, {255, 17, 1}, overflow_mode::saturate);
        EXPECT_EQ(r.brdf, spec::cos_one) << c;
        EXPECT_EQ(r.out[0], 255u << 8);
        EXPECT_EQ(r.out[1], 17u << 8);
    }
}

TEST(UA60553Golden, InverterAndCarryFormTheTwosComplementDifference) {
    // ADD9 = cos^2 + ~(cos << 15) + 1 must equal cos^2 - cos for every code (patent: "subtraction
    // in two's complement, carry input 28 at logic 1").
    for (uint64_t c = 0; c <= 0xFFFF; ++c) {
        const auto r = golden_ua60553(500, c, {1, 1, 1}, overflow_mode::wrap);
        ASSERT_EQ((r.cos2 + r.inv8 + 1) & spec::d_fmt.mask(), r.diff) << c;
        const double d = to_real(r.diff, spec::d_fmt);
        const double cr = to_real(c, spec::cos_fmt);
        ASSERT_EQ(d, cr * cr - cr) << c;
    }
}

// Quantisation bound of the documented formats (README): MUL10 floors to 2^-15 and MUL12..14
// floor to 2^-8, so 0 <= real - device < k_s*I * 2^-15 + 2^-8 <= 0.0117 of an 8-bit LSB.
class UA60553Quantisation : public ::testing::TestWithParam<unsigned> {};

TEST_P(UA60553Quantisation, WithinTheBoundOfTheRealValuedDatapath) {
    const unsigned n = GetParam();
    const double a = golden_a_linear(n, ua60553::patent) / 128.0;
    for (uint64_t ksi : {255u, 200u, 1u}) {
        const double bound = ksi / 32768.0 + 1.0 / 256.0;
        ASSERT_LT(bound, 1.0);  // at most 1 LSB of an 8-bit result, as required
        double worst = 0.0;
        for (uint64_t c = 0; c <= spec::cos_one; ++c) {
            const auto r = golden_ua60553(n, c, {ksi, ksi, ksi}, overflow_mode::saturate);
            const double hw = to_real(r.out[0], spec::out_fmt);
            const double real = ref::real_datapath_out(a, to_real(c, spec::cos_fmt), static_cast<double>(ksi));
            const double err = real - hw;
            ASSERT_GE(err, -1e-12) << "n=" << n << " cos=" << c;
            ASSERT_LT(err, bound) << "n=" << n << " cos=" << c;
            worst = std::max(worst, err);
        }
        EXPECT_GT(worst, 0.0) << "floors never dropped anything: the bound check would be vacuous";
    }
}

INSTANTIATE_TEST_SUITE_P(N, UA60553Quantisation, ::testing::Values(1u, 2u, 10u, 100u, 1000u));

TEST(Scene, SphereLineHasItsHighlightWhereNEqualsH) {
    // Light along the view direction: H = V = +z, so cos = z = sqrt(1 - x^2) on the line y = 0.
    const auto c = scene::sphere_line_cos(0.0, 5, 0.0, 0.0, 1.0);
    ASSERT_EQ(c.size(), 5u);
    EXPECT_DOUBLE_EQ(c[2], 1.0);
    EXPECT_NEAR(c[1], std::sqrt(0.75), 1e-12);
    EXPECT_EQ(c[0], 0.0);
    EXPECT_EQ(scene::cos_code(1.0), 0x8000u);
    EXPECT_EQ(scene::cos_code(0.5), 0x4000u);
}

}  // namespace test_ua60553_golden
