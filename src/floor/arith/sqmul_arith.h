// The bit-exact functions of the square-and-multiply designs (ours; formats/sqmul_formats.h), plain
// C++ written from the format table, not from the blocks: cos^n exact up to the floors of their
// products. Left to right with one multiplier (the baseline, golden_sqmul: the golden model the
// device is checked against, and what its fast model, the TLM wrapper and the pipeline's fast model
// call; the floor, docs/layers.md) and right to left with two (golden_sqmul_r2l); both on the Q1.18
// word by default, or on Q1.p_frac for the word-length study (p_frac in [p_frac_min, p_frac_max]).
#pragma once

#include <array>
#include <cstdint>

#include "formats/fixed_point.h"
#include "formats/sqmul_formats.h"

namespace shading {

struct sqmul_nets {
    unsigned squares = 0, multiplies = 0;  // products of each kind written to a register
    unsigned steps = 0;                    // clocks between the load and the done edge
    uint64_t p = 0;                        // P after the last step, Q1.p_frac
    std::array<uint64_t, 3> out{};         // colour multipliers on P's 16 high wires, Q9.8
};

// Left to right: floor(log2 n) squares and popcount(n) - 1 multiplications, one per step (n = 0
// is read as n = 1: none). Saturate mode clamps the loaded cos to 1.0 (a code above 0x8000 is out
// of range); wrap mode loads it as it is and every product keeps its p_frac + 1 low wires above the
// floor.
sqmul_nets golden_sqmul(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi, overflow_mode mode,
                        unsigned p_frac = sqmul::p_frac);

// Right to left: one step per bit of n up to its leading one (floor(log2 n) + 1 steps; n = 0:
// none, P = 1.0 = cos^0), each writing X^2 to X and, when the bit is 1, P x X to P (popcount(n)
// multiplications; the first is by P = 1.0, exact). The modes as golden_sqmul's.
sqmul_nets golden_sqmul_r2l(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                            overflow_mode mode, unsigned p_frac = sqmul::p_frac);

}  // namespace shading
