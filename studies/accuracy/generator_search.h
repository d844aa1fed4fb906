// Search of the ROM-free generators of `a` that cost no more than UA 60553's (modules/tuned/README.md, "A better
// ROM-free a(n)"): a = n*K31 + s*K32 on the patent's buses (K31, |K32| Q0.7, a Q11.7), with
//   K31: at most 4 non-zero bits (the patent's node 31 has 4), in [0.75, 0.83];
//   K32: at most 3 non-zero bits, either sign (node 32 tied to the constant's two's complement);
//   optionally n < 2 forced to a = 0 (one OR gate over n's bits 9..1 and a key block on the a bus).
// Ranked by the worst bit-accurate max relative error above 0.56 over n in [1, 1000], then by the
// number of non-zero constant bits, then by the worst over n in [1, 512].
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "study_metrics.h"

namespace shading::study {

struct candidate {
    uint64_t k31 = 0;         // Q0.7 code
    int64_t k32 = 0;          // signed, Q0.7 units
    bool n_lt2_zero = false;  // special case n < 2 -> a = 0
    double worst_1000 = 0, worst_512 = 0;
    // Filled by rank_against_rom: max over n in [1, 1000] of (error(n) - error_ROM(n)) and the
    // number of n where the candidate is worse than the ROM prototype.
    double excess_over_rom = 0;
    unsigned n_worse_than_rom = 0;
    unsigned nnz() const;
    std::string k31_string() const;  // 7 bits, MSB (weight 1/2) first
    std::string k32_string() const;  // |K32|, 7 bits
};

// a on the Q11.7 bus for this candidate (direct integer arithmetic, wraps like ADD15).
uint64_t candidate_a(const candidate& c, unsigned n);

// All candidates whose worst error is below `keep_below`, best first. Deterministic.
std::vector<candidate> search_generators(const grid& g, double keep_below);

// Fills excess_over_rom / n_worse_than_rom of every candidate and returns the index of the one
// that follows the ROM prototype (UA 22802) most closely n by n: smallest excess, then smallest
// worst case, then fewest non-zero constant bits. Deterministic.
std::size_t rank_against_rom(const grid& g, std::vector<candidate>& all);

}  // namespace shading::study
