// The bit-exact function of the tuned UA 60553 variant (ua60553::tuned_generator), plain C++: its
// golden model, and what a_gen_tuned::a_word and the TLM wrapper call (the floor, docs/layers.md).
#pragma once

#include <array>
#include <cstdint>

#include "arith/specular_arith.h"
#include "formats/ua60553_formats.h"

namespace shading {

// a on the Q11.7 bus: n < 2 -> 0 (key block closed); else n*K31 +/- |K32|, wrapped to 18 bits.
uint64_t golden_a_tuned(uint64_t n_bits, const ua60553::tuned_generator& g);

datapath_nets golden_ua60553_tuned(uint64_t n_bits, uint64_t cos_bits, const std::array<uint64_t, 3>& ksi,
                                   overflow_mode mode,
                                   const ua60553::tuned_generator& g = ua60553::minimax);

}  // namespace shading
