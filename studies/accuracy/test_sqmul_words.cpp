// The square-and-multiply designs' golden models (src/floor/arith/sqmul_arith.*) at hand-worked words,
// both walks and several P words; their clocks per sample against the hand-derived formula; the
// study's relative-error measure against functions whose error is known. No simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "formats/specular_formats.h"
#include "formats/sqmul_formats.h"
#include "arith/sqmul_arith.h"
#include "reference/brdf_reference.h"
#include "sqmul_words.h"

using namespace shading;
using namespace shading::study;

namespace {
constexpr auto sat = overflow_mode::saturate;
uint64_t l2r(unsigned n, uint64_t code, unsigned frac = 18) { return golden_sqmul(n, code, {0, 0, 0}, sat, frac).p; }
uint64_t r2l(unsigned n, uint64_t code, unsigned frac = 18) { return golden_sqmul_r2l(n, code, {0, 0, 0}, sat, frac).p; }
}  // namespace

TEST(SqmulWords, HandWorkedWords) {
    // cos = 0x7FFF on Q1.18: c = 2^18 - 8 = 262136. c^2 = floor((2^18 - 8)^2 / 2^18) = 2^18 - 16 =
    // 262128 (the 64 / 2^18 floored away); c^3 = floor(262128 * 262136 / 2^18) = 2^18 - 24 = 262120,
    // in both orders (right to left: P = 1.0 x c = c exactly, then c x c^2).
    EXPECT_EQ(l2r(2, 0x7FFF), 262128u);
    EXPECT_EQ(l2r(3, 0x7FFF), 262120u);
    EXPECT_EQ(r2l(3, 0x7FFF), 262120u);
    // Q1.15: c = 32767, c^2 = floor(32767^2 / 2^15) = floor(1073676289 / 32768) = 32766.
    EXPECT_EQ(l2r(2, 0x7FFF, 15), 32766u);
    EXPECT_EQ(r2l(2, 0x7FFF, 15), 32766u);
    // Exact powers of 1/2 stay exact: 0.75^3 = 27/64 on Q1.18 = 110592; 0.5^5 = 2^13 = 8192 on Q1.18.
    EXPECT_EQ(l2r(3, 0x6000), 110592u);
    EXPECT_EQ(r2l(3, 0x6000), 110592u);
    EXPECT_EQ(r2l(5, 0x4000), 8192u);
    EXPECT_EQ(l2r(5, 0x4000, 20), 32768u);
}

TEST(SqmulWords, TheTwoWalksFloorDifferently) {
    // n = 6 = 0b110, cos = 0x7005: c = 229416 on Q1.18 (cos^6 = 117772.15 LSB). Left to right:
    // c^2 = 200774, c^3 = 175707, (c^3)^2 = 117770. Right to left: X = c^2 = 200774, then P = c^2,
    // X = c^4 = floor(200774^2 / 2^18) = 153771, then P = c^2 x c^4 = 117771.
    EXPECT_EQ(l2r(6, 0x7005), 117770u);
    EXPECT_EQ(r2l(6, 0x7005), 117771u);
}

TEST(SqmulWords, EdgesOfTheRange) {
    // n = 0: left to right reads it as n = 1 (P = cos), right to left walks no bit (P = 1.0 = cos^0).
    EXPECT_EQ(l2r(0, 0x5000), 0x5000u << 3);
    EXPECT_EQ(r2l(0, 0x5000), sqmul::p_one);
    // Saturate mode clamps a cos above 1.0: every power is 1.0.
    EXPECT_EQ(l2r(1000, 0x9000), sqmul::p_one);
    EXPECT_EQ(r2l(1000, 0x9000), sqmul::p_one);
    // Words outside the study's range are refused.
    EXPECT_THROW(golden_sqmul(3, 0x7000, {0, 0, 0}, sat, 14), std::invalid_argument);
    EXPECT_THROW(golden_sqmul_r2l(3, 0x7000, {0, 0, 0}, sat, 25), std::invalid_argument);
}

TEST(SqmulWords, ColourOutputsOnTheSixteenHighWires) {
    // cos = 0.75, n = 3 on Q1.20: P = 27/64 = 442368; its 16 high wires 27/64 on Q1.15 = 13824;
    // x 255 = 3525120, >> 7 (Q9.8) = 27540.
    const auto g = golden_sqmul_r2l(3, 0x6000, {255, 0, 1}, sat, 20);
    EXPECT_EQ(g.p, 442368u);
    EXPECT_EQ(g.out[0], 27540u);
    EXPECT_EQ(g.out[1], 0u);
    EXPECT_EQ(g.out[2], 108u);  // 13824 >> 7
}

TEST(SqmulWords, ClocksPerSampleFollowTheFormula) {
    // The golden models' steps + 4 against floor(log2 n) + popcount(n) + 3 and floor(log2 n) + 5.
    for (unsigned n = 1; n < 1024; ++n) {
        ASSERT_EQ(sqmul_clocks(sqmul_walk::left_to_right, n), sqmul_clocks_formula(sqmul_walk::left_to_right, n)) << n;
        ASSERT_EQ(sqmul_clocks(sqmul_walk::right_to_left, n), sqmul_clocks_formula(sqmul_walk::right_to_left, n)) << n;
    }
    // By hand, the synchroniser's two edges, the taking edge and the done edge being 4:
    // n = 1000 = 0b1111101000: 9 squares + 5 multiplications + 4 = 18; 10 bits + 4 = 14.
    // n = 5 = 0b101: 2 + 1 + 4 = 7 and 3 + 4 = 7; n = 100 = 0b1100100: 6 + 2 + 4 = 12 and 7 + 4 = 11.
    EXPECT_EQ(sqmul_clocks(sqmul_walk::left_to_right, 1000), 18u);
    EXPECT_EQ(sqmul_clocks(sqmul_walk::right_to_left, 1000), 14u);
    EXPECT_EQ(sqmul_clocks(sqmul_walk::left_to_right, 5), 7u);
    EXPECT_EQ(sqmul_clocks(sqmul_walk::right_to_left, 5), 7u);
    EXPECT_EQ(sqmul_clocks(sqmul_walk::left_to_right, 100), 12u);
    EXPECT_EQ(sqmul_clocks(sqmul_walk::right_to_left, 100), 11u);
}

TEST(SqmulWords, TheRelativeErrorMeasureFindsAKnownError) {
    // cos^n x (1 + 1e-3) everywhere, and 2 % at one (n, code) where cos^n >= 0.56: n = 7, code
    // 0x7F00 (0.9921875^7 = 0.9466 >= 0.56, and >= 0.1).
    const auto f = [](unsigned n, uint64_t c) {
        const double p = ref::cos_pow(to_real(c, spec::cos_fmt), n);
        return p * (n == 7 && c == 0x7F00 ? 1.02 : 1.001);
    };
    for (double threshold : {0.56, 0.1}) {
        const rel_error r = worst_rel_error(f, threshold, 20);
        EXPECT_NEAR(r.worst, 0.02, 1e-12);
        EXPECT_EQ(r.at_n, 7u);
        EXPECT_EQ(r.at_code, 0x7F00u);
        EXPECT_EQ(r.n_above_1pct, 1u);
    }
    // Without the spike: 1e-3 at every n; a code with cos^n just below the threshold is not read
    // (n = 1, threshold 0.56: code 18350 = 0.55999 has a 50 % error and is skipped).
    const auto g = [](unsigned n, uint64_t c) {
        const double p = ref::cos_pow(to_real(c, spec::cos_fmt), n);
        return n == 1 && c == 18350 ? 1.5 * p : p * 1.001;
    };
    const rel_error r = worst_rel_error(g, 0.56, 1);
    EXPECT_NEAR(r.worst, 1e-3, 1e-12);
    EXPECT_EQ(r.n_above_1pct, 0u);
}
