// The search for a ROM-free a(n) (generator_search.h) re-derives the tuned UA 60553 variant's
// constants (formats/ua60553_formats.h): minimax is its winner, rom_matched its choice closest to the
// ROM prototype, and the search's a-law is the golden model's word for word.
#include <gtest/gtest.h>

#include "formats/ua60553_formats.h"
#include "arith/ua60553_tuned_arith.h"
#include "generator_search.h"
#include "study_metrics.h"

using namespace shading;

TEST(UA60553TunedGolden, MinimaxIsTheSearchWinner) {
    const study::grid g;
    const auto all = study::search_generators(g, 0.035);
    ASSERT_FALSE(all.empty());
    EXPECT_EQ(all.front().k31_string(), ua60553::minimax.k31_bits);
    EXPECT_EQ(all.front().k32_string(), ua60553::minimax.k32_bits);
    EXPECT_EQ(all.front().k32 < 0, ua60553::minimax.k32_negative);
    EXPECT_TRUE(all.front().n_lt2_zero);
    // The search's own a-law is the golden model's.
    for (unsigned n = 0; n < 1024; ++n)
        EXPECT_EQ(study::candidate_a(all.front(), n), golden_a_tuned(n, ua60553::minimax)) << n;
}

TEST(UA60553TunedGolden, RomMatchedIsTheSearchChoiceClosestToTheRom) {
    const study::grid g;
    auto all = study::search_generators(g, 0.035);
    ASSERT_FALSE(all.empty());
    const auto& m = all[study::rank_against_rom(g, all)];
    EXPECT_EQ(m.k31_string(), ua60553::rom_matched.k31_bits);
    EXPECT_EQ(m.k32_string(), ua60553::rom_matched.k32_bits);
    EXPECT_EQ(m.k32 < 0, ua60553::rom_matched.k32_negative);
    EXPECT_TRUE(m.n_lt2_zero);
}
